#include "ui/video/video_export.h"

#include "ui/video/video_writer.h"

#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <spawn.h>
#include <sys/wait.h>
#include <vector>

extern char** environ;

namespace ui {

namespace {

/// The last line of a file that says something: the run's summary or its error.
std::string lastLine(const std::string& file) {
    std::ifstream in(file);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
}

} // namespace

VideoExport::~VideoExport() {
    if (state_ != State::Running) return;
    kill(child_, SIGTERM);
    int status = 0;
    waitpid(child_, &status, 0);
    // Ended by the signal, the run could not remove its unfinished file itself.
    std::error_code ec;
    std::filesystem::remove(partialVideoFile(out_), ec);
    std::filesystem::remove(log_, ec);
}

bool VideoExport::start(const std::string& exe, const std::string& level, const std::string& replay,
                        const std::string& out, const std::vector<std::string>& extra) {
    if (state_ == State::Running) {
        message_ = "a video is being exported already";
        return false;
    }
    out_ = out;
    message_.clear();
    log_ = out + ".log";
    posix_spawn_file_actions_t io;
    posix_spawn_file_actions_init(&io);
    posix_spawn_file_actions_addopen(&io, 1, log_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&io, 1, 2);
    std::vector<std::string> words{exe, "run", level, "--replay", replay, "--video", out};
    words.insert(words.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (std::string& w : words)
        argv.push_back(w.data());
    argv.push_back(nullptr);
    const int rc = posix_spawn(&child_, exe.c_str(), &io, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&io);
    if (rc != 0) {
        state_ = State::Failed;
        message_ = "cannot start " + exe + ": " + std::strerror(rc);
        return false;
    }
    state_ = State::Running;
    return true;
}

VideoExport::State VideoExport::poll() {
    if (state_ != State::Running) return state_;
    int status = 0;
    if (waitpid(child_, &status, WNOHANG) == child_) finished(status);
    return state_;
}

void VideoExport::finished(int status) {
    const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    message_ = lastLine(log_);
    if (!ok && message_.empty())
        message_ = WIFSIGNALED(status)
                       ? "the export was stopped by signal " + std::to_string(WTERMSIG(status))
                       : "the export failed";
    state_ = ok ? State::Done : State::Failed;
    std::error_code ec;
    std::filesystem::remove(log_, ec);
}

} // namespace ui
