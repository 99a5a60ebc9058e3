// The thin edge of the network: ENet (reliable, ordered delivery over UDP, made for
// games) carrying the protocol's messages. Everything it receives goes through
// game::net::decode before anything else sees it; nothing here knows the game's rules.
#pragma once

#include "game/net/message.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

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

class Link {
  public:
    /// A host listening on `bindAddress`:`port` (port 0: any free port) for up to
    /// `maxPeers` connections. Null with `why` set on failure.
    static std::unique_ptr<Link> listen(const std::string& bindAddress, std::uint16_t port,
                                        std::size_t maxPeers, std::string& why);
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

  private:
    explicit Link(ENetHost* host) : host_(host) {}
    ENetHost* host_;
};

/// "HOST[:PORT]" -> host and port (default `fallbackPort`); nullopt when malformed.
std::optional<std::pair<std::string, std::uint16_t>> parseAddress(const std::string& text,
                                                                  std::uint16_t fallbackPort);

} // namespace ui::net
