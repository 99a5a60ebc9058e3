// The live physics settings, by name: the one table the UI's controls, the `set`
// command of scripts and replays, and the settings file all go through, so a change
// made in the window is a command a replay can carry.
#pragma once

#include "physics/world.h"

#include <span>
#include <string>
#include <variant>

namespace game {

/// A setting's value as typed in a script or chosen in the UI.
using SettingValue = std::variant<double, bool, std::string>;

struct SettingInfo {
    const char* name;
    const char* unit;        ///< "" when dimensionless
    const char* help;
    enum class Kind { Number, Boolean, Choice } kind;
    double min = 0.0, max = 0.0; ///< for numbers
};

/// Every live setting.
std::span<const SettingInfo> settings();
const SettingInfo* findSetting(const std::string& name);

/// Applies `value` to the setting `name` of def. Returns "" when applied, otherwise the
/// reason it was refused (unknown name, wrong type, out of range, with the range); def
/// is unchanged when refused.
std::string applySetting(phys::WorldDef& def, const std::string& name, const SettingValue& value);

/// Current value of a setting, for display and for settings files.
SettingValue readSetting(const phys::WorldDef& def, const std::string& name);

std::string describe(const SettingValue& v);

} // namespace game
