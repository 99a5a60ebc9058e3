// The aim a player edits, seen on the other side as it moves: the sender sends a change
// at most 20 times a second and the same aim again while held; the receiver shows the
// last one while fresh and while the turn is the sender's.
#include "game/net/peer_aim.h"

#include <gtest/gtest.h>

namespace game::net {

TEST(PeerAim, AChangingAimIsSentAtMostTwentyTimesASecondAndAHeldOneRefreshed) {
    AimSharing out;
    const AimSeen a{40.0, 30.0}, b{41.0, 30.0};
    EXPECT_FALSE(out.due(std::nullopt, 0.0)) << "not editing: nothing";
    EXPECT_TRUE(out.due(a, 0.0));
    EXPECT_FALSE(out.due(b, 0.02)) << "a change 20 ms later waits";
    EXPECT_TRUE(out.due(b, 0.06));
    EXPECT_FALSE(out.due(b, 0.3)) << "held: nothing new";
    EXPECT_TRUE(out.due(b, 0.47)) << "held for 0.4 s: sent again, so it stays fresh";
    EXPECT_FALSE(out.due(std::nullopt, 0.5));
    EXPECT_TRUE(out.due(b, 0.56)) << "a new edit is news, even the same aim";
}

TEST(PeerAim, TheLastAimHeardShowsWhileFreshAndWhileItIsTheSendersTurn) {
    PeerAim in;
    EXPECT_FALSE(in.shown(1, 0.0));
    in.heard({120.0, 55.0}, 1, 10.0);
    ASSERT_TRUE(in.shown(1, 10.5));
    EXPECT_EQ(*in.shown(1, 10.5), (AimSeen{120.0, 55.0}));
    EXPECT_FALSE(in.shown(0, 10.5)) << "the turn passed";
    EXPECT_FALSE(in.shown(1, 11.2)) << "stale after a second: the player let go";
}

} // namespace game::net
