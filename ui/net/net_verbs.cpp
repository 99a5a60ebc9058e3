#include "ui/net/net_verbs.h"

#include "game/files/data_folder.h"
#include "game/cli/verbs.h"
#include "game/replay.h"
#include "ui/net/net_duel.h"
#include "ui/net/net_screen.h"

#include <chrono>
#include <csignal>
#include <iostream>

namespace ui::net {

namespace {

using game::cli::Args;

// Ctrl+C (or a polite kill) in a headless duel: leave it with a goodbye at the next pump
// rather than die and leave the other side waiting for a return.
volatile std::sig_atomic_t gStopRequested = 0;
extern "C" void requestStop(int) {
    gStopRequested = 1;
}

const char* const kHostUsage =
    R"(usage: artillery host [LEVEL] [--port P] [--bind ADDR] [--name NAME]
           [--commands FILE | --autoplay] [--record FILE] [--timeout S] [--wait S]
           [--window] [--json]

Hosts a duel over the network (ENet over UDP): the host plays cannon 0, the player who
joins plays cannon 1, spectators may watch. Lockstep on the command stream: each side
sends only its own commands, and both compare state hashes at every replay checkpoint.
LEVEL is a duel level (default: 10_duel.json of the game's levels). You play it in a
window; with --autoplay or --commands the cannon is played for you, without one unless
--window.

  --port P          UDP port (default 7777; 0 picks a free one, printed)
  --bind ADDR       address to listen on (default 127.0.0.1; 0.0.0.0: every interface)
  --name NAME       your name (at most 24 printable characters; default host)
  --commands FILE   a JSON list of commands for your cannon, applied at their ticks
                    in your turns
  --autoplay        the computer plays your cannon
  --record FILE     save the match as a replay (also when it ends by desync or timeout);
                    a window saves it without: network-last.json in your replays folder
  --timeout S       how long a dropped player may take to come back (default 60 s)
  --wait S          how long to wait for a player to join (default 120 s)
  --window          the window also with --autoplay or --commands. Without LEVEL it
                    opens on the host/join form (the duel map, address, port, names);
                    the match plays as in the game's window (drag or arrows aim, Space
                    or Enter fires, E ends the turn, Tab or 1-8 the shell, P the
                    launch arc). --screenshot F.png (last frame), --frames N,
                    --close-when-over
  --json            {"result":"over|desync|abandoned|refused|failed","message":..,
                     "ticks":n,"final_hash":"hex","winner":i}
  --limit S         stop after S seconds of wall time whatever happens (default 3600)
Test hooks (both verbs): --tamper-at-tick N nudges the first shell in flight from tick N
on (a tampered client), --drop-at-tick N (join) cuts the connection once and reconnects,
--quit-at-tick N vanishes without a goodbye.
Exit: 0 the match was played to the end, 1 it was not (desync, abandoned, refused),
2 bad input (an address --bind cannot take, a --record FILE that cannot be written). The
host drops a connection that says no hello within 5 s, or stays in ENet's handshake for
over 5 s; takes 4 connections from one address and 4 spectators at most; and gives the
joining player's seat a secret token, which a rejoin must present. See docs/network.md.
)";

const char* const kJoinUsage = R"(usage: artillery join HOST[:P] [--name NAME] [--token T] [--spectate]
           [--commands FILE | --autoplay] [--record FILE] [--levels DIR] [--timeout S]
           [--wait S] [--window] [--json]

Joins a duel hosted with `artillery host` and plays cannon 1 in a window (with
--autoplay or --commands without one, unless --window), or watches it with --spectate.
The level is the host's: it is looked up by file name in DIR (default: the game's
levels) and must have the same content hash; the program version must match too.

  HOST[:P]          the host's address and port (default port 7777)
  --name NAME       your name (default guest)
  --token T         the seat token the host gave at your first join (printed then): a
                    new process takes your seat back with it; a name alone does not
  --spectate        watch only (the host's read-only command stream)
  --commands FILE   a JSON list of commands for your cannon, applied at their ticks
                    in your turns
  --autoplay        the computer plays your cannon
  --record FILE     save the match as a replay (a window: network-last.json without it)
  --levels DIR      where to look for the host's level (default: the game's levels)
  --timeout S       how long to keep trying to reconnect after a drop (default 60 s)
  --wait S          how long to wait for the host to answer (default 120 s)
  --window          a window also for --autoplay, --commands or --spectate, as for host
                    (--screenshot, --frames, --close-when-over)
  --json            as for host; --limit S and the test hooks --tamper-at-tick N,
                    --drop-at-tick N and --quit-at-tick N as for host too
Exit: 0 the match was played to the end, 1 it was not, 2 bad input.
)";

/// LEVEL (host) or HOST[:P] (join), and the options both verbs take.
NetOptions readNetOptions(const Args& args, bool host) {
    NetOptions o;
    o.host = host;
    args.text("<positional>"); // LEVEL or HOST[:P]
    const auto& pos = args.positionals();
    if (pos.size() > 1)
        args.fail("takes one " + std::string(host ? "LEVEL" : "HOST[:P]") + ", got " +
                  std::to_string(pos.size()));
    if (host) {
        o.levelFile = pos.empty() ? game::shippedLevel("10_duel.json") : pos[0];
        o.port = static_cast<std::uint16_t>(args.integer("port", kDefaultPort, 0, 65535));
        o.bindAddress = args.text("bind", "127.0.0.1");
    } else {
        if (pos.empty()) args.fail("needs the host's address, HOST[:P]");
        const auto a = parseAddress(pos[0], kDefaultPort);
        if (!a) args.fail("'" + pos[0] + "' is not HOST[:P] with P in 1..65535");
        o.address = a->first;
        o.port = a->second;
        o.spectate = args.flag("spectate");
        o.levelsDir = args.text("levels", game::levelsFolder());
        o.token = args.text("token", "");
        if (!o.token.empty() && (o.token.size() != 16 || o.token.find_first_not_of(
                                                             "0123456789abcdef") != std::string::npos))
            args.fail("--token expects the 16 hex digits the host gave, got '" + o.token + "'");
    }
    o.name = args.text("name", host ? "host" : "guest");
    if (o.name.empty() || o.name.size() > game::net::kMaxNameBytes)
        args.fail("--name expects 1 to 24 printable characters");
    for (char c : o.name)
        if (c < 0x20 || c > 0x7e) args.fail("--name expects printable ASCII characters");
    o.autoplay = args.flag("autoplay");
    o.recordFile = args.text("record", "");
    if (!o.recordFile.empty()) requireWritableFile(args, "record", o.recordFile);
    o.timeoutSeconds = args.number("timeout", 60.0, 0.1, 86400.0, "s");
    o.waitSeconds = args.number("wait", 120.0, 0.1, 86400.0, "s");
    if (args.has("tamper-at-tick"))
        o.tamperTick = static_cast<std::uint64_t>(args.integer("tamper-at-tick", 0, 0, 1'000'000));
    if (args.has("drop-at-tick"))
        o.dropAtTick = static_cast<std::uint64_t>(args.integer("drop-at-tick", 0, 0, 1'000'000));
    if (args.has("quit-at-tick"))
        o.quitAtTick = static_cast<std::uint64_t>(args.integer("quit-at-tick", 0, 0, 1'000'000));
    if (auto file = args.text("commands")) {
        try {
            o.script = game::loadCommands(*file);
        } catch (const std::exception& e) {
            throw game::cli::UsageError(e.what());
        }
    }
    return o;
}

/// The duel without a window, to its end: bounded by every wait inside (each has its
/// own timeout) and by --limit for the whole run. Ctrl+C leaves with a goodbye.
int playHeadless(NetDuel& duel, const NetOptions& o, double limitSeconds, std::ostream& log) {
    const auto started = std::chrono::steady_clock::now();
    auto printLog = [&] {
        for (const std::string& line : duel.takeLog())
            log << line << std::endl;
    };
    printLog();
    gStopRequested = 0;
    std::signal(SIGINT, requestStop);
    std::signal(SIGTERM, requestStop);
    int code = game::cli::kOk;
    while (duel.pump(5, 240)) {
        printLog();
        if (gStopRequested) {
            duel.leave(o.name + " stopped");
            printLog();
            break;
        }
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >
            limitSeconds) {
            duel.leave(o.name + " stopped after --limit " +
                       std::to_string(static_cast<int>(limitSeconds)) + " s");
            log << "stopped after --limit " << limitSeconds << " s\n";
            code = game::cli::kCheckFailed;
            break;
        }
    }
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    printLog();
    if (code != game::cli::kOk) return code;
    return duel.result() == NetResult::Over ? game::cli::kOk : game::cli::kCheckFailed;
}

void printResultJson(const NetDuel& duel, std::ostream& out) {
    const auto* ls = duel.lockstep();
    std::string msg;
    for (char c : duel.message())
        msg += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
    out << "{\"result\":\"" << netResultName(duel.result()) << "\",\"message\":\"" << msg
        << "\",\"ticks\":" << (ls ? ls->match().tick() : 0) << ",\"final_hash\":\""
        << (ls ? game::hex(ls->match().hash()) : "")
        << "\",\"winner\":" << (ls ? ls->match().winner() : -1) << "}\n";
}

int runNet(const Args& args, std::ostream& out, bool host) {
    const NetOptions o = readNetOptions(args, host);
    const bool json = args.flag("json");
    const double limitSeconds = args.number("limit", 3600.0, 1.0, 86400.0, "s");
    // A person plays in a window; only the computer, a script or a spectator plays
    // without one.
    const bool player = !o.autoplay && !args.has("commands") && !o.spectate;
    const bool window = args.flag("window") || player;
    NetWindowOptions wo;
    if (window) {
        wo.screenshot = args.text("screenshot", "");
        if (args.has("frames")) wo.frames = args.integer("frames", 0, 1, 100'000'000);
        wo.closeWhenOver = args.flag("close-when-over");
    }
    args.rejectUnknown();
    if (o.autoplay && !o.script.empty()) args.fail("takes --commands or --autoplay, not both");
    if (window) {
        wo.duel = o;
        wo.personPlays = player;
        // The form is for choosing: a level or an address on the command line (or a
        // player other than you) has chosen already.
        wo.startNow = o.autoplay || o.spectate || args.has("commands") || !args.positionals().empty();
        return runNetWindow(wo, out);
    }
    NetDuel duel(o);
    std::string why;
    if (!duel.start(why)) {
        std::cerr << "artillery " << (host ? "host" : "join") << ": " << why << "\n";
        return game::cli::kBadInput;
    }
    const int code = playHeadless(duel, o, limitSeconds, json ? std::cerr : out);
    if (json) printResultJson(duel, out);
    return code;
}

int runHost(const Args& args, std::ostream& out) {
    return runNet(args, out, true);
}
int runJoin(const Args& args, std::ostream& out) {
    return runNet(args, out, false);
}

} // namespace

const game::cli::Verb& hostVerb() {
    static const game::cli::Verb v{"host",
                                   "host a duel over the network (lockstep on commands)",
                                   kHostUsage,
                                   {"autoplay", "window", "close-when-over"},
                                   runHost};
    return v;
}

const game::cli::Verb& joinVerb() {
    static const game::cli::Verb v{"join",
                                   "join or watch a networked duel",
                                   kJoinUsage,
                                   {"autoplay", "spectate", "window", "close-when-over"},
                                   runJoin};
    return v;
}

} // namespace ui::net
