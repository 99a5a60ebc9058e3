// A duel over the network, one side of it: the host (cannon 0, and the spectators'
// source), a joining player (cannon 1) or a spectator. It owns the ENet link and the
// lockstep session and is driven by pump() — from the headless verbs' loop or once per
// frame by the window — so the same code runs with and without a screen.
//
// Timing lives here, at the edge (wall-clock timeouts for a dropped peer); the match
// itself advances only by ticks, whatever the network does.
#pragma once

#include "game/level.h"
#include "game/net/lockstep.h"
#include "game/net/peer_aim.h"
#include "ui/net/enet_link.h"

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace ui::net {

inline constexpr std::uint16_t kDefaultPort = 7777;

// What the host admits, so that nobody can hold its door shut (docs/network.md).
/// ENet slots and the most one address may hold: the player, its stale connection on
/// a reconnect, and spectators, from one machine.
inline constexpr HostLimits kHostLimits{16, 4};
/// Spectators at most; more are refused.
inline constexpr std::size_t kMaxSpectators = 4;
/// Slots kept free for the player it expects: when fewer are free, the connection that
/// has been unidentified longest (in the handshake, or without a hello) is dropped, if
/// it has been so for kGraceSeconds (a player needs a round trip or two to say hello:
/// the newest connection is the one most likely to be the player).
inline constexpr std::size_t kReservedSlots = 2;
inline constexpr double kGraceSeconds = 1.0;
/// A connection must finish ENet's handshake, and then say hello, within this (s).
inline constexpr double kHandshakeSeconds = 5.0;
inline constexpr double kHelloSeconds = 5.0;

struct NetOptions {
    bool host = true;
    // host
    std::string levelFile;
    std::string bindAddress = "127.0.0.1";
    std::uint16_t port = kDefaultPort; ///< 0: any free port (printed)
    // join
    std::string address = "127.0.0.1";
    std::string levelsDir = "levels"; ///< where the joiner looks for the host's level
    bool spectate = false;
    /// The seat token the host gave at the first join (16 hex digits): a new process
    /// presents it to take the seat back ("" for a first join).
    std::string token;
    // both
    std::string name = "player";
    bool autoplay = false;
    std::vector<game::Command> script; ///< local commands at their ticks (own turns)
    std::string recordFile;
    double timeoutSeconds = 60.0; ///< how long a dropped peer may take to return
    double waitSeconds = 120.0;   ///< how long to wait for the other side to appear
    // test hooks
    std::optional<std::uint64_t> tamperTick; ///< perturb the shell from this tick on
    std::optional<std::uint64_t> dropAtTick; ///< cut the connection once, then reconnect
    std::optional<std::uint64_t> quitAtTick; ///< vanish at this tick without a goodbye
};

enum class NetResult { Running, Over, Desync, Abandoned, Refused, Failed };
const char* netResultName(NetResult r);

class NetDuel {
  public:
    explicit NetDuel(NetOptions options);
    /// Listens (host) or connects (join). False with `why` on failure.
    bool start(std::string& why);
    /// Services the network for up to `waitMs`, then runs at most `maxTicks` ticks.
    /// Returns false once the duel is finished (result() says how).
    bool pump(std::uint32_t waitMs, std::uint64_t maxTicks);
    /// A command from the window for the local cannon ("" or why refused).
    std::string submit(const game::Command& c);

    NetResult result() const { return result_; }
    const std::string& message() const { return message_; }
    std::uint16_t port() const { return link_ ? link_->port() : 0; }
    /// Null until the match starts (a joiner learns the level from the host).
    const game::net::Lockstep* lockstep() const { return lockstep_.get(); }
    const game::Level* level() const { return level_ ? &*level_ : nullptr; }
    /// Lines for the log since the last call.
    std::vector<std::string> takeLog();
    /// The players' names, cannon 0 then 1 ("" while unknown).
    const std::string& playerName(int cannon) const { return names_[cannon == 0 ? 0 : 1]; }
    bool paused() const { return paused_; }
    /// Saves the recording now (when --record was given).
    void save();
    /// Once a frame: the aim the local player is editing (none: not editing), shared
    /// with the other side as it moves (game/net/peer_aim.h) in the local turn.
    void shareAim(std::optional<game::net::AimSeen> editing);
    /// The other player's aim as they edit it, while it is their turn (for drawing).
    std::optional<game::net::AimSeen> peerAim() const;
    /// The local side leaves a duel still running (the window closed, --limit): the other
    /// side is told at once, with `why`, instead of waiting out its time to reconnect;
    /// the recording is saved and the result is Abandoned.
    void leave(const std::string& why);

  private:
    using Clock = std::chrono::steady_clock;
    void onEvent(const LinkEvent& e);
    void hostMessage(PeerId peer, const game::net::Message& m);
    void joinMessage(const game::net::Message& m);
    void hostHello(PeerId peer, const game::net::Message& m);
    void refuseJoin(PeerId peer, const std::string& why);
    void welcomeSpectator(PeerId peer, const game::net::Message& m);
    void seatPlayer(PeerId peer, const game::net::Message& m);
    /// The seat's token checked: "" when `m` may take the seat, else why not.
    std::string seatRefusal(const game::net::Message& m) const;
    /// Host: drops connections that hold a slot without becoming a player or spectator.
    void guardTheDoor();
    /// Host: while fewer than kReservedSlots are free, drops the connection unidentified
    /// the longest (at least kGraceSeconds).
    void keepRoom();
    // Joiner: the host's messages before the match, and the welcome.
    void onOffer(const game::net::Message& m);
    void sendHello(const std::string& levelHash);
    void beforeWelcome(const game::net::Message& m);
    void onWelcome(const game::net::Message& m);
    void stepMatch(std::uint64_t maxTicks);
    void flushOutboxes();
    void finish(NetResult r, std::string message);
    /// To the other player, and from the host to the spectators too.
    void sendToOthers(const game::net::Message& m);
    /// Bye, with `why`, to the others.
    void sayGoodbye(const std::string& why);
    void closePeer(PeerId peer, const std::string& why);
    void reconnect();
    double since(Clock::time_point t) const;

    NetOptions o_;
    std::unique_ptr<Link> link_;
    std::optional<game::Level> level_;
    std::unique_ptr<game::net::Lockstep> lockstep_;
    NetResult result_ = NetResult::Running;
    std::string message_;
    std::vector<std::string> log_;
    std::string names_[2];
    // host
    PeerId player_ = nullptr;
    bool playerEverJoined_ = false;
    std::set<PeerId> spectators_;
    /// Connected, offered the match, no hello yet: since when.
    std::map<PeerId, Clock::time_point> greeted_;
    /// The seat's secret, given to its player at the first join ("" while it is free).
    std::string seatToken_;
    // join
    PeerId server_ = nullptr;
    bool offered_ = false;
    bool welcomed_ = false;
    // both
    bool paused_ = false;
    Clock::time_point started_ = Clock::now(), droppedAt_;
    std::optional<Clock::time_point> overAt_;
    bool byeSent_ = false, peerBye_ = false, dropped_ = false;
    std::string peerByeReason_;
    game::net::AimSharing aimSharing_;
    game::net::PeerAim peerAim_;
    std::size_t nextScript_ = 0;
};

} // namespace ui::net
