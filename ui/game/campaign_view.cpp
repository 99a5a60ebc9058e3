#include "ui/game/campaign_view.h"
#include "ui/game/lesson_pictures.h"
#include "ui/platform/imgui_layer.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>

namespace ui {

namespace {

const ImVec4 kGold(1.0f, 0.79f, 0.24f, 1.0f);
const ImVec4 kDim(0.7f, 0.75f, 0.82f, 1.0f);
const ImVec4 kLocked(0.5f, 0.52f, 0.56f, 1.0f);

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
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
    for (const LevelEntry& e : levels) {
        byName[fileName(e.file)] = &e;
        if (e.error.empty() && e.mode == game::Mode::Duel) menu.campaign.duels.insert(fileName(e.file));
    }
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

MenuChoice nextLevelCard(const CampaignMenu& menu, const game::Progress& progress,
                         const std::string& levelFile, ImVec2 corner) {
    MenuChoice choice;
    const auto next = game::nextLevel(menu.campaign, levelFile);
    if (!next) return choice;
    const LevelEntry& e = menu.chapters[next->chapter][next->level];
    const game::Lock lock =
        game::levelLock(menu.campaign, next->chapter, next->level, progress, e.mode);
    ImGui::SetNextWindowPos(corner, ImGuiCond_Always);
    ImGui::Begin("Next level", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoTitleBar);
    const std::string label = "Next: " + std::to_string(next->chapter + 1) + "." +
                              std::to_string(next->level + 1) + "  " + e.name;
    ImGui::BeginDisabled(!lock.open || !e.error.empty());
    if (ImGui::Button(label.c_str())) chooseLevel(menu, *next, progress, choice);
    ImGui::EndDisabled();
    if (!lock.open) {
        // As wide as the results card above it at most: a long reason wraps.
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + panelPx(420));
        ImGui::TextColored(kLocked, "locked: %s", lock.why.c_str());
        ImGui::PopTextWrapPos();
    }
    ImGui::SameLine();
    // Another go at this level, as R does: what a player who missed a star reaches for.
    if (ImGui::Button("Retry (R)")) choice.restart = true;
    ImGui::SameLine();
    if (ImGui::Button("Levels (L)")) choice.levelSelect = true;
    ImGui::End();
    return choice;
}

MenuChoice lessonScreen(const game::Campaign& campaign, std::size_t chapter,
                        const std::string& thenLevel, const LessonArt& art) {
    MenuChoice choice;
    const game::Chapter& ch = campaign.chapters.at(chapter);
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(d.x * 0.5f, d.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(std::min(panelPx(760), d.x - panelPx(24)), 0), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(d.x, d.y - panelPx(16))); // else it scrolls
    ImGui::Begin("Lesson", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar);
    ImGui::TextColored(kGold, "CHAPTER %zu", chapter + 1);
    ImGui::SameLine();
    ImGui::TextUnformatted(ch.title.c_str());
    ImGui::Separator();
    // The idea as a picture, drawn by the game from the chapter's formula.
    // On a short screen the picture gives up height first, so the text stays in view.
    const float height = std::min(ImGui::GetContentRegionAvail().x * 0.42f, 0.4f * d.y);
    const ImVec2 size(std::round(height / 0.42f), std::round(height));
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    if (art.pictures && !art.picture.empty())
        if (const TextureTarget* t = art.pictures->picture(art.picture, static_cast<int>(size.x * scale.x),
                                                           static_cast<int>(size.y * scale.y), art.fbo)) {
            ImGui::SetCursorPosX(ImGui::GetCursorPosX() + 0.5f * (ImGui::GetContentRegionAvail().x - size.x));
            ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(t->texture())), size,
                         ImVec2(0, 1), ImVec2(1, 0));
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextColored(kDim, "%s", lessonPictureCaption(art.picture).c_str());
            ImGui::PopTextWrapPos();
        }
    ImGui::Spacing();
    // The formula stands on its own, in the large face: read from across the room.
    ImGui::PushFont(largeFont());
    ImGui::PushStyleColor(ImGuiCol_Text, kGold);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(ch.formula.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
    ImGui::PopFont();
    ImGui::Spacing();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(ch.lesson.c_str());
    ImGui::PopTextWrapPos();
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
