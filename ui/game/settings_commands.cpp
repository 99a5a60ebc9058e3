#include "ui/game/settings_commands.h"

#include <algorithm>

namespace ui {

std::vector<game::Command> settingCommands(const game::LiveSettings& before,
                                           const game::LiveSettings& after) {
    // The names of both sides: a pair with a value of its own in `before` only has been
    // given back to the rule.
    std::vector<std::string> names = game::settingNames(after);
    for (const std::string& n : game::settingNames(before))
        if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
    std::vector<game::Command> out;
    for (const std::string& name : names) {
        if (name == "planet") continue;
        const game::SettingValue now = game::readSetting(after, name);
        if (now == game::readSetting(before, name)) continue;
        game::Command c;
        c.kind = game::CommandKind::Set;
        c.text = name;
        c.value = now;
        out.push_back(std::move(c));
    }
    return out;
}

std::vector<game::Command> settingCommands(const phys::WorldDef& before, const phys::WorldDef& after) {
    return settingCommands(game::LiveSettings{before, {}}, game::LiveSettings{after, {}});
}

} // namespace ui
