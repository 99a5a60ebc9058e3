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
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace ui::net {

inline constexpr std::uint16_t kDefaultPort = 7777;

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
    std::set<PeerId> spectators_, greeted_;
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
