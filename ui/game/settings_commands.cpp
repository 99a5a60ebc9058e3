#include "ui/game/settings_commands.h"

#include "game/settings.h"

#include <string_view>

namespace ui {

std::vector<game::Command> settingCommands(const phys::WorldDef& before, const phys::WorldDef& after) {
    std::vector<game::Command> out;
    for (const game::SettingInfo& s : game::settings()) {
        if (std::string_view(s.name) == "planet") continue;
        const game::SettingValue now = game::readSetting(after, s.name);
        if (now == game::readSetting(before, s.name)) continue;
        game::Command c;
        c.kind = game::CommandKind::Set;
        c.text = s.name;
        c.value = now;
        out.push_back(std::move(c));
    }
    return out;
}

} // namespace ui
