// The home view of every shipped level: the cannons and targets are in it, and it shows
// nothing outside the level's bounds when they are wider than the view (what lies
// outside cannot be reached: a sandbox spawn there is refused). Camera arithmetic only.
#include "game/level.h"
#include "game/match.h"
#include "ui/game/match_view.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = fs::path(__FILE__).parent_path().parent_path().parent_path();

std::vector<fs::path> shippedLevels() {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(kRoot / "levels")) {
        const std::string name = e.path().filename().string();
        if (e.path().extension() == ".json" && !name.empty() && name[0] >= '0' && name[0] <= '9')
            files.push_back(e.path());
    }
    return files;
}

} // namespace

TEST(LevelCamera, TheHomeViewShowsTheLevelAndNothingOutsideIt) {
    const auto files = shippedLevels();
    ASSERT_GE(files.size(), 30u);
    for (const fs::path& f : files) {
        const game::Match m(game::loadLevel(f.string()));
        for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{1920, 1080}, std::pair{800, 800}}) {
            const ui::Camera c = ui::levelCamera(m, w, h);
            const phys::Vec2 lo = c.visibleMin(), hi = c.visibleMax();
            const game::Level& l = m.level();
            if (l.worldMax.x - l.worldMin.x >= hi.x - lo.x) {
                EXPECT_GE(lo.x, l.worldMin.x - 1e-9) << f.filename() << " at " << w << "x" << h;
                EXPECT_LE(hi.x, l.worldMax.x + 1e-9) << f.filename() << " at " << w << "x" << h;
            }
            for (const auto& cannon : m.cannons()) {
                EXPECT_GE(cannon.def.position.x, lo.x) << f.filename();
                EXPECT_LE(cannon.def.position.x, hi.x) << f.filename();
            }
            for (const auto& t : m.targets()) {
                EXPECT_GE(t.position.x, lo.x) << f.filename();
                EXPECT_LE(t.position.x, hi.x) << f.filename();
            }
        }
    }
}
