#!/usr/bin/env bash
# The docs' pictures of the game's screens, drawn by the game itself:
#   docs/screenshots.sh [BUILD]      (make screenshots runs it; BUILD defaults to build)
# Screens a level opens on are drawn headless (`play --headless --screenshot`); the
# lesson screen is reached as a player reaches it, so that one runs the real window on a
# virtual display (Xvfb), clicks the chapter's Lesson button with xdotool and grabs the
# screen with ImageMagick's import. Progress and settings go to a scratch folder.
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${1:-build}/artillery
[ -x "$exe" ] || { echo "screenshots.sh: no executable at $exe (build first)" >&2; exit 2; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"; [ -n "${xvfb:-}" ] && kill "$xvfb" 2>/dev/null || true' EXIT
export XDG_CONFIG_HOME=$scratch/config

shot() { # LEVEL-OR-EMPTY PNG [play options...]
  local level=$1 png=$2; shift 2
  "$exe" play $level --headless --frames 3 --progress "$scratch/progress.json" "$@" \
    --screenshot "$png" >/dev/null
  echo "drew $png"
}
shot "" docs/level_select.png
shot levels/40_scatter.json docs/weapon_level.png
shot levels/01_earth_basics.json docs/scoring_hud.png
shot levels/37_castle_duel.json docs/castle_duel.png --warmup 6

# The lab: explicit Euler at 30 Hz on First shot, recorded and watched as a replay 150
# ticks of 120 Hz in (5 s of the match's 30 Hz, after the landing): the exact path beside
# the trail and the verdict that carries the comparison.
"$exe" run levels/12_first_shot.json --commands tests/data/first_shot_euler_30hz.json \
  --ticks 400 --record "$scratch/euler.replay.json" >/dev/null
"$exe" play --replay "$scratch/euler.replay.json" --headless --warmup 1.25 --frames 3 \
  --screenshot docs/lab_exact_path.png >/dev/null
echo "drew docs/lab_exact_path.png"

# The lesson screen: the first chapter's Lesson button, on the level select.
for tool in Xvfb xdotool import; do
  command -v "$tool" >/dev/null || { echo "screenshots.sh: $tool is missing (apt-get install xvfb xdotool imagemagick)" >&2; exit 2; }
done
display=:$((90 + RANDOM % 100))
Xvfb "$display" -screen 0 1280x720x24 >/dev/null 2>&1 &
xvfb=$!
sleep 1
DISPLAY=$display "$exe" play --progress "$scratch/progress.json" --frames 400 >/dev/null 2>&1 &
game=$!
sleep 3
DISPLAY=$display xdotool mousemove 461 62 click 1
sleep 1.5
DISPLAY=$display import -window root docs/lesson.png
echo "drew docs/lesson.png"
kill "$game" 2>/dev/null || true

# The end card: Earth basics as the computer played it (its golden replay), watched to
# just past the match's end (tick 2779 of 120 Hz) and taken over with T, as a player
# takes over a replay; the card stands once the camera is home.
DISPLAY=$display "$exe" play --replay tests/replays/01_earth_basics.replay.json --warmup 23.7 \
  --frames 900 >/dev/null 2>&1 &
game=$!
sleep 4
DISPLAY=$display xdotool key t
sleep 3
DISPLAY=$display import -window root docs/end_card.png
echo "drew docs/end_card.png"
kill "$game" 2>/dev/null || true

# Compare in one key: X on First shot (no air) and on Air drag, the paths, their legend
# and the shot's work-precision chart.
compare() { # LEVEL PNG
  DISPLAY=$display "$exe" play "$1" --progress "$scratch/progress.json" --frames 600 >/dev/null 2>&1 &
  game=$!
  sleep 3
  DISPLAY=$display xdotool key x
  sleep 1.5
  DISPLAY=$display import -window root "$2"
  echo "drew $2"
  kill "$game" 2>/dev/null || true
}
compare levels/12_first_shot.json docs/lab_compare.png
compare levels/18_air_drag.json docs/lab_compare_drag.png
