#include "ui/game/live_play.h"

#include "ui/game/match_view.h"
#include "ui/game/pad_input.h"
#include "ui/game/turn_controls.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace ui {

game::SessionOptions liveSessionOptions(PlayerFiles& files, const game::Level& level,
                                        const std::string& recordFile, std::string& status) {
    game::SessionOptions o;
    o.difficulty = files.settings().difficulty;
    o.cpuSeed = level.seed;
    // Every match is recorded; the session saves at each turn's end.
    o.recordFile = recordFile;
    o.onSaveFailure = [&files, &status](const std::string& why) { // the game plays on
        if (const std::string said = files.failedOnce("the replay", why); !said.empty()) {
            std::cerr << "artillery: " << said << "\n";
            status = said;
        }
    };
    return o;
}

void LivePlay::start(std::unique_ptr<game::Session> session) {
    session_ = std::move(session);
    phys::ClockDef cd;
    cd.tickSeconds = session_->match().world().def().tickSeconds;
    clock_ = phys::FixedClock(cd);
    aim_ = AimInput();
    rewind_ = RewindControl();
    branchNote_.clear();
    turnPlayer_ = -1;
    resultRecorded_ = newBest_ = false;
}

void LivePlay::stop() {
    session_.reset();
    aim_ = AimInput();
    branchNote_.clear();
}

bool LivePlay::humanTurn() const {
    if (!session_) return false;
    const game::Match& m = session_->match();
    return !m.over() && m.cannon().def.player != "cpu";
}

std::string LivePlay::submit(const game::Command& command) {
    if (!session_) return "";
    const std::string why = session_->submit(command);
    if (why.empty()) return "";
    say(std::string(game::commandName(command.kind)) + ": " + why);
    return notice_;
}

void LivePlay::say(std::string text, double seconds) {
    notice_ = std::move(text);
    noticeSeconds_ = seconds;
}

std::string LivePlay::submit(const std::vector<game::Command>& commands) {
    std::string refused;
    for (const game::Command& c : commands)
        if (std::string why = submit(c); !why.empty()) refused = std::move(why);
    return refused;
}

void LivePlay::pollHeldInput(double dt, bool keysFree, PadInput& pad) {
    const game::Match& m = session_->match();
    if (m.currentPlayer() != turnPlayer_) { // a new turn: the banner says whose
        turnPlayer_ = m.currentPlayer();
        turnStartTick_ = m.tick();
    }
    HeldAxes axes;
    if (humanTurn() && !m.shell()) {
        if (keysFree) axes = heldArrowKeys();
        if (pad.connected()) {
            const PadAxes stick = pad.axes();
            aim_.stick(stick.stickX, stick.stickY);
            axes.padPower = stick.power;
        }
    }
    submit(holdToAim(axes, dt, aim_, m, humanTurn()));
}

void LivePlay::simulate(double wallSeconds, bool menuPause, const std::function<void()>& onTick,
                        FrameStats& stats) {
    clock_.setPaused(time_.paused || menuPause);
    clock_.setTimeScale(time_.timeScale);
    if (time_.stepRequested) {
        clock_.requestSingleStep();
        time_.stepRequested = false;
    }
    const int wanted = clock_.advance(wallSeconds);
    double physicsUs = 0.0;
    const TicksRun run = runTicksWithin(clock_, wanted, tickBudget_, [&] {
        session_->step();
        onTick();
        physicsUs += session_->match().world().profile().totalUs;
    });
    // What a tick costs here is the world, the blocks and the match together.
    slowMotion_.frame(run, wanted, wallSeconds);
    const game::Match& m = session_->match();
    stats.ticksThisFrame = run.ran;
    if (run.ran > 0) stats.physicsUs = physicsUs / run.ran;
    stats.integrateUs = m.world().profile().integrateUs;
    stats.springsUs = m.world().profile().springsUs;
    stats.tick = m.tick();
    stats.simSeconds = m.time();
    stats.particles = m.world().particles.count();
    stats.springs = m.world().springs.size();
}

void LivePlay::warmUp(double seconds, const std::function<void()>& onTick) {
    if (!session_) return;
    const auto ticks = static_cast<long long>(seconds / session_->match().world().def().tickSeconds);
    for (long long i = 0; i < ticks; ++i) {
        session_->step();
        onTick();
    }
}

void LivePlay::rewindTo(std::uint64_t tick) {
    const game::Match& before = session_->match();
    if (tick >= before.tick()) return;
    const double dt = before.world().def().tickSeconds;
    session_->rewindTo(tick);
    aim_ = AimInput();
    resultRecorded_ = session_->match().over();
    newBest_ = false;
    char note[160];
    std::snprintf(note, sizeof note, "rewound to %.1f s: playing on as a new branch",
                  static_cast<double>(tick) * dt);
    markBranch(note, tick);
}

void LivePlay::markBranch(std::string note, std::uint64_t tick) {
    branchNote_ = std::move(note);
    branchTick_ = tick;
}

bool LivePlay::takeFinish() {
    if (!session_ || !session_->match().over() || resultRecorded_) return false;
    resultRecorded_ = true;
    return true;
}

/// "Your turn" (or "Player 2's turn" when people share the duel) for the first two
/// seconds of a person's turn in a duel, until the shot.
std::string LivePlay::turnBanner(const game::Match& m) const {
    const auto shown = static_cast<std::uint64_t>(2.0 / m.world().def().tickSeconds);
    if (m.level().mode != game::Mode::Duel || m.over() || m.shell() || m.currentPlayer() != turnPlayer_ ||
        m.tick() >= turnStartTick_ + shown)
        return "";
    int people = 0;
    for (const game::CannonState& c : m.cannons()) people += c.def.player != "cpu";
    if (people < 2) return "Your turn";
    return defaultPlayerName(m.cannon().def.player) + "'s turn";
}

std::string LivePlay::banner() const {
    if (!session_) return "";
    const game::Match& m = session_->match();
    char banner[64] = "";
    // A branch says so for its first seconds (simulated: it stays while paused).
    const auto branchTicks = static_cast<std::uint64_t>(3.0 / m.world().def().tickSeconds);
    if (time_.paused)
        std::snprintf(banner, sizeof banner, "PAUSED  (. steps one tick)");
    else if (slowMotion_.shown())
        std::snprintf(banner, sizeof banner, "SLOW MOTION: a tick of %.0f ms takes %.0f ms",
                      1000.0 * m.world().def().tickSeconds, slowMotion_.tickWallMs());
    else if (time_.timeScale != 1.0f)
        std::snprintf(banner, sizeof banner, "speed x%g", static_cast<double>(time_.timeScale));
    else if (!branchNote_.empty() && m.tick() < branchTick_ + branchTicks)
        std::snprintf(banner, sizeof banner, "BRANCH from %.1f s",
                      static_cast<double>(branchTick_) * m.world().def().tickSeconds);
    else if (!m.over() && m.cannon().def.player == "cpu" && !m.shell())
        std::snprintf(banner, sizeof banner, "Computer's turn: it is aiming");
    else if (const std::string turn = turnBanner(m); !turn.empty())
        std::snprintf(banner, sizeof banner, "%s", turn.c_str());
    else if (m.over() && newBest_)
        std::snprintf(banner, sizeof banner, "new best for this level!");
    return banner;
}

void LivePlay::fadeNotice(double wallSeconds) {
    noticeSeconds_ = std::max(0.0, noticeSeconds_ - wallSeconds);
}

} // namespace ui
