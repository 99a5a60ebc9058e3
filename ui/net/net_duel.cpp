#include "ui/net/net_duel.h"

#include "game/files/text_file.h"
#include "game/replay.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <random>
#include <thread>

namespace ui::net {

using game::net::Message;
using game::net::MessageType;

const char* netResultName(NetResult r) {
    switch (r) {
    case NetResult::Running:
        return "running";
    case NetResult::Over:
        return "over";
    case NetResult::Desync:
        return "desync";
    case NetResult::Abandoned:
        return "abandoned";
    case NetResult::Refused:
        return "refused";
    case NetResult::Failed:
        return "failed";
    }
    return "?";
}

namespace {

/// How long both sides linger after the match to exchange the last checkpoints (s).
constexpr double kGoodbyeSeconds = 10.0;
constexpr double kAfterByeSeconds = 1.0;

Message offerFor(const game::Level& level, const std::string& name, std::uint64_t every) {
    Message m;
    m.type = MessageType::Offer;
    m.version = game::net::kProgramVersion;
    m.levelHash = level.contentHash;
    m.levelName = std::filesystem::path(level.file).filename().string();
    m.name = name;
    m.checkpointEvery = static_cast<std::uint32_t>(every);
    return m;
}

/// A seat's secret: 64 bits from the system's random source, as 16 hex digits.
std::string newSeatToken() {
    std::random_device random;
    const std::uint64_t bits = (static_cast<std::uint64_t>(random()) << 32) ^ random();
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(bits));
    return text;
}

Message reasonMessage(MessageType t, const std::string& why) {
    Message m;
    m.type = t;
    m.reason = why.substr(0, game::net::kMaxReasonBytes);
    return m;
}

} // namespace

NetDuel::NetDuel(NetOptions options) : o_(std::move(options)) {
    names_[o_.host ? 0 : 1] = o_.name;
}

double NetDuel::since(Clock::time_point t) const {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

std::vector<std::string> NetDuel::takeLog() {
    std::vector<std::string> out;
    out.swap(log_);
    return out;
}

bool NetDuel::start(std::string& why) {
    if (o_.host) {
        try {
            level_ = game::loadLevel(o_.levelFile);
        } catch (const std::exception& e) {
            why = e.what();
            return false;
        }
        if (level_->mode != game::Mode::Duel || level_->cannons.size() != 2) {
            why = o_.levelFile + ": a network duel needs a duel level with two cannons";
            return false;
        }
        link_ = Link::listen(o_.bindAddress, o_.port, kHostLimits, why);
        if (!link_) return false;
        game::net::LockstepOptions lo;
        lo.localCannon = 0;
        lo.autoplay = o_.autoplay;
        lo.tamperTick = o_.tamperTick;
        lockstep_ = std::make_unique<game::net::Lockstep>(*level_, lo);
        log_.push_back("hosting " + std::filesystem::path(o_.levelFile).filename().string() +
                       " on " + o_.bindAddress + ":" + std::to_string(link_->port()));
        return true;
    }
    link_ = Link::connect(o_.address, o_.port, why);
    if (!link_) return false;
    log_.push_back("connecting to " + o_.address + ":" + std::to_string(o_.port));
    return true;
}

void NetDuel::finish(NetResult r, std::string message) {
    if (result_ != NetResult::Running) return;
    result_ = r;
    message_ = std::move(message);
    log_.push_back(message_);
    flushOutboxes();
    save();
    if (link_) {
        // disconnect_later sends what is queued first; a spectator far behind (a busy
        // machine) may still be receiving the stream, so wait for every peer's
        // disconnection, at most kGoodbyeSeconds, before the socket closes.
        // The other player, once it has said goodbye, is leaving too: its disconnection
        // crosses ours, or it has gone and nobody will answer, so it gets a second.
        std::size_t open = 0;
        for (PeerId p : {player_, server_})
            if (p) link_->close(p), ++open;
        for (PeerId s : spectators_)
            link_->close(s), ++open;
        const double wait = peerBye_ && spectators_.empty() ? kAfterByeSeconds : kGoodbyeSeconds;
        const auto closing = Clock::now();
        while (open > 0 && since(closing) < wait) {
            const LinkEvent e = link_->poll(10);
            if (e.kind == LinkEvent::Kind::Disconnected) --open;
        }
    }
}

void NetDuel::sendToOthers(const Message& m) {
    if (o_.host && player_) link_->send(player_, m);
    if (o_.host)
        for (PeerId s : spectators_)
            link_->send(s, m);
    if (!o_.host && server_) link_->send(server_, m);
}

void NetDuel::sayGoodbye(const std::string& why) {
    // Spectators too: behind the stream on a busy machine, they learn that it is complete
    // and play the rest of it after the host has gone.
    sendToOthers(reasonMessage(MessageType::Bye, why));
    link_->flush();
}

void NetDuel::leave(const std::string& why) {
    if (result_ != NetResult::Running) return;
    if (lockstep_) lockstep_->markProgress();
    if (link_) {
        flushOutboxes(); // what was played so far reaches the other side first
        sayGoodbye(why);
    }
    const std::uint64_t tick = lockstep_ ? lockstep_->match().tick() : 0;
    finish(NetResult::Abandoned, "left the duel at tick " + std::to_string(tick) + ": " + why);
}

void NetDuel::save() {
    if (o_.recordFile.empty() || !lockstep_ || !level_) return;
    try {
        game::saveReplay(o_.recordFile, lockstep_->recording(level_->file));
        log_.push_back("replay saved to " + o_.recordFile);
    } catch (const std::exception& e) {
        log_.push_back(std::string("could not save the replay: ") + e.what());
    }
}

void NetDuel::closePeer(PeerId peer, const std::string& why) {
    log_.push_back("closing " + link_->address(peer) + ": " + why);
    link_->send(peer, reasonMessage(MessageType::Bye, why));
    link_->close(peer);
    greeted_.erase(peer);
    spectators_.erase(peer);
    if (peer == player_) {
        player_ = nullptr;
        paused_ = true;
        droppedAt_ = Clock::now();
    }
}

std::string NetDuel::submit(const game::Command& c) {
    if (!lockstep_ || result_ != NetResult::Running) return "the match is not running";
    if (lockstep_->localCannon() == game::net::kSpectator) return "spectators watch only";
    return lockstep_->submit(c);
}

void NetDuel::refuseJoin(PeerId peer, const std::string& why) {
    link_->send(peer, reasonMessage(MessageType::Refuse, why));
    closePeer(peer, why);
}

void NetDuel::hostHello(PeerId peer, const Message& m) {
    const std::string levelName = std::filesystem::path(level_->file).filename().string();
    if (m.version != game::net::kProgramVersion)
        return refuseJoin(peer, "program version differs: host runs '" +
                                    std::string(game::net::kProgramVersion) + "', " + m.name +
                                    " runs '" + m.version + "'");
    if (m.levelHash != level_->contentHash)
        return refuseJoin(peer, "level differs: host plays " + levelName + " (content hash " +
                                    level_->contentHash + "), " + m.name +
                                    (m.levelHash.empty() ? " has no level with that name"
                                                         : " has content hash " + m.levelHash));
    greeted_.erase(peer);
    if (m.spectator) return welcomeSpectator(peer, m);
    if (const std::string why = seatRefusal(m); !why.empty()) return refuseJoin(peer, why);
    seatPlayer(peer, m);
}

void NetDuel::welcomeSpectator(PeerId peer, const Message& m) {
    if (spectators_.size() >= kMaxSpectators)
        return refuseJoin(peer, "the host takes at most " + std::to_string(kMaxSpectators) +
                                    " spectators");
    spectators_.insert(peer);
    Message welcome;
    welcome.type = MessageType::Welcome;
    welcome.cannon = -1;
    welcome.name = names_[0];
    link_->send(peer, welcome);
    for (const Message& c : lockstep_->catchUp(0, true))
        link_->send(peer, c);
    log_.push_back("spectator " + m.name + " joined at tick " +
                   std::to_string(lockstep_->match().tick()));
}

std::string NetDuel::seatRefusal(const Message& m) const {
    if (seatToken_.empty()) return ""; // the seat is free: the first player takes it
    if (m.token == seatToken_) return "";
    // A name is whatever a peer says: only the token the seat's player was given at its
    // first join takes the seat back.
    if (!m.token.empty()) return "that is not the seat's token (join with --spectate to watch)";
    return "the seat is " + names_[1] + "'s" + (player_ ? "" : ", held for its return") +
           "; a rejoin presents the seat token the host gave at the first join (join with "
           "--spectate to watch)";
}

void NetDuel::seatPlayer(PeerId peer, const Message& m) {
    if (player_ && player_ != peer) {
        // The seat's player again from a new connection: its old one went stale before
        // the timeout noticed (a cut cable). The new one takes over.
        link_->cut(player_);
        player_ = nullptr;
    }
    if (seatToken_.empty()) seatToken_ = newSeatToken();
    player_ = peer;
    names_[1] = m.name;
    Message welcome;
    welcome.type = MessageType::Welcome;
    welcome.cannon = 1;
    welcome.name = names_[0];
    welcome.token = seatToken_;
    lockstep_->forgetPeerProgress();
    welcome.commandIndex = lockstep_->commandCount();
    welcome.tick = static_cast<std::uint32_t>(lockstep_->match().tick());
    link_->send(peer, welcome);
    Link::setTimeout(peer, 5000);
    if (playerEverJoined_) {
        log_.push_back(m.name + " is back at tick " + std::to_string(m.tick) +
                       "; resuming from tick " + std::to_string(lockstep_->match().tick()));
    } else {
        log_.push_back(m.name + " joined from " + link_->address(peer));
    }
    playerEverJoined_ = true;
    paused_ = false;
    // Everything the player lacks from its count on (a new process lacks its own old
    // commands too), then our mark.
    for (const Message& c : lockstep_->catchUp(m.commandIndex, false))
        link_->send(peer, c);
}

void NetDuel::guardTheDoor() {
    for (const std::string& who : link_->resetStaleHandshakes(kHandshakeSeconds))
        log_.push_back("dropped " + who + ": its connection stayed in the handshake for over " +
                       std::to_string(static_cast<int>(kHandshakeSeconds)) + " s");
    std::vector<PeerId> silent;
    for (const auto& [peer, at] : greeted_)
        if (since(at) > kHelloSeconds) silent.push_back(peer);
    for (PeerId peer : silent) {
        log_.push_back("dropped " + link_->address(peer) + ": no hello within " +
                       std::to_string(static_cast<int>(kHelloSeconds)) + " s");
        link_->send(peer, reasonMessage(MessageType::Bye, "no hello in time"));
        link_->flush(); // the goodbye goes before the slot is freed
        greeted_.erase(peer);
        link_->disconnectNow(peer);
    }
    keepRoom();
}

void NetDuel::keepRoom() {
    while (link_->freeSlots() < kReservedSlots) {
        // The connection unidentified the longest: in ENet's handshake, or connected
        // without a hello.
        std::optional<std::pair<PeerId, double>> oldest;
        bool greeted = false;
        for (const auto& entry : link_->handshakes())
            if (!oldest || entry.second > oldest->second) oldest = entry;
        for (const auto& [peer, at] : greeted_)
            if (!oldest || since(at) > oldest->second) oldest = {peer, since(at)}, greeted = true;
        if (!oldest || oldest->second < kGraceSeconds) return;
        log_.push_back("dropped " + link_->address(oldest->first) +
                       (greeted ? ": no hello" : ": still in the handshake") +
                       ", and the host keeps room for its player");
        if (greeted) {
            greeted_.erase(oldest->first);
            link_->disconnectNow(oldest->first);
        } else {
            link_->reset(oldest->first);
        }
    }
}

void NetDuel::shareAim(std::optional<game::net::AimSeen> editing) {
    const bool mine = lockstep_ && link_ && result_ == NetResult::Running && lockstep_->localTurn();
    if (!aimSharing_.due(mine ? editing : std::nullopt, since(started_))) return;
    Message m;
    m.type = MessageType::Aiming;
    m.player = static_cast<std::uint8_t>(lockstep_->localCannon());
    m.angleDeg = editing->angleDeg;
    m.speedMps = editing->speedMps;
    sendToOthers(m);
}

std::optional<game::net::AimSeen> NetDuel::peerAim() const {
    if (!lockstep_) return std::nullopt;
    return peerAim_.shown(lockstep_->match().currentPlayer(), since(started_));
}

void NetDuel::hostMessage(PeerId peer, const Message& m) {
    if (greeted_.count(peer)) {
        if (m.type != MessageType::Hello)
            return closePeer(peer, std::string("expected hello, got ") + messageName(m.type));
        return hostHello(peer, m);
    }
    if (spectators_.count(peer)) {
        if (m.type == MessageType::Bye) {
            spectators_.erase(peer);
            return;
        }
        return closePeer(peer, "spectators send nothing but bye");
    }
    if (peer != player_) return;
    if (m.type == MessageType::Bye) {
        peerBye_ = true;
        peerByeReason_ = m.reason;
        return;
    }
    if (m.type == MessageType::Aiming) { // the player's, only drawn: the spectators see it too
        peerAim_.heard({m.angleDeg, m.speedMps}, 1, since(started_));
        for (PeerId s : spectators_)
            link_->send(s, m);
        return;
    }
    if (std::string why = lockstep_->receive(m); !why.empty())
        closePeer(peer, "protocol error: " + why);
}

void NetDuel::sendHello(const std::string& levelHash) {
    Message hello;
    hello.type = MessageType::Hello;
    hello.version = game::net::kProgramVersion;
    hello.name = o_.name;
    hello.spectator = o_.spectate;
    hello.levelHash = levelHash;
    hello.token = o_.spectate ? "" : o_.token;
    if (lockstep_) {
        hello.commandIndex = lockstep_->commandCount();
        hello.tick = static_cast<std::uint32_t>(lockstep_->match().tick());
    }
    link_->send(server_, hello);
}

void NetDuel::onOffer(const Message& m) {
    if (m.type != MessageType::Offer)
        return finish(NetResult::Failed, std::string("expected the host's offer, got ") +
                                             game::net::messageName(m.type));
    offered_ = true;
    names_[0] = m.name;
    const std::filesystem::path file = std::filesystem::path(o_.levelsDir) / m.levelName;
    std::string levelHash;
    try {
        game::Level level = game::loadLevel(file.string());
        levelHash = level.contentHash;
        if (level.contentHash == m.levelHash) level_ = std::move(level);
    } catch (const std::exception&) {
        // No such level here: the empty hash tells the host, which says what differs.
    }
    sendHello(levelHash);
}

void NetDuel::beforeWelcome(const Message& m) {
    if (m.type == MessageType::Refuse)
        return finish(NetResult::Refused, "the host refused: " + m.reason);
    if (m.type == MessageType::Bye) return finish(NetResult::Refused, "the host closed: " + m.reason);
    if (m.type == MessageType::Offer && level_) // a reconnect: the host offers again
        return sendHello(level_->contentHash);
    if (m.type != MessageType::Welcome)
        return finish(NetResult::Failed,
                      std::string("expected welcome, got ") + game::net::messageName(m.type));
    onWelcome(m);
}

void NetDuel::onWelcome(const Message& m) {
    welcomed_ = true;
    paused_ = false;
    names_[0] = m.name;
    if (!m.token.empty() && m.token != o_.token) {
        o_.token = m.token; // presented again by every reconnect
        log_.push_back("seat token " + m.token + ": a new process takes this seat back with --token " +
                       m.token);
    }
    if (lockstep_) {
        log_.push_back("back in the match at tick " + std::to_string(lockstep_->match().tick()));
        lockstep_->catchUpTo(m.tick);
        lockstep_->resume(m.commandIndex);
        return;
    }
    game::net::LockstepOptions lo;
    lo.localCannon = m.cannon;
    lo.autoplay = o_.autoplay;
    lo.tamperTick = o_.tamperTick;
    lockstep_ = std::make_unique<game::net::Lockstep>(*level_, lo);
    lockstep_->catchUpTo(m.tick);
    if (m.tick > 0)
        log_.push_back("rejoining: replaying the match up to tick " + std::to_string(m.tick));
    log_.push_back(std::string(o_.spectate ? "watching " : "playing ") +
                   std::filesystem::path(level_->file).filename().string() + " against host " +
                   m.name);
}

void NetDuel::joinMessage(const Message& m) {
    if (!offered_) return onOffer(m);
    if (!welcomed_) return beforeWelcome(m);
    if (m.type == MessageType::Bye) {
        peerBye_ = true;
        peerByeReason_ = m.reason;
        return;
    }
    if (m.type == MessageType::Aiming) { // only drawn; a spectator hears both players'
        peerAim_.heard({m.angleDeg, m.speedMps}, m.player, since(started_));
        return;
    }
    if (std::string why = lockstep_->receive(m); !why.empty()) {
        link_->send(server_, reasonMessage(MessageType::Bye, "protocol error: " + why));
        finish(NetResult::Failed, "protocol error from the host: " + why);
    }
}

void NetDuel::onEvent(const LinkEvent& e) {
    switch (e.kind) {
    case LinkEvent::Kind::None:
        return;
    case LinkEvent::Kind::Connected:
        if (o_.host) {
            greeted_[e.peer] = Clock::now();
            link_->send(e.peer, offerFor(*level_, names_[0], game::kDefaultCheckpointEvery));
        } else {
            server_ = e.peer;
            Link::setTimeout(e.peer, 5000);
        }
        return;
    case LinkEvent::Kind::Malformed:
        if (o_.host) return closePeer(e.peer, "malformed message: " + e.error);
        return finish(NetResult::Failed, "malformed message from the host: " + e.error);
    case LinkEvent::Kind::Message:
        if (o_.host) return hostMessage(e.peer, e.message);
        return joinMessage(e.message);
    case LinkEvent::Kind::Disconnected:
        if (o_.host) {
            greeted_.erase(e.peer);
            spectators_.erase(e.peer);
            if (e.peer == player_) {
                player_ = nullptr;
                if (lockstep_->over() || peerBye_) return;
                paused_ = true;
                droppedAt_ = Clock::now();
                log_.push_back(names_[1] + " dropped at tick " +
                               std::to_string(lockstep_->match().tick()) +
                               "; the match is paused for up to " +
                               std::to_string(static_cast<int>(o_.timeoutSeconds)) + " s");
            }
            return;
        }
        server_ = nullptr;
        if (!level_ || !welcomed_) {
            if (!lockstep_)
                return finish(NetResult::Failed,
                              "could not connect to " + o_.address + ":" + std::to_string(o_.port));
        }
        if (lockstep_ && (lockstep_->over() || peerBye_)) return;
        if (!paused_) {
            paused_ = true;
            droppedAt_ = Clock::now();
            log_.push_back("connection to the host lost at tick " +
                           std::to_string(lockstep_ ? lockstep_->match().tick() : 0) +
                           "; reconnecting");
        }
        welcomed_ = false;
        reconnect();
        return;
    }
}

void NetDuel::reconnect() {
    std::string why;
    link_ = Link::connect(o_.address, o_.port, why);
    if (!link_) log_.push_back("reconnect failed: " + why);
}

void NetDuel::flushOutboxes() {
    if (!lockstep_ || !link_) return;
    for (const Message& m : lockstep_->takeOutbox()) {
        if (o_.host && player_) link_->send(player_, m);
        if (!o_.host && server_ && welcomed_) link_->send(server_, m);
    }
    for (const Message& m : lockstep_->takeSpectatorOutbox())
        for (PeerId s : spectators_)
            link_->send(s, m);
    link_->flush();
}

void NetDuel::stepMatch(std::uint64_t maxTicks) {
    game::net::Lockstep& ls = *lockstep_;
    for (std::uint64_t i = 0; i < maxTicks; ++i) {
        if (o_.quitAtTick && ls.match().tick() >= *o_.quitAtTick) {
            // Test hook: vanish like a crashed process, no goodbye.
            if (server_) link_->cut(server_);
            server_ = nullptr;
            return finish(NetResult::Failed, "left without a goodbye at tick " +
                                                 std::to_string(ls.match().tick()) +
                                                 " (test hook)");
        }
        if (o_.dropAtTick && ls.match().tick() >= *o_.dropAtTick && server_) {
            o_.dropAtTick.reset();
            log_.push_back("cutting the connection at tick " + std::to_string(ls.match().tick()) +
                           " (test hook)");
            flushOutboxes();
            link_->cut(server_);
            server_ = nullptr;
            welcomed_ = false;
            paused_ = true;
            droppedAt_ = Clock::now();
            std::this_thread::sleep_for(std::chrono::milliseconds(300));
            reconnect();
            return;
        }
        while (nextScript_ < o_.script.size() && ls.localTurn() &&
               o_.script[nextScript_].tick <= ls.match().tick()) {
            if (std::string why = ls.submit(o_.script[nextScript_]); !why.empty())
                log_.push_back("tick " + std::to_string(ls.match().tick()) + ": " +
                               game::commandName(o_.script[nextScript_].kind) + " refused: " + why);
            ++nextScript_;
        }
        if (!ls.canStep()) return;
        ls.step();
    }
}

bool NetDuel::pump(std::uint32_t waitMs, std::uint64_t maxTicks) {
    if (result_ != NetResult::Running) return false;
    if (!link_) {
        if (since(droppedAt_) > o_.timeoutSeconds)
            finish(NetResult::Abandoned, "could not get back to the host within " +
                                             std::to_string(static_cast<int>(o_.timeoutSeconds)) +
                                             " s");
        else
            reconnect();
        return result_ == NetResult::Running;
    }
    for (LinkEvent e = link_->poll(waitMs);
         e.kind != LinkEvent::Kind::None && result_ == NetResult::Running; e = link_->poll(0))
        onEvent(e);
    if (result_ != NetResult::Running) return false;
    if (o_.host) guardTheDoor();
    const bool connected = o_.host ? player_ != nullptr : (server_ != nullptr && welcomed_);
    // After the peer's goodbye the stream is complete: play it out, connected or not, up
    // to the local player's turn, which nobody would see.
    const bool peerGone = lockstep_ && peerBye_ && !lockstep_->over() && lockstep_->localTurn();
    if (lockstep_ && (connected || peerBye_) && !paused_ && !peerGone) stepMatch(maxTicks);
    if (result_ != NetResult::Running) return false;
    flushOutboxes();
    if (!lockstep_ || (!o_.host && !welcomed_ && !paused_)) {
        if (since(started_) > o_.waitSeconds && !playerEverJoined_ && !lockstep_)
            finish(NetResult::Failed, "nobody answered within " +
                                          std::to_string(static_cast<int>(o_.waitSeconds)) + " s");
        return result_ == NetResult::Running;
    }
    const game::net::Lockstep& ls = *lockstep_;
    const std::string tick = std::to_string(ls.match().tick());
    if (!ls.stopped().empty()) {
        const bool desync = ls.stopped().rfind("desync", 0) == 0;
        finish(desync ? NetResult::Desync : NetResult::Failed, ls.stopped());
        return false;
    }
    if (o_.host && !playerEverJoined_) {
        if (since(started_) > o_.waitSeconds)
            finish(NetResult::Failed, "no player joined within " +
                                          std::to_string(static_cast<int>(o_.waitSeconds)) + " s");
        return result_ == NetResult::Running;
    }
    if (paused_ && since(droppedAt_) > o_.timeoutSeconds) {
        finish(NetResult::Abandoned, (o_.host ? names_[1] : std::string("the host")) +
                                         " did not return within " +
                                         std::to_string(static_cast<int>(o_.timeoutSeconds)) +
                                         " s: the match ends at tick " + tick);
        return false;
    }
    if (ls.over()) {
        if (!byeSent_) {
            byeSent_ = true;
            overAt_ = Clock::now();
            sayGoodbye("match over");
        }
        const int winner = ls.match().winner();
        const std::string who =
            winner < 0 ? "a draw"
                       : "cannon " + std::to_string(winner) + " (" + names_[winner] + ") wins";
        const bool spectator = ls.localCannon() == game::net::kSpectator;
        if (peerBye_ || spectator || (o_.host && !player_) || since(*overAt_) > kGoodbyeSeconds)
            finish(NetResult::Over, "match over at tick " + tick + ": " + who + ", final hash " +
                                        game::hex(ls.match().hash()));
        return result_ == NetResult::Running;
    }
    if (peerBye_ && (ls.localTurn() || (!ls.canStep() && ls.pending() == 0)))
        finish(NetResult::Abandoned, "the other side left at tick " + tick + ": " + peerByeReason_);
    return result_ == NetResult::Running;
}

} // namespace ui::net
