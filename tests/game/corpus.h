// Shared check for corpora of bad files: each directory has expected.tsv listing
// "file<TAB>substring of the one message its loader must produce".
#pragma once

#include "game/files/text_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

inline int checkBadCorpus(const std::filesystem::path& dir,
                          const std::function<void(const std::string&)>& load) {
    std::ifstream manifest(dir / "expected.tsv");
    EXPECT_TRUE(manifest) << "missing " << dir / "expected.tsv";
    std::string line;
    int cases = 0;
    while (std::getline(manifest, line)) {
        if (line.empty() || line[0] == '#') continue;
        const auto tab = line.find('\t');
        EXPECT_NE(tab, std::string::npos) << line;
        if (tab == std::string::npos) continue;
        const std::string file = (dir / line.substr(0, tab)).string();
        const std::string expected = line.substr(tab + 1);
        ++cases;
        try {
            load(file);
            ADD_FAILURE() << file << " loaded, but should fail with: " << expected;
        } catch (const game::LoadError& e) {
            const std::string msg = e.what();
            EXPECT_EQ(msg.rfind(file + ": ", 0), 0u) << "message starts with the file: " << msg;
            EXPECT_NE(msg.find(expected), std::string::npos)
                << file << "\n  got:      " << msg << "\n  expected: " << expected;
        }
    }
    return cases;
}
