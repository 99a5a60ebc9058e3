#!/bin/bash
# Every verb, driven with inputs that throw: outputs that cannot be written (a missing
# folder, a path through a regular file, /proc, a folder where a file goes: all refuse
# root too, and CI runs as root), numbers at their documented limits, and a file size
# limit that makes a write fail during the work. Each must end with one line and its
# documented exit code (2 refused before any work, 3 failed during it), never a signal.
#   no_abort.sh EXE SOURCE_DIR WORK_DIR
set -u
EXE=$1 SRC=$2 WORK=$3
rm -rf "$WORK" && mkdir -p "$WORK/dir" && cd "$WORK" || exit 2
LEVEL=$SRC/levels/01_earth_basics.json
DUEL=$SRC/levels/10_duel.json
echo "a plain file" > plain.txt
failures=0

# expect CODE PATTERN -- ARGS...: the exit code, and a line of stderr+stdout matching
# PATTERN (extended regex). A signal (exit above 128) always fails.
expect() {
    local code=$1 pattern=$2; shift 3
    "$EXE" "$@" > out.log 2>&1
    local rc=$?
    if [ $rc -gt 128 ]; then
        echo "FAIL: artillery $* died of signal $((rc - 128))"; cat out.log; failures=$((failures + 1))
    elif [ $rc != "$code" ]; then
        echo "FAIL: artillery $* exited $rc, expected $code"; cat out.log; failures=$((failures + 1))
    elif ! grep -Eq -- "$pattern" out.log; then
        echo "FAIL: artillery $*: no line matches '$pattern'"; cat out.log; failures=$((failures + 1))
    else
        echo "ok ($rc): artillery $*"
    fi
}

# --- outputs refused before the work (exit 2), naming the path and the reason ---------
expect 2 "^artillery run: --record: cannot write '/nonexistent/dir/x.json': the folder '/nonexistent/dir' does not exist" -- \
    run "$LEVEL" --autoplay --record /nonexistent/dir/x.json
expect 2 "^artillery run: --record: cannot write '/proc/x.json': the folder '/proc' does not take new files" -- \
    run "$LEVEL" --autoplay --record /proc/x.json
expect 2 "^artillery run: --record: cannot write 'dir': 'dir' is a folder, not a file" -- \
    run "$LEVEL" --autoplay --record dir
expect 2 "^artillery run: --record: cannot write 'plain.txt/x.json': 'plain.txt' is not a folder" -- \
    run "$LEVEL" --autoplay --record plain.txt/x.json
expect 2 "^artillery run: --record: cannot write '/dev/null': '/dev/null' is not a regular file" -- \
    run "$LEVEL" --autoplay --record /dev/null
# Refused before the simulation: the first line out is the refusal (no run summary).
expect 2 "^artillery run: --audio: cannot write '/proc/a.wav'" -- run "$LEVEL" --autoplay --audio /proc/a.wav
expect 2 "^artillery run: --video: cannot write '/proc/v.mp4'" -- run "$LEVEL" --autoplay --video /proc/v.mp4
expect 2 "^artillery run: --png: cannot write into '/proc/frames'" -- run "$LEVEL" --autoplay --png /proc/frames
expect 2 "^artillery run: --png: cannot write into 'plain.txt/frames': 'plain.txt' is not a folder" -- \
    run "$LEVEL" --autoplay --png plain.txt/frames
expect 2 "^artillery generate: --output: cannot write '': an empty file name" -- \
    generate --seed 1 --mode practice -o ""
expect 2 "^artillery generate: --output: cannot write '/proc/x.json'" -- generate --seed 1 --mode practice -o /proc/x.json
expect 2 "^artillery solve-level: --record: cannot write '/proc/x.json'" -- solve-level "$LEVEL" --record /proc/x.json
expect 2 "^artillery bench: --csv: cannot write '/proc/x.csv'" -- bench stability --quick --csv /proc/x.csv --png x.png
expect 2 "^artillery bench: --png: cannot write 'nowhere/x.png'" -- bench stability --quick --csv x.csv --png nowhere/x.png
expect 2 "^artillery play: --screenshot: cannot write '/proc/x.png'" -- play "$LEVEL" --headless --frames 1 --screenshot /proc/x.png
expect 2 "^artillery host: --record: cannot write '/proc/x.json'" -- host "$DUEL" --port 0 --autoplay --record /proc/x.json
expect 2 "^artillery join: --record: cannot write '/proc/x.json'" -- join 127.0.0.1:9 --autoplay --record /proc/x.json
expect 2 "^artillery host: cannot listen on 192.0.2.1:0: 192.0.2.1 is not an address of this machine" -- \
    host "$DUEL" --port 0 --autoplay --bind 192.0.2.1

# --- numbers at their documented limits: run, or are refused with one line ----------------
expect 0 "seed-9223372036854775807|\"seed\":9223372036854775807" -- \
    generate --seed 9223372036854775807 --mode practice -o max_seed.json --json
expect 0 "\"seed\":9223372036854775807" -- generate --seed 9223372036854775807 --mode duel -o max_duel.json --json
expect 2 "--seed expects a whole number in \\[0, 9223372036854775807\\], got '9223372036854775808'" -- \
    generate --seed 9223372036854775808 --mode practice -o x.json
expect 0 "solutions" -- solve --from 0,0 --to 1000000000,0 --speed 1000000 --gravity 10000 --json
expect 2 "asks for more than 1e8 steps" -- trajectory --speed 1000000 --angle 360 --time 1000000 --dt 1e-7
expect 2 "ask for more than 5e7 steps" -- drop --height 100000 --cor 1 --bounces 100 --dt 1e-6
expect 0 "\"steps\":" -- spring --k 1e6 --mass 1e-6 --x0 1e6 --time 1 --integrator implicit-euler --json
expect 0 "frames in" -- run "$LEVEL" --ticks 2 --png big --every 1000000 --size 16x16
expect 2 "--ticks expects a whole number in \\[1, 432000\\]" -- run "$LEVEL" --ticks 432001
expect 2 "expected a regular file" -- replay verify /dev/zero
expect 1 "/dev/zero: \\$: expected a regular file" -- check /dev/zero
expect 1 "plain.txt: .*line 1" -- check plain.txt
expect 2 "expected a regular file, got a directory" -- run dir

# --- a write that fails during the work: exit 3, one line (a file size limit makes each
# write past it fail with EFBIG; the program ignores SIGXFSZ, so it is not killed) -------
limited() { (ulimit -f 2; exec "$@"); }
expect_limited() {
    local code=$1 pattern=$2; shift 3
    limited "$EXE" "$@" > out.log 2>&1
    local rc=$?
    if [ $rc -gt 128 ] || [ $rc != "$code" ] || ! grep -Eq -- "$pattern" out.log; then
        echo "FAIL (file size limit): artillery $* exited $rc, expected $code and '$pattern'"
        cat out.log; failures=$((failures + 1))
    else
        echo "ok ($rc, file size limit): artillery $*"
    fi
}
expect_limited 3 "^artillery run: the run stopped: .*limited.json: writing failed: File too large" -- \
    run "$LEVEL" --autoplay --record limited.json
expect_limited 3 "^artillery run: the sound track was not written: .*limited.wav: writing failed: File too large" -- \
    run "$LEVEL" --ticks 600 --audio limited.wav
expect_limited 3 "^artillery generate: the level was not written: .*limited_level.json: writing failed" -- \
    generate --seed 1 --mode practice -o limited_level.json
# Standard output that takes nothing: the verb's output is lost, and it says so.
"$EXE" solve --from 0,0 --to 40,0 --speed 30 > /dev/full 2> out.log
rc=$?
if [ $rc = 3 ] && grep -q "^artillery solve: standard output could not be written" out.log; then
    echo "ok (3): artillery solve > /dev/full"
else
    echo "FAIL: artillery solve > /dev/full exited $rc"; cat out.log; failures=$((failures + 1))
fi
# Writes are atomic: what is left of the replay is its last whole save (the first turn's,
# under the limit), which verifies.
if [ -e limited.json ] && ! (cd "$SRC" && "$EXE" replay verify "$WORK/limited.json" > /dev/null); then
    echo "FAIL: the replay left behind is not whole"; failures=$((failures + 1))
fi
ls | grep -q '\.tmp\.' && { echo "FAIL: a temporary file was left behind"; ls; failures=$((failures + 1)); }

# --- an honest message: a command the match refused is a warning of replay verify ------
sed 's/"commands": \[/"commands": [ {"cmd": "select", "projectile": "nuke", "tick": 0},/' \
    "$SRC/tests/replays/01_earth_basics.replay.json" > nuke.replay.json
(cd "$SRC" && "$EXE" replay verify "$WORK/nuke.replay.json") > out.log 2>&1
rc=$?
if [ $rc = 0 ] && grep -q "^ok: " out.log &&
    grep -q "^warning: .*nuke.replay.json: tick 0: select 'nuke' refused: " out.log; then
    echo "ok (0): replay verify warns of the refused select"
else
    echo "FAIL: replay verify of a refused select exited $rc"; cat out.log; failures=$((failures + 1))
fi

[ $failures = 0 ] && echo "every verb ended with its line and code, no signal" || exit 1
