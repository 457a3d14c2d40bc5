#!/bin/sh
# `ringloc fuse --odometry -` live (issue 38): the stand-in's camera on a
# pty (the robot standing at 1.5, 2.0; frames up to 50 ms late beyond
# their latency field, the board's own clock), odometry lines piped in as
# they come with CLOCK_MONOTONIC times (/proc/uptime: the same clock on a
# host that has not slept); the fused pose printed per odometry line must
# be the stand-in's, each frame's fate logged.
# usage: test_fuse_live.sh RINGLOC STANDIN TMPDIR
R=$1
S=$2
T=$3
rm -rf "$T"
mkdir -p "$T"
port=$((20000 + ($$ + 7) % 20000))
"$S" --port $port --frames-pty "$T/tty" --seconds 4 --start 1.5,2.0,0.3 --transport 0.05 >"$T/standin.err" 2>&1 &
sp=$!
i=0
while [ ! -L "$T/tty" ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
fail=0
i=0
while [ $i -lt 50 ]; do awk '{ printf "%s 0 0 0\n", $1 }' /proc/uptime; sleep 0.05; i=$((i + 1)); done |
    "$R" fuse --odometry - --fates "$T/fates.txt" "$T/tty" >"$T/live.jsonl" 2>"$T/live.err" ||
    { echo "FAIL: ringloc fuse --odometry -: $(cat "$T/live.err")"; fail=1; }
kill $sp 2>/dev/null
wait $sp 2>/dev/null
cat "$T/live.err"
echo "$(wc -l <"$T/live.jsonl") poses printed live; fates: $(awk '{ print $3 }' "$T/fates.txt" | sort | uniq -c | tr '\n' ' ')"
tail -1 "$T/live.jsonl" | awk '{ x = $4; y = $6; sub(/,/, "", x); sub(/,/, "", y)
    e = 1000 * sqrt((x - 1.5)^2 + (y - 2.0)^2); printf "last fused pose %.2f mm from the truth\n", e; exit !(e <= 2) }' ||
    { echo "FAIL: the live pose is not the robot's: $(tail -1 "$T/live.jsonl")"; fail=1; }
[ "$(wc -l <"$T/live.jsonl")" -ge 10 ] || { echo "FAIL: too few poses printed"; fail=1; }
grep -q " applied " "$T/fates.txt" || { echo "FAIL: no frame applied in the fates"; fail=1; }
[ $fail = 0 ]
