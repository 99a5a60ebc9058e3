#include "ui/game/turn_controls.h"

#include "ui/game/weapon_look.h"

namespace ui {

std::optional<std::vector<game::Command>> pressTurnKey(SDL_Keycode key, AimInput& aim,
                                                       const game::Match& m, std::string* message) {
    const game::CannonState& c = m.cannon();
    auto selected = [](std::optional<game::Command> s) {
        return s ? std::vector<game::Command>{*s} : std::vector<game::Command>{};
    };
    switch (key) {
    case SDLK_SPACE:
        if (!m.shell()) aim.startCharge();
        return std::vector<game::Command>{};
    case SDLK_RETURN:
    case SDLK_KP_ENTER:
    case SDLK_f:
        return aim.fire(c);
    case SDLK_e:
        return std::vector<game::Command>{AimInput::endTurn()};
    case SDLK_TAB: {
        const auto ball = nextBall(c);
        return selected(ball ? AimInput::select(c, *ball) : std::nullopt);
    }
    case SDLK_LEFT:
    case SDLK_RIGHT:
    case SDLK_UP:
    case SDLK_DOWN: {
        // A tap steps once, at once: a tap shorter than a frame still counts.
        if (m.shell()) return std::vector<game::Command>{};
        const bool fine = (SDL_GetModState() & KMOD_SHIFT) != 0;
        const int angle = key == SDLK_LEFT ? 1 : key == SDLK_RIGHT ? -1 : 0;
        const int power = key == SDLK_UP ? 1 : key == SDLK_DOWN ? -1 : 0;
        aim.step(angle, power, fine, c.def.maxSpeedMps);
        return std::vector<game::Command>{};
    }
    default:
        if (key >= SDLK_1 && key <= SDLK_8) {
            // A weapon's own number, whatever the level's list (docs/weapons.md's order).
            std::string why;
            const auto weapon = weaponByKey(c, static_cast<int>(key - SDLK_1) + 1, why);
            if (!weapon && message) *message = why;
            return selected(weapon ? AimInput::select(c, *weapon) : std::nullopt);
        }
        return std::nullopt;
    }
}

std::vector<game::Command> releaseTurnKey(SDL_Keycode key, AimInput& aim, const game::Match& m) {
    if (key != SDLK_SPACE || !aim.charging()) return {};
    return aim.releaseCharge(m.cannon());
}

bool dragToAim(const SDL_Event& e, AimInput& aim, const game::Match& m, bool myTurn,
               phys::Vec2 pivotPx, phys::Vec2 pixelsPerPoint, std::vector<game::Command>& out) {
    const double maxSpeed = m.cannon().def.maxSpeedMps;
    auto pixels = [&](int x, int y) { return phys::Vec2{x * pixelsPerPoint.x, y * pixelsPerPoint.y}; };
    if (e.type == SDL_MOUSEBUTTONDOWN && e.button.button == SDL_BUTTON_LEFT) {
        if (myTurn && !m.shell()) aim.beginDrag(pivotPx, pixels(e.button.x, e.button.y), maxSpeed);
        return true;
    }
    if (e.type == SDL_MOUSEBUTTONUP && e.button.button == SDL_BUTTON_LEFT) {
        out = aim.endDrag(m.cannon());
        return true;
    }
    if (e.type == SDL_MOUSEMOTION && aim.dragging()) {
        aim.dragTo(pivotPx, pixels(e.motion.x, e.motion.y), maxSpeed);
        return true;
    }
    return false;
}

HeldAxes heldArrowKeys() {
    const Uint8* keys = SDL_GetKeyboardState(nullptr);
    auto down = [&](SDL_Scancode k) { return keys[k] ? 1.0 : 0.0; };
    const double fine = down(SDL_SCANCODE_LSHIFT) + down(SDL_SCANCODE_RSHIFT) > 0.0 ? 0.2 : 1.0;
    return {fine * (down(SDL_SCANCODE_LEFT) - down(SDL_SCANCODE_RIGHT)),
            fine * (down(SDL_SCANCODE_UP) - down(SDL_SCANCODE_DOWN))};
}

std::vector<game::Command> holdToAim(HeldAxes axes, double dt, AimInput& aim,
                                     const game::Match& m, bool myTurn) {
    const game::CannonState& c = m.cannon();
    std::vector<game::Command> settled;
    if (!myTurn || m.shell()) {
        aim.cancelCharge();
    } else if (axes.angle != 0.0 || axes.power != 0.0 || axes.padPower != 0.0) {
        aim.hold(axes.angle, axes.power, dt, c.def.maxSpeedMps);
        aim.sweep(0.0, axes.padPower, dt, c.def.maxSpeedMps);
    } else {
        aim.releaseHold();
        if (aim.editing() && !aim.dragging() && !aim.charging())
            settled = aim.commit(c); // keys released (or the stick let go): the aim settles
    }
    aim.updateCharge(dt);
    aim.sync(c);
    return settled;
}

} // namespace ui
