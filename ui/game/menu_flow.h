// The game screen's menus: which one is open (level select, a chapter's lesson, the
// recorded replays, the pause menu) and the help over them, the lists they show, and the
// first level's landscape behind the level select before any game starts. draw() draws
// the open one and returns what the player chose; follow() carries out the choices that
// only move between menus, and the game screen the rest (open a level, a replay, the
// editor, quit).
#pragma once

#include "game/match.h"
#include "game/progress.h"
#include "ui/game/campaign_view.h"
#include "ui/game/game_menus.h"
#include "ui/game/level_select.h"
#include "ui/game/lesson_pictures.h"
#include "ui/game/level_thumbnails.h"
#include "ui/game/player_settings.h"

#include <memory>
#include <string>
#include <vector>

namespace ui {

class MenuFlow {
  public:
    /// The levels in `levelsFolder` and its campaign.
    explicit MenuFlow(const std::string& levelsFolder);

    Overlay overlay() const { return overlay_; }
    void open(Overlay overlay) { overlay_ = overlay; }
    void close() { overlay_ = Overlay::None; }
    /// A menu or the help is open: the match waits.
    bool holdsTheGame() const { return overlay_ != Overlay::None || helpOpen_; }
    bool helpOpen() const { return helpOpen_; }
    void toggleHelp() { helpOpen_ = !helpOpen_; }
    void closeHelp() { helpOpen_ = false; }
    /// The help alone (the editor's screen has no other menu).
    void drawHelp();

    /// The replays recorded in `folder`, listed.
    void showReplays(const std::string& folder);

    /// Draws the open menu and the help; what the player chose this frame. `editing` names
    /// the level the editor holds ("" none); `silentWhy` why the game plays silent; `match`
    /// the match played (the pause menu rewinds it with `rewind`), null for none; `fbo` the
    /// framebuffer being drawn (the level select's pictures are drawn, then it is bound again).
    MenuChoice draw(const game::Progress& progress, PlayerSettings& settings,
                    const std::string& replaysFolder, const std::string& silentWhy,
                    const std::string& editing, const game::Match* match, RewindControl& rewind,
                    unsigned fbo);
    /// The card at a finished level's end: the next level on the way, again, the select.
    MenuChoice nextLevelCard(const game::Progress& progress, const std::string& levelFile,
                             ImVec2 corner) const;
    /// Carries out the choices that only move between menus (a lesson, the replays, back,
    /// help). True when a lesson read for the first time went into `progress` (save it).
    bool follow(const MenuChoice& choice, game::Progress& progress, const std::string& replaysFolder);

    /// The one line that introduces the weapon `levelFile` is the first of the campaign's
    /// levels to offer ("New: the grenade bounces ..."), "" when it offers none first.
    std::string weaponIntroduction(const std::string& levelFile) const;

    /// The first level that loads, drawn behind the level select (none once a game starts).
    void showBackdrop();
    const game::Match* backdrop() const { return backdrop_.get(); }
    void dropBackdrop() { backdrop_.reset(); }

    RandomMapForm& randomMap() { return randomMap_; }

  private:
    Overlay overlay_ = Overlay::None;
    bool helpOpen_ = false;
    std::vector<LevelEntry> levels_;
    /// The levels in their chapters, and what the player has earned ("" file: not kept).
    CampaignMenu campaign_;
    std::vector<ReplayEntry> replays_;
    /// The lesson on screen (Overlay::Lesson) and the level its Play button opens.
    std::size_t lessonChapter_ = 0;
    std::string lessonThenLevel_;
    RandomMapForm randomMap_;      ///< the level select's Random map row
    LevelEditorForm editorForm_;   ///< the level select's Level editor row
    LevelSelectState page_;        ///< the level select's page
    LevelThumbnails pictures_;     ///< the level select's pictures of the levels
    LessonPictures lessonPictures_; ///< the lessons' pictures
    std::unique_ptr<game::Match> backdrop_;
};

} // namespace ui
