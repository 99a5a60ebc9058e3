// "Export video" in the replay viewer: `artillery run LEVEL --replay FILE --video OUT.mp4`
// in a child process. The replay is re-simulated and drawn offscreen there, by the very
// code path of the command line, while the window keeps drawing and keeps its own GL
// context (a headless context in the same process would take over the GL function table
// the window uses).
#pragma once

#include <string>
#include <sys/types.h>
#include <vector>

namespace ui {

class VideoExport {
  public:
    enum class State { Idle, Running, Done, Failed };

    VideoExport() = default;
    /// Stops an export still running (the child is ended and waited for).
    ~VideoExport();
    VideoExport(const VideoExport&) = delete;
    VideoExport& operator=(const VideoExport&) = delete;

    /// Starts `exe run LEVEL --replay REPLAY --video OUT [EXTRA...]`. False (state Failed,
    /// message()) when the process cannot be started or an export is already running.
    bool start(const std::string& exe, const std::string& level, const std::string& replay,
               const std::string& out, const std::vector<std::string>& extra = {});
    /// Looks whether the child has ended, without waiting.
    State poll();
    State state() const { return state_; }
    /// The video's path.
    const std::string& file() const { return out_; }
    /// While running: "". Done: the run's line about the video. Failed: why.
    const std::string& message() const { return message_; }

  private:
    void finished(int status);

    State state_ = State::Idle;
    pid_t child_ = -1;
    std::string out_;
    std::string log_; ///< the child's stdout and stderr
    std::string message_;
};

} // namespace ui
