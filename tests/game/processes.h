// Work run in several processes at once, as two windows of the game run side by side
// (the tests of what they share: the progress and settings files).
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

/// Runs work(k) for k = 0 .. n-1, each in a child process of its own, all at once, and
/// expects each to exit with 0 (work's result is the child's exit code).
inline void runInProcesses(int n, const std::function<int(int)>& work) {
    std::vector<pid_t> children;
    for (int k = 0; k < n; ++k) {
        const pid_t child = ::fork();
        ASSERT_GE(child, 0);
        if (child == 0) ::_exit(work(k));
        children.push_back(child);
    }
    for (pid_t child : children) {
        int status = 0;
        ASSERT_EQ(::waitpid(child, &status, 0), child);
        ASSERT_TRUE(WIFEXITED(status));
        EXPECT_EQ(WEXITSTATUS(status), 0);
    }
}
