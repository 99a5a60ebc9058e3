#include "game/replay_player.h"

#include "game/ai.h"

#include <algorithm>

namespace game {

namespace {

/// The replay's own settings; the computer is never asked (its commands are recorded).
SessionOptions playbackOptions(const Replay& r) {
    SessionOptions o;
    o.difficulty = difficultyFromName(r.difficulty).value_or(Difficulty::Normal);
    o.cpuSeed = r.cpuSeed;
    o.checkpointEvery = r.checkpointEvery;
    o.hotseat = true;
    return o;
}

/// Which parts of the match differ, named as `artillery replay verify` names them.
std::string differingParts(const Checkpoint& got, const Checkpoint& want) {
    std::string what;
    auto add = [&](bool differs, const char* part) {
        if (differs) what += (what.empty() ? "" : ", ") + std::string(part);
    };
    add(got.particles != want.particles, "particles");
    add(got.bodies != want.bodies, "bodies");
    add(got.game != want.game, "game");
    return what.empty() ? "match" : what;
}

} // namespace

ReplayPlayer::ReplayPlayer(const Level& level, Replay replay)
    : replay_(std::move(replay)), session_(level, playbackOptions(replay_)),
      restarts_(level, replay_) {
    for (const Command& c : replay_.commands)
        if (c.kind == CommandKind::Fire && c.tick < replay_.ticks) shots_.push_back(c.tick);
}

void ReplayPlayer::step() {
    if (atEnd()) return;
    const std::vector<Command>& commands = replay_.commands;
    while (nextCommand_ < commands.size() && commands[nextCommand_].tick <= tick()) {
        const bool firstTime = tick() >= furthest_;
        if (!session_.submit(commands[nextCommand_++]).empty() && firstTime) ++refused_;
    }
    session_.step();
    compareCheckpoint();
    furthest_ = std::max(furthest_, tick());
}

void ReplayPlayer::compareCheckpoint() {
    const std::vector<Checkpoint>& stored = replay_.checkpoints;
    while (nextCheckpoint_ < stored.size() && stored[nextCheckpoint_].tick < tick())
        ++nextCheckpoint_;
    const bool firstTime = tick() > furthest_;
    if (nextCheckpoint_ < stored.size() && stored[nextCheckpoint_].tick == tick()) {
        const Checkpoint& want = stored[nextCheckpoint_++];
        const Checkpoint got = checkpointOf(session_.match());
        if (firstTime) ++checkpointsChecked_;
        if (got.hash != want.hash && (!divergence_ || divergence_->tick > want.tick))
            divergence_ = ReplayDivergence{want.tick, differingParts(got, want)};
    }
    if (atEnd() && session_.match().hash() != replay_.finalHash && !divergence_)
        divergence_ = ReplayDivergence{tick(), "final state"};
}

void ReplayPlayer::seek(std::uint64_t target) {
    target = std::min(target, lastTick());
    if (target < tick()) {
        std::unique_ptr<Match> start = restarts_.take(target);
        lastSeekResimulated_ = target - (start ? start->tick() : 0);
        session_.rewindTo(target, std::move(start));
        // The session kept the commands before `target`; the replay's own list says
        // where to go on (refused commands, if any, are not in the session's).
        const auto& commands = replay_.commands;
        nextCommand_ = static_cast<std::size_t>(
            std::lower_bound(commands.begin(), commands.end(), target,
                             [](const Command& c, std::uint64_t t) { return c.tick < t; }) -
            commands.begin());
        const auto& stored = replay_.checkpoints;
        nextCheckpoint_ = static_cast<std::size_t>(
            std::upper_bound(stored.begin(), stored.end(), target,
                             [](std::uint64_t t, const Checkpoint& c) { return t < c.tick; }) -
            stored.begin());
    }
    while (tick() < target)
        step();
}

bool ReplayPlayer::prepareRestartPoints(std::uint64_t tickBudget) {
    return restarts_.build(tickBudget);
}

std::optional<std::uint64_t> ReplayPlayer::shotBefore(std::uint64_t t) const {
    const auto it = std::lower_bound(shots_.begin(), shots_.end(), t);
    if (it == shots_.begin()) return std::nullopt;
    return *std::prev(it);
}

std::optional<std::uint64_t> ReplayPlayer::shotAfter(std::uint64_t t) const {
    const auto it = std::upper_bound(shots_.begin(), shots_.end(), t);
    if (it == shots_.end()) return std::nullopt;
    return *it;
}

Session ReplayPlayer::takeOver(const SessionOptions& options) && {
    session_.continueAs(options);
    return std::move(session_);
}

} // namespace game
