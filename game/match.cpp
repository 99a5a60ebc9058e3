#include "game/match.h"

#include "game/material_names.h"
#include "game/scoring.h"
#include "game/shot_model.h"
#include "game/weapons.h"
#include "physics/ballistics.h"
#include "physics/projectiles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace game {

using namespace phys;

const char* eventName(EventKind k) {
    switch (k) {
    case EventKind::Fired: return "fired";
    case EventKind::Bounce: return "bounce";
    case EventKind::Burst: return "burst";
    case EventKind::Crater: return "crater";
    case EventKind::TargetHit: return "target_hit";
    case EventKind::Toppled: return "toppled";
    case EventKind::CannonHit: return "cannon_hit";
    case EventKind::ShotOver: return "shot_over";
    case EventKind::TurnOver: return "turn_over";
    case EventKind::MatchOver: return "match_over";
    case EventKind::SettingChanged: return "setting_changed";
    case EventKind::Refused: return "refused";
    case EventKind::Unstable: return "unstable";
    case EventKind::Landed: return "landed";
    case EventKind::Verdict: return "verdict";
    }
    return "?";
}

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kBarrelLength = 1.5;   // m, muzzle distance from the cannon's pivot

/// A block's rigid material by name (the level check refused unknown names); density
/// comes from the level.
RigidMaterial blockMaterial(const Block& b) {
    RigidMaterial m = blockMaterialFromName(b.material).value_or(RigidMaterial{});
    m.density = b.density;
    return m;
}

WorldDef worldDefFor(const LevelPhysics& p) {
    WorldDef d;
    d.forces.gravity = {0.0, -p.gravity};
    d.forces.drag = p.drag ? DragModel::Quadratic : DragModel::None;
    d.forces.airDensity = p.airDensity;
    d.forces.water = p.water;
    d.forces.waterLevel = p.waterLevel;
    return d;
}

template <class T> void appendOnce(std::vector<T>& list, const T& x) {
    if (std::find(list.begin(), list.end(), x) == list.end()) list.push_back(x);
}

/// A uniform draw in [0, 1) from the top 53 bits: the same on every platform (the
/// standard distributions are not specified bit for bit).
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

} // namespace

Match::Match(const Level& level)
    : level_(level), world_(worldDefFor(level.physics)), terrain_(level.terrain.points),
      rng_(level.seed) {
    // Each projectile bounces with a material of its own name, so that
    // restitution.<projectile> changes that projectile alone (game/settings.h).
    for (const ProjectilePreset& p : projectilePresets()) projectileMaterial(world_.materials, p);
    RigidWorldDef rd;
    rd.gravity = world_.def().forces.gravity;
    rigid_ = std::make_unique<RigidWorld>(rd);
    buildWorld();
    WorldDef d = world_.def();
    d.forces.wind = {drawWind(), 0.0};
    world_.setDef(d);
}

double Match::drawWind() {
    const double lo = level_.physics.windMin, hi = level_.physics.windMax;
    return lo + (hi - lo) * unit(rng_);
}

void Match::rebuildStaticShapes() {
    world_.shapes.clear();
    const MaterialId ground = surfaceMaterialFromName(world_.materials, level_.terrain.material).value_or(material::kEarth);
    world_.shapes.addPolyline(terrain_.points(), ground);
    for (const Obstacle& o : level_.obstacles) {
        const MaterialId m = surfaceMaterialFromName(world_.materials, o.material).value_or(material::kFloor);
        switch (o.shape) {
        case Obstacle::Shape::Polyline: world_.shapes.addPolyline(o.points, m); break;
        case Obstacle::Shape::Polygon: world_.shapes.addPolygon(o.points, m); break;
        case Obstacle::Shape::Circle: world_.shapes.addCircle(o.center, o.radius, m); break;
        }
    }
    // The rigid layer needs the same ground for blocks to stand on.
    // Particles meet the ground as the shapes above, not through its Box2D mirror.
    if (rigidTerrain_.valid()) {
        coupling_.unmirror(rigidTerrain_);
        rigid_->destroyBody(rigidTerrain_);
    }
    rigidTerrain_ = rigid_->createTerrain(terrain_.points(), RigidMaterial{0.0, 0.8, 0.0});
    coupling_.mirror(rigidTerrain_);
}

void Match::buildWorld() {
    rebuildStaticShapes();
    for (const Obstacle& o : level_.obstacles) {
        BodyDef bd;
        bd.type = BodyType::Static;
        const RigidMaterial m{0.0, 0.5, 0.3};
        BodyId body;
        switch (o.shape) {
        case Obstacle::Shape::Polyline: body = rigid_->createTerrain(o.points, m); break;
        case Obstacle::Shape::Polygon: body = rigid_->createPolygon(bd, o.points, m); break;
        case Obstacle::Shape::Circle:
            bd.position = o.center;
            body = rigid_->createCircle(bd, o.radius, m);
            break;
        }
        coupling_.mirror(body); // particles meet the obstacle as a static shape
    }
    for (const Block& b : level_.blocks) addBlock(b);
    for (const Rope& r : level_.ropes) addRope(r);
    for (const Blob& b : level_.blobs) addBlob(b);
    for (const Cannon& c : level_.cannons) {
        CannonState s;
        s.def = c;
        s.angleDeg = c.angleDeg;
        s.speedMps = c.speedMps;
        s.hitPoints = kCannonHitPoints;
        s.shotsLeft = level_.shots;
        s.ammoLeft = c.projectileCounts;
        s.ammoLeft.resize(c.projectiles.size(), -1);
        cannons_.push_back(s);
    }
    for (const Target& t : level_.targets) targets_.push_back({t, t.position, false});
}

BodyId Match::addBlock(const Block& b) {
    BodyDef bd;
    bd.position = b.position;
    bd.angle = b.angleDeg * kDegToRad;
    const BodyId id = rigid_->createBox(bd, b.size * 0.5, blockMaterial(b));
    blocks_.push_back({b, id, false});
    return id;
}

void Match::addRope(const Rope& r) {
    // Points on a parabola whose arc is about (1 + sag) times the span; rods keep
    // each link at its share of that length.
    const Vec2 span = r.to - r.from;
    const double spanLength = length(span);
    const double depth = spanLength * std::sqrt(3.0 * r.sag / 8.0);
    const double link = (1.0 + r.sag) * spanLength / r.segments;
    ParticleId prev = kNoParticle;
    RopeState built{r, kNoParticle, kNoParticle};
    for (int i = 0; i <= r.segments; ++i) {
        const double s = static_cast<double>(i) / r.segments;
        ParticleDef pd;
        pd.position = r.from + span * s + Vec2{0.0, -4.0 * depth * s * (1.0 - s)};
        // An end tied to a block hangs on it (a joint), else it may be pinned.
        const int tied = i == 0 ? r.fromBlock : i == r.segments ? r.toBlock : -1;
        const bool pinned = tied < 0 && ((i == 0 && r.pinFrom) || (i == r.segments && r.pinTo));
        pd.mass = pinned ? 0.0 : r.massPerSegment;
        pd.radius = std::min(0.15, 0.3 * link);
        pd.material = material::kWooden;
        const ParticleId id = world_.particles.add(pd);
        if (tied >= 0)
            coupling_.attach(id, blocks_[static_cast<std::size_t>(tied)].body, pd.position, *rigid_);
        if (prev != kNoParticle) {
            DistanceConstraint c;
            c.a = id;
            c.b = prev;
            c.length = link;
            world_.constraints.push_back(c);
        }
        if (i == 0) built.first = id;
        built.last = id;
        prev = id;
    }
    ropes_.push_back(built);
}

void Match::addBlob(const Blob& b) {
    const double m = b.mass / (b.points + 1);
    ParticleDef pd;
    pd.position = b.center;
    pd.mass = m;
    pd.radius = 0.25 * b.radius;
    pd.material = material::kTennis;
    const ParticleId center = world_.particles.add(pd);
    std::vector<ParticleId> ring;
    for (int i = 0; i < b.points; ++i) {
        const double a = 2.0 * std::numbers::pi * i / b.points;
        pd.position = b.center + Vec2{std::cos(a), std::sin(a)} * b.radius;
        pd.radius = std::min(0.2, std::numbers::pi * b.radius / b.points);
        ring.push_back(world_.particles.add(pd));
    }
    auto spring = [&](ParticleId x, ParticleId y) {
        Spring s;
        s.a = x;
        s.b = y;
        s.restLength = length(world_.particles.position(x) - world_.particles.position(y));
        s.stiffness = b.stiffness;
        s.damping = 0.05 * std::sqrt(b.stiffness * m);
        world_.springs.push_back(s);
    };
    for (int i = 0; i < b.points; ++i) {
        spring(ring[static_cast<std::size_t>(i)], ring[static_cast<std::size_t>((i + 1) % b.points)]);
        spring(ring[static_cast<std::size_t>(i)], center);
    }
    blobs_.push_back({b, center, ring, false});
}

void Match::emit(EventKind kind, int player, Vec2 where, double value, std::string text) {
    emit({tick(), kind, player, where, value, std::move(text), {}, std::nullopt});
}

void Match::emit(GameEvent e) {
    events_.push_back(std::move(e));
    judge_.observe(*this, events_.back());
}

std::optional<ParticleId> Match::shell() const {
    if (shell_ == kNoParticle) return std::nullopt;
    return shell_;
}

bool Match::closedFormExact() const {
    const ForceDef& f = world_.def().forces;
    const bool drag = f.drag != DragModel::None && (f.airDensity > 0.0 || f.drag == DragModel::Linear);
    return !drag && !f.water;
}

bool Match::ballisticOnly() const {
    const ForceDef& f = world_.def().forces;
    return closedFormExact() && f.wind.x == 0.0 && f.wind.y == 0.0;
}

Vec2 Match::muzzle(double angleDeg) const {
    const double a = angleDeg * kDegToRad;
    return cannon().def.position + Vec2{std::cos(a), std::sin(a)} * kBarrelLength;
}

Ammo Match::selectedAmmo() const {
    return ammoAt(cannon().projectile);
}

Ammo Match::ammoAt(std::size_t index) const {
    const std::vector<std::string>& list = cannon().def.projectiles;
    return index < list.size() ? ammoFromName(list[index]).value_or(Ammo{}) : Ammo{};
}

MaterialsInPlay Match::materialsInPlay() const {
    MaterialsInPlay in;
    for (const CannonState& c : cannons_)
        for (const std::string& p : c.def.projectiles) appendOnce(in.projectiles, p);
    if (sandbox())
        for (const ProjectilePreset& p : projectilePresets()) appendOnce(in.projectiles, std::string(p.name));
    for (const std::string& name : in.projectiles)
        if (const auto p = projectileFromName(name))
            appendOnce(in.moving, projectileMaterial(world_.materials, *p));
    const ParticleSet& set = world_.particles;
    for (std::size_t i = 0; i < set.slots(); ++i)
        if (set.flags[i] & kAlive) appendOnce(in.moving, set.material[i]);
    for (std::size_t i = 0; i < world_.shapes.count(); ++i)
        appendOnce(in.surfaces, world_.shapes.material(world_.shapes.ref(i)));
    return in;
}

void Match::closeVerdict() {
    if (std::optional<GameEvent> v = judge_.close(*this))
        emit(v->kind, v->player, v->where, v->value, std::move(v->text));
}

void Match::fire() {
    closeVerdict(); // the last shot's, if it has not settled yet
    stirred_ = true;
    CannonState& c = cannons_[static_cast<std::size_t>(current_)];
    shellAmmo_ = selectedAmmo();
    const double a = c.angleDeg * kDegToRad;
    const Vec2 v{c.speedMps * std::cos(a), c.speedMps * std::sin(a)};
    ParticleDef pd = particleDef(shellAmmo_.preset, muzzle(c.angleDeg), v);
    pd.material = shellAmmo_.weapon ? weaponMaterial(world_.materials, shellAmmo_)
                                    : projectileMaterial(world_.materials, shellAmmo_.preset);
    pd.flags |= kProjectile;
    shell_ = world_.particles.add(pd);
    shellFiredTick_ = tick();
    closestMiss_ = INFINITY;
    flight_ = ShellFlight{};
    flight_.lastVelocity = v;
    flight_.launchPosition = flight_.lastPosition = pd.position;
    flight_.launchVelocity = v;
    if (!sandbox()) --c.shotsLeft;
    if (!sandbox() && c.projectile < c.ammoLeft.size() && c.ammoLeft[c.projectile] > 0)
        --c.ammoLeft[c.projectile];
    ++shotsFired_;
    emit({tick(), EventKind::Fired, current_, pd.position, c.speedMps, shellAmmo_.preset.name,
          shotModelName(world_.def(), pd), std::nullopt});
}

void Match::burst(Vec2 at, int spared, ParticleId piece) {
    emit(EventKind::Burst, current_, at, shellAmmo_.blastRadius);
    const Blast blast{at, shellAmmo_.blastImpulse, shellAmmo_.blastRadius};
    const ParticleId gone = piece == kNoParticle ? shell_ : piece;
    if (world_.particles.alive(gone)) world_.particles.remove(gone); // the shell itself is gone
    applyBlast(world_.particles, blast);
    rigid_->applyBlast(blast);
    if (level_.terrain.destructible && shellAmmo_.craterRadius > 0.0 &&
        terrain_.carve(at, shellAmmo_.craterRadius)) {
        rebuildStaticShapes();
        world_.wakeAll(); // sleepers do not notice that the ground under them has gone
        emit(EventKind::Crater, current_, at, shellAmmo_.craterRadius);
    }
    // Duel: a burst next to a cannon hits it.
    if (level_.mode == Mode::Duel)
        for (std::size_t i = 0; i < cannons_.size(); ++i) {
            CannonState& k = cannons_[i];
            if (static_cast<int>(i) == current_ || static_cast<int>(i) == spared || k.hitPoints <= 0)
                continue;
            if (length(k.def.position - at) <= kCannonRadius + shellAmmo_.blastRadius * 0.5) {
                --k.hitPoints;
                emit(EventKind::CannonHit, static_cast<int>(i), at, k.hitPoints);
            }
        }
}

void Match::scorePasses(bool shotEnding) {
    CannonState& shooter = cannons_[static_cast<std::size_t>(current_)];
    const Vec2 p = world_.particles.alive(shell_) ? world_.particles.position(shell_) : Vec2{};
    for (TargetState& t : targets_) {
        if (t.hit || !std::isfinite(t.closestInside)) continue;
        const bool receding = !shotEnding && length(p - t.position) > t.closestInside;
        if (!receding && !shotEnding) continue;
        t.hit = true;
        const double r = shellAmmo_.preset.diameter * 0.5;
        const double closeness = 1.0 - t.closestInside / (t.def.radius + r);
        const int points = discPoints(t.def.points, closeness);
        shooter.score += points;
        emit(EventKind::TargetHit, current_, t.position, points);
    }
}

void Match::endShot(double closestMiss) {
    if (promoteFragment()) return; // the cluster's other fragments fly on
    scorePasses(true);
    if (world_.particles.alive(shell_)) world_.particles.remove(shell_);
    shell_ = kNoParticle;
    emit(EventKind::ShotOver, current_, {}, std::isfinite(closestMiss) ? closestMiss : -1.0);
    const bool allDown = allTargetsDown();
    if (level_.mode == Mode::Duel) {
        int alive = 0, shots = 0;
        for (const auto& k : cannons_) {
            alive += k.hitPoints > 0;
            shots += k.shotsLeft;
        }
        if (alive <= 1 || shots == 0) return finish();
    } else if (level_.mode == Mode::Practice) {
        if (allDown) return finish();
        // Out of shots, the game ends once what the last shot set moving has come to
        // rest (finishWhenDone), so a block it knocks over late still scores in its shot.
        if (cannon().shotsLeft == 0) return;
    }
    nextTurn();
}

void Match::nextTurn() {
    if (level_.mode == Mode::Duel) {
        for (std::size_t step = 1; step <= cannons_.size(); ++step) {
            const int next = static_cast<int>((static_cast<std::size_t>(current_) + step) % cannons_.size());
            if (cannons_[static_cast<std::size_t>(next)].hitPoints > 0) {
                current_ = next;
                break;
            }
        }
    }
    WorldDef d = world_.def();
    d.forces.wind = {drawWind(), 0.0};
    world_.setDef(d);
    emit(EventKind::TurnOver, current_, {}, d.forces.wind.x);
}

void Match::finish() {
    over_ = true;
    if (level_.mode == Mode::Duel) {
        int best = -1, bestHp = -1;
        bool tie = false;
        for (std::size_t i = 0; i < cannons_.size(); ++i) {
            const int hp = cannons_[i].hitPoints;
            if (hp > bestHp) {
                best = static_cast<int>(i);
                bestHp = hp;
                tie = false;
            } else if (hp == bestHp) {
                tie = true;
            }
        }
        winner_ = tie ? -1 : best;
    } else {
        const bool allDown = allTargetsDown();
        if (allDown) cannons_[0].score += kShotBonus * cannons_[0].shotsLeft;
        winner_ = allDown ? 0 : -1;
    }
    closeVerdict(); // the last shot's, before the match's end
    emit(EventKind::MatchOver, winner_, {}, score());
}

// One tick: the rules, then the shot's verdict once what it set moving has settled.
void Match::step() {
    stepRules();
    if (std::optional<GameEvent> v = judge_.afterTick(*this))
        emit(v->kind, v->player, v->where, v->value, std::move(v->text));
}

// The rules as named phases: the physics, what it knocked over, the fragments, then the
// shell's own story (its passes, a duel hit, its contacts, its landing, its weapon, its end).
void Match::stepRules() {
    if (!stepPhysics()) return;
    scoreToppled();
    stepFragments();
    if (shell_ == kNoParticle) return finishWhenDone();
    stepShell();
}

bool Match::stepPhysics() {
    coupling_.prepare(world_, *rigid_);
    world_.step();
    // The guard: nothing non-finite or runaway survives the tick, and the player is told
    // which setting caused it.
    const bool shellAlive = shell_ != kNoParticle && world_.particles.alive(shell_);
    if (const GuardReport g = guardWorld(world_); g.tripped()) {
        emit(EventKind::Unstable, current_, {}, g.removed, g.cause);
        if (shellAlive && !world_.particles.alive(shell_)) {
            endShot(closestMiss_);
            return false;
        }
    }
    coupling_.exchange(world_, *rigid_);
    pullGrabbed();
    rigid_->step(world_.def().tickSeconds);
    updateTargets();
    return true;
}

void Match::finishWhenDone() {
    if (over_ || level_.mode != Mode::Practice || shotsFired_ == 0) return;
    if (allTargetsDown()) return finish();
    if (cannon().shotsLeft > 0) return;
    const auto lastEnd = std::find_if(events_.rbegin(), events_.rend(),
                                      [](const GameEvent& e) { return e.kind == EventKind::ShotOver; });
    const std::uint64_t since = lastEnd == events_.rend() ? tick() : lastEnd->tick;
    const double waited = static_cast<double>(tick() - since) * world_.def().tickSeconds;
    if (structuresAtRest(*this) || waited >= kSettleSeconds) finish();
}

void Match::stepShell() {
    const Vec2 p = world_.particles.position(shell_);
    const double r = world_.particles.radius[shell_];
    followTargetPasses(p, r);
    scorePasses(false);
    if (level_.mode == Mode::Duel && hitEnemyCannon(p, r)) return;
    const ShellTouch touch = shellContacts();
    if (!flight_.landed) {
        if (touch.touched) reportLanding(p);
        flight_.lastPosition = p;
    }
    if (stepWeapon(p, touch.touched, touch.impact)) return;
    if (shellIsDone(p)) endShot(closestMiss_);
}

void Match::followTargetPasses(Vec2 p, double r) {
    // A hit scores by how close to the centre the shell passes, judged at the closest point
    // of its pass (the first tick inside is usually near the rim).
    for (TargetState& t : targets_) {
        if (t.hit) continue;
        const double d = length(p - t.position);
        closestMiss_ = std::min(closestMiss_, std::max(0.0, d - t.def.radius));
        if (d <= t.def.radius + r && d <= t.closestInside) t.closestInside = d;
    }
}

bool Match::hitEnemyCannon(Vec2 p, double r) {
    // Passing through an enemy cannon hits it and ends the shot.
    for (std::size_t i = 0; i < cannons_.size(); ++i) {
        CannonState& k = cannons_[i];
        if (static_cast<int>(i) == current_ || k.hitPoints <= 0) continue;
        const double d = length(p - k.def.position);
        closestMiss_ = std::min(closestMiss_, std::max(0.0, d - kCannonRadius));
        if (d <= kCannonRadius + r) {
            --k.hitPoints;
            emit(EventKind::CannonHit, static_cast<int>(i), p, k.hitPoints);
            if (shellAmmo_.blastRadius > 0.0) {
                burst(p, static_cast<int>(i)); // which must not hit it a second time
            } else {
                world_.particles.remove(shell_);
            }
            endShot(0.0);
            return true;
        }
    }
    return false;
}

Match::ShellTouch Match::shellContacts() {
    // Impacts: a shell bursts on its first; a ball bounces. A body it struck has already
    // taken the shell's impulse (the coupling ran first).
    ShellTouch touch;
    const auto touching = [&](Vec2 where, double closingSpeed) {
        touch.touched = true;
        touch.impact = touch.impact || closingSpeed > 1.0;
        if (shellAmmo_.behaviour.onImpact == OnImpact::Bounce && closingSpeed > 1.0)
            emit(EventKind::Bounce, current_, where, closingSpeed);
    };
    for (const ContactEvent& e : world_.contacts())
        if (e.a == shell_ || e.b == shell_) touching(e.position, e.closingSpeed);
    for (const BodyContactEvent& e : coupling_.events())
        if (e.particle == shell_) touching(e.point, e.closingSpeed);
    return touch;
}

bool Match::shellIsDone(Vec2 p) const {
    const double flight = static_cast<double>(tick() - shellFiredTick_) * world_.def().tickSeconds;
    const bool outside = p.x < level_.worldMin.x || p.x > level_.worldMax.x || p.y < level_.worldMin.y;
    const bool resting = !shellHeld() && ((world_.particles.flags[shell_] & kSleeping) ||
                         (flight > 1.0 && length(world_.particles.velocity(shell_)) < 0.05));
    return outside || resting || flight > kMaxFlightSeconds || !std::isfinite(p.x) || !std::isfinite(p.y);
}

std::uint64_t Match::gameHash() const {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (const auto& c : cannons_) {
        const double v[2] = {c.angleDeg, c.speedMps};
        const int k[4] = {static_cast<int>(c.projectile), c.hitPoints, c.shotsLeft, c.score};
        h = hashBytes(h, v, sizeof v);
        h = hashBytes(h, k, sizeof k);
    }
    // Counted weapons only: a level without counts hashes as it always has.
    for (const auto& c : cannons_)
        for (const int left : c.ammoLeft)
            if (left >= 0) h = hashBytes(h, &left, sizeof left);
    for (const auto& t : targets_) h = hashBytes(h, &t.hit, sizeof t.hit);
    for (const auto& b : blocks_) h = hashBytes(h, &b.toppled, sizeof b.toppled);
    for (const auto& b : blobs_) h = hashBytes(h, &b.toppled, sizeof b.toppled);
    const int state[4] = {current_, over_ ? 1 : 0, shotsFired_, winner_};
    h = hashBytes(h, state, sizeof state);
    const double w = wind();
    h = hashBytes(h, &w, sizeof w);
    // Only when set, so the hashes of matches played without aids stay what they were.
    if (assisted_) h = hashBytes(h, &assisted_, sizeof assisted_);
    for (const auto& p : terrain_.points()) h = hashBytes(h, &p.y, sizeof p.y);
    return h;
}

std::uint64_t Match::hash() const {
    const std::uint64_t parts[3] = {world_.hash(), rigid_->hash(), gameHash()};
    return hashBytes(0xcbf29ce484222325ull, parts, sizeof parts);
}

std::size_t runCommands(Match& match, const std::vector<Command>& commands, std::uint64_t ticks,
                        std::size_t next) {
    const std::uint64_t end = match.tick() + ticks;
    while (match.tick() < end) {
        while (next < commands.size() && commands[next].tick <= match.tick())
            match.apply(commands[next++]);
        match.step();
    }
    return next;
}

} // namespace game
