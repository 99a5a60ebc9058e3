// The thin edge of the network: ENet (reliable, ordered delivery over UDP, made for
// games) carrying the protocol's messages. Everything it receives goes through
// game::net::decode before anything else sees it; nothing here knows the game's rules.
#pragma once

#include "game/net/message.h"

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

typedef struct _ENetHost ENetHost;
typedef struct _ENetPeer ENetPeer;

namespace ui::net {

/// One connection's handle (stable while the peer is connected).
using PeerId = ENetPeer*;

struct LinkEvent {
    enum class Kind { None, Connected, Message, Malformed, Disconnected } kind = Kind::None;
    PeerId peer = nullptr;
    game::net::Message message; ///< Kind::Message
    std::string error;          ///< Kind::Malformed: why the packet was refused
};

/// How many connections a host takes: ENet's peer slots, and how many of them one
/// address may hold (ENet's duplicatePeers), so that a single machine cannot fill them.
struct HostLimits {
    std::size_t slots = 16;
    std::size_t perAddress = 4;
};

class Link {
  public:
    /// A host listening on `bindAddress`:`port` (port 0: any free port). Null with `why`
    /// set on failure, naming the address and the system's reason (an address this
    /// machine lacks, a port in use).
    static std::unique_ptr<Link> listen(const std::string& bindAddress, std::uint16_t port,
                                        const HostLimits& limits, std::string& why);
    /// A client connecting to `address`:`port`; the Connected event says when it is up.
    static std::unique_ptr<Link> connect(const std::string& address, std::uint16_t port,
                                         std::string& why);
    ~Link();

    /// The port this side is bound to.
    std::uint16_t port() const;
    /// Waits up to `timeoutMs` for one event.
    LinkEvent poll(std::uint32_t timeoutMs);
    void send(PeerId peer, const game::net::Message& m);
    /// Closes a peer's connection once what was sent is delivered.
    void close(PeerId peer);
    /// Drops a peer at once, without telling it (a cut cable; test hook).
    void cut(PeerId peer);
    /// Sends what is queued now.
    void flush();
    std::string address(PeerId peer) const;
    /// Makes the peer's connection time out after `ms` without acknowledgements.
    static void setTimeout(PeerId peer, std::uint32_t ms);
    /// Ends a connection at once, freeing its slot (one unacknowledged goodbye is sent):
    /// for a peer that will not be waited for.
    void disconnectNow(PeerId peer);

    // Holding the door. ENet keeps a connection in its handshake (a CONNECT not
    // acknowledged, or a goodbye not acknowledged) until its own timeout, up to 30 s:
    // slots held by packets that cost their sender nothing. These are the host's answer.
    /// Resets every connection that has been in the handshake, or in closing, for more
    /// than `seconds`; returns their addresses, for the log.
    std::vector<std::string> resetStaleHandshakes(double seconds);
    /// The connections in the handshake now (not those closing), each with how long it
    /// has been there, s.
    std::vector<std::pair<PeerId, double>> handshakes();
    /// Frees a connection's slot at once, telling nobody.
    void reset(PeerId peer);
    /// Slots no connection holds, in any state.
    std::size_t freeSlots() const;

  private:
    using Clock = std::chrono::steady_clock;
    explicit Link(ENetHost* host) : host_(host) {}
    /// The connections in the handshake or closing now, with when each was first seen
    /// so (a slot reused by a new connection has a new connectID and starts again).
    std::vector<std::pair<PeerId, Clock::time_point>> unsettled();
    ENetHost* host_;
    std::map<PeerId, std::pair<std::uint32_t, Clock::time_point>> firstSeen_;
};

/// "HOST[:PORT]" -> host and port (default `fallbackPort`); nullopt when malformed.
std::optional<std::pair<std::string, std::uint16_t>> parseAddress(const std::string& text,
                                                                  std::uint16_t fallbackPort);

} // namespace ui::net
