#include "game/net/lockstep.h"

#include <algorithm>

namespace game::net {

std::string desyncMessage(std::uint64_t tick, const Checkpoint& a, const Checkpoint& b) {
    std::string parts;
    auto add = [&](bool differ, const char* name) {
        if (differ) parts += std::string(parts.empty() ? "" : ", ") + name;
    };
    add(a.particles != b.particles, "particles");
    add(a.bodies != b.bodies, "bodies");
    add(a.game != b.game, "game");
    if (parts.empty()) parts = "match";
    return "desync at tick " + std::to_string(tick) + " (" + parts + " differ)";
}

Lockstep::Lockstep(const Level& level, const LockstepOptions& options)
    : match_(std::make_unique<Match>(level)), options_(options),
      cpu_(options.difficulty,
           options.cpuSeed + static_cast<std::uint64_t>(std::max(0, options.localCannon)),
           options.cpuDelayTicks),
      levelHash_(level.contentHash) {
    if (options_.checkpointEvery == 0) options_.checkpointEvery = kDefaultCheckpointEvery;
    if (options_.advanceEvery == 0) options_.advanceEvery = 1;
}

bool Lockstep::localTurn() const {
    return options_.localCannon != kSpectator && !match_->over() &&
           match_->currentPlayer() == options_.localCannon;
}

bool Lockstep::canStep() const {
    if (!stopped_.empty() || match_->over()) return false;
    if (localTurn() && !catchingUp()) return true;
    return match_->tick() < peerMark_;
}

void Lockstep::send(Message m, bool toSpectators) {
    if (options_.localCannon == kSpectator) return;
    if (toSpectators && options_.localCannon == 0) spectatorOutbox_.push_back(m);
    outbox_.push_back(std::move(m));
}

void Lockstep::stop(std::string why) {
    if (!stopped_.empty()) return;
    stopped_ = why;
    Message bye;
    bye.type = MessageType::Bye;
    bye.reason = why.substr(0, kMaxReasonBytes);
    send(bye);
}

std::string Lockstep::submit(Command command) {
    if (!stopped_.empty()) return "the match has stopped: " + stopped_;
    if (!networkCommand(command.kind))
        return std::string("'") + commandName(command.kind) +
               "' is not a duel command (aim, power, select, fire, end_turn)";
    if (!localTurn()) return "it is not your turn";
    if (catchingUp())
        return "catching up with the match (tick " + std::to_string(replayUntil_) + ")";
    command.tick = match_->tick();
    if (std::string why = match_->apply(command); !why.empty()) return why;
    send(commandMessage(command, commandCount(), options_.localCannon));
    commands_.push_back(std::move(command));
    players_.push_back(options_.localCannon);
    return "";
}

void Lockstep::applyPending() {
    while (!pending_.empty() && pending_.front().tick == match_->tick()) {
        const Message m = pending_.front();
        pending_.pop_front();
        if (match_->currentPlayer() != m.player) {
            return stop("player " + std::to_string(m.player) +
                        " sent a command outside its turn (tick " + std::to_string(m.tick) + ")");
        }
        const Command c = commandOf(m);
        if (std::string why = match_->apply(c); !why.empty())
            return stop("the peer's " + std::string(commandName(c.kind)) + " at tick " +
                        std::to_string(m.tick) + " is refused here: " + why);
        // The host forwards the joiner's commands to spectators as it applies them.
        if (options_.localCannon == 0) spectatorOutbox_.push_back(m);
        commands_.push_back(c);
        players_.push_back(m.player);
    }
}

void Lockstep::computerTurn() {
    const bool turn = options_.autoplay && localTurn() && !catchingUp() && !match_->shell();
    for (const Command& c : cpu_.due(*match_, turn))
        submit(c);
}

void Lockstep::step() {
    if (!canStep()) return;
    applyPending();
    if (!stopped_.empty()) return;
    computerTurn();
    const bool mine = localTurn() && !catchingUp();
    if (options_.tamperTick && !tampered_ && match_->tick() >= *options_.tamperTick)
        tampered_ = const_cast<Match&>(*match_).perturbShellForTest({0.001, 0.0});
    match_->step();
    const std::uint64_t t = match_->tick();
    if (mine) {
        Message mark;
        if (!localTurn() && !match_->over()) {
            mark.type = MessageType::Handover; // the turn passed during this tick
        } else if (match_->over() || t % options_.advanceEvery == 0) {
            mark.type = MessageType::Advance;
        }
        if (mark.type != MessageType::Bye) {
            mark.tick = static_cast<std::uint32_t>(t);
            lastMarkSent_ = t;
            send(mark, false);
        }
    }
    if (options_.localCannon == 0 &&
        (match_->over() || t % options_.advanceEvery == 0 || mine != localTurn())) {
        Message mark;
        mark.type = MessageType::Advance;
        mark.tick = static_cast<std::uint32_t>(t);
        spectatorOutbox_.push_back(mark);
    }
    if (t % options_.checkpointEvery == 0) checkpoint();
}

void Lockstep::markProgress() {
    const std::uint64_t t = match_->tick();
    if (!localTurn() || catchingUp() || t <= lastMarkSent_) return;
    Message mark;
    mark.type = MessageType::Advance;
    mark.tick = static_cast<std::uint32_t>(t);
    lastMarkSent_ = t;
    send(mark); // the host's spectators follow it too
}

void Lockstep::checkpoint() {
    const Checkpoint c = checkpointOf(*match_);
    checkpoints_.push_back(c);
    Message m;
    m.type = MessageType::Checkpoint;
    m.tick = static_cast<std::uint32_t>(c.tick);
    m.particles = c.particles;
    m.bodies = c.bodies;
    m.game = c.game;
    send(m);
    if (auto it = peerCheckpoints_.find(c.tick); it != peerCheckpoints_.end()) {
        compare(c, it->second);
        peerCheckpoints_.erase(it);
    }
}

void Lockstep::compare(const Checkpoint& mine, const Message& theirs) {
    Checkpoint other = mine;
    other.particles = theirs.particles;
    other.bodies = theirs.bodies;
    other.game = theirs.game;
    if (other.particles != mine.particles || other.bodies != mine.bodies || other.game != mine.game)
        stop(desyncMessage(mine.tick, mine, other));
}

std::string Lockstep::receive(const Message& m) {
    if (!stopped_.empty()) return "";
    const std::uint64_t now = match_->tick();
    switch (m.type) {
    case MessageType::Command: {
        const std::size_t known = commands_.size() + pending_.size();
        if (m.commandIndex < known) return ""; // sent again after a reconnect
        if (m.commandIndex > known)
            return "command number " + std::to_string(m.commandIndex) + " arrived, expected " +
                   std::to_string(known);
        const int sender = options_.localCannon == kSpectator ? m.player : 1 - options_.localCannon;
        const bool ownReplayed = m.player == options_.localCannon && m.tick < replayUntil_;
        if (m.player != sender && !ownReplayed)
            return "a command for cannon " + std::to_string(m.player) +
                   " came from the peer of cannon " + std::to_string(sender);
        const std::uint64_t last = pending_.empty() ? now : pending_.back().tick;
        if (m.tick < last)
            return "a command for tick " + std::to_string(m.tick) + " arrived after tick " +
                   std::to_string(last);
        if (pending_.size() >= kMaxPending)
            return "more than " + std::to_string(kMaxPending) + " commands waiting";
        pending_.push_back(m);
        return "";
    }
    case MessageType::Advance:
    case MessageType::Handover:
        if (m.tick < peerMark_)
            return std::string(messageName(m.type)) + " to tick " + std::to_string(m.tick) +
                   " after one to tick " + std::to_string(peerMark_);
        peerMark_ = m.tick;
        return "";
    case MessageType::Checkpoint: {
        if (m.tick == 0 || m.tick % options_.checkpointEvery != 0)
            return "checkpoint at tick " + std::to_string(m.tick) + " is not a multiple of " +
                   std::to_string(options_.checkpointEvery);
        if (m.tick <= now) {
            const std::size_t i = m.tick / options_.checkpointEvery - 1;
            if (i < checkpoints_.size()) compare(checkpoints_[i], m);
            return "";
        }
        if (peerCheckpoints_.size() >= kMaxPending)
            return "too many checkpoints ahead of this side";
        peerCheckpoints_[m.tick] = m;
        return "";
    }
    case MessageType::Bye:
        stopped_ = stopped_.empty() ? "the peer left: " + m.reason : stopped_;
        return "";
    default:
        return std::string("a ") + messageName(m.type) + " message in the middle of a match";
    }
}

std::vector<Message> Lockstep::takeOutbox() {
    std::vector<Message> out;
    out.swap(outbox_);
    return out;
}

std::vector<Message> Lockstep::takeSpectatorOutbox() {
    std::vector<Message> out;
    out.swap(spectatorOutbox_);
    return out;
}

std::vector<Message> Lockstep::catchUp(std::uint32_t fromIndex, bool forSpectator) const {
    std::vector<Message> out;
    for (std::size_t i = fromIndex; i < commands_.size(); ++i)
        out.push_back(commandMessage(commands_[i], static_cast<std::uint32_t>(i), players_[i]));
    if (forSpectator)
        for (const Checkpoint& c : checkpoints_) {
            Message m;
            m.type = MessageType::Checkpoint;
            m.tick = static_cast<std::uint32_t>(c.tick);
            m.particles = c.particles;
            m.bodies = c.bodies;
            m.game = c.game;
            out.push_back(m);
        }
    // Every command of ours before our tick is in the list above.
    Message mark;
    mark.type = MessageType::Advance;
    mark.tick = static_cast<std::uint32_t>(forSpectator ? match_->tick()
                                                        : std::max(lastMarkSent_, match_->tick()));
    if (forSpectator || localTurn() || mark.tick > 0) out.push_back(mark);
    return out;
}

void Lockstep::forgetPeerProgress() {
    pending_.clear();
    peerCheckpoints_.clear();
    peerMark_ = std::min<std::uint64_t>(peerMark_, match_->tick());
}

void Lockstep::resume(std::uint32_t peerHas) {
    for (const Message& m : catchUp(peerHas, false)) {
        if (m.type == MessageType::Command && m.player != options_.localCannon) continue;
        send(m, false);
    }
}

Replay Lockstep::recording(const std::string& levelFile) const {
    Replay r;
    r.levelFile = levelFile;
    r.levelHash = levelHash_;
    r.checkpointEvery = options_.checkpointEvery;
    r.ticks = match_->tick();
    r.commands = commands_;
    r.checkpoints = checkpoints_;
    r.finalHash = match_->hash();
    return r;
}

} // namespace game::net
