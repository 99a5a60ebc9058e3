// libFuzzer target: arbitrary bytes into one file loader, chosen at compile time by
// FUZZ_LOADER (1 level, 2 replay, 3 commands, 4 player settings). Accepted input must
// load whole; anything else must be refused with a LoadError. Any other exception, a
// crash, a hang or a leak is a bug: the fuzzer stops and saves the input (in the build
// folder, see the Makefile's fuzz target), which then goes into the bad-file corpus of
// tests/data with the message it must produce.
#include "game/command.h"
#include "game/files/text_file.h"
#include "game/level.h"
#include "game/replay.h"
#if FUZZ_LOADER == 4
#include "ui/game/player_settings.h"
#endif

#include <cstddef>
#include <cstdint>
#include <string>

namespace {
void load(const std::string& text) {
#if FUZZ_LOADER == 1
    game::parseLevel("fuzz.json", text);
#elif FUZZ_LOADER == 2
    game::parseReplay("fuzz.json", text);
#elif FUZZ_LOADER == 3
    game::parseCommands("fuzz.json", text);
#else
    ui::parsePlayerSettings("fuzz.json", text);
#endif
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        load(std::string(reinterpret_cast<const char*>(data), size));
    } catch (const game::LoadError&) {
        // Refused with a message: what bad input must get.
    }
    return 0;
}
