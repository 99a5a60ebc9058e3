#include "ui/net/net_screen.h"

#include "game/cli/args.h"
#include "game/audio/synthesizer.h"
#include "ui/game/match_frame.h"
#include "ui/game/player_settings.h"
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
};

/// Draws the host/join form; true when the player pressed Host, Join or Watch (and
/// `o` then holds the choice).
bool drawForm(Form& f, NetOptions& o, const std::string& error) {
    ImGui::SetNextWindowPos(ImVec2(panelPx(40), panelPx(40)), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(panelPx(460), 0), ImGuiCond_Always);
    ImGui::Begin("Network duel", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize);
    ImGui::TextWrapped(
        "Host a duel (you play cannon 0) or join one (cannon 1). Both sides need the "
        "same program and the same level file.");
    ImGui::InputText("your name", f.name, sizeof f.name);
    ImGui::InputText("level (host)", f.level, sizeof f.level);
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

/// The local cannon's keys as commands (only in one's own turn; the duel refuses others).
void keyCommand(NetDuel& duel, SDL_Keycode key, std::string& status) {
    const auto* ls = duel.lockstep();
    if (!ls || !ls->localTurn()) return;
    const game::CannonState& c = ls->match().cannon();
    game::Command cmd;
    switch (key) {
    case SDLK_LEFT:
        cmd.kind = game::CommandKind::Aim;
        cmd.number = c.angleDeg + 1.0;
        break;
    case SDLK_RIGHT:
        cmd.kind = game::CommandKind::Aim;
        cmd.number = c.angleDeg - 1.0;
        break;
    case SDLK_UP:
        cmd.kind = game::CommandKind::Power;
        cmd.number = std::min(c.def.maxSpeedMps, c.speedMps + 1.0);
        break;
    case SDLK_DOWN:
        cmd.kind = game::CommandKind::Power;
        cmd.number = std::max(0.0, c.speedMps - 1.0);
        break;
    case SDLK_TAB:
        cmd.kind = game::CommandKind::Select;
        cmd.text = c.def.projectiles[(c.projectile + 1) % c.def.projectiles.size()];
        break;
    case SDLK_SPACE:
        cmd.kind = game::CommandKind::Fire;
        break;
    case SDLK_RETURN:
        cmd.kind = game::CommandKind::EndTurn;
        break;
    default:
        return;
    }
    if (std::string why = duel.submit(cmd); !why.empty()) status = why;
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
                    ls->over()        ? "match over"
                    : ls->localTurn() ? "your turn (arrows aim, Tab shell, Space fire)"
                    : duel.paused()   ? "connection lost: paused"
                    : ls->canStep()   ? "their turn"
                                      : "waiting for the other side");
    }
    for (const std::string& line : log)
        ImGui::TextUnformatted(line.c_str());
    if (!status.empty()) ImGui::TextColored(ImVec4(1, 0.8f, 0.3f, 1), "%s", status.c_str());
    ImGui::End();
}

} // namespace

int runNetWindow(const NetWindowOptions& opt, std::ostream& out) {
    std::string error;
    auto window = SdlWindow::open(opt.duel.host ? "artillery host" : "artillery join", opt.width,
                                  opt.height, error);
    if (!window) {
        std::cerr << "artillery: " << error << "\n";
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
    copyInto(form.name, sizeof form.name, opt.duel.name);
    if (!opt.duel.levelFile.empty()) copyInto(form.level, sizeof form.level, opt.duel.levelFile);
    copyInto(form.address, sizeof form.address, opt.duel.address);
    form.port = opt.duel.port;
    form.autoplay = opt.duel.autoplay;
    NetOptions chosen = opt.duel;
    std::unique_ptr<NetDuel> duel;
    std::deque<std::string> log;
    std::string status, formError;
    auto begin = [&](const NetOptions& o) {
        duel = std::make_unique<NetDuel>(o);
        std::string why;
        if (!duel->start(why)) {
            formError = why;
            duel.reset();
        }
    };
    if (opt.startNow) begin(chosen);
    auto last = Clock::now();
    double owed = 0.0;
    long long overFrames = 0;
    bool running = true;
    for (long long f = 0; running && (!opt.frames || f < *opt.frames); ++f) {
        SDL_Event e;
        while (SDL_PollEvent(&e)) {
            if (window->toggleFullScreenOn(e)) continue;
            const bool uiWants = imgui.processEvent(e);
            if (e.type == SDL_QUIT) running = false;
            if (e.type == SDL_KEYDOWN && !uiWants && duel)
                keyCommand(*duel, e.key.keysym.sym, status);
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
        }
        const int w = window->width(), h = window->height();
        imgui.newFrame(dt);
        gl::fn.BindFramebuffer(GL_FRAMEBUFFER, window->framebuffer());
        const game::Match* match = duel && duel->lockstep() ? &duel->lockstep()->match() : nullptr;
        if (match) {
            view.observe(*match);
            MatchViewOptions o;
            o.playerNames = {duel->playerName(0), duel->playerName(1)};
            o.trajectoryPreview = false;
            o.solutionHint = false;
            if (match->over())
                o.banner = match->winner() < 0 ? std::string("draw")
                                               : duel->playerName(match->winner()) + " wins";
            const Camera camera = levelCamera(*match, w, h);
            drawMatchFrame(renderer, view, *match, camera, o);
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
    if (duel->result() == NetResult::Running) duel->save();
    return duel->result() == NetResult::Over ? game::cli::kOk : game::cli::kCheckFailed;
}

} // namespace ui::net
