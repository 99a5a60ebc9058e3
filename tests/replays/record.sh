#!/usr/bin/env bash
# Re-records the golden replays: the computer plays every cannon of each level that has
# one (hard difficulty) for 40 simulated seconds; levels named as arguments (paths from
# the repository root, e.g. levels/20_skip_shot.json) get one too. Run after a deliberate
# physics change, check that each game still hits something, and commit the new files
# with the reason for the change.
set -euo pipefail
cd "$(dirname "$0")/../.."
exe=${ARTILLERY:-build/artillery}
levels=("$@")
for golden in tests/replays/*.replay.json; do
  levels+=("levels/$(basename "$golden" .replay.json).json")
done
for level in "${levels[@]}"; do
  name=$(basename "$level" .json)
  if [ "$name" = 20_skip_shot ] || [ "$name" = 28_stiff_jelly ]; then
    # The solver's game: the bank shot and the stiff blob it knocks off (the computer
    # aims at targets directly and would miss the skip shot).
    "$exe" solve-level "$level" --record "tests/replays/$name.replay.json" > /dev/null
  elif [ "$name" = 11_sandbox ]; then
    # The sandbox has nothing for the computer to aim at: a hand-written script.
    "$exe" run "$level" --commands tests/replays/sandbox_script.json --ticks 4800 \
           --record "tests/replays/$name.replay.json" > /dev/null
  else
    "$exe" run "$level" --autoplay --difficulty hard --ticks 4800 \
           --record "tests/replays/$name.replay.json" > /dev/null
  fi
  hits=$("$exe" replay verify "tests/replays/$name.replay.json" --json)
  echo "$name: $hits"
done
