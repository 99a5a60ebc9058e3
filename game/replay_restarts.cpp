#include "game/replay_restarts.h"

#include <algorithm>

namespace game {

void playReplayTo(Match& match, const std::vector<Command>& commands, std::size_t& nextCommand,
                  std::uint64_t tick) {
    while (match.tick() < tick) {
        while (nextCommand < commands.size() && commands[nextCommand].tick <= match.tick())
            match.apply(commands[nextCommand++]);
        match.step();
    }
}

RestartPoints::RestartPoints(const Level& level, const Replay& replay, const RestartPointsDef& def)
    : level_(level), commands_(replay.commands) {
    // Points at spacing, 2 spacing, ... before the end, at most maxPoints of them.
    const std::uint64_t n = std::max<std::size_t>(def.maxPoints, 1);
    spacing_ = std::max<std::uint64_t>({def.spacing, 1, (replay.ticks + n - 1) / n});
    for (std::uint64_t t = spacing_; t < replay.ticks; t += spacing_) slots_.push_back({t, nullptr});
}

std::size_t RestartPoints::parked() const {
    return static_cast<std::size_t>(
        std::count_if(slots_.begin(), slots_.end(), [](const Slot& s) { return s.match != nullptr; }));
}

bool RestartPoints::build(std::uint64_t tickBudget) {
    while (true) {
        if (!builder_.match) {
            // The first missing point; a builder always starts from the start.
            const auto missing = std::find_if(slots_.begin(), slots_.end(),
                                              [](const Slot& s) { return s.match == nullptr; });
            if (missing == slots_.end()) return true;
            builder_.match = std::make_unique<Match>(level_);
            builder_.nextCommand = 0;
            builder_.slot = static_cast<std::size_t>(missing - slots_.begin());
        }
        Slot& slot = slots_[builder_.slot];
        const std::uint64_t left = slot.tick - builder_.match->tick();
        const std::uint64_t go = std::min(left, tickBudget);
        playReplayTo(*builder_.match, commands_, builder_.nextCommand, builder_.match->tick() + go);
        tickBudget -= go;
        if (builder_.match->tick() < slot.tick) return false; // out of budget
        slot.match = std::move(builder_.match);
    }
}

std::unique_ptr<Match> RestartPoints::take(std::uint64_t tick) {
    for (auto it = slots_.rbegin(); it != slots_.rend(); ++it)
        if (it->tick <= tick && it->match) return std::move(it->match);
    return nullptr;
}

} // namespace game
