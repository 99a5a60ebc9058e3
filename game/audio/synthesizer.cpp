#include "game/audio/synthesizer.h"

#include "game/ammo.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace game::audio {

using phys::Vec2;

namespace {

constexpr double kSpeedOfSound = 343.0; ///< m/s, air at 20 C
/// Events older than this when first seen are not sounded (a replay viewer that jumped
/// ahead, or a rewind): s.
constexpr double kStaleSeconds = 0.25;

/// The shell's whistle: the tone of air over it rises with its speed (a vortex shedding
/// frequency f = St v / d, Strouhal St ~ 0.2, scaled into the ear's range) and its
/// loudness with the dynamic pressure, v^2.
double whistlePitch(double speed) {
    return 260.0 + 20.0 * speed;
}
double whistleGain(double speed) {
    return 0.12 * std::min(1.0, (speed / 50.0) * (speed / 50.0));
}

} // namespace

Synthesizer::Synthesizer(const SynthesizerDef& def) : def_(def) {}

// ---- the clock -------------------------------------------------------------------------
std::int64_t Synthesizer::sampleOfTick(std::uint64_t tick) const {
    if (tickMilliHz_ <= 0 || tick < baseTick_) return baseSample_;
    // floor((t - t0) * 48000 / f) with f in mHz: integers only, so it never drifts.
    const auto ticks = static_cast<std::int64_t>(tick - baseTick_);
    return baseSample_ + ticks * kSampleRate * 1000 / tickMilliHz_;
}

void Synthesizer::followClock(const Match& m) {
    const auto milliHz =
        static_cast<std::int64_t>(std::llround(1000.0 / m.world().def().tickSeconds));
    if (!seen_) {
        baseTick_ = 0;
        baseSample_ = def_.live ? cursor_ : 0;
        tickMilliHz_ = milliHz;
        return;
    }
    if (milliHz != tickMilliHz_ && m.tick() > 0) {
        // A `set tick_hz`: the tick just run was the first of the new length.
        const std::uint64_t first = m.tick() - 1;
        baseSample_ = sampleOfTick(first);
        baseTick_ = first;
        tickMilliHz_ = milliHz;
    }
}

// ---- voices ----------------------------------------------------------------------------
double Synthesizer::panOf(Vec2 where) const {
    const double half = 0.5 * (view_.right - view_.left);
    if (!(half > 0.0)) return 0.0;
    return std::clamp((where.x - 0.5 * (view_.left + view_.right)) / half, -1.0, 1.0);
}

std::int64_t Synthesizer::atTick(std::uint64_t tick) const {
    return def_.live ? cursor_ : std::max(cursor_, sampleOfTick(tick));
}

void Synthesizer::start(Voice v, std::uint64_t tick, Vec2 where, std::uint64_t salt) {
    v.start = atTick(tick);
    if (v.bus == Bus::Effects) v.pan = panOf(where);
    // Noise seeded from the event's tick, its kind and what distinguishes it: the same
    // event always makes the same noise.
    v.noise = generate::SeededRandom(generate::mix64(
        tick * 0x9e3779b97f4a7c15ull ^ (static_cast<std::uint64_t>(v.kind) << 56) ^ salt));
    v.id = ++started_[static_cast<std::size_t>(v.kind)] | static_cast<std::uint64_t>(v.kind) << 56;
    if (voices_.size() >= def_.maxVoices && v.kind != VoiceKind::Whistle) {
        // The quietest voice (never the whistle) gives way, unless the new one is quieter.
        auto quietest = voices_.end();
        for (auto it = voices_.begin(); it != voices_.end(); ++it)
            if (it->kind != VoiceKind::Whistle &&
                (quietest == voices_.end() || it->gain < quietest->gain))
                quietest = it;
        if (quietest == voices_.end() || quietest->gain >= v.gain) return;
        *quietest = std::move(v);
        return;
    }
    voices_.push_back(std::move(v));
}

void Synthesizer::click() {
    Voice v = audio::click();
    v.start = cursor_; // a click sounds now, on any clock
    v.noise = generate::SeededRandom(generate::mix64(static_cast<std::uint64_t>(cursor_)));
    v.id = ++started_[static_cast<std::size_t>(v.kind)] | static_cast<std::uint64_t>(v.kind) << 56;
    voices_.push_back(std::move(v)); // a click is short: it may pass the voice limit
}

// ---- listening -------------------------------------------------------------------------
void Synthesizer::forgetMatch() {
    for (Voice& v : voices_)
        if (v.kind == VoiceKind::Whistle) v.keys.push_back({cursor_, 0.0, 0.0, v.pan, true});
    whistles_.clear();
    seen_ = false;
    seenEvents_ = 0;
    waterEntry_.forget();
    blockVelocity_.clear();
    blockSeen_.clear();
}

void Synthesizer::observe(const Match& m) {
    if (seen_ && (m.tick() < lastTick_ || m.events().size() < seenEvents_)) forgetMatch();
    if (!viewSet_) view_ = {m.level().worldMin.x, m.level().worldMax.x};
    // A paused match (looked at every frame, no tick run) has nothing new to hear: its
    // contacts are the last tick's, already heard.
    const bool ticked = !seen_ || m.tick() != lastTick_;
    followClock(m);
    seen_ = true;
    hearEvents(m);
    if (ticked) {
        hearShell(m);
        // A level settling as it opens is silent: impacts are heard once the player has
        // set something moving.
        if (m.stirred()) hearContacts(m);
        hearBlocks(m);
    }
    lastTick_ = m.tick();
}

void Synthesizer::hearEvents(const Match& m) {
    const auto& events = m.events();
    const auto stale = static_cast<std::uint64_t>(kStaleSeconds / m.world().def().tickSeconds);
    const Vec2 middle{0.5 * (view_.left + view_.right), 0.0};
    for (std::size_t k = seenEvents_; k < events.size(); ++k) {
        const GameEvent& e = events[k];
        if (e.kind == EventKind::Fired) firedAmmo_ = e.text;
        if (e.tick + stale < m.tick()) continue;
        switch (e.kind) {
        case EventKind::Fired:
            start(report(e.value), e.tick, e.where, k);
            break;
        case EventKind::Burst: {
            const auto ammo = ammoFromName(firedAmmo_);
            start(blast(ammo ? ammo->blastImpulse : 150.0, e.value), e.tick, e.where, k);
            break;
        }
        case EventKind::TargetHit: // a major third, bright: C6 then E6
            start(chime(1046.5, 2, 1.2599, 0.45), e.tick, e.where, k);
            break;
        case EventKind::Toppled:
            start(crack(0.8), e.tick, e.where, k);
            break;
        case EventKind::CannonHit:
            start(impact(Timbre::Steel, 25.0, 0.7), e.tick, e.where, k);
            break;
        case EventKind::MatchOver: {
            // Practice: a rising fifth per star (C5, G5, D6). A duel won by the first
            // player rises three notes; lost or drawn falls two.
            const bool practice = m.level().mode == Mode::Practice;
            const int stars = m.stars();
            if (practice && stars > 0)
                start(chime(523.25, stars, 1.5, 0.4), e.tick, middle, k);
            else if (!practice && e.player == 0)
                start(chime(523.25, 3, 1.5, 0.4), e.tick, middle, k);
            else
                start(chime(392.0, 2, 0.75, 0.35), e.tick, middle, k);
            break;
        }
        default:
            break;
        }
    }
    seenEvents_ = events.size();
}

void Synthesizer::hearShell(const Match& m) {
    // A splash where the shell went into the water since the last look.
    if (const auto entry = waterEntry_.look(m))
        start(splash(entry->downSpeed), m.tick(), entry->point, 0x5b1a5b);
    std::optional<ShellSound> heard;
    if (const auto shell = m.shell()) {
        const phys::ParticleSet& p = m.world().particles;
        heard = ShellSound{p.position(*shell), p.velocity(*shell)};
        // Under water the air is gone: no whistle (water drag stops the shell within metres).
        heard->underwater =
            m.level().physics.water && heard->position.y < m.level().physics.waterLevel;
    }
    // One whistle, whichever shell the match follows (none: it fades out).
    const KeyedShell flying{0, heard.value_or(ShellSound{})};
    followWhistles(std::span(&flying, heard ? 1 : 0), m.tick(),
                   0.5 * (m.level().worldMin.y + m.level().worldMax.y));
}

void Synthesizer::followWhistles(std::span<const KeyedShell> shells, std::uint64_t tick,
                                 double listenerY) {
    const std::int64_t at = atTick(tick);
    auto voiceOf = [&](std::uint64_t id) -> Voice* {
        for (Voice& v : voices_)
            if (v.id == id && !v.ending) return &v;
        return nullptr;
    };
    // A shell no longer told: its whistle fades out.
    std::erase_if(whistles_, [&](const Whistling& w) {
        const bool flying = std::any_of(shells.begin(), shells.end(),
                                        [&](const KeyedShell& s) { return s.key == w.key; });
        if (flying) return false;
        if (Voice* v = voiceOf(w.voice)) v->keys.push_back({at, v->targetHz, 0.0, v->pan, true});
        return true;
    });
    for (const KeyedShell& s : shells) {
        const Vec2 p = s.shell.position;
        const Vec2 v = s.shell.velocity;
        const double speed = length(v);
        // Doppler: the listener sits at the middle of the view, half its width in front
        // of the screen; f' = f c / (c + v_r), v_r the speed away from the listener.
        const double half = 0.5 * (view_.right - view_.left);
        const Vec2 listener{0.5 * (view_.left + view_.right), listenerY};
        const Vec2 away = p - listener;
        const double distance = std::sqrt(dot(away, away) + half * half);
        const double receding = dot(v, away) / std::max(1e-9, distance);
        const double pitch = whistlePitch(speed) * kSpeedOfSound / (kSpeedOfSound + receding);
        auto w = std::find_if(whistles_.begin(), whistles_.end(),
                              [&](const Whistling& x) { return x.key == s.key; });
        Voice* whistling = w == whistles_.end() ? nullptr : voiceOf(w->voice);
        if (!whistling) {
            start(whistle(), tick, p, 0);
            whistling = &voices_.back(); // a whistle is always admitted
            if (w == whistles_.end())
                whistles_.push_back({s.key, whistling->id});
            else
                w->voice = whistling->id;
        }
        const double gain = s.shell.underwater ? 0.0 : whistleGain(speed);
        whistling->keys.push_back({at, pitch, gain, panOf(p), false});
    }
}

// ---- a scene that is not a match -------------------------------------------------------
void Synthesizer::hearShot(Vec2 muzzle, double muzzleSpeed) {
    start(report(muzzleSpeed), 0, muzzle, ++toldEvents_);
}

void Synthesizer::hearLanding(Vec2 where, double speed, Timbre surface) {
    if (!(speed > def_.impactSpeedMps)) return;
    start(impact(surface, speed, 0.0), 0, where, ++toldEvents_);
}

void Synthesizer::hearShellsInFlight(std::span<const KeyedShell> shells, double listenerY) {
    followWhistles(shells, 0, listenerY);
}

void Synthesizer::stillWhistles() {
    followWhistles({}, 0, 0.0);
}

void Synthesizer::hearContacts(const Match& m) {
    // What one contact sounds like: where, how hard, of what, how elastic.
    struct Hit {
        double speed;
        Vec2 where;
        Timbre timbre;
        double restitution;
        std::uint64_t salt;
    };
    std::vector<Hit> hits;
    const phys::World& w = m.world();
    auto materialOf = [&](phys::ParticleId p) -> const std::string& {
        return w.materials[w.particles.material[p]].name;
    };
    // The harder of the two sets the ring: a steel ball on earth still rings.
    auto harder = [](Timbre particle, Timbre surface) {
        return particle == Timbre::Steel ? Timbre::Steel : surface;
    };
    // Particles on the static world and on each other, as the solver resolved them: the
    // restitution it applied is e = v_out.n / v_in.n.
    for (const phys::ContactEvent& e : w.contacts()) {
        if (e.resting || !(e.closingSpeed > def_.impactSpeedMps)) continue;
        const std::string& surface = e.b == phys::kNoParticle
                                         ? w.materials[w.shapes.material(e.shape)].name
                                         : materialOf(e.b);
        hits.push_back({e.closingSpeed, e.position,
                        harder(timbreOf(materialOf(e.a)), timbreOf(surface)),
                        std::clamp(dot(e.velocity, e.normal) / e.closingSpeed, 0.0, 1.0), e.a});
    }
    // Particles on blocks (the coupling's impulses): the block's material; e from the
    // particle's velocity after the tick along the contact normal.
    for (const phys::BodyContactEvent& e : m.coupling().events()) {
        if (!(e.closingSpeed > def_.impactSpeedMps) || !w.particles.alive(e.particle)) continue;
        Timbre block = Timbre::Wood;
        for (const BlockState& b : m.blocks())
            if (b.body == e.body) block = timbreOf(b.def.material);
        const double out = dot(w.particles.velocity(e.particle), e.normal);
        hits.push_back({e.closingSpeed, e.point, harder(timbreOf(materialOf(e.particle)), block),
                        std::clamp(out / e.closingSpeed, 0.0, 1.0), 0xc0u + e.particle});
    }
    // The hardest are heard (ties keep their order).
    std::stable_sort(hits.begin(), hits.end(),
                     [](const Hit& a, const Hit& b) { return a.speed > b.speed; });
    if (hits.size() > def_.impactsPerTick) hits.resize(def_.impactsPerTick);
    for (const Hit& h : hits)
        start(impact(h.timbre, h.speed, h.restitution), m.tick(), h.where, h.salt);
}

void Synthesizer::hearBlocks(const Match& m) {
    const auto& blocks = m.blocks();
    const std::uint64_t ticks = std::max<std::uint64_t>(1, m.tick() - lastTick_);
    const double dt = m.world().def().tickSeconds * static_cast<double>(ticks);
    blockVelocity_.resize(blocks.size());
    blockSeen_.resize(blocks.size(), false);
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        const BlockState& b = blocks[i];
        if (!m.rigid().alive(b.body)) {
            blockSeen_[i] = false;
            continue;
        }
        const phys::RigidBodyState s = m.rigid().state(b.body);
        // What gravity alone would have made of the last velocity; the rest is an impulse
        // from a contact (or a blast): heard as an impact at |dv|.
        const Vec2 expected = blockVelocity_[i] + m.rigid().gravityKick(b.body, dt);
        const double jump = length(s.linearVelocity - expected);
        if (blockSeen_[i] && jump > 2.0 * def_.impactSpeedMps && m.stirred())
            start(impact(timbreOf(b.def.material), jump, 0.3), m.tick(), s.position, 0xb10c + i);
        blockVelocity_[i] = s.linearVelocity;
        blockSeen_[i] = true;
    }
}

// ---- rendering -------------------------------------------------------------------------
void Synthesizer::render(float* out, std::size_t frames) {
    std::vector<double> left(frames, 0.0), right(frames, 0.0);
    const double master = mix_.mute ? 0.0 : std::clamp(mix_.master, 0.0, 1.0);
    for (Voice& v : voices_) {
        const double bus = master * std::clamp(v.bus == Bus::Ui ? mix_.ui : mix_.effects, 0.0, 1.0);
        for (std::size_t i = 0; i < frames && !v.done(); ++i) {
            if (cursor_ + static_cast<std::int64_t>(i) < v.start) continue;
            const double x = v.next() * bus;
            // Equal-power pan: theta = (pan + 1) pi / 4, L = cos theta, R = sin theta, so
            // L^2 + R^2 is the same wherever the sound is.
            const double theta = (v.pan + 1.0) * 0.25 * std::numbers::pi;
            left[i] += x * std::cos(theta);
            right[i] += x * std::sin(theta);
        }
    }
    std::erase_if(voices_, [](const Voice& v) { return v.done(); });
    // Soft limiter: instant attack to the gain that keeps the louder channel at the
    // ceiling, then an exponential release back to 1 (time constant limiterRelease).
    const double release = 1.0 - std::exp(-1.0 / (def_.limiterReleaseSeconds * kSampleRate));
    for (std::size_t i = 0; i < frames; ++i) {
        limiterGain_ += release * (1.0 - limiterGain_);
        const double peak = std::max(std::abs(left[i]), std::abs(right[i]));
        if (peak * limiterGain_ > def_.limiterCeiling) limiterGain_ = def_.limiterCeiling / peak;
        out[2 * i] = static_cast<float>(left[i] * limiterGain_);
        out[2 * i + 1] = static_cast<float>(right[i] * limiterGain_);
    }
    cursor_ += static_cast<std::int64_t>(frames);
}

} // namespace game::audio
