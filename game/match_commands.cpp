#include "game/match.h"

#include "game/weapons.h"

#include <algorithm>

// The commands a match takes (aim, power, select, fire, end turn, set, assist, sandbox
// and its tools): each checked, applied or refused with one line the player can read.

namespace game {

using phys::kNoParticle;
using phys::RigidWorldDef;

std::string Match::refuse(const Command& cmd, std::string why) {
    emit(EventKind::Refused, current_, {}, 0.0, std::string(commandName(cmd.kind)) + ": " + why);
    return why;
}

std::string Match::apply(const Command& cmd) {
    CannonState& c = cannons_[static_cast<std::size_t>(current_)];
    switch (cmd.kind) {
    case CommandKind::Aim:
        if (!(cmd.number >= -180.0 && cmd.number <= 180.0))
            return refuse(cmd, "angle must be in [-180, 180] degrees");
        c.angleDeg = cmd.number;
        return "";
    case CommandKind::Power:
        if (!(cmd.number >= 0.0 && cmd.number <= c.def.maxSpeedMps))
            return refuse(cmd, "muzzle speed must be in [0, " + std::to_string(c.def.maxSpeedMps) +
                                   "] m/s for this cannon");
        c.speedMps = cmd.number;
        return "";
    case CommandKind::Select: return select(cmd);
    case CommandKind::Fire:
        if (over_) return refuse(cmd, "the match is over");
        if (shell_ != kNoParticle) return refuse(cmd, "a shell is still in flight");
        if (c.shotsLeft <= 0 && !sandbox()) return refuse(cmd, "no shots left");
        if (c.projectile < c.ammoLeft.size() && c.ammoLeft[c.projectile] == 0 && !sandbox())
            return refuse(cmd, "no " + c.def.projectiles[c.projectile] + " left");
        fire();
        return "";
    case CommandKind::EndTurn:
        if (over_) return refuse(cmd, "the match is over");
        if (shell_ != kNoParticle) return refuse(cmd, "wait until the shell lands");
        nextTurn();
        return "";
    case CommandKind::Set: return set(cmd);
    case CommandKind::Assist: {
        // A learning aid in view: the result can no longer earn the third star.
        const int bit = cmd.text == "hint" ? kAssistHint : cmd.text == "preview" ? kAssistPreview : 0;
        if (bit == 0) return refuse(cmd, "expected preview or hint, got \"" + cmd.text + "\"");
        if (!(assisted_ & bit)) emit(EventKind::SettingChanged, current_, {}, 0.0, "assist = " + cmd.text);
        assisted_ |= bit;
        return "";
    }
    case CommandKind::Sandbox:
        if (sandbox()) return refuse(cmd, "the level is already a sandbox");
        level_.mode = Mode::Sandbox;
        over_ = false;
        emit(EventKind::SettingChanged, current_, {}, 0.0, "mode = sandbox");
        return "";
    case CommandKind::Spawn:
    case CommandKind::Grab:
    case CommandKind::Drag:
    case CommandKind::Release: return sandboxTool(cmd);
    }
    return refuse(cmd, "unknown command");
}

std::string Match::select(const Command& cmd) {
    CannonState& c = cannons_[static_cast<std::size_t>(current_)];
    const auto& list = c.def.projectiles;
    const auto it = std::find(list.begin(), list.end(), cmd.text);
    if (it == list.end()) {
        // A weapon or ball by name that this level does not offer (the window's fixed
        // weapon keys send these): one short line the player can read at a glance.
        if (knownProjectile(cmd.text)) return refuse(cmd, "this level has no " + cmd.text);
        std::string names;
        for (const auto& n : list) names += (names.empty() ? "" : ", ") + n;
        return refuse(cmd, "this cannon fires " + names + ", not \"" + cmd.text + "\"");
    }
    // A name the level lists but no preset or weapon has would fire a shell of nothing.
    if (!knownProjectile(cmd.text)) return refuse(cmd, "\"" + cmd.text + "\" is not a projectile or weapon");
    c.projectile = static_cast<std::size_t>(it - list.begin());
    return "";
}

std::string Match::set(const Command& cmd) {
    LiveSettings live = liveSettings();
    if (std::string why = applySetting(live, cmd.text, cmd.value); !why.empty()) return refuse(cmd, why);
    world_.setDef(live.world);
    world_.materials = std::move(live.materials); // its pair cache is rebuilt: next contact
    RigidWorldDef rd = rigid_->def();
    rd.gravity = live.world.forces.gravity;
    rigid_->setDef(rd);
    emit(EventKind::SettingChanged, current_, {}, 0.0, cmd.text + " = " + describe(cmd.value));
    return "";
}

std::string Match::sandboxTool(const Command& cmd) {
    if (!sandbox())
        return refuse(cmd, "only in the sandbox (open the level as a sandbox, or send \"sandbox\" first)");
    std::string why;
    switch (cmd.kind) {
    case CommandKind::Spawn: why = spawn(cmd); break;
    case CommandKind::Grab: why = grabAt(cmd.at); break;
    case CommandKind::Drag:
        if (grab_.kind == GrabState::Kind::None) why = "nothing is grabbed";
        else dragTo(cmd.at);
        break;
    default:
        if (grab_.kind == GrabState::Kind::None) why = "nothing is grabbed";
        else release();
        break;
    }
    if (why.empty()) stirred_ = stirred_ || cmd.kind == CommandKind::Spawn || cmd.kind == CommandKind::Grab;
    return why.empty() ? why : refuse(cmd, why);
}

} // namespace game
