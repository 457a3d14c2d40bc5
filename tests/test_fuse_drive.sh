#!/bin/sh
# rl_fuse from the truth (issue 27): `ringloc run` with the PNG-sequence
# camera over the circle rendered for it (0.1 m a frame) and over the path
# drives' straight and rect, pose frames into a file, decoded
# by `ringloc monitor`; then test_fuse_drive times them along the drives
# beside simulated odometry and judges the fused pose at every tick.
# usage: test_fuse_drive.sh RINGLOC TEST_FUSE_DRIVE FUSE_DIR PATHS_DIR TMPDIR
R=$1
X=$2
F=$(cd "$3" && pwd)
P=$(cd "$4" && pwd)
T=$5
rm -rf "$T"
mkdir -p "$T" "$T/line"
# frames of one folder through the firmware: DIR PATTERN NAME
frames() {
    # shellcheck disable=SC2086 # the pattern's words are globs, in their order
    (cd "$1" && for p in $2; do ls $p; done) | sed 's|^|'"$1"'/|' >"$T/$3.txt"
    cat >"$T/$3.yaml" <<CFG
camera: {backend: png, device: $3.txt, width: 640, height: 480, rate: 50}
calibration: $1/camera.yaml
map: $1/map.yaml
robot: $1/robot.yaml
serial: {device: $3.bin, baud: 115200}
recognition: {local: auto}
CFG
    (cd "$T" && "$R" run --config "$3.yaml" 2>"$3.err") || { echo "FAIL: run on $1: $(cat "$T/$3.err")"; exit 1; }
    "$R" monitor "$T/$3.bin" >"$T/$3.jsonl" 2>/dev/null || { echo "FAIL: monitor $3.bin"; exit 1; }
}
frames "$F" "circle_*.png" fuse
frames "$P" "straight_*.png rect_*.png" paths
"$X" "$F" "$T/fuse.jsonl" "$P" "$T/paths.jsonl" "$T/fuse.png" "$T"
rc=$?
# `ringloc fuse` on the circle at 1 m/s (odometry log, recorded frames): the
# fused pose against the truth after the first second, and bad inputs
fail=0
"$R" fuse --odometry "$T/odometry.txt" --track 0.33 --wheel-noise 0.0002 --rate 100 "$T/frames.bin" \
    >"$T/fused.jsonl" 2>"$T/fuse.err" || { echo "FAIL: ringloc fuse: $(cat "$T/fuse.err")"; fail=1; }
cat "$T/fuse.err"
# RMS of the fused pose (JSON lines) against the truth after 1 s: TRUTH FUSED
rms_of() {
    awk 'NR == FNR { tx[sprintf("%.2f", $1)] = $2; ty[sprintf("%.2f", $1)] = $3; next }
    { t = $2; x = $4; y = $6; sub(/,/, "", t); sub(/,/, "", x); sub(/,/, "", y); k = sprintf("%.2f", t)
      if (t + 0 >= 1.0 && (k in tx)) { s += (x - tx[k])^2 + (y - ty[k])^2; n++ } }
    END { if (n < 500) print "none"; else printf "%.3f", 1000 * sqrt(s / n) }' "$1" "$2"
}
rms=$(rms_of "$T/truth.txt" "$T/fused.jsonl")
echo "ringloc fuse on the circle at 1 m/s: $rms mm RMS against the truth (after 1 s)"
case $rms in none) fail=1 ;; *) awk -v r="$rms" 'BEGIN { exit !(r <= 3) }' || fail=1 ;; esac
# the real line replayed as the controller saw it (issue 38): time_ms on the
# board's clock, up to 100 ms of delay outside the latency field, arrivals
L=$T/line
"$R" fuse --odometry "$L/odometry.txt" --arrivals "$L/arrivals.txt" --fates "$L/fates.txt" --track 0.33 \
    --wheel-noise 0.0002 "$L/frames.bin" >"$L/fused.jsonl" 2>"$L/fuse.err" ||
    { echo "FAIL: ringloc fuse --arrivals: $(cat "$L/fuse.err")"; fail=1; }
cat "$L/fuse.err"
rms=$(rms_of "$L/truth.txt" "$L/fused.jsonl")
echo "ringloc fuse --arrivals on the real line: $rms mm RMS against the truth (after 1 s)"
case $rms in none) fail=1 ;; *) awk -v r="$rms" 'BEGIN { exit !(r <= 3) }' || fail=1 ;; esac
grep -q " 0 restarts" "$L/fuse.err" || { echo "FAIL: a false restart on the real line"; fail=1; }
# every frame's fate, once: as many lines as frames, the first ones untimed
[ "$(wc -l <"$L/fates.txt")" = "$(wc -l <"$L/arrivals.txt")" ] || { echo "FAIL: fates: $(wc -l <"$L/fates.txt") lines"; fail=1; }
head -1 "$L/fates.txt" | grep -q "^0 .* untimed " || { echo "FAIL: the first fate: $(head -1 "$L/fates.txt")"; fail=1; }
# without the arrivals the same recording's time_ms are not the odometry's clock
"$R" fuse --odometry "$L/odometry.txt" "$L/frames.bin" >/dev/null 2>"$T/err"
[ $? = 1 ] && grep -q "no pose" "$T/err" || echo "note: without --arrivals: $(cat "$T/err")"
sed '2s/^[0-9]*/999/' "$L/arrivals.txt" >"$T/bad_arrivals.txt"
"$R" fuse --odometry "$L/odometry.txt" --arrivals "$T/bad_arrivals.txt" "$L/frames.bin" >/dev/null 2>"$T/err"
[ $? = 1 ] && grep -q "bad_arrivals.txt:2: sequence 999, but pose frame 2 is 1" "$T/err" ||
    { echo "FAIL: arrivals of another recording: $(cat "$T/err")"; fail=1; }
grep -q '"t": 1.000, "x":' "$T/fused.jsonl" || { echo "FAIL: no pose at 1.000 s"; fail=1; }
printf '0 0 0 0\n0.1 0.1 0 0\n0.05 0.2 0 0\n' >"$T/bad_odo.txt"
"$R" fuse --odometry "$T/bad_odo.txt" "$T/frames.bin" >/dev/null 2>"$T/err"
[ $? = 1 ] && grep -q "bad_odo.txt:3: time 0.05 does not follow 0.1" "$T/err" || { echo "FAIL: bad log: $(cat "$T/err")"; fail=1; }
"$R" fuse --odometry "$T/odometry.txt" --rate 0 "$T/frames.bin" >/dev/null 2>"$T/err"
[ $? = 2 ] && grep -q -- "--rate: 0 is out of range" "$T/err" || { echo "FAIL: bad rate: $(cat "$T/err")"; fail=1; }
"$R" fuse --odometry "$T/odometry.txt" "$T/missing.bin" >/dev/null 2>"$T/err"
[ $? = 1 ] && grep -q "missing.bin" "$T/err" || { echo "FAIL: missing frames: $(cat "$T/err")"; fail=1; }
# `ringloc monitor --record --arrivals`: the bytes kept as read, each pose
# frame's sequence number with its arrival (here a file: all at once)
"$R" monitor --record "$T/rec.bin" --arrivals "$T/rec_arrivals.txt" "$L/frames.bin" >/dev/null 2>"$T/err" &&
    cmp -s "$T/rec.bin" "$L/frames.bin" && [ "$(cut -d' ' -f1 "$T/rec_arrivals.txt")" = "$(cut -d' ' -f1 "$L/arrivals.txt")" ] ||
    { echo "FAIL: monitor --record --arrivals: $(cat "$T/err")"; fail=1; }
[ $rc = 0 ] && [ $fail = 0 ]
