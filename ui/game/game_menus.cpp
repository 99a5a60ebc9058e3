#include "ui/game/game_menus.h"

#include "game/files/json_reader.h"
#include "game/level.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <filesystem>

namespace ui {

namespace {

const ImVec4 kGoldText(1.0f, 0.79f, 0.24f, 1.0f);
const ImVec4 kDimText(0.7f, 0.75f, 0.82f, 1.0f);

void centreNextWindow(float width) {
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(d.x * 0.5f, d.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(width, 0), ImGuiCond_Always);
}

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

std::string starsText(int stars) {
    std::string s;
    for (int k = 0; k < 3; ++k) s += k < stars ? "*" : ".";
    return s;
}

} // namespace

std::vector<LevelEntry> listLevels(const std::string& folder) {
    std::vector<LevelEntry> out;
    std::error_code ec;
    for (const auto& f : std::filesystem::directory_iterator(folder, ec)) {
        if (f.path().extension() != ".json") continue;
        LevelEntry e;
        e.file = f.path().string();
        try {
            const game::Level l = game::loadLevel(e.file);
            e.name = l.name;
            e.lesson = l.lesson.empty() ? l.description : l.lesson;
            e.mode = game::modeName(l.mode);
        } catch (const std::exception& err) {
            e.name = f.path().filename().string();
            e.error = err.what();
        }
        out.push_back(std::move(e));
    }
    std::sort(out.begin(), out.end(), [](const LevelEntry& a, const LevelEntry& b) { return a.file < b.file; });
    return out;
}

MenuChoice levelSelectScreen(const std::vector<LevelEntry>& levels, PlayerSettings& settings) {
    MenuChoice choice;
    centreNextWindow(760.0f);
    ImGui::Begin("Choose a level", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextColored(kGoldText, "ARTILLERY");
    ImGui::SameLine();
    ImGui::TextColored(kDimText, "a physics playground: every level shows one idea");
    ImGui::Separator();
    if (levels.empty()) ImGui::TextWrapped("No level files found (looked for levels/*.json).");
    if (ImGui::BeginTable("levels", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH)) {
        ImGui::TableSetupColumn("level", ImGuiTableColumnFlags_WidthFixed, 190.0f);
        ImGui::TableSetupColumn("mode", ImGuiTableColumnFlags_WidthFixed, 70.0f);
        ImGui::TableSetupColumn("lesson", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("best", ImGuiTableColumnFlags_WidthFixed, 90.0f);
        ImGui::TableHeadersRow();
        for (const LevelEntry& e : levels) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::PushID(e.file.c_str());
            ImGui::BeginDisabled(!e.error.empty());
            if (ImGui::Selectable(e.name.c_str(), false, ImGuiSelectableFlags_SpanAllColumns))
                choice.openLevel = e.file;
            ImGui::EndDisabled();
            ImGui::PopID();
            ImGui::TableNextColumn();
            ImGui::TextColored(kDimText, "%s", e.mode.c_str());
            ImGui::TableNextColumn();
            if (e.error.empty())
                ImGui::TextWrapped("%s", e.lesson.c_str());
            else
                ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", e.error.c_str());
            ImGui::TableNextColumn();
            if (const LevelResult* r = settings.result(e.file)) {
                if (e.mode == "duel")
                    ImGui::TextColored(kGoldText, "%s", r->won ? "won" : "played");
                else
                    ImGui::TextColored(kGoldText, "%s %d", starsText(r->stars).c_str(), r->bestScore);
            } else {
                ImGui::TextColored(kDimText, "-");
            }
        }
        ImGui::EndTable();
    }
    ImGui::Separator();
    ImGui::PushItemWidth(120);
    choice.settingsChanged |= difficultyCombo(settings);
    ImGui::PopItemWidth();
    ImGui::SameLine();
    choice.settingsChanged |= ImGui::Checkbox("hotseat (duel against a person)", &settings.hotseat);
    ImGui::SameLine(ImGui::GetWindowWidth() - 120);
    if (ImGui::Button("Help (F1)")) choice.help = true;
    ImGui::SameLine();
    if (ImGui::Button("Quit")) choice.quit = true;
    ImGui::End();
    return choice;
}

MenuChoice pauseMenu(PlayerSettings& settings) {
    MenuChoice choice;
    centreNextWindow(300.0f);
    ImGui::Begin("Paused", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings);
    const ImVec2 wide(-FLT_MIN, 0);
    if (ImGui::Button("Resume (Esc)", wide)) choice.resume = true;
    if (ImGui::Button("Restart level (R)", wide)) choice.restart = true;
    if (ImGui::Button("Choose another level (L)", wide)) choice.levelSelect = true;
    if (ImGui::Button("Help (F1)", wide)) choice.help = true;
    ImGui::Separator();
    ImGui::PushItemWidth(120);
    choice.settingsChanged |= difficultyCombo(settings);
    ImGui::PopItemWidth();
    choice.settingsChanged |= ImGui::Checkbox("hotseat duel (from the next match)", &settings.hotseat);
    choice.settingsChanged |= ImGui::Checkbox("trajectory preview (P)", &settings.trajectoryPreview);
    choice.settingsChanged |= ImGui::Checkbox("firing-solution hint (H)", &settings.solutionHint);
    choice.settingsChanged |= ImGui::Checkbox("physics panel (F2)", &settings.physicsPanel);
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
        {"Enter or F", "fire at the power set"},
        {"1 .. 8, Tab", "choose the projectile"},
        {"E", "end the turn (duels)"},
        {"P / H", "trajectory preview / firing-solution hint"},
        {"Esc", "pause menu"},
        {"F1 or ?", "this help"},
        {"F2", "physics panel"},
        {". (period)", "one tick (pauses)"},
        {"[ / ]", "slower / faster (x1/16 .. x4); \\ back to x1"},
        {"Backspace", "pause / resume the simulation"},
        {"R", "restart the level"},
        {"L", "level select"},
        {"wheel, right drag, Home", "zoom, pan, re-frame"},
        {"F12", "screenshot (PNG in the current folder)"},
        {"controller", "left stick aims, triggers set power, A fires, B ends the turn, Start pauses"},
    };
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
        ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed, 190.0f);
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
    ImGui::TextColored(kDimText,
                       "Every change you make is a command at a tick: the game is recorded as a replay.");
    ImGui::End();
}

MatchPanelRequests matchPanel(const game::Match& m, bool humanTurn, PlayerSettings& settings,
                              game::Difficulty inUse, bool hotseatInUse) {
    MatchPanelRequests req;
    // On the band of soil at the bottom, beside the aim panel: cannons, targets and
    // castles stand above it, and the arcs fly higher still.
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(342, d.y - 12), ImGuiCond_FirstUseEver, ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSize(ImVec2(250, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("Match", nullptr, ImGuiWindowFlags_NoFocusOnAppearing);
    const game::CannonState& c = m.cannon();
    ImGui::BeginDisabled(!humanTurn);
    ImGui::PushItemWidth(150);
    const std::string current = c.def.projectiles[c.projectile];
    if (ImGui::BeginCombo("projectile", current.c_str())) {
        for (std::size_t i = 0; i < c.def.projectiles.size(); ++i) {
            const std::string label = std::to_string(i + 1) + "  " + c.def.projectiles[i];
            if (ImGui::Selectable(label.c_str(), i == c.projectile) && i != c.projectile)
                req.projectile = i;
        }
        ImGui::EndCombo();
    }
    ImGui::PopItemWidth();
    const bool canFire = !m.shell() && !m.over() && c.shotsLeft > 0;
    ImGui::BeginDisabled(!canFire);
    if (ImGui::Button("FIRE", ImVec2(110, 34))) req.fire = true;
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(m.over() || m.shell().has_value() || m.level().mode != game::Mode::Duel);
    if (ImGui::Button("End turn", ImVec2(110, 34))) req.endTurn = true;
    ImGui::EndDisabled();
    ImGui::EndDisabled();
    req.settingsChanged |= ImGui::Checkbox("preview (P)", &settings.trajectoryPreview);
    ImGui::SameLine();
    req.settingsChanged |= ImGui::Checkbox("hint (H)", &settings.solutionHint);
    if (m.level().mode == game::Mode::Duel)
        ImGui::TextColored(kDimText, "%s", hotseatInUse ? "hotseat: two players" :
                                               (std::string("computer: ") + game::difficultyName(inUse)).c_str());
    ImGui::End();
    return req;
}

} // namespace ui
