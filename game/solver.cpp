#include "game/solver.h"

#include "game/ai.h"
#include "game/match.h"
#include "game/scoring.h"
#include "game/weapons.h"
#include "physics/ballistics.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace game {

using phys::Vec2;

namespace {

/// Ticks the structures get to settle after a shot before the next (a toppling block
/// takes a while to fall over).
constexpr std::uint64_t kSettleTicks = 240;
constexpr std::uint64_t kMaxGameTicks = 120ull * 60 * 10;
/// Trial games in all: a level with hundreds of targets and shots still ends in minutes,
/// with the best game found so far.
constexpr long kMaxEvaluations = 3000;
/// Things to hit that seed candidates, nearest the cannon first.
constexpr std::size_t kMaxAimPoints = 6;
/// Grid candidates played in full after the preview's screening.
constexpr std::size_t kGridPlayed = 16;

struct Shot {
    std::string weapon;
    double angleDeg = 45.0;
    double speedMps = 30.0;
};

struct Outcome {
    int score = 0;
    bool over = false;
    int stars = 0;
    double miss = INFINITY; ///< the last shot's closest miss (m), 0 on a hit
    std::uint64_t endTick = 0;
    bool fired = false; ///< the last shot was accepted
    int damage = 0;     ///< duel: hit points the last shooter's enemies have lost
    /// What a shot is worth: points, and in a duel 100 for each hit point taken.
    int points() const { return score + 100 * damage; }
};

bool hasStructures(const Level& l) {
    for (const auto& b : l.blocks)
        if (b.target) return true;
    for (const auto& b : l.blobs)
        if (b.target) return true;
    return false;
}

std::vector<Command> shotCommands(const Shot& s, std::uint64_t tick) {
    std::vector<Command> out(4);
    out[0].kind = CommandKind::Select;
    out[0].text = s.weapon;
    out[1].kind = CommandKind::Aim;
    out[1].number = s.angleDeg;
    out[2].kind = CommandKind::Power;
    out[2].number = s.speedMps;
    out[3].kind = CommandKind::Fire;
    for (auto& c : out)
        c.tick = tick;
    return out;
}

/// Plays `commands` from the start; stops once they are all applied, no shell flies and
/// the structures have settled (or the match is over).
Outcome play(const Level& level, const std::vector<Command>& commands, long& evaluations) {
    ++evaluations;
    Match m(level);
    Outcome out;
    std::size_t next = 0;
    int shooter = 0;
    const bool settle = hasStructures(level);
    std::uint64_t quietSince = 0;
    while (m.tick() < kMaxGameTicks) {
        while (next < commands.size() && commands[next].tick <= m.tick()) {
            const Command& c = commands[next++];
            if (c.kind == CommandKind::Fire) shooter = m.currentPlayer();
            const std::string why = m.apply(c);
            if (c.kind == CommandKind::Fire) out.fired = why.empty();
        }
        if (next == commands.size()) {
            if (m.over()) break;
            // A practice game out of shots ends itself once its last shot has settled.
            const bool ending = level.mode == Mode::Practice && m.cannon().shotsLeft == 0;
            if (!m.shell() && !ending) {
                if (commands.empty()) break; // the first shot goes at once
                if (quietSince == 0) quietSince = m.tick();
                if (!settle || m.tick() >= quietSince + kSettleTicks || structuresAtRest(m)) break;
            } else {
                quietSince = 0;
            }
        }
        m.step();
    }
    out.score = m.score();
    if (level.mode == Mode::Duel)
        for (std::size_t i = 0; i < m.cannons().size(); ++i)
            if (static_cast<int>(i) != shooter)
                out.damage += kCannonHitPoints - m.cannons()[i].hitPoints;
    out.over = m.over();
    out.stars = m.stars();
    out.endTick = m.tick();
    for (auto it = m.events().rbegin(); it != m.events().rend(); ++it)
        if (it->kind == EventKind::ShotOver) {
            out.miss = it->value < 0.0 ? INFINITY : it->value;
            break;
        }
    return out;
}

/// A candidate's worth: points gained first, then finishing, then the closest miss.
struct Worth {
    int gain = -1;
    bool over = false;
    double miss = INFINITY;
    bool operator<(const Worth& o) const {
        if (gain != o.gain) return gain < o.gain;
        if (over != o.over) return !over && o.over;
        return miss > o.miss;
    }
};

class Search {
  public:
    Search(const Level& level) : level_(level) {}

    SolveResult run() {
        SolveResult r;
        r.practice = level_.mode == Mode::Practice;
        if (!r.practice) return r;
        Outcome state = play(level_, commands_, evaluations_);
        for (int shot = 0; shot < level_.shots && !state.over; ++shot) {
            Outcome next;
            const auto best = searchShot(state, state.endTick, next);
            if (!best) break; // no shot scores: stop here
            for (const Command& c : shotCommands(*best, state.endTick))
                commands_.push_back(c);
            state = next;
            ++r.shots;
        }
        const Outcome final = play(level_, commands_, evaluations_);
        r.stars = final.stars;
        r.score = final.score;
        r.maxScore = levelScoring(level_).maxScore();
        r.starScores = levelScoring(level_).starScores();
        r.commands = commands_;
        r.ticks = final.endTick + 1;
        r.evaluations = evaluations_;
        return r;
    }

    /// The best shot fired at tick `at` after the commands so far (whose game stands at
    /// `state`), and the game it makes; nullopt when none gains anything.
    std::optional<Shot> searchShot(const Outcome& state, std::uint64_t at, Outcome& result) {
        const bool duel = level_.mode == Mode::Duel;
        Shot best;
        Worth bestWorth;
        Outcome bestOutcome;
        // A shot that ends the game with three stars cannot be bettered by more search;
        // in a duel the first hit is taken.
        auto consider = [&](const Shot& s) {
            if (bestOutcome.over && bestOutcome.stars == 3) return;
            if (duel && bestWorth.gain > 0) return;
            if (evaluations_ >= kMaxEvaluations) return; // a bound on any level's search
            std::vector<Command> trial = commands_;
            for (const Command& c : shotCommands(s, at))
                trial.push_back(c);
            const Outcome o = play(level_, trial, evaluations_);
            if (!o.fired) return;
            const Worth w{o.points() - state.points(), o.over, o.miss};
            if (bestWorth < w) {
                bestWorth = w;
                best = s;
                bestOutcome = o;
            }
        };
        for (const Shot& s : seeds(at))
            consider(s);
        if (bestWorth.gain <= 0)
            for (const Shot& s : grid(at))
                consider(s);
        if (bestWorth.gain < 0) return std::nullopt; // nothing can be fired
        // A shot that scores is polished for points; a miss gets a short look around.
        refine(best, bestWorth, bestOutcome, consider, bestWorth.gain > 0 ? 6 : 2);
        if (bestWorth.gain <= 0 && !bestWorth.over && !duel) return std::nullopt;
        result = bestOutcome;
        return best;
    }

    std::vector<Command> commands_;

  private:
    /// The match as it stands before the next shot (re-played from the level).
    std::unique_ptr<Match> matchAt(std::uint64_t tick) {
        auto m = std::make_unique<Match>(level_);
        runCommands(*m, commands_, tick);
        return m;
    }

    std::vector<std::string> weaponsLeft(const Match& m) {
        std::vector<std::string> out;
        const CannonState& c = m.cannon();
        for (std::size_t i = 0; i < c.def.projectiles.size(); ++i)
            if ((i >= c.ammoLeft.size() || c.ammoLeft[i] != 0) &&
                knownProjectile(c.def.projectiles[i]))
                out.push_back(c.def.projectiles[i]);
        return out;
    }

    /// Where there is something to hit: targets still standing, target blocks and blobs.
    std::vector<Vec2> aimPoints(const Match& m) {
        std::vector<Vec2> out;
        for (const auto& t : m.targets())
            if (!t.hit) out.push_back(t.position);
        for (const auto& b : m.blocks())
            if (b.def.target && !b.toppled) out.push_back(m.rigid().state(b.body).position);
        for (const auto& b : m.blobs())
            if (b.def.target && !b.toppled) out.push_back(m.world().particles.position(b.center));
        if (m.level().mode == Mode::Duel)
            for (std::size_t i = 0; i < m.cannons().size(); ++i)
                if (static_cast<int>(i) != m.currentPlayer() && m.cannons()[i].hitPoints > 0)
                    out.push_back(m.cannons()[i].def.position);
        const Vec2 from = m.cannon().def.position;
        std::stable_sort(out.begin(), out.end(),
                         [&](Vec2 a, Vec2 b) { return length(a - from) < length(b - from); });
        if (out.size() > kMaxAimPoints) out.resize(kMaxAimPoints);
        return out;
    }

    std::vector<Shot> seeds(std::uint64_t at) {
        std::vector<Shot> out;
        std::vector<std::pair<std::size_t, std::size_t>> perWeapon; // [begin, end) in out
        auto m = matchAt(at);
        const double g = -m->world().def().forces.gravity.y;
        const double vmax = m->cannon().def.maxSpeedMps;
        for (const std::string& w : weaponsLeft(*m)) {
            Command sel;
            sel.kind = CommandKind::Select;
            sel.text = w;
            m->apply(sel);
            const std::size_t first = out.size();
            for (const Vec2 p : aimPoints(*m)) {
                // The firing solution at speeds from the least that reaches up: both arcs.
                const Vec2 d = p - m->cannon().def.position;
                const double least = std::sqrt(std::max(0.0, g * (d.y + length(d))));
                for (const double f : {1.02, 1.1, 1.25, 1.5, 2.0}) {
                    const double s = std::min(vmax, f * least);
                    for (const auto& sol : phys::solveFiring(m->muzzle(45.0), p, s, g))
                        out.push_back({w, sol.angleDeg, s});
                }
                if (!m->ballisticOnly()) {
                    const AimSolution a = aimAt(*m, p);
                    out.push_back({w, a.angleDeg, a.speedMps});
                }
            }
            // Closest preview first: a game that ends with three stars stops the search.
            std::vector<std::pair<double, Shot>> ranked;
            for (std::size_t i = first; i < out.size(); ++i) {
                double miss = INFINITY;
                for (const Vec2 q : m->previewTrajectory(out[i].angleDeg, out[i].speedMps, 12.0))
                    for (const Vec2 p : aimPoints(*m))
                        miss = std::min(miss, length(q - p));
                ranked.push_back({miss, out[i]});
            }
            std::stable_sort(ranked.begin(), ranked.end(),
                             [](const auto& x, const auto& y) { return x.first < y.first; });
            for (std::size_t i = 0; i < ranked.size(); ++i)
                out[first + i] = ranked[i].second;
            perWeapon.push_back({first, out.size()});
        }
        // Each weapon's best first, then each one's second, ...: the weapon a level needs
        // (the mortar for a heavy crate) is tried early.
        std::vector<Shot> interleaved;
        for (std::size_t rank = 0; interleaved.size() < out.size(); ++rank)
            for (const auto& [begin, end] : perWeapon)
                if (begin + rank < end) interleaved.push_back(out[begin + rank]);
        return interleaved;
    }

    /// The coarse grid, screened by the preview (the shell alone, up to its first contact
    /// or 12 s): the candidates whose paths pass closest to something to hit, or whose
    /// first contact is nearest to it (a bank shot's first wall), are played in full.
    std::vector<Shot> grid(std::uint64_t at) {
        auto m = matchAt(at);
        const double vmax = m->cannon().def.maxSpeedMps;
        const std::vector<Vec2> points = aimPoints(*m);
        std::vector<std::pair<double, Shot>> ranked;
        for (const std::string& w : weaponsLeft(*m)) {
            Command sel;
            sel.kind = CommandKind::Select;
            sel.text = w;
            m->apply(sel);
            for (double a = 5.0; a < 176.0; a += 7.5)
                for (const double f : {0.3, 0.45, 0.6, 0.75, 0.9, 1.0}) {
                    double miss = INFINITY;
                    for (const Vec2 q : m->previewTrajectory(a, f * vmax, 12.0))
                        for (const Vec2 p : points)
                            miss = std::min(miss, length(q - p));
                    ranked.push_back({miss, Shot{w, a, f * vmax}});
                }
        }
        std::stable_sort(ranked.begin(), ranked.end(),
                         [](const auto& x, const auto& y) { return x.first < y.first; });
        std::vector<Shot> out;
        for (std::size_t i = 0; i < ranked.size() && i < kGridPlayed; ++i)
            out.push_back(ranked[i].second);
        // Bank shots: the preview ends at the first wall, so also play an even spread of the
        // rest, every weapon and direction.
        for (std::size_t i = kGridPlayed; i < ranked.size(); i += 6)
            out.push_back(ranked[i].second);
        return out;
    }

    template <class Consider>
    void refine(Shot& best, Worth& worth, Outcome&, Consider& consider, int rounds) {
        if (worth.gain < 0) return;
        const double vmax = matchAt(0)->cannon().def.maxSpeedMps;
        double da = 2.0, ds = 0.03 * vmax;
        for (int round = 0; round < rounds; ++round) {
            bool moved = true;
            for (int guard = 0; moved && guard < 4; ++guard) {
                moved = false;
                const Shot centre = best;
                for (const auto& [ka, ks] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                    Shot s = centre;
                    s.angleDeg = std::clamp(centre.angleDeg + ka * da, -180.0, 180.0);
                    s.speedMps = std::clamp(centre.speedMps + ks * ds, 0.0, vmax);
                    const Worth before = worth;
                    consider(s);
                    if (before < worth) moved = true;
                }
            }
            da *= 0.5;
            ds *= 0.5;
        }
    }

    const Level& level_;
    long evaluations_ = 0;
};

} // namespace

SolveResult solveLevel(const Level& level) {
    return Search(level).run();
}

std::vector<Command> solverTurn(const Level& level, const std::vector<Command>& history,
                                std::uint64_t tick) {
    Search search(level);
    search.commands_ = history;
    long evaluations = 0;
    const Outcome state = play(level, history, evaluations);
    Outcome next;
    const auto best = search.searchShot(state, tick, next);
    if (!best) return {};
    return shotCommands(*best, tick);
}

Replay replayOf(const Level& level, const SolveResult& result) {
    Replay r;
    r.levelFile = level.file;
    r.levelHash = level.contentHash;
    r.difficulty = "hard";
    r.commands = result.commands;
    Match m(level);
    std::size_t next = 0;
    while (m.tick() < result.ticks) {
        while (next < r.commands.size() && r.commands[next].tick <= m.tick())
            m.apply(r.commands[next++]);
        m.step();
        if (m.tick() % r.checkpointEvery == 0) r.checkpoints.push_back(checkpointOf(m));
    }
    r.ticks = m.tick();
    r.finalHash = m.hash();
    return r;
}

} // namespace game
