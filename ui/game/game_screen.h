// The game in a window: a level select screen, then a level played through a
// game::Session under a fixed-step clock. Every change the player makes (aim, power,
// projectile, fire, end turn, physics settings) is a Command submitted to the session,
// so the window drives the match exactly as a script or a replay does; wall time only
// feeds the clock and shapes gestures (charging), never the simulation.
//
// The screen is a set of controllers over what is on it, each owning its own state:
//   LivePlay        the match played: session, clock, aim, time controls (live_play.h)
//   ReplayControl   a replay watched, the last shot again, taking over (replay_control.h)
//   MenuFlow        level select, lesson, replays list, pause menu, help (menu_flow.h)
//   EditorFlow      the level editor and its playtest (editor_flow.h)
//   CameraControl   framing, following the shell, zoom and pan (camera_control.h)
//   PlayerFiles     settings, progress, layout, the replays and maps folders (player_files.h)
//   GameSound       the synthesizer and the sound card (game_sound.h)
//   key bindings    what each key does, as a table (key_bindings.h)
// The screen moves between them (open a level, a replay, the editor) and draws a frame.
//
// Section index
//   GameScreenDef   what to open and how
//   GameScreen      frame(), handleEvent(); what the tests look at
#pragma once

#include "game/level.h"
#include "ui/game/camera_control.h"
#include "ui/game/editor_flow.h"
#include "ui/game/game_sound.h"
#include "ui/game/key_bindings.h"
#include "ui/game/live_play.h"
#include "ui/game/match_view.h"
#include "ui/game/measure_tools.h"
#include "ui/game/menu_flow.h"
#include "ui/game/pad_input.h"
#include "ui/game/player_files.h"
#include "ui/game/replay_control.h"
#include "ui/game/screen_layout.h"
#include "ui/game/sandbox_tools.h"
#include "ui/game/stats_panel.h"
#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"
#include "ui/play/physics_panel.h"
#include "ui/play/screen.h"
#include "ui/render/render_target.h"
#include "ui/render/renderer2d.h"

#include <optional>
#include <string>
#include <vector>

namespace ui {

class SdlWindow;

struct GameScreenDef {
    std::string levelFile;           ///< "" opens the level select screen
    std::string replayFile;          ///< a replay to watch (instead of a level)
    std::string levelsFolder = "levels";
    int msaaSamples = 0;             ///< 0 = auto (4 on a GPU, off on llvmpipe)
    bool panel = true;               ///< the ImGui physics panel
    /// Where results, choices and the ImGui layout persist ("" = nowhere: tests, headless).
    std::string settingsFolder;
    /// The campaign progress file ("" = progress.json in settingsFolder, if any).
    std::string progressFile;
    bool progressReadOnly = false; ///< read it, never write it (check runs)
    /// Choices when nothing is stored (the command line overrides stored ones).
    std::optional<game::Difficulty> difficulty;
    std::optional<bool> hotseat;
    /// Open the level as a sandbox (a `sandbox` command at its first tick).
    bool sandbox = false;
    /// Open the level editor on levelFile ("" = a new level) instead of playing.
    bool edit = false;
    /// What to draw at the start: trails and the debug view's overlays (play flags).
    ViewControls view;
    /// Wall time a frame may spend running ticks (tick_budget.h); none: the window's
    /// kWindowTickBudgetSeconds, and no limit headless.
    std::optional<double> tickBudgetSeconds;
};

class GameScreen final : public Screen {
  public:
    /// `window` is null headless. Throws std::runtime_error when GL 3.3 core is missing
    /// or the level cannot be loaded (with the loader's message).
    GameScreen(GLContext& context, SdlWindow* window, const GameScreenDef& def);
    ~GameScreen() override;

    void frame(double wallSeconds) override;
    bool handleEvent(const SDL_Event& event) override;
    bool running() const override { return running_; }
    /// The player chose Network duel: the window closes and the network duel screen opens.
    bool networkDuelRequested() const { return networkDuel_; }
    std::string saveScreenshot(const std::string& path) override;
    bool takeScreenshotRequest() override;
    void setMeasuredFrameMs(double ms) override;
    void warmUp(double seconds) override;

    /// The line at the top of the picture now ("PAUSED ...", "SLOW MOTION ...", a
    /// replay's), "" for none.
    std::string banner() const;
    /// The match being played, if any (null on the level select screen or in a replay).
    const game::Session* session() const { return play_.sessionOrNull(); }
    /// The view of the match on screen now (before a blast's shake).
    const Camera& camera() const { return camera_.camera(); }
    /// The refused command the HUD shows now ("spawn: ..."), "" for none.
    std::string notice() const { return play_.notice(); }
    /// The replay being watched, if any.
    const ReplayViewer* replayViewer() const { return replays_.viewer(); }
    /// The level editor, while it is on screen (null otherwise).
    LevelEditorView* levelEditor() { return editor_.onScreen(); }
    /// The match being played is the editor's level (a playtest: the editor waits).
    bool playtest() const { return editor_.playtest(); }
    /// What the last frame drawn showed: its overlays and the objects the player must see.
    const ScreenLayout& layout() const { return layout_; }
    std::string layoutJson() const override;

  private:
    // Moving between what is on screen.
    void openLevel(const std::string& file);
    void restart();
    void openReplay(const std::string& file);
    void watchLastShot();
    void backToLive();
    void takeOverReplay();
    void rewindLive(std::uint64_t tick);
    void openEditor(game::Level level);
    void playEditedLevel();
    void backToEditor();
    /// The match on screen: the one played or the one watched (null on the menus alone).
    const game::Match* shownMatch() const;
    bool hotseatInUse() const;
    /// The level as played: with hotseat, the computer's cannon handed to a second person.
    game::Level levelInPlay() const;
    void frameLevel(const game::Match& m);
    bool follows() const;

    // A frame.
    void advance(double wallSeconds);
    void fitToWindow();
    void drawWorld();
    void drawPlaying();
    void drawPanels();
    void drawEditorPanels();
    void replayPanel();
    void matchPanels(MenuChoice& choice, bool& sceneToEditor);
    /// Where the ImGui window `name` goes (its top-left corner, window points): the first
    /// of the usual places (beside the aim readout at the bottom, the bottom right, the
    /// top right and the top left under the HUD's band, the bottom middle, then along the
    /// bottom edge and the top band) where it covers nothing the frame shows so far; its
    /// size is last frame's, or `estimate` (points). With `nextTo` (pixels), under it and
    /// over it, centred, come first.
    ImVec2 clearCorner(const char* name, ImVec2 estimate, const PixelRect* nextTo = nullptr) const;
    double labPanelsRight() const;
    PendingAim shownAim() const;
    void physicsPanelOfMatch(game::Match& m);
    void playtestButton(MenuChoice& choice);
    void actOn(const MenuChoice& choice, bool sceneToEditor);
    void markAssists();
    void recordResultOnce();
    void hearFrame();

    // Input.
    void submit(const game::Command& command);
    void submit(const std::vector<game::Command>& commands);
    bool keyDown(const SDL_Event& e);
    bool backKey();
    void gameKeyAction(GameKey action);
    bool replayKey(const SDL_Event& e);
    bool editorEvent(const SDL_Event& e);
    void padAction(PadAction action);
    bool mouseInMatch(const SDL_Event& e);
    bool measureEvent(const SDL_Event& e, phys::Vec2 scale);
    phys::Vec2 pixelsPerPoint() const;

    GLContext& context_;
    SdlWindow* window_;
    GameScreenDef def_;
    bool glLoaded_;
    ImGuiLayer imgui_;
    Renderer2D renderer_;
    MultisampleTarget msaa_;
    int samples_ = 1;

    PlayerFiles files_;
    MenuFlow menus_;
    game::Level level_; ///< the level played or watched
    LivePlay play_;
    ReplayControl replays_;
    EditorFlow editor_;
    CameraControl camera_;
    ViewControls view_;
    MatchView matchView_;
    SandboxTools sandboxTools_;
    StatsPanel statsPanel_; ///< Compare, energy and momentum, Charts
    PadInput pad_;          ///< a game controller, if one is plugged in
    GameSound sound_;
    FrameStats stats_;
    ScreenLayout layout_; ///< the frame's overlays and objects, gathered as it is drawn
    bool statsShown_ = false; ///< the Stats window (a lab panel: shown on its key)
    bool costShown_ = false;  ///< the cost readout (F3)
    MeasureTools measure_;    ///< probe, tape, stopwatch (M)
    int framesMeasured_ = 0;
    bool running_ = true;
    bool networkDuel_ = false;
    bool screenshotRequested_ = false;
};

} // namespace ui
