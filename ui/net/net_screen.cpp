#include "ui/net/net_screen.h"

#include "game/audio/synthesizer.h"
#include "game/cli/args.h"
#include "game/files/save_folder.h"
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

/// The player's replays folder's file for the last network duel ("" without a home). A
/// settings folder that cannot be written gives a temporary folder, said on the terminal.
std::string lastNetworkDuelFile() {
    const game::SaveFolder saves(configFolder());
    if (!saves.notice().empty()) std::cerr << "artillery: " << saves.notice() << "\n";
    if (saves.replaysFolder().empty()) return "";
    return (std::filesystem::path(saves.replaysFolder()) / "network-last.json").string();
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

/// The duel's window and everything that lives as long as it: the form, the duel once
/// chosen, the local player's aim, the log and the sound. One frame at a time: the
/// events, the duel's ticks, the picture.
class DuelWindow {
  public:
    DuelWindow(const NetWindowOptions& opt, std::unique_ptr<SdlWindow> window, std::ostream& out)
        : opt_(opt), out_(out), window_(std::move(window)), imgui_(*window_, window_.get()),
          chosen_(opt.duel) {
        // The duel sounds as a game in the game's window does: the synthesizer hears the
        // match after each frame's ticks (it never writes it: the lockstep hashes are the
        // same).
        if (audio_.silent()) std::cerr << "artillery: playing silent (" << audio_.why() << ")\n";
        sound_.setMix(playerSoundMix(opt.frames.has_value()));
        form_.maps = duelMaps(opt.duel.levelsDir);
        copyInto(form_.name, sizeof form_.name, opt.duel.name);
        if (!opt.duel.levelFile.empty())
            copyInto(form_.level, sizeof form_.level, opt.duel.levelFile);
        copyInto(form_.address, sizeof form_.address, opt.duel.address);
        form_.port = opt.duel.port;
        form_.autoplay = opt.duel.autoplay;
        if (opt.startNow) begin(chosen_);
    }

    int run() {
        auto last = Clock::now();
        for (long long f = 0; running_ && (!opt_.frames || f < *opt_.frames); ++f) {
            handleEvents();
            const auto now = Clock::now();
            const double dt = std::chrono::duration<double>(now - last).count();
            last = now;
            if (duel_) pumpDuel(dt);
            drawFrame(dt);
            const bool lastFrame = !running_ || (opt_.frames && f + 1 == *opt_.frames);
            if (lastFrame) saveScreenshot();
            window_->present();
        }
        if (!duel_) return game::cli::kCheckFailed;
        duel_->leave(chosen_.name + leaving_);
        for (const std::string& line : duel_->takeLog())
            out_ << line << std::endl;
        return duel_->result() == NetResult::Over ? game::cli::kOk : game::cli::kCheckFailed;
    }

  private:
    void begin(NetOptions o) {
        // Every game is a replay: without --record, a duel in the window goes where the
        // game's own replays go (its Replays list), as the last network duel. Check runs
        // (--frames) leave nothing behind.
        if (o.recordFile.empty() && !opt_.frames) o.recordFile = lastNetworkDuelFile();
        duel_ = std::make_unique<NetDuel>(o);
        std::string why;
        if (!duel_->start(why)) {
            formError_ = why;
            duel_.reset();
        }
    }

    void handleEvents() {
        SDL_Event e;
        while (SDL_PollEvent(&e)) {
            if (window_->toggleFullScreenOn(e)) continue;
            imgui_.processEvent(e);
            if (e.type == SDL_QUIT) running_ = false;
            if (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE && duel_ &&
                duel_->result() == NetResult::Running) {
                askingToLeave_ = !askingToLeave_;
                aim_.cancelCharge();
                continue;
            }
            if (askingToLeave_) continue; // the question has the keys and the mouse
            if (e.type == SDL_KEYDOWN && e.key.keysym.sym == SDLK_ESCAPE && !duel_ &&
                !imgui_.wantsKeyboard())
                running_ = false; // Esc on the form: back (to the level select, if from there)
            // A key typed into the form's fields, or the mouse over a panel, is the
            // panels'; a key let go ends a charge wherever it is.
            const bool forPanels = e.type == SDL_KEYDOWN ? imgui_.wantsKeyboard()
                                   : e.type == SDL_KEYUP ? false
                                                         : imgui_.wantsMouse() || imgui_.pressOnWindow(e);
            if (!forPanels && duel_ && duel_->lockstep())
                turnEvent(*duel_, e, aim_,
                          camera_.toPixel(duel_->lockstep()->match().cannon().def.position),
                          preview_, status_);
        }
    }

    /// The match runs at 120 ticks per wall second; lockstep may hold it back.
    void pumpDuel(double dt) {
        owed_ = std::min(owed_ + dt * kTicksPerSecond, 16.0);
        const auto ticks = static_cast<std::uint64_t>(owed_);
        const std::uint64_t before = duel_->lockstep() ? duel_->lockstep()->match().tick() : 0;
        duel_->pump(0, ticks);
        const std::uint64_t after = duel_->lockstep() ? duel_->lockstep()->match().tick() : 0;
        owed_ -= static_cast<double>(after - before);
        if (after == before) owed_ = std::min(owed_, 1.0);
        for (std::string& line : duel_->takeLog()) {
            out_ << line << std::endl;
            log_.push_back(std::move(line));
            if (log_.size() > 6) log_.pop_front();
        }
        if (duel_->result() != NetResult::Running && opt_.closeWhenOver && ++overFrames_ > 30)
            running_ = false;
        if (duel_->lockstep()) holdTheAim(*duel_, aim_, dt, imgui_.wantsKeyboard(), status_);
    }

    void drawFrame(double dt) {
        const int w = window_->width(), h = window_->height();
        imgui_.newFrame(dt);
        gl::fn.BindFramebuffer(GL_FRAMEBUFFER, window_->framebuffer());
        const game::Match* match = duel_ && duel_->lockstep() ? &duel_->lockstep()->match() : nullptr;
        if (match) {
            view_.observe(*match);
            camera_ = levelCamera(*match, w, h);
            drawMatchFrame(renderer_, view_, *match, camera_, duelView(*duel_, aim_, preview_));
            if (!audio_.silent()) {
                sound_.setView({camera_.visibleMin().x, camera_.visibleMax().x});
                sound_.observe(*match);
            }
        } else {
            gl::fn.Viewport(0, 0, w, h);
            gl::fn.ClearColor(0.07f, 0.12f, 0.2f, 1.0f);
            gl::fn.Clear(GL_COLOR_BUFFER_BIT);
        }
        if (!duel_) {
            if (drawForm(form_, chosen_, formError_)) begin(chosen_);
        } else {
            drawStatus(*duel_, log_, status_);
            const int me = duel_->lockstep() ? duel_->lockstep()->localCannon() : 0;
            if (askingToLeave_ &&
                drawLeaveQuestion(askingToLeave_, duel_->playerName(me == 0 ? 1 : 0))) {
                leaving_ = " left";
                running_ = false; // leaves with a goodbye in run()
            }
        }
        imgui_.drawLabels(renderer_.labels());
        imgui_.render();
        if (!audio_.silent()) audio_.feed(sound_);
    }

    void saveScreenshot() {
        if (opt_.screenshot.empty()) return;
        const std::string err = writePng(
            opt_.screenshot, readFramebuffer(window_->framebuffer(), window_->width(), window_->height()));
        if (err.empty())
            out_ << "screenshot: " << opt_.screenshot << std::endl;
        else
            std::cerr << "artillery: " << err << "\n";
    }

    const NetWindowOptions& opt_;
    std::ostream& out_;
    std::unique_ptr<SdlWindow> window_; ///< its GL functions loaded (runNetWindow)
    ImGuiLayer imgui_;
    AudioDevice audio_;
    game::audio::Synthesizer sound_{game::audio::SynthesizerDef{.live = true}};
    Renderer2D renderer_;
    MatchView view_;
    Form form_;
    NetOptions chosen_;
    std::unique_ptr<NetDuel> duel_;
    std::deque<std::string> log_;
    std::string status_, formError_;
    AimInput aim_;
    bool preview_ = true; ///< the launch arc, as in a duel at home (P)
    Camera camera_;       ///< the last frame's: where the cannon is on screen
    double owed_ = 0.0;
    long long overFrames_ = 0;
    bool running_ = true;
    bool askingToLeave_ = false;               ///< Esc in a running duel
    std::string leaving_ = " closed the window"; ///< why, as the other side will read it
};

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
    DuelWindow duelWindow(opt, std::move(window), out);
    return duelWindow.run();
}

} // namespace ui::net
