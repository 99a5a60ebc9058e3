// libFuzzer target: arbitrary bytes into the network message decoder, as any packet
// from a peer reaches it. The decoder must refuse bad bytes with a reason and never
// crash, hang or read out of bounds; what it accepts must encode back to the very same
// bytes (nothing is lost or invented between the wire and the game).
#include "game/net/message.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const game::net::Decoded d = game::net::decode(data, size);
    if (!d.message) {
        if (d.error.empty()) std::abort(); // a refusal must say why
        return 0;
    }
    const std::vector<std::uint8_t> again = game::net::encode(*d.message);
    if (again.size() != size || std::memcmp(again.data(), data, size) != 0) std::abort();
    return 0;
}
