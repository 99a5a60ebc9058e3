// The game in a window: a level select screen, then a level played through a
// game::Session under a fixed-step clock. Every change the player makes (aim, power,
// projectile, fire, end turn, physics settings) is a Command submitted to the session,
// so the window drives the match exactly as a script or a replay does; wall time only
// feeds the clock and shapes gestures (charging), never the simulation.
//
// Replays: the screen also watches a recorded game (ReplayViewer, from
// `--replay FILE` or the Replays list), drawn on the same path as live play, and turns
// it into a live game at any moment ("take over": a new replay branches from there).
// A live game rewinds the same way (Session::rewindTo): back to any earlier tick, and
// play goes on from there as a branch.
//
// Section index
//   GameScreenDef   what to open and how
//   GameScreen      frame(), handleEvent(); level select, playing, watching, overlays
#pragma once

#include "game/audio/synthesizer.h"
#include "game/effects/camera_rig.h"
#include "game/level.h"
#include "game/progress.h"
#include "game/session.h"
#include "physics/clock.h"
#include "ui/game/aim_input.h"
#include "ui/game/campaign_view.h"
#include "ui/game/editor_screen.h"
#include "ui/game/game_menus.h"
#include "ui/game/match_view.h"
#include "ui/game/pad_input.h"
#include "ui/game/player_files.h"
#include "ui/game/player_settings.h"
#include "ui/game/replay_view.h"
#include "ui/game/sandbox_tools.h"
#include "ui/game/stats_panel.h"
#include "ui/platform/audio_device.h"
#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"
#include "ui/play/physics_panel.h"
#include "ui/play/screen.h"
#include "ui/render/pixel_rect.h"
#include "ui/render/render_target.h"
#include "ui/render/renderer2d.h"
#include "ui/render/screenshot.h"

#include <memory>
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
    const game::Session* session() const { return session_.get(); }
    /// The view of the match on screen now (before a blast's shake).
    const Camera& camera() const { return camera_; }
    /// The refused command the HUD shows now ("spawn: ..."), "" for none.
    std::string notice() const { return noticeSeconds_ > 0.0 ? notice_ : std::string(); }
    /// The replay being watched, if any.
    const ReplayViewer* replayViewer() const { return viewer_.get(); }
    /// The level editor, while it is on screen (null otherwise).
    LevelEditorView* levelEditor() { return editing_ ? editor_.get() : nullptr; }
    /// The match being played is the editor's level (a playtest: the editor waits).
    bool playtest() const { return playtest_; }

  private:
    void openLevel(const std::string& file);
    // The level editor (ui/game/editor_screen.*): open it, play its level, come back.
    void openEditor(game::Level level);
    void playEditedLevel();
    void backToEditor();
    bool editorEvent(const SDL_Event& e);
    void editorPanels();
    /// Where Save As and the playtest write levels: the player's maps folder.
    std::string mapsFolder() const;
    void restart();
    /// Plays `session` from its current tick (a new match, or a replay taken over).
    void playSession(std::unique_ptr<game::Session> session);
    game::SessionOptions liveOptions(const std::string& recordFile);
    bool hotseatInUse() const;
    /// Where the game records replays ("" in check runs and headless: nowhere).
    std::string replaysFolder() const;
    std::string recordFileFor(const std::string& name) const;
    /// The match on screen: the one played or the one watched (null on the menus alone).
    const game::Match* shownMatch() const;
    // Replays and rewinding.
    void openReplay(const std::string& file);
    void showReplays();
    void takeOverReplay();
    void rewindLive(std::uint64_t tick);
    /// The live game's last shot again (Z): its recording so far, watched from half a
    /// second before the shot, while the game waits; at the end (or Z, Esc) play goes on
    /// where it stood. Take over (T) plays on from the moment watched instead, as a branch.
    void watchLastShot();
    void backToLive();
    /// Watching the live game's last shot (the game waits behind it).
    bool instantReplay() const { return viewer_ && viewer_->instant() && session_; }
    bool replayKey(const SDL_Event& e);
    std::string liveBanner(const game::Match& m) const;
    void cameraEvent(const SDL_Event& e);
    /// The level's framing, and the camera rig's home.
    void frameLevel(const game::Match& m);
    /// The panel along the bottom (the Match panel, or the replay viewer's: where it was
    /// drawn open, openWindowRect) covers part of the screen: the follow camera frames
    /// shots above it, and home moves so nothing to aim at stands under it. Called once a
    /// frame while one is drawn.
    void keepClearOfPanels(const game::Match& m, const std::optional<PixelRect>& panel);
    /// The camera follows the shell (the setting is on and the player has not panned).
    bool following() const;
    void followShot(const game::Match& m);
    /// The camera drawn with: the view shaken by blasts, when shaking is on.
    Camera shakenCamera() const;
    void markAssists();
    void submit(const std::vector<game::Command>& commands);
    void submit(const game::Command& command);
    bool humanTurn() const;
    void simulate(double wallSeconds);
    void pollHeldInput(double wallSeconds);
    void recordResultOnce();
    void drawPlaying();
    void drawPanels();
    void persist();
    /// The sound: the synthesizer hears the match on screen (a live one after every
    /// tick, a replay once a frame) and the device plays it; nothing without a device.
    bool hearing() const;
    void hearTick(const game::Match& m);
    void hearFrame();
    phys::Vec2 pivotPixels() const;
    phys::Vec2 pixelsPerPoint() const;
    phys::Vec2 pointerPixels(int x, int y) const;
    bool keyDown(const SDL_Event& e);

    GLContext& context_;
    SdlWindow* window_;
    GameScreenDef def_;
    bool glLoaded_;
    ImGuiLayer imgui_;
    Renderer2D renderer_;
    MultisampleTarget msaa_;
    int samples_ = 1;

    PlayerSettings settings_;
    PlayerFiles files_; ///< where settings_ and progress_ are read and saved
    std::vector<LevelEntry> levels_;
    /// The levels in their chapters, and what the player has earned ("" file: not kept).
    CampaignMenu campaign_;
    game::Progress progress_;
    /// The lesson on screen (Overlay::Lesson) and the level its Play button opens.
    std::size_t lessonChapter_ = 0;
    std::string lessonThenLevel_;

    game::Level level_;
    std::unique_ptr<game::Session> session_;
    std::unique_ptr<ReplayViewer> viewer_;
    std::vector<ReplayEntry> replays_;
    RewindControl rewind_;
    RandomMapForm randomMap_; ///< the level select's Random map row
    LevelEditorForm editorForm_; ///< the level select's Level editor row
    /// The level editor; kept while its level is played or the level select is shown.
    std::unique_ptr<LevelEditorView> editor_;
    bool editing_ = false;  ///< the editor is on screen
    bool playtest_ = false; ///< the match in play is the editor's level
    /// Where the game in play branched from (a replay taken over, a rewind), "" if not.
    std::string branchNote_;
    std::uint64_t branchTick_ = 0;
    /// The first level, drawn behind the level select screen before any game starts.
    std::unique_ptr<game::Match> backdrop_;
    phys::FixedClock clock_;
    std::optional<double> tickBudget_; ///< wall s a frame may spend on ticks (tick_budget.h)
    /// Wall seconds until the slow-motion banner goes (the budget cut a frame's ticks).
    SlowMotion slowMotion_; ///< the budget cut a frame lately
    TimeControls time_;
    ViewControls view_;
    MatchView matchView_;
    AimInput aim_;
    SandboxTools sandboxTools_;
    StatsPanel statsPanel_; ///< Compare, energy and momentum, Charts
    Camera camera_;
    game::CameraRig rig_; ///< follows the shell, frames the impact, returns
    /// How much of the bottom the panels there covered when the level was last framed (a
    /// fraction of the height), and for how many more frames home jumps to a new framing
    /// rather than gliding: ImGui sizes a panel over its first two frames, and a level that
    /// just opened should not be seen moving into place.
    double coveredBottom_ = 0.0;
    int homeJumpFrames_ = 3;
    bool cameraMoved_ = false;
    bool panning_ = false;
    bool resultRecorded_ = false;
    bool newBest_ = false;

    Overlay overlay_ = Overlay::None;
    bool helpOpen_ = false;
    bool running_ = true;
    bool networkDuel_ = false;
    bool screenshotRequested_ = false;
    FrameStats stats_;
    /// What the match refused last (a spawn outside the world, say), shown on the HUD
    /// for noticeSeconds_ more of wall time: else the press seems to do nothing.
    std::string notice_;
    double noticeSeconds_ = 0.0;
    int framesMeasured_ = 0;
    PadInput pad_; ///< a game controller, if one is plugged in
    /// The sound card (window only; silent when there is none) and what it plays: voices
    /// start as the match's events are heard, a frame at a time.
    std::unique_ptr<AudioDevice> audio_;
    game::audio::Synthesizer sound_{game::audio::SynthesizerDef{.live = true}};
};

} // namespace ui
