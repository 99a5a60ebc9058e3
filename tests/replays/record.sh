#!/usr/bin/env bash
# Records golden replays: one real game per level, which CTest re-simulates and compares
# checkpoint by checkpoint (every tests/replays/*.replay.json; tests/replays/CMakeLists.txt).
#
#   tests/replays/record.sh              re-record the goldens there are
#   tests/replays/record.sh --all        record a golden for every shipped level
#   tests/replays/record.sh LEVEL...     record these (paths from the repository root,
#                                        e.g. levels/20_skip_shot.json)
#   --out DIR                            write them to DIR instead of tests/replays
#                                        (to look before replacing anything)
#
# How a level is played is decided by its mode (as `artillery check` reads it):
#   practice  the solver's best game on it (solve-level LEVEL --record): the shots that
#             score the most, bank shots included, where the computer player would aim
#             at the targets directly and miss a skip shot;
#   duel      the computer against itself at hard difficulty for 40 simulated seconds
#             (run --autoplay --record);
#   sandbox   a hand-written command script (nothing there for the computer to aim at):
#             tests/replays/NAME.commands.json, else tests/replays/sandbox_script.json.
# Run after a deliberate change of the rules or the physics, check in the listing that
# each game still does something (its ticks, its final hash), and commit the new files
# with the reason for the change. Each line gives the seconds the recording took.
set -euo pipefail
cd "$(dirname "$0")/../.."
exe=${ARTILLERY:-build/artillery}
out=tests/replays
levels=()
all=false
while [ $# -gt 0 ]; do
  case $1 in
    --all) all=true ;;
    --out) out=${2:?--out needs a folder}; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    -*) echo "record.sh: unknown option '$1' (--all, --out DIR, LEVEL...)" >&2; exit 2 ;;
    *) levels+=("$1") ;;
  esac
  shift
done
if $all; then
  for level in levels/*.json; do
    [ "$(basename "$level")" = campaign.json ] || levels+=("$level")
  done
elif [ ${#levels[@]} -eq 0 ]; then
  for golden in tests/replays/*.replay.json; do
    levels+=("levels/$(basename "$golden" .replay.json).json")
  done
fi
[ -x "$exe" ] || { echo "record.sh: no executable at $exe (build first, or set ARTILLERY)" >&2; exit 2; }
mkdir -p "$out"

# The mode of a level: practice, duel or sandbox.
mode_of() {
  "$exe" check "$1" --json | grep -o '"mode":"[a-z]*"' | cut -d'"' -f4
}
# Tenths of a second since $1 (date +%s%N).
tenths_since() { echo $(( ($(date +%s%N) - $1) / 100000000 )); }

total_start=$(date +%s%N)
for level in "${levels[@]}"; do
  name=$(basename "$level" .json)
  golden="$out/$name.replay.json"
  mode=$(mode_of "$level") || { echo "record.sh: $level does not load (artillery check $level)" >&2; exit 1; }
  start=$(date +%s%N)
  case $mode in
    practice)
      how=solver
      "$exe" solve-level "$level" --record "$golden" > /dev/null ;;
    duel)
      how=autoplay
      "$exe" run "$level" --autoplay --difficulty hard --ticks 4800 --record "$golden" > /dev/null ;;
    sandbox)
      how=script
      script=tests/replays/$name.commands.json
      [ -f "$script" ] || script=tests/replays/sandbox_script.json
      "$exe" run "$level" --commands "$script" --ticks 4800 --record "$golden" > /dev/null ;;
    *)
      echo "record.sh: $level has mode '$mode', which this script cannot play" >&2
      exit 1 ;;
  esac
  t=$(tenths_since "$start")
  result=$("$exe" replay verify "$golden" --json)
  printf '%-22s %-8s %4d.%d s  %s\n' "$name" "$how" $((t / 10)) $((t % 10)) "$result"
done
t=$(tenths_since "$total_start")
printf 'recorded %d golden replay(s) in %d.%d s\n' "${#levels[@]}" $((t / 10)) $((t % 10))
