// The Match panel holds what the match has (a duel's computer line, a branch's note) in
// full, wherever a saved layout put it and however tall it was saved: a size saved in a
// practice level must not cut a duel's rewind slider off, nor push the panel off the
// bottom of the screen.
#include "headless_game.h"
#include "ui/game/match_view.h"
#include "ui/render/pixel_rect.h"

#include <gtest/gtest.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

TEST(MatchPanel, ADuelsPanelFitsWhatItHoldsWhateverSizeWasSaved) {
    const fs::path settings =
        fs::temp_directory_path() / ("artillery-match-panel-" + std::to_string(::getpid()));
    fs::remove_all(settings);
    fs::create_directories(settings);
    // What a practice level leaves at 1280x720: the panel as tall as its five rows.
    std::ofstream(settings / "imgui.ini") << "[Window][Match]\nPos=342,524\nSize=250,184\n\n"
                                             "[ArtilleryDisplay][Display]\nSize=1280,720\n";
    {
        test_game::HeadlessGame duel("10_duel.json", 1280, 720, settings);
        ASSERT_NE(duel.screen, nullptr);
        const ImGuiWindow* w = ImGui::FindWindowByName("Match");
        ASSERT_NE(w, nullptr);
        // Nothing scrolls out of sight: the panel is as tall as its content.
        EXPECT_EQ(w->ScrollMax.y, 0.0f) << "the rewind slider is cut off";
        EXPECT_GT(w->Size.y, 184.0f) << "a duel has one more line than a practice level";
        EXPECT_LE(w->Pos.y + w->Size.y, 720.0f) << "the panel runs off the bottom";
        EXPECT_GE(w->Pos.y, 0.0f);
    }
    fs::remove_all(settings);
}

// On a screen too narrow for both, the Physics and Stats panels at the top right open
// under the wind gauge, not over it; on a 720p one they stay at the top.
TEST(MatchPanel, TheTopRightPanelsOpenUnderTheWindGaugeOnANarrowScreen) {
    const fs::path settings =
        fs::temp_directory_path() / ("artillery-match-narrow-" + std::to_string(::getpid()));
    auto top = [&](int w, int h, const char* name) {
        fs::remove_all(settings);
        test_game::HeadlessGame game("03_windy_valley.json", w, h, settings);
        EXPECT_NE(game.screen, nullptr);
        const ImGuiWindow* panel = ImGui::FindWindowByName(name);
        EXPECT_NE(panel, nullptr) << name;
        return panel ? panel->Pos.y : -1.0f;
    };
    // 800x600: the HUD at 0.625 of its 1280x720 design, the gauge 68 x 0.625 = 42.5 deep.
    EXPECT_GE(top(800, 600, "Physics"), 42.5f);
    EXPECT_GE(top(800, 600, "Stats"), 42.5f + 34.0f);
    EXPECT_EQ(top(1280, 720, "Physics"), 10.0f);
    EXPECT_EQ(top(1280, 720, "Stats"), 44.0f);
    fs::remove_all(settings);
}

// The follow camera keeps the shot above the panels along the bottom: the Match panel as
// it opens (its top edge) and the aim readout (118 design pixels); moved up off the
// bottom, the Match panel is left out and the readout alone counts.
TEST(MatchPanel, TheCoveredBottomIsTheMatchPanelsTopWhereItOpens) {
    const fs::path settings =
        fs::temp_directory_path() / ("artillery-match-covered-" + std::to_string(::getpid()));
    fs::remove_all(settings);
    {
        test_game::HeadlessGame duel("36_bridge_duel.json", 1280, 720, settings);
        ASSERT_NE(duel.screen, nullptr);
        const ImGuiWindow* w = ImGui::FindWindowByName("Match");
        ASSERT_NE(w, nullptr);
        const ui::PixelRect rect{w->Pos.x, w->Pos.y, w->Pos.x + w->Size.x, w->Pos.y + w->Size.y};
        const double covered = ui::coveredBottom(rect, 1280.0, 720.0);
        EXPECT_DOUBLE_EQ(covered, (720.0 - w->Pos.y) / 720.0);
        EXPECT_GT(covered, 118.0 / 720.0) << "the Match panel stands taller than the readout";
        const ui::PixelRect movedUp{rect.x0, 100.0, rect.x1, 100.0 + (rect.y1 - rect.y0)};
        EXPECT_DOUBLE_EQ(ui::coveredBottom(movedUp, 1280.0, 720.0), 118.0 / 720.0);
        // At 4K the readout scales with the HUD: the same fraction.
        EXPECT_DOUBLE_EQ(ui::coveredBottom({}, 3840.0, 2160.0), 118.0 / 720.0);
    }
    fs::remove_all(settings);
}

// At home, as a level opens at 1280x720, nothing the player aims at or fires from lies
// under the Match panel: no target, no marked block or blob, no cannon. (With the band of
// soil at a fixed 22 % of the height, seven levels had a target under it, the campaign's
// first among them.)
TEST(MatchPanel, CoversNothingToAimAtOrFireFromAtHome) {
    const fs::path settings =
        fs::temp_directory_path() / ("artillery-match-home-" + std::to_string(::getpid()));
    for (const auto& entry : fs::directory_iterator(test_game::kRoot / "levels")) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".json" || name == "campaign.json") continue;
        fs::remove_all(settings);
        test_game::HeadlessGame game(name, 1280, 720, settings);
        ASSERT_NE(game.screen, nullptr);
        ASSERT_NE(game.screen->session(), nullptr) << name;
        const ImGuiWindow* w = ImGui::FindWindowByName("Match");
        ASSERT_NE(w, nullptr) << name;
        const ui::PixelRect panel{w->Pos.x, w->Pos.y, w->Pos.x + w->Size.x, w->Pos.y + w->Size.y};
        const game::Match& m = game.screen->session()->match();
        const ui::Camera& home = game.screen->camera();
        auto covered = [&](phys::Vec2 p, double radiusM, const std::string& what) {
            const phys::Vec2 c = home.toPixel(p);
            const double r = std::max(radiusM * home.pixelsPerMetre, 6.0);
            const ui::PixelRect box{c.x - r, c.y - r, c.x + r, c.y + r};
            EXPECT_FALSE(panel.overlaps(box))
                << name << ": the " << what << " at (" << p.x << ", " << p.y << ") m, " << c.x
                << ", " << c.y << " px, is under the Match panel (" << panel.x0 << ", " << panel.y0
                << ")-(" << panel.x1 << ", " << panel.y1 << ")";
        };
        for (const game::TargetState& t : m.targets())
            covered(t.position, t.def.radius, "target");
        for (const game::BlockState& b : m.blocks())
            if (b.def.target)
                covered(m.rigid().state(b.body).position,
                        0.5 * std::max(b.def.size.x, b.def.size.y), "marked block");
        for (const game::BlobState& b : m.blobs())
            if (b.def.target) covered(m.world().particles.position(b.center), b.def.radius, "blob");
        for (const game::CannonState& c : m.cannons())
            covered(c.def.position, game::kCannonRadius, "cannon");
    }
    fs::remove_all(settings);
}
