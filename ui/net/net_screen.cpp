#include "ui/net/net_screen.h"

#include "game/cli/args.h"
#include "game/audio/synthesizer.h"
#include "ui/game/aim_input.h"
#include "ui/game/game_menus.h"
#include "ui/game/match_frame.h"
#include "ui/game/player_settings.h"
#include "ui/game/turn_controls.h"
#include "ui/platform/audio_device.h"
#include "ui/platform/gl_setup.h"
#include "ui/platform/imgui_layer.h"
#include "ui/platform/sdl_window.h"
#include "ui/render/gl.h"
#include "ui/render/renderer2d.h"
#include "ui/render/screenshot.h"

#include <SDL.h>
#include <imgui.h>

#include <chrono>
#include <cstring>
#include <deque>
#include <filesystem>
#include <iostream>
#include <memory>

namespace ui::net {

namespace {

using Clock = std::chrono::steady_clock;
/// Ticks per second of wall time (the match's own tick is 1/120 s by default).
constexpr double kTicksPerSecond = 120.0;

void copyInto(char* dst, std::size_t size, const std::string& s) {
    std::strncpy(dst, s.c_str(), size - 1);
    dst[size - 1] = '\0';
}

/// The form before the duel: what `host` and `join` take on the command line.
struct Form {
    char address[64] = "127.0.0.1";
    char level[256] = "levels/10_duel.json";
    char name[game::net::kMaxNameBytes + 1] = "player";
    int port = kDefaultPort;
    bool autoplay = false;
    std::vector<LevelEntry> maps; ///< the duel levels of the levels folder
};

/// The duel maps the host can pick by name (any other file can be typed in).
std::vector<LevelEntry> duelMaps(const std::string& folder) {
    std::vector<LevelEntry> maps = listLevels(folder);
    std::erase_if(maps, [](const LevelEntry& e) {
        return e.mode != game::Mode::Duel || !e.error.empty();
    });
    return maps;
}

/// The map list: picking one fills in its file.
void pickMap(Form& f) {
    const char* shown = "another file";
    for (const LevelEntry& e : f.maps)
        if (e.file == f.level) shown = e.name.c_str();
    if (!ImGui::BeginCombo("map (host)", shown)) return;
    for (const LevelEntry& e : f.maps)
        if (ImGui::Selectable(e.name.c_str(), e.file == f.level)) copyInto(f.level, sizeof f.level, e.file);
    ImGui::EndCombo();
}

/// The player's replays folder's file for the last network duel ("" without a home).
std::string lastNetworkDuelFile() {
    const std::string config = configFolder();
    if (config.empty()) return "";
    const std::filesystem::path folder = std::filesystem::path(config) / "replays";
    std::error_code ec;
    std::filesystem::create_directories(folder, ec);
    return ec ? "" : (folder / "network-last.json").string();
}

/// Draws the host/join form; true when the player pressed Host, Join or Watch (and
/// `o` then holds the choice).
bool drawForm(Form& f, NetOptions& o, const std::string& error) {
    ImGui::SetNextWindowPos(ImVec2(panelPx(40), panelPx(40)), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(panelPx(460), 0), ImGuiCond_Always);
    ImGui::Begin("Network duel", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize);
    ImGui::TextWrapped(
        "Host a duel (you play cannon 0) or join one (cannon 1). Both sides need the "
        "same program and the same level file. Esc closes.");
    ImGui::InputText("your name", f.name, sizeof f.name);
    pickMap(f);
    ImGui::InputText("level file (host)", f.level, sizeof f.level);
    ImGui::InputText("address (join)", f.address, sizeof f.address);
    ImGui::InputInt("port", &f.port);
    if (f.port < 1) f.port = 1;
    if (f.port > 65535) f.port = 65535;
    ImGui::Checkbox("the computer plays my cannon", &f.autoplay);
    bool go = false;
    if (ImGui::Button("Host")) {
        o.host = true;
        go = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Join")) {
        o.host = false;
        o.spectate = false;
        go = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Watch")) {
        o.host = false;
        o.spectate = true;
        go = true;
    }
    if (!error.empty()) ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", error.c_str());
    ImGui::End();
    if (go) {
        o.name = f.name[0] ? f.name : "player";
        o.levelFile = f.level;
        o.address = f.address;
        o.port = static_cast<std::uint16_t>(f.port);
        o.autoplay = f.autoplay;
    }
    return go;
}

/// Whether the local player may aim now: their own turn of a duel still on.
bool myTurn(const NetDuel& duel) {
    const auto* ls = duel.lockstep();
    return ls && ls->localTurn() && !ls->over() && duel.result() == NetResult::Running;
}

/// The local player's commands go to the duel (which refuses them outside one's turn).
void submitAll(NetDuel& duel, const std::vector<game::Command>& commands, std::string& status) {
    for (const game::Command& c : commands)
        if (std::string why = duel.submit(c); !why.empty()) status = why;
}

/// A window event as the local player's turn at the cannon (turn_controls.h, as in the
/// game's window), and P for the launch arc's preview.
void turnEvent(NetDuel& duel, const SDL_Event& e, AimInput& aim, phys::Vec2 pivotPx,
               bool& preview, std::string& status) {
    const auto* ls = duel.lockstep();
    if (!ls) return;
    const game::Match& m = ls->match();
    const bool mine = myTurn(duel);
    if (e.type == SDL_KEYDOWN && !e.key.repeat) {
        if (e.key.keysym.sym == SDLK_p) preview = !preview;
        if (mine)
            if (auto commands = pressTurnKey(e.key.keysym.sym, aim, m, &status))
                submitAll(duel, *commands, status);
    } else if (e.type == SDL_KEYUP) {
        submitAll(duel, releaseTurnKey(e.key.keysym.sym, aim, m), status);
    } else {
        const ImVec2 s = ImGui::GetIO().DisplayFramebufferScale;
        std::vector<game::Command> aimed;
        if (dragToAim(e, aim, m, mine, pivotPx, {s.x, s.y}, aimed)) submitAll(duel, aimed, status);
    }
}

void drawStatus(const NetDuel& duel, const std::deque<std::string>& log,
                const std::string& status) {
    // Top right: the match's HUD has the top left (level, hit points) and the bottom.
    ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x - panelPx(10), panelPx(10)),
                            ImGuiCond_Always, ImVec2(1, 0));
    ImGui::SetNextWindowBgAlpha(0.75f);
    ImGui::Begin("duel", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoTitleBar);
    const auto* ls = duel.lockstep();
    if (ls) {
        const int me = ls->localCannon();
        ImGui::Text("%s (cannon 0) vs %s (cannon 1)%s", duel.playerName(0).c_str(),
                    duel.playerName(1).c_str(), me < 0 ? "   watching" : "");
        ImGui::Text("tick %llu   %s", static_cast<unsigned long long>(ls->match().tick()),
                    ls->over()                              ? "match over"
                    : duel.result() != NetResult::Running ? "the duel has ended"
                    : ls->localTurn() && ls->match().shell() ? "your shot is in the air"
                    : ls->localTurn() ? "your turn: drag or arrows aim, Space or Enter fires"
                    : duel.paused()   ? "connection lost: paused"
                    : ls->canStep()   ? "their turn"
                                      : "waiting for the other side");
    }
    for (const std::string& line : log)
        ImGui::TextUnformatted(line.c_str());
    if (!status.empty()) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "%s", status.c_str());
    ImGui::End();
}

/// Once a frame: held keys move the local player's aim (settled as commands when let
/// go), and the aim being edited goes to the other side, which watches the barrel move.
void holdTheAim(NetDuel& duel, AimInput& aim, double dt, bool typing, std::string& status) {
    const bool mine = myTurn(duel);
    submitAll(duel,
              holdToAim(typing ? HeldAxes{} : heldArrowKeys(), dt, aim, duel.lockstep()->match(), mine),
              status);
    std::optional<game::net::AimSeen> editing;
    if (mine && aim.editing()) editing = game::net::AimSeen{aim.pending().angleDeg, aim.pending().speedMps};
    duel.shareAim(editing);
}

/// What the match view draws: in one's own turn the aim being edited and the launch arc
/// (never the whole path, nor the computer's hint: both players see the same aids); in
/// theirs, their aim as they edit it; the winner, or why the duel ended.
MatchViewOptions duelView(const NetDuel& duel, const AimInput& aim, bool preview) {
    const game::Match& match = duel.lockstep()->match();
    MatchViewOptions o;
    o.playerNames = {duel.playerName(0), duel.playerName(1)};
    const bool mine = myTurn(duel);
    o.trajectoryPreview = preview && mine;
    o.fullPreview = false;
    o.solutionHint = false;
    if (mine && aim.editing()) o.pending = aim.pending();
    if (!mine)
        if (const auto theirs = duel.peerAim()) o.pending = PendingAim{theirs->angleDeg, theirs->speedMps};
    o.charge = aim.chargeFraction();
    if (match.over())
        o.banner = match.winner() < 0 ? std::string("draw") : duel.playerName(match.winner()) + " wins";
    else if (duel.result() != NetResult::Running)
        o.banner = duel.message(); // "the other side left at tick 366: ..."
    return o;
}

/// Esc during a duel: leave it (the other side is told and the duel ends for both) or
/// stay. True when the player chose to leave; `open` goes false on either choice.
bool drawLeaveQuestion(bool& open, const std::string& opponent) {
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(display.x / 2, display.y / 2), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::Begin("Leave the duel?", nullptr,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::Text("%s will be told, and the duel ends for both of you.",
                opponent.empty() ? "The other side" : opponent.c_str());
    const bool leave = ImGui::Button("Leave (Enter)") ||
                       ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false);
    ImGui::SameLine();
    if (ImGui::Button("Stay (Esc)")) open = false;
    ImGui::End();
    if (leave) open = false;
    return leave;
}

} // namespace

int runNetWindow(const NetWindowOptions& opt, std::ostream& out) {
    std::string error;
    auto window = SdlWindow::open(opt.duel.host ? "artillery host" : "artillery join", opt.width,
                                  opt.height, error);
    if (!window) {
        std::cerr << "artillery: " << error << "\n";
        if (opt.personPlays)
            std::cerr << "artillery: a person plays the duel in a window; without one, "
                         "give --autoplay or --commands FILE\n";
        return game::cli::kBadInput;
    }
    loadGLOrThrow(*window);
    ImGuiLayer imgui(*window, window.get());
    // The duel sounds as a game in the game's window does: the synthesizer hears the match
    // after each frame's ticks (it never writes it: the lockstep hashes are the same).
    AudioDevice audio;
    if (audio.silent()) std::cerr << "artillery: playing silent (" << audio.why() << ")\n";
    game::audio::Synthesizer sound{game::audio::SynthesizerDef{.live = true}};
    sound.setMix(playerSoundMix(opt.frames.has_value()));
    Renderer2D renderer;
    MatchView view;
    Form form;
    form.maps = duelMaps(opt.duel.levelsDir);
    copyInto(form.name, sizeof form.name, opt.duel.name);
    if (!opt.duel.levelFile.empty()) copyInto(form.level, sizeof form.level, opt.duel.levelFile);
    copyInto(form.address, sizeof form.address, opt.duel.address);
    form.port = opt.duel.port;
    form.autoplay = opt.duel.autoplay;
    NetOptions chosen = opt.duel;
    std::unique_ptr<NetDuel> duel;
    std::deque<std::string> log;
    std::string status, formError;
    auto begin = [&](NetOptions o) {
        // Every game is a replay: without --record, a duel in the window goes where the
        // game's own replays go (its Replays list), as the last network duel. Check runs
        // (--frames) leave nothing behind.
        if (o.recordFile.empty() && !opt.frames) o.recordFile = lastNetworkDuelFile();
        duel = std::make_unique<NetDuel>(o);
        std::string why;
        if (!duel->start(why)) {
            formError = why;
            duel.reset();
        }
    };
    if (opt.startNow) begin(chosen);
    AimInput aim;
    bool preview = true; // the launch arc, as in a duel at home (P)
    Camera camera;       // the last frame's: where the cannon is on screen
    auto last = Clock::now();
    double owed = 0.0;
    long long overFrames = 0;
    bool running = true;
    bool askingToLeave = false; // Esc in a running duel
    std::string leaving = " closed the window"; // why, as the other side will read it
    for (long long f = 0; running && (!opt.frames || f < *opt.frames); ++f) {
        SDL_Event e;
        while (SDL_PollEvent(&e)) {
            if (window->toggleFullScreenOn(e)) continue;
            imgui.processEvent(e);
            if (e.type == SDL_QUIT) running = false;
            if (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE && duel &&
                duel->result() == NetResult::Running) {
                askingToLeave = !askingToLeave;
                aim.cancelCharge();
                continue;
            }
            if (askingToLeave) continue; // the question has the keys and the mouse
            if (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE && !duel &&
                !imgui.wantsKeyboard())
                running = false; // Esc on the form: back (to the level select, if from there)
            // A key typed into the form's fields, or the mouse over a panel, is the
            // panels'; a key let go ends a charge wherever it is.
            const bool forPanels = e.type == SDL_KEYDOWN ? imgui.wantsKeyboard()
                                   : e.type == SDL_KEYUP ? false
                                                         : imgui.wantsMouse() || imgui.pressOnWindow(e);
            if (!forPanels && duel && duel->lockstep())
                turnEvent(*duel, e, aim, camera.toPixel(duel->lockstep()->match().cannon().def.position),
                          preview, status);
        }
        const auto now = Clock::now();
        const double dt = std::chrono::duration<double>(now - last).count();
        last = now;
        if (duel) {
            // The match runs at 120 ticks per wall second; lockstep may hold it back.
            owed = std::min(owed + dt * kTicksPerSecond, 16.0);
            const auto ticks = static_cast<std::uint64_t>(owed);
            const std::uint64_t before = duel->lockstep() ? duel->lockstep()->match().tick() : 0;
            duel->pump(0, ticks);
            const std::uint64_t after = duel->lockstep() ? duel->lockstep()->match().tick() : 0;
            owed -= static_cast<double>(after - before);
            if (after == before) owed = std::min(owed, 1.0);
            for (std::string& line : duel->takeLog()) {
                out << line << std::endl;
                log.push_back(std::move(line));
                if (log.size() > 6) log.pop_front();
            }
            if (duel->result() != NetResult::Running && opt.closeWhenOver && ++overFrames > 30)
                running = false;
            if (duel->lockstep()) holdTheAim(*duel, aim, dt, imgui.wantsKeyboard(), status);
        }
        const int w = window->width(), h = window->height();
        imgui.newFrame(dt);
        gl::fn.BindFramebuffer(GL_FRAMEBUFFER, window->framebuffer());
        const game::Match* match = duel && duel->lockstep() ? &duel->lockstep()->match() : nullptr;
        if (match) {
            view.observe(*match);
            camera = levelCamera(*match, w, h);
            drawMatchFrame(renderer, view, *match, camera, duelView(*duel, aim, preview));
            if (!audio.silent()) {
                sound.setView({camera.visibleMin().x, camera.visibleMax().x});
                sound.observe(*match);
            }
        } else {
            gl::fn.Viewport(0, 0, w, h);
            gl::fn.ClearColor(0.07f, 0.12f, 0.2f, 1.0f);
            gl::fn.Clear(GL_COLOR_BUFFER_BIT);
        }
        if (!duel) {
            if (drawForm(form, chosen, formError)) begin(chosen);
        } else {
            drawStatus(*duel, log, status);
            const int me = duel->lockstep() ? duel->lockstep()->localCannon() : 0;
            if (askingToLeave && drawLeaveQuestion(askingToLeave, duel->playerName(me == 0 ? 1 : 0))) {
                leaving = " left";
                running = false; // leaves with a goodbye below
            }
        }
        imgui.drawLabels(renderer.labels());
        imgui.render();
        if (!audio.silent()) audio.feed(sound);
        const bool lastFrame = !running || (opt.frames && f + 1 == *opt.frames);
        if (lastFrame && !opt.screenshot.empty()) {
            const std::string err =
                writePng(opt.screenshot, readFramebuffer(window->framebuffer(), w, h));
            if (err.empty())
                out << "screenshot: " << opt.screenshot << std::endl;
            else
                std::cerr << "artillery: " << err << "\n";
        }
        window->present();
    }
    if (!duel) return game::cli::kCheckFailed;
    duel->leave(chosen.name + leaving);
    for (const std::string& line : duel->takeLog())
        out << line << std::endl;
    return duel->result() == NetResult::Over ? game::cli::kOk : game::cli::kCheckFailed;
}

} // namespace ui::net
