// Nothing lost: a writer killed in the middle of a save leaves the previous file intact
// (writeFileAtomically writes a temporary file and renames it over the target).
#include "game/files/text_file.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;

TEST(AtomicSave, AWriterKilledMidSaveLeavesThePreviousFileIntact) {
    const fs::path dir = fs::temp_directory_path() / ("artillery_kill_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "replay.json";
    const std::string previous = R"({"saved": "before"})";
    game::writeFileAtomically(file.string(), previous);

    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        // A save far too big to finish before the parent kills it (1 GiB).
        const std::string huge(std::size_t{1} << 30, 'x');
        const char go = 1;
        if (::write(ready[1], &go, 1) != 1) ::_exit(2);
        game::writeFileAtomically(file.string(), huge);
        ::_exit(0);
    }
    char go = 0;
    ASSERT_EQ(::read(ready[0], &go, 1), 1) << "the child is about to save";
    ::close(ready[0]);
    ::close(ready[1]);
    // Wait until the child is visibly writing its temporary file, then kill it.
    const fs::path tmp = dir / ("replay.json.tmp." + std::to_string(child));
    bool writing = false;
    for (int i = 0; i < 20000 && !writing; ++i) {
        std::error_code ec;
        writing = fs::exists(tmp, ec) && fs::file_size(tmp, ec) > 1024;
        if (!writing) std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    EXPECT_TRUE(writing) << "the child never started writing";
    EXPECT_TRUE(WIFSIGNALED(status)) << "the child finished its save before being killed";

    std::ifstream in(file);
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_EQ(s.str(), previous) << "the previous save must be untouched";
    fs::remove_all(dir);
}
