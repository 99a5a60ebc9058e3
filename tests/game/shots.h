// Shared steps of the tests that play a shipped level: load it, make a command, fire.
#pragma once

#include "game/command.h"
#include "game/level.h"
#include "game/match.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace shots {

inline game::Level level(const std::string& name) {
    return game::loadLevel(
        (std::filesystem::path(ARTILLERY_SOURCE_DIR) / "levels" / name).string());
}

inline game::Command cmd(game::CommandKind k, double number = 0.0, std::string text = {}) {
    game::Command c;
    c.kind = k;
    c.number = number;
    c.text = std::move(text);
    return c;
}

/// Aims, powers and fires the current cannon.
inline void shoot(game::Match& m, double angleDeg, double speedMps) {
    ASSERT_EQ(m.apply(cmd(game::CommandKind::Aim, angleDeg)), "");
    ASSERT_EQ(m.apply(cmd(game::CommandKind::Power, speedMps)), "");
    ASSERT_EQ(m.apply(cmd(game::CommandKind::Fire)), "");
}

} // namespace shots
