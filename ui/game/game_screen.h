// The game in a window (issue 5): a level select screen, then a level played through a
// game::Session under a fixed-step clock. Every change the player makes (aim, power,
// projectile, fire, end turn, physics settings) is a Command submitted to the session,
// so the window drives the match exactly as a script or a replay does; wall time only
// feeds the clock and shapes gestures (charging), never the simulation.
//
// Section index
//   GameScreenDef   what to open and how
//   GameScreen      frame(), handleEvent(); level select, playing, overlays
#pragma once

#include "game/level.h"
#include "game/session.h"
#include "physics/clock.h"
#include "ui/game/aim_input.h"
#include "ui/game/game_menus.h"
#include "ui/game/match_view.h"
#include "ui/game/player_settings.h"
#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"
#include "ui/play/physics_panel.h"
#include "ui/play/screen.h"
#include "ui/render/render_target.h"
#include "ui/render/renderer2d.h"
#include "ui/render/screenshot.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

struct _SDL_GameController;

namespace ui {

class SdlWindow;

struct GameScreenDef {
    std::string levelFile;           ///< "" opens the level select screen
    std::string levelsFolder = "levels";
    int msaaSamples = 0;             ///< 0 = auto (4 on a GPU, off on llvmpipe)
    bool panel = true;               ///< the ImGui physics panel
    /// Where results, choices and the ImGui layout persist ("" = nowhere: tests, headless).
    std::string settingsFolder;
    /// Choices when nothing is stored (the command line overrides stored ones).
    std::optional<game::Difficulty> difficulty;
    std::optional<bool> hotseat;
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
    std::string saveScreenshot(const std::string& path) override;
    bool takeScreenshotRequest() override;
    void setMeasuredFrameMs(double ms) override;
    void warmUp(double seconds) override;

    /// The match being played, if any (null on the level select screen).
    const game::Session* session() const { return session_.get(); }

  private:
    void openLevel(const std::string& file);
    void restart();
    void submit(const std::vector<game::Command>& commands);
    void submit(const game::Command& command);
    bool humanTurn() const;
    void simulate(double wallSeconds);
    void pollHeldInput(double wallSeconds);
    void recordResultOnce();
    void drawPlaying();
    void drawPanels();
    void persist();
    phys::Vec2 pivotPixels() const;
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
    std::string settingsFile_, iniFile_;
    std::vector<LevelEntry> levels_;

    game::Level level_;
    std::unique_ptr<game::Session> session_;
    /// The first level, drawn behind the level select screen before any game starts.
    std::unique_ptr<game::Match> backdrop_;
    phys::FixedClock clock_;
    TimeControls time_;
    ViewControls view_;
    MatchView matchView_;
    AimInput aim_;
    Camera camera_;
    bool cameraMoved_ = false;
    bool panning_ = false;
    bool resultRecorded_ = false;
    bool newBest_ = false;

    Overlay overlay_ = Overlay::None;
    bool helpOpen_ = false;
    bool running_ = true;
    bool screenshotRequested_ = false;
    FrameStats stats_;
    int framesMeasured_ = 0;
    _SDL_GameController* pad_ = nullptr;
    bool padFireHeld_ = false;
};

} // namespace ui
