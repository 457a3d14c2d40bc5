#!/bin/sh
# Issue 43: tracking windows against full frames on a rendered drive,
# judged by the renderer's truth (NAME.yaml). `ringloc locate` over the
# drive's frames in order, tracked (--track) and with --no-track:
# - tracked, no landmark is given a wrong id (each lies within half a
#   radius of a truth landmark of its id);
# - every whole landmark (its disk in the frame) a full frame reads is read in the tracked run's
#   frame too, and most frames are read by windows;
# - every frame with two whole landmarks whose full pose is within 5 cm of
#   the truth has a tracked pose within 5 cm;
# - with JUMP_FRAME (the frame the robot was carried to, --path tour's
#   halfway), that frame is read in full and placed right.
# usage: test_track.sh RINGLOC DIR TMPDIR PREFIX [JUMP_FRAME]
. "$(dirname "$0")/sh_lib.sh"
P=$4
J=${5:-}

(cd "$D" && ls "$P"*.png) | sed 's|^|'"$D"'/|' >"$T/frames.txt"
n=$(wc -l <"$T/frames.txt")
[ "$n" -ge 20 ] && ok || bad "only $n $P frames in $D"

locate_frames() { locate_frames_in "$T/frames.txt" "$@"; }
locate_frames --track >"$T/tracked.jsonl" 2>"$T/tracked.err"
locate_frames --no-track >"$T/full.jsonl" 2>"$T/full.err"
[ "$(wc -l <"$T/tracked.jsonl")" = "$n" ] && [ "$(wc -l <"$T/full.jsonl")" = "$n" ] && ok ||
    bad "locate gave $(wc -l <"$T/tracked.jsonl") tracked and $(wc -l <"$T/full.jsonl") full lines for $n frames"

# one line per frame and thing: "T k x y" truth robot, "S k W|H n" its size,
# "L k id u v r visible"
# truth landmark, "A k id u v" tracked detection, "B k id u v" full one,
# "PA k x y" / "PB k x y" poses ("-" none), "W k windows|full"
k=0
while read -r f; do
    sed -n 's/^robot: {x: \([-0-9.]*\), y: \([-0-9.]*\),.*/T '$k' \1 \2/p' "${f%.png}.yaml"
    sed -n 's/^width: \([0-9]*\)/S '$k' W \1/p; s/^height: \([0-9]*\)/S '$k' H \1/p' "${f%.png}.yaml"
    sed -n 's/.*{id: \([0-9]*\), x: [-0-9.]*, y: [-0-9.]*, u: \([-0-9.]*\), v: \([-0-9.]*\), radius: \([-0-9.]*\), visible: \([-0-9.]*\).*/L '$k' \1 \2 \3 \4 \5/p' "${f%.png}.yaml"
    k=$((k + 1))
done <"$T/frames.txt" >"$T/facts.txt"
for m in A B; do
    [ $m = A ] && src="$T/tracked.jsonl" || src="$T/full.jsonl"
    awk -v m=$m '{ k = NR - 1; s = $0
        while (match(s, /"id": [0-9]+, "code": "[01]*", "u": [-0-9.]+, "v": [-0-9.]+/)) {
            t = substr(s, RSTART, RLENGTH); s = substr(s, RSTART + RLENGTH)
            gsub(/[",:]/, " ", t); split(t, f, " +"); print m, k, f[3], f[7], f[9] }
        if (match($0, /"pose": \{"x": [-0-9.]+, "y": [-0-9.]+/)) {
            t = substr($0, RSTART, RLENGTH); gsub(/[",:{]/, " ", t); split(t, f, " +"); print "P" m, k, f[4], f[6] }
        else print "P" m, k, "-", "-"
        if (m == "A") { w = ($0 ~ /"track": "windows"/) ? "windows" : "full"; print "W", k, w } }' "$src"
done >>"$T/facts.txt"

awk -v jump="$J" '
    $1 == "T" { tx[$2] = $3; ty[$2] = $4 }
    $1 == "S" { size[$2, $3] = $4 }
    $1 == "L" { n = nl[$2]++; lid[$2, n] = $3; lu[$2, n] = $4; lv[$2, n] = $5; lr[$2, n] = $6; lvis[$2, n] = $7 }
    $1 == "A" || $1 == "B" { n = nd[$1, $2]++; did[$1, $2, n] = $3; du[$1, $2, n] = $4; dv[$1, $2, n] = $5 }
    $1 == "PA" || $1 == "PB" { px[$1, $2] = $3; py[$1, $2] = $4 }
    $1 == "W" { w[$2] = $3; frames++; windows += $3 == "windows" }
    function on(m, k, i, j) { # detection i of run m lies on truth landmark j of its id
        return did[m, k, i] == lid[k, j] && (du[m, k, i] - lu[k, j])^2 + (dv[m, k, i] - lv[k, j])^2 < (0.5 * lr[k, j])^2 }
    function reads(m, k, j,   i) { for (i = 0; i < nd[m, k]; i++) if (on(m, k, i, j)) return 1; return 0 }
    function right(m, k) { return px[m, k] != "-" && (px[m, k] - tx[k])^2 + (py[m, k] - ty[k])^2 <= 0.05^2 }
    END {
        for (k = 0; k < frames; k++) {
            whole = 0
            for (i = 0; i < nd["A", k]; i++) {
                hit = 0
                for (j = 0; j < nl[k]; j++) hit += on("A", k, i, j)
                if (!hit) { wrong++; print "frame " k ": tracked id " did["A", k, i] " at " du["A", k, i] " " dv["A", k, i] " is wrong" }
            }
            for (j = 0; j < nl[k]; j++) {
                # whole: its disk in the frame (the truth says visible 1 a pixel or two beyond)
                if (lvis[k, j] < 1 || lu[k, j] - lr[k, j] < 0 || lv[k, j] - lr[k, j] < 0 ||
                    lu[k, j] + lr[k, j] > size[k, "W"] - 1 || lv[k, j] + lr[k, j] > size[k, "H"] - 1) continue
                whole++
                if (reads("B", k, j) && !reads("A", k, j)) { lost++; print "frame " k " (" w[k] "): whole id " lid[k, j] " read in full, not tracked" }
            }
            if (whole >= 2 && right("PB", k) && !right("PA", k)) { pose++; print "frame " k " (" w[k] "): tracked pose " px["PA", k] " " py["PA", k] " for truth " tx[k] " " ty[k] }
        }
        if (jump != "" && (w[jump] != "full" || !right("PA", jump))) { jumpbad = 1; print "frame " jump " (carried there): " w[jump] ", pose " px["PA", jump] " " py["PA", jump] " for truth " tx[jump] " " ty[jump] }
        printf "SUMMARY %d %d %d %d %d %d\n", wrong, lost, pose, windows, frames, jumpbad
    }' "$T/facts.txt" >"$T/judge.txt"
set -- $(sed -n 's/^SUMMARY //p' "$T/judge.txt")
grep -v '^SUMMARY' "$T/judge.txt" | head -20
[ "$1" = 0 ] && ok || bad "$P: $1 wrong ids in tracked frames"
[ "$2" = 0 ] && ok || bad "$P: $2 whole landmarks read in full frames but not tracked"
[ "$3" = 0 ] && ok || bad "$P: $3 tracked poses off where the full ones are right"
[ "$((2 * $4))" -ge "$5" ] && ok || bad "$P: only $4 of $5 frames read by windows"
[ "$6" = 0 ] && ok || bad "$P: the frame the robot was carried to was not read in full and placed"

sh_done
