// The game screen's input: keys by the table (key_bindings.h) in their scopes, the
// replay viewer's keys, the mouse over the field (aim, the sandbox's tools, the camera),
// the controller's buttons and the editor's keys and mouse.
#include "ui/game/game_screen.h"

#include "ui/game/turn_controls.h"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>
#include <iterator>

namespace ui {

namespace {

/// Time scales the [ and ] keys step through.
constexpr float kSpeeds[] = {1.0f / 16, 0.125f, 0.25f, 0.5f, 1.0f, 2.0f, 4.0f};

/// One step along kSpeeds from `now`, up (`by` 1) or down (-1).
float nextSpeed(float now, int by) {
    int i = 0;
    while (i + 1 < static_cast<int>(std::size(kSpeeds)) && kSpeeds[i] < now) ++i;
    return kSpeeds[std::clamp(i + by, 0, static_cast<int>(std::size(kSpeeds)) - 1)];
}

} // namespace

// ---- events ---------------------------------------------------------------------------
void GameScreen::submit(const game::Command& command) {
    if (std::string why = play_.submit(command); !why.empty()) stats_.status = std::move(why);
}

void GameScreen::submit(const std::vector<game::Command>& commands) {
    for (const game::Command& c : commands) submit(c);
}

phys::Vec2 GameScreen::pixelsPerPoint() const {
    // Window points to framebuffer pixels (they differ on high-DPI screens).
    const ImVec2 s = ImGui::GetIO().DisplayFramebufferScale;
    return {s.x, s.y};
}

bool GameScreen::handleEvent(const SDL_Event& e) {
    if (e.type == SDL_QUIT) return false;
    if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE) return false;
    const bool uiWants = imgui_.processEvent(e);
    if (editor_.editing()) return editorEvent(e);
    const PadAction pad = pad_.handle(e);
    if (e.type == SDL_KEYDOWN && !imgui_.wantsKeyboard()) return keyDown(e) && running_;
    if (e.type == SDL_KEYUP && play_.active())
        submit(releaseTurnKey(e.key.keysym.sym, play_.aim(), play_.match()));
    const bool panelsMouse = (uiWants && imgui_.wantsMouse()) || imgui_.pressOnWindow(e);
    if (replays_.watching() && !panelsMouse && menus_.overlay() == Overlay::None)
        camera_.event(e, pixelsPerPoint(), follows());
    if (!play_.active() || replays_.watching()) return running_;
    padAction(pad);
    if (panelsMouse || menus_.overlay() != Overlay::None) return running_;
    return mouseInMatch(e);
}

void GameScreen::padAction(PadAction action) {
    const game::Match& m = play_.match();
    switch (action) {
    case PadAction::Fire:
        if (play_.humanTurn()) submit(play_.aim().fire(m.cannon()));
        break;
    case PadAction::EndTurn:
        if (play_.humanTurn()) submit(AimInput::endTurn());
        break;
    case PadAction::NextProjectile:
        if (auto s = AimInput::selectNext(m.cannon())) submit(*s);
        break;
    case PadAction::Pause:
        menus_.open(menus_.overlay() == Overlay::Pause ? Overlay::None : Overlay::Pause);
        break;
    case PadAction::None:
        break;
    }
}

/// The measuring tools take the left button and the pointer's moves while one is on; the
/// wheel and a right drag still move the camera. True when the event was theirs.
bool GameScreen::measureEvent(const SDL_Event& e, phys::Vec2 scale) {
    const bool button = e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP;
    if (!(button && e.button.button == SDL_BUTTON_LEFT) && e.type != SDL_MOUSEMOTION) return false;
    const int x = e.type == SDL_MOUSEMOTION ? e.motion.x : e.button.x;
    const int y = e.type == SDL_MOUSEMOTION ? e.motion.y : e.button.y;
    const Camera& c = camera_.camera();
    const phys::Vec2 at = c.toWorld({x * scale.x, y * scale.y});
    if (e.type == SDL_MOUSEBUTTONDOWN) measure_.press(at, c.metres(14.0 * scale.x));
    else if (e.type == SDL_MOUSEBUTTONUP) measure_.lift(at);
    else {
        measure_.move(at);
        camera_.event(e, scale, follows()); // a right drag pans on
    }
    return true;
}

/// The mouse over the field of a live match: the sandbox's tools when they are on, else
/// a drag aims; the wheel and a right drag move the camera.
bool GameScreen::mouseInMatch(const SDL_Event& e) {
    const game::Match& m = play_.match();
    const phys::Vec2 scale = pixelsPerPoint();
    if (measure_.on() && measureEvent(e, scale)) return running_;
    if (sandboxTools_.active(m) && (e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP ||
                                    e.type == SDL_MOUSEMOTION)) {
        const bool left = e.type == SDL_MOUSEMOTION || e.button.button == SDL_BUTTON_LEFT;
        const int x = e.type == SDL_MOUSEMOTION ? e.motion.x : e.button.x;
        const int y = e.type == SDL_MOUSEMOTION ? e.motion.y : e.button.y;
        const phys::Vec2 at = camera_.camera().toWorld({x * scale.x, y * scale.y});
        if (left && e.type == SDL_MOUSEBUTTONDOWN) submit(sandboxTools_.press(at));
        else if (left && e.type == SDL_MOUSEBUTTONUP) submit(sandboxTools_.lift(at));
        else if (e.type == SDL_MOUSEMOTION) submit(sandboxTools_.move(at));
        if (!left || e.type == SDL_MOUSEMOTION) camera_.event(e, scale, follows()); // right drag still pans
        return running_;
    }
    const phys::Vec2 pivot = camera_.camera().toPixel(m.cannon().def.position);
    std::vector<game::Command> aimed;
    if (dragToAim(e, play_.aim(), m, play_.humanTurn(), pivot, scale, aimed))
        submit(aimed);
    else
        camera_.event(e, scale, follows()); // wheel zooms, right (or middle) drag pans
    return running_;
}

/// A key pressed on the game screen: the table's keys (key_bindings.h) in their scope,
/// the replay viewer's while one is watched, and the turn's keys before the match's.
bool GameScreen::keyDown(const SDL_Event& e) {
    const SDL_Keycode key = e.key.keysym.sym;
    const std::optional<KeyBinding> bound = gameKey(key, (e.key.keysym.mod & KMOD_SHIFT) != 0);
    const bool noMenu = menus_.overlay() == Overlay::None;
    if (bound && bound->scope == KeyScope::Always) {
        if (bound->action == GameKey::Back) return backKey();
        gameKeyAction(bound->action);
        return true;
    }
    if (bound && bound->scope == KeyScope::Playtest && editor_.playtest() && editor_.held()) {
        gameKeyAction(bound->action);
        return true;
    }
    if (replays_.watching() && noMenu) return replayKey(e);
    // Held Backspace keeps rewinding, a second at a time.
    if (bound && bound->scope == KeyScope::Live && play_.active() && noMenu) {
        gameKeyAction(bound->action);
        return true;
    }
    if (!play_.active() || !noMenu || e.key.repeat) return true;
    if (play_.humanTurn()) {
        std::string message;
        if (auto commands = pressTurnKey(key, play_.aim(), play_.match(), &message)) {
            submit(*commands);
            if (!message.empty()) play_.say(message);
            return true;
        }
    }
    if (bound && bound->scope == KeyScope::Match) gameKeyAction(bound->action);
    return true;
}

/// Esc closes what is open, innermost first: the help, the last shot watched, a charge,
/// a menu over another; in a match with nothing open, the pause menu; on the first level
/// select screen, it quits.
bool GameScreen::backKey() {
    const Overlay overlay = menus_.overlay();
    if (menus_.helpOpen())
        menus_.closeHelp();
    else if (replays_.instant(play_) && overlay == Overlay::None)
        backToLive();
    else if (play_.aim().charging())
        play_.aim().cancelCharge();
    else if (overlay == Overlay::Replays || overlay == Overlay::Lesson)
        menus_.open(Overlay::LevelSelect);
    else if (overlay == Overlay::Pause || (overlay == Overlay::LevelSelect && shownMatch()))
        menus_.close();
    else if (overlay == Overlay::None)
        menus_.open(Overlay::Pause);
    else
        running_ = false;
    return true;
}

void GameScreen::gameKeyAction(GameKey action) {
    PlayerSettings& settings = files_.settings();
    TimeControls& time = play_.time();
    switch (action) {
    case GameKey::Screenshot: screenshotRequested_ = true; break;
    case GameKey::BackToEditor: backToEditor(); break;
    case GameKey::Help: menus_.toggleHelp(); break;
    case GameKey::Back: backKey(); break;
    case GameKey::Rewind: {
        const game::Match& m = play_.match();
        const auto second = static_cast<std::uint64_t>(1.0 / m.world().def().tickSeconds);
        play_.aim().cancelCharge();
        rewindLive(m.tick() > second ? m.tick() - second : 0);
        break;
    }
    case GameKey::WatchLastShot: watchLastShot(); break;
    case GameKey::TogglePreview: settings.trajectoryPreview = !settings.trajectoryPreview; break;
    case GameKey::ToggleHint: settings.solutionHint = !settings.solutionHint; break;
    case GameKey::ToggleFullPreview:
        settings.fullPreview = !settings.fullPreview;
        if (settings.fullPreview) settings.trajectoryPreview = true;
        break;
    case GameKey::ToggleFollow:
        settings.cameraFollow = !settings.cameraFollow;
        if (!settings.cameraFollow) frameLevel(play_.match()); // back to the level's framing
        break;
    case GameKey::TogglePhysicsPanel: settings.physicsPanel = !settings.physicsPanel; break;
    case GameKey::ToggleStats: statsShown_ = !statsShown_; break;
    case GameKey::ToggleCost: costShown_ = !costShown_; break;
    case GameKey::ToggleCompare:
        if (play_.active()) statsPanel_.toggleCompare(play_.match(), shownAim());
        break;
    case GameKey::NextMeasureTool:
        measure_.next();
        // A tool is a mode: the pointer says so (a window only; headless has no cursor).
        if (window_)
            SDL_SetCursor(SDL_CreateSystemCursor(measure_.on() ? SDL_SYSTEM_CURSOR_CROSSHAIR
                                                               : SDL_SYSTEM_CURSOR_ARROW));
        break;
    case GameKey::StepTick: time.paused = time.stepRequested = true; break;
    case GameKey::TogglePause: time.paused = !time.paused; break;
    case GameKey::Slower: time.timeScale = nextSpeed(time.timeScale, -1); break;
    case GameKey::Faster: time.timeScale = nextSpeed(time.timeScale, +1); break;
    case GameKey::NormalSpeed: time.timeScale = 1.0f; break;
    case GameKey::Restart: restart(); break;
    case GameKey::LevelSelect: menus_.open(Overlay::LevelSelect); break;
    case GameKey::Home:
        frameLevel(play_.match());
        camera_.forgetMoves();
        break;
    }
}

bool GameScreen::replayKey(const SDL_Event& e) {
    ReplayViewer& viewer = *replays_.viewer();
    bool handled = false;
    const ReplayRequests req = viewer.key(e.key.keysym, e.key.repeat != 0, handled);
    if (req.takeOver) takeOverReplay();
    if (handled || e.key.repeat) return true;
    switch (e.key.keysym.sym) {
    case SDLK_z:
        if (replays_.instant(play_)) backToLive();
        break;
    case SDLK_l:
        menus_.open(Overlay::LevelSelect);
        break;
    case SDLK_HOME:
        frameLevel(viewer.match());
        camera_.forgetMoves();
        break;
    default:
        break;
    }
    return true;
}

/// Keys and the mouse while the editor is on screen: F12, F1 and Home as everywhere,
/// the rest the editor's.
bool GameScreen::editorEvent(const SDL_Event& e) {
    if (e.type == SDL_KEYDOWN) {
        if (imgui_.wantsKeyboard()) return running_;
        const SDL_Keycode key = e.key.keysym.sym;
        if (key == SDLK_F12) screenshotRequested_ = true;
        if (key == SDLK_F1) menus_.toggleHelp();
        if (key == SDLK_HOME) camera_.forgetMoves(); // framed again next frame
        const bool ctrl = (e.key.keysym.mod & KMOD_CTRL) != 0;
        const bool shift = (e.key.keysym.mod & KMOD_SHIFT) != 0;
        const EditorRequests r = editor_.held()->key(key, ctrl, shift);
        if (r.play) playEditedLevel();
        if (r.close) {
            editor_.leave();
            menus_.open(Overlay::LevelSelect);
        }
        return running_;
    }
    const bool mouse = e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP ||
                       e.type == SDL_MOUSEMOTION || e.type == SDL_MOUSEWHEEL;
    if (mouse) editor_.mouse(e, imgui_, camera_, pixelsPerPoint(), context_.width());
    return running_;
}

} // namespace ui
