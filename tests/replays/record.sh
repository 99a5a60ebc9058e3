#!/usr/bin/env bash
# Re-records the golden replays: the computer plays every cannon of every shipped level
# (hard difficulty) for 40 simulated seconds. Run from the repository root after a
# deliberate physics change, check that each game still hits something, and commit the
# new files with the reason for the change.
set -euo pipefail
cd "$(dirname "$0")/../.."
exe=${ARTILLERY:-build/artillery}
for level in levels/*.json; do
  name=$(basename "$level" .json)
  if [ "$name" = 11_sandbox ]; then
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
