// The campaign on the level select screen: each chapter's heading with its lesson button
// and stars, its levels with the stars earned (greyed with the reason while locked), and
// the one-screen lesson shown before a chapter's first level. What opens is decided by
// game/campaign.h; this file only draws it and reports the player's choice.
#pragma once

#include "game/campaign.h"
#include "game/progress.h"
#include "ui/game/game_menus.h"

#include <cstddef>
#include <string>
#include <vector>

namespace ui {

/// The levels folder as the select screen shows it: the campaign's chapters with their
/// level entries, and the levels outside every chapter (all of them when the folder has
/// no campaign.json).
struct CampaignMenu {
    game::Campaign campaign;
    std::vector<std::vector<LevelEntry>> chapters; ///< entries of each chapter, in order
    std::vector<LevelEntry> outside;               ///< the sandbox, and unlisted files
    std::string error; ///< why campaign.json did not load ("" when it did or is absent)
    /// Each level a chapter names that cannot be played, said (game::describe): the
    /// levels after it open without it.
    std::vector<std::string> missing;
};

/// Sorts `levels` (listLevels of `folder`) into the chapters of `folder`/campaign.json.
CampaignMenu campaignMenu(const std::string& folder, const std::vector<LevelEntry>& levels);

/// The next level on the way through the campaign: the first open practice level not
/// cleared yet, where the player left off (the duels, always open, are not the way);
/// none when every one is cleared or the campaign is empty.
std::optional<game::LevelPlace> levelOnTheWay(const CampaignMenu& menu,
                                              const game::Progress& progress);
/// Opens the level at `place` as a click on its row does: its chapter's lesson first,
/// the first time.
void chooseLevel(const CampaignMenu& menu, game::LevelPlace place, const game::Progress& progress,
                 MenuChoice& choice);
/// The level select's "Play next" button (and Enter): levelOnTheWay, chosen.
void playNextButton(const CampaignMenu& menu, const game::Progress& progress, MenuChoice& choice);

/// When a match of `levelFile` is over: a small card with the campaign's next level, its
/// button (the lesson first when its chapter starts and was not read) or why it is locked.
/// Draws nothing for a level outside the chapters or the last one. Its top-left corner
/// is at `corner` (window points).
MenuChoice nextLevelCard(const CampaignMenu& menu, const game::Progress& progress,
                         const std::string& levelFile, ImVec2 corner);

class LessonPictures;

/// What a lesson is drawn with: its picture's name ("" none), the pictures, and the
/// framebuffer bound again once one is drawn.
struct LessonArt {
    std::string picture;
    LessonPictures* pictures = nullptr;
    unsigned fbo = 0;
};

/// One chapter's lesson on a screen of its own: its picture, the formula large, the
/// lesson in a few sentences. `thenLevel` is the level the player picked ("" when the
/// lesson was opened on its own): the button plays it.
MenuChoice lessonScreen(const game::Campaign& campaign, std::size_t chapter,
                        const std::string& thenLevel, const LessonArt& art = {});

} // namespace ui
