#include "game/session.h"

#include <algorithm>

namespace game {

Session::Session(const Level& level, const SessionOptions& options)
    : match_(std::make_unique<Match>(level)), options_(options),
      cpu_(options.difficulty, options.cpuSeed, options.cpuDelayTicks) {
    replay_.levelFile = level.file;
    replay_.levelHash = level.contentHash;
    replay_.difficulty = difficultyName(options.difficulty);
    replay_.cpuSeed = options.cpuSeed;
    replay_.checkpointEvery = options.checkpointEvery;
}

std::string Session::submit(Command command) {
    command.tick = match_->tick();
    std::string why = match_->apply(command);
    if (why.empty()) replay_.commands.push_back(std::move(command));
    return why;
}

void Session::step() {
    Match& m = *match_;
    const bool cpuTurn = !options_.hotseat && !m.over() && !m.shell() &&
                         (options_.autoplay || m.cannon().def.player == "cpu");
    for (Command c : cpu_.due(m, cpuTurn)) submit(c);
    m.step();
    if (m.tick() % options_.checkpointEvery == 0) replay_.checkpoints.push_back(checkpointOf(m));
    // Save at the end of each turn and of the match.
    bool turnEnded = false;
    for (; eventsSeen_ < m.events().size(); ++eventsSeen_) {
        const EventKind k = m.events()[eventsSeen_].kind;
        turnEnded = turnEnded || k == EventKind::TurnOver || k == EventKind::MatchOver;
    }
    if (turnEnded && !options_.recordFile.empty()) saveAtTurnEnd();
}

void Session::saveAtTurnEnd() {
    if (!options_.onSaveFailure) return save(options_.recordFile);
    try {
        save(options_.recordFile);
    } catch (const std::exception& e) {
        options_.onSaveFailure(e.what());
    }
}

Replay Session::finishedRecording() const {
    Replay r = replay_;
    r.ticks = match_->tick();
    r.finalHash = match_->hash();
    return r;
}

void Session::save(const std::string& file) const { saveReplay(file, finishedRecording()); }

void Session::rewindTo(std::uint64_t tick) { rewindTo(tick, nullptr); }

void Session::rewindTo(std::uint64_t tick, std::unique_ptr<Match> start) {
    if (tick > match_->tick()) tick = match_->tick();
    std::vector<Command> keep;
    for (const Command& c : replay_.commands)
        if (c.tick < tick) keep.push_back(c);
    std::erase_if(replay_.checkpoints, [&](const Checkpoint& c) { return c.tick > tick; });
    // The computer's generator must be where it was: re-create it and replay its turns'
    // draws by re-running from the start with the recorded commands (the computer is not
    // consulted again; its commands are in the recording).
    if (!start || start->tick() > tick) start = std::make_unique<Match>(match_->level());
    match_ = std::move(start);
    // Commands before the start's tick are in it already.
    std::size_t next = static_cast<std::size_t>(
        std::lower_bound(keep.begin(), keep.end(), match_->tick(),
                         [](const Command& c, std::uint64_t t) { return c.tick < t; }) -
        keep.begin());
    while (match_->tick() < tick) {
        while (next < keep.size() && keep[next].tick <= match_->tick()) match_->apply(keep[next++]);
        match_->step();
    }
    replay_.commands = std::move(keep);
    eventsSeen_ = match_->events().size();
    // Draw the computer's generator forward past the turns it has already taken, so a
    // branch does not repeat its earlier aim errors.
    cpu_ = ComputerTurns(options_.difficulty, options_.cpuSeed + tick, options_.cpuDelayTicks);
}

void Session::continueAs(const SessionOptions& options) {
    const std::uint64_t every = options_.checkpointEvery;
    options_ = options;
    options_.checkpointEvery = every;
    replay_.difficulty = difficultyName(options.difficulty);
    replay_.cpuSeed = options.cpuSeed;
    // As after a rewind: the computer's generator is seeded from the branch point, so a
    // branch does not replay the original's aim errors.
    cpu_ = ComputerTurns(options.difficulty, options.cpuSeed + match_->tick(), options.cpuDelayTicks);
}

} // namespace game
