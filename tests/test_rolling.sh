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
# one error line.
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

expect 2 "--rolling" -- "$RENDER" --out "$T/x" --path straight --frames 1 --rolling 200,1
expect 2 "--rolling" -- "$RENDER" --out "$T/x" --path straight --frames 1 --rolling 30
expect 2 "--rolling" -- "$RENDER" --out "$T/x" --path straight --frames 1 --rolling 30,nan
sh_done
