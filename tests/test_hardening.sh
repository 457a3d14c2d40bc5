#!/bin/sh
# Faults the firmware and the tools must survive (issue 18), as a user
# meets them: each check fails without its fix.
# usage: test_hardening.sh RINGLOC PATHS_DIR TMPDIR
. "$(dirname "$0")/sh_lib.sh"

# a long drive: the rendered frames listed many times over
: >"$T/frames.txt"
for k in 1 2 3 4 5 6 7 8; do ls "$D"/straight_*.png "$D"/rect_*.png >>"$T/frames.txt"; done
cfg() { # SERIAL RATE
    cat <<CFG
camera: {backend: png, device: $T/frames.txt, width: 640, height: 480, rate: $2}
calibration: $D/camera.yaml
map: $D/map.yaml
robot: $D/robot.yaml
serial: {device: $1, baud: 115200}
CFG
}

# 1. a serial device that is not there is never made a file, in /dev or
#    as the dangling link of a pty monitor that went away; the loop says
#    so and keeps retrying
dev=/dev/ttyRLTEST$$
cfg "$dev" 200 >"$T/nodev.yaml"
"$R" run --config "$T/nodev.yaml" 2>"$T/nodev.err"; rc=$?
if [ -e "$dev" ]; then bad "$dev was created"; rm -f "$dev"; else ok; fi
# (and the summary counts no pose that never reached a line)
grep -q "$dev: no such device; retrying" "$T/nodev.err" && ! grep -q " 0 serial errors" "$T/nodev.err" &&
    grep -q " frames, 0 poses, 0 status frames" "$T/nodev.err" && ok ||
    bad "absent device: rc $rc: $(tail -3 "$T/nodev.err")"
ln -s /dev/pts/nonexistent$$ "$T/dangling"
cfg "$T/dangling" 200 >"$T/dangling.yaml"
"$R" run --config "$T/dangling.yaml" 2>"$T/dangling.err"
[ -L "$T/dangling" ] && [ ! -e /dev/pts/nonexistent$$ ] && grep -q "no such device" "$T/dangling.err" && ok ||
    bad "dangling link: $(tail -2 "$T/dangling.err")"

# 2. a pty monitor restarted in the middle of a run gets the frames sent
#    after its restart
cfg "$T/tty" 20 >"$T/pty.yaml" # 11 s of frames
count() { n=$(grep -c '"type"' "$1" 2>/dev/null); echo "${n:-0}"; }
"$R" monitor --pty "$T/tty" >"$T/first.jsonl" 2>/dev/null &
m1=$!
i=0
while [ ! -L "$T/tty" ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
"$R" run --config "$T/pty.yaml" 2>"$T/pty.err" &
run=$!
# frames through the first monitor (a sanitizer build starts slowly)
i=0
while [ "$(count "$T/first.jsonl")" -lt 10 ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done
kill -TERM $m1
wait $m1 2>/dev/null
sleep 0.5
"$R" monitor --pty "$T/tty" >"$T/second.jsonl" 2>/dev/null &
m2=$!
i=0
while [ "$(count "$T/second.jsonl")" -lt 21 ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done
kill -TERM $run
wait $run
i=0
while kill -0 $m2 2>/dev/null && [ $i -lt 30 ]; do sleep 0.1; i=$((i + 1)); done
kill $m2 2>/dev/null
wait $m2 2>/dev/null
n1=$(count "$T/first.jsonl")
n2=$(count "$T/second.jsonl")
[ "$n1" -ge 10 ] && [ "$n2" -ge 20 ] && [ ! -f "$T/tty" ] && ok ||
    bad "pty restart: $n1 frames before, $n2 after: $(tail -3 "$T/pty.err")"

# 3. monitor: a character device that is no serial line ends like a file;
#    --pty stops on SIGTERM before any writer came; a baud of 0 is refused
timeout 5 "$R" monitor /dev/null >/dev/null 2>&1; rc=$?
[ $rc = 0 ] && ok || bad "monitor /dev/null: rc $rc (124: it never ended)"
"$R" monitor --pty "$T/idle" >/dev/null 2>&1 &
m=$!
sleep 0.5
kill -TERM $m
i=0
while kill -0 $m 2>/dev/null && [ $i -lt 20 ]; do sleep 0.1; i=$((i + 1)); done
if kill -0 $m 2>/dev/null; then bad "monitor --pty ignored SIGTERM"; kill -KILL $m; else ok; fi
wait $m 2>/dev/null
"$R" monitor --baud 0 "$T/first.jsonl" 2>"$T/err"; rc=$?
[ $rc = 2 ] && grep -q "baud: 0 is not a supported baud rate" "$T/err" && ok || bad "monitor --baud 0: rc $rc"

# 4. run: SIGHUP stops it with its summary; standard output piped into a
#    reader that goes away stops it at once, saying why
cfg "$T/hup.bin" 20 >"$T/hup.yaml"
"$R" run --config "$T/hup.yaml" 2>"$T/hup.err" &
pid=$!
# its first frame written: running, its signals handled (a loaded machine or
# a sanitizer build may take seconds to get there)
i=0
while [ ! -s "$T/hup.bin" ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done
sleep 0.2
kill -HUP $pid
wait $pid; rc=$?
[ $rc = 0 ] && grep -q "frames dropped (stopped by signal)" "$T/hup.err" && ok || bad "SIGHUP: rc $rc: $(tail -1 "$T/hup.err")"
cfg - 20 >"$T/pipe.yaml"
start=$(date +%s)
"$R" run --config "$T/pipe.yaml" 2>"$T/pipe.err" | head -c 100 >/dev/null
took=$(( $(date +%s) - start ))
grep -q "standard output closed (broken pipe); stopping" "$T/pipe.err" && [ $took -lt 8 ] && ok ||
    bad "broken pipe: ${took}s: $(tail -2 "$T/pipe.err")"

# 5. numbers out of their range, from files and the command line: one
#    error line naming the file and key (or the option), never a NaN pose
one_error() { # WHAT EXPECTED-RC PATTERN COMMAND...
    what=$1 want=$2 pat=$3
    shift 3
    timeout 20 "$@" >"$T/out" 2>"$T/err"; rc=$?
    if [ $rc = "$want" ] && [ "$(wc -l <"$T/err")" = 1 ] && grep -q -- "$pat" "$T/err" && ! grep -qi nan "$T/out"; then
        ok
    else
        bad "$what: rc $rc: $(head -2 "$T/err")"
    fi
}
frame=$(head -1 "$T/frames.txt")
sed 's/data: \[\([0-9.]*\), 0, \([0-9.]*\), 0, \([0-9.]*\)/data: [1e-300, 0, \2, 0, 1e-300/' "$D/camera.yaml" >"$T/cam_tiny.yaml"
one_error "fx 1e-300" 1 "cam_tiny.yaml:[0-9]*: camera_matrix: 640x480, fx 1e-300" \
    "$R" locate --camera "$T/cam_tiny.yaml" --map "$D/map.yaml" --robot "$D/robot.yaml" "$frame"
awk 'NR == 1, /x:/ { if (!done && sub(/x: [-0-9.]+/, "x: 1e308")) done = 1 } { print }' "$D/map.yaml" >"$T/map_far.yaml"
one_error "map x 1e308" 1 "map_far.yaml:[0-9]*: landmarks\[0\].x: 1e+308 is out of range" \
    "$R" locate --camera "$D/camera.yaml" --map "$T/map_far.yaml" --robot "$D/robot.yaml" "$frame"
python3 -c "print('landmarks: ' + '[' * 200000 + ']' * 200000)" >"$T/deep.yaml" 2>/dev/null ||
    awk 'BEGIN { printf "landmarks: "; for (i = 0; i < 200000; i++) printf "["; for (i = 0; i < 200000; i++) printf "]"; print "" }' >"$T/deep.yaml"
one_error "200,000 levels of YAML" 1 "deep.yaml:1: nested more than 64 levels deep" \
    "$R" locate --camera "$D/camera.yaml" --map "$T/deep.yaml" --robot "$D/robot.yaml" "$frame"
printf 'family: ring5\ndiameter: 0.21\nceiling_height: 2.75\ndiameter: 0.5\nlandmarks: []\n' >"$T/dup.yaml"
one_error "a doubled key" 1 "dup.yaml:4: diameter: given twice (first at line 2)" \
    "$R" locate --camera "$D/camera.yaml" --map "$T/dup.yaml" --robot "$D/robot.yaml" "$frame"
printf 'camera_mount: {x: 0, y: 0, z: 0.88, z: 5}\n' >"$T/dup_robot.yaml"
one_error "a doubled key in a flow mapping" 1 "dup_robot.yaml:1: z: given twice (first at line 1)" \
    "$R" locate --camera "$D/camera.yaml" --map "$D/map.yaml" --robot "$T/dup_robot.yaml" "$frame"
sed 's/^serial:.*/serial: {device: x.bin, baud: 115200}\nlog_interval: -5/' "$T/hup.yaml" >"$T/logint.yaml"
one_error "log_interval -5" 1 "logint.yaml:[0-9]*: log_interval: -5 is out of range" "$R" run --config "$T/logint.yaml"
one_error "plan --distance 1e300" 2 "distance: 1e300 is out of range" \
    "$R" plan --landmarks 30 --resolution 640x480 --hfov 70 --distance 1e300
one_error "plan --grid 65536x65536" 2 "grid: 65536x65536: each side at most" \
    "$R" plan --resolution 640x480 --hfov 70 --distance 1.87 --grid 65536x65536 --pitch 0.61 --ceiling-height 2.75
one_error "calibrate-offsets --pose nan" 2 "--pose: 'nan,nan,nan' is not X,Y,YAW" \
    "$R" calibrate-offsets --map "$D/map.yaml" --robot "$D/robot.yaml" --pose nan,nan,nan --out "$T/o.yaml" "$frame"

sed '0,/rows: 3/s//rows: 65536/; 0,/cols: 3/s//cols: 65536/' "$D/camera.yaml" >"$T/cam_huge.yaml"
one_error "a 65536x65536 camera matrix" 1 "cam_huge.yaml:[0-9]*: camera_matrix: rows x cols is 65536x65536 but data has 9" \
    "$R" locate --camera "$T/cam_huge.yaml" --map "$D/map.yaml" --robot "$D/robot.yaml" "$frame"
one_error "a folder as a frame" 1 "$T: a folder, not a PNG image" "$R" detect "$T"

# 6. the PNG camera: a frame that cannot be read is reported and skipped,
#    the others still give poses; with loop: true the list plays again
printf '%s\n' "$T/absent.png" "$frame" "$T" "$frame" >"$T/mixed.txt"
cfg - 0 | sed "s|device: $T/frames.txt|device: $T/mixed.txt|" >"$T/mixed.yaml"
"$R" run --config "$T/mixed.yaml" >"$T/mixed.bin" 2>"$T/mixed.err"; rc=$?
[ $rc = 0 ] && grep -q "camera: $T/absent.png: No such file or directory; frame skipped" "$T/mixed.err" &&
    grep -q ": 2 frames, 2 poses, 2 status frames, 0 camera errors, 2 bad frames," "$T/mixed.err" && ok ||
    bad "bad frames in the list: rc $rc: $(cat "$T/mixed.err")"
cfg - 0 | sed "s|device: $T/frames.txt|device: $T/mixed.txt|; s|rate: 0|rate: 0, loop: true|" >"$T/loop.yaml"
"$R" run --config "$T/loop.yaml" --frames 9 >"$T/loop.bin" 2>"$T/loop.err"; rc=$?
[ $rc = 0 ] && grep -q ": 9 frames, 9 poses, " "$T/loop.err" && ok ||
    bad "loop: rc $rc: $(tail -1 "$T/loop.err")"

# 7. --probe describes the configured camera and exits, reading nothing
#    else; a V4L2 device that is not there is one error line
"$R" run --config "$T/mixed.yaml" --probe >"$T/probe.out" 2>"$T/probe.err"; rc=$?
[ $rc = 0 ] && grep -q "png $T/mixed.txt: 4 frames of 640x480 (configured), 2 not readable" "$T/probe.out" && ok ||
    bad "probe: rc $rc: $(cat "$T/probe.out" "$T/probe.err")"
sed "s|backend: png, device: $T/frames.txt|backend: v4l2, device: /dev/videoRLTEST$$|" "$T/nodev.yaml" >"$T/v4l2.yaml"
"$R" run --config "$T/v4l2.yaml" --probe >"$T/probe.out" 2>"$T/probe.err"; rc=$?
[ $rc = 1 ] && [ "$(wc -l <"$T/probe.err")" = 1 ] && grep -q "camera: /dev/videoRLTEST$$: no such device" "$T/probe.err" && ok ||
    bad "probe of an absent device: rc $rc: $(cat "$T/probe.err")"

# 8. lens models: an OpenCV fisheye calibration (fisheye_model: 1) reads as
#    the fisheye model, and one without an image size loads with --size
fish=$(dirname "$0")/frames/fisheye_opencv.yaml
"$R" locate --camera "$fish" --map "$D/map.yaml" --robot "$D/robot.yaml" "$frame" >"$T/fish.json" 2>"$T/fish.err"; rc=$?
[ $rc = 0 ] && grep -q '"pose": ' "$T/fish.json" && ok || bad "fisheye file: rc $rc: $(cat "$T/fish.err")"
grep -v "^image_" "$fish" >"$T/nosize.yaml"
"$R" locate --camera "$T/nosize.yaml" --map "$D/map.yaml" --robot "$D/robot.yaml" "$frame" >/dev/null 2>"$T/nosize.err"; rc=$?
"$R" locate --size 640x480 --camera "$T/nosize.yaml" --map "$D/map.yaml" --robot "$D/robot.yaml" "$frame" \
    >"$T/nosize.json" 2>&1; rc2=$?
[ $rc = 1 ] && grep -q "nosize.yaml:[0-9]*: image_width: missing, and no image size given" "$T/nosize.err" &&
    [ $rc2 = 0 ] && grep -q '"width": 640' "$T/nosize.json" && ok || bad "size-less file: rc $rc, $rc2: $(cat "$T/nosize.err")"

# 9. recording while running: one frame in `every` kept as PNG with
#    frames.txt, the poses the same as without, the disk bounded
ls "$D"/straight_*.png >"$T/rec_list.txt"
cfg - 0 | sed "s|device: $T/frames.txt|device: $T/rec_list.txt|" >"$T/norec.yaml"
"$R" run --config "$T/norec.yaml" >"$T/norec.bin" 2>/dev/null
{ cat "$T/norec.yaml"; printf 'record: {dir: rec, every: 3}\n'; } >"$T/rec.yaml"
"$R" run --config "$T/rec.yaml" >"$T/rec.bin" 2>"$T/rec.err"; rc=$?
n=$(ls "$T/rec/drive_001"/frame_*.png 2>/dev/null | wc -l)
"$R" detect "$T/rec/drive_001/frame_0000003.png" | sed 's/.*"landmarks"/"landmarks"/; s/"elapsed_us": [0-9.]*//' >"$T/rec_det.txt"
"$R" detect "$(sed -n 4p "$T/rec_list.txt")" | sed 's/.*"landmarks"/"landmarks"/; s/"elapsed_us": [0-9.]*//' >"$T/orig_det.txt"
[ $rc = 0 ] && [ "$n" = 4 ] && [ "$(wc -l <"$T/rec/drive_001/frames.txt")" = 4 ] && grep -q "recorded 4 frames" "$T/rec.err" &&
    grep -q ": 12 frames, 12 poses" "$T/rec.err" && cmp -s "$T/rec_det.txt" "$T/orig_det.txt" &&
    [ "$(wc -c <"$T/rec.bin")" = "$(wc -c <"$T/norec.bin")" ] && ok ||
    bad "recording: rc $rc, $n frames: $(tail -2 "$T/rec.err")"
{ cat "$T/norec.yaml"; printf 'record: {dir: rec_small, every: 1, max_mb: 0.1}\n'; } >"$T/rec_small.yaml"
"$R" run --config "$T/rec_small.yaml" >/dev/null 2>"$T/rec_small.err"; rc=$?
n=$(ls "$T/rec_small/drive_001"/frame_*.png 2>/dev/null | wc -l)
[ $rc = 0 ] && [ "$n" -ge 1 ] && [ "$n" -lt 12 ] && grep -q "max_mb; recording stopped" "$T/rec_small.err" &&
    grep -q ": 12 frames, 12 poses" "$T/rec_small.err" && ok || bad "max_mb: rc $rc, $n frames: $(tail -1 "$T/rec_small.err")"
# (a folder that cannot be made: one line, and the poses all the same,
# issue 39)
"$R" run --config "$T/norec.yaml" --record /proc/ringloc_rec 2>"$T/rec_bad.err"; rc=$?
[ $rc = 0 ] && [ "$(grep -c "record:" "$T/rec_bad.err")" = 1 ] && grep -q ": 12 frames, 12 poses" "$T/rec_bad.err" &&
    grep -q "record: /proc/ringloc_rec: cannot make the recording folder" "$T/rec_bad.err" &&
    ok || bad "unwritable recording folder: rc $rc: $(cat "$T/rec_bad.err")"

# 10. outputs (issue 28): a failed write keeps the old file whole and says
#     why in one line; no output is written through a link; SIGXFSZ at its
#     default kills nothing (ringloc ignores it)
limited() { # BLOCKS-OF-512 COMMAND...: under a file-size limit, SIGXFSZ at its default
    blocks=$1; shift
    sh -c 'ulimit -f "$0"; exec "$@"' "$blocks" "$@"
}
cp "$D/robot.yaml" "$T/robot.yaml"
set -- "$D"/straight_00*.png
limited 0 "$R" calibrate-mount --camera "$D/camera.yaml" --map "$D/map.yaml" --robot "$T/robot.yaml" \
    --out "$T/robot.yaml" "$@" 2>&1 >/dev/null | cat >"$T/mount.err"
[ "$(wc -l <"$T/mount.err")" = 1 ] && grep -q "robot.yaml: File too large" "$T/mount.err" &&
    cmp -s "$D/robot.yaml" "$T/robot.yaml" && [ -z "$(ls -A "$T" | grep '^\.robot')" ] && ok ||
    bad "calibrate-mount --out robot.yaml under ulimit -f 0: $(cat "$T/mount.err"), $(wc -c <"$T/robot.yaml") bytes"
printf 'old map\n' >"$T/plan_map.yaml"
limited 0 "$R" plan --landmarks 30 --resolution 640x480 --hfov 70 --distance 1.87 --grid 4x3 --pitch 0.61 \
    --ceiling-height 2.75 --camera-height 0.88 --map-out "$T/plan_map.yaml" 2>&1 >/dev/null | cat >"$T/plan.err"
grep -q "plan_map.yaml: File too large" "$T/plan.err" && [ "$(cat "$T/plan_map.yaml")" = "old map" ] && ok ||
    bad "plan --map-out under 1 kB: $(cat "$T/plan.err")"
limited 2 "$R" gen --family ring5 --id 25 --diameter 0.19 --pdf "$T/lm.pdf" 2>&1 >/dev/null | cat >"$T/gen.err"; rc=$?
grep -q "lm.pdf: File too large" "$T/gen.err" && [ ! -e "$T/lm.pdf" ] && ok ||
    bad "gen --pdf under 1 kB: $(cat "$T/gen.err"), $(ls -l "$T/lm.pdf" 2>&1)"
limited 8 "$R" gen --family ring5 --id 25 --px 200 --png "$T/lm.png" 2>&1 >/dev/null | cat >"$T/genpng.err"
grep -q "File too large" "$T/genpng.err" && ! ls "$T"/lm*.png "$T"/.lm* >/dev/null 2>&1 && ok ||
    bad "gen --png under 4 kB: $(cat "$T/genpng.err"), $(ls "$T" | grep lm)"
printf 'keep\n' >"$T/victim"
ln -s "$T/victim" "$T/ann.png"
"$R" detect --map "$D/map.yaml" --annotate "$T/ann.png" "$frame" >/dev/null 2>"$T/ann.err"; rc=$?
[ $rc = 1 ] && grep -q "ann.png: is a symbolic link" "$T/ann.err" && [ "$(cat "$T/victim")" = keep ] && ok ||
    bad "detect --annotate through a link: rc $rc: $(cat "$T/ann.err")"

# 11. a FIFO where a file is expected is refused at once, never waited on
mkfifo "$T/fifo"
one_error "run --config FIFO" 1 "fifo: a FIFO, not a YAML file" "$R" run --config "$T/fifo"
one_error "locate --camera FIFO" 1 "fifo: a FIFO, not a YAML file" \
    "$R" locate --camera "$T/fifo" --map "$D/map.yaml" --robot "$D/robot.yaml" "$frame"
one_error "detect --map FIFO" 1 "fifo: a FIFO, not a YAML file" "$R" detect --map "$T/fifo" "$frame"
one_error "a FIFO as an image" 1 "fifo: a FIFO, not a PNG image" "$R" detect "$T/fifo"
cfg "$T/fifo" 0 >"$T/fifo_serial.yaml"
timeout 20 "$R" run --config "$T/fifo_serial.yaml" --frames 3 >/dev/null 2>"$T/fifo_serial.err"; rc=$?
[ $rc = 1 ] && grep -q "neither a serial device nor a file" "$T/fifo_serial.err" && ok ||
    bad "a FIFO as the serial line: rc $rc: $(tail -2 "$T/fifo_serial.err")"

# 12. the serial line: /dev/full says why; nothing reached the line: exit 1
cfg /dev/full 0 | sed "s|device: $T/frames.txt|device: $T/rec_list.txt|" >"$T/full.yaml"
"$R" run --config "$T/full.yaml" >/dev/null 2>"$T/full.err"; rc=$?
[ $rc = 1 ] && grep -q "serial: write failed (No space left on device)" "$T/full.err" &&
    grep -q "no frame reached /dev/full" "$T/full.err" && ok || bad "/dev/full: rc $rc: $(cat "$T/full.err")"
#     and recording goes on without the line: every third of the 12 frames
{ cat "$T/full.yaml"; printf 'record: {dir: rec_noline, every: 3}\n'; } >"$T/rec_noline.yaml"
"$R" run --config "$T/rec_noline.yaml" >/dev/null 2>"$T/rec_noline.err"; rc=$?
n=$(ls "$T/rec_noline/drive_001"/frame_*.png 2>/dev/null | wc -l)
[ $rc = 1 ] && [ "$n" = 4 ] && grep -q "recorded 4 frames" "$T/rec_noline.err" && ok ||
    bad "recording with the serial line down: rc $rc, $n frames: $(tail -3 "$T/rec_noline.err")"

# 13. recording (issue 28): standard output closed gives no frame to the
#     recorder's files; a second run gets its own folder; a planted link
#     is never followed; a file-size limit stops recording, not the poses,
#     and leaves no partial frame (nor a temporary one)
{ cat "$T/norec.yaml"; printf 'record: {dir: rec2, every: 3}\n'; } >"$T/rec2.yaml"
"$R" run --config "$T/rec2.yaml" >&- 2>"$T/rec2a.err"
"$R" run --config "$T/rec2.yaml" >/dev/null 2>"$T/rec2b.err"
good=0
for f in "$T"/rec2/drive_00*/frame_*.png; do
    [ "$(head -c 4 "$f" | od -An -c | tr -d ' ')" = "211PNG" ] && good=$((good + 1))
done
[ "$good" = 8 ] && [ "$(wc -l <"$T/rec2/drive_001/frames.txt")" = 4 ] &&
    [ "$(wc -l <"$T/rec2/drive_002/frames.txt")" = 4 ] && grep -q "recording one frame in 3 to .*rec2/drive_002" "$T/rec2b.err" && ok ||
    bad "two recordings, one with stdout closed: $good whole PNGs: $(ls -R "$T/rec2")"
mkdir -p "$T/rec3" "$T/elsewhere"
ln -s "$T/elsewhere" "$T/rec3/drive_001"
"$R" run --config "$T/norec.yaml" --record "$T/rec3" >/dev/null 2>"$T/rec3.err"; rc=$?
[ $rc = 0 ] && [ -z "$(ls -A "$T/elsewhere")" ] && [ "$(ls "$T/rec3/drive_002" | grep -c png)" = 2 ] && ok ||
    bad "a planted drive_001 link: rc $rc: $(ls "$T/elsewhere"): $(tail -1 "$T/rec3.err")"
ln -s "$T/elsewhere" "$T/rec_link"
"$R" run --config "$T/norec.yaml" --record "$T/rec_link" >/dev/null 2>"$T/rec_link.err"; rc=$?
[ $rc = 0 ] && grep -q ": 12 frames, 12 poses" "$T/rec_link.err" && grep -q "rec_link: not a folder" "$T/rec_link.err" && [ -z "$(ls -A "$T/elsewhere")" ] && ok ||
    bad "a link as the recording folder: rc $rc: $(cat "$T/rec_link.err")"
if [ "$(id -u)" = 0 ]; then
    mkdir -p "$T/rec_other" && chown nobody "$T/rec_other"
    "$R" run --config "$T/norec.yaml" --record "$T/rec_other" >/dev/null 2>"$T/rec_other.err"; rc=$?
    [ $rc = 0 ] && grep -q ": 12 frames, 12 poses" "$T/rec_other.err" && grep -q "rec_other: belongs to another user" "$T/rec_other.err" && ok ||
        bad "another user's recording folder: rc $rc: $(cat "$T/rec_other.err")"
fi
{ cat "$T/norec.yaml"; printf 'record: {dir: rec4, every: 1}\n'; } >"$T/rec4.yaml"
sh -c 'ulimit -f 200; exec "$@"' sh "$R" run --config "$T/rec4.yaml" 2>"$T/rec4.err" |
    cat >"$T/rec4.bin" # 100 kB a file: less than a frame
n=$(ls -A "$T/rec4/drive_001" | grep -vc '^frames.txt$')
[ "$n" = 0 ] && [ ! -s "$T/rec4/drive_001/frames.txt" ] && [ "$(wc -c <"$T/rec4.bin")" = "$(wc -c <"$T/norec.bin")" ] &&
    grep -q "File too large; recording stopped" "$T/rec4.err" && grep -q ": 12 frames, 12 poses" "$T/rec4.err" &&
    [ "$(grep -c "recording stopped" "$T/rec4.err")" = 2 ] && ok ||
    bad "recording under a file-size limit: $n frames: $(cat "$T/rec4.err")"

# 14. monitor marks fields out of their range (issue 28): frames made by
#     hand from the frame format (rl_packet.h), ARCOS checksum summed by hand
bytes() { for b; do printf "\\$(printf %03o "0x$b")"; done; }
{   # a status frame with reason 200; sum 0x5301 + 0xC800 = 0x1B01
    bytes FA FB 0E 53 01 00 00 00 00 00 00 C8 00 00 00 1B 01
    # a pose frame, version 2, yaw 32767e-4 rad (beyond pi); sum 0x5002 + 0xFF7F = 0x4F81
    bytes FA FB 24 50 02 00 00 00 00 00 00 00 00 00 00 00 00 00 00 FF 7F
    bytes 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 4F 81
    # an ordinary status frame (reason 1): nothing marked; sum 0x5301 + 0x0100 = 0x5401
    bytes FA FB 0E 53 01 00 00 00 00 00 00 01 00 00 00 54 01
} >"$T/odd.bin"
timeout 5 "$R" monitor "$T/odd.bin" >"$T/odd.jsonl" 2>/dev/null
[ "$(sed -n 1p "$T/odd.jsonl" | grep -c '"reason": 200.*"out_of_range": \["reason"\]')" = 1 ] &&
    [ "$(sed -n 2p "$T/odd.jsonl" | grep -c '"yaw": 3.2767.*"out_of_range": \["yaw"\]')" = 1 ] &&
    [ "$(sed -n 3p "$T/odd.jsonl" | grep -c 'out_of_range')" = 0 ] && ok || bad "monitor's out-of-range fields: $(cat "$T/odd.jsonl")"

# 15. every bad PNG of a camera's frames is named in the log (issue 28:
#     only the first was, the rest rate-limited away), each once
{ sed -n 1,3p "$T/frames.txt"; for k in 1 2 3 4 5; do echo "$T/bad$k.png"; done; sed -n 4,6p "$T/frames.txt"; } >"$T/badlist.txt"
for k in 1 2 3 4 5; do printf 'not a png %s\n' "$k" >"$T/bad$k.png"; done
cfg - 0 | sed "s|device: $T/frames.txt|device: $T/badlist.txt|" >"$T/badlist.yaml"
"$R" run --config "$T/badlist.yaml" 2>"$T/badlist.err" >/dev/null
named=0
for k in 1 2 3 4 5; do [ "$(grep -c "bad$k.png" "$T/badlist.err")" = 1 ] && named=$((named + 1)); done
[ $named = 5 ] && grep -q ": 6 frames, 6 poses, 5 status frames" "$T/badlist.err" && ok ||
    bad "bad PNGs in the camera's frames: $named of 5 named once: $(cat "$T/badlist.err")"

# 16. site-check (issue 28): skipped files make the exit code 1 (the table
#     is still printed), an image too small to hold a landmark is no photo,
#     and the progress line ends before the next error line
mkdir -p "$T/photos"
for k in 01 02 03 04 05 06 07 08 09 10 11 12 13 14 15 16 17 18 19 20; do
    cp "$D/straight_000.png" "$T/photos/p$k.png"
done
printf 'not a png\n' >"$T/photos/p21.png"
"$R" gen --family ring5 --id 3 --png "$T/photos/p22.png" --px 16 # a landmark's own picture: 16 px
"$R" site-check --rounds 1 "$T/photos" >"$T/sc.out" 2>"$T/sc.err"; rc=$?
[ $rc = 1 ] && grep -q "wholly inside" "$T/sc.out" && grep -q "p21.png" "$T/sc.err" &&
    grep -q "p22.png" "$T/sc.err" && grep -q "2 of 22 files skipped" "$T/sc.err" &&
    ! grep -q "of 22 photos.*png" "$T/sc.err" && ok || bad "site-check with bad files: rc $rc: $(cat "$T/sc.err")"
# a kind with none placed has no rate: A3 sheets (the default for 0.21 m)
# cannot lie within 1 R of a lamp without covering it; the others have one
grep -qE 'wholly inside +[1-9][0-9]* +[0-9]+ +[0-9.]+% +0' "$T/sc.out" &&
    grep -qE 'within 1 R of a light +0 +0 +- +0' "$T/sc.out" && ok || bad "site-check's rates: $(cat "$T/sc.out")"
"$R" site-check --rounds 1 --json "$T/photos/p01.png" >"$T/sc.json" 2>"$T/sc.err"
grep -qE '"near_light": \{"placed": 0, "identified": 0, "rate": null' "$T/sc.json" &&
    grep -qE '"complete": \{"placed": [1-9][0-9]*, "identified": [0-9]+, "rate": [0-9.]+' "$T/sc.json" && ok ||
    bad "site-check's JSON rates: $(cat "$T/sc.json" "$T/sc.err")"

sh_done
