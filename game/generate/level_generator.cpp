#include "game/generate/level_generator.h"

#include "game/generate/noise.h"
#include "game/generate/seeded_random.h"
#include "game/level_write.h"
#include "game/match.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace game::generate {

namespace {

/// Terrain samples are this far apart (m); pads are whole samples, so a flattened pad is
/// exactly flat between its samples.
constexpr double kSpacing = 5.0;
/// Height of a cannon's pivot above its pad (m): the barrel clears the ground.
constexpr double kCannonLift = 1.5;

/// Centimetres: generated files read like hand-written ones, and the rounding is exact
/// (std::round, a multiply and a divide, each correctly rounded).
double cm(double x) {
    return std::round(x * 100.0) / 100.0;
}

/// What each difficulty asks of the player.
struct Recipe {
    double worldWidth = 220.0;  ///< m
    double worldHeight = 120.0; ///< m, above y = 0
    double baseHeight = 8.0;    ///< mean ground height, m
    double relief = 8.0;        ///< ground height varies by up to +- this, m
    double hill = 0.0;          ///< a hill this high in the middle of the map, m
    double windMax = 0.0;       ///< wind drawn per turn in [-windMax, windMax], m/s
    int targets = 2;            ///< practice: round targets
    int towers = 0;             ///< block towers (practice: with a target block on top)
    int towerBlocks = 0;        ///< blocks under the top one
    bool blob = false;          ///< practice: a soft blob to knock over
    bool rope = false;          ///< a rope hung between two posts, in the way
};

// Easy, normal, hard.
constexpr Recipe kPractice[] = {
    {.relief = 8.0},
    {.relief = 14.0, .windMax = 3.0, .towers = 1, .towerBlocks = 2},
    {.relief = 20.0, .windMax = 6.0, .towers = 1, .towerBlocks = 3, .blob = true},
};
constexpr Recipe kDuel[] = {
    {.worldWidth = 320.0,
     .worldHeight = 160.0,
     .baseHeight = 12.0,
     .relief = 10.0,
     .windMax = 2.0,
     .targets = 0},
    {.worldWidth = 320.0,
     .worldHeight = 160.0,
     .baseHeight = 12.0,
     .relief = 16.0,
     .hill = 12.0,
     .windMax = 5.0,
     .targets = 0,
     .towers = 1,
     .towerBlocks = 2},
    {.worldWidth = 320.0,
     .worldHeight = 160.0,
     .baseHeight = 12.0,
     .relief = 22.0,
     .hill = 24.0,
     .windMax = 8.0,
     .targets = 0,
     .towers = 2,
     .towerBlocks = 3,
     .rope = true},
};

Recipe recipe(Mode mode, Difficulty d) {
    const auto i = static_cast<std::size_t>(d);
    return mode == Mode::Duel ? kDuel[i] : kPractice[i];
}

/// The ground as samples every kSpacing metres, with flattened pads.
struct Ground {
    std::vector<Vec2> points;

    double at(int i) const { return points[static_cast<std::size_t>(i)].y; }
    double x(int i) const { return points[static_cast<std::size_t>(i)].x; }
    /// Flattens samples i - half .. i + half to sample i's height; returns that height.
    double pad(int i, int half) {
        const double h = at(i);
        for (int k = std::max(0, i - half); k <= std::min(last(), i + half); ++k)
            points[static_cast<std::size_t>(k)].y = h;
        return h;
    }
    int last() const { return static_cast<int>(points.size()) - 1; }
};

Ground noiseGround(SeededRandom& rng, const Recipe& r) {
    const std::uint64_t noiseSeed = rng.next();
    const NoiseDef noise{80.0, 4, 0.5};
    Ground g;
    const int n = static_cast<int>(r.worldWidth / kSpacing);
    for (int i = 0; i <= n; ++i) {
        const double x = kSpacing * i;
        // The hill: (1 - u^2)^2 for |u| < 1, u the distance from the middle over a
        // quarter of the width; smooth at its foot, so the noise rides on it.
        const double u = (x - 0.5 * r.worldWidth) / (0.25 * r.worldWidth);
        const double bump = u * u < 1.0 ? (1.0 - u * u) * (1.0 - u * u) : 0.0;
        g.points.push_back(
            {x, cm(r.baseHeight + r.hill * bump + r.relief * valueNoise(noiseSeed, noise, x))});
    }
    return g;
}

/// A sample index in [lo, hi].
int pick(SeededRandom& rng, int lo, int hi) {
    return lo + rng.below(hi - lo + 1);
}

Cannon cannonAt(Vec2 position, double angleDeg, std::string player) {
    Cannon c;
    c.position = position;
    c.angleDeg = angleDeg;
    c.speedMps = 40.0;
    c.maxSpeedMps = 70.0;
    c.player = std::move(player);
    c.projectiles = {"cannonball", "steel-ball", "golf-ball"};
    c.projectileCounts = {-1, -1, -1};
    return c;
}

/// A tower on a pad at height h: `count` upright blocks, and on top a target block when
/// `targetOnTop` (practice) or one more block (duel). Blocks touch without overlapping.
void addTower(Level& l, double x, double h, int count, bool targetOnTop) {
    const Vec2 size{1.0, 2.0};
    double y = h;
    for (int k = 0; k < count; ++k) {
        Block b;
        b.position = {x, cm(y + 0.5 * size.y)};
        b.size = size;
        b.material = "wood";
        b.density = 600.0;
        l.blocks.push_back(b);
        y += size.y;
    }
    Block top;
    top.size = {1.2, 1.2};
    top.position = {x, cm(y + 0.5 * top.size.y)};
    top.material = "wood";
    top.target = targetOnTop;
    l.blocks.push_back(top);
}

/// A rope hung between two steel posts straddling sample i (its pad at height h).
void addRope(Level& l, double x, double h) {
    const double height = 14.0, halfSpan = 6.0;
    for (const double px : {x - halfSpan, x + halfSpan}) {
        Obstacle post;
        post.shape = Obstacle::Shape::Polyline;
        post.points = {{px, h}, {px, cm(h + height)}};
        l.obstacles.push_back(post);
    }
    Rope r;
    r.from = {x - halfSpan, cm(h + height)};
    r.to = {x + halfSpan, cm(h + height)};
    r.segments = 12;
    r.sag = 0.15;
    l.ropes.push_back(r);
}

/// Splits samples [lo, hi] into `n` equal slots and picks one sample inside each, two
/// samples clear of the slot's edges so neighbouring features never touch.
std::vector<int> spread(SeededRandom& rng, int lo, int hi, int n) {
    std::vector<int> out;
    const int width = (hi - lo + 1) / n;
    for (int k = 0; k < n; ++k) {
        const int start = lo + k * width;
        out.push_back(pick(rng, start + 2, start + width - 3));
    }
    return out;
}

/// Shuffles with the generator (Fisher-Yates): which slot gets which feature.
template <class T> void shuffle(SeededRandom& rng, std::vector<T>& v) {
    for (int i = static_cast<int>(v.size()) - 1; i > 0; --i)
        std::swap(v[static_cast<std::size_t>(i)], v[static_cast<std::size_t>(rng.below(i + 1))]);
}

void practiceLayout(Level& l, Ground& g, SeededRandom& rng, const Recipe& r, Difficulty d) {
    const int cannonSample = pick(rng, 2, 5);
    const double cannonGround = g.pad(cannonSample, 1);
    l.cannons.push_back(cannonAt({g.x(cannonSample), cm(cannonGround + kCannonLift)}, 45.0, "1"));

    enum Feature { RoundTarget, Tower, SoftBlob };
    std::vector<Feature> features(static_cast<std::size_t>(r.targets), RoundTarget);
    for (int k = 0; k < r.towers; ++k)
        features.push_back(Tower);
    if (r.blob) features.push_back(SoftBlob);
    shuffle(rng, features);

    const double radius[] = {2.0, 1.5, 1.2};
    const int points[] = {100, 150, 250};
    const auto slots = spread(rng, 14, g.last() - 2, static_cast<int>(features.size()));
    for (std::size_t k = 0; k < features.size(); ++k) {
        const int s = slots[k];
        const double h = g.pad(s, 1);
        switch (features[k]) {
        case RoundTarget: {
            Target t;
            t.radius = radius[static_cast<int>(d)];
            // Half of them float: a high target asks for the other arc.
            const double lift = rng.chance(0.5) ? rng.between(3.0, 12.0) : 0.2;
            t.position = {g.x(s), cm(h + t.radius + lift)};
            t.points = points[rng.below(3)];
            l.targets.push_back(t);
            break;
        }
        case Tower:
            addTower(l, g.x(s), h, r.towerBlocks, true);
            break;
        case SoftBlob: {
            Blob b;
            b.radius = 1.2;
            b.center = {g.x(s), cm(h + b.radius + 0.05)};
            b.target = true;
            l.blobs.push_back(b);
            break;
        }
        }
    }
    l.shots = static_cast<int>(features.size()) + 2;
}

void duelLayout(Level& l, Ground& g, SeededRandom& rng, const Recipe& r) {
    const int first = pick(rng, 4, 9), second = pick(rng, g.last() - 9, g.last() - 4);
    const double h1 = g.pad(first, 1), h2 = g.pad(second, 1);
    l.cannons.push_back(cannonAt({g.x(first), cm(h1 + kCannonLift)}, 45.0, "1"));
    l.cannons.push_back(cannonAt({g.x(second), cm(h2 + kCannonLift)}, 135.0, "cpu"));

    // Between the cannons: towers, and at the hardest a rope across the middle.
    const int mid = g.last() / 2;
    const int features = r.towers + (r.rope ? 1 : 0);
    if (features == 0) return;
    const auto slots = spread(rng, mid - 10, mid + 10, features);
    for (int k = 0; k < features; ++k) {
        const int s = slots[static_cast<std::size_t>(k)];
        const double h = g.pad(s, 2);
        if (k < r.towers)
            addTower(l, g.x(s), h, r.towerBlocks, false);
        else
            addRope(l, g.x(s), h);
    }
    l.shots = 10;
}

std::uint64_t candidateSeed(const GenerateDef& def, int index) {
    const std::uint64_t variant = (static_cast<std::uint64_t>(index) << 8) |
                                  (static_cast<std::uint64_t>(def.mode) << 4) |
                                  static_cast<std::uint64_t>(def.difficulty);
    return mix64(def.seed) ^ mix64(variant + 0x5eed);
}

std::string levelName(const GenerateDef& def) {
    return std::string("Random ") + modeName(def.mode) + " " + std::to_string(def.seed) + " (" +
           difficultyName(def.difficulty) + ")";
}

/// The shell of the first turn's shot: did it hit the other cannon?
bool firstShotHits(const Level& level) {
    const auto shot = solverTurn(level, {}, 0);
    if (shot.empty()) return false;
    Match m(level);
    for (const Command& c : shot)
        m.apply(c);
    const std::uint64_t limit =
        m.tick() + static_cast<std::uint64_t>(kMaxFlightSeconds * 120.0) + 600;
    while (m.tick() < limit) {
        m.step();
        for (const GameEvent& e : m.events()) {
            if (e.kind == EventKind::CannonHit && e.player != 0) return true;
            if (e.kind == EventKind::TurnOver || e.kind == EventKind::MatchOver) return false;
        }
    }
    return false;
}

} // namespace

Level candidateLevel(const GenerateDef& def, int index) {
    const Recipe r = recipe(def.mode, def.difficulty);
    SeededRandom rng(candidateSeed(def, index));
    Level l;
    l.name = levelName(def);
    l.mode = def.mode;
    l.lesson = "A map from a seed: the same seed gives the same map on every computer.";
    l.description = "Made by artillery generate --seed " + std::to_string(def.seed) + " --mode " +
                    modeName(def.mode) + " --difficulty " + difficultyName(def.difficulty) +
                    " (candidate " + std::to_string(index + 1) + ").";
    l.worldMin = {0.0, -20.0};
    l.worldMax = {r.worldWidth, r.worldHeight};
    l.physics.windMin = -r.windMax;
    l.physics.windMax = r.windMax;
    l.seed = def.seed;

    Ground g = noiseGround(rng, r);
    if (def.mode == Mode::Duel)
        duelLayout(l, g, rng, r);
    else
        practiceLayout(l, g, rng, r, def.difficulty);
    l.terrain.points = g.points;

    // The file is the level: what a loader makes of the written text is what is offered.
    const std::string text = levelToJson(l);
    Level loaded = parseLevel(l.name, text);
    loaded.file.clear();
    return loaded;
}

std::pair<bool, bool> duelHitsEachWay(const Level& level) {
    Level swapped = level;
    std::swap(swapped.cannons[0], swapped.cannons[1]);
    return {firstShotHits(level), firstShotHits(swapped)};
}

Generated generateLevel(const GenerateDef& def) {
    Generated out;
    for (int index = 0; index < std::max(1, def.maxCandidates); ++index) {
        out.level = candidateLevel(def, index);
        out.candidates = index + 1;
        if (def.mode == Mode::Duel) {
            std::tie(out.hitByFirst, out.hitBySecond) = duelHitsEachWay(out.level);
            out.playable = out.hitByFirst && out.hitBySecond;
        } else {
            const SolveResult s = solveLevel(out.level);
            out.stars = s.stars;
            out.shots = s.shots;
            out.playable = s.stars == 3;
        }
        if (out.playable) break;
    }
    out.text = levelToJson(out.level);
    return out;
}

} // namespace game::generate
