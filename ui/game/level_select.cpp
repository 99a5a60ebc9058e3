// Section index
//   tiles    a level's tile: picture, name, stars, lock; the grid of a page
//   pages    the page's heading (chapter, stars, lesson) and turning the pages
//   screen   the window, the footer with the other screens and the player's choices
#include "ui/game/level_select.h"

#include "ui/platform/imgui_layer.h"

#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <string>

namespace ui {

namespace {

const ImVec4 kGold(1.0f, 0.79f, 0.24f, 1.0f);
const ImVec4 kDim(0.7f, 0.75f, 0.82f, 1.0f);
const ImVec4 kLocked(0.55f, 0.57f, 0.62f, 1.0f);
const ImVec4 kError(1.0f, 0.45f, 0.45f, 1.0f);
constexpr float kTileWidth = 250.0f;    ///< design px
constexpr float kTooltipWidth = 420.0f; ///< design px: a tooltip wraps at this width

/// "★★☆": the stars earned of three.
std::string starsText(int stars) {
    std::string s;
    for (int k = 0; k < 3; ++k) s += k < stars ? "\u2605" : "\u2606";
    return s;
}

/// A tooltip that wraps (a lesson is a few sentences) instead of running off the screen.
void wrappedTooltip(const std::string& text) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(panelPx(kTooltipWidth));
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

/// What the player earned on a level: stars and the best score, a duel won; nothing yet.
void resultLine(const LevelEntry& e, const game::Progress& progress) {
    const game::LevelResult* r = progress.result(e.file);
    if (e.mode == game::Mode::Duel) {
        ImGui::TextColored(r && r->won ? kGold : kDim, "%s", !r ? "duel: not played yet"
                                                             : r->won ? "duel: won" : "duel: played");
        return;
    }
    if (e.mode != game::Mode::Practice) {
        ImGui::TextColored(kDim, "%s", game::modeName(e.mode));
        return;
    }
    if (!r) {
        ImGui::TextColored(kDim, "%s  not played yet", starsText(0).c_str());
        return;
    }
    ImGui::TextColored(kGold, "%s  best %d%s", starsText(r->stars).c_str(), r->bestScore,
                       r->assisted ? "  (assisted)" : "");
}

struct TileView {
    std::string number; ///< "2.3", "" outside the chapters
    game::Lock lock;
    bool next = false;  ///< the next level on the way: highlighted
};

/// One level's tile; true when it was clicked (and may be played).
bool tile(const LevelEntry& e, const TileView& v, const game::Progress& progress,
          LevelThumbnails& pictures, unsigned fbo) {
    const float width = panelPx(kTileWidth);
    const ImVec2 size(width, width * 9.0f / 16.0f);
    const bool open = v.lock.open && e.error.empty();
    bool clicked = false;
    ImGui::BeginGroup();
    ImGui::PushID(e.file.c_str());
    const ImVec2 scale = ImGui::GetIO().DisplayFramebufferScale;
    const TextureTarget* picture =
        e.error.empty() ? pictures.picture(e.file, static_cast<int>(size.x * scale.x),
                                           static_cast<int>(size.y * scale.y), fbo)
                        : nullptr;
    const ImVec4 tint = open ? ImVec4(1, 1, 1, 1) : ImVec4(0.4f, 0.42f, 0.48f, 1);
    if (picture) {
        const auto texture = reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(picture->texture()));
        clicked = ImGui::ImageButton(texture, size, ImVec2(0, 1), ImVec2(1, 0), 2,
                                     ImVec4(0, 0, 0, 0), tint);
    } else {
        clicked = ImGui::Button(e.error.empty() ? "" : "cannot be read", ImVec2(size.x + 4, size.y + 4));
    }
    const bool hovered = ImGui::IsItemHovered();
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    if (v.next) {
        ImDrawList* draw = ImGui::GetWindowDrawList();
        draw->AddRect(lo, hi, ImGui::GetColorU32(kGold), 0.0f, 0, panelPx(3));
        draw->AddRectFilled(ImVec2(lo.x + panelPx(6), lo.y + panelPx(6)),
                            ImVec2(lo.x + panelPx(64), lo.y + panelPx(28)), ImGui::GetColorU32(kGold));
        draw->AddText(ImVec2(lo.x + panelPx(13), lo.y + panelPx(8)), IM_COL32(20, 24, 32, 255), "NEXT");
    }
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
    ImGui::TextColored(open ? ImVec4(1, 1, 1, 1) : kLocked, "%s%s%s", v.number.c_str(),
                       v.number.empty() ? "" : "  ", e.name.c_str());
    if (!e.error.empty())
        ImGui::TextColored(kError, "%s", e.error.c_str());
    else if (!v.lock.open)
        ImGui::TextColored(kLocked, "Locked: %s", v.lock.why.c_str());
    else
        resultLine(e, progress);
    ImGui::PopTextWrapPos();
    ImGui::PopID();
    ImGui::EndGroup();
    if (hovered && e.error.empty() && !e.lesson.empty()) wrappedTooltip(e.lesson);
    return clicked && open;
}

/// The tiles of a page in rows as wide as the window holds.
void tileGrid(const std::vector<LevelEntry>& levels, const std::vector<TileView>& views,
              const game::Progress& progress, LevelThumbnails& pictures, unsigned fbo,
              std::optional<std::size_t>& clicked) {
    const float width = panelPx(kTileWidth) + 2 * ImGui::GetStyle().FramePadding.x;
    const float spacing = ImGui::GetStyle().ItemSpacing.x * 3;
    const int columns = std::max(1, static_cast<int>((ImGui::GetContentRegionAvail().x + spacing) /
                                                     (width + spacing)));
    for (std::size_t i = 0; i < levels.size(); ++i) {
        if (i % static_cast<std::size_t>(columns) != 0) ImGui::SameLine(0.0f, spacing);
        if (tile(levels[i], views[i], progress, pictures, fbo)) clicked = i;
    }
}

// ---- pages ----------------------------------------------------------------------------------
std::size_t pageCount(const CampaignMenu& menu) {
    return menu.chapters.size() + (menu.outside.empty() ? 0 : 1);
}

/// The chapter's heading: its number, title, the stars earned of those there are, its
/// lesson, and why it is locked. True when the lesson was asked for.
bool chapterHeading(const CampaignMenu& menu, std::size_t c, const game::Progress& progress) {
    const game::Chapter& ch = menu.campaign.chapters[c];
    const game::Lock lock = game::chapterLock(menu.campaign, c, progress);
    int practice = 0;
    for (const LevelEntry& e : menu.chapters[c]) practice += e.mode == game::Mode::Practice && e.error.empty();
    ImGui::TextColored(lock.open ? kGold : kLocked, "Chapter %zu of %zu", c + 1, menu.chapters.size());
    ImGui::SameLine();
    ImGui::TextUnformatted(ch.title.c_str());
    ImGui::SameLine();
    ImGui::TextColored(kGold, "\u2605 %d / %d", game::chapterStars(ch, progress), 3 * practice);
    ImGui::SameLine();
    const bool lesson = ImGui::SmallButton("Lesson");
    if (!lock.open) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(kLocked, "Locked: %s", lock.why.c_str());
        ImGui::PopTextWrapPos();
    }
    return lesson;
}

/// The page turners and the heading; the arrow keys turn the pages too.
void pageHeading(const CampaignMenu& menu, const game::Progress& progress, LevelSelectState& state,
                 MenuChoice& choice) {
    const std::size_t pages = pageCount(menu);
    ImGui::BeginDisabled(state.page == 0);
    if (ImGui::ArrowButton("previous", ImGuiDir_Left)) --state.page;
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(state.page + 1 >= pages);
    if (ImGui::ArrowButton("next", ImGuiDir_Right)) ++state.page;
    ImGui::EndDisabled();
    ImGui::SameLine();
    const bool typing = ImGui::GetIO().WantTextInput || ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
    if (!typing && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow)) && state.page > 0) --state.page;
    if (!typing && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow)) && state.page + 1 < pages)
        ++state.page;
    if (state.page < menu.chapters.size()) {
        if (chapterHeading(menu, state.page, progress)) {
            choice.showLesson = state.page;
            choice.lessonThenLevel.clear();
        }
    } else {
        ImGui::TextColored(kGold, "More levels");
        ImGui::SameLine();
        ImGui::TextColored(kDim, "always open");
    }
}

/// The page's tiles: a chapter's levels, or those outside every chapter.
void pageTiles(const CampaignMenu& menu, const game::Progress& progress, const LevelSelectState& state,
               LevelThumbnails& pictures, unsigned fbo, MenuChoice& choice) {
    const auto onTheWay = levelOnTheWay(menu, progress);
    std::optional<std::size_t> clicked;
    if (state.page < menu.chapters.size()) {
        const std::size_t c = state.page;
        const std::vector<LevelEntry>& levels = menu.chapters[c];
        std::vector<TileView> views;
        for (std::size_t l = 0; l < levels.size(); ++l)
            views.push_back({std::to_string(c + 1) + "." + std::to_string(l + 1),
                             game::levelLock(menu.campaign, c, l, progress, levels[l].mode),
                             onTheWay == game::LevelPlace{c, l}});
        tileGrid(levels, views, progress, pictures, fbo, clicked);
        if (clicked) chooseLevel(menu, {c, *clicked}, progress, choice);
        return;
    }
    const std::vector<TileView> views(menu.outside.size());
    tileGrid(menu.outside, views, progress, pictures, fbo, clicked);
    if (clicked) choice.openLevel = menu.outside[*clicked].file;
}

// ---- screen ---------------------------------------------------------------------------------
/// The other screens, each a button; the random map and the editor open a small form.
void otherScreens(const LevelSelectForms& forms, MenuChoice& choice) {
    if (ImGui::Button("Replays")) choice.replays = true;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Watch the games you played, and take one over");
    if (forms.randomMap) {
        ImGui::SameLine();
        if (ImGui::Button("Random map...")) ImGui::OpenPopup("random map");
        if (ImGui::BeginPopup("random map")) {
            randomMapRow(*forms.randomMap, choice);
            ImGui::EndPopup();
        }
    }
    if (forms.editor && forms.levels) {
        ImGui::SameLine();
        if (ImGui::Button("Level editor...")) ImGui::OpenPopup("level editor");
        if (ImGui::BeginPopup("level editor")) {
            levelEditorRow(*forms.editor, *forms.levels, choice);
            ImGui::EndPopup();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Network duel")) choice.networkDuel = true; // ui/net/net_screen.cpp
}

/// The player's choices, help and quit.
void choicesRow(PlayerSettings& settings, MenuChoice& choice) {
    ImGui::PushItemWidth(panelPx(120));
    choice.settingsChanged |= difficultyCombo(settings);
    ImGui::PopItemWidth();
    ImGui::SameLine();
    choice.settingsChanged |= ImGui::Checkbox("hotseat (a duel against a person)", &settings.hotseat);
    ImGui::SameLine();
    if (ImGui::Button("Help (F1)")) choice.help = true;
    ImGui::SameLine();
    if (ImGui::Button("Quit")) choice.quit = true;
}

} // namespace

MenuChoice levelSelectScreen(const CampaignMenu& menu, const game::Progress& progress,
                             PlayerSettings& settings, LevelSelectState& state,
                             LevelThumbnails& pictures, unsigned fbo, const LevelSelectForms& forms) {
    MenuChoice choice;
    // The page where the player left off, when the screen first opens.
    if (!state.opened) {
        if (const auto next = levelOnTheWay(menu, progress)) state.page = next->chapter;
        state.opened = true;
    }
    state.page = std::min(state.page, std::max<std::size_t>(pageCount(menu), 1) - 1);
    const ImVec2 d = ImGui::GetIO().DisplaySize;
    const float margin = panelPx(12);
    const ImVec2 size(std::min(panelPx(1160), d.x - 2 * margin), std::min(panelPx(690), d.y - 2 * margin));
    ImGui::SetNextWindowPos(ImVec2(d.x * 0.5f, d.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(size, ImGuiCond_Always);
    ImGui::Begin("Choose a level", nullptr,
                 ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar);
    ImGui::TextColored(kGold, "ARTILLERY");
    ImGui::SameLine();
    ImGui::TextColored(kDim, "a physics playground: every level shows one idea");
    if (!menu.error.empty()) ImGui::TextColored(kError, "%s", menu.error.c_str());
    for (const std::string& missing : menu.missing) { // a level the campaign names, not there
        ImGui::PushStyleColor(ImGuiCol_Text, kError);
        ImGui::TextWrapped("%s", missing.c_str());
        ImGui::PopStyleColor();
    }
    if (pageCount(menu) == 0) ImGui::TextWrapped("No level files found (looked for levels/*.json).");
    ImGui::Separator();
    if (pageCount(menu) > 0) pageHeading(menu, progress, state, choice);
    const float footer = ImGui::GetFrameHeightWithSpacing() * 2 + ImGui::GetStyle().ItemSpacing.y * 2;
    ImGui::BeginChild("tiles", ImVec2(0, -footer));
    if (pageCount(menu) > 0) pageTiles(menu, progress, state, pictures, fbo, choice);
    ImGui::EndChild();
    ImGui::Separator();
    playNextButton(menu, progress, choice);
    ImGui::SameLine();
    otherScreens(forms, choice);
    choicesRow(settings, choice);
    ImGui::End();
    return choice;
}

} // namespace ui
