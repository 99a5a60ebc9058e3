// A hostile peer for the network tests: a scripted ENet client that tries to hold the
// host's door shut from another loopback address (all of 127.0.0.0/8 is this machine),
// while a real player joins from 127.0.0.1.
//
// usage: intruder --to PORT --from ADDR --seconds S MODE
//   --silent N        N connections that finish ENet's handshake, then say nothing
//   --flood N         every 0.25 s a new socket sends N CONNECTs and never answers the
//                     host again (each would hold a slot in ENet's handshake)
//   --impostor NAME   a join under a player's name, without the seat's token
//   --spectators N    N spectators' hellos (the host takes a few)
// Prints what happened to each connection, one line each, and a summary line; exits 0
// when it ran (the test reads the lines), 2 on bad usage.
#include "game/net/message.h"

#include <enet/enet.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

struct Options {
    std::uint16_t port = 0;
    std::string from = "127.0.0.2";
    double seconds = 20.0;
    std::string mode;
    int count = 1;
    std::string name;
};

double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

ENetHost* socketFrom(const std::string& from, std::size_t peers) {
    ENetAddress local{};
    enet_address_set_host_ip(&local, from.c_str());
    local.port = 0;
    ENetHost* host = enet_host_create(&local, peers, 1, 0, 0);
    if (!host) {
        std::fprintf(stderr, "intruder: cannot bind %s\n", from.c_str());
        std::exit(2);
    }
    return host;
}

ENetAddress hostAddress(const Options& o) {
    ENetAddress to{};
    enet_address_set_host_ip(&to, "127.0.0.1");
    to.port = o.port;
    return to;
}

void send(ENetPeer* peer, const game::net::Message& m) {
    const std::vector<std::uint8_t> bytes = game::net::encode(m);
    enet_peer_send(peer, 0, enet_packet_create(bytes.data(), bytes.size(), ENET_PACKET_FLAG_RELIABLE));
}

std::optional<game::net::Message> decoded(const ENetEvent& e) {
    game::net::Decoded d = game::net::decode(e.packet->data, e.packet->dataLength);
    enet_packet_destroy(e.packet);
    return d.message;
}

/// N connections that complete the handshake, hear the offer and say nothing.
void silent(const Options& o) {
    ENetHost* host = socketFrom(o.from, static_cast<std::size_t>(o.count));
    const ENetAddress to = hostAddress(o);
    std::map<ENetPeer*, int> index;
    std::map<ENetPeer*, Clock::time_point> connectedAt;
    for (int k = 0; k < o.count; ++k) index[enet_host_connect(host, &to, 1, 0)] = k;
    int connected = 0, dropped = 0, turnedAway = 0;
    double longest = 0.0;
    bool settled = false;
    const auto start = Clock::now();
    while (since(start) < o.seconds && (connected == 0 || dropped < connected)) {
        if (!settled && since(start) > 1.5) {
            // Loopback answers in milliseconds: a CONNECT not answered by now was turned
            // away (it would be retried for ENet's timeout, and get in once the host has
            // dropped the others: a later, separate attempt).
            settled = true;
            for (const auto& [peer, k] : index)
                if (!connectedAt.count(peer)) {
                    enet_peer_reset(peer);
                    ++turnedAway;
                    std::printf("silent %d: no slot\n", k);
                }
        }
        ENetEvent e;
        while (enet_host_service(host, &e, 20) > 0) {
            if (e.type == ENET_EVENT_TYPE_CONNECT) {
                ++connected;
                connectedAt[e.peer] = Clock::now();
                std::printf("silent %d: connected, says nothing\n", index[e.peer]);
            } else if (e.type == ENET_EVENT_TYPE_DISCONNECT && connectedAt.count(e.peer)) {
                const double held = since(connectedAt[e.peer]);
                longest = std::max(longest, held);
                ++dropped;
                std::printf("silent %d: disconnected by the host after %.1f s\n", index[e.peer], held);
            } else if (e.type == ENET_EVENT_TYPE_RECEIVE) {
                enet_packet_destroy(e.packet); // the offer: not answered
            }
        }
    }
    std::printf("silent: %d connected, %d turned away, %d disconnected by the host, held at "
                "most %.1f s\n",
                connected, turnedAway, dropped, longest);
    enet_host_destroy(host);
}

/// New sockets every 0.25 s, each sending N CONNECTs it never follows up: the host's
/// VERIFY_CONNECTs are never acknowledged.
void flood(const Options& o) {
    const ENetAddress to = hostAddress(o);
    std::vector<ENetHost*> sockets;
    long sent = 0;
    const auto start = Clock::now();
    while (since(start) < o.seconds && sockets.size() < 64) {
        ENetHost* host = socketFrom(o.from, static_cast<std::size_t>(o.count));
        for (int k = 0; k < o.count; ++k)
            if (enet_host_connect(host, &to, 1, 0)) ++sent;
        enet_host_flush(host); // the CONNECTs go out; nothing is serviced again
        sockets.push_back(host);
        std::this_thread::sleep_for(std::chrono::milliseconds(250));
    }
    std::printf("flood: %ld CONNECTs from %s on %zu sockets, never acknowledged\n", sent,
                o.from.c_str(), sockets.size());
    for (ENetHost* h : sockets)
        enet_host_destroy(h);
}

/// Waits for the host's offer on a connection; false when none came in time.
bool awaitOffer(ENetHost* host, const Options& o, game::net::Message& offer) {
    const auto start = Clock::now();
    ENetEvent e;
    while (since(start) < o.seconds)
        while (enet_host_service(host, &e, 20) > 0)
            if (e.type == ENET_EVENT_TYPE_RECEIVE)
                if (auto m = decoded(e); m && m->type == game::net::MessageType::Offer) {
                    offer = *m;
                    return true;
                }
    return false;
}

game::net::Message helloFor(const game::net::Message& offer, const std::string& name, bool spectator) {
    game::net::Message hello;
    hello.type = game::net::MessageType::Hello;
    hello.version = game::net::kProgramVersion;
    hello.levelHash = offer.levelHash;
    hello.name = name;
    hello.spectator = spectator;
    return hello;
}

/// The host's answer to a hello: "welcomed as cannon C", "refused: REASON" or "closed".
std::string answer(ENetHost* host, ENetPeer* peer, const Options& o) {
    const auto start = Clock::now();
    ENetEvent e;
    while (since(start) < o.seconds)
        while (enet_host_service(host, &e, 20) > 0) {
            if (e.peer != peer) {
                if (e.type == ENET_EVENT_TYPE_RECEIVE) enet_packet_destroy(e.packet);
                continue;
            }
            if (e.type == ENET_EVENT_TYPE_DISCONNECT) return "closed";
            if (e.type != ENET_EVENT_TYPE_RECEIVE) continue;
            const auto m = decoded(e);
            if (!m) continue;
            if (m->type == game::net::MessageType::Refuse) return "refused: " + m->reason;
            if (m->type == game::net::MessageType::Welcome)
                return "welcomed as cannon " + std::to_string(m->cannon);
        }
    return "no answer";
}

/// A player's name without the seat's token.
int impostor(const Options& o) {
    ENetHost* host = socketFrom(o.from, 1);
    const ENetAddress to = hostAddress(o);
    ENetPeer* peer = enet_host_connect(host, &to, 1, 0);
    game::net::Message offer;
    if (!awaitOffer(host, o, offer)) {
        std::printf("impostor %s: no offer\n", o.name.c_str());
        return 0;
    }
    send(peer, helloFor(offer, o.name, false));
    std::printf("impostor %s: %s\n", o.name.c_str(), answer(host, peer, o).c_str());
    enet_host_destroy(host);
    return 0;
}

/// N spectators at once, each on its own socket.
int spectators(const Options& o) {
    int welcomed = 0, refused = 0;
    std::vector<ENetHost*> sockets;
    for (int k = 0; k < o.count; ++k) {
        ENetHost* host = socketFrom(o.from, 1);
        sockets.push_back(host);
        const ENetAddress to = hostAddress(o);
        ENetPeer* peer = enet_host_connect(host, &to, 1, 0);
        game::net::Message offer;
        if (!awaitOffer(host, o, offer)) continue;
        send(peer, helloFor(offer, "eve" + std::to_string(k), true));
        const std::string said = answer(host, peer, o);
        std::printf("spectator %d: %s\n", k, said.c_str());
        welcomed += said.rfind("welcomed", 0) == 0;
        refused += said.rfind("refused", 0) == 0;
    }
    std::printf("spectators: %d welcomed, %d refused\n", welcomed, refused);
    for (ENetHost* h : sockets)
        enet_host_destroy(h);
    return 0;
}

[[noreturn]] void usage() {
    std::fprintf(stderr, "usage: intruder --to PORT [--from ADDR] [--seconds S] "
                         "(--silent N | --flood N | --impostor NAME | --spectators N)\n");
    std::exit(2);
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string a = argv[i], v = argv[i + 1];
        if (a == "--to") o.port = static_cast<std::uint16_t>(std::atoi(v.c_str()));
        else if (a == "--from") o.from = v;
        else if (a == "--seconds") o.seconds = std::atof(v.c_str());
        else if (a == "--silent" || a == "--flood" || a == "--spectators")
            o.mode = a.substr(2), o.count = std::atoi(v.c_str());
        else if (a == "--impostor") o.mode = "impostor", o.name = v;
        else usage();
    }
    if (o.port == 0 || o.mode.empty() || o.count < 1) usage();
    if (enet_initialize() != 0) return 2;
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    int code = 0;
    if (o.mode == "silent") silent(o);
    if (o.mode == "flood") flood(o);
    if (o.mode == "impostor") code = impostor(o);
    if (o.mode == "spectators") code = spectators(o);
    enet_deinitialize();
    return code;
}
