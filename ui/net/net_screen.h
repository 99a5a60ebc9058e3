// The network duel in a window: a host/join screen (address, port, level, names), then
// the match drawn with the window's drawing code while a NetDuel runs it in lockstep.
// The local cannon is played as in the game's window (turn_controls.h: drag or arrows
// aim, Space or Enter fires, E ends the turn) or by the computer (--autoplay).
#pragma once

#include "ui/net/net_duel.h"

#include <iosfwd>
#include <optional>
#include <string>

namespace ui::net {

struct NetWindowOptions {
    NetOptions duel;
    bool startNow = false; ///< skip the form (the command line said everything)
    int width = 960, height = 540;
    std::string screenshot;          ///< PNG of the last frame
    std::optional<long long> frames; ///< stop after this many frames
    bool closeWhenOver = false;      ///< leave a few frames after the match ends
    bool personPlays = false;        ///< nobody else could play the cannon without a window
};

/// Runs the window; exit code as the headless verbs (0 match played to the end).
int runNetWindow(const NetWindowOptions& options, std::ostream& out);

} // namespace ui::net
