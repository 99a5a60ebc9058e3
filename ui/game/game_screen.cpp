// Section index
//   set-up       GameScreen(), openLevel, restart, persistence
//   commands     submit: the only way the window changes the match
//   time         simulate: fixed ticks from the clock, held keys and the controller
//   replays      openReplay, takeOverReplay, rewindLive, watchLastShot: watching, branching,
//                rewinding, the last shot again
//   drawing      frame, drawPlaying, drawPanels
//   events       handleEvent: mouse aim, keys, controller buttons
#include "ui/platform/gl_setup.h"
#include "ui/game/game_screen.h"

#include "game/editor/level_editor.h"
#include "game/editor/sandbox_to_level.h"
#include "game/files/text_file.h"
#include "game/level_write.h"
#include "ui/game/match_frame.h"
#include "ui/game/random_map.h"
#include "ui/game/settings_commands.h"
#include "ui/game/target_inset.h"
#include "ui/game/tick_budget.h"
#include "ui/game/turn_controls.h"
#include "ui/platform/imgui_layer.h"
#include "ui/platform/sdl_window.h"
#include "ui/render/design_canvas.h"
#include "ui/render/gl.h"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <stdexcept>

namespace ui {

namespace {

/// Hotseat: the computer's cannon is handed to a second person. The level is data, so
/// this is a copy with the player renamed; the session then never runs the AI for it.
game::Level withHotseat(game::Level level) {
    for (game::Cannon& c : level.cannons)
        if (c.player == "cpu") c.player = "2";
    return level;
}

/// How long a refused command stays on the HUD, s of wall time.
constexpr double kNoticeSeconds = 3.0;

/// Time scales the [ and ] keys step through.
constexpr float kSpeeds[] = {1.0f / 16, 0.125f, 0.25f, 0.5f, 1.0f, 2.0f, 4.0f};

/// The view the window opens with: the player's stored draw choices, plus what the
/// command line turns on (its draw flags only switch things on).
ViewControls openingView(ViewControls flags, const DrawChoices& stored) {
    DebugOverlays& d = flags.draw;
    flags.trails = flags.trails && stored.trails;
    flags.labels = flags.labels && stored.labels;
    d.velocities = d.velocities || stored.velocities;
    d.forces = d.forces || stored.forces;
    d.ghosts = d.ghosts || stored.ghosts;
    d.contacts = d.contacts || stored.contacts;
    d.cells = d.cells || stored.cells;
    d.sleeping = d.sleeping || stored.sleeping;
    d.models = d.models || stored.models;
    return flags;
}

DrawChoices drawChoices(const ViewControls& v) {
    const DebugOverlays& d = v.draw;
    return {v.trails,   v.labels, d.velocities, d.forces, d.ghosts,
            d.contacts, d.cells,  d.sleeping,   d.models};
}

} // namespace

// ---- set-up ---------------------------------------------------------------------------
GameScreen::GameScreen(GLContext& context, SdlWindow* window, const GameScreenDef& def)
    : context_(context), window_(window), def_(def), glLoaded_(loadGLOrThrow(context)),
      imgui_(context, window) {
    stats_.context = context.name();
    tickBudget_ = def_.tickBudgetSeconds;
    if (!tickBudget_ && window_) tickBudget_ = kWindowTickBudgetSeconds;
    samples_ = autoSamples(def_.msaaSamples);
    msaa_.resize(context.width(), context.height(), samples_);
    // The player's files (ui/game/player_files.h): read here, saved merged in persist().
    files_ = PlayerFiles({def_.settingsFolder, def_.progressFile, def_.progressReadOnly});
    settings_ = files_.loadSettings();
    if (const std::string ini = files_.loadLayout(); !ini.empty())
        ImGui::LoadIniSettingsFromMemory(ini.data(), ini.size());
    progress_ = files_.loadProgress(settings_);
    for (const std::string& notice : files_.takeNotices()) { // said once: terminal and window
        std::cerr << "artillery: " << notice << "\n";
        stats_.status = notice;
    }
    view_ = openingView(def_.view, settings_.draw);
    matchView_.followGhosts(view_.draw.ghosts);
    if (def_.difficulty) settings_.difficulty = *def_.difficulty;
    if (def_.hotseat) settings_.hotseat = *def_.hotseat;
    if (!def_.panel) settings_.physicsPanel = false;
    levels_ = listLevels(def_.levelsFolder);
    campaign_ = campaignMenu(def_.levelsFolder, levels_);
    if (window_ && SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) == 0) pad_.openFirst();
    if (window_) {
        audio_ = std::make_unique<AudioDevice>();
        if (audio_->silent()) std::cerr << "artillery: playing silent (" << audio_->why() << ")\n";
    }
    if (!def_.replayFile.empty()) {
        openReplay(def_.replayFile); // throws with the loader's message
    } else if (def_.edit) {
        openEditor(def_.levelFile.empty() ? game::editor::newLevel()
                                          : game::loadLevel(def_.levelFile)); // throws likewise
    } else if (def_.levelFile.empty()) {
        overlay_ = Overlay::LevelSelect;
        for (const LevelEntry& e : levels_) {
            if (!e.error.empty()) continue;
            backdrop_ = std::make_unique<game::Match>(game::loadLevel(e.file));
            frameLevel(*backdrop_);
            break;
        }
    } else
        openLevel(def_.levelFile); // throws with the loader's message
}

GameScreen::~GameScreen() {
    persist();
}

void GameScreen::persist() {
    settings_.draw = drawChoices(view_);
    std::size_t size = 0;
    const char* ini = ImGui::SaveIniSettingsToMemory(&size);
    for (const std::string& err : files_.save(progress_, settings_, std::string(ini, size)))
        std::cerr << "artillery: " << err << "\n";
}

void GameScreen::openLevel(const std::string& file) {
    level_ = game::loadLevel(file);
    editing_ = playtest_ = false;
    backdrop_.reset();
    viewer_.reset();
    restart();
    overlay_ = Overlay::None;
}

std::string GameScreen::replaysFolder() const { return files_.replaysFolder(); }

std::string GameScreen::recordFileFor(const std::string& name) const {
    const std::string folder = replaysFolder();
    if (folder.empty()) return "";
    return (std::filesystem::path(folder) / name).string();
}

bool GameScreen::hotseatInUse() const {
    return settings_.hotseat && level_.mode == game::Mode::Duel;
}

game::SessionOptions GameScreen::liveOptions(const std::string& recordFile) {
    game::SessionOptions o;
    o.difficulty = settings_.difficulty;
    o.cpuSeed = level_.seed;
    // Every match is recorded; the session saves at each turn's end.
    o.recordFile = recordFile;
    o.onSaveFailure = [this](const std::string& why) { // the game plays on, and says so once
        if (const std::string said = files_.failedOnce("the replay", why); !said.empty()) {
            std::cerr << "artillery: " << said << "\n";
            stats_.status = said;
        }
    };
    return o;
}

void GameScreen::restart() {
    if (instantReplay()) backToLive(); // R restarts the level, not the shot watched
    if (viewer_) {
        viewer_->requestSeek(0); // a replay restarts from its beginning
        return;
    }
    const std::string stem = std::filesystem::path(level_.file).stem().string();
    playSession(std::make_unique<game::Session>(hotseatInUse() ? withHotseat(level_) : level_,
                                                liveOptions(recordFileFor(stem + "-last.json"))));
    matchView_.reset();
    cameraMoved_ = false;
    frameLevel(session_->match());
    if (def_.sandbox && !session_->match().sandbox()) {
        game::Command c; // every level opens as a sandbox too: a command, so it replays
        c.kind = game::CommandKind::Sandbox;
        submit(c);
    }
}

void GameScreen::playSession(std::unique_ptr<game::Session> session) {
    session_ = std::move(session);
    viewer_.reset();
    phys::ClockDef cd;
    cd.tickSeconds = session_->match().world().def().tickSeconds;
    clock_ = phys::FixedClock(cd);
    aim_ = AimInput();
    rewind_ = RewindControl();
    branchNote_.clear();
    resultRecorded_ = newBest_ = false;
}

const game::Match* GameScreen::shownMatch() const {
    if (viewer_) return &viewer_->match();
    return session_ ? &session_->match() : nullptr;
}

// ---- the level editor --------------------------------------------------------------------
std::string GameScreen::mapsFolder() const { return randomMapsFolder(def_.settingsFolder); }

void GameScreen::openEditor(game::Level level) {
    editor_ = std::make_unique<LevelEditorView>(std::move(level), mapsFolder());
    session_.reset();
    viewer_.reset();
    backdrop_.reset();
    editing_ = true;
    playtest_ = false;
    overlay_ = Overlay::None;
    cameraMoved_ = panning_ = false;
    camera_ = editor_->framing(context_.width(), context_.height());
}

/// As the Random map row does: the level is written into the maps folder and played from
/// there, through the loader, so what is played is what the file says (and a replay of
/// it names a file that holds it).
void GameScreen::playEditedLevel() {
    const game::editor::LevelEditor& edited = editor_->editor();
    if (!edited.valid()) return;
    const std::string file = (std::filesystem::path(mapsFolder()) / "playtest.json").string();
    try {
        std::filesystem::create_directories(mapsFolder());
        game::saveLevel(file, edited.level());
        openLevel(file);
    } catch (const std::exception& e) {
        stats_.status = std::string("cannot play it: ") + e.what();
        std::cerr << "artillery: " << stats_.status << "\n";
        return;
    }
    playtest_ = true;
}

void GameScreen::backToEditor() {
    session_.reset();
    viewer_.reset();
    editing_ = true;
    playtest_ = false;
    overlay_ = Overlay::None;
    cameraMoved_ = panning_ = false;
    camera_ = editor_->framing(context_.width(), context_.height());
    aim_ = AimInput();
}

void GameScreen::editorPanels() {
    const EditorRequests r = editor_->panel();
    if (helpOpen_) helpOverlay(helpOpen_);
    if (r.play) playEditedLevel();
    if (r.close) {
        editing_ = false; // kept: the level select offers to come back to it
        overlay_ = Overlay::LevelSelect;
    }
}

bool GameScreen::editorEvent(const SDL_Event& e) {
    LevelEditorView& view = *editor_;
    if (e.type == SDL_KEYDOWN) {
        if (imgui_.wantsKeyboard()) return running_;
        const SDL_Keycode key = e.key.keysym.sym;
        if (key == SDLK_F12) screenshotRequested_ = true;
        if (key == SDLK_F1) helpOpen_ = !helpOpen_;
        if (key == SDLK_HOME) cameraMoved_ = false; // framed again next frame
        const bool ctrl = (e.key.keysym.mod & KMOD_CTRL) != 0;
        const bool shift = (e.key.keysym.mod & KMOD_SHIFT) != 0;
        const EditorRequests r = view.key(key, ctrl, shift);
        if (r.play) playEditedLevel();
        if (r.close) {
            editing_ = false;
            overlay_ = Overlay::LevelSelect;
        }
        return running_;
    }
    const bool mouse = e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP ||
                       e.type == SDL_MOUSEMOTION || e.type == SDL_MOUSEWHEEL;
    if (!mouse) return running_;
    // The panel takes the mouse over it, but a drag begun in the world ends in the world.
    if ((imgui_.wantsMouse() || imgui_.pressOnWindow(e)) && !view.dragging() && !panning_)
        return running_;
    const double reach = camera_.metres(8.0); // a handle takes clicks 8 px around it
    // Over the panel a press is the panel's, even on the frame the editor comes back
    // (ImGui learns what is under the pointer only from the frame it draws).
    const bool overPanel = e.type == SDL_MOUSEBUTTONDOWN &&
                           pointerPixels(e.button.x, e.button.y).x <
                               std::min<double>(panelPx(kEditorPanelWidth), 0.5 * context_.width());
    if (e.type == SDL_MOUSEBUTTONDOWN && e.button.button == SDL_BUTTON_LEFT && !overPanel)
        view.press(camera_.toWorld(pointerPixels(e.button.x, e.button.y)), reach);
    else if (e.type == SDL_MOUSEBUTTONUP && e.button.button == SDL_BUTTON_LEFT)
        view.lift();
    else {
        if (e.type == SDL_MOUSEMOTION)
            view.move(camera_.toWorld(pointerPixels(e.motion.x, e.motion.y)), reach);
        cameraEvent(e); // wheel zooms, right (or middle) drag pans
    }
    return running_;
}

// ---- camera ---------------------------------------------------------------------------
void GameScreen::frameLevel(const game::Match& m) {
    camera_ = levelCamera(m, context_.width(), context_.height(), coveredBottom_);
    rig_.setHome(camera_.center, camera_.pixelsPerMetre, camera_.width, camera_.height);
    rig_.tick(m); // from this tick on
    homeJumpFrames_ = 3;
}

void GameScreen::keepClearOfPanels(const game::Match& m, const std::optional<PixelRect>& panel) {
    const double covered =
        coveredBottom(panel.value_or(PixelRect{}), context_.width(), context_.height());
    const bool mayJump = homeJumpFrames_ > 0;
    homeJumpFrames_ = std::max(0, homeJumpFrames_ - 1); // called once a frame
    rig_.setCoveredBottom(covered);
    // A line more or less in the panel (a hint's, a duel's) moves home; a pixel does not.
    if (std::abs(covered - coveredBottom_) < 0.005) return;
    coveredBottom_ = covered;
    const Camera home = levelCamera(m, context_.width(), context_.height(), coveredBottom_);
    rig_.moveHome(home.center, home.pixelsPerMetre, mayJump);
    if (following() && rig_.phase() == game::CameraRig::Phase::Home) {
        camera_.center = rig_.center();
        camera_.pixelsPerMetre = rig_.pixelsPerMetre();
    }
}

bool GameScreen::following() const { return !editing_ && settings_.cameraFollow && !cameraMoved_; }

void GameScreen::followShot(const game::Match& m) {
    rig_.tick(m);
    if (!following()) return;
    camera_.center = rig_.center();
    camera_.pixelsPerMetre = rig_.pixelsPerMetre();
}

Camera GameScreen::shakenCamera() const {
    Camera c = camera_;
    const double shake = matchView_.effects().shake();
    if (!settings_.screenShake || shake <= 0.0) return c;
    // Up to 9 px, in a pattern that depends on simulated time only (two incommensurate
    // frequencies), so a replay shakes the same way every time it is watched.
    const double t = matchView_.effects().time();
    const double px = 9.0 * shake;
    c.center += phys::Vec2{std::sin(97.0 * t), std::cos(71.0 * t)} * c.metres(px);
    return c;
}

/// A learning aid in view during a human's turn is a command, so the replay carries it
/// and the match caps the stars (game/match.h, kAssistedMaxStars).
void GameScreen::markAssists() {
    if (!session_ || viewer_ || !humanTurn()) return;
    const game::Match& m = session_->match();
    if (m.level().mode != game::Mode::Practice) return;
    auto assist = [&](int bit, const char* what) {
        if (m.assisted() & bit) return;
        game::Command c;
        c.kind = game::CommandKind::Assist;
        c.text = what;
        submit(c);
    };
    if (settings_.trajectoryPreview && settings_.fullPreview) assist(game::kAssistPreview, "preview");
    if (settings_.solutionHint) assist(game::kAssistHint, "hint");
}

// ---- commands -------------------------------------------------------------------------
void GameScreen::submit(const game::Command& command) {
    if (!session_) return;
    const std::string why = session_->submit(command);
    if (why.empty()) return;
    stats_.status = notice_ = std::string(game::commandName(command.kind)) + ": " + why;
    noticeSeconds_ = kNoticeSeconds;
}

void GameScreen::submit(const std::vector<game::Command>& commands) {
    for (const game::Command& c : commands) submit(c);
}

bool GameScreen::humanTurn() const {
    if (!session_) return false;
    const game::Match& m = session_->match();
    return !m.over() && m.cannon().def.player != "cpu";
}

void GameScreen::recordResultOnce() {
    const game::Match& m = session_->match();
    if (!m.over() || resultRecorded_) return;
    resultRecorded_ = true;
    if (playtest_) return; // a level being made earns no stars
    const bool humanWon = m.winner() >= 0 &&
                          m.cannons()[static_cast<std::size_t>(m.winner())].def.player != "cpu";
    newBest_ = progress_.record(level_.file, m.score(), m.stars(), humanWon, m.assisted() != 0);
    persist();
}

// ---- time -----------------------------------------------------------------------------
void GameScreen::pollHeldInput(double dt) {
    const game::Match& m = session_->match();
    HeldAxes axes;
    if (humanTurn() && !m.shell()) {
        if (!imgui_.wantsKeyboard() && window_ && overlay_ == Overlay::None) axes = heldArrowKeys();
        if (pad_.connected()) {
            const PadAxes pad = pad_.axes();
            aim_.stick(pad.stickX, pad.stickY);
            axes.power += pad.power;
        }
    }
    submit(holdToAim(axes, dt, aim_, m, humanTurn()));
}

void GameScreen::simulate(double wallSeconds) {
    const bool menuPause = overlay_ != Overlay::None || helpOpen_;
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
        matchView_.observe(session_->match());
        statsPanel_.sample(session_->match());
        hearTick(session_->match());
        physicsUs += session_->match().world().profile().totalUs;
    });
    const int ticks = run.ran;
    // What a tick costs here is the world, the blocks and the match together.
    slowMotion_.frame(run, wanted, wallSeconds);
    const game::Match& m = session_->match();
    stats_.ticksThisFrame = ticks;
    if (ticks > 0) stats_.physicsUs = physicsUs / ticks;
    stats_.integrateUs = m.world().profile().integrateUs;
    stats_.springsUs = m.world().profile().springsUs;
    stats_.tick = m.tick();
    stats_.simSeconds = m.time();
    stats_.particles = m.world().particles.count();
    stats_.springs = m.world().springs.size();
    recordResultOnce();
}

void GameScreen::warmUp(double seconds) {
    if (viewer_) viewer_->warmUp(seconds, matchView_);
    if (!session_) return;
    const auto ticks = static_cast<long long>(seconds / session_->match().world().def().tickSeconds);
    for (long long i = 0; i < ticks; ++i) {
        session_->step();
        matchView_.observe(session_->match());
        statsPanel_.sample(session_->match());
    }
}

// ---- replays ---------------------------------------------------------------------------
void GameScreen::openReplay(const std::string& file) {
    game::Replay replay = game::loadReplay(file);
    level_ = game::levelForReplay(file, replay);
    // The same level the live game would use, so taking over plays as a new game would.
    viewer_ = std::make_unique<ReplayViewer>(file, hotseatInUse() ? withHotseat(level_) : level_,
                                             std::move(replay));
    editing_ = playtest_ = false;
    session_.reset();
    backdrop_.reset();
    branchNote_.clear();
    aim_ = AimInput();
    matchView_.reset();
    cameraMoved_ = false;
    frameLevel(viewer_->match());
    overlay_ = Overlay::None;
}

void GameScreen::showReplays() {
    replays_ = listReplays(replaysFolder());
    overlay_ = Overlay::Replays;
}

namespace {

/// The tick of the match's last shot (any cannon's), if one was fired.
std::optional<std::uint64_t> lastShotTick(const game::Match& m) {
    const auto& events = m.events();
    for (auto e = events.rbegin(); e != events.rend(); ++e)
        if (e->kind == game::EventKind::Fired) return e->tick;
    return std::nullopt;
}

/// Where the shot fired at `fired` first met something: its first bounce, burst or hit,
/// or the tick it was over.
std::optional<std::uint64_t> impactTick(const game::Match& m, std::uint64_t fired) {
    using game::EventKind;
    for (const game::GameEvent& e : m.events())
        if (e.tick > fired && (e.kind == EventKind::Bounce || e.kind == EventKind::Burst ||
                               e.kind == EventKind::TargetHit || e.kind == EventKind::CannonHit ||
                               e.kind == EventKind::ShotOver))
            return e.tick;
    return std::nullopt;
}

} // namespace

void GameScreen::watchLastShot() {
    if (!session_ || viewer_ || session_->match().shell()) return;
    const game::Match& m = session_->match();
    const auto fired = lastShotTick(m);
    if (!fired) return;
    const auto lead = static_cast<std::uint64_t>(0.5 / m.world().def().tickSeconds);
    aim_.cancelCharge();
    viewer_ =
        std::make_unique<ReplayViewer>("the last shot", m.level(), session_->finishedRecording());
    viewer_->makeInstant(*fired > lead ? *fired - lead : 0, impactTick(m, *fired));
}

void GameScreen::backToLive() {
    // Watched to its end, the replay stands where the game does, trails and all; left
    // sooner, the view starts again from the game as it stands.
    const bool atTheGame = viewer_ && viewer_->player().atEnd();
    viewer_.reset();
    if (atTheGame || !session_) return;
    matchView_.reset();
    matchView_.observe(session_->match());
}

void GameScreen::takeOverReplay() {
    const double dt = viewer_->match().world().def().tickSeconds;
    const std::uint64_t at = viewer_->player().tick();
    const std::string from = std::filesystem::path(viewer_->file()).filename().string();
    // A new file per branch: the replay watched stays as it was.
    const std::string record = recordFileFor(std::filesystem::path(level_.file).stem().string() +
                                             "-branch-" + std::to_string(at) + ".json");
    playSession(std::make_unique<game::Session>(viewer_->takeOver(liveOptions(record))));
    resultRecorded_ = session_->match().over(); // a finished game is not scored again
    branchTick_ = at;
    char note[256];
    std::snprintf(note, sizeof note, "branch of %s from %.1f s, %s", from.c_str(),
                  static_cast<double>(at) * dt,
                  record.empty()
                      ? "not recorded (check run)"
                      : ("recording " + std::filesystem::path(record).filename().string()).c_str());
    branchNote_ = note;
    if (!record.empty()) {
        try {
            session_->save(record);
        } catch (const std::exception& e) {
            stats_.status = std::string("branch not saved: ") + e.what();
        }
    }
}

void GameScreen::rewindLive(std::uint64_t tick) {
    const game::Match& before = session_->match();
    if (tick >= before.tick()) return;
    const double dt = before.world().def().tickSeconds;
    session_->rewindTo(tick);
    matchView_.reset();
    matchView_.observe(session_->match());
    aim_ = AimInput();
    resultRecorded_ = session_->match().over();
    newBest_ = false;
    branchTick_ = tick;
    char note[160];
    std::snprintf(note, sizeof note, "rewound to %.1f s: playing on as a new branch",
                  static_cast<double>(tick) * dt);
    branchNote_ = note;
}

// ---- drawing --------------------------------------------------------------------------
phys::Vec2 GameScreen::pivotPixels() const {
    return camera_.toPixel(session_->match().cannon().def.position);
}

std::string GameScreen::banner() const {
    if (viewer_) return viewer_->banner();
    return session_ ? liveBanner(session_->match()) : std::string();
}

std::string GameScreen::liveBanner(const game::Match& m) const {
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
        std::snprintf(banner, sizeof banner, "the computer is aiming...");
    else if (m.over() && newBest_)
        std::snprintf(banner, sizeof banner, "new best for this level!");
    return banner;
}

void GameScreen::drawPlaying() {
    const game::Match& m = *shownMatch();
    MatchViewOptions o;
    o.trails = view_.trails;
    o.overlays = view_.draw;
    for (const game::CannonState& c : m.cannons())
        o.playerNames.push_back(defaultPlayerName(c.def.player));
    if (viewer_) {
        // A replay shows what was played: no aim being edited, no preview of one.
        o.trajectoryPreview = false;
        o.solutionHint = false;
        o.banner = viewer_->banner();
    } else {
        o.trajectoryPreview = settings_.trajectoryPreview && humanTurn();
        o.fullPreview = settings_.fullPreview;
        o.solutionHint = settings_.solutionHint && humanTurn();
        if (humanTurn() && aim_.editing()) o.pending = aim_.pending();
        o.charge = aim_.chargeFraction();
        o.banner = liveBanner(m);
        o.notice = notice();
    }
    const Camera shown = shakenCamera();
    drawMatchFrame(renderer_, matchView_, m, shown, o);
    if (!viewer_ && session_) { // the rope being drawn, the hand and what it holds
        sandboxTools_.draw(renderer_, m);
        statsPanel_.drawWorld(renderer_, m);
        renderer_.flush();
    }
    // Beside the Stats window when it is open where the close-up goes (last frame's place);
    // not while its charts take the middle of the view.
    TargetInsetDef insetDef;
    if (const auto stats = openWindowRect("Stats")) insetDef = clearOf(insetDef, shown, *stats);
    const auto inset = statsPanel_.chartsShown() ? std::nullopt : targetInset(m, shown, insetDef);
    if (inset)
        drawTargetInset(renderer_, matchView_, m, shown, *inset, o);
}

void GameScreen::drawPanels() {
    if (editing_) {
        editorPanels();
        return;
    }
    MenuChoice choice;
    editorForm_.editing = editor_ ? editor_->editor().level().name : "";
    if (overlay_ == Overlay::LevelSelect)
        choice = levelSelectScreen(campaign_, progress_, settings_, &randomMap_, &editorForm_, &levels_);
    if (overlay_ == Overlay::Lesson)
        choice = lessonScreen(campaign_.campaign, lessonChapter_, lessonThenLevel_);
    if (overlay_ == Overlay::Replays) choice = replaysScreen(replays_, replaysFolder());
    if (overlay_ == Overlay::Pause) choice = pauseMenu(settings_, audio_ ? audio_->why() : "");
    if (helpOpen_) helpOverlay(helpOpen_);
    if (viewer_ && overlay_ == Overlay::None) {
        const ReplayRequests req = viewer_->panel();
        keepClearOfPanels(viewer_->match(), openWindowRect("Replay"));
        if (req.takeOver)
            takeOverReplay();
        else if (req.close)
            showReplays();
        else if (req.exportVideo)
            viewer_->exportVideo(replaysFolder());
        else if (req.backToGame)
            backToLive();
    }
    bool sceneToEditor = false;
    if (session_ && !viewer_ && overlay_ == Overlay::None) {
        game::Match& m = session_->match();
        const MatchPanelRequests req = matchPanel(m, humanTurn(), settings_, settings_.difficulty,
                                                  hotseatInUse(), rewind_, branchNote_);
        keepClearOfPanels(m, openWindowRect("Match"));
        if (req.projectile)
            if (auto c = AimInput::select(m.cannon(), *req.projectile)) submit(*c);
        if (req.fire && humanTurn()) submit(aim_.fire(m.cannon()));
        if (req.watchLastShot) watchLastShot();
        submit(sandboxTools_.panel(m));
        sceneToEditor = sandboxTools_.takeSaveAsLevel();
        if (playtest_) {
            const ImVec2 display = ImGui::GetIO().DisplaySize;
            // Under the wind gauge at the top centre.
            const auto underGauge = static_cast<float>(76.0 * hudScale(display.x, display.y));
            ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, underGauge), ImGuiCond_Always,
                                    ImVec2(0.5f, 0.0f));
            ImGui::Begin("Playtest", nullptr,
                         ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                             ImGuiWindowFlags_NoSavedSettings);
            if (ImGui::Button("Back to the editor (F4)")) choice.continueEditing = true;
            ImGui::End();
        }
        if (req.endTurn && humanTurn()) submit(AimInput::endTurn());
        const PendingAim shownAim = aim_.editing() ? aim_.pending() : PendingAim{m.cannon().angleDeg, m.cannon().speedMps};
        if (auto d = statsPanel_.panel(m, shownAim)) submit(settingCommands(m.world().def(), *d));
        if (settings_.physicsPanel) {
            const game::LiveSettings before = m.liveSettings();
            game::LiveSettings edited = before;
            SceneRequests scene;
            // Folded at first: the sky is where the shells fly. Its layout persists.
            ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
            if (physicsPanel(edited, m.materialsInPlay(), time_, view_, scene, stats_))
                submit(settingCommands(before, edited));
            if (scene.fire && humanTurn()) submit(aim_.fire(m.cannon()));
            if (scene.reset) restart();
        }
        if (m.over() && resultRecorded_ && !choice.openLevel && !playtest_)
            choice = nextLevelCard(campaign_, progress_, level_.file);
        // Last: a rewind replaces the match `m` refers to.
        if (req.rewindTo && session_) rewindLive(*req.rewindTo);
    }
    if (choice.lessonSeen && progress_.lessonsSeen.insert(*choice.lessonSeen).second) persist();
    if (choice.showLesson) {
        lessonChapter_ = *choice.showLesson;
        lessonThenLevel_ = choice.lessonThenLevel;
        overlay_ = Overlay::Lesson;
    }
    if (sceneToEditor && session_) openEditor(game::editor::sandboxToLevel(session_->match()));
    if (choice.openLevel) openLevel(*choice.openLevel);
    if (choice.editLevel) {
        try {
            openEditor(choice.editLevel->empty() ? game::editor::newLevel()
                                                 : game::loadLevel(*choice.editLevel));
        } catch (const std::exception& e) {
            stats_.status = e.what();
            std::cerr << "artillery: " << e.what() << "\n";
        }
    }
    if (choice.continueEditing && editor_) backToEditor();
    if (choice.randomMap)
        if (const auto file = writeRandomMap(*choice.randomMap, settings_.difficulty,
                                             randomMapsFolder(def_.settingsFolder), randomMap_.status))
            openLevel(*file);
    if (choice.openReplay) {
        try {
            openReplay(*choice.openReplay);
        } catch (const std::exception& e) {
            stats_.status = e.what();
            std::cerr << "artillery: " << e.what() << "\n";
        }
    }
    if (choice.replays) showReplays();
    if (choice.resume) overlay_ = Overlay::None;
    if (choice.restart && (session_ || viewer_)) {
        restart();
        overlay_ = Overlay::None;
    }
    if (choice.levelSelect) overlay_ = Overlay::LevelSelect;
    if (choice.help) helpOpen_ = true;
    if (choice.quit) running_ = false;
    if (choice.networkDuel) networkDuel_ = true, running_ = false;
    if (choice.settingsChanged) persist();
    // A click for every button, box and slider pressed this frame.
    if (hearing() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && ImGui::IsAnyItemHovered())
        sound_.click();
}

bool GameScreen::hearing() const {
    return audio_ && !audio_->silent();
}

void GameScreen::hearTick(const game::Match& m) {
    if (!hearing()) return;
    // Panned across what the camera shows.
    sound_.setView({camera_.visibleMin().x, camera_.visibleMax().x});
    sound_.observe(m);
}

void GameScreen::hearFrame() {
    if (!hearing()) return;
    sound_.setMix(settings_.sound);
    // A live match was heard tick by tick (simulate); a replay is heard once a frame.
    // Stopped time (paused, a menu open) silences the whistle: the shell hangs still.
    if (viewer_) {
        if (viewer_->stopped())
            sound_.stillWhistles();
        else
            hearTick(viewer_->match());
    } else if (!session_) {
        sound_.forgetMatch();
    } else if (clock_.paused()) {
        sound_.stillWhistles();
    }
    audio_->feed(sound_);
}

void GameScreen::frame(double wallSeconds) {
    noticeSeconds_ = std::max(0.0, noticeSeconds_ - wallSeconds);
    if (editing_) {
        // The level being made is not simulated: it is drawn at its first tick.
    } else if (viewer_) {
        viewer_->advance(wallSeconds, overlay_ != Overlay::None || helpOpen_, matchView_,
                         tickBudget_);
        if (instantReplay() && viewer_->player().atEnd()) backToLive();
    } else if (session_) {
        pollHeldInput(wallSeconds);
        simulate(wallSeconds);
    }
    const int w = context_.width(), h = context_.height();
    if (editing_ && !cameraMoved_) {
        camera_ = editor_->framing(w, h); // the whole world beside the panel
        msaa_.resize(w, h, samples_);
    } else if (w != camera_.width || h != camera_.height) {
        if (cameraMoved_ || !shownMatch())
            camera_.width = w, camera_.height = h;
        else
            frameLevel(*shownMatch());
        msaa_.resize(w, h, samples_);
    }
    if (const game::Match* shown = shownMatch()) followShot(*shown);
    markAssists();
    imgui_.newFrame(wallSeconds);
    msaa_.bind(context_.framebuffer());
    if (editing_) {
        editor_->drawWorld(renderer_, camera_);
    } else if (shownMatch()) {
        drawPlaying();
    } else if (backdrop_) {
        // The select screen over the first level's landscape.
        MatchViewOptions o;
        o.hud = false;
        o.trajectoryPreview = false;
        drawMatchFrame(renderer_, matchView_, *backdrop_, camera_, o);
    } else {
        gl::fn.Viewport(0, 0, w, h);
        gl::fn.ClearColor(0.07f, 0.12f, 0.2f, 1.0f);
        gl::fn.Clear(GL_COLOR_BUFFER_BIT);
        renderer_.begin(camera_);
        renderer_.flush();
    }
    stats_.vertices = renderer_.stats().vertices;
    msaa_.resolveInto(context_.framebuffer());
    drawPanels();
    imgui_.drawLabels(renderer_.labels());
    imgui_.render();
    hearFrame();
}

std::string GameScreen::saveScreenshot(const std::string& path) {
    const std::string error =
        writePng(path, readFramebuffer(context_.framebuffer(), context_.width(), context_.height()));
    stats_.status = error.empty() ? "saved " + path : error;
    return error;
}

bool GameScreen::takeScreenshotRequest() {
    const bool r = screenshotRequested_;
    screenshotRequested_ = false;
    return r;
}

void GameScreen::setMeasuredFrameMs(double ms) {
    stats_.frameMs = framesMeasured_ < 2 ? ms : 0.9 * stats_.frameMs + 0.1 * ms;
    ++framesMeasured_;
}

// ---- events ---------------------------------------------------------------------------
phys::Vec2 GameScreen::pixelsPerPoint() const {
    // Window points to framebuffer pixels (they differ on high-DPI screens).
    const ImVec2 s = ImGui::GetIO().DisplayFramebufferScale;
    return {s.x, s.y};
}

phys::Vec2 GameScreen::pointerPixels(int x, int y) const {
    const phys::Vec2 s = pixelsPerPoint();
    return {x * s.x, y * s.y};
}

bool GameScreen::keyDown(const SDL_Event& e) {
    const SDL_Keycode key = e.key.keysym.sym;
    if (key == SDLK_F12) {
        screenshotRequested_ = true;
        return true;
    }
    if (key == SDLK_F4 && playtest_ && editor_) {
        backToEditor();
        return true;
    }
    if (key == SDLK_F1 || key == SDLK_QUESTION || (key == SDLK_SLASH && (e.key.keysym.mod & KMOD_SHIFT))) {
        helpOpen_ = !helpOpen_;
        return true;
    }
    if (key == SDLK_ESCAPE) {
        if (helpOpen_)
            helpOpen_ = false;
        else if (instantReplay() && overlay_ == Overlay::None)
            backToLive();
        else if (aim_.charging())
            aim_.cancelCharge();
        else if (overlay_ == Overlay::Replays || overlay_ == Overlay::Lesson)
            overlay_ = Overlay::LevelSelect;
        else if (overlay_ == Overlay::Pause || (overlay_ == Overlay::LevelSelect && shownMatch()))
            overlay_ = Overlay::None;
        else if (overlay_ == Overlay::None)
            overlay_ = Overlay::Pause;
        else
            running_ = false; // Esc on the first level select screen quits
        return true;
    }
    if (viewer_ && overlay_ == Overlay::None) return replayKey(e);
    // Held Backspace keeps rewinding, a second at a time.
    if (key == SDLK_BACKSPACE && session_ && overlay_ == Overlay::None) {
        const std::uint64_t now = session_->match().tick();
        const auto second =
            static_cast<std::uint64_t>(1.0 / session_->match().world().def().tickSeconds);
        aim_.cancelCharge();
        rewindLive(now > second ? now - second : 0);
        return true;
    }
    if (!session_ || overlay_ != Overlay::None || e.key.repeat) return true;
    game::Match& m = session_->match();
    if (humanTurn())
        if (auto commands = pressTurnKey(key, aim_, m)) {
            submit(*commands);
            return true;
        }
    switch (key) {
    case SDLK_z:
        watchLastShot();
        break;
    case SDLK_p:
        settings_.trajectoryPreview = !settings_.trajectoryPreview;
        break;
    case SDLK_h:
        settings_.solutionHint = !settings_.solutionHint;
        break;
    case SDLK_v:
        settings_.fullPreview = !settings_.fullPreview;
        if (settings_.fullPreview) settings_.trajectoryPreview = true;
        break;
    case SDLK_c:
        settings_.cameraFollow = !settings_.cameraFollow;
        if (!settings_.cameraFollow) frameLevel(m); // back to the level's framing
        break;
    case SDLK_F2:
        settings_.physicsPanel = !settings_.physicsPanel;
        break;
    case SDLK_PERIOD:
        time_.paused = true;
        time_.stepRequested = true;
        break;
    case SDLK_k:
        time_.paused = !time_.paused;
        break;
    case SDLK_LEFTBRACKET:
    case SDLK_RIGHTBRACKET: {
        int i = 0;
        while (i + 1 < static_cast<int>(std::size(kSpeeds)) && kSpeeds[i] < time_.timeScale) ++i;
        i += key == SDLK_RIGHTBRACKET ? 1 : -1;
        time_.timeScale = kSpeeds[std::clamp(i, 0, static_cast<int>(std::size(kSpeeds)) - 1)];
        break;
    }
    case SDLK_BACKSLASH:
        time_.timeScale = 1.0f;
        break;
    case SDLK_r:
        restart();
        break;
    case SDLK_l:
        overlay_ = Overlay::LevelSelect;
        break;
    case SDLK_HOME:
        frameLevel(m);
        cameraMoved_ = false;
        break;
    default:
        break;
    }
    return true;
}

bool GameScreen::replayKey(const SDL_Event& e) {
    bool handled = false;
    const ReplayRequests req = viewer_->key(e.key.keysym, e.key.repeat != 0, handled);
    if (req.takeOver) takeOverReplay();
    if (handled || e.key.repeat) return true;
    switch (e.key.keysym.sym) {
    case SDLK_z:
        if (instantReplay()) backToLive();
        break;
    case SDLK_l:
        overlay_ = Overlay::LevelSelect;
        break;
    case SDLK_HOME:
        frameLevel(viewer_->match());
        cameraMoved_ = false;
        break;
    default:
        break;
    }
    return true;
}

void GameScreen::cameraEvent(const SDL_Event& e) {
    if (e.type == SDL_MOUSEWHEEL && e.wheel.y != 0) {
        int mx = 0, my = 0;
        SDL_GetMouseState(&mx, &my);
        const double factor = e.wheel.y > 0 ? 1.15 : 1.0 / 1.15;
        if (following()) { // the followed view zooms about its centre, and keeps following
            rig_.zoomBy(factor);
            camera_.pixelsPerMetre *= factor;
        } else {
            camera_.zoomAt(pointerPixels(mx, my), factor);
            cameraMoved_ = true;
        }
    } else if (e.type == SDL_MOUSEBUTTONDOWN && e.button.button != SDL_BUTTON_LEFT) {
        panning_ = true;
    } else if (e.type == SDL_MOUSEBUTTONUP && e.button.button != SDL_BUTTON_LEFT) {
        panning_ = false;
    } else if (e.type == SDL_MOUSEMOTION && panning_) {
        camera_.panPixels(pointerPixels(e.motion.xrel, e.motion.yrel));
        cameraMoved_ = true;
    }
}

bool GameScreen::handleEvent(const SDL_Event& e) {
    if (e.type == SDL_QUIT) return false;
    if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE) return false;
    const bool uiWants = imgui_.processEvent(e);
    if (editing_) return editorEvent(e);
    const PadAction padAction = pad_.handle(e);
    if (e.type == SDL_KEYDOWN && !imgui_.wantsKeyboard()) return keyDown(e) && running_;
    if (e.type == SDL_KEYUP && session_) submit(releaseTurnKey(e.key.keysym.sym, aim_, session_->match()));
    const bool panelsMouse = (uiWants && imgui_.wantsMouse()) || imgui_.pressOnWindow(e);
    if (viewer_ && !panelsMouse && overlay_ == Overlay::None) cameraEvent(e);
    if (!session_ || viewer_) return running_;
    game::Match& m = session_->match();
    switch (padAction) {
    case PadAction::Fire:
        if (humanTurn()) submit(aim_.fire(m.cannon()));
        break;
    case PadAction::EndTurn:
        if (humanTurn()) submit(AimInput::endTurn());
        break;
    case PadAction::NextProjectile:
        if (auto s = AimInput::selectNext(m.cannon())) submit(*s);
        break;
    case PadAction::Pause:
        overlay_ = overlay_ == Overlay::Pause ? Overlay::None : Overlay::Pause;
        break;
    case PadAction::None:
        break;
    }
    if (panelsMouse) return running_;
    if (overlay_ != Overlay::None) return running_;
    if (sandboxTools_.active(m) && (e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP ||
                                    e.type == SDL_MOUSEMOTION)) {
        const bool left = e.type == SDL_MOUSEMOTION || e.button.button == SDL_BUTTON_LEFT;
        const int x = e.type == SDL_MOUSEMOTION ? e.motion.x : e.button.x;
        const int y = e.type == SDL_MOUSEMOTION ? e.motion.y : e.button.y;
        const phys::Vec2 at = camera_.toWorld(pointerPixels(x, y));
        if (left && e.type == SDL_MOUSEBUTTONDOWN) submit(sandboxTools_.press(at));
        else if (left && e.type == SDL_MOUSEBUTTONUP) submit(sandboxTools_.lift(at));
        else if (e.type == SDL_MOUSEMOTION) submit(sandboxTools_.move(at));
        if (!left || e.type == SDL_MOUSEMOTION) cameraEvent(e); // right drag still pans
        return running_;
    }
    std::vector<game::Command> aimed;
    if (dragToAim(e, aim_, m, humanTurn(), pivotPixels(), pixelsPerPoint(), aimed))
        submit(aimed);
    else
        cameraEvent(e); // wheel zooms, right (or middle) drag pans
    return running_;
}

} // namespace ui
