// A seat belongs to its token: while its player is connected and the match is on, a
// second join under the player's name (the default "guest" was both players' name)
// is refused, and the match plays through with its player. Three NetDuels over ENet on
// 127.0.0.1, each pumped by a thread of its own (a side's goodbye waits for the others'
// acknowledgements); the host and the player run no tick until the second join has had
// its answer, so it meets the match in progress, connected.
#include "ui/net/net_duel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

namespace {

const std::filesystem::path kRoot =
    std::filesystem::path(__FILE__).parent_path().parent_path().parent_path();

using ui::net::NetDuel;
using ui::net::NetOptions;
using ui::net::NetResult;

/// Pumps `duel` until it ends (or a minute passes): ticks only once `play` is set.
void pumpToTheEnd(NetDuel& duel, const std::atomic<bool>& play, std::atomic<bool>& started) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (duel.pump(5, play ? 240 : 0) && std::chrono::steady_clock::now() < until)
        if (duel.lockstep()) started = true;
}

TEST(NetSeat, ANameAloneNeverTakesASeatFromItsConnectedPlayer) {
    NetOptions host;
    host.host = true;
    host.levelFile = (kRoot / "levels/10_duel.json").string();
    host.port = 0;
    host.autoplay = true;
    host.name = "ada";
    NetDuel h(host);
    std::string why;
    ASSERT_TRUE(h.start(why)) << why;

    NetOptions bob;
    bob.host = false;
    bob.address = "127.0.0.1";
    bob.port = h.port();
    bob.levelsDir = (kRoot / "levels").string();
    bob.name = "bob";
    bob.autoplay = true;
    NetDuel b(bob);
    ASSERT_TRUE(b.start(why)) << why;

    std::atomic<bool> play{false}, hostStarted{false}, bobSeated{false};
    std::thread hostThread([&] { pumpToTheEnd(h, play, hostStarted); });
    std::thread bobThread([&] { pumpToTheEnd(b, play, bobSeated); });
    for (int i = 0; i < 1000 && !bobSeated; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_TRUE(bobSeated) << "the player joined";

    NetDuel impostor(bob); // the same name, no token
    ASSERT_TRUE(impostor.start(why)) << why;
    std::atomic<bool> never{false};
    pumpToTheEnd(impostor, play, never);
    EXPECT_EQ(impostor.result(), NetResult::Refused) << impostor.message();
    EXPECT_EQ(impostor.message().rfind("the host refused: the seat is bob's; a rejoin presents "
                                       "the seat token the host gave at the first join",
                                       0),
              0u)
        << impostor.message();
    EXPECT_FALSE(never) << "the second join never saw the match";

    play = true;
    hostThread.join();
    bobThread.join();
    EXPECT_EQ(h.result(), NetResult::Over) << h.message();
    EXPECT_EQ(b.result(), NetResult::Over) << b.message();
    ASSERT_NE(h.lockstep(), nullptr);
    ASSERT_NE(b.lockstep(), nullptr);
    EXPECT_EQ(h.lockstep()->match().hash(), b.lockstep()->match().hash());
    EXPECT_EQ(h.playerName(1), "bob");
}

} // namespace
