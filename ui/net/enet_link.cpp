#include "ui/net/enet_link.h"

#include <enet/enet.h>

#include <arpa/inet.h>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

namespace ui::net {

namespace {

/// ENet's library state is process-wide: initialised once, released at exit.
bool initialised() {
    static const bool ok = [] {
        if (enet_initialize() != 0) return false;
        std::atexit(enet_deinitialize);
        return true;
    }();
    return ok;
}

/// Packets above the protocol's limit are dropped by ENet itself before any decoding.
void limit(ENetHost* host) {
    host->maximumPacketSize = game::net::kMaxMessageBytes;
    host->maximumWaitingData = 64 * 1024;
}

/// Why a UDP socket cannot be bound to address:port, "" when it can. ENet says only
/// that it failed; the system's reason (an address the machine lacks, a port in use)
/// is found by trying the same bind first.
std::string bindRefusal(std::uint32_t host, std::uint16_t port, const std::string& shown) {
    const int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
    if (fd < 0) return std::string("cannot open a UDP socket: ") + std::strerror(errno);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = host; // ENet keeps it in network order
    const int rc = ::bind(fd, reinterpret_cast<const sockaddr*>(&a), sizeof a);
    const int error = errno;
    ::close(fd);
    if (rc == 0) return "";
    const std::string where = "cannot listen on " + shown + ":" + std::to_string(port) + ": ";
    if (error == EADDRNOTAVAIL)
        return where + shown + " is not an address of this machine (--bind names one of its "
                               "own addresses, or 0.0.0.0 for all of them)";
    if (error == EADDRINUSE) return where + "the port is in use (--port 0 picks a free one)";
    return where + std::strerror(error);
}

/// ENet's peer states between "nobody" and "connected", and from "closing" to "closed".
bool unsettledState(ENetPeerState s) {
    switch (s) {
    case ENET_PEER_STATE_CONNECTING:
    case ENET_PEER_STATE_ACKNOWLEDGING_CONNECT:
    case ENET_PEER_STATE_CONNECTION_PENDING:
    case ENET_PEER_STATE_CONNECTION_SUCCEEDED:
    case ENET_PEER_STATE_DISCONNECT_LATER:
    case ENET_PEER_STATE_DISCONNECTING:
    case ENET_PEER_STATE_ACKNOWLEDGING_DISCONNECT:
        return true;
    default:
        return false;
    }
}

} // namespace

std::unique_ptr<Link> Link::listen(const std::string& bindAddress, std::uint16_t port,
                                   const HostLimits& limits, std::string& why) {
    if (!initialised()) {
        why = "ENet could not be initialised";
        return nullptr;
    }
    ENetAddress address{};
    if (enet_address_set_host_ip(&address, bindAddress.c_str()) != 0) {
        why = "'" + bindAddress + "' is not an IPv4 address";
        return nullptr;
    }
    address.port = port;
    why = bindRefusal(address.host, port, bindAddress);
    if (!why.empty()) return nullptr;
    ENetHost* host = enet_host_create(&address, limits.slots, 1, 0, 0);
    if (!host) {
        why = "cannot listen on " + bindAddress + ":" + std::to_string(port);
        return nullptr;
    }
    limit(host);
    host->duplicatePeers = limits.perAddress;
    return std::unique_ptr<Link>(new Link(host));
}

std::unique_ptr<Link> Link::connect(const std::string& address, std::uint16_t port,
                                    std::string& why) {
    if (!initialised()) {
        why = "ENet could not be initialised";
        return nullptr;
    }
    ENetHost* host = enet_host_create(nullptr, 1, 1, 0, 0);
    if (!host) {
        why = "cannot open a UDP socket";
        return nullptr;
    }
    limit(host);
    ENetAddress to{};
    if (enet_address_set_host(&to, address.c_str()) != 0) {
        enet_host_destroy(host);
        why = "cannot resolve host '" + address + "'";
        return nullptr;
    }
    to.port = port;
    ENetPeer* peer = enet_host_connect(host, &to, 1, 0);
    if (peer) enet_peer_timeout(peer, 0, 5000, 5000); // an unanswered attempt fails after 5 s
    if (!peer) {
        enet_host_destroy(host);
        why = "cannot start a connection to " + address;
        return nullptr;
    }
    return std::unique_ptr<Link>(new Link(host));
}

Link::~Link() {
    if (host_) enet_host_destroy(host_);
}

std::uint16_t Link::port() const {
    return host_->address.port;
}

LinkEvent Link::poll(std::uint32_t timeoutMs) {
    ENetEvent e;
    LinkEvent out;
    if (enet_host_service(host_, &e, timeoutMs) <= 0) return out;
    out.peer = e.peer;
    switch (e.type) {
    case ENET_EVENT_TYPE_CONNECT:
        out.kind = LinkEvent::Kind::Connected;
        break;
    case ENET_EVENT_TYPE_DISCONNECT:
        out.kind = LinkEvent::Kind::Disconnected;
        break;
    case ENET_EVENT_TYPE_RECEIVE: {
        game::net::Decoded d = game::net::decode(e.packet->data, e.packet->dataLength);
        enet_packet_destroy(e.packet);
        if (d.message) {
            out.kind = LinkEvent::Kind::Message;
            out.message = std::move(*d.message);
        } else {
            out.kind = LinkEvent::Kind::Malformed;
            out.error = std::move(d.error);
        }
        break;
    }
    default:
        break;
    }
    return out;
}

void Link::send(PeerId peer, const game::net::Message& m) {
    const std::vector<std::uint8_t> bytes = game::net::encode(m);
    ENetPacket* p = enet_packet_create(bytes.data(), bytes.size(), ENET_PACKET_FLAG_RELIABLE);
    if (enet_peer_send(peer, 0, p) != 0) enet_packet_destroy(p);
}

void Link::close(PeerId peer) {
    enet_peer_disconnect_later(peer, 0);
}

void Link::cut(PeerId peer) {
    enet_peer_reset(peer);
}

void Link::flush() {
    enet_host_flush(host_);
}

std::string Link::address(PeerId peer) const {
    char ip[64] = "?";
    enet_address_get_host_ip(&peer->address, ip, sizeof ip);
    return std::string(ip) + ":" + std::to_string(peer->address.port);
}

void Link::setTimeout(PeerId peer, std::uint32_t ms) {
    enet_peer_timeout(peer, 0, ms, ms);
}

void Link::disconnectNow(PeerId peer) {
    enet_peer_disconnect_now(peer, 0);
    firstSeen_.erase(peer);
}

std::vector<std::pair<PeerId, Link::Clock::time_point>> Link::unsettled() {
    const auto now = Clock::now();
    std::vector<std::pair<PeerId, Clock::time_point>> out;
    for (std::size_t i = 0; i < host_->peerCount; ++i) {
        ENetPeer* p = &host_->peers[i];
        if (!unsettledState(p->state)) {
            firstSeen_.erase(p);
            continue;
        }
        auto [it, fresh] = firstSeen_.try_emplace(p, p->connectID, now);
        if (!fresh && it->second.first != p->connectID) it->second = {p->connectID, now};
        out.emplace_back(p, it->second.second);
    }
    return out;
}

std::vector<std::string> Link::resetStaleHandshakes(double seconds) {
    std::vector<std::string> reset;
    const auto now = Clock::now();
    for (const auto& [peer, since] : unsettled()) {
        if (std::chrono::duration<double>(now - since).count() <= seconds) continue;
        reset.push_back(address(peer));
        enet_peer_reset(peer);
        firstSeen_.erase(peer);
    }
    return reset;
}

std::vector<std::pair<PeerId, double>> Link::handshakes() {
    std::vector<std::pair<PeerId, double>> out;
    const auto now = Clock::now();
    for (const auto& [peer, since] : unsettled()) {
        const ENetPeerState s = peer->state;
        if (s == ENET_PEER_STATE_DISCONNECT_LATER || s == ENET_PEER_STATE_DISCONNECTING ||
            s == ENET_PEER_STATE_ACKNOWLEDGING_DISCONNECT)
            continue; // leaving already
        out.emplace_back(peer, std::chrono::duration<double>(now - since).count());
    }
    return out;
}

void Link::reset(PeerId peer) {
    enet_peer_reset(peer);
    firstSeen_.erase(peer);
}

std::size_t Link::freeSlots() const {
    std::size_t free = 0;
    for (std::size_t i = 0; i < host_->peerCount; ++i)
        free += host_->peers[i].state == ENET_PEER_STATE_DISCONNECTED;
    return free;
}

std::optional<std::pair<std::string, std::uint16_t>> parseAddress(const std::string& text,
                                                                  std::uint16_t fallbackPort) {
    const auto colon = text.rfind(':');
    std::string host = text.substr(0, colon);
    std::uint16_t port = fallbackPort;
    if (colon != std::string::npos) {
        const std::string p = text.substr(colon + 1);
        unsigned v = 0;
        const auto [end, ec] = std::from_chars(p.data(), p.data() + p.size(), v);
        if (ec != std::errc() || end != p.data() + p.size() || v == 0 || v > 65535)
            return std::nullopt;
        port = static_cast<std::uint16_t>(v);
    }
    if (host.empty()) return std::nullopt;
    return std::make_pair(host, port);
}

} // namespace ui::net
