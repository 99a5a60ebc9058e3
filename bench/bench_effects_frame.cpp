// bench_effects_frame: what a blast's effects cost a frame. A 1280x720 headless frame
// (OSMesa, llvmpipe) of the castle level a few ticks after a cannonball burst, framed as
// the camera frames an impact, drawn with the effects (debris, dust, splinters, smoke,
// flash, crater marks, shot feedback) and without them, alternately, N times each; prints
// the medians side by side, their ratio (the budget: at most 1.2), the opening frame of
// the level (home framing, before any shot) for reference, the pieces in the air
// and the load average before and after (the machine may be shared: compare ratios).
// Also the effects' own cost per tick (Effects::observe), which the window pays per tick.
//
//   bench_effects_frame [LEVEL.json] [--frames N] [--after TICKS]
#include "bench/options.h"
#include "game/files/text_file.h"
#include "game/level.h"
#include "game/match.h"
#include "ui/game/match_frame.h"
#include "ui/game/match_view.h"
#include "ui/platform/gl_context.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/gl.h"
#include "ui/render/renderer2d.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace {

std::string loadAverage() {
    std::ifstream f("/proc/loadavg");
    std::string a, b, c;
    f >> a >> b >> c;
    return a + " " + b + " " + c;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct Options {
    std::string file = "levels/05_castle.json";
    int frames = 30, after = 20;
};

/// The options, or nullopt after the usage line.
std::optional<Options> parseOptions(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        bool ok = true;
        if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
            ok = bench_args::countOption("bench_effects_frame", "--frames", argv[++i], o.frames, 1);
        else if (!std::strcmp(argv[i], "--after") && i + 1 < argc)
            ok = bench_args::countOption("bench_effects_frame", "--after", argv[++i], o.after, 0);
        else
            o.file = argv[i];
        if (ok) continue;
        std::fprintf(stderr, "usage: bench_effects_frame [LEVEL.json] [--frames N >= 1] [--after TICKS >= 0]\n");
        return std::nullopt;
    }
    return o;
}

/// The castle's own cannon fires a cannonball low at the castle; it bursts among the
/// blocks (the shot of docs/effects-and-camera.md). The burst event, or null after a line.
const game::GameEvent* fireUntilBurst(game::Match& m, ui::MatchView& view, const std::string& file) {
    for (auto [kind, number] : {std::pair{game::CommandKind::Aim, 20.0},
                                {game::CommandKind::Power, 48.0},
                                {game::CommandKind::Fire, 0.0}}) {
        game::Command c;
        c.kind = kind;
        c.number = number;
        if (const std::string why = m.apply(c); !why.empty()) {
            std::fprintf(stderr, "bench_effects_frame: %s refused the shot: %s\n", file.c_str(), why.c_str());
            return nullptr;
        }
    }
    for (int k = 0; k < 30 * 120; ++k) {
        m.step();
        view.observe(m);
        for (const game::GameEvent& e : m.events())
            if (e.kind == game::EventKind::Burst) return &e;
    }
    std::fprintf(stderr, "bench_effects_frame: the shot on %s never burst (a level without cannonballs?)\n",
                 file.c_str());
    return nullptr;
}

/// Mean microseconds of Effects::observe over `ticks` ticks after the burst.
double observeMicroseconds(game::Match& m, ui::MatchView& view, int ticks) {
    double us = 0.0;
    for (int k = 0; k < ticks; ++k) {
        m.step();
        const auto t0 = std::chrono::steady_clock::now();
        view.observe(m);
        us += std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
    }
    return ticks ? us / ticks : 0.0;
}

std::optional<game::Level> load(const std::string& file) {
    try {
        return game::loadLevel(file);
    } catch (const game::LoadError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return std::nullopt;
    }
}

} // namespace

int main(int argc, char** argv) {
    const std::optional<Options> opt = parseOptions(argc, argv);
    if (!opt) return 2;
    const auto [file, frames, after] = *opt;
    const std::optional<game::Level> loaded = load(file);
    if (!loaded) return 2;
    const game::Level& level = *loaded;
    const int W = 1280, H = 720;
    std::string error;
    auto context = ui::createHeadlessContext(W, H, ui::HeadlessBackend::Auto, error);
    if (!context) {
        std::fprintf(stderr, "bench_effects_frame: no headless GL context: %s\n", error.c_str());
        return 1;
    }
    if (const char* e = ui::gl::loadGL(context->procAddress()); *e) {
        std::fprintf(stderr, "bench_effects_frame: %s\n", e);
        return 1;
    }
    auto imgui = std::make_unique<ui::ImGuiLayer>(*context, nullptr);
    auto renderer = std::make_unique<ui::Renderer2D>();

    game::Match m(level);
    ui::MatchView view;
    const game::GameEvent* burst = fireUntilBurst(m, view, file);
    if (!burst) return 2;
    const phys::Vec2 burstAt = burst->where; // the event list grows as the match steps
    const double observeUs = observeMicroseconds(m, view, after);
    ui::Camera cam = ui::levelCamera(m, W, H);
    cam.pixelsPerMetre *= 2.2; // the rig's impact zoom
    cam.center = burstAt + phys::Vec2{0.0, cam.metres(0.15 * H)};
    // The level as it opens, framed whole: the plain frame of a game before any shot.
    const game::Match opening(level);
    ui::MatchView openingView;
    const ui::Camera home = ui::levelCamera(opening, W, H);
    auto draw = [&](bool effects, bool atOpening = false) {
        ui::MatchViewOptions o;
        o.effects = effects;
        const auto t0 = std::chrono::steady_clock::now();
        imgui->newFrame(1.0 / 60.0);
        if (atOpening)
            ui::drawMatchFrame(*renderer, openingView, opening, home, o);
        else
            ui::drawMatchFrame(*renderer, view, m, cam, o);
        imgui->drawLabels(renderer->labels());
        imgui->render();
        context->present(); // waits until the frame is drawn
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
            .count();
    };
    const std::string loadBefore = loadAverage();
    draw(true), draw(false); // warm the caches and the shader
    std::vector<double> plain, blast, opened;
    for (int i = 0; i < frames; ++i) {
        blast.push_back(draw(true));
        plain.push_back(draw(false));
        opened.push_back(draw(true, true));
    }
    const std::string loadAfter = loadAverage();
    const double p = median(plain), b = median(blast);
    std::printf("%s, %dx%d headless, %d frames each, %d ticks after the burst\n",
                level.name.c_str(), W, H, frames, after);
    std::printf("pieces in the air %zu, smoke puffs %zu, soil specks %zu\n",
                view.effects().pieces().count(), view.effects().smoke().size(),
                view.effects().specks().size());
    std::printf(
        "plain frame median %.2f ms, blast frame median %.2f ms, ratio %.3f (budget 1.20: %s)\n", p,
        b, b / p, b <= 1.2 * p ? "met" : "NOT met");
    std::printf(
        "the level as it opens (home framing, no shot yet) median %.2f ms; blast / that %.3f\n",
        median(opened), b / median(opened));
    std::printf("effects per tick (Effects::observe) mean %.1f us over %d ticks\n", observeUs, after);
    std::printf("load average before %s, after %s\n", loadBefore.c_str(), loadAfter.c_str());
    // Labels and GL objects go before the context.
    renderer.reset();
    imgui.reset();
    return 0;
}
