#include "ui/play/play_verb.h"

#include "ui/net/net_screen.h"

#include "game/files/data_folder.h"
#include "game/files/text_file.h"
#include "game/replay.h"
#include "ui/game/game_screen.h"
#include "ui/game/player_settings.h"
#include "ui/platform/sdl_window.h"
#include "ui/play/play_screen.h"

#include <SDL.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>

namespace ui {

namespace {

using game::cli::Args;
using Clock = std::chrono::steady_clock;

constexpr const char* kPlayUsage =
    R"(usage: artillery play [LEVEL | --replay FILE] [--frames N] [--screenshot FILE.png]
                      [--size WxH] [--headless] [--context auto|osmesa|egl]
                      [--warmup SECONDS] [--msaa N] [--no-panel]
                      [--difficulty easy|normal|hard] [--hotseat] [--sandbox] [--demo]
                      [--edit] [--progress FILE]
                      [--velocities] [--forces] [--ghosts] [--contacts] [--cells]
                      [--sleeping] [--models] [--json]

Plays LEVEL in a window; without LEVEL the level select screen opens (the campaign:
the shipped levels in chapters with their lessons, your stars, and what opens next;
any level opens here as LEVEL, locked or not). The shipped levels are found beside the
executable (../share/artillery/levels when installed; the source tree's in a build),
from any working folder. Aim by dragging from the cannon
(direction = angle, length = power) or with the arrow keys, hold Space to charge and
release to fire (a tap fires at the power set), 1-8 pick the projectile. Every change
you make, physics settings included, is a command the session records, so each game
is a replay. Progress, choices and the panel layout are kept in
$XDG_CONFIG_HOME/artillery (~/.config/artillery), the replays in its replays/ folder
("Replays" on the level select screen lists them).

With --replay the window watches a recorded game instead: play / pause, one tick, any
speed from x1/8 to x16, a scrub bar over the whole game (going back re-simulates it
from the start), the previous or next shot, and "Take over" (T), which hands you the
match at that moment to play on; the branch is recorded as a new replay. The viewer
compares the replay's checkpoints as it plays and says so if the game diverges. In a
game, Backspace (or the Match panel's rewind slider) goes back in time the same way
and play goes on from there, and Z watches the last shot again in the viewer, then
goes back to the game where it stood.

options:
  LEVEL                 a level file (levels/*.json)
  --replay FILE         watch a replay (artillery run --record, or one the game
                        recorded); its level is found as `artillery replay verify`
                        finds it (a bad file or a changed level: exit 2)
  --frames N            run N frames, then exit (default: until the window closes);
                        such check runs leave no settings or replays behind
  --screenshot FILE     save the last frame as PNG (headless, the last frame is always
                        saved: by default to $TMPDIR/artillery-demo.png)
  --size WxH            window or picture size in pixels (default 1280x720)
  --headless            draw offscreen, no window (also used when there is no display)
  --context NAME        headless GL: auto (OSMesa, else EGL), osmesa or egl
  --warmup SECONDS      simulate this long before the first frame (default 0)
  --msaa N              anti-aliasing samples, 0..16 (default 0 = auto: 4 on a GPU,
                        off on software renderers such as llvmpipe, where it is slow)
  --no-panel            hide the ImGui physics panel
  --difficulty NAME     the computer's aim in duels: easy, normal (default) or hard
  --hotseat             a duel's computer cannon is played by a second person
  --sandbox             open LEVEL as a sandbox: no shot budget, no score, and the
                        Sandbox panel's tools (spawn blocks, balls, ropes, springs,
                        cloth, blobs; grab and drag) on the left mouse button
  --edit                open the level editor on LEVEL (a new level without one):
                        terrain points, cannons, targets, blocks, ropes, blobs, the
                        physics and the wind; checked live as `check` does; saved
                        into your maps folder; F5 plays it, F4 comes back
  --demo                the physics demo scene instead of a level (a cannon with a
                        drag-free twin and a swinging spring chain; heard in a
                        window: reports, whistles, landings); with it:
                        --integrator NAME, --planet NAME | --gravity G, --wind VX,
                        --no-drag
  --json                print the run's figures as JSON

draw (the physics panel's "draw" toggles, on from the start; levels and --demo):
  --velocities          velocity arrows (yellow, 0.1 m per m/s)
  --forces              net force of gravity, drag, wind, springs and buoyancy
                        (magenta), in weights: 30 px of arrow = m g
  --ghosts              closed-form ghost of every integrated flight: where the
                        exact parabola puts it, the parabola, and the integrator's
                        error (orange line, with its length in metres)
  --contacts            the last tick's contact points and normals (red)
  --cells               broad-phase grid cells that hold particles (green)
  --sleeping            sleeping particles and bodies dimmed, marked with a z
  --models              a ring per particle, an outline per body, coloured by the
                        model that moves it: closed form green, integrated orange,
                        asleep blue, fixed grey, Box2D pink (asleep: dark pink)

keys:  mouse drag aim   arrows angle/power   hold Space charge, release fire
       Space tap or Enter/F fire at the power set   1-8 projectile   E end turn
       P preview   H hint   Esc pause menu   F1 or ? help   F2 physics panel
       F3 the cost (frame, physics time, what each model moves)   . one tick
       M measuring tools: probe, tape, stopwatch, off (the mouse measures)
       X compare every integrator on the aim on screen
       K pause/resume   Backspace (hold) rewind 1 s, play on as a branch
       Z the last shot again (Z or Esc: back to the game)
       [ ] slower/faster   R restart   L levels   F12 screenshot
replay: Space or K play/pause   . one tick   , one tick back   [ ] speed x1/8..x16
       \ x1   left/right 1 s back/forward (Shift 5 s)   PgUp/PgDn previous/next shot
       R from the start   T take over (play on from here, recording a branch)
editor: 1-7 tool (select, terrain, cannon, target, block, rope, blob)   left click
       places, drag moves   Del deletes   G grid snap   Ctrl+Z undo   Ctrl+Y redo
       Ctrl+S save   F5 play (F4 back to the editor)   Esc deselect, then levels
mouse: wheel zooms at the pointer, right drag pans, Home re-frames
controller: left stick aims, triggers set power, A fires, B ends the turn

Headless, frames advance 1/60 s each, so a run gives the same picture every time.
Exit codes: 0 ok, 2 bad input (a --screenshot that cannot be written included: refused
before anything is drawn), 3 the frame could not be drawn or saved, or the game failed.
)";

struct PlayOptions {
    int width = 1280;
    int height = 720;
    std::optional<long long> frames;
    std::string screenshot;
    bool headless = false;
    HeadlessBackend backend = HeadlessBackend::Auto;
    double warmupSeconds = 0.0;
    int msaa = 0;
    bool panel = true;
    bool json = false;
    ViewControls view; ///< what to draw from the start (the draw flags)
    phys::WorldDef world = demoWorldDef();
    std::string level;  ///< "" = level select (window) or the demo (headless)
    std::string replay; ///< a replay to watch instead
    bool demo = false;
    std::optional<game::Difficulty> difficulty;
    std::optional<bool> hotseat;
    bool sandbox = false;
    bool edit = false;    ///< the level editor on `level` ("" = a new level)
    std::string progress; ///< a progress file to use instead of the settings folder's
};

struct RunReport {
    long long frames = 0;
    double firstFrameMs = 0.0; ///< includes shader compilation and font upload
    double meanFrameMs = 0.0;
    double minFrameMs = 0.0;
    double maxFrameMs = 0.0;
    std::string context;
    std::string screenshot; ///< absolute path, "" when none
    bool networkDuel = false; ///< the player chose Network duel in the menu
    std::string layout;       ///< the last frame's layout as JSON, "" for none
};

void parseSize(const Args& args, PlayOptions& o) {
    const auto text = args.text("size");
    if (!text) return;
    int w = 0, h = 0;
    char x = 0, extra = 0;
    std::istringstream in(*text);
    if (!(in >> w >> x >> h) || (x != 'x' && x != 'X') || (in >> extra) || w < 64 || h < 64 ||
        w > 8192 || h > 8192)
        args.fail("--size expects WxH with each side in 64..8192 pixels, got '" + *text + "'");
    o.width = w, o.height = h;
}

PlayOptions parseOptions(const Args& args) {
    PlayOptions o;
    parseSize(args, o);
    if (args.has("frames"))
        o.frames = args.integer("frames", 1, 1, std::numeric_limits<int>::max());
    o.screenshot = args.text("screenshot", "");
    if (!o.screenshot.empty() && std::filesystem::path(o.screenshot).extension() != ".png")
        args.fail("--screenshot expects a file name ending in .png, got '" + o.screenshot + "'");
    if (!o.screenshot.empty()) game::cli::requireWritableFile(args, "screenshot", o.screenshot);
    o.headless = args.flag("headless");
    const std::string context = args.text("context", "auto");
    if (context == "auto")
        o.backend = HeadlessBackend::Auto;
    else if (context == "osmesa")
        o.backend = HeadlessBackend::OSMesa;
    else if (context == "egl")
        o.backend = HeadlessBackend::EGL;
    else
        args.fail("--context expects one of auto, osmesa, egl, got '" + context + "'");
    o.warmupSeconds = args.number("warmup", 0.0, 0.0, 3600.0, "s");
    o.msaa = static_cast<int>(args.integer("msaa", 0, 0, 16));
    o.panel = !args.flag("no-panel");
    DebugOverlays& draw = o.view.draw;
    draw.velocities = args.flag("velocities");
    draw.forces = args.flag("forces");
    draw.ghosts = args.flag("ghosts");
    draw.contacts = args.flag("contacts");
    draw.cells = args.flag("cells");
    draw.sleeping = args.flag("sleeping");
    draw.models = args.flag("models");
    o.world.integrator = game::cli::integratorOption(args, o.world.integrator);
    o.world.forces.gravity = {0.0, -game::cli::gravityOption(args)};
    o.world.forces.wind = {args.number("wind", 0.0, -100.0, 100.0, "m/s"), 0.0};
    if (args.flag("no-drag")) o.world.forces.drag = phys::DragModel::None;
    o.json = args.flag("json");
    args.text("<positional>"); // LEVEL may be given
    const auto& pos = args.positionals();
    if (pos.size() > 1) args.fail("expects at most one LEVEL, got " + std::to_string(pos.size()));
    if (!pos.empty() && !std::filesystem::exists(pos[0]))
        args.fail("level file '" + pos[0] + "' does not exist");
    if (!pos.empty()) o.level = pos[0];
    o.demo = args.flag("demo");
    o.replay = args.text("replay", "");
    if (!o.replay.empty()) {
        if (!o.level.empty()) args.fail("give a LEVEL or --replay FILE, not both");
        if (o.demo) args.fail("--demo and --replay cannot be combined");
        // Checked here so a bad file is bad input (exit 2) with the loader's one message.
        try {
            const game::Replay r = game::loadReplay(o.replay);
            game::levelForReplay(o.replay, r);
        } catch (const game::LoadError& e) {
            throw game::cli::UsageError("artillery play: " + std::string(e.what()));
        }
    }
    if (args.has("difficulty")) {
        const std::string d = args.text("difficulty", "normal");
        o.difficulty = game::difficultyFromName(d);
        if (!o.difficulty) args.fail("--difficulty expects easy, normal or hard, got '" + d + "'");
    }
    if (args.flag("hotseat")) o.hotseat = true;
    o.sandbox = args.flag("sandbox");
    if (o.sandbox && (o.demo || !o.replay.empty()))
        args.fail("--sandbox opens a level: it cannot go with --demo or --replay");
    o.edit = args.flag("edit");
    if (o.edit && (o.demo || !o.replay.empty() || o.sandbox))
        args.fail("--edit opens the level editor: it cannot go with --demo, --replay or --sandbox");
    o.progress = args.text("progress", "");
    if (!o.progress.empty() && (o.demo || !o.replay.empty()))
        args.fail("--progress is for the levels: it cannot go with --demo or --replay");
    args.rejectUnknown();
    return o;
}

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

PlayScreenDef screenDef(const PlayOptions& o, const SdlWindow* window) {
    PlayScreenDef d;
    d.sound = window != nullptr;
    d.mix = playerSoundMix(o.frames.has_value());
    d.msaaSamples = o.msaa;
    d.panel = o.panel;
    d.view = o.view;
    d.world = o.world;
    return d;
}

/// The game for a level (or the level select screen in a window); the physics demo with
/// --demo, or headless without a level.
std::unique_ptr<Screen> makeScreen(GLContext& context, SdlWindow* window, const PlayOptions& o) {
    const bool demo = o.demo || (o.level.empty() && o.replay.empty() && o.progress.empty() &&
                                 !o.edit && !window);
    if (demo) return std::make_unique<PlayScreen>(context, window, screenDef(o, window));
    GameScreenDef d;
    d.levelFile = o.level;
    d.replayFile = o.replay;
    d.levelsFolder = game::levelsFolder();
    d.msaaSamples = o.msaa;
    d.panel = o.panel;
    d.difficulty = o.difficulty;
    d.hotseat = o.hotseat;
    d.sandbox = o.sandbox;
    d.edit = o.edit;
    d.view = o.view;
    // A person playing keeps results and layout; check runs (--frames) and headless
    // pictures leave nothing behind.
    if (window && !o.frames) d.settingsFolder = configFolder();
    d.progressFile = o.progress;
    d.progressReadOnly = o.frames.has_value();
    return std::make_unique<GameScreen>(context, window, d);
}

/// The first frame compiles shaders and uploads the font; it is reported apart, and the
/// mean, min and max are over the frames after it (all frames when there is only one).
void accumulate(RunReport& r, double ms) {
    if (r.frames == 0) r.firstFrameMs = ms;
    if (r.frames == 1) r.meanFrameMs = r.minFrameMs = r.maxFrameMs = 0.0;
    const long long n = r.frames == 0 ? 0 : r.frames - 1; // frames counted in the mean so far
    ++r.frames;
    r.minFrameMs = n == 0 ? ms : std::min(r.minFrameMs, ms);
    r.maxFrameMs = std::max(r.maxFrameMs, ms);
    r.meanFrameMs += (ms - r.meanFrameMs) / static_cast<double>(n + 1);
}

std::string absolute(const std::string& path) {
    std::error_code ec;
    auto p = std::filesystem::absolute(path, ec);
    return ec ? path : p.lexically_normal().string();
}

/// Saves the last frame if asked; returns false (and says why) when it cannot.
bool saveIfAsked(Screen& screen, const PlayOptions& o, RunReport& report) {
    if (o.screenshot.empty()) return true;
    const std::string error = screen.saveScreenshot(o.screenshot);
    if (!error.empty()) {
        std::cerr << "artillery play: " << error << "\n";
        return false;
    }
    report.screenshot = absolute(o.screenshot);
    return true;
}

int runHeadless(const PlayOptions& o, RunReport& report) {
    std::string error;
    auto context = createHeadlessContext(o.width, o.height, o.backend, error);
    if (!context) {
        std::cerr << "artillery play: no headless GL context: " << error << "\n";
        return game::cli::kWorkFailed;
    }
    report.context = context->name();
    const auto screenPtr = makeScreen(*context, nullptr, o);
    Screen& screen = *screenPtr;
    screen.warmUp(o.warmupSeconds);
    const long long frames = o.frames.value_or(1);
    for (long long f = 0; f < frames; ++f) {
        const auto t0 = Clock::now();
        screen.frame(1.0 / 60.0);
        context->present(); // waits for the frame: the time includes the GPU's work
        const double ms = msSince(t0);
        screen.setMeasuredFrameMs(ms);
        accumulate(report, ms);
    }
    report.layout = screen.layoutJson();
    return saveIfAsked(screen, o, report) ? game::cli::kOk : game::cli::kWorkFailed;
}

/// Returns -1 when no window could be opened (the caller falls back to headless).
int runWindow(const PlayOptions& o, RunReport& report) {
    std::string error;
    auto window = SdlWindow::open("artillery", o.width, o.height, error);
    if (!window) {
        std::cerr << "artillery play: " << error << "; drawing headless instead\n";
        return -1;
    }
    report.context = window->name();
    const auto screenPtr = makeScreen(*window, window.get(), o);
    Screen& screen = *screenPtr;
    screen.warmUp(o.warmupSeconds);
    auto last = Clock::now();
    bool running = true;
    for (long long f = 0; running && (!o.frames || f < *o.frames); ++f) {
        SDL_Event e;
        while (SDL_PollEvent(&e))
            if (!window->toggleFullScreenOn(e)) running = screen.handleEvent(e) && running;
        running = running && screen.running();
        const auto now = Clock::now();
        const double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        screen.frame(dt);
        const bool lastFrame = !running || (o.frames && f + 1 == *o.frames);
        if (screen.takeScreenshotRequest()) {
            const std::string name = screenshotFileName();
            if (screen.saveScreenshot(name).empty())
                std::cout << "screenshot: " << absolute(name) << std::endl;
        }
        if (lastFrame) report.layout = screen.layoutJson();
        if (lastFrame && !saveIfAsked(screen, o, report)) return game::cli::kWorkFailed;
        window->present();
        const double ms = msSince(now);
        screen.setMeasuredFrameMs(ms);
        accumulate(report, ms);
    }
    if (const auto* game = dynamic_cast<const GameScreen*>(&screen))
        report.networkDuel = game->networkDuelRequested();
    return game::cli::kOk;
}

void printReport(std::ostream& out, const RunReport& r, const PlayOptions& o, bool json) {
    if (json) {
        out << "{\"frames\":" << r.frames << ",\"context\":\"" << r.context
            << "\",\"width\":" << o.width << ",\"height\":" << o.height
            << ",\"mean_frame_ms\":" << r.meanFrameMs << ",\"min_frame_ms\":" << r.minFrameMs
            << ",\"max_frame_ms\":" << r.maxFrameMs << ",\"first_frame_ms\":" << r.firstFrameMs
            << ",\"screenshot\":";
        if (r.screenshot.empty())
            out << "null";
        else
            out << "\"" << r.screenshot << "\"";
        if (!r.layout.empty()) out << ",\"layout\":" << r.layout;
        out << "}\n";
        return;
    }
    char line[200];
    std::snprintf(line, sizeof line,
                  "%lld frames, %s %dx%d: %.2f ms/frame (min %.2f, max %.2f; first frame %.1f ms)",
                  r.frames, r.context.c_str(), o.width, o.height, r.meanFrameMs, r.minFrameMs,
                  r.maxFrameMs, r.firstFrameMs);
    out << line << "\n";
    if (!r.screenshot.empty()) out << "screenshot: " << r.screenshot << "\n";
}

/// Without a window the only way to see anything is a picture: unless told otherwise,
/// 2 s into the scene (a shell pair in the air, the chain swinging), a few frames so
/// the clock's interpolation runs as in a window, saved to the temp directory.
PlayOptions headlessDemo(PlayOptions o) {
    o.headless = true;
    if (!o.frames) {
        o.frames = 5;
        if (o.warmupSeconds == 0.0 && o.level.empty()) o.warmupSeconds = 2.0;
    }
    if (o.screenshot.empty()) {
        const std::string shown = o.replay.empty() ? o.level : o.replay;
        const std::string name =
            shown.empty() || o.demo
                ? std::string("artillery-demo.png")
                : "artillery-" + std::filesystem::path(shown).stem().string() + ".png";
        o.screenshot = (std::filesystem::temp_directory_path() / name).string();
    }
    return o;
}

int play(PlayOptions o, std::ostream& out) {
    RunReport report;
    int code = -1;
    try {
        if (!o.headless && displayAvailable()) code = runWindow(o, report);
        // Network duel chosen in the menu: its own window (ui/net), the game's size; when
        // it closes, back to the level select.
        while (report.networkDuel && code == game::cli::kOk) {
            net::NetWindowOptions duel;
            duel.width = o.width, duel.height = o.height;
            duel.duel.levelsDir = game::levelsFolder(); // the game's: its maps, by name
            duel.duel.levelFile = (std::filesystem::path(duel.duel.levelsDir) / "10_duel.json").string();
            net::runNetWindow(duel, out);
            report = {};
            o.level.clear(), o.replay.clear(), o.demo = o.edit = false;
            code = runWindow(o, report);
        }
        if (code < 0) {
            if (!o.headless && !displayAvailable())
                std::cerr << "artillery play: no display (DISPLAY is not set); drawing headless\n";
            o = headlessDemo(o);
            code = runHeadless(o, report);
        }
    } catch (const game::LoadError& e) { // a level or replay the game was given
        std::cerr << "artillery play: " << e.what() << "\n";
        return game::cli::kBadInput;
    } catch (const std::exception& e) {
        std::cerr << "artillery play: " << e.what() << "\n";
        return game::cli::kWorkFailed;
    }
    if (code == game::cli::kOk) printReport(out, report, o, o.json);
    return code;
}

} // namespace

int runPlay(const Args& args, std::ostream& out) {
    return play(parseOptions(args), out);
}

const game::cli::Verb& playVerb() {
    static const game::cli::Verb verb{"play",
                                      "play in a window (headless picture without a display)",
                                      kPlayUsage,
                                      {"headless", "no-panel", "no-drag", "velocities", "forces",
                                       "ghosts", "contacts", "cells", "sleeping", "models", "demo",
                                       "hotseat", "sandbox", "edit"},
                                      runPlay};
    return verb;
}

int runDefault(std::ostream& out, void (*printOverview)(std::ostream&)) {
    if (displayAvailable()) return play(PlayOptions{}, out);
    out << "No display: drawing the demo headless (OSMesa, EGL fallback).\n";
    const int code = play(headlessDemo(PlayOptions{}), out);
    if (code != game::cli::kOk) return code;
    out << "Open the PNG above to see it; with a display, `artillery` opens the window.\n\n";
    printOverview(out);
    return code;
}

} // namespace ui
