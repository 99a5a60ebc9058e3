// A key pressed and let go between two frames is seen pressed for one frame by ImGui
// 1.86: its release is held back to the frame after.
#include "ui/platform/key_taps.h"

#include <gtest/gtest.h>

namespace {

SDL_Event key(Uint32 type, SDL_Scancode code) {
    SDL_Event e{};
    e.type = type;
    e.key.keysym.scancode = code;
    return e;
}

} // namespace

TEST(KeyTaps, AQuickTapsReleaseWaitsForTheFrameAfterTheOneThatSeesItDown) {
    ui::KeyTaps taps;
    // Frame 1's events: Enter down and up before the frame begins.
    EXPECT_FALSE(taps.holdBack(key(SDL_KEYDOWN, SDL_SCANCODE_RETURN)));
    EXPECT_TRUE(taps.holdBack(key(SDL_KEYUP, SDL_SCANCODE_RETURN)));
    EXPECT_TRUE(taps.releasesDue().empty()) << "frame 1 sees Enter down";
    const std::vector<SDL_Event> due = taps.releasesDue(); // frame 2 begins
    ASSERT_EQ(due.size(), 1u);
    EXPECT_EQ(due[0].type, SDL_KEYUP);
    EXPECT_EQ(due[0].key.keysym.scancode, SDL_SCANCODE_RETURN);
    EXPECT_TRUE(taps.releasesDue().empty());
}

TEST(KeyTaps, AKeyHeldAcrossAFrameIsReleasedAtOnce) {
    ui::KeyTaps taps;
    EXPECT_FALSE(taps.holdBack(key(SDL_KEYDOWN, SDL_SCANCODE_SPACE)));
    EXPECT_TRUE(taps.releasesDue().empty()); // a frame with Space down
    EXPECT_FALSE(taps.holdBack(key(SDL_KEYUP, SDL_SCANCODE_SPACE)));
    EXPECT_FALSE(taps.holdBack(key(SDL_KEYUP, SDL_SCANCODE_A))) << "never pressed here";
}
