#include "ui/net/enet_link.h"

#include <enet/enet.h>

#include <charconv>

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

} // namespace

std::unique_ptr<Link> Link::listen(const std::string& bindAddress, std::uint16_t port,
                                   std::size_t maxPeers, std::string& why) {
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
    ENetHost* host = enet_host_create(&address, maxPeers, 1, 0, 0);
    if (!host) {
        why = "cannot listen on " + bindAddress + ":" + std::to_string(port) + " (port in use?)";
        return nullptr;
    }
    limit(host);
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
