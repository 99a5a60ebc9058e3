#include "ui/game/menu_flow.h"

#include "game/weapon_text.h"

#include <algorithm>

namespace ui {

MenuFlow::MenuFlow(const std::string& levelsFolder)
    : levels_(listLevels(levelsFolder)), campaign_(campaignMenu(levelsFolder, levels_)) {}

std::string MenuFlow::weaponIntroduction(const std::string& levelFile) const {
    std::vector<std::string> met; // the weapons the levels before it offer, in play order
    for (const std::vector<LevelEntry>& chapter : campaign_.chapters)
        for (const LevelEntry& e : chapter) {
            if (e.file == levelFile) {
                for (const std::string& w : e.weapons)
                    if (std::find(met.begin(), met.end(), w) == met.end()) return game::weaponIntroduction(w);
                return "";
            }
            met.insert(met.end(), e.weapons.begin(), e.weapons.end());
        }
    return "";
}

void MenuFlow::drawHelp() {
    if (helpOpen_) helpOverlay(helpOpen_);
}

void MenuFlow::showReplays(const std::string& folder) {
    replays_ = listReplays(folder);
    overlay_ = Overlay::Replays;
}

MenuChoice MenuFlow::draw(const game::Progress& progress, PlayerSettings& settings,
                          const std::string& replaysFolder, const std::string& silentWhy,
                          const std::string& editing, const game::Match* match,
                          RewindControl& rewind, unsigned fbo) {
    MenuChoice choice;
    editorForm_.editing = editing;
    if (overlay_ == Overlay::LevelSelect)
        choice = levelSelectScreen(campaign_, progress, settings, page_, pictures_, fbo,
                                   {&randomMap_, &editorForm_, &levels_});
    if (overlay_ == Overlay::Lesson)
        choice = lessonScreen(campaign_.campaign, lessonChapter_, lessonThenLevel_,
                              {campaign_.campaign.chapters.at(lessonChapter_).picture,
                               &lessonPictures_, fbo});
    if (overlay_ == Overlay::Replays) choice = replaysScreen(replays_, replaysFolder);
    if (overlay_ == Overlay::Pause) choice = pauseMenu(settings, silentWhy, match, rewind);
    drawHelp();
    return choice;
}

MenuChoice MenuFlow::nextLevelCard(const game::Progress& progress, const std::string& levelFile,
                                   ImVec2 corner) const {
    return ui::nextLevelCard(campaign_, progress, levelFile, corner);
}

bool MenuFlow::follow(const MenuChoice& choice, game::Progress& progress,
                      const std::string& replaysFolder) {
    const bool lessonRead = choice.lessonSeen && progress.lessonsSeen.insert(*choice.lessonSeen).second;
    if (choice.showLesson) {
        lessonChapter_ = *choice.showLesson;
        lessonThenLevel_ = choice.lessonThenLevel;
        overlay_ = Overlay::Lesson;
    }
    if (choice.replays) showReplays(replaysFolder);
    if (choice.resume) overlay_ = Overlay::None;
    if (choice.levelSelect) overlay_ = Overlay::LevelSelect;
    if (choice.help) helpOpen_ = true;
    return lessonRead;
}

void MenuFlow::showBackdrop() {
    overlay_ = Overlay::LevelSelect;
    for (const LevelEntry& e : levels_) {
        if (!e.error.empty()) continue;
        backdrop_ = std::make_unique<game::Match>(game::loadLevel(e.file));
        break;
    }
}

} // namespace ui
