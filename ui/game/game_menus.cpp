#include "ui/game/game_menus.h"
#include "ui/game/campaign_view.h"
#include "ui/game/match_view.h"
#include "ui/game/weapon_look.h"

#include "game/files/text_file.h"
#include "game/level.h"
#include "game/replay.h"
#include "game/weapons.h"
#include "ui/platform/imgui_layer.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <ctime>
#include <cstdio>
#include <filesystem>
#include <random>

namespace ui {

namespace {

const ImVec4 kGoldText(1.0f, 0.79f, 0.24f, 1.0f);
const ImVec4 kDimText(0.7f, 0.75f, 0.82f, 1.0f);

/// The next window in the middle of the display, `width` design px wide (at most the
/// display's) and as tall as it needs, up to the display's height (then it scrolls).
void centreNextWindow(float width) {
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    const float margin = panelPx(8);
    ImGui::SetNextWindowPos(ImVec2(d.x * 0.5f, d.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(panelPx(width), d.x - 2 * margin), 0), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(d.x - 2 * margin, d.y - 2 * margin));
}

/// The next window in the middle of the display, sized to what it holds: at least `width`
/// design px wide, never past the display's edges (a taller one scrolls). Its text wraps
/// (dimWrapped, TextWrapped) at the width its widest control sets.
ImGuiWindowFlags centreFittedWindow(float width) {
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    const float margin = panelPx(8);
    ImGui::SetNextWindowPos(ImVec2(d.x * 0.5f, d.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(std::min(panelPx(width), d.x - 2 * margin), 0),
                                        ImVec2(d.x - 2 * margin, d.y - 2 * margin));
    return ImGuiWindowFlags_AlwaysAutoResize;
}

/// A full-screen menu: a fixed window in the middle with a gold heading and a dim line.
void beginMenuWindow(const char* title, const char* heading, const char* subtitle) {
    centreNextWindow(760.0f);
    ImGui::Begin(title, nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextColored(kGoldText, "%s", heading);
    ImGui::SameLine();
    ImGui::TextColored(kDimText, "%s", subtitle);
    ImGui::Separator();
}

} // namespace

bool difficultyCombo(PlayerSettings& s) {
    const game::Difficulty all[] = {game::Difficulty::Easy, game::Difficulty::Normal,
                                    game::Difficulty::Hard};
    bool changed = false;
    if (ImGui::BeginCombo("computer", game::difficultyName(s.difficulty))) {
        for (const auto d : all)
            if (ImGui::Selectable(game::difficultyName(d), d == s.difficulty) && d != s.difficulty) {
                s.difficulty = d;
                changed = true;
            }
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("How much aiming error the computer adds (duels; applies from the next match)");
    return changed;
}

namespace {

/// The seed as typed: decimal digits only, at most the largest seed a level holds.
std::optional<std::uint64_t> seedFromText(const char* text) {
    std::uint64_t seed = 0;
    if (!*text) return std::nullopt;
    for (const char* c = text; *c; ++c) {
        if (*c < '0' || *c > '9' || seed > (0x7fffffffffffffffull - 9) / 10) return std::nullopt;
        seed = seed * 10 + static_cast<std::uint64_t>(*c - '0');
    }
    return seed;
}

} // namespace

/// Random map: a seed field (the seed is the map: share it), a New seed button (drawn by
/// the operating system; the map it names is the same everywhere), practice or duel,
/// and Generate, which asks for the map to be made and played.
void randomMapRow(RandomMapForm& form, MenuChoice& choice) {
    ImGui::TextColored(kGoldText, "Random map");
    ImGui::SameLine();
    ImGui::PushItemWidth(panelPx(170));
    ImGui::InputText("seed", form.seed, sizeof form.seed, ImGuiInputTextFlags_CharsDecimal);
    ImGui::PopItemWidth();
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("The same seed gives the same map on every computer");
    ImGui::SameLine();
    if (ImGui::SmallButton("New seed")) {
        std::random_device device;
        const std::uint64_t drawn = (static_cast<std::uint64_t>(device()) << 20) ^ device();
        std::snprintf(form.seed, sizeof form.seed, "%llu",
                      static_cast<unsigned long long>(drawn % 1000000000ull));
    }
    ImGui::SameLine();
    if (ImGui::RadioButton("practice", !form.duel)) form.duel = false;
    ImGui::SameLine();
    if (ImGui::RadioButton("duel", form.duel)) form.duel = true;
    ImGui::SameLine();
    const auto seed = seedFromText(form.seed);
    ImGui::BeginDisabled(!seed);
    if (ImGui::Button("Generate and play")) choice.randomMap = RandomMapRequest{*seed, form.duel};
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Made at the computer's difficulty (below), checked playable, saved in "
                          "your maps folder, played at once");
    ImGui::EndDisabled();
    if (!seed)
        ImGui::TextColored(kDimText, "the seed is a whole number, 0 .. 9223372036854775807");
    else if (!form.status.empty())
        ImGui::TextColored(kDimText, "%s", form.status.c_str());
}

/// Level editor: a new level, or a listed one to edit, or the one being edited.
void levelEditorRow(LevelEditorForm& form, const std::vector<LevelEntry>& levels, MenuChoice& choice) {
    ImGui::TextColored(kGoldText, "Level editor");
    ImGui::SameLine();
    if (ImGui::Button("New level")) choice.editLevel = std::string();
    ImGui::SameLine();
    std::vector<const LevelEntry*> loadable;
    for (const LevelEntry& e : levels)
        if (e.error.empty()) loadable.push_back(&e);
    form.selected = std::clamp(form.selected, 0, std::max(0, static_cast<int>(loadable.size()) - 1));
    ImGui::PushItemWidth(panelPx(230));
    if (!loadable.empty() &&
        ImGui::BeginCombo("##editlevel", loadable[static_cast<std::size_t>(form.selected)]->name.c_str())) {
        for (std::size_t i = 0; i < loadable.size(); ++i)
            if (ImGui::Selectable(loadable[i]->name.c_str(), static_cast<int>(i) == form.selected))
                form.selected = static_cast<int>(i);
        ImGui::EndCombo();
    }
    ImGui::PopItemWidth();
    ImGui::SameLine();
    ImGui::BeginDisabled(loadable.empty());
    if (ImGui::Button("Edit")) choice.editLevel = loadable[static_cast<std::size_t>(form.selected)]->file;
    ImGui::EndDisabled();
    if (!form.editing.empty()) {
        ImGui::SameLine();
        if (ImGui::Button(("Back to " + form.editing).c_str())) choice.continueEditing = true;
    }
}


std::vector<LevelEntry> listLevels(const std::string& folder) {
    std::vector<LevelEntry> out;
    std::error_code ec;
    for (const auto& f : std::filesystem::directory_iterator(folder, ec)) {
        // The campaign (chapters of these levels) sits beside them; it is no level.
        if (f.path().extension() != ".json" || f.path().filename() == "campaign.json") continue;
        LevelEntry e;
        e.file = f.path().string();
        try {
            const game::Level l = game::loadLevel(e.file);
            e.name = l.name;
            e.lesson = l.lesson.empty() ? l.description : l.lesson;
            e.mode = l.mode;
            for (const game::Cannon& c : l.cannons)
                for (const std::string& p : c.projectiles)
                    if (game::weaponFromName(p) &&
                        std::find(e.weapons.begin(), e.weapons.end(), p) == e.weapons.end())
                        e.weapons.push_back(p);
        } catch (const std::exception& err) {
            e.name = f.path().filename().string();
            e.error = err.what();
        }
        out.push_back(std::move(e));
    }
    std::sort(out.begin(), out.end(), [](const LevelEntry& a, const LevelEntry& b) { return a.file < b.file; });
    return out;
}

std::vector<ReplayEntry> listReplays(const std::string& folder) {
    namespace fs = std::filesystem;
    std::vector<std::pair<fs::file_time_type, ReplayEntry>> found;
    std::error_code ec;
    for (const auto& f : fs::directory_iterator(folder, ec)) {
        if (f.path().extension() != ".json") continue;
        ReplayEntry e;
        e.file = f.path().string();
        const fs::file_time_type when = fs::last_write_time(f.path(), ec);
        const std::time_t t = std::chrono::system_clock::to_time_t(
            std::chrono::time_point_cast<std::chrono::system_clock::duration>(
                std::chrono::file_clock::to_sys(when)));
        char stamp[32] = "";
        if (const std::tm* local = std::localtime(&t))
            std::strftime(stamp, sizeof stamp, "%Y-%m-%d %H:%M", local);
        e.modified = stamp;
        try {
            const game::Replay r = game::loadReplay(e.file);
            const game::Level level = game::levelForReplay(e.file, r);
            e.level = level.name;
            // At the default tick (a `set tick_hz` command may change it on the way).
            e.seconds = static_cast<double>(r.ticks) * phys::WorldDef{}.tickSeconds;
            e.shots = static_cast<int>(
                std::count_if(r.commands.begin(), r.commands.end(), [](const game::Command& c) {
                    return c.kind == game::CommandKind::Fire;
                }));
        } catch (const std::exception& err) {
            e.level = "?";
            e.error = err.what();
        }
        found.emplace_back(when, std::move(e));
    }
    std::sort(found.begin(), found.end(),
              [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<ReplayEntry> out;
    for (auto& [when, e] : found)
        out.push_back(std::move(e));
    return out;
}


MenuChoice replaysScreen(const std::vector<ReplayEntry>& replays, const std::string& folder) {
    MenuChoice choice;
    beginMenuWindow("Replays", "REPLAYS", "every game is recorded; watch one, scrub it, take it over");
    if (folder.empty())
        ImGui::TextWrapped(
            "This run keeps no replays (check runs and headless pictures leave nothing "
            "behind). Watch a file with: artillery play --replay FILE");
    else if (replays.empty())
        ImGui::TextWrapped("No replays yet in %s: play a level and its game is recorded here.",
                           folder.c_str());
    if (!replays.empty() &&
        ImGui::BeginTable(
            "replays", 5,
            ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_ScrollY,
            ImVec2(0, panelPx(
                          std::min(420.0f, 30.0f + 26.0f * static_cast<float>(replays.size())))))) {
        ImGui::TableSetupColumn("replay", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("level", ImGuiTableColumnFlags_WidthFixed, panelPx(150));
        ImGui::TableSetupColumn("length", ImGuiTableColumnFlags_WidthFixed, panelPx(55));
        ImGui::TableSetupColumn("shots", ImGuiTableColumnFlags_WidthFixed, panelPx(40));
        ImGui::TableSetupColumn("recorded", ImGuiTableColumnFlags_WidthFixed, panelPx(140));
        ImGui::TableHeadersRow();
        for (const ReplayEntry& e : replays) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::PushID(e.file.c_str());
            ImGui::BeginDisabled(!e.error.empty());
            const std::string name = std::filesystem::path(e.file).filename().string();
            if (ImGui::Selectable(name.c_str(), false, ImGuiSelectableFlags_SpanAllColumns))
                choice.openReplay = e.file;
            ImGui::EndDisabled();
            if (!e.error.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
                ImGui::SetTooltip("%s", e.error.c_str());
            ImGui::PopID();
            ImGui::TableNextColumn();
            if (e.error.empty())
                ImGui::TextUnformatted(e.level.c_str());
            else
                ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "cannot be watched");
            ImGui::TableNextColumn();
            ImGui::TextColored(kDimText, "%.0f s", e.seconds);
            ImGui::TableNextColumn();
            ImGui::TextColored(kDimText, "%d", e.shots);
            ImGui::TableNextColumn();
            ImGui::TextColored(kDimText, "%s", e.modified.c_str());
        }
        ImGui::EndTable();
    }
    ImGui::Separator();
    if (ImGui::Button("Back to the levels (Esc)")) choice.levelSelect = true;
    ImGui::SameLine(ImGui::GetWindowWidth() - panelPx(120));
    if (ImGui::Button("Help (F1)")) choice.help = true;
    ImGui::SameLine();
    if (ImGui::Button("Quit")) choice.quit = true;
    ImGui::End();
    return choice;
}

bool soundSection(game::audio::SoundMix& mix, const std::string& silentWhy) {
    ImGui::TextUnformatted("Sound");
    bool done = false;
    auto volume = [&](const char* label, double& value) {
        float v = static_cast<float>(value);
        if (ImGui::SliderFloat(label, &v, 0.0f, 1.0f, "%.2f")) value = v; // heard at once
        done |= ImGui::IsItemDeactivatedAfterEdit();                     // saved when let go
    };
    volume("master volume", mix.master);
    volume("effects volume", mix.effects);
    volume("UI volume", mix.ui);
    done |= ImGui::Checkbox("mute", &mix.mute);
    if (!silentWhy.empty()) dimWrapped("silent: " + silentWhy);
    return done;
}

namespace {

/// The match paused: back to any earlier moment (play goes on from there as a new branch,
/// the later commands dropped; applied when the slider is let go), and the last shot again.
void rewindAndReplay(const game::Match& m, RewindControl& rewind, MenuChoice& choice) {
    const double dt = m.world().def().tickSeconds;
    const double now = static_cast<double>(m.tick()) * dt;
    if (!rewind.dragging) rewind.seconds = now;
    ImGui::PushItemWidth(-FLT_MIN);
    float seconds = static_cast<float>(rewind.seconds);
    ImGui::SliderFloat("##rewind", &seconds, 0.0f, static_cast<float>(now), "rewind to %.1f s",
                       ImGuiSliderFlags_NoInput);
    rewind.dragging = ImGui::IsItemActive();
    rewind.seconds = std::min(static_cast<double>(seconds), now);
    if (ImGui::IsItemDeactivatedAfterEdit() && rewind.seconds < now)
        choice.rewindTo = static_cast<std::uint64_t>(std::llround(rewind.seconds / dt));
    ImGui::PopItemWidth();
    dimWrapped("drag back and let go: you play on from there (Backspace: 1 s)");
    ImGui::BeginDisabled(m.shotsFired() == 0 || m.shell().has_value());
    if (ImGui::Button("Watch the last shot again (Z)", ImVec2(-FLT_MIN, 0))) choice.watchLastShot = true;
    ImGui::EndDisabled();
    ImGui::Separator();
}

} // namespace

MenuChoice pauseMenu(PlayerSettings& settings, const std::string& silentWhy,
                     const game::Match* match, RewindControl& rewind) {
    MenuChoice choice;
    const ImGuiWindowFlags fitted = centreFittedWindow(300.0f);
    ImGui::Begin("Paused", nullptr,
                 fitted | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings);
    const ImVec2 wide(-FLT_MIN, 0);
    if (ImGui::Button("Resume (Esc)", wide)) choice.resume = true;
    if (ImGui::Button("Restart level (R)", wide)) choice.restart = true;
    if (ImGui::Button("Choose another level (L)", wide)) choice.levelSelect = true;
    if (ImGui::Button("Help (F1)", wide)) choice.help = true;
    ImGui::Separator();
    if (match) rewindAndReplay(*match, rewind, choice);
    ImGui::PushItemWidth(panelPx(120));
    choice.settingsChanged |= difficultyCombo(settings);
    ImGui::PopItemWidth();
    choice.settingsChanged |= ImGui::Checkbox("hotseat duel (from the next match)", &settings.hotseat);
    choice.settingsChanged |= ImGui::Checkbox("trajectory preview (P)", &settings.trajectoryPreview);
    choice.settingsChanged |= ImGui::Checkbox("full preview, assisted (V)", &settings.fullPreview);
    choice.settingsChanged |= ImGui::Checkbox("firing-solution hint, assisted (H)", &settings.solutionHint);
    dimWrapped("assisted results earn at most two stars");
    choice.settingsChanged |= ImGui::Checkbox("camera follows the shell (C)", &settings.cameraFollow);
    choice.settingsChanged |= ImGui::Checkbox("screen shake", &settings.screenShake);
    choice.settingsChanged |= ImGui::Checkbox("physics panel (F2)", &settings.physicsPanel);
    ImGui::Separator();
    ImGui::PushItemWidth(panelPx(160));
    choice.settingsChanged |= soundSection(settings.sound, silentWhy);
    ImGui::PopItemWidth();
    ImGui::Separator();
    if (ImGui::Button("Quit", wide)) choice.quit = true;
    ImGui::End();
    return choice;
}

void helpOverlay(bool& open) {
    centreNextWindow(600.0f);
    ImGui::Begin("Help", &open, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                                    ImGuiWindowFlags_NoResize);
    struct Row {
        const char* keys;
        const char* does;
    };
    const Row rows[] = {
        {"left mouse drag", "aim: from the cannon, direction = angle, length = power"},
        {"left / right", "turn the barrel (Shift: fine)"},
        {"up / down", "power (Shift: fine)"},
        {"hold Space, release", "charge the power from zero and fire"},
        {"tap Space, Enter, F", "fire at the power set"},
        {"1 .. 8, Tab", "choose the projectile"},
        {"E", "end the turn (duels)"},
        {"P / V / H", "launch-arc preview / full preview / firing-solution hint (the last two: at "
                      "most 2 stars)"},
        {"C", "camera follows the shell and frames the impact (on / off)"},
        {"Esc", "pause menu"},
        {"F1 or ?", "this help"},
        {"F2, F6", "the lab: physics panel, Stats window (compare integrators, energy, charts)"},
        {"F3", "the cost in a corner: frame time, physics time per tick, what each model moves"},
        {"M", "measuring tools: probe a path, tape measure, stopwatch, off (the mouse measures)"},
        {"X", "compare: every integrator fires the aim, each landing error and cost, and their chart"},
        {". (period)", "one tick (pauses)"},
        {"[ / ]", "slower / faster (x1/16 .. x4); \\ back to x1"},
        {"K", "pause / resume the simulation"},
        {"Backspace (hold)",
         "rewind 1 s and play on from there (a new branch; the Match panel's slider goes further)"},
        {"Z", "watch the last shot again; Z or Esc: back to the game"},
        {"replay: Space, . ,", "play / pause, one tick forward, one back"},
        {"replay: arrows, PgUp/PgDn", "1 s back / forward (Shift: 5 s), previous / next shot"},
        {"replay: [ ] \\, R, T", "speed x1/8 .. x16, x1; from the start; take over"},
        {"R", "restart the level"},
        {"L", "level select"},
        {"editor: 1 .. 7, G",
         "tool (select, terrain, cannon, target, block, rope, blob); grid snap"},
        {"editor: Del, Ctrl+Z/Y, Ctrl+S", "delete the selected item; undo / redo; save"},
        {"editor: F5, F4", "play the level being made; back to the editor from its match"},
        {"wheel, right drag, Home", "zoom, pan, re-frame"},
        {"F11, Alt+Enter", "full screen (the panels and the HUD scale with it)"},
        {"F12", "screenshot (PNG in the current folder)"},
        {"controller",
         "left stick aims, triggers set power, A fires, B ends the turn, Start pauses"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, panelPx(190));
        ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch);
        for (const Row& r : rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(kGoldText, "%s", r.keys);
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", r.does);
        }
        ImGui::EndTable();
    }
    ImGui::PushStyleColor(ImGuiCol_Text, kDimText);
    ImGui::TextWrapped("Every change you make is a command at a tick: the game is recorded as a replay.");
    ImGui::PopStyleColor();
    ImGui::End();
}

MatchPanelRequests matchControls(const game::Match& m, bool humanTurn, ImVec2 corner) {
    MatchPanelRequests req;
    ImGui::SetNextWindowPos(corner, ImGuiCond_Always);
    ImGui::Begin("Controls", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
    const game::CannonState& c = m.cannon();
    ImGui::BeginDisabled(!humanTurn);
    if (const auto chosen = projectileBar(c)) req.projectile = *chosen;
    ImGui::SameLine();
    const bool canFire = !m.shell() && !m.over() && c.shotsLeft > 0;
    ImGui::BeginDisabled(!canFire);
    if (ImGui::Button("FIRE", ImVec2(panelPx(90), panelPx(44)))) req.fire = true;
    ImGui::EndDisabled();
    if (m.level().mode == game::Mode::Duel) {
        ImGui::SameLine();
        ImGui::BeginDisabled(m.over() || m.shell().has_value());
        if (ImGui::Button("End turn", ImVec2(0, panelPx(44)))) req.endTurn = true;
        ImGui::EndDisabled();
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Menu", ImVec2(0, panelPx(44)))) req.menu = true;
    ImGui::End();
    return req;
}

} // namespace ui
