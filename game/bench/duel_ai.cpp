#include "game/bench/duel_ai.h"

#include "game/match.h"
#include "game/solver.h"

#include <array>
#include <utility>
#include <vector>

namespace game::bench {

std::string DuelPlayer::name() const {
    return difficulty ? difficultyName(*difficulty) : "solver";
}

DuelResult playDuel(const Level& level, const DuelPlayer& a, const DuelPlayer& b, bool aStarts,
                    std::uint64_t seed) {
    // Cannon 0 starts; put the starting side's cannon first.
    Level l = level;
    l.seed = seed;
    if (!aStarts) std::swap(l.cannons[0], l.cannons[1]);
    const std::array<const DuelPlayer*, 2> side = {aStarts ? &a : &b, aStarts ? &b : &a};
    std::array<ComputerPlayer, 2> cpu = {
        ComputerPlayer(side[0]->difficulty.value_or(Difficulty::Hard), seed * 2 + 1),
        ComputerPlayer(side[1]->difficulty.value_or(Difficulty::Hard), seed * 2 + 2)};

    Match m(l);
    std::vector<Command> history;
    // Every turn ends in a shot that ends, or a refused fire (then the turn is ended).
    const auto maxTicks =
        static_cast<std::uint64_t>((2 * l.shots + 2) * (kMaxFlightSeconds + 5.0) * 120.0);
    int turnsTaken = 0, shotsOver = 0;
    std::size_t eventsSeen = 0;
    while (!m.over() && m.tick() < maxTicks) {
        for (; eventsSeen < m.events().size(); ++eventsSeen)
            shotsOver += m.events()[eventsSeen].kind == EventKind::ShotOver;
        if (!m.shell() && turnsTaken == shotsOver) {
            const int who = m.currentPlayer();
            const DuelPlayer& p = *side[static_cast<std::size_t>(who)];
            std::vector<Command> turn =
                p.difficulty ? cpu[static_cast<std::size_t>(who)].takeTurn(m, m.tick())
                             : solverTurn(l, history, m.tick());
            bool fired = false;
            for (Command& c : turn) {
                c.tick = m.tick();
                if (m.apply(c).empty()) {
                    history.push_back(c);
                    fired = fired || c.kind == CommandKind::Fire;
                }
            }
            if (!fired) {
                Command end;
                end.tick = m.tick();
                end.kind = CommandKind::EndTurn;
                m.apply(end);
                history.push_back(end);
            } else {
                ++turnsTaken;
            }
        }
        m.step();
    }
    DuelResult r;
    r.shots = m.shotsFired();
    r.ticks = m.tick();
    const int w = m.over() ? m.winner() : -1;
    // Map the winning cannon back to its side.
    if (w == 0 || w == 1) r.winner = (w == 0) == aStarts ? 0 : 1;
    return r;
}

} // namespace game::bench
