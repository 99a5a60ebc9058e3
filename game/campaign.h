// The campaign: the shipped levels in chapters, from the closed-form parabola to stiff
// springs, each chapter opening with a short lesson, its formula and a picture of the idea. Read from levels/campaign.json
// (format in levels/README.md) strictly: every error names the file, the JSON path and
// what was expected, and a campaign is loaded whole or not at all.
//
// Unlocking, as a player of Angry Birds expects: inside a chapter, level k+1 opens once
// level k is cleared (one star, or a won duel); a chapter opens once the chapter before
// it has earned `starsToOpen` stars in all, and then its first level is open. A duel is
// open from the start wherever it stands, as the maps of a versus mode are.
#pragma once

#include "game/level.h"
#include "game/progress.h"

#include <cstddef>
#include <map>
#include <set>
#include <optional>
#include <string>
#include <vector>

namespace game {

struct Chapter {
    std::string id;      ///< short name, unique in the campaign ("drag")
    std::string title;   ///< shown as the chapter's heading
    std::string lesson;  ///< the lesson shown before its first level (<= 400 characters)
    std::string formula; ///< the formula the lesson is about, in real symbols (θ, √, ²)
    std::string picture; ///< the picture of the idea the lesson screen draws (lessonPictures)
    /// Stars the previous chapter must have earned for this one to open (0 for the first).
    int starsToOpen = 0;
    std::vector<std::string> levels; ///< level file names in the levels folder, in order
};

struct Campaign {
    std::string file;
    std::vector<Chapter> chapters;
    /// Shipped levels deliberately outside every chapter (the sandbox), always open.
    std::vector<std::string> outside;
    /// The chapters' level files that the folder lacks or that do not load, by file name,
    /// with why (from missingLevels): they cannot be played, so they lock nothing.
    std::map<std::string, std::string> missing;
    /// The chapters' level files that are duels (won, not starred), by file name, so a
    /// lock names what clears the level before it.
    std::set<std::string> duels;
};

/// A level a chapter names that cannot be played: no such file in the levels folder, or
/// a file that does not load. The campaign is still played (`check` refuses it), and
/// the level select says which level is missing and why.
struct MissingLevel {
    std::size_t chapter = 0, level = 0;
    std::string file; ///< the name the chapter gives
    std::string why;  ///< "no such level file in levels", or the loader's message
};
/// The chapters' levels that `levelsFolder` lacks or cannot load, in play order.
std::vector<MissingLevel> missingLevels(const Campaign& campaign, const std::string& levelsFolder);
/// One line for the level select: "levels/campaign.json: $.chapters[0].levels[2]: names
/// 03_gone.json, which cannot be played (no such level file in levels): the levels after
/// it open without it".
std::string describe(const Campaign& campaign, const MissingLevel& missing);
/// A picture the lesson screen draws for a chapter: its name in campaign.json and what
/// it shows.
struct LessonPicture {
    const char* name;
    const char* shows;
};
/// Every picture a chapter may name, in campaign order.
const std::vector<LessonPicture>& lessonPictures();

/// Parses a campaign strictly; throws LoadError (file, JSON path, what was expected).
Campaign parseCampaign(const std::string& file, const std::string& text);
Campaign loadCampaign(const std::string& file);

/// What is wrong with a campaign against the levels folder beside it: a chapter's level
/// that does not exist or does not load, a *.json in the folder that is in no chapter and
/// not listed as outside, a chapter asking for more stars than the one before it can give.
/// One message per problem, each naming the file and the JSON path; empty when sound.
std::vector<std::string> campaignProblems(const Campaign& campaign,
                                          const std::string& levelsFolder);

/// Where a level is in the campaign: chapter and level index.
struct LevelPlace {
    std::size_t chapter = 0, level = 0;
    bool operator==(const LevelPlace&) const = default;
};
/// The level file's place (matched by file name), if it is in a chapter.
std::optional<LevelPlace> findLevel(const Campaign& campaign, const std::string& levelFile);
/// The level after it in play order (the next chapter's first after a chapter's last);
/// none after the last level or for a level outside the chapters.
std::optional<LevelPlace> nextLevel(const Campaign& campaign, const std::string& levelFile);

/// Stars earned in a chapter (duels earn none).
int chapterStars(const Chapter& chapter, const Progress& progress);
/// A level counts as cleared with at least one star, or a duel once won.
bool cleared(const Progress& progress, const std::string& levelFile);

/// Whether something is open, and if not, what the player must do ("" when open). A
/// level in campaign.missing is passed over: the level after it opens as if it were
/// cleared, and the stars it could have given are not asked of its chapter.
struct Lock {
    bool open = true;
    std::string why;
};
Lock chapterLock(const Campaign& campaign, std::size_t chapter, const Progress& progress);
Lock levelLock(const Campaign& campaign, std::size_t chapter, std::size_t level,
               const Progress& progress);
/// The same for a level of `mode`: a duel is open from the start, so a person can take
/// any duel map against a friend or the computer at once (it still counts as cleared only
/// once won); any other level is open as levelLock says.
Lock levelLock(const Campaign& campaign, std::size_t chapter, std::size_t level,
               const Progress& progress, Mode mode);

} // namespace game
