// What every loader reads: regular files of at most kMaxFileBytes, refused before a byte
// is read otherwise (a device never ends, a FIFO with no writer never answers), and
// messages that print the file's bytes as valid UTF-8.
#include "game/files/json_reader.h"
#include "game/level.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace {

std::string refusal(const std::string& file) {
    try {
        game::readFile(file);
    } catch (const game::LoadError& e) {
        return e.what();
    }
    return "(read)";
}

std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("artillery-file-limits-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir / name;
}

TEST(FileLimits, DevicesFifosAndDirectoriesAreRefusedBeforeReading) {
    EXPECT_EQ(refusal("/dev/zero"), "/dev/zero: $: expected a regular file, got a device");
    const auto dir = scratch("a-folder");
    std::filesystem::create_directories(dir);
    EXPECT_EQ(refusal(dir.string()), dir.string() + ": $: expected a regular file, got a directory");
    const auto fifo = scratch("a-fifo");
    std::filesystem::remove(fifo);
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(refusal(fifo.string()),
              fifo.string() + ": $: expected a regular file, got a FIFO (named pipe)");
    std::filesystem::remove(fifo);
    std::filesystem::remove_all(dir.parent_path());
}

TEST(FileLimits, AFileAboveTheLimitIsRefusedAndOneAtItIsRead) {
    const auto big = scratch("big.json");
    std::filesystem::resize_file((std::ofstream(big), big), game::kMaxFileBytes + 1);
    EXPECT_EQ(refusal(big.string()),
              big.string() + ": $: the file is 16777217 bytes; files of at most 16777216 bytes "
                             "(16 MiB) are read");
    std::filesystem::resize_file(big, game::kMaxFileBytes);
    EXPECT_EQ(game::readFile(big.string()).size(), game::kMaxFileBytes);
    std::filesystem::remove_all(big.parent_path());
}

TEST(FileLimits, DepthIsBoundedBeforeParsing) {
    // 60,000 levels deep once crashed the process through recursion.
    const std::string deep = std::string(60000, '[') + std::string(60000, ']');
    try {
        game::parseJson("deep.json", deep);
        FAIL() << "parsed";
    } catch (const game::LoadError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "deep.json: line 1, column 65: arrays and objects nest deeper than 64 levels "
                  "(no file format of the game needs more than 5)");
    }
    EXPECT_NO_THROW(game::parseJson("ok.json", std::string(64, '[') + std::string(64, ']')));
}

TEST(FileLimits, MessagesEscapeBytesThatAreNotUtf8) {
    EXPECT_EQ(game::printable("caf\xc3\xa9 \xd7 \x01 ok"), "caf\xc3\xa9 \\xd7 \\x01 ok");
    EXPECT_EQ(game::printable("\xed\xa0\x80"), "\\xed\\xa0\\x80"); // a UTF-16 surrogate
    EXPECT_EQ(game::printable("\xc0\xaf"), "\\xc0\\xaf");          // an overlong '/'
    EXPECT_EQ(game::characterCount("\xc3\xa9t\xc3\xa9"), 3u);
    const game::LoadError e("f\xff.json", "$", "got \xd7");
    EXPECT_EQ(std::string(e.what()), "f\\xff.json: $: got \\xd7");
}

} // namespace
