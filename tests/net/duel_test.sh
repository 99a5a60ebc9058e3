#!/bin/bash
# Networked duels between real processes over 127.0.0.1 (ports chosen by the system,
# so tests running side by side never collide). Every wait is bounded.
#   duel_test.sh EXE RELAY SOURCE_DIR WORK_DIR MODE [INTRUDER]
# MODE: loopback | relay | tamper | reconnect | rejoin | timeout | refuse | hostile |
#       window | played
#   (window, played: XVFB_RUN in the environment names xvfb-run; played: xdotool too;
#   hostile: INTRUDER, the scripted hostile peer of tests/net/intruder.cpp)
set -u
EXE=$1 RELAY=$2 SRC=$3 WORK=$4 MODE=$5 INTRUDER=${6:-}
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$SRC" || exit 2
# Whatever is still running when this script ends (a failed mode leaves a host waiting
# for its player) ends with it.
trap 'kill $(jobs -p) 2>/dev/null' EXIT
fail() { echo "FAIL ($MODE): $*"; for f in "$WORK"/*.log; do echo "--- $f"; cat "$f"; done; exit 1; }

# Waits (at most 10 s) for "on 127.0.0.1:PORT" in a log and prints PORT.
port_of() {
    for _ in $(seq 100); do
        p=$(sed -n 's/.* on 127\.0\.0\.1:\([0-9]*\).*/\1/p' "$1" | head -1)
        [ -n "$p" ] && { echo "$p"; return 0; }
        sleep 0.1
    done
    return 1
}

# An uninterrupted duel: both sides autoplayed, the reference for every mode.
duel() { # NAME HOST_ARGS -- JOIN_ARGS (the join target is filled in)
    local name=$1; shift
    local hargs=() jargs=() target_relay=""
    while [ "$1" != "--" ]; do hargs+=("$1"); shift; done; shift
    jargs=("$@")
    timeout 120 "$EXE" host levels/10_duel.json --port 0 --autoplay --name ada \
        --record "$WORK/$name.host.json" "${hargs[@]}" > "$WORK/$name.host.log" 2>&1 &
    HOST_PID=$!
    HP=$(port_of "$WORK/$name.host.log") || fail "the host did not start"
    TARGET=$HP
    if [ "${USE_RELAY:-0}" = 1 ]; then
        timeout 120 "$RELAY" --to "$HP" --drop 0.1 --delay-ms 40 --seed 7 --seconds 100 > "$WORK/$name.relay.log" 2>&1 &
        RELAY_PID=$!
        TARGET=$(port_of "$WORK/$name.relay.log") || fail "the relay did not start"
    fi
    timeout 120 "$EXE" join "127.0.0.1:$TARGET" --autoplay --name bob \
        --record "$WORK/$name.join.json" "${jargs[@]}" > "$WORK/$name.join.log" 2>&1
    JOIN_RC=$?
    wait $HOST_PID; HOST_RC=$?
    if [ "${USE_RELAY:-0}" = 1 ]; then kill -TERM "$RELAY_PID" 2>/dev/null; wait "$RELAY_PID" 2>/dev/null; fi
    return 0
}

final_hash() { sed -n 's/.*"final_hash": *"\([0-9a-f]*\)".*/\1/p' "$1" | head -1; }

case $MODE in
loopback)
    # With a spectator watching from the start.
    timeout 120 "$EXE" host levels/10_duel.json --port 0 --autoplay --name ada --record "$WORK/h.json" > "$WORK/h.log" 2>&1 &
    H=$!
    HP=$(port_of "$WORK/h.log") || fail "the host did not start"
    timeout 120 "$EXE" join "127.0.0.1:$HP" --spectate --name eve --record "$WORK/s.json" > "$WORK/s.log" 2>&1 &
    S=$!
    sleep 0.3
    timeout 120 "$EXE" join "127.0.0.1:$HP" --autoplay --name bob --record "$WORK/j.json" > "$WORK/j.log" 2>&1 || fail "join exited $?"
    wait $H || fail "host exited $?"
    wait $S || fail "spectator exited $?"
    cmp "$WORK/h.json" "$WORK/j.json" || fail "the two replays differ"
    cmp "$WORK/h.json" "$WORK/s.json" || fail "the spectator's replay differs"
    "$EXE" replay verify "$WORK/h.json" || fail "the host's replay does not verify"
    "$EXE" replay verify "$WORK/j.json" || fail "the joiner's replay does not verify"
    grep -q "match over at tick .*: cannon . (.*) wins, final hash $(final_hash "$WORK/h.json")" "$WORK/j.log" || fail "no result line"
    grep -q "spectator eve joined" "$WORK/h.log" || fail "the spectator was not announced"
    ;;
relay)
    duel plain --
    [ $JOIN_RC = 0 ] && [ $HOST_RC = 0 ] || fail "plain duel exited $HOST_RC/$JOIN_RC"
    USE_RELAY=1 duel lossy --
    [ $JOIN_RC = 0 ] && [ $HOST_RC = 0 ] || fail "lossy duel exited $HOST_RC/$JOIN_RC"
    grep -q "dropped [1-9]" "$WORK/lossy.relay.log" || fail "the relay dropped nothing"
    cmp "$WORK/lossy.host.json" "$WORK/lossy.join.json" || fail "the replays through the relay differ"
    cmp "$WORK/plain.host.json" "$WORK/lossy.host.json" || fail "the relay changed the match"
    "$EXE" replay verify "$WORK/lossy.join.json" || fail "the replay does not verify"
    ;;
tamper)
    duel tamper -- --tamper-at-tick 0
    [ $JOIN_RC = 1 ] && [ $HOST_RC = 1 ] || fail "expected exit 1 on both sides, got $HOST_RC/$JOIN_RC"
    # The computer fires at tick 180 (its pause, then a second of aiming): the shell is
    # nudged from there, and the checkpoint at 240 differs.
    grep -qx "desync at tick 240 (particles differ)" "$WORK/tamper.host.log" || fail "host: no desync message"
    grep -qx "desync at tick 240 (particles differ)" "$WORK/tamper.join.log" || fail "joiner: no desync message"
    # Both keep their replay; the honest host's verifies, the tampered one's does not.
    "$EXE" replay verify "$WORK/tamper.host.json" || fail "the host's replay does not verify"
    "$EXE" replay verify "$WORK/tamper.join.json" > "$WORK/verify.log" 2>&1 && fail "the tampered replay verifies"
    grep -q "tick 240" "$WORK/verify.log" || fail "verify does not name tick 240"
    ;;
reconnect)
    duel plain --
    [ $HOST_RC = 0 ] || fail "plain duel exited $HOST_RC"
    duel cut -- --drop-at-tick 3000
    [ $JOIN_RC = 0 ] && [ $HOST_RC = 0 ] || fail "interrupted duel exited $HOST_RC/$JOIN_RC"
    grep -q "cutting the connection at tick 3000" "$WORK/cut.join.log" || fail "the connection was not cut"
    grep -q "back in the match" "$WORK/cut.join.log" || fail "the joiner did not come back"
    [ "$(final_hash "$WORK/cut.host.json")" = "$(final_hash "$WORK/plain.host.json")" ] || fail "final hash differs from the uninterrupted match"
    cmp "$WORK/cut.host.json" "$WORK/cut.join.json" || fail "the replays differ"
    ;;
rejoin)
    # The joiner's process dies at tick 3000; a new process under the same name without
    # the seat's token is refused; one given the token (printed at the first join) takes
    # the seat back, replays the host's stream (its predecessor's commands included) and
    # plays on.
    duel plain --
    [ $HOST_RC = 0 ] || fail "plain duel exited $HOST_RC"
    timeout 120 "$EXE" host levels/10_duel.json --port 0 --autoplay --name ada --timeout 30 \
        --record "$WORK/h.json" > "$WORK/h.log" 2>&1 &
    H=$!
    HP=$(port_of "$WORK/h.log") || fail "the host did not start"
    timeout 60 "$EXE" join "127.0.0.1:$HP" --autoplay --name bob --quit-at-tick 3000 > "$WORK/j1.log" 2>&1
    TOKEN=$(sed -n 's/^seat token \([0-9a-f]*\): .*/\1/p' "$WORK/j1.log" | head -1)
    [ -n "$TOKEN" ] || fail "the first joiner was given no seat token"
    timeout 60 "$EXE" join "127.0.0.1:$HP" --autoplay --name bob > "$WORK/j0.log" 2>&1 && fail "a name alone took the seat"
    # (The host may not have noticed the drop yet: then the seat is still its player's.)
    grep -Eq "the host refused: the seat is bob's(, held for its return)?; a rejoin presents" "$WORK/j0.log" \
        || fail "no refusal of the name alone"
    timeout 120 "$EXE" join "127.0.0.1:$HP" --autoplay --name bob --token "$TOKEN" --record "$WORK/j2.json" > "$WORK/j2.log" 2>&1 || fail "the new joiner exited $?"
    wait $H || fail "host exited $?"
    grep -q "left without a goodbye at tick 3000" "$WORK/j1.log" || fail "the first joiner did not quit"
    grep -q "rejoining: replaying the match up to tick" "$WORK/j2.log" || fail "the new joiner did not replay"
    cmp "$WORK/h.json" "$WORK/j2.json" || fail "the replays differ"
    "$EXE" replay verify "$WORK/h.json" || fail "the replay does not verify"
    # The computer restarted after the drop aims with a fresh generator, not the one the
    # first process had drawn from: from its first turn on, the match is another one
    # than without the drop (docs/network.md says so).
    echo "final hash without the drop $(final_hash "$WORK/plain.host.json"), with the restart $(final_hash "$WORK/h.json")"
    ;;
hostile)
    # The door, with a scripted hostile peer (tests/net/intruder.cpp) from other loopback
    # addresses while the player comes from 127.0.0.1. Two hosts:
    [ -x "$INTRUDER" ] || fail "no intruder program"
    # 1. Every slot taken: sixteen connections from four addresses finish ENet's
    #    handshake and say nothing, and a CONNECT flood from 127.0.0.3 never answers.
    #    The player joins all the same (the host keeps room) and the match plays through.
    timeout 120 "$EXE" host levels/10_duel.json --port 0 --autoplay --name ada \
        --record "$WORK/full.host.json" > "$WORK/full.host.log" 2>&1 &
    H=$!
    HP=$(port_of "$WORK/full.host.log") || fail "the host did not start"
    for a in 2 7 8 9; do
        timeout 60 "$INTRUDER" --to "$HP" --from 127.0.0.$a --seconds 20 --silent 4 > "$WORK/full.silent$a.log" 2>&1 &
    done
    timeout 60 "$INTRUDER" --to "$HP" --from 127.0.0.3 --seconds 8 --flood 8 > "$WORK/full.flood.log" 2>&1 &
    sleep 1
    SECONDS=0
    timeout 120 "$EXE" join "127.0.0.1:$HP" --autoplay --name bob --record "$WORK/full.join.json" > "$WORK/full.join.log" 2>&1 \
        || fail "the player could not play with every slot taken (exit $?)"
    echo "with every slot taken at the door, the player joined and played the match in $SECONDS s"
    wait $H || fail "host exited $?"
    wait # the intruders
    cmp "$WORK/full.host.json" "$WORK/full.join.json" || fail "the two replays differ"
    grep -q "bob joined from 127.0.0.1" "$WORK/full.host.log" || fail "the player did not join"
    grep -q "no hello, and the host keeps room" "$WORK/full.host.log" || fail "the host made no room"
    # 2. The deadlines, then the seat: silent connections (six tried, four taken: one
    #    address holds four at most) and the flood; the host drops the silent ones 5 s
    #    after their handshake and resets the flood's half-open ones; then the player joins, drops out at tick 3000 (its seat held for its
    #    return), a join under its name without the token is refused, the host takes
    #    four spectators of five, and the player's new process comes back with the token
    #    and plays the match through.
    timeout 120 "$EXE" host levels/10_duel.json --port 0 --autoplay --name ada --timeout 30 \
        --record "$WORK/h.json" > "$WORK/h.log" 2>&1 &
    H=$!
    HP=$(port_of "$WORK/h.log") || fail "the host did not start"
    timeout 60 "$INTRUDER" --to "$HP" --from 127.0.0.2 --seconds 20 --silent 6 > "$WORK/silent.log" 2>&1 &
    SI=$!
    timeout 60 "$INTRUDER" --to "$HP" --from 127.0.0.3 --seconds 10 --flood 8 > "$WORK/flood.log" 2>&1 &
    FL=$!
    wait $SI
    for _ in $(seq 100); do grep -q "stayed in the handshake" "$WORK/h.log" && break; sleep 0.1; done
    timeout 60 "$EXE" join "127.0.0.1:$HP" --autoplay --name bob --quit-at-tick 3000 > "$WORK/j1.log" 2>&1
    TOKEN=$(sed -n 's/^seat token \([0-9a-f]*\): .*/\1/p' "$WORK/j1.log" | head -1)
    timeout 60 "$INTRUDER" --to "$HP" --from 127.0.0.4 --seconds 10 --impostor bob > "$WORK/impostor.log" 2>&1
    timeout 60 "$INTRUDER" --to "$HP" --from 127.0.0.5 --seconds 10 --spectators 3 > "$WORK/spectators1.log" 2>&1
    timeout 60 "$INTRUDER" --to "$HP" --from 127.0.0.6 --seconds 10 --spectators 2 > "$WORK/spectators2.log" 2>&1
    timeout 120 "$EXE" join "127.0.0.1:$HP" --autoplay --name bob --token "$TOKEN" \
        --record "$WORK/j.json" > "$WORK/j.log" 2>&1 || fail "the player's new process exited $?"
    wait $H || fail "host exited $?"
    wait $FL
    cat "$WORK/silent.log" "$WORK/flood.log" "$WORK/impostor.log" "$WORK/spectators1.log" "$WORK/spectators2.log"
    grep -Eq "^silent: 4 connected, 2 turned away, 4 disconnected by the host, held at most [5-7]\.[0-9] s$" "$WORK/silent.log" \
        || fail "one address held more than four, or the silent ones were not dropped 5 s after their handshake"
    [ "$(grep -c 'dropped 127\.0\.0\.2:[0-9]*: no hello within 5 s' "$WORK/h.log")" = 4 ] || fail "the host did not drop the silent peers"
    grep -q "dropped 127\.0\.0\.3:[0-9]*: its connection stayed in the handshake for over 5 s" "$WORK/h.log" \
        || fail "the host did not reset the flood's connections"
    [ -n "$TOKEN" ] || fail "the player was given no seat token"
    # (The host may not have noticed the drop yet: then the seat is still its player's.)
    grep -Eq "impostor bob: refused: the seat is bob's(, held for its return)?; a rejoin presents the seat token" "$WORK/impostor.log" \
        || fail "a name alone was not refused"
    grep -q "^spectators: 3 welcomed, 0 refused$" "$WORK/spectators1.log" || fail "the first three spectators were not taken"
    grep -q "^spectators: 1 welcomed, 1 refused$" "$WORK/spectators2.log" || fail "the fifth spectator was taken"
    grep -q "refused: the host takes at most 4 spectators" "$WORK/spectators2.log" || fail "no spectator refusal"
    grep -q "match over at tick" "$WORK/j.log" || fail "the match did not play through"
    cmp "$WORK/h.json" "$WORK/j.json" || fail "the two replays differ"
    "$EXE" replay verify "$WORK/h.json" || fail "the replay does not verify"
    ;;
timeout)
    duel gone --timeout 2 -- --quit-at-tick 2000
    [ $HOST_RC = 1 ] || fail "host exited $HOST_RC, expected 1"
    grep -Eq "^bob did not return within 2 s: the match ends at tick [0-9]+$" "$WORK/gone.host.log" || fail "no timeout message"
    grep -q "replay saved to $WORK/gone.host.json" "$WORK/gone.host.log" || fail "the match was not saved"
    "$EXE" replay verify "$WORK/gone.host.json" || fail "the saved match does not verify"
    ;;
refuse)
    # A joiner whose level folder has an edited copy: the host says what differs.
    mkdir -p "$WORK/levels"
    sed 's/"shots": 10/"shots": 9/' levels/10_duel.json > "$WORK/levels/10_duel.json"
    duel edited --wait 3 -- --levels "$WORK/levels"
    [ $JOIN_RC = 1 ] || fail "join exited $JOIN_RC, expected 1"
    grep -q "the host refused: level differs: host plays 10_duel.json (content hash [0-9a-f]*), bob has content hash [0-9a-f]*" "$WORK/edited.join.log" || fail "no level message"
    ;;
played)
    # A person plays the host's window: the gestures run inside the virtual display.
    "$XVFB_RUN" -a -s "-screen 0 960x540x24" bash "$0" "$EXE" "$RELAY" "$SRC" "$WORK/inside" played_inside \
        || fail "the played window failed"
    ;;
played_inside)
    # The host's window (960x540, at the screen's corner) waits for its player; the guest
    # is the computer. Once it has joined: a drag from the cannon's pivot (about 87, 377
    # in the window) to 173 px right and 100 px up, i.e. 30 degrees and 200 of the 260 px
    # that mean full power (70 m/s): 53.8 m/s; then Enter fires. Then Esc and Enter leave
    # the duel: the guest must learn it at once, not after its time to reconnect, the
    # host's replay must hold that aim, that power and the fire, as cannon 0's, and the
    # two sides' replays must be the same bytes.
    timeout 120 "$EXE" host levels/10_duel.json --port 0 --name ada \
        --record "$WORK/played.json" > "$WORK/h.log" 2>&1 &
    H=$!
    HP=$(port_of "$WORK/h.log") || fail "the host did not start"
    timeout 120 "$EXE" join "127.0.0.1:$HP" --autoplay --name bob \
        --record "$WORK/guest.json" > "$WORK/j.log" 2>&1 &
    J=$!
    for _ in $(seq 100); do grep -q "bob joined from" "$WORK/h.log" && break; sleep 0.1; done
    grep -q "bob joined from" "$WORK/h.log" || fail "nobody joined"
    sleep 1
    xdotool mousemove 120 360 mousedown 1 sleep 0.2 mousemove 200 300 sleep 0.2 \
        mousemove 260 277 sleep 0.3 mouseup 1 sleep 0.3 key Return || fail "xdotool failed"
    sleep 1
    xdotool key Escape sleep 0.3 key Return || fail "xdotool failed"
    wait $H
    SECONDS=0
    wait $J
    echo "the guest learnt that the host left within $SECONDS s"
    [ $SECONDS -le 5 ] || fail "the guest took $SECONDS s to learn that the host left"
    grep -q "the other side left at tick [0-9]*: ada left" "$WORK/j.log" \
        || fail "the guest was not told that the host left"
    grep -q "left the duel at tick [0-9]*: ada left" "$WORK/h.log" \
        || fail "the host did not say it left"
    "$EXE" replay verify "$WORK/played.json" > /dev/null || fail "the host's replay does not verify"
    "$EXE" replay verify "$WORK/guest.json" > /dev/null || fail "the guest's replay does not verify"
    cmp "$WORK/played.json" "$WORK/guest.json" || fail "the two sides' replays differ"
    # The first aim, power and fire of the replay (its commands, one field a line).
    first() { sed -n "s/.*\"$1\": *\([0-9.]*\).*/\1/p" "$WORK/played.json" | head -1; }
    AIM=$(first angle_deg) POWER=$(first speed_mps)
    echo "the window's first aim: $AIM deg, $POWER m/s"
    grep -q '"cmd": *"fire"' "$WORK/played.json" || fail "the window fired nothing"
    awk -v a="$AIM" -v p="$POWER" 'BEGIN { exit !(a > 25 && a < 35 && p > 49 && p < 59) }' \
        || fail "the replay's aim is not the drag's"
    ;;
window)
    # The host plays in its window under a virtual display ($XVFB_RUN): the duel is heard
    # there as in the game's window. SDL's disk driver writes the sound to a file; the
    # first shot's report must be in it. The join stops itself once the host has gone.
    SDL_AUDIODRIVER=disk SDL_DISKAUDIOFILE="$WORK/host.raw" timeout 120 "$XVFB_RUN" -a \
        -s "-screen 0 960x540x24" "$EXE" host levels/10_duel.json --port 0 --autoplay \
        --name ada --window --frames 900 > "$WORK/h.log" 2>&1 &
    H=$!
    HP=$(port_of "$WORK/h.log") || fail "the host did not start"
    timeout 120 "$EXE" join "127.0.0.1:$HP" --autoplay --name bob --timeout 2 --limit 60 \
        > "$WORK/j.log" 2>&1
    wait $H
    grep -q "bob joined from" "$WORK/h.log" || fail "nobody joined"
    [ -s "$WORK/host.raw" ] || fail "the window wrote no sound"
    od -An -tx1 -v "$WORK/host.raw" | grep -q '[1-9a-f]' || fail "the window's duel was silent"
    ;;
*) echo "unknown mode $MODE"; exit 2 ;;
esac
echo "ok ($MODE)"
