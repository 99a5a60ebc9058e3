#include "ui/game/replay_control.h"

#include <cstdio>
#include <filesystem>
#include <optional>

namespace ui {

namespace {

/// The tick of the match's last shot (any cannon's), if one was fired.
std::optional<std::uint64_t> lastShotTick(const game::Match& m) {
    const auto& events = m.events();
    for (auto e = events.rbegin(); e != events.rend(); ++e)
        if (e->kind == game::EventKind::Fired) return e->tick;
    return std::nullopt;
}

/// Where the shot fired at `fired` first met something: its first bounce, burst or hit,
/// or the tick it was over.
std::optional<std::uint64_t> impactTick(const game::Match& m, std::uint64_t fired) {
    using game::EventKind;
    for (const game::GameEvent& e : m.events())
        if (e.tick > fired && (e.kind == EventKind::Bounce || e.kind == EventKind::Burst ||
                               e.kind == EventKind::TargetHit || e.kind == EventKind::CannonHit ||
                               e.kind == EventKind::ShotOver))
            return e.tick;
    return std::nullopt;
}

} // namespace

void ReplayControl::watch(const std::string& file, const game::Level& level, game::Replay replay) {
    viewer_ = std::make_unique<ReplayViewer>(file, level, std::move(replay));
}

bool ReplayControl::watchLastShot(LivePlay& play) {
    if (!play.active() || viewer_ || play.match().shell()) return false;
    const game::Match& m = play.match();
    const auto fired = lastShotTick(m);
    if (!fired) return false;
    const auto lead = static_cast<std::uint64_t>(0.5 / m.world().def().tickSeconds);
    play.aim().cancelCharge();
    viewer_ = std::make_unique<ReplayViewer>("the last shot", m.level(),
                                             play.session().finishedRecording());
    viewer_->makeInstant(*fired > lead ? *fired - lead : 0, impactTick(m, *fired));
    return true;
}

void ReplayControl::backToLive(const LivePlay& play, MatchView& view) {
    const bool atTheGame = viewer_ && viewer_->player().atEnd();
    viewer_.reset();
    if (atTheGame || !play.active()) return;
    view.reset();
    view.observe(play.match());
}

void ReplayControl::takeOver(LivePlay& play, PlayerFiles& files, const game::Level& level,
                             std::string& status) {
    const double dt = viewer_->match().world().def().tickSeconds;
    const std::uint64_t at = viewer_->player().tick();
    const std::string from = std::filesystem::path(viewer_->file()).filename().string();
    // A new file per branch: the replay watched stays as it was.
    const std::string record = files.recordFileFor(std::filesystem::path(level.file).stem().string() +
                                                   "-branch-" + std::to_string(at) + ".json");
    game::SessionOptions options = liveSessionOptions(files, level, record, status);
    play.start(std::make_unique<game::Session>(viewer_->takeOver(options)));
    viewer_.reset();
    if (play.match().over()) play.markRecorded(); // a finished game is not scored again
    char note[256];
    std::snprintf(note, sizeof note, "branch of %s from %.1f s, %s", from.c_str(),
                  static_cast<double>(at) * dt,
                  record.empty()
                      ? "not recorded (check run)"
                      : ("recording " + std::filesystem::path(record).filename().string()).c_str());
    play.markBranch(note, at);
    if (record.empty()) return;
    try {
        play.session().save(record);
    } catch (const std::exception& e) {
        status = std::string("branch not saved: ") + e.what();
    }
}

} // namespace ui
