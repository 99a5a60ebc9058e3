// A lossy relay for the network tests: UDP datagrams between one client and a server
// on 127.0.0.1, each delayed by a random time (so they arrive reordered) or dropped,
// from a seeded generator. ENet must deliver the commands reliably and in order anyway;
// the tests check that the match's result does not change.
//
// usage: relay --to PORT [--drop P] [--delay-ms MAX] [--seed N] [--seconds S]
// Prints "relay on 127.0.0.1:PORT" once bound (port chosen by the system), then runs
// until S seconds pass or nothing has moved for 15 s.
#include <arpa/inet.h>
#include <csignal>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <queue>
#include <random>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t stopRequested = 0;
void requestStop(int) {
    stopRequested = 1;
}

struct Datagram {
    Clock::time_point due;
    bool toServer;
    std::vector<char> bytes;
    bool operator>(const Datagram& o) const { return due > o.due; }
};

sockaddr_in loopback(unsigned short port) {
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_port = htons(port);
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    return a;
}

int udpSocket(unsigned short port) {
    const int s = socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in a = loopback(port);
    if (s < 0 || bind(s, reinterpret_cast<sockaddr*>(&a), sizeof a) != 0) {
        std::perror("relay: bind");
        std::exit(2);
    }
    return s;
}

} // namespace

int main(int argc, char** argv) {
    unsigned short to = 0;
    double drop = 0.1, seconds = 120.0;
    int delayMs = 40;
    unsigned long long seed = 1;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string k = argv[i];
        const char* v = argv[i + 1];
        if (k == "--to")
            to = static_cast<unsigned short>(std::atoi(v));
        else if (k == "--drop")
            drop = std::atof(v);
        else if (k == "--delay-ms")
            delayMs = std::atoi(v);
        else if (k == "--seed")
            seed = std::strtoull(v, nullptr, 10);
        else if (k == "--seconds")
            seconds = std::atof(v);
        else {
            std::fprintf(stderr, "relay: unknown option %s\n", k.c_str());
            return 2;
        }
    }
    if (to == 0) {
        std::fprintf(stderr, "relay: --to PORT is required\n");
        return 2;
    }
    // One socket faces the client, one the server (so the server sees one peer).
    const int front = udpSocket(0), back = udpSocket(0);
    sockaddr_in bound{};
    socklen_t len = sizeof bound;
    getsockname(front, reinterpret_cast<sockaddr*>(&bound), &len);
    std::printf("relay on 127.0.0.1:%u\n", ntohs(bound.sin_port));
    std::fflush(stdout);

    const sockaddr_in server = loopback(to);
    sockaddr_in client{};
    bool haveClient = false;
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::priority_queue<Datagram, std::vector<Datagram>, std::greater<>> queue;
    const auto start = Clock::now();
    auto lastTraffic = start;
    long forwarded = 0, dropped = 0;
    std::signal(SIGTERM, requestStop);
    while (!stopRequested && Clock::now() - start < std::chrono::duration<double>(seconds) &&
           Clock::now() - lastTraffic < std::chrono::seconds(15)) {
        pollfd fds[2] = {{front, POLLIN, 0}, {back, POLLIN, 0}};
        poll(fds, 2, 1);
        for (int i = 0; i < 2; ++i) {
            if (!(fds[i].revents & POLLIN)) continue;
            std::vector<char> buf(65536);
            sockaddr_in from{};
            socklen_t fl = sizeof from;
            const ssize_t n = recvfrom(fds[i].fd, buf.data(), buf.size(), 0,
                                       reinterpret_cast<sockaddr*>(&from), &fl);
            if (n < 0) continue;
            lastTraffic = Clock::now();
            if (i == 0) {
                client = from; // the client may come back from a new port
                haveClient = true;
            }
            if (u(rng) < drop) {
                ++dropped;
                continue;
            }
            buf.resize(static_cast<std::size_t>(n));
            const auto lag =
                std::chrono::microseconds(static_cast<long>(u(rng) * delayMs * 1000.0));
            queue.push({Clock::now() + lag, i == 0, std::move(buf)});
        }
        while (!queue.empty() && queue.top().due <= Clock::now()) {
            const Datagram& d = queue.top();
            if (d.toServer)
                sendto(back, d.bytes.data(), d.bytes.size(), 0,
                       reinterpret_cast<const sockaddr*>(&server), sizeof server);
            else if (haveClient)
                sendto(front, d.bytes.data(), d.bytes.size(), 0,
                       reinterpret_cast<const sockaddr*>(&client), sizeof client);
            ++forwarded;
            queue.pop();
        }
    }
    std::printf("relay: forwarded %ld, dropped %ld\n", forwarded, dropped);
    close(front);
    close(back);
    return 0;
}
