#!/bin/sh
# End to end, as on the robot: `ringloc run` with the PNG-sequence camera
# over the rendered paths, pose frames through a pseudo-terminal, decoded
# by `ringloc monitor`; every pose checked against the renderer's truth.
# With FRAMES (a pattern), those frames of the folder instead: the issue 16
# site's drive, whose map repeats ids (places found from constellations,
# tracked from the last pose).
# usage: test_e2e.sh RINGLOC PATHS_DIR TMPDIR [FRAMES]
. "$(dirname "$0")/sh_lib.sh"

frames=${4:-"straight_*.png rect_*.png circle_*.png"}
# shellcheck disable=SC2086 # the pattern's words are globs
(cd "$D" && ls $frames) >"$T/frames.txt"
sed 's|^|'"$D"'/|' "$T/frames.txt" >"$T/frames_abs.txt"
cat >"$T/ringloc.yaml" <<CFG
camera: {backend: png, device: frames_abs.txt, width: 640, height: 480, rate: 50}
calibration: $D/camera.yaml
map: $D/map.yaml
robot: $D/robot.yaml
serial: {device: tty, baud: 115200}
recognition: {local: auto}
CFG

"$R" monitor --pty "$T/tty" >"$T/poses.jsonl" 2>"$T/monitor.err" &
mon=$!
i=0
while [ ! -L "$T/tty" ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
"$R" run --config "$T/ringloc.yaml" 2>"$T/run.err"
rc=$?
# the monitor ends when the writer closes; never wait on it forever
i=0
while kill -0 $mon 2>/dev/null && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
kill $mon 2>/dev/null
wait $mon 2>/dev/null
[ $rc = 0 ] && ok || bad "run exited $rc: $(cat "$T/run.err")"

# every frame gave a pose, in order, within 1 cm and 0.5 degree of the truth
n=$(wc -l <"$T/frames.txt")
got=$(grep -c '"type": "pose"' "$T/poses.jsonl")
[ "$got" = "$n" ] && ok || bad "$got poses for $n frames"
k=0
while read -r f; do
    name=${f%.png}
    truth=$(sed -n 's/^robot: {x: \([-0-9.]*\), y: \([-0-9.]*\), yaw: \([-0-9.]*\)}/\1 \2 \3/p' "$D/$name.yaml")
    line=$(sed -n "$((k + 1))p" "$T/poses.jsonl")
    pose=$(echo "$line" | sed -n 's/.*"seq": \([0-9]*\), "time_ms": [0-9]*, "x": \([-0-9.]*\), "y": \([-0-9.]*\), "yaw": \([-0-9.]*\).*/\1 \2 \3 \4/p')
    if awk -v t="$truth" -v p="$pose" -v k=$k 'BEGIN { split(t, a, " "); split(p, b, " ");
            dyaw = b[4] - a[3]; while (dyaw > 3.14159265) dyaw -= 6.2831853; while (dyaw < -3.14159265) dyaw += 6.2831853;
            exit !(b[1] == k && sqrt((a[1]-b[2])^2 + (a[2]-b[3])^2) <= 0.01 && (dyaw < 0 ? -dyaw : dyaw) <= 0.0087) }'; then
        ok
    else
        bad "$name: pose '$pose' vs truth '$truth'"
    fi
    k=$((k + 1))
done <"$T/frames.txt"

# configuration errors: one line naming the file and key, exit 1
printf 'camera: {backend: usb, device: x}\nserial: {device: -}\ncalibration: c\nmap: m\nrobot: r\n' >"$T/bad1.yaml"
"$R" run --config "$T/bad1.yaml" 2>"$T/err"; rc=$?
[ $rc = 1 ] && grep -q "bad1.yaml:1: camera.backend: 'usb' is not png, v4l2, libcamera or sim" "$T/err" && ok || bad "bad backend: $(cat "$T/err")"
sed 's/baud: 115200/baud: 12345/' "$T/ringloc.yaml" >"$T/bad2.yaml"
"$R" run --config "$T/bad2.yaml" 2>"$T/err"; rc=$?
[ $rc = 1 ] && grep -q "serial.baud: 12345 is not a supported baud rate" "$T/err" && ok || bad "bad baud: $(cat "$T/err")"
grep -v '^map:' "$T/ringloc.yaml" >"$T/bad3.yaml"
"$R" run --config "$T/bad3.yaml" 2>"$T/err"; rc=$?
[ $rc = 1 ] && grep -qE "bad3.yaml:[0-9]+: map: missing key" "$T/err" && ok || bad "missing map: $(cat "$T/err")"

# a camera device that is not there (yet): the loop keeps going and says
# so in status frames, and SIGTERM stops it cleanly
sed 's|backend: png, device: frames_abs.txt|backend: v4l2, device: /nonexistent/video9|; s|device: tty|device: status.bin|' "$T/ringloc.yaml" >"$T/nocam.yaml"
"$R" run --config "$T/nocam.yaml" 2>"$T/nocam.err" &
pid=$!
# status frames every 200 ms once it runs; a loaded machine may take seconds
# to start it (a large site's map), so wait for three: 4 s of waits, the
# monitor's runs on top (the rate limit below, 3 lines, holds under 15 s:
# the first line and one a 5 s interval)
sleep 1
i=0
st=0
while [ "$st" -lt 3 ] && [ $i -lt 12 ]; do
    sleep 0.25
    "$R" monitor "$T/status.bin" >"$T/status.jsonl" 2>/dev/null
    st=$(grep -c '"type": "status", .*"reason": 2' "$T/status.jsonl")
    i=$((i + 1))
done
kill -TERM $pid
wait $pid; rc=$?
"$R" monitor "$T/status.bin" >"$T/status.jsonl" 2>/dev/null
st=$(grep -c '"type": "status", .*"reason": 2' "$T/status.jsonl")
[ $rc = 0 ] && [ "$st" -ge 3 ] && grep -q "stopped by signal" "$T/nocam.err" && grep -q "/nonexistent/video9" "$T/nocam.err" && ok ||
    bad "missing camera: rc $rc, $st status frames: $(cat "$T/nocam.err")"
lines=$(grep -c "camera:" "$T/nocam.err")
[ "$lines" -le 3 ] && ok || bad "$lines camera log lines in under 5 s: not rate-limited"

sh_done
