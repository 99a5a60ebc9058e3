// The play screen: the demo scene under a fixed-step clock, drawn by the renderer with
// the physics panel on top. The same object runs in the window and headless; only who
// feeds it time and events differs (ui/play/play_verb.cpp).
#pragma once

#include "game/audio/synthesizer.h"
#include "physics/clock.h"
#include "ui/demo/demo_scene.h"
#include "ui/demo/demo_sound.h"
#include "ui/demo/demo_view.h"
#include "ui/platform/audio_device.h"
#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"
#include "ui/play/physics_panel.h"
#include "ui/play/screen.h"
#include "ui/render/render_target.h"
#include "ui/render/renderer2d.h"
#include "ui/render/screenshot.h"
#include "ui/render/world_view.h"

#include <memory>
#include <optional>
#include <string>

union SDL_Event;

namespace ui {

class SdlWindow;

struct PlayScreenDef {
    /// Anti-aliasing samples for the world: 1 = off, 0 = auto (4 on a GPU; off on
    /// software renderers, where llvmpipe's multisampling triples the frame time).
    int msaaSamples = 0;
    bool panel = true; ///< draw the ImGui physics panel
    ViewControls view; ///< what to draw at the start
    phys::WorldDef world = demoWorldDef();
    DemoDef demo;
    /// Heard through the sound card (a window; never headless): the shots, the shell's
    /// whistle and its landings, at the player's volumes.
    bool sound = false;
    game::audio::SoundMix mix;
};

class PlayScreen final : public Screen {
  public:
    /// Loads GL from `context` and sets up ImGui, the renderer and the scene. `window` is
    /// null headless. Throws std::runtime_error when GL 3.3 core is not there.
    PlayScreen(GLContext& context, SdlWindow* window, const PlayScreenDef& def = {});

    /// Advances the clock by `wallSeconds`, runs the ticks it hands out, and draws the
    /// frame into the context's framebuffer (not yet presented).
    void frame(double wallSeconds) override;
    /// Handles one window event (keys, mouse). Returns false when the player quits.
    bool handleEvent(const SDL_Event& event) override;

    /// The picture of the frame just drawn (call after frame(), before present()).
    Image capture() const;
    /// Writes the frame just drawn as PNG; reports the outcome in the stats line.
    /// Returns "" on success, else the error.
    std::string saveScreenshot(const std::string& path) override;
    /// True once when the player asked for a screenshot (F12) since the last call.
    bool takeScreenshotRequest() override;

    void setMeasuredFrameMs(double ms) override;
    /// Simulates `seconds` of the demo in ticks, without drawing.
    void warmUp(double seconds) override;
    DemoScene& scene() { return scene_; }
    Camera& camera() { return camera_; }
    const FrameStats& stats() const { return stats_; }
    const phys::FixedClock& clock() const { return clock_; }

  private:
    void simulate(double wallSeconds);
    void applySettings(const phys::WorldDef& def);
    void drawScene();
    void drawHud();
    /// After each tick: what the overlays keep across ticks (the ghosts' launches).
    void observeTick();
    /// After the frame's ticks: what the scene did, to the sound card.
    void hearFrame();

    GLContext& context_;
    bool glLoaded_;
    ImGuiLayer imgui_;
    Renderer2D renderer_;
    MultisampleTarget msaa_;
    PlayScreenDef def_;
    DemoScene scene_;
    phys::FixedClock clock_;
    std::optional<double> tickBudget_; ///< wall s a frame may spend on ticks (window only)
    Camera camera_;
    bool cameraMoved_ = false; ///< the player zoomed or panned; keep it on resize
    bool dragging_ = false;
    TimeControls time_;
    ViewControls view_;
    FrameStats stats_;
    PositionSnapshot previous_;
    phys::ClosedFormGhosts ghosts_;
    bool screenshotRequested_ = false;
    int framesMeasured_ = 0;
    std::unique_ptr<AudioDevice> audio_; ///< null headless
    game::audio::Synthesizer sound_{game::audio::SynthesizerDef{.live = true}};
    DemoSound demoSound_;
};

/// A screenshot file name that does not exist yet: artillery-YYYYMMDD-HHMMSS.png.
std::string screenshotFileName();

} // namespace ui
