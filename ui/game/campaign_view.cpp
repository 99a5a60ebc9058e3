#include "ui/game/campaign_view.h"
#include "ui/platform/imgui_layer.h"
#include "ui/render/design_canvas.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <map>

namespace ui {

namespace {

const ImVec4 kGold(1.0f, 0.79f, 0.24f, 1.0f);
const ImVec4 kDim(0.7f, 0.75f, 0.82f, 1.0f);
const ImVec4 kLocked(0.5f, 0.52f, 0.56f, 1.0f);
const ImVec4 kError(1.0f, 0.4f, 0.4f, 1.0f);
constexpr float kTableHeight = 470.0f; ///< px: the chapters scroll inside the menu

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

std::string starsText(int stars) {
    std::string s;
    for (int k = 0; k < 3; ++k)
        s += k < stars ? "*" : ".";
    return s;
}

/// The best-result column: stars and score, "won" for a duel, "-" before any play.
void resultCell(const LevelEntry& e, const game::Progress& progress) {
    const game::LevelResult* r = progress.result(e.file);
    if (!r) {
        ImGui::TextColored(kDim, "-");
    } else if (e.mode == game::Mode::Duel) {
        ImGui::TextColored(kGold, "%s", r->won ? "won" : "played");
    } else {
        ImGui::TextColored(kGold, "%s %d%s", starsText(r->stars).c_str(), r->bestScore,
                           r->assisted ? " (assisted)" : "");
        if (r->assisted && ImGui::IsItemHovered())
            ImGui::SetTooltip("Played with the full preview or the hint: at most two stars");
    }
}

/// One level's row: its number and name (a click plays it), mode, lesson or why it is
/// locked, and the best result.
void levelRow(const std::string& number, const LevelEntry& e, const game::Lock& lock,
              const game::Progress& progress, bool& clicked) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::PushID(e.file.c_str());
    ImGui::BeginDisabled(!e.error.empty() || !lock.open);
    const std::string label = number.empty() ? e.name : number + "  " + e.name;
    if (ImGui::Selectable(label.c_str(), false, ImGuiSelectableFlags_SpanAllColumns))
        clicked = true;
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", !e.error.empty() ? e.error.c_str()
                                : lock.open      ? e.lesson.c_str()
                                            : ("Locked: " + lock.why + "\n" + e.lesson).c_str());
    ImGui::PopID();
    ImGui::TableNextColumn();
    ImGui::TextColored(kDim, "%s", e.error.empty() ? game::modeName(e.mode) : "");
    ImGui::TableNextColumn();
    if (!e.error.empty())
        ImGui::TextColored(kError, "%s", e.error.c_str());
    else if (!lock.open)
        ImGui::TextColored(kLocked, "locked: %s", lock.why.c_str()); // the tooltip: the lesson
    else
        ImGui::TextUnformatted(e.lesson.c_str()); // one line, clipped; the tooltip has it all
    ImGui::TableNextColumn();
    resultCell(e, progress);
}

/// A chapter's heading row: number and title, stars earned of those there are, the
/// lesson button, and why it is locked.
bool chapterRow(std::size_t c, const game::Chapter& ch, const std::vector<LevelEntry>& levels,
                const game::Lock& lock, const game::Progress& progress) {
    ImGui::TableNextRow(ImGuiTableRowFlags_None, panelPx(28));
    ImGui::TableSetBgColor(ImGuiTableBgTarget_RowBg0,
                           ImGui::GetColorU32(ImVec4(0.16f, 0.2f, 0.3f, 1)));
    ImGui::TableNextColumn();
    ImGui::TextColored(lock.open ? kGold : kLocked, "Chapter %zu", c + 1);
    ImGui::TableNextColumn();
    int practice = 0;
    for (const LevelEntry& e : levels)
        practice += e.mode == game::Mode::Practice && e.error.empty();
    ImGui::TextColored(kGold, "%d/%d *", game::chapterStars(ch, progress), 3 * practice);
    ImGui::TableNextColumn();
    ImGui::TextColored(lock.open ? ImVec4(1, 1, 1, 1) : kLocked, "%s", ch.title.c_str());
    if (!lock.open) {
        ImGui::SameLine();
        ImGui::TextColored(kLocked, "(locked: %s)", lock.why.c_str());
    }
    ImGui::TableNextColumn();
    ImGui::PushID(static_cast<int>(c));
    const bool lesson = ImGui::SmallButton("Lesson");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", ch.formula.c_str());
    ImGui::PopID();
    return lesson;
}

} // namespace

CampaignMenu campaignMenu(const std::string& folder, const std::vector<LevelEntry>& levels) {
    CampaignMenu menu;
    const std::string file = (std::filesystem::path(folder) / "campaign.json").string();
    std::error_code ec;
    if (std::filesystem::exists(file, ec)) {
        try {
            menu.campaign = game::loadCampaign(file);
            for (const game::MissingLevel& m : game::missingLevels(menu.campaign, folder)) {
                menu.campaign.missing[m.file] = m.why;
                menu.missing.push_back(game::describe(menu.campaign, m));
            }
        } catch (const std::exception& e) {
            menu.error = e.what();
        }
    }
    std::map<std::string, const LevelEntry*> byName;
    for (const LevelEntry& e : levels)
        byName[fileName(e.file)] = &e;
    std::map<std::string, bool> placed;
    for (const game::Chapter& ch : menu.campaign.chapters) {
        menu.chapters.emplace_back();
        for (const std::string& name : ch.levels) {
            placed[name] = true;
            if (const auto it = byName.find(name); it != byName.end()) {
                menu.chapters.back().push_back(*it->second);
            } else {
                LevelEntry missing;
                missing.file = (std::filesystem::path(folder) / name).string();
                missing.name = name;
                missing.error = "no such level file in " + folder;
                menu.chapters.back().push_back(missing);
            }
        }
    }
    for (const LevelEntry& e : levels)
        if (!placed.count(fileName(e.file))) menu.outside.push_back(e);
    return menu;
}

std::optional<game::LevelPlace> levelOnTheWay(const CampaignMenu& menu,
                                              const game::Progress& progress) {
    const game::Campaign& campaign = menu.campaign;
    for (std::size_t c = 0; c < campaign.chapters.size() && c < menu.chapters.size(); ++c)
        for (std::size_t l = 0; l < menu.chapters[c].size(); ++l) {
            const LevelEntry& e = menu.chapters[c][l];
            if (e.mode == game::Mode::Duel || !e.error.empty() || game::cleared(progress, e.file))
                continue;
            if (game::levelLock(campaign, c, l, progress, e.mode).open)
                return game::LevelPlace{c, l};
        }
    return std::nullopt;
}

void chooseLevel(const CampaignMenu& menu, game::LevelPlace place, const game::Progress& progress,
                 MenuChoice& choice) {
    const LevelEntry& e = menu.chapters[place.chapter][place.level];
    if (!progress.lessonsSeen.count(menu.campaign.chapters[place.chapter].id)) {
        choice.showLesson = place.chapter;
        choice.lessonThenLevel = e.file;
    } else {
        choice.openLevel = e.file;
    }
}

void playNextButton(const CampaignMenu& menu, const game::Progress& progress, MenuChoice& choice) {
    const auto next = levelOnTheWay(menu, progress);
    if (!next) return;
    const std::string label = "Play next: " + std::to_string(next->chapter + 1) + "." +
                              std::to_string(next->level + 1) + "  " +
                              menu.chapters[next->chapter][next->level].name + "  (Enter)";
    ImGui::PushStyleColor(ImGuiCol_Text, kGold);
    const bool pressed = ImGui::Button(label.c_str());
    ImGui::PopStyleColor();
    // Enter as well, unless a text field (the random map's seed, a level's name) has it.
    if (pressed || (!ImGui::GetIO().WantTextInput &&
                    ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter), false)))
        chooseLevel(menu, *next, progress, choice);
}

void campaignTable(const CampaignMenu& menu, const game::Progress& progress, MenuChoice& choice) {
    if (!menu.error.empty()) ImGui::TextColored(kError, "%s", menu.error.c_str());
    for (const std::string& missing : menu.missing) {
        ImGui::PushStyleColor(ImGuiCol_Text, kError);
        ImGui::TextWrapped("%s", missing.c_str());
        ImGui::PopStyleColor();
    }
    // When the screen opens, the list scrolls to the first open level not yet cleared:
    // where the player left off. Twice: on the first frame the list has no height yet.
    ImGuiStorage* storage = ImGui::GetStateStorage();
    const ImGuiID scrollKey = ImGui::GetID("scroll to the next level");
    if (ImGui::IsWindowAppearing()) storage->SetInt(scrollKey, 2);
    const int scrollFrames = storage->GetInt(scrollKey, 0);
    bool scrollToNext = scrollFrames > 0;
    storage->SetInt(scrollKey, std::max(0, scrollFrames - 1));
    if (!ImGui::BeginTable("campaign", 4,
                           ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH |
                               ImGuiTableFlags_ScrollY,
                           ImVec2(0, panelPx(kTableHeight))))
        return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("level", ImGuiTableColumnFlags_WidthFixed, panelPx(200));
    ImGui::TableSetupColumn("mode", ImGuiTableColumnFlags_WidthFixed, panelPx(70));
    ImGui::TableSetupColumn("lesson", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("best", ImGuiTableColumnFlags_WidthFixed, panelPx(150));
    ImGui::TableHeadersRow();
    const game::Campaign& campaign = menu.campaign;
    const auto onTheWay = levelOnTheWay(menu, progress);
    for (std::size_t c = 0; c < campaign.chapters.size(); ++c) {
        const game::Chapter& ch = campaign.chapters[c];
        const std::vector<LevelEntry>& levels = menu.chapters[c];
        if (chapterRow(c, ch, levels, game::chapterLock(campaign, c, progress), progress)) {
            choice.showLesson = c;
            choice.lessonThenLevel.clear();
        }
        for (std::size_t l = 0; l < levels.size(); ++l) {
            const game::Lock lock = game::levelLock(campaign, c, l, progress, levels[l].mode);
            bool clicked = false;
            levelRow(std::to_string(c + 1) + "." + std::to_string(l + 1), levels[l], lock, progress,
                     clicked);
            if (scrollToNext && onTheWay == game::LevelPlace{c, l}) {
                ImGui::SetScrollHereY(0.3f);
                scrollToNext = false;
            }
            if (clicked) chooseLevel(menu, {c, l}, progress, choice);
        }
    }
    if (!menu.outside.empty()) {
        ImGui::TableNextRow(ImGuiTableRowFlags_None, panelPx(28));
        ImGui::TableNextColumn();
        ImGui::TextColored(kGold, "%s", campaign.chapters.empty() ? "Levels" : "Outside");
        ImGui::TableNextColumn();
        ImGui::TableNextColumn();
        ImGui::TextColored(kDim, "%s", campaign.chapters.empty() ? "" : "always open");
        ImGui::TableNextColumn();
    }
    for (const LevelEntry& e : menu.outside) {
        bool clicked = false;
        levelRow("", e, game::Lock{}, progress, clicked);
        if (clicked) choice.openLevel = e.file;
    }
    ImGui::EndTable();
}

MenuChoice nextLevelCard(const CampaignMenu& menu, const game::Progress& progress,
                         const std::string& levelFile) {
    MenuChoice choice;
    const auto next = game::nextLevel(menu.campaign, levelFile);
    if (!next) return choice;
    const LevelEntry& e = menu.chapters[next->chapter][next->level];
    const game::Lock lock =
        game::levelLock(menu.campaign, next->chapter, next->level, progress, e.mode);
    // Just below the results card in the middle of the screen (ui/game/match_view.cpp).
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    const auto belowCard = static_cast<float>(86.0 * hudScale(d.x, d.y));
    ImGui::SetNextWindowPos(ImVec2(d.x * 0.5f, d.y * 0.5f + belowCard), ImGuiCond_Always,
                            ImVec2(0.5f, 0.0f));
    ImGui::Begin("Next level", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoTitleBar);
    const std::string label = "Next: " + std::to_string(next->chapter + 1) + "." +
                              std::to_string(next->level + 1) + "  " + e.name;
    ImGui::BeginDisabled(!lock.open || !e.error.empty());
    if (ImGui::Button(label.c_str())) chooseLevel(menu, *next, progress, choice);
    ImGui::EndDisabled();
    if (!lock.open) ImGui::TextColored(kLocked, "locked: %s", lock.why.c_str());
    ImGui::SameLine();
    if (ImGui::Button("Levels (L)")) choice.levelSelect = true;
    ImGui::End();
    return choice;
}

MenuChoice lessonScreen(const game::Campaign& campaign, std::size_t chapter,
                        const std::string& thenLevel) {
    MenuChoice choice;
    const game::Chapter& ch = campaign.chapters.at(chapter);
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(d.x * 0.5f, d.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(panelPx(680), 0), ImGuiCond_Always);
    ImGui::Begin("Lesson", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings);
    ImGui::TextColored(kGold, "CHAPTER %zu", chapter + 1);
    ImGui::SameLine();
    ImGui::TextUnformatted(ch.title.c_str());
    ImGui::Separator();
    ImGui::Spacing();
    // The formula stands on its own line, large enough to read from across the room.
    ImGui::SetWindowFontScale(1.25f);
    ImGui::PushStyleColor(ImGuiCol_Text, kGold);
    ImGui::TextWrapped("%s", ch.formula.c_str());
    ImGui::PopStyleColor();
    ImGui::SetWindowFontScale(1.0f);
    ImGui::Spacing();
    ImGui::TextWrapped("%s", ch.lesson.c_str());
    ImGui::Spacing();
    ImGui::Separator();
    if (!thenLevel.empty()) {
        if (ImGui::Button("Play (Enter)", ImVec2(panelPx(200), 0)) ||
            ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter))) {
            choice.openLevel = thenLevel;
            choice.lessonSeen = ch.id;
        }
        ImGui::SameLine();
    }
    if (ImGui::Button("Back to the levels (Esc)")) {
        choice.levelSelect = true;
        choice.lessonSeen = ch.id;
    }
    ImGui::End();
    return choice;
}

} // namespace ui
