// The live physics settings, by name: the one table the UI's controls, the `set`
// command of scripts and replays, `artillery run --help` and the README all go through,
// so a change made in the window is a command a replay can carry. Names, ranges, help
// and the refusal messages ("restitution.golf-ball expects a preset name (golf, ...) or
// a number in [0, 1], got 1.3") all come from the table in settings.cpp.
//
// Two entries are families: "restitution.PROJECTILE" (one setting per projectile
// preset: restitution.golf-ball, ...) and "pair.MATERIAL.MATERIAL" (one per pair of
// materials: pair.golf-ball.earth, ...).
#pragma once

#include "physics/projectiles.h"
#include "physics/world.h"

#include <span>
#include <string>
#include <variant>
#include <vector>

namespace game {

/// A setting's value as typed in a script or chosen in the UI.
using SettingValue = std::variant<double, bool, std::string>;

/// What the live settings change: the world's definition and its material table (the
/// restitution each projectile bounces with, pairs with values of their own). A match's
/// are its world's; a default one holds the defaults (for checking a script on load).
struct LiveSettings {
    phys::WorldDef world;
    phys::MaterialTable materials;
};

/// What a match's material controls show: the projectiles in play and the materials
/// that can touch (Match::materialsInPlay()).
struct MaterialsInPlay {
    std::vector<std::string> projectiles;   ///< what the cannons fire (every preset in a sandbox)
    std::vector<phys::MaterialId> moving;   ///< of those projectiles, then of particles alive now
    std::vector<phys::MaterialId> surfaces; ///< of the static shapes (terrain, obstacles)
};

struct SettingInfo {
    /// The name, or a family's pattern ("restitution.PROJECTILE"): the part up to the
    /// first dot is fixed, the rest names a projectile or two materials.
    const char* name;
    const char* unit;        ///< "" when dimensionless
    const char* help;
    enum class Kind {
        Number,         ///< a number in [min, max]
        Boolean,        ///< true or false
        Choice,         ///< one of settingChoices()
        ChoiceOrNumber, ///< one of settingChoices(), or a number in [min, max]
    } kind;
    double min = 0.0, max = 0.0; ///< for numbers
    /// ChoiceOrNumber: what the names are, for messages ("a preset name"); null: quoted.
    const char* choiceNoun = nullptr;
};

/// Every live setting.
std::span<const SettingInfo> settings();
/// The entry for a name ("tick_hz"; a family's for "restitution.golf-ball"), or null
/// when no setting has that name (a family's suffix must name a projectile or materials).
const SettingInfo* findSetting(const std::string& name);
/// The names a Choice or ChoiceOrNumber setting takes, in the order a menu lists them.
std::vector<std::string> settingChoices(const SettingInfo& s);
/// What a setting takes, as refusals say it: "a number in [10, 2000] Hz", "true or
/// false", "one of impulse, penalty, none", "a preset name (golf, ...) or a number in [0, 1]".
std::string expectation(const SettingInfo& s);

/// Every setting of `s` by its concrete name, in the table's order: the world's, then
/// restitution.<projectile> for every projectile preset, then pair.<a>.<b> for each pair
/// of materials with an entry of its own.
std::vector<std::string> settingNames(const LiveSettings& s);

/// Applies `value` to the setting `name`. Returns "" when applied, otherwise why it was
/// refused (unknown name, wrong type, out of range: with what was expected); `s` is
/// unchanged when refused. Material changes take effect at the next contact.
std::string applySetting(LiveSettings& s, const std::string& name, const SettingValue& value);
/// The same on a world definition alone (the demo scene, tests): a material setting is
/// checked against the default table, which is then thrown away.
std::string applySetting(phys::WorldDef& def, const std::string& name, const SettingValue& value);

/// Current value of a setting, for display, for the panel's diffs and for settings files.
/// restitution.<p> reads as the preset's name when the value is a preset's, else the
/// number; pair.<a>.<b> reads as the pair's own e, or "combine" when it has none.
SettingValue readSetting(const LiveSettings& s, const std::string& name);
SettingValue readSetting(const phys::WorldDef& def, const std::string& name);

/// The material a projectile bounces with: the table's material of the projectile's own
/// name, added as a copy of the preset's material when missing, so that
/// restitution.cannonball changes cannonballs and not the steel balls of the same metal.
phys::MaterialId projectileMaterial(phys::MaterialTable& table, const phys::ProjectilePreset& p);
/// Without adding: the preset's own material while the table has no copy yet.
phys::MaterialId projectileMaterial(const phys::MaterialTable& table, const phys::ProjectilePreset& p);

std::string describe(const SettingValue& v);

/// One entry per setting (name, what it takes, unit, help), for --help.
std::string settingsHelp();

} // namespace game
