// Section index
//   set-up    ReplayViewer()
//   time      advance, warmUp: the clock's ticks, jumps
//   controls  panel, key, banner
//   video     exportVideo, the panel's line about it
#include "ui/game/replay_view.h"

#include "ui/game/tick_budget.h"
#include "ui/platform/imgui_layer.h"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iterator>

namespace ui {

namespace {

const ImVec4 kGoldText(1.0f, 0.79f, 0.24f, 1.0f);
const ImVec4 kDimText(0.7f, 0.75f, 0.82f, 1.0f);
const ImVec4 kGoodText(0.55f, 0.9f, 0.55f, 1.0f);
const ImVec4 kBadText(1.0f, 0.4f, 0.4f, 1.0f);

const char* const kSpeedNames[] = {"x1/8", "x1/4", "x1/2", "x1", "x2", "x4", "x8", "x16"};
static_assert(std::size(kSpeedNames) == std::size(kReplaySpeeds));
/// An instant replay slows to this speed (x1/4) around the impact, from kSlowBeforeSeconds
/// before it to kSlowAfterSeconds after (simulated time): the moment the shot lands, four
/// times as long.
constexpr int kSlowMotionSpeed = 1;
constexpr double kSlowBeforeSeconds = 0.25, kSlowAfterSeconds = 0.75;

/// x16 at 30 frames per second is 64 ticks of 1/120 s a frame; a cap well above it.
constexpr int kMaxReplayTicksPerFrame = 256;
/// Ticks re-simulated per frame to build the restart points that make seeking back fast:
/// about 5 ms of a frame on the costliest shipped level (0.04 ms a tick).
constexpr std::uint64_t kRestartTicksPerFrame = 120;

// A button that can be greyed out, with a tooltip that shows either way. True when
// pressed (never while disabled).
bool buttonWhen(bool enabled, const char* label, const char* tooltip) {
    ImGui::BeginDisabled(!enabled);
    const bool pressed = ImGui::Button(label);
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", tooltip);
    return pressed;
}

} // namespace

// ---- set-up ---------------------------------------------------------------------------
ReplayViewer::ReplayViewer(std::string file, const game::Level& level, game::Replay replay)
    : file_(std::move(file)) {
    player_.emplace(level, std::move(replay));
    phys::ClockDef cd;
    cd.tickSeconds = tickSeconds();
    cd.maxTicksPerFrame = kMaxReplayTicksPerFrame;
    clock_ = phys::FixedClock(cd);
}

void ReplayViewer::makeInstant(std::uint64_t fromTick, std::optional<std::uint64_t> impactTick) {
    instant_ = true;
    seek_ = fromTick;
    if (!impactTick) return;
    const auto before = static_cast<std::uint64_t>(std::lround(kSlowBeforeSeconds / tickSeconds()));
    const auto after = static_cast<std::uint64_t>(std::lround(kSlowAfterSeconds / tickSeconds()));
    slowMotion_ = {*impactTick > before ? *impactTick - before : 0, *impactTick + after};
}

int ReplayViewer::speedNow() const {
    const std::uint64_t t = player_->tick();
    const bool slow =
        slowMotion_ && !speedPicked_ && t >= slowMotion_->first && t < slowMotion_->second;
    return slow ? kSlowMotionSpeed : speed_;
}

game::Session ReplayViewer::takeOver(const game::SessionOptions& options) {
    game::Session s = std::move(*player_).takeOver(options);
    player_.reset();
    return s;
}

// ---- time -----------------------------------------------------------------------------
void ReplayViewer::advance(double wallSeconds, bool held, MatchView& view,
                           std::optional<double> tickBudgetSeconds) {
    game::ReplayPlayer& p = *player_;
    if (seek_) {
        const std::uint64_t target = std::min(*seek_, p.lastTick());
        seek_.reset();
        if (target >= p.tick()) {
            // Forwards tick by tick, so the shell's trail is drawn whole.
            while (p.tick() < target) {
                p.step();
                view.observe(p.match());
            }
        } else {
            p.seek(target);
            view.reset();
            view.observe(p.match());
        }
    }
    // A `set tick_hz` command in the replay changes the tick; the clock follows.
    if (clock_.def().tickSeconds != tickSeconds()) clock_.setTickSeconds(tickSeconds());
    clock_.setPaused(paused_ || held || p.atEnd());
    clock_.setTimeScale(kReplaySpeeds[speedNow()]);
    if (stepRequested_) {
        clock_.requestSingleStep();
        stepRequested_ = false;
    }
    const int wanted = clock_.advance(wallSeconds);
    const TicksRun run = runTicksWithin(clock_, wanted, tickBudgetSeconds, [&] {
        if (p.atEnd()) return;
        p.step();
        view.observe(p.match());
    });
    heldBack_.frame(run, wanted, wallSeconds);
    if (p.atEnd()) paused_ = true; // Space then plays it again from the start
    p.prepareRestartPoints(kRestartTicksPerFrame);
}

void ReplayViewer::warmUp(double seconds, MatchView& view) {
    game::ReplayPlayer& p = *player_;
    const auto ticks = static_cast<std::uint64_t>(std::max(0.0, seconds) / tickSeconds());
    for (std::uint64_t i = 0; i < ticks && !p.atEnd(); ++i) {
        p.step();
        view.observe(p.match());
    }
}

std::optional<std::uint64_t> ReplayViewer::previousShot() const {
    const std::uint64_t now = seek_.value_or(player_->tick());
    const auto grace = static_cast<std::uint64_t>(0.5 / tickSeconds());
    return player_->shotBefore(now > grace ? now - grace : 0);
}

void ReplayViewer::togglePlay() {
    if (paused_ && player_->atEnd()) seek_ = 0;
    paused_ = !paused_;
}

void ReplayViewer::changeSpeed(int by) {
    speed_ = std::clamp(speed_ + by, 0, static_cast<int>(std::size(kReplaySpeeds)) - 1);
    speedPicked_ = true;
}

void ReplayViewer::jumpBy(double seconds) {
    const double ticks = std::round(seconds / tickSeconds());
    const double base = static_cast<double>(seek_.value_or(player_->tick()));
    seek_ = static_cast<std::uint64_t>(std::max(0.0, base + ticks));
}

// ---- controls -------------------------------------------------------------------------
ReplayRequests ReplayViewer::panel(ImVec2 corner) {
    ReplayRequests req;
    const game::ReplayPlayer& p = *player_;
    const double dt = tickSeconds();
    // Where the game screen found room for it: clear of what the player watches.
    ImGui::SetNextWindowPos(corner, ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(panelPx(470), 0), ImGuiCond_Always);
    ImGui::Begin("Replay", nullptr,
                 ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::TextColored(kDimText, "%s: %.1f s, %zu shots", p.match().level().name.c_str(),
                       static_cast<double>(p.lastTick()) * dt, p.shotTicks().size());
    transportRow();
    // The scrub bar over the whole recording; it seeks while dragged, backwards too.
    std::uint64_t shown = seek_.value_or(p.tick());
    const std::uint64_t lo = 0, hi = std::max<std::uint64_t>(p.lastTick(), 1);
    char label[64];
    std::snprintf(label, sizeof label, "%.1f s of %.1f s", static_cast<double>(shown) * dt,
                  static_cast<double>(p.lastTick()) * dt);
    ImGui::SetNextItemWidth(-FLT_MIN);
    if (ImGui::SliderScalar("##scrub", ImGuiDataType_U64, &shown, &lo, &hi, label)) seek_ = shown;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Drag to any moment (going back plays it again from the start)");
    verdictLine();
    if (ImGui::Button("Take over (T)")) req.takeOver = true;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Play on from this moment: the commands so far are kept and a new replay "
                          "branches from here");
    ImGui::SameLine();
    if (instant_) {
        if (ImGui::Button("Back to the game (Z)")) req.backToGame = true;
    } else {
        if (buttonWhen(video_.state() != VideoExport::State::Running, "Export video",
                       "write the whole replay as an MP4 with sound, beside the replays"))
            req.exportVideo = true;
        ImGui::SameLine();
        if (ImGui::Button("Replays")) req.close = true;
    }
    videoLine();
    ImGui::End();
    return req;
}

void ReplayViewer::transportRow() {
    const game::ReplayPlayer& p = *player_;
    const auto prevShot = previousShot(), nextShot = p.shotAfter(seek_.value_or(p.tick()));
    if (buttonWhen(prevShot.has_value(), "|<", "the previous shot (Page Up)")) seek_ = prevShot;
    ImGui::SameLine();
    if (buttonWhen(true, "<<", "a second back (left arrow)")) jumpBy(-1.0);
    ImGui::SameLine();
    if (ImGui::Button(paused_ ? (p.atEnd() ? "Again" : "Play") : "Pause", ImVec2(panelPx(70), 0)))
        togglePlay();
    ImGui::SameLine();
    if (buttonWhen(!p.atEnd(), "Step", "one tick (.); one back: ,")) {
        paused_ = true;
        stepRequested_ = true;
    }
    ImGui::SameLine();
    if (buttonWhen(true, ">>", "a second on (right arrow)")) jumpBy(1.0);
    ImGui::SameLine();
    if (buttonWhen(nextShot.has_value(), ">|", "the next shot (Page Down)")) seek_ = nextShot;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-FLT_MIN);
    speedPicked_ |=
        ImGui::SliderInt("##speed", &speed_, 0, static_cast<int>(std::size(kReplaySpeeds)) - 1,
                         kSpeedNames[speed_], ImGuiSliderFlags_NoInput);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("speed ([ and ])");
}

/// What a player wants to know of a recording: that it plays as it was played, or from
/// when it does not and what differs. Said once it is known, not as a running count.
void ReplayViewer::verdictLine() {
    const game::ReplayPlayer& p = *player_;
    const double dt = tickSeconds();
    if (const auto& div = p.divergence()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kBadText);
        ImGui::TextWrapped("Not as recorded from %.1f s (tick %llu): %s differs. Another build, "
                           "or an edited file.",
                           static_cast<double>(div->tick) * dt,
                           static_cast<unsigned long long>(div->tick), div->what.c_str());
        ImGui::PopStyleColor();
    } else if (p.atEnd() && p.checkpointsChecked() > 0) {
        ImGui::TextColored(kGoodText, "Replay verified: it plays exactly as it was recorded.");
    }
    if (p.refusedCommands() > 0)
        ImGui::TextColored(kBadText, "%zu recorded command(s) could not be played here",
                           p.refusedCommands());
}

ReplayRequests ReplayViewer::key(const SDL_Keysym& k, bool repeat, bool& handled) {
    ReplayRequests req;
    handled = true;
    const bool shift = (k.mod & KMOD_SHIFT) != 0;
    switch (k.sym) {
    case SDLK_SPACE:
    case SDLK_k:
        if (!repeat) togglePlay();
        break;
    case SDLK_PERIOD:
        paused_ = true;
        stepRequested_ = true;
        break;
    case SDLK_COMMA:
        paused_ = true;
        if (player_->tick() > 0) seek_ = seek_.value_or(player_->tick()) - 1;
        break;
    case SDLK_LEFT:
        jumpBy(shift ? -5.0 : -1.0);
        break;
    case SDLK_RIGHT:
        jumpBy(shift ? 5.0 : 1.0);
        break;
    case SDLK_PAGEUP:
        if (const auto t = previousShot()) seek_ = t;
        break;
    case SDLK_PAGEDOWN:
        if (const auto t = player_->shotAfter(seek_.value_or(player_->tick()))) seek_ = t;
        break;
    case SDLK_LEFTBRACKET:
        changeSpeed(-1);
        break;
    case SDLK_RIGHTBRACKET:
        changeSpeed(+1);
        break;
    case SDLK_BACKSLASH:
        speed_ = 3;
        speedPicked_ = true;
        break;
    case SDLK_r:
        if (!repeat) seek_ = 0;
        break;
    case SDLK_t:
        req.takeOver = !repeat;
        break;
    default:
        handled = false;
        break;
    }
    return req;
}

// ---- video ----------------------------------------------------------------------------
void ReplayViewer::exportVideo(const std::string& folder) {
    namespace fs = std::filesystem;
    fs::path name = fs::path(file_).stem(); // "05_castle.replay.json" -> "05_castle"
    if (name.extension() == ".replay") name = name.stem();
    const fs::path dir = folder.empty() ? fs::path(file_).parent_path() : fs::path(folder);
    std::error_code ec;
    fs::create_directories(dir, ec);
    const std::string out = (dir / name).string() + ".mp4";
    // The same program, so the video is drawn by the same code as `run --video`.
    video_.start("/proc/self/exe", match().level().file, file_, out);
}

bool ReplayViewer::videoLine() {
    const VideoExport::State state = video_.poll();
    std::string detail = video_.file();
    switch (state) {
    case VideoExport::State::Idle:
        return false;
    case VideoExport::State::Running:
        ImGui::TextColored(kDimText, "exporting the video ...");
        break;
    case VideoExport::State::Done:
        ImGui::TextColored(kGoodText, "video saved: %s",
                           std::filesystem::path(video_.file()).filename().string().c_str());
        break;
    case VideoExport::State::Failed:
        ImGui::TextColored(kBadText, "video not written");
        detail = video_.message();
        break;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", detail.c_str());
    return true;
}

std::string ReplayViewer::banner() const {
    const game::ReplayPlayer& p = *player_;
    char line[64];
    if (p.divergence())
        std::snprintf(line, sizeof line, "REPLAY DIVERGED");
    else if (p.atEnd())
        std::snprintf(line, sizeof line, "REPLAY ended (T plays on)");
    else if (instant_)
        std::snprintf(line, sizeof line, "LAST SHOT %s  %.1f s", kSpeedNames[speedNow()],
                      static_cast<double>(p.tick()) * tickSeconds());
    else if (paused_)
        std::snprintf(line, sizeof line, "REPLAY paused  %.1f s",
                      static_cast<double>(p.tick()) * tickSeconds());
    else
        std::snprintf(line, sizeof line, "REPLAY %s  %.1f s", kSpeedNames[speed_],
                      static_cast<double>(p.tick()) * tickSeconds());
    std::string banner = line;
    if (heldBack_.shown() && !paused_ && !p.atEnd() && !p.divergence()) {
        std::snprintf(line, sizeof line, "  SLOW MOTION: a tick of %.0f ms takes %.0f ms",
                      1000.0 * tickSeconds(), heldBack_.tickWallMs());
        banner += line;
    }
    return banner;
}

} // namespace ui
