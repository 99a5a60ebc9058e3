// The player's progress through the levels: the best result of each level and the
// chapter lessons already read. Kept as its own file (progress.json) in the player's
// settings folder, written atomically (temp file + rename). A damaged file is kept aside
// as FILE.damaged, the game starts from no progress and says so once. Two windows of the
// game share the file: each saves what it added merged into what the other saved, under
// a lock, so neither loses the other's results.
#pragma once

#include <map>
#include <set>
#include <string>

namespace game {

struct LevelResult {
    int bestScore = 0;
    int stars = 0;    ///< 0..3
    int plays = 0;    ///< matches finished
    bool won = false; ///< duel: beaten at least once
    /// The best stars so far came only with a learning aid (full preview or hint) in
    /// view, so they are at most two; the level select says so.
    bool assisted = false;
};

struct Progress {
    /// By level file name (not path), so results survive moving the folder.
    std::map<std::string, LevelResult> results;
    /// Chapter ids whose lesson the player has seen (shown once before the first level).
    std::set<std::string> lessonsSeen;

    /// Records a finished match; returns true when it beat the stored best (as many stars
    /// without an aid as before with one counts) and earned something: a star or a win.
    bool record(const std::string& levelFile, int score, int stars, bool won,
                bool assisted = false);
    const LevelResult* result(const std::string& levelFile) const;
};

/// Takes the results `older` holds (an older settings file's, by level file name) for
/// the levels `progress` has none of; returns whether any were taken.
bool adoptOlderResults(Progress& progress, const std::map<std::string, LevelResult>& older);

/// Parses a progress file strictly; throws LoadError naming the file, the JSON path and
/// what was expected.
Progress parseProgress(const std::string& file, const std::string& text);
/// Reads progress; a missing file gives no progress. A damaged one is renamed to
/// FILE.damaged (kept for the player to look at), no progress is returned and `warning`
/// says what was wrong and where the file went; else `warning` is empty.
Progress loadProgress(const std::string& file, std::string& warning);
/// Writes atomically (temp file + rename), creating the folder. Returns "" or why it failed.
std::string saveProgress(const std::string& file, const Progress& progress);

/// Two results of one level as one: the best score and stars, won if either was, and
/// assisted only when every result at the best stars was (the stars of an unassisted
/// game are not taken back by an assisted one), and the larger count of plays (a merge
/// counts them itself: mergeProgress).
LevelResult bestOf(const LevelResult& a, const LevelResult& b);
/// What a run added (`mine`, against `base`: the progress as the run last read or wrote
/// it) merged into the progress another window left in the file meanwhile (`onDisk`):
/// per level the best result, and the plays of the file plus this run's new ones; the
/// lessons either has seen.
Progress mergeProgress(const Progress& onDisk, const Progress& base, const Progress& mine);
/// Saves a run's progress beside other windows': under an advisory lock on FILE.lock
/// (game/files/file_lock.h) it reads the file again, merges (mergeProgress) and writes
/// atomically. On success `base` and `mine` both become the merged whole, so results
/// another window saved show here too. Returns "" or why nothing was saved; `warning`
/// says when the file had been damaged meanwhile (it is kept aside, as loadProgress does).
std::string saveProgressMerged(const std::string& file, Progress& base, Progress& mine,
                               std::string& warning);

} // namespace game
