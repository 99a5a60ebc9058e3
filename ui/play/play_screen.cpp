#include "ui/platform/gl_setup.h"
#include "ui/play/play_screen.h"

#include "ui/game/tick_budget.h"
#include "ui/platform/sdl_window.h"
#include "ui/render/design_canvas.h"
#include "ui/render/gl.h"

#include <SDL.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace ui {

namespace {

phys::ClockDef clockFor(const phys::WorldDef& def) {
    phys::ClockDef c;
    c.tickSeconds = def.tickSeconds;
    return c;
}

} // namespace

PlayScreen::PlayScreen(GLContext& context, SdlWindow* window, const PlayScreenDef& def)
    : context_(context), glLoaded_(loadGLOrThrow(context)), imgui_(context, window), def_(def),
      scene_(def.world, def.demo), clock_(clockFor(def.world)),
      camera_(demoCamera(scene_, context.width(), context.height())) {
    if (window) tickBudget_ = kWindowTickBudgetSeconds;
    stats_.context = context.name();
    view_ = def_.view;
    def_.msaaSamples = autoSamples(def_.msaaSamples);
    msaa_.resize(context.width(), context.height(), def_.msaaSamples);
    if (def_.sound) {
        audio_ = std::make_unique<AudioDevice>();
        if (audio_->silent()) std::cerr << "artillery: playing silent (" << audio_->why() << ")\n";
        sound_.setMix(def_.mix);
    }
}

void PlayScreen::hearFrame() {
    if (!audio_ || audio_->silent()) return;
    // Panned across what the camera shows, heard from its middle.
    const Vec2 lo = camera_.visibleMin(), hi = camera_.visibleMax();
    sound_.setView({lo.x, hi.x});
    demoSound_.hear(scene_, sound_, 0.5 * (lo.y + hi.y), clock_.paused());
    audio_->feed(sound_);
}

void PlayScreen::applySettings(const phys::WorldDef& def) {
    if (!validate(def).empty()) return; // the panel's ranges keep it valid; never apply junk
    if (def.tickSeconds != scene_.world.def().tickSeconds) clock_.setTickSeconds(def.tickSeconds);
    scene_.world.setDef(def);
}

void PlayScreen::simulate(double wallSeconds) {
    clock_.setPaused(time_.paused);
    clock_.setTimeScale(time_.timeScale);
    if (time_.stepRequested) {
        clock_.requestSingleStep();
        time_.stepRequested = false;
    }
    double physicsUs = 0.0;
    // In a window, slow motion rather than a freeze when a tick costs more than it
    // simulates (tick_budget.h).
    const int ticks = runTicksWithin(clock_, clock_.advance(wallSeconds), tickBudget_, [&] {
                          // The state before the last tick is what the frame blends from.
                          previous_.capture(scene_.world.particles);
                          scene_.tick();
                          observeTick();
                          physicsUs += scene_.world.profile().totalUs;
                      }).ran;
    stats_.ticksThisFrame = ticks;
    if (ticks > 0) {
        const phys::StepProfile& p = scene_.world.profile();
        stats_.physicsUs = physicsUs / ticks;
        stats_.integrateUs = p.integrateUs;
        stats_.springsUs = p.springsUs;
    }
    stats_.tick = scene_.world.tick();
    stats_.simSeconds = scene_.world.time();
    stats_.particles = scene_.world.particles.count();
    stats_.springs = scene_.world.springs.size();
    stats_.stiffest = phys::stiffestSpring(scene_.world.springs, scene_.world.particles);
}

void PlayScreen::drawScene() {
    DemoViewOptions o;
    o.trails = view_.trails;
    o.labels = view_.labels;
    o.world.minRadius = camera_.metres(3.0);
    o.world.overlays = view_.draw;
    o.world.pixel = camera_.metres(1.0);
    o.world.ghosts = &ghosts_;
    // Paused or single-stepping shows the tick itself, not a blend toward it.
    if (view_.interpolate && !time_.paused && !previous_.x.empty()) {
        o.world.previous = &previous_;
        o.world.alpha = clock_.alpha();
    }
    renderer_.begin(camera_);
    drawDemo(renderer_, scene_, o);
    drawHud();
    renderer_.flush();
}

void PlayScreen::drawHud() {
    // The stats line, over the soil at the bottom left where nothing flies.
    const phys::WorldDef& d = scene_.world.def();
    char line[256];
    std::snprintf(
        line, sizeof line,
        "frame %.1f ms   physics %.1f us/tick   %s %.0f Hz x%d   drag %s   wind %.1f m/s"
        "   t %.2f s%s   next shot %.1f s",
        stats_.frameMs, stats_.physicsUs, phys::info(d.integrator).name, 1.0 / d.tickSeconds,
        d.substeps, d.forces.drag == phys::DragModel::None ? "off" : "on", d.forces.wind.x,
        stats_.simSeconds, time_.paused ? " (paused)" : "", std::max(scene_.nextShotIn(), 0.0));
    // At the bottom left, as large as the panels' text (design_canvas.h).
    const float u = panelScale(camera_.width, camera_.height);
    renderer_.screenLabel({12.0 * u, camera_.height - 30.0 * u}, line, Color::hex(0xf2ead8),
                          0.9f * u);
}

void PlayScreen::frame(double wallSeconds) {
    simulate(wallSeconds);

    const int w = context_.width(), h = context_.height();
    if (w != camera_.width || h != camera_.height) {
        if (cameraMoved_) {
            camera_.width = w, camera_.height = h;
        } else {
            camera_ = demoCamera(scene_, w, h);
        }
        msaa_.resize(w, h, def_.msaaSamples);
    }
    hearFrame();

    imgui_.newFrame(wallSeconds);

    // The world, anti-aliased, then resolved into the context's framebuffer.
    msaa_.bind(context_.framebuffer());
    gl::fn.Viewport(0, 0, w, h);
    gl::fn.ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl::fn.Clear(GL_COLOR_BUFFER_BIT);
    drawScene();
    stats_.vertices = renderer_.stats().vertices;
    msaa_.resolveInto(context_.framebuffer());

    // Panels and labels on top, straight into the final picture.
    if (def_.panel) {
        phys::WorldDef settings = scene_.world.def();
        SceneRequests requests;
        if (physicsPanel(settings, time_, view_, requests, stats_)) applySettings(settings);
        if (requests.fire) scene_.fire();
        if (requests.reset) {
            scene_.reset();
            previous_ = {};
            ghosts_.clear();
        }
        // A click for every button, box and slider pressed, as in the game.
        if (audio_ && !audio_->silent() && ImGui::IsMouseClicked(ImGuiMouseButton_Left) &&
            ImGui::IsAnyItemHovered())
            sound_.click();
    }
    imgui_.drawLabels(renderer_.labels());
    imgui_.render();
}

bool PlayScreen::handleEvent(const SDL_Event& e) {
    if (e.type == SDL_QUIT) return false;
    if (e.type == SDL_WINDOWEVENT && e.window.event == SDL_WINDOWEVENT_CLOSE) return false;
    const bool uiHasMouse =
        (imgui_.processEvent(e) && imgui_.wantsMouse()) || imgui_.pressOnWindow(e);
    if (e.type == SDL_KEYDOWN && !imgui_.wantsKeyboard()) {
        switch (e.key.keysym.sym) {
        case SDLK_ESCAPE:
            return false;
        case SDLK_F12:
            screenshotRequested_ = true;
            break;
        case SDLK_SPACE:
            time_.paused = !time_.paused;
            break;
        case SDLK_PERIOD:
        case SDLK_s:
            time_.paused = true;
            time_.stepRequested = true;
            break;
        case SDLK_f:
            scene_.fire();
            break;
        case SDLK_r:
            scene_.reset();
            previous_ = {};
            ghosts_.clear();
            break;
        case SDLK_v:
            view_.draw.velocities = !view_.draw.velocities;
            break;
        case SDLK_t:
            view_.trails = !view_.trails;
            break;
        case SDLK_1:
            time_.timeScale = 0.1f;
            break;
        case SDLK_2:
            time_.timeScale = 0.25f;
            break;
        case SDLK_3:
            time_.timeScale = 1.0f;
            break;
        case SDLK_HOME:
            camera_ = demoCamera(scene_, context_.width(), context_.height());
            cameraMoved_ = false;
            break;
        default:
            break;
        }
    }
    if (uiHasMouse) return true;
    // Window points to framebuffer pixels (they differ on high-DPI screens).
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    if (e.type == SDL_MOUSEWHEEL && e.wheel.y != 0) {
        int mx = 0, my = 0;
        SDL_GetMouseState(&mx, &my);
        camera_.zoomAt({mx * scale.x, my * scale.y}, e.wheel.y > 0 ? 1.15 : 1.0 / 1.15);
        cameraMoved_ = true;
    } else if (e.type == SDL_MOUSEBUTTONDOWN &&
               (e.button.button == SDL_BUTTON_RIGHT || e.button.button == SDL_BUTTON_MIDDLE ||
                e.button.button == SDL_BUTTON_LEFT)) {
        dragging_ = true;
    } else if (e.type == SDL_MOUSEBUTTONUP) {
        dragging_ = false;
    } else if (e.type == SDL_MOUSEMOTION && dragging_) {
        camera_.panPixels({e.motion.xrel * scale.x, e.motion.yrel * scale.y});
        cameraMoved_ = true;
    }
    return true;
}

Image PlayScreen::capture() const {
    return readFramebuffer(context_.framebuffer(), context_.width(), context_.height());
}

std::string PlayScreen::saveScreenshot(const std::string& path) {
    std::string error = writePng(path, capture());
    stats_.status = error.empty() ? "saved " + path : error;
    return error;
}

bool PlayScreen::takeScreenshotRequest() {
    const bool r = screenshotRequested_;
    screenshotRequested_ = false;
    return r;
}

void PlayScreen::warmUp(double seconds) {
    const int ticks = static_cast<int>(seconds / scene_.world.def().tickSeconds);
    for (int i = 0; i < ticks; ++i) {
        scene_.tick();
        observeTick();
    }
}

void PlayScreen::observeTick() {
    // The ghosts' launch states are kept only while they are shown.
    if (view_.draw.ghosts)
        ghosts_.observe(scene_.world);
    else
        ghosts_.clear();
}

void PlayScreen::setMeasuredFrameMs(double ms) {
    // Smoothed so the number can be read while it changes every frame; the first frame
    // (shader compilation, font upload) is not typical and is replaced by the second.
    stats_.frameMs = framesMeasured_ < 2 ? ms : 0.9 * stats_.frameMs + 0.1 * ms;
    ++framesMeasured_;
}

std::string screenshotFileName() {
    const std::time_t now = std::time(nullptr);
    std::tm local{};
    localtime_r(&now, &local);
    char stamp[32];
    std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
    std::string name = std::string("artillery-") + stamp + ".png";
    for (int i = 2; std::filesystem::exists(name); ++i)
        name = std::string("artillery-") + stamp + "-" + std::to_string(i) + ".png";
    return name;
}

} // namespace ui
