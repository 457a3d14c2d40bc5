#!/bin/sh
# The renderer's rolling shutter (ringloc-render --rolling), against a
# calculation by hand: the rows are read top to bottom in READOUT while the
# robot drives forward at SPEED, and the frame's pose (its truth) is the
# middle row's. A row read a fraction f of the readout after the middle
# row (f = (v + 0.5) / H - 0.5) sees the ceiling from SPEED f READOUT
# further forward, so a landmark there lies that much further back in the
# image: its centre moves down (image top = forward) by
# SPEED f READOUT fy / D pixels (fy the focal length, D the camera's
# distance to the ceiling), and not sideways. Judged on `ringloc detect`'s
# centres in the same frames rendered with and without the shutter. Also:
# --rolling 0,0 draws exactly the global shutter's frame; bad values get
# one error line. Then the pose of a rolling-shutter drive round a circle,
# `ringloc locate` with and without --readout, against the renderer's truth.
# usage: test_rolling.sh RINGLOC RENDER TMPDIR
set -u
R=$1
RENDER=$2
T=$3
rm -rf "$T"
mkdir -p "$T"
. "$(dirname "$0")/sh_check.sh"
READOUT_MS=33
SPEED=1.0

"$RENDER" --out "$T/global" --path straight --frames 4 --write-camera "$T/camera.yaml" >/dev/null &&
    "$RENDER" --out "$T/rolling" --path straight --frames 4 --rolling $READOUT_MS,$SPEED >/dev/null &&
    "$RENDER" --out "$T/zero" --path straight --frames 4 --rolling 0,0 >/dev/null && ok ||
    bad "ringloc-render failed"
for f in "$T"/global/*.png; do
    cmp -s "$f" "$T/zero/$(basename "$f")" && ok || bad "--rolling 0,0 changed $(basename "$f")"
done
# along the path: the straight drive's 4 frames are 0.8 m apart, so 0.8 s a
# frame is the 1 m/s given above: the same frames
"$RENDER" --out "$T/along" --path straight --frames 4 --rolling $READOUT_MS --interval 0.8 >/dev/null && ok ||
    bad "ringloc-render --rolling MS --interval failed"
for f in "$T"/rolling/*.png; do
    cmp -s "$f" "$T/along/$(basename "$f")" && ok || bad "--rolling $READOUT_MS --interval 0.8 is not $SPEED m/s: $(basename "$f")"
done

fy=$(sed -n 's/^ *data: \[\([-0-9.]*\), 0, [-0-9.]*, 0, \([-0-9.]*\),.*/\2/p' "$T/camera.yaml" | head -1)
D=$(sed -n 's/^distance: \([0-9.]*\)/\1/p' "$T/global/straight_000.yaml")
[ -n "$fy" ] && [ -n "$D" ] && ok || bad "no focal length ($fy) or distance ($D)"

# "k id u v complete" per detection, G global and S rolling
for m in global rolling; do
    "$R" detect "$T/$m"/straight_*.png | awk -v m=$m '{ s = $0
        while (match(s, /"id": [0-9]+, "code": "[01]*", "u": [-0-9.]+, "v": [-0-9.]+, "radius": [-0-9.]+, "score": [-0-9.]+, "runner_up": [-0-9.]+, "pass": "[a-z]+", "complete": [a-z]+/)) {
            t = substr(s, RSTART, RLENGTH); s = substr(s, RSTART + RLENGTH)
            gsub(/[",:]/, " ", t); split(t, f, " +"); print m, NR - 1, f[3], f[7], f[9], f[19] } }'
done >"$T/centres.txt"

awk -v T="$READOUT_MS" -v s="$SPEED" -v fy="$fy" -v D="$D" '
    $1 == "global" && $6 == "true" { gu[$2, $3] = $4; gv[$2, $3] = $5 }
    $1 == "rolling" && $6 == "true" { ru[$2, $3] = $4; rv[$2, $3] = $5 }
    END {
        for (k in gv) {
            if (!(k in rv)) { lost++; continue }
            f = (gv[k] + 0.5) / 480 - 0.5
            want = s * f * T / 1000 * fy / D
            tol = 0.35 + 0.1 * (want < 0 ? -want : want)
            dv = rv[k] - gv[k]; du = ru[k] - gu[k]
            n++
            if (want < -1.5) up++
            if (want > 1.0) down++
            if ((dv - want)^2 > tol^2 || du^2 > tol^2) {
                bad++; printf "FAIL: landmark at row %.1f moved %.2f, %.2f px (want %.2f down, 0 across)\n", gv[k], dv, du, want }
        }
        printf "%d landmarks, %d above the middle moved up over 1.5 px, %d below down over 1 px, %d off, %d lost\n", n, up, down, bad, lost
        exit !(n >= 8 && up >= 2 && down >= 2 && bad == 0 && lost == 0) }' "$T/centres.txt" && ok ||
    bad "the rolling shutter moved the centres otherwise than by hand"

# The pose of a drive round a circle (0.6 m, 24 frames) at 1 m/s, turning
# 1.667 rad/s, the camera 0.12 m ahead of the robot's centre, rows read in
# 33 ms: `ringloc locate` without --readout is off by v x (row time) for
# landmarks away from the middle row (millimetres: the shutter matters);
# with --readout 33 the centres are moved to the middle row's instant by the
# last two poses' motion, and from the third frame on (two poses known)
# every pose is within 0.6 mm of the truth (a global shutter's: 0.1-0.2 mm).
M="--mount 0.12,-0.03,0.02"
"$RENDER" --out "$T/circle" --path circle --frames 24 $M --rolling $READOUT_MS,1.0,1.6667 \
    --write-map "$T/map.yaml" --write-camera "$T/cam.yaml" --write-robot "$T/robot.yaml" >/dev/null && ok ||
    bad "ringloc-render failed (circle)"
interval=0.15708 # 2 pi 0.6 m / 24 frames at 1 m/s
# poses DIR RO MAP: `ringloc locate --readout RO` over DIR's circle frames
# against the renderer's truth, "frames 2-N RMS, largest, none" on stdout and
# exit 0 when readout 0 is off by over 2 mm RMS (the shutter matters) or a
# readout's every pose from the third on is within LIMIT mm
poses() {
    d=$1 ro=$2 map=$3 limit=$4
    "$R" locate --interval $interval --readout $ro --camera "$T/cam.yaml" --map "$map" \
        --robot "$T/robot.yaml" "$d"/circle_*.png >"$d/poses_$ro.jsonl" 2>"$T/locate.err" || bad "locate failed"
    k=0
    for y in "$d"/circle_*.yaml; do
        sed -n 's/^robot: {x: \([-0-9.]*\), y: \([-0-9.]*\),.*/T '$k' \1 \2/p' "$y"
        k=$((k + 1))
    done >"$d/truth.txt"
    awk '{ if (match($0, /"pose": \{"x": [-0-9.]+, "y": [-0-9.]+/)) {
            t = substr($0, RSTART, RLENGTH); gsub(/[",:{]/, " ", t); split(t, f, " +"); print "P", NR - 1, f[4], f[6] }
           else print "P", NR - 1, "-", "-" }' "$d/poses_$ro.jsonl" >>"$d/truth.txt"
    awk -v ro=$ro -v limit=$limit '$1 == "T" { tx[$2] = $3; ty[$2] = $4 } $1 == "P" { px[$2] = $3; py[$2] = $4; n++ }
        END {
            for (k = 2; k < n; k++) {
                if (px[k] == "-") { none++; continue }
                e = sqrt((px[k] - tx[k])^2 + (py[k] - ty[k])^2) * 1000; s += e * e; m++
                if (e > worst) worst = e
            }
            rms = m ? sqrt(s / m) : 0
            printf "readout %s ms: frames 2-%d %.2f mm RMS, largest %.2f mm, %d without a pose\n", ro, n - 1, rms, worst, none
            if (ro == 0) exit !(m == n - 2 && rms > 2.0)
            exit !(m == n - 2 && worst < limit) }' "$d/truth.txt"
}
for ro in 0 $READOUT_MS; do
    poses "$T/circle" $ro "$T/map.yaml" 0.6 && ok || bad "readout $ro: the poses are not as they should be (above)"
done

# The same drive under a ceiling that is not one plane: half the ids hang
# 0.5 m below it (on beams; the map gives their z), 1.37 m above the camera
# instead of 1.87: the travel moves them 1.87 / 1.37 times as far in the
# image. Each centre is moved at its own landmark's height: every pose from
# the third on within 0.5 mm (moved as if on the ceiling: 0.91 mm).
LOW=
for id in 1 3 5 7 9 11 13 15 17 19 21 23 25 27 29; do LOW="$LOW --lower $id,0.5"; done
"$RENDER" --out "$T/hung" --path circle --frames 24 $M --rolling $READOUT_MS,1.0,1.6667 $LOW \
    --write-map "$T/map_hung.yaml" >/dev/null && ok || bad "ringloc-render failed (hung circle)"
[ "$(grep -c ' z: ' "$T/map_hung.yaml")" = 15 ] && ok || bad "the hung map has not 15 heights"
poses "$T/hung" $READOUT_MS "$T/map_hung.yaml" 0.5 && ok ||
    bad "readout $READOUT_MS, landmarks on beams: the poses are not within 0.5 mm (above)"

expect 2 "--rolling" -- "$RENDER" --out "$T/x" --path straight --frames 1 --rolling 200,1
expect 2 "--rolling" -- "$RENDER" --out "$T/x" --path straight --frames 1 --rolling 30,nan
expect 2 "--interval" -- "$RENDER" --out "$T/x" --path straight --frames 1 --rolling 30
expect 2 "--path" -- "$RENDER" --out "$T/x" --set clean --count 1 --rolling 30
sh_done
