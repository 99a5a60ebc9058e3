// Section index
//   set-up       GameScreen(), the controllers
//   moving       openLevel, restart, replays, the editor: what is on screen
//   drawing      frame, drawPlaying, drawPanels and what the choices in them do
// The input (keys, mouse, controller) is in game_screen_input.cpp.
#include "ui/platform/gl_setup.h"
#include "ui/game/game_screen.h"

#include "game/editor/level_editor.h"
#include "game/editor/sandbox_to_level.h"
#include "ui/game/cost_readout.h"
#include "ui/game/match_frame.h"
#include "ui/game/random_map.h"
#include "ui/game/settings_commands.h"
#include "ui/game/target_inset.h"
#include "ui/platform/sdl_window.h"
#include "ui/render/design_canvas.h"
#include "ui/render/gl.h"
#include "ui/render/screenshot.h"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

namespace ui {

namespace {

/// Hotseat: the computer's cannon is handed to a second person. The level is data, so
/// this is a copy with the player renamed; the session then never runs the AI for it.
game::Level withHotseat(game::Level level) {
    for (game::Cannon& c : level.cannons)
        if (c.player == "cpu") c.player = "2";
    return level;
}

PlayerFilesDef filesDef(const GameScreenDef& def) {
    return {def.settingsFolder, def.progressFile, def.progressReadOnly};
}

std::optional<double> tickBudget(const GameScreenDef& def, const SdlWindow* window) {
    if (def.tickBudgetSeconds || !window) return def.tickBudgetSeconds;
    return kWindowTickBudgetSeconds;
}

} // namespace

// ---- set-up ---------------------------------------------------------------------------
GameScreen::GameScreen(GLContext& context, SdlWindow* window, const GameScreenDef& def)
    : context_(context), window_(window), def_(def), glLoaded_(loadGLOrThrow(context)),
      imgui_(context, window), files_(filesDef(def)), menus_(def.levelsFolder),
      play_(tickBudget(def, window)), sound_(window != nullptr) {
    stats_.context = context.name();
    stats_.status = files_.warning();
    samples_ = autoSamples(def_.msaaSamples);
    msaa_.resize(context.width(), context.height(), samples_);
    PlayerSettings& settings = files_.settings();
    view_ = openingView(def_.view, settings.draw);
    matchView_.followGhosts(view_.draw.ghosts);
    if (def_.difficulty) settings.difficulty = *def_.difficulty;
    if (def_.hotseat) settings.hotseat = *def_.hotseat;
    if (!def_.panel) settings.physicsPanel = false;
    if (window_ && SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) == 0) pad_.openFirst();
    if (!def_.replayFile.empty()) {
        openReplay(def_.replayFile); // throws with the loader's message
    } else if (def_.edit) {
        openEditor(def_.levelFile.empty() ? game::editor::newLevel()
                                          : game::loadLevel(def_.levelFile)); // throws likewise
    } else if (def_.levelFile.empty()) {
        menus_.showBackdrop();
        if (menus_.backdrop()) frameLevel(*menus_.backdrop());
    } else
        openLevel(def_.levelFile); // throws with the loader's message
}

GameScreen::~GameScreen() {
    files_.save(view_);
}

// ---- moving between what is on screen ---------------------------------------------------
void GameScreen::openLevel(const std::string& file) {
    level_ = game::loadLevel(file);
    editor_.endPlaytest();
    menus_.dropBackdrop();
    replays_.close();
    restart();
    menus_.close();
    // A weapon met for the first time is introduced in a line, while the player has no
    // result on the level that brings it.
    if (!files_.progress().result(level_.file))
        if (const std::string intro = menus_.weaponIntroduction(level_.file); !intro.empty())
            play_.say(intro, 8.0);
}

bool GameScreen::hotseatInUse() const {
    return files_.settings().hotseat && level_.mode == game::Mode::Duel;
}

game::Level GameScreen::levelInPlay() const {
    return hotseatInUse() ? withHotseat(level_) : level_;
}

void GameScreen::restart() {
    if (replays_.instant(play_)) backToLive(); // R restarts the level, not the shot watched
    if (ReplayViewer* viewer = replays_.viewer()) {
        viewer->requestSeek(0); // a replay restarts from its beginning
        return;
    }
    const std::string stem = std::filesystem::path(level_.file).stem().string();
    const std::string record = files_.recordFileFor(stem + "-last.json");
    play_.start(std::make_unique<game::Session>(
        levelInPlay(), liveSessionOptions(files_, level_, record, stats_.status)));
    matchView_.reset();
    measure_.reset();
    camera_.forgetMoves();
    frameLevel(play_.match());
    if (def_.sandbox && !play_.match().sandbox()) {
        game::Command c; // every level opens as a sandbox too: a command, so it replays
        c.kind = game::CommandKind::Sandbox;
        submit(c);
    }
}

const game::Match* GameScreen::shownMatch() const {
    if (const ReplayViewer* viewer = replays_.viewer()) return &viewer->match();
    return play_.active() ? &play_.match() : nullptr;
}

void GameScreen::openReplay(const std::string& file) {
    game::Replay replay = game::loadReplay(file);
    level_ = game::levelForReplay(file, replay);
    // The same level the live game would use, so taking over plays as a new game would.
    replays_.watch(file, levelInPlay(), std::move(replay));
    editor_.endPlaytest();
    play_.stop();
    menus_.dropBackdrop();
    matchView_.reset();
    camera_.forgetMoves();
    frameLevel(replays_.viewer()->match());
    menus_.close();
}

void GameScreen::watchLastShot() {
    replays_.watchLastShot(play_);
}

void GameScreen::backToLive() {
    replays_.backToLive(play_, matchView_);
}

void GameScreen::takeOverReplay() {
    replays_.takeOver(play_, files_, level_, stats_.status);
}

void GameScreen::rewindLive(std::uint64_t tick) {
    if (tick >= play_.match().tick()) return;
    play_.rewindTo(tick);
    matchView_.reset();
    matchView_.observe(play_.match());
}

void GameScreen::openEditor(game::Level level) {
    editor_.open(std::move(level), files_.mapsFolder());
    play_.stop();
    replays_.close();
    menus_.dropBackdrop();
    menus_.close();
    camera_.forgetMoves();
    camera_.stopPanning();
    camera_.camera() = editor_.held()->framing(context_.width(), context_.height());
}

/// As the Random map row does: the level is written into the maps folder and played from
/// there, through the loader, so what is played is what the file says (and a replay of
/// it names a file that holds it).
void GameScreen::playEditedLevel() {
    std::string error;
    const auto file = editor_.writePlaytest(files_.mapsFolder(), error);
    if (file) {
        try {
            openLevel(*file);
            editor_.startPlaytest();
            return;
        } catch (const std::exception& e) {
            error = e.what();
        }
    }
    if (error.empty()) return; // the level does not pass check: the panel says why
    stats_.status = "cannot play it: " + error;
    std::cerr << "artillery: " << stats_.status << "\n";
}

void GameScreen::backToEditor() {
    play_.stop();
    replays_.close();
    editor_.resume();
    menus_.close();
    camera_.forgetMoves();
    camera_.stopPanning();
    camera_.camera() = editor_.held()->framing(context_.width(), context_.height());
    play_.aim() = AimInput();
}

void GameScreen::frameLevel(const game::Match& m) {
    camera_.frameLevel(m, context_.width(), context_.height());
}

bool GameScreen::follows() const { return !editor_.editing() && files_.settings().cameraFollow; }

// ---- drawing --------------------------------------------------------------------------
std::string GameScreen::banner() const {
    if (const ReplayViewer* viewer = replays_.viewer()) return viewer->banner();
    return play_.banner();
}

void GameScreen::frame(double wallSeconds) {
    play_.fadeNotice(wallSeconds);
    advance(wallSeconds);
    fitToWindow();
    if (const game::Match* shown = shownMatch()) camera_.followShot(*shown, follows());
    markAssists();
    imgui_.newFrame(wallSeconds);
    layout_.clear(context_.width(), context_.height());
    // The panels stand where they stood last frame until they are drawn again: what is
    // placed before them (the HUD's boxes, the close-up) keeps clear of them.
    for (const auto& [name, rect] : drawnWindowRects()) layout_.addOverlay("panel." + name, rect);
    msaa_.bind(context_.framebuffer());
    drawWorld();
    stats_.vertices = renderer_.stats().vertices;
    msaa_.resolveInto(context_.framebuffer());
    drawPanels();
    const std::vector<PixelRect> labels = imgui_.drawLabels(renderer_.labels());
    for (std::size_t i = 0; i < labels.size(); ++i)
        if (renderer_.labels()[i].world) layout_.addOverlay("label", labels[i]);
    imgui_.render();
    std::erase_if(layout_.overlays, [](const LayoutOverlay& o) { return o.name.starts_with("panel."); });
    for (const auto& [name, rect] : drawnWindowRects()) layout_.addOverlay("panel." + name, rect);
    hearFrame();
}

std::string GameScreen::layoutJson() const { return ui::layoutJson(layout_); }

/// The frame's ticks: the replay's, or the live match's (the level being made is not
/// simulated: it is drawn at its first tick).
void GameScreen::advance(double wallSeconds) {
    if (editor_.editing()) return;
    if (ReplayViewer* viewer = replays_.viewer()) {
        viewer->advance(wallSeconds, menus_.holdsTheGame(), matchView_, play_.tickBudget());
        if (replays_.instant(play_) && viewer->player().atEnd()) backToLive();
    } else if (play_.active()) {
        const bool keysFree = !imgui_.wantsKeyboard() && window_ && menus_.overlay() == Overlay::None;
        play_.pollHeldInput(wallSeconds, keysFree, pad_);
        play_.simulate(
            wallSeconds, menus_.holdsTheGame(),
            [&] {
                const game::Match& m = play_.match();
                matchView_.observe(m);
                measure_.observe(m);
                statsPanel_.sample(m);
                sound_.hearTick(m, camera_.camera());
            },
            stats_);
        recordResultOnce();
    }
}

/// A window resized: the editor frames its world anew, a match its level (unless the
/// player moved the view).
void GameScreen::fitToWindow() {
    const int w = context_.width(), h = context_.height();
    Camera& camera = camera_.camera();
    if (editor_.editing() && !camera_.moved()) {
        camera = editor_.held()->framing(w, h); // the whole world beside the panel
        msaa_.resize(w, h, samples_);
    } else if (w != camera.width || h != camera.height) {
        if (camera_.moved() || !shownMatch())
            camera.width = w, camera.height = h;
        else
            frameLevel(*shownMatch());
        msaa_.resize(w, h, samples_);
    }
}

void GameScreen::drawWorld() {
    if (editor_.editing()) {
        editor_.held()->drawWorld(renderer_, camera_.camera());
    } else if (shownMatch()) {
        drawPlaying();
    } else if (const game::Match* backdrop = menus_.backdrop()) {
        // The select screen over the first level's landscape.
        MatchViewOptions o;
        o.hud = false;
        o.trajectoryPreview = false;
        drawMatchFrame(renderer_, matchView_, *backdrop, camera_.camera(), o);
    } else {
        gl::fn.Viewport(0, 0, context_.width(), context_.height());
        gl::fn.ClearColor(0.07f, 0.12f, 0.2f, 1.0f);
        gl::fn.Clear(GL_COLOR_BUFFER_BIT);
        renderer_.begin(camera_.camera());
        renderer_.flush();
    }
}

void GameScreen::drawPlaying() {
    const game::Match& m = *shownMatch();
    const PlayerSettings& settings = files_.settings();
    const bool humanTurn = play_.humanTurn();
    MatchViewOptions o;
    o.trails = view_.trails;
    o.overlays = view_.draw;
    for (const game::CannonState& c : m.cannons())
        o.playerNames.push_back(defaultPlayerName(c.def.player));
    if (const ReplayViewer* viewer = replays_.viewer()) {
        // A replay shows what was played: no aim being edited, no preview of one.
        o.trajectoryPreview = false;
        o.solutionHint = false;
        o.endCard = false;
        o.banner = viewer->banner();
    } else {
        o.trajectoryPreview = settings.trajectoryPreview && humanTurn;
        o.fullPreview = settings.fullPreview;
        o.solutionHint = settings.solutionHint && humanTurn;
        if (humanTurn && play_.aim().editing()) o.pending = play_.aim().pending();
        if (humanTurn) o.rubberBand = play_.aim().rubberBand();
        o.charge = play_.aim().chargeFraction();
        o.banner = play_.banner();
        o.notice = play_.notice();
    }
    o.layout = &layout_;
    const Camera shown = camera_.shaken(matchView_.effects(), settings.screenShake);
    drawMatchFrame(renderer_, matchView_, m, shown, o);
    if (!replays_.watching() && play_.active()) { // the rope being drawn, the hand and what it holds
        sandboxTools_.draw(renderer_, m);
        measure_.draw(renderer_);
        statsPanel_.drawWorld(renderer_, m, &layout_);
        renderer_.flush();
    }
    // Clear of what the frame shows; not while the Stats window's charts take the middle
    // of the view.
    const auto inset = statsPanel_.chartsShown() ? std::nullopt : targetInset(m, shown, {}, &layout_);
    if (inset) drawTargetInset(renderer_, matchView_, m, shown, *inset, o);
}

void GameScreen::drawPanels() {
    if (editor_.editing()) {
        drawEditorPanels();
        return;
    }
    MenuChoice choice = menus_.draw(files_.progress(), files_.settings(), files_.replaysFolder(),
                                    sound_.silentWhy(),
                                    editor_.held() ? editor_.held()->editor().level().name : "",
                                    play_.active() ? &play_.match() : nullptr, play_.rewind(),
                                    context_.framebuffer());
    if (replays_.watching() && menus_.overlay() == Overlay::None) replayPanel();
    bool sceneToEditor = false;
    if (play_.active() && !replays_.watching() && menus_.overlay() == Overlay::None)
        matchPanels(choice, sceneToEditor);
    actOn(choice, sceneToEditor);
    // A click for every button, box and slider pressed this frame.
    if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && ImGui::IsAnyItemHovered()) sound_.click();
}

void GameScreen::drawEditorPanels() {
    const EditorRequests r = editor_.held()->panel();
    menus_.drawHelp();
    if (r.play) playEditedLevel();
    if (r.close) {
        editor_.leave(); // kept: the level select offers to come back to it
        menus_.open(Overlay::LevelSelect);
    }
}

void GameScreen::replayPanel() {
    ReplayViewer& viewer = *replays_.viewer();
    const ReplayRequests req = viewer.panel(clearCorner("Replay", ImVec2(panelPx(470), panelPx(150))));
    camera_.keepClearOfPanels(viewer.match(), std::nullopt, context_.width(), context_.height(),
                              follows());
    if (req.takeOver)
        takeOverReplay();
    else if (req.close)
        menus_.showReplays(files_.replaysFolder());
    else if (req.exportVideo)
        viewer.exportVideo(files_.replaysFolder());
    else if (req.backToGame)
        backToLive();
}

/// The panels of a live match: the Match panel, the sandbox's, the Stats window, the
/// physics panel, the playtest's way back and the card at the end.
void GameScreen::matchPanels(MenuChoice& choice, bool& sceneToEditor) {
    game::Match& m = play_.match();
    PlayerSettings& settings = files_.settings();
    const bool humanTurn = play_.humanTurn();
    const MatchPanelRequests req =
        matchControls(m, humanTurn, clearCorner("Controls", ImVec2(panelPx(420), panelPx(44) + 2.0f * ImGui::GetStyle().WindowPadding.y)));
    camera_.keepClearOfTheRight(labPanelsRight());
    camera_.keepClearOfPanels(m, std::nullopt, context_.width(), context_.height(), follows());
    if (req.projectile)
        if (auto c = AimInput::select(m.cannon(), *req.projectile)) submit(*c);
    if (req.fire && humanTurn) submit(play_.aim().fire(m.cannon()));
    if (req.menu) menus_.open(Overlay::Pause);
    // The lab's panels: the sandbox's in a sandbox, the others on their keys.
    if (m.sandbox()) submit(sandboxTools_.panel(m));
    sceneToEditor = sandboxTools_.takeSaveAsLevel();
    if (editor_.playtest()) playtestButton(choice);
    if (req.endTurn && humanTurn) submit(AimInput::endTurn());
    const PendingAim shownAim = this->shownAim();
    statsPanel_.followAim(m, shownAim);
    if (statsShown_)
        if (auto d = statsPanel_.panel(m, shownAim)) submit(settingCommands(m.world().def(), *d));
    if (settings.physicsPanel) physicsPanelOfMatch(m);
    if (costShown_) costReadout(costFigures(m, stats_.frameMs), clearCorner("Cost", costReadoutEstimate()));
    if (m.over() && play_.resultRecorded() && !choice.openLevel && !editor_.playtest() &&
        camera_.still()) {
        // Beside the results card, wherever the HUD put it, and clear of the field: once
        // the camera is home, so it opens in its place rather than hopping as the view glides.
        const auto card = std::find_if(layout_.overlays.begin(), layout_.overlays.end(),
                                       [](const LayoutOverlay& o) { return o.name == "card"; });
        const ImVec2 corner = clearCorner("Next level", ImVec2(panelPx(460), panelPx(60)),
                                          card == layout_.overlays.end() ? nullptr : &card->rect);
        choice = menus_.nextLevelCard(files_.progress(), level_.file, corner);
    }
}

/// The aim on screen: the one being edited, else the cannon's.
PendingAim GameScreen::shownAim() const {
    const game::Match& m = play_.match();
    return play_.aim().editing() ? play_.aim().pending()
                                 : PendingAim{m.cannon().angleDeg, m.cannon().speedMps};
}

/// How much of the width the lab's panels cover along the right edge, where they open
/// (last frame's places): the camera frames the level left of them.
double GameScreen::labPanelsRight() const {
    const double W = context_.width();
    double right = 0.0;
    for (const char* name : {"Physics", "Stats"})
        if (const auto r = openWindowRect(name); r && r->x1 >= W - 40.0 * hudScale(W, context_.height()))
            right = std::max(right, (W - r->x0) / W);
    return right;
}

ImVec2 GameScreen::clearCorner(const char* name, ImVec2 estimate, const PixelRect* nextTo) const {
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    ImVec2 size(estimate.x, estimate.y); // until it has been drawn once
    if (const auto was = openWindowRect(name))
        size = ImVec2(static_cast<float>((was->x1 - was->x0) / scale.x),
                      static_cast<float>((was->y1 - was->y0) / scale.y));
    const double W = context_.width(), H = context_.height(), u = hudScale(W, H);
    const double w = size.x * scale.x, h = size.y * scale.y, m = 12.0 * u;
    const double beside = 336.0 * u, top = kHudTopBand * u;
    std::vector<PixelRect> places;
    if (nextTo) {
        const double x = 0.5 * (nextTo->x0 + nextTo->x1 - w);
        places.push_back({x, nextTo->y1 + m, x + w, nextTo->y1 + m + h});
        places.push_back({x, nextTo->y0 - m - h, x + w, nextTo->y0 - m});
    }
    places.insert(places.end(), {{beside, H - m - h, beside + w, H - m},
                                     {W - m - w, H - m - h, W - m, H - m},
                                     {W - m - w, top, W - m, top + h},
                                     {m, top, m + w, top + h},
                                     {0.5 * (W - w), H - m - h, 0.5 * (W + w), H - m}});
    // When the corners are taken (the lab's panels open, the close-up beside them), the
    // bottom edge and the top band, left to right, before standing over anything.
    for (double x = m; x + w <= W - m; x += 24.0 * u)
        for (const double y : {H - m - h, top}) places.push_back({x, y, x + w, y + h});
    std::vector<PixelRect> avoid = layout_.objectRects();
    for (const LayoutOverlay& o : layout_.overlays)
        if (o.name != std::string("panel.") + name) avoid.push_back(o.rect); // not itself
    const auto place = firstClear(places, avoid, PixelRect{0.0, 0.0, W, H}).value_or(places.front());
    return ImVec2(static_cast<float>(place.x0 / scale.x), static_cast<float>(place.y0 / scale.y));
}

void GameScreen::physicsPanelOfMatch(game::Match& m) {
    const game::LiveSettings before = m.liveSettings();
    game::LiveSettings edited = before;
    stats_.stiffest = phys::stiffestSpring(m.world().springs, m.world().particles);
    stats_.energyTrend = statsPanel_.energyTrend(stats_.energyTrendSeconds);
    SceneRequests scene;
    // Folded at first: the sky is where the shells fly. Its layout persists.
    ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    if (physicsPanel(edited, m.materialsInPlay(), play_.time(), view_, scene, stats_))
        submit(settingCommands(before, edited));
    if (scene.fire && play_.humanTurn()) submit(play_.aim().fire(m.cannon()));
    if (scene.reset) restart();
}

/// Under the wind gauge at the top centre: the way back to the editor.
void GameScreen::playtestButton(MenuChoice& choice) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const auto underGauge = static_cast<float>(76.0 * hudScale(display.x, display.y));
    ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, underGauge), ImGuiCond_Always,
                            ImVec2(0.5f, 0.0f));
    ImGui::Begin("Playtest", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoSavedSettings);
    if (ImGui::Button("Back to the editor (F4)")) choice.continueEditing = true;
    ImGui::End();
}

/// What the player chose in a menu or a card this frame: the moves between menus are the
/// menus' own; what changes the screen (a level, a replay, the editor, quitting) is here.
void GameScreen::actOn(const MenuChoice& choice, bool sceneToEditor) {
    if (menus_.follow(choice, files_.progress(), files_.replaysFolder())) files_.save(view_);
    if (sceneToEditor && play_.active()) openEditor(game::editor::sandboxToLevel(play_.match()));
    auto tryTo = [&](auto&& open) {
        try {
            open();
        } catch (const std::exception& e) {
            stats_.status = e.what();
            std::cerr << "artillery: " << e.what() << "\n";
        }
    };
    if (choice.openLevel) openLevel(*choice.openLevel);
    if (choice.editLevel)
        tryTo([&] {
            openEditor(choice.editLevel->empty() ? game::editor::newLevel()
                                                 : game::loadLevel(*choice.editLevel));
        });
    if (choice.continueEditing && editor_.held()) backToEditor();
    if (choice.randomMap)
        if (const auto file = writeRandomMap(*choice.randomMap, files_.settings().difficulty,
                                             files_.mapsFolder(), menus_.randomMap().status))
            openLevel(*file);
    if (choice.openReplay) tryTo([&] { openReplay(*choice.openReplay); });
    if (choice.rewindTo && play_.active()) rewindLive(*choice.rewindTo);
    if (choice.watchLastShot && replays_.watchLastShot(play_)) menus_.close();
    if (choice.restart && shownMatch()) {
        restart();
        menus_.close();
    }
    if (choice.quit) running_ = false;
    if (choice.networkDuel) networkDuel_ = true, running_ = false;
    if (choice.settingsChanged) files_.save(view_);
}

/// A learning aid in view during a human's turn is a command, so the replay carries it
/// and the match caps the stars (game/match.h, kAssistedMaxStars).
void GameScreen::markAssists() {
    if (!play_.active() || replays_.watching() || !play_.humanTurn()) return;
    const game::Match& m = play_.match();
    if (m.level().mode != game::Mode::Practice) return;
    const PlayerSettings& settings = files_.settings();
    auto assist = [&](int bit, const char* what) {
        if (m.assisted() & bit) return;
        game::Command c;
        c.kind = game::CommandKind::Assist;
        c.text = what;
        submit(c);
    };
    if (settings.trajectoryPreview && settings.fullPreview) assist(game::kAssistPreview, "preview");
    if (settings.solutionHint) assist(game::kAssistHint, "hint");
}

void GameScreen::recordResultOnce() {
    if (!play_.takeFinish()) return;
    if (editor_.playtest()) return; // a level being made earns no stars
    const game::Match& m = play_.match();
    const bool humanWon = m.winner() >= 0 &&
                          m.cannons()[static_cast<std::size_t>(m.winner())].def.player != "cpu";
    play_.setNewBest(files_.recordResult(level_.file, m.score(), m.stars(), humanWon,
                                         m.assisted() != 0, view_));
}

void GameScreen::hearFrame() {
    const ReplayViewer* viewer = replays_.viewer();
    sound_.hearFrame(files_.settings().sound, viewer ? &viewer->match() : nullptr,
                     viewer && viewer->stopped(), play_.active(), play_.clockPaused(),
                     camera_.camera());
}

void GameScreen::warmUp(double seconds) {
    // The camera follows through the warm-up as it would have, watched: it starts at the
    // first tick, and its first frame after takes every tick since at once.
    if (const game::Match* shown = shownMatch()) camera_.followShot(*shown, follows());
    if (ReplayViewer* viewer = replays_.viewer()) viewer->warmUp(seconds, matchView_);
    play_.warmUp(seconds, [&] {
        matchView_.observe(play_.match());
        statsPanel_.sample(play_.match());
    });
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

} // namespace ui
