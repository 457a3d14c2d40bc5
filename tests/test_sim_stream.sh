#!/bin/sh
# The simulation path end to end: poses streamed into ringloc-render
# (--path stream) become frames on a pipe, which ringloc-fw reads through
# the sim camera; every pose frame must carry its pose's time (not when the
# frame was read) and the streamed pose (the renderer's input is the truth).
# usage: test_sim_stream.sh RINGLOC RINGLOC_RENDER RINGLOC_FW TMPDIR
set -u
RL=$1 RENDER=$2 FW=$3 T=$4/sim_stream
rm -rf "$T" && mkdir -p "$T/st" || exit 1
cd "$T" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
"$RL" plan --area 6x5 --pitch 0.8 --resolution 640x480 --hfov 70 --ceiling-height 2.75 --camera-height 0.88 \
    --map-out site.yaml > /dev/null 2>&1 || fail "plan"
"$RENDER" --site-map site.yaml --mount 0.1,0,0 --write-camera cam.yaml --write-robot robot.yaml || fail "render setup"
cat > fw.yaml <<'YAML'
camera:
  backend: sim
  device: st/frames
calibration: cam.yaml
map: site.yaml
robot: robot.yaml
serial:
  device: out.bin
  baud: 115200
YAML
# five poses 0.2 s apart in a clock of their own (7 s on): time, x, y, yaw
printf '%s\n' "7000000 2.00 2.00 0.30" "7200000 2.04 2.01 0.31" "7400000 2.08 2.02 0.32" \
    "7600000 2.12 2.03 0.33" "7800000 2.16 2.04 0.34" > poses.txt
mkfifo st/frames || fail "mkfifo"
"$RENDER" --out st --path stream --site-map site.yaml --mount 0.1,0,0 < poses.txt > st/frames &
"$FW" --config fw.yaml 2> fw.log || { cat fw.log; fail "ringloc-fw"; }
wait $! || fail "ringloc-render --path stream"
"$RL" monitor out.bin | grep '"type": "pose"' > poses.json
[ "$(wc -l < poses.json)" -eq 5 ] || { cat fw.log poses.json; fail "expected 5 pose frames"; }
# pair each pose frame with its streamed pose
paste -d ' ' poses.txt poses.json | awk '{
    t = $1 / 1000; x = $2; y = $3
    tm = fx = fy = ""
    for (i = 5; i <= NF; i++) {
        if ($i == "\"time_ms\":" && tm == "") tm = $(i + 1) + 0
        if ($i == "\"x\":" && fx == "") fx = $(i + 1) + 0
        if ($i == "\"y\":" && fy == "") fy = $(i + 1) + 0
    }
    if (tm != t) { print "FAIL: frame " NR " time_ms " tm ", its pose was at " t; bad = 1 }
    d = sqrt((fx - x) ^ 2 + (fy - y) ^ 2)
    if (d > 0.005) { print "FAIL: frame " NR " is " d " m from its pose"; bad = 1 }
} END { exit bad }' || exit 1
# a malformed pose line: one line naming it, exit 1
echo "7000000 2.0 nope 0.3" | "$RENDER" --out st --path stream --site-map site.yaml > /dev/null 2> err.txt
[ $? -eq 1 ] && grep -q "standard input:1: not 'T_US X Y YAW'" err.txt || fail "bad line: $(cat err.txt)"
echo ok
