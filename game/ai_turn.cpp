#include "game/ai_turn.h"

#include <algorithm>
#include <cmath>

namespace game {

namespace {

/// Ticks of a duration at `dt` s a tick, at least one.
std::uint64_t ticksOf(double seconds, double dt) {
    return static_cast<std::uint64_t>(std::max(1LL, std::llround(seconds / dt)));
}

/// The sweep's steps at `dt` s a tick: one every `every` ticks, `steps` of them.
struct Sweep {
    std::uint64_t every, steps;
    std::uint64_t ticks() const { return every * steps; }
};
Sweep sweepAt(double dt) {
    const std::uint64_t every = ticksOf(kAimStepSeconds, dt);
    return {every, std::max<std::uint64_t>(1, ticksOf(kAimSweepSeconds, dt) / every)};
}

/// Smoothstep: starts and stops at rest, as a hand on a wheel does.
double ease(double s) { return s * s * (3.0 - 2.0 * s); }

Command at(std::uint64_t tick, CommandKind kind, double number = 0.0) {
    Command c;
    c.tick = tick;
    c.kind = kind;
    c.number = number;
    return c;
}

} // namespace

std::vector<Command> aimSweep(const CannonState& cannon, const std::vector<Command>& turn,
                              std::uint64_t tick, double dt) {
    const auto find = [&](CommandKind k) {
        return std::find_if(turn.begin(), turn.end(), [&](const Command& c) { return c.kind == k; });
    };
    const auto aim = find(CommandKind::Aim), power = find(CommandKind::Power);
    if (find(CommandKind::Fire) == turn.end() || aim == turn.end() || power == turn.end()) return turn;
    std::vector<Command> out;
    for (const Command& c : turn)
        if (c.kind == CommandKind::Select) out.push_back(c);
    const Sweep sweep = sweepAt(dt);
    double lastAngle = cannon.angleDeg, lastSpeed = cannon.speedMps;
    for (std::uint64_t k = 1; k <= sweep.steps; ++k) {
        const double e = ease(static_cast<double>(k) / static_cast<double>(sweep.steps));
        const bool last = k == sweep.steps; // exactly the chosen aim, not a rounding of it
        const double angle = last ? aim->number : cannon.angleDeg + (aim->number - cannon.angleDeg) * e;
        const double speed = last ? power->number : cannon.speedMps + (power->number - cannon.speedMps) * e;
        const std::uint64_t t = tick + k * sweep.every;
        // Only what moves: a barrel already on its aim sends nothing.
        if (angle != lastAngle) out.push_back(at(t, CommandKind::Aim, angle));
        if (speed != lastSpeed) out.push_back(at(t, CommandKind::Power, speed));
        lastAngle = angle;
        lastSpeed = speed;
    }
    out.push_back(at(tick + sweep.ticks(), CommandKind::Fire));
    return out;
}

std::vector<Command> ComputerTurns::due(const Match& match, bool computersTurn) {
    if (!computersTurn) {
        planAt_.reset();
        plan_.clear();
        return {};
    }
    const std::uint64_t now = match.tick();
    if (plan_.empty()) {
        if (!planAt_) planAt_ = now + thinkTicks_;
        if (now < *planAt_) return {};
        planAt_.reset();
        const double dt = match.world().def().tickSeconds;
        const double delay = static_cast<double>(sweepAt(dt).ticks()) * dt;
        const std::vector<Command> turn = player_.takeTurn(match, now, delay);
        for (const Command& c : aimSweep(match.cannon(), turn, now, dt)) plan_.push_back(c);
    }
    std::vector<Command> out;
    while (!plan_.empty() && plan_.front().tick <= now) {
        out.push_back(plan_.front());
        plan_.pop_front();
    }
    return out;
}

} // namespace game
