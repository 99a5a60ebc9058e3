#include "game/cli/verbs.h"

#include "game/files/output_path.h"
#include "game/files/text_file.h"
#include "game/settings.h"
#include "physics/forces.h"

#include <string>

namespace game::cli {

namespace {

/// `run --help`: the options, then every setting a `set` command takes, from the
/// settings table (its data is constant-initialised, so this is safe during kVerbs'
/// initialisation).
const std::string& runUsage() {
    static const std::string usage = std::string(R"(usage: artillery run LEVEL.json [--replay FILE | --commands FILE] [--ticks N]
           [--png DIR --every K | --video FILE [--fps N] [--no-audio]]
           [--size WxH] [--no-hud] [--record FILE] [--audio FILE.wav]
           [--autoplay] [--difficulty easy|normal|hard] [--json]

Plays LEVEL with no window: the commands of a replay or of a commands script are
applied at their ticks (the computer plays its own turns), and the run prints the
events, the score and the final state hash.

  --replay FILE      a recorded game (its level must be LEVEL, same content hash)
  --commands FILE    a JSON list of {"tick": t, "cmd": ...} (README.md, "Game rules";
                     the settings of "set" commands are listed below)
  --ticks N          how many ticks to simulate (default: the replay's length, or until
                     the match is over, at most 60 s after the last command or the
                     computer's last shot)
  --png DIR          write a PNG every K ticks (--every, default 60) into DIR, drawn
                     headlessly with the window's drawing code (OSMesa, or EGL)
  --video FILE       write the run as a video playing at real speed, drawn like --png:
                     FILE.mp4 is H.264 (MPEG-4 part 2 where libavcodec lacks it) with
                     the match's sound in AAC, stereo 48 kHz; FILE.gif has pictures only
  --fps N            the video's frames per second, 1..60 (default 30)
  --no-audio         an MP4 without a sound track
  --size WxH         frame size (default 1280x720; even for MP4); --no-hud leaves the HUD out
  --record FILE      save this run as a replay
  --audio FILE.wav   write the match's sound track, synthesized from its events (the
                     report, the whistle, impacts, blasts, splashes, chimes): 16-bit
                     PCM WAV, stereo 48 kHz, tick t at sample floor(t * 48000 * dt),
                     the same file for the same run
  --autoplay         the computer plays every cannon (at --difficulty)
  --json             {"ticks":n,"final_hash":"hex","score":..,"shots":n,"over":b,
                      "winner":i,"events":[...],"sim_ms":..,"render_ms":..}; each
                     shot's verdict is an event: {"kind":"verdict","tick":t,"player":p,
                     "value":points (0 in a duel),"text":"hit +150"}; with
                     --video also "video":{"file":..,"codec":..,"frames":n,"seconds":..},
                     --audio also "audio":{"file":..,"frames":n,"seconds":..}
                     each event: {"tick","kind","player","where"?,"value","text"?};
                     "fired" also "model": "closed-form" or the integrator that
                     flies the shell ("explicit-euler", ...); "landed" (the shell's
                     first contact; where: its centre) also "closed_form_error_m":
                     how far beyond the exact path's landing on the same surface it
                     landed (m, + long), absent with drag, wind or water

Exit code: 0 ok, 2 bad input (a file to write that cannot be written is refused before
the run: its folder missing, no folder, or taking no new file), 3 a file could not be
written while the run went on (the replay at a turn's end, a frame, the sound, the video).
)") +
        "\nSettings a commands file's {\"cmd\": \"set\", \"name\": .., \"value\": ..} takes:\n" +
        settingsHelp();
    return usage;
}

const Verb kVerbs[] = {
    {"solve", "firing solution: launch angles and flight times to hit a point",
     R"(usage: artillery solve --from X,Y --to X,Y --speed V [--gravity G | --planet NAME] [--json]

Launch angles that take a shell from --from to --to at muzzle speed V under uniform
gravity, with their flight times: none (out of range), one or two, the low (direct)
shot first. Angles are degrees counter-clockwise from +x, so a shot to the left is
above 90.

  --from X,Y      launch point, m
  --to X,Y        target point, m
  --speed V       muzzle speed, m/s (> 0)
  --gravity G     gravity, m/s^2 (default 9.81)
  --planet NAME   earth (9.81), moon (1.62), mars (3.71), jupiter (24.79)
  --json          {"solutions":[{"angle_deg":..,"flight_time_s":..}, ...]}
)",
     {},
     runSolve},
    {"trajectory", "one shot with a chosen integrator against the closed form",
     R"(usage: artillery trajectory --speed V --angle DEG --time T [--from X,Y]
           [--integrator NAME] [--dt S] [--gravity G | --planet NAME]
           [--mass M] [--diameter D] [--cd C] [--air-density R] [--wind VX,VY] [--json]

Simulates one particle launched at V m/s and DEG degrees for T seconds in steps of
dt and prints its state. Without drag or wind it also prints the closed-form state
p0 + v0 t + g t^2/2 and the position error. Any of --diameter, --cd, --air-density or
--wind switches quadratic air drag on (F = 1/2 rho Cd A |v - w| (v - w)).

  --from X,Y        launch point, m (default 0,0)
  --speed V         muzzle speed, m/s
  --angle DEG       launch angle, degrees counter-clockwise from +x
  --time T          simulated time, s (rounded to a whole number of steps)
  --integrator N    explicit-euler, symplectic-euler (euler-cromer), verlet,
                    velocity-verlet (default), leapfrog, midpoint, rk4, implicit-euler
  --dt S            time step, s (default 0.01)
  --gravity G       m/s^2 (default 9.81), or --planet NAME
  --mass M          kg (default 1)
  --diameter D      m (default 0.1)
  --cd C            drag coefficient (default 0.47, a sphere)
  --air-density R   kg/m^3 (default 1.225)
  --wind VX,VY      wind velocity, m/s (default 0,0)
  --json            {"position":[x,y],"velocity":[vx,vy],"steps":n,"time_s":t,
                     "closed_form":{"position":[..],"velocity":[..]}|null,
                     "position_error_m":e|null}
)",
     {},
     runTrajectory},
    {"spring", "a mass on a spring: integrator against the analytic solution",
     R"(usage: artillery spring --k K --mass M --x0 X --time T [--integrator NAME]
           [--dt S] [--damping C] [--json]

Simulates a mass M on a spring of stiffness K (and damping C) released at rest from
X and prints its position, its energy against the initial energy, the analytic
solution of m x'' + c x' + k x = 0 and the error. w dt = sqrt(K/M) dt decides
stability: explicit Euler gains energy at any dt, symplectic Euler and Verlet are
stable below 2, RK4 below 2.83, implicit Euler always.

  --k K           stiffness, N/m (> 0)
  --mass M        kg (> 0)
  --x0 X          initial displacement, m
  --time T        simulated time, s
  --integrator N  as for trajectory (default velocity-verlet)
  --dt S          time step, s (default 0.01)
  --damping C     N s/m (default 0)
  --json          {"position":..,"velocity":..,"energy_j":..,"initial_energy_j":..,
                   "analytic_position":..,"position_error_m":..,"steps":n,"omega_dt":..}
)",
     {},
     runSpring},
    {"drop", "bounce apexes of a dropped ball against e^(2k) H",
     R"(usage: artillery drop --height H (--cor E | --material NAME) [--bounces N]
           [--integrator NAME] [--dt S] [--model particle|rigid] [--discrete]
           [--contact impulse|penalty] [--stiffness F] [--gravity G | --planet NAME]
           [--json]

Drops a ball from rest, its lowest point H above a rigid floor, and reports the apex
of each bounce against e^(2k) H, the height the measured e = sqrt(h/H) predicts (balls
dropped from 92 cm: Claypool, Game Physics, ch. 10). The bounce is resolved at the time
of impact, so with an integrator exact under constant acceleration (velocity-verlet,
midpoint, rk4, leapfrog) the apexes do not depend on dt; explicit and symplectic Euler
show their own (first-order) error.

  --height H      drop height of the ball's lowest point, m (> 0)
  --cor E         coefficient of restitution ball-floor, 0..1 (a pair entry)
  --material N    the ball's material; its restitution against the floor is:
                  golf 0.858, tennis 0.712, billiard 0.804, hand-ball 0.752,
                  wooden 0.603, steel-bearing 0.597, glass-marble 0.658,
                  rubber-band-ball 0.828, hollow-hard-plastic 0.688,
                  perfectly-elastic 1, perfectly-plastic 0, baseball 0.546,
                  earth 0.3, default 0.5
  --bounces N     apexes to report, 1..100 (default 3)
  --integrator N  explicit-euler, symplectic-euler (euler-cromer), verlet,
                  velocity-verlet (default), leapfrog, midpoint, rk4, implicit-euler
  --dt S          time step, s (default 1/120)
  --model M       particle (default), or rigid: the same drop as a Box2D circle on a
                  static floor, to see how close Box2D comes to e^(2k) H
  --discrete      overlap testing with bisection in time instead of continuous
                  (swept-sphere) detection
  --contact M     impulse (default: equation 4 at the time of impact) or penalty
                  (a spring-damper while overlapping: it sinks into the floor, and
                  is unstable once 2 pi f dt > 2)
  --stiffness F   penalty contact stiffness, Hz (default 10)
  --gravity G     m/s^2 (default 9.81), or --planet NAME
  --json          {"bounces":[{"apex_m":..,"expected_apex_m":..,"relative_error":..},
                   ...],"restitution":e,"height_m":H,"integrator":..,"dt_s":..,
                   "continuous":true|false,"came_to_rest":true|false,
                   "contact":"impulse"|"penalty","max_penetration_m":..}

Exit codes: 0 ok, 2 bad input.
)",
     {"discrete"},
     runDrop},
    {"check", "validate level files",
     R"(usage: artillery check LEVEL.json... [--json]

Loads each level file and reports whether it is valid. An invalid file gets one
message naming the file, the JSON path and what was expected, e.g.
  levels/bad.json: $.cannons[0].speed_mps: expected a number in [0, 60] m/s ...
The level format is documented in levels/README.md. A file named campaign.json is
the campaign (levels/campaign.json): its chapters are checked against the levels
folder beside it (every level loads, every level file is in one chapter or outside),
so `artillery check levels/*.json` checks the whole folder.

Exit code: 0 when every file is valid, 1 when any is not, 2 on bad usage.
  --json   {"levels":[{"file":..,"ok":true,"name":..,"mode":..,"content_hash":..}
                      | {"file":..,"ok":false,"path":..,"error":..}],"failed":n}
)",
     {},
     runCheck},
    {"run", "headless simulation of a level: replay or script in, events, hash, PNG frames out",
     runUsage().c_str(),
     {"no-hud", "autoplay", "no-audio"},
     runRun},
    {"replay", "replay verify FILE: re-simulate a replay and compare its checkpoints",
     R"(usage: artillery replay verify FILE [--json]

Re-simulates the recorded game from its level, seed and commands and compares the
state hash at every checkpoint (every 120 ticks by default) and at the end.

A command the match refused as it re-ran them (a weapon the level lacks, a fire out of
turn) changed nothing; each is reported as a warning ("warning: FILE: tick 120: select
'nuke' refused: ..."), which does not change the exit code.

Exit code: 0 when every checkpoint matches, 1 at the first divergent tick (and what
diverged: particles, bodies or game), 2 when the file or its level cannot be read or
the level has changed since the recording.
  --json   {"ok":bool,"ticks":n,"checkpoints":n,"first_divergent_tick":t|null,
            "final_hash":"hex","warnings":[..]}
)",
     {},
     runReplayVerify},
    {"solve-level", "the best game the solver finds on a level: stars, score, shots, commands",
     R"(usage: artillery solve-level LEVEL.json [--json] [--record FILE] [--require-stars N]

Searches aims, powers, weapons and the order of shots through the same simulation
as the game, shot by shot: candidates from the firing solution (both arcs, at speeds
from the least that reaches up) and the computer's trial-shot aim, a coarse grid of
angles and speeds when none scores, then a pattern search that halves its steps.
Prints the best result (stars, score, shots) and the shots that achieve it, with the
level's scoring: the largest score its rules allow (every bonus included) and the least
score of one, two and three stars. A score above that largest is a fault of the rules:
it is said and exits 1.
A duel has no stars: it is checked instead, one shot from each side must be able to
hit the other (the solver's shot at the start, the test `generate` puts its duel maps
to). A sandbox has nothing to solve: it says so and exits 0.

  --json             {"stars":s,"score":n,"max_score":m,"star_scores":[s1,s2,s3],
                      "shots":k,"commands":[...]}
  --record FILE      save the solved game as a replay (replay verify accepts it)
  --require-stars N  exit 1 when a practice level reaches fewer than N stars, or (N >= 1)
                     when a side of a duel cannot hit the other
                     (a duel's --json: {"mode":"duel","hits":[b,b],"playable":b})

Exit code: 0 ok, 1 fewer stars than --require-stars (or a score above the largest),
2 bad input (a --record FILE that cannot be written included), 3 the replay could not
be written after the search.
)",
     {},
     runSolveLevel},
    {"generate", "a level from a seed: same seed, same file; checked playable first",
     R"(usage: artillery generate --seed N --mode practice|duel [--difficulty easy|normal|hard]
                         -o FILE [--json]

Makes a level from a seed: ground from fractal value noise, cannons on flat pads,
targets and block towers (practice) or a second cannon with towers and a rope
between (duel), a wind range and a name with the seed. The same seed, mode and
difficulty give the same bytes on every computer. Before writing, the map is
checked: a practice map must give the solver 3 stars, a duel map must let each
cannon hit the other with one shot; if not, the next candidate derived from the
seed is tried (at most 8), and the output says which candidate it took.

  --seed N           0 .. 9223372036854775807
  --mode M           practice or duel
  --difficulty D     easy, normal (default) or hard: relief, wind, structures
  -o FILE            where to write the level (also --output FILE)
  --json             {"file":..|null,"seed":n,"mode":..,"difficulty":..,"name":..,
                      "candidates":n,"playable":b,"content_hash":"hex",
                      "stars":s | "hits":[b,b]}

Exit code: 0 written, 1 no playable candidate (nothing written), 2 bad input (an output
file that cannot be written is refused before the search), 3 the file could not be
written after it.
)",
     {},
     runGenerate},
};

} // namespace

std::span<const Verb> verbs() { return kVerbs; }

double gravityOption(const Args& args) {
    const bool hasG = args.has("gravity"), hasPlanet = args.has("planet");
    if (hasG && hasPlanet) args.fail("give --gravity or --planet, not both");
    if (hasPlanet) {
        const std::string name = *args.text("planet");
        if (auto g = phys::gravityFromPlanet(name)) return *g;
        args.fail("--planet expects one of earth, moon, mars, jupiter, got '" + name + "'");
    }
    return args.number("gravity", 9.81, 0.0, 1e4, "m/s^2");
}

phys::Integrator integratorOption(const Args& args, phys::Integrator fallback) {
    auto name = args.text("integrator");
    if (!name) return fallback;
    if (auto id = phys::integratorFromName(*name)) return *id;
    args.fail("--integrator expects one of " + phys::integratorNameList() + ", got '" + *name +
              "'");
}

void requireWritableFile(const Args& args, const std::string& option, const std::string& file) {
    if (const std::string why = unwritableFile(file); !why.empty())
        args.refuse("--" + option + ": cannot write '" + printable(file) + "': " + why);
}

void requireWritableFolder(const Args& args, const std::string& option, const std::string& folder,
                           bool create) {
    if (const std::string why = unwritableFolder(folder, create); !why.empty())
        args.refuse("--" + option + ": cannot write into '" + printable(folder) + "': " + why);
}

} // namespace game::cli
