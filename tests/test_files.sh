#!/bin/sh
# Issue 39, items 2-4: no command removes, replaces or writes into a file
# it did not make unless told (--force, or an output it names); every
# write error reaches the exit status, standard output's included; a
# rewritten file keeps its group and mode; a name of the file system's
# longest length works. Each check fails without its fix.
# usage: test_files.sh RINGLOC PATHS_DIR TMPDIR RINGLOC_STANDIN
. "$(dirname "$0")/sh_lib.sh"
S=$4

# 1. monitor --pty and the stand-in keep a file that LINK names; a stale
#    link into /dev/pts (a monitor that was killed) is theirs to replace,
#    and removed when they end
printf 'camera_mount: {x: 0.1, y: 0, z: 0.88, yaw: 0}\n' >"$T/robot.yaml"
cp "$T/robot.yaml" "$T/robot.orig"
timeout 5 "$R" monitor --pty "$T/robot.yaml" >/dev/null 2>"$T/mon.err"; rc=$?
[ $rc = 1 ] && cmp -s "$T/robot.yaml" "$T/robot.orig" && [ "$(wc -l <"$T/mon.err")" = 1 ] &&
    grep -q "robot.yaml: exists and is a regular file; not replaced" "$T/mon.err" && ok ||
    bad "monitor --pty over a file: rc $rc: $(cat "$T/mon.err")"
timeout 5 "$S" --port $((20000 + $$ % 20000)) --frames-pty "$T/robot.yaml" --seconds 1 2>"$T/sti.err"; rc=$?
[ $rc = 1 ] && cmp -s "$T/robot.yaml" "$T/robot.orig" && grep -q "robot.yaml: exists and is a regular file" "$T/sti.err" &&
    ok || bad "standin --frames-pty over a file: rc $rc: $(cat "$T/sti.err")"
ln -s /dev/pts/ringloc-gone$$ "$T/stale"
"$R" monitor --pty "$T/stale" >/dev/null 2>"$T/stale.err" &
m=$!
i=0
while ! grep -q listening "$T/stale.err" 2>/dev/null && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
target=$(readlink "$T/stale")
live=no
[ -c "$target" ] && live=yes
kill -TERM $m
wait $m
[ "${target#/dev/pts/}" != "$target" ] && [ $live = yes ] && [ ! -e "$T/stale" ] && [ ! -L "$T/stale" ] && ok ||
    bad "monitor --pty over a stale link: -> '$target', $(cat "$T/stale.err")"
# --force: told to, it replaces the file
"$R" monitor --pty "$T/robot.yaml" --force >/dev/null 2>"$T/force.err" &
m=$!
i=0
while ! grep -q listening "$T/force.err" 2>/dev/null && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
[ -L "$T/robot.yaml" ] && ok || bad "monitor --pty --force: $(cat "$T/force.err")"
kill -TERM $m
wait $m
cp "$T/robot.orig" "$T/robot.yaml"

# 2. plan --grid (and --area) without --map-out keeps a map.yaml that is
#    there; named, or with --force, it is written
mkdir -p "$T/site"
printf 'surveyed map\n' >"$T/site/map.yaml"
plan() { (cd "$T/site" && "$R" plan --landmarks 12 --resolution 640x480 --hfov 70 --distance 1.87 \
    --ceiling-height 2.5 --pitch 0.61 "$@"); }
plan --grid 4x3 >/dev/null 2>"$T/plan.err"; rc=$?
[ $rc = 1 ] && [ "$(cat "$T/site/map.yaml")" = "surveyed map" ] && [ "$(wc -l <"$T/plan.err")" = 1 ] &&
    grep -q "map.yaml exists; not replaced" "$T/plan.err" && ok || bad "plan --grid over map.yaml: rc $rc: $(cat "$T/plan.err")"
plan --area 3x3 >/dev/null 2>"$T/plan.err"; rc=$?
[ $rc = 1 ] && [ "$(cat "$T/site/map.yaml")" = "surveyed map" ] && ok || bad "plan --area over map.yaml: rc $rc: $(cat "$T/plan.err")"
plan --grid 4x3 --force >/dev/null 2>"$T/plan.err"; rc=$?
[ $rc = 0 ] && [ "$(grep -c 'id:' "$T/site/map.yaml")" = 12 ] && ok || bad "plan --grid --force: rc $rc: $(cat "$T/plan.err")"
printf 'surveyed map\n' >"$T/site/map.yaml"
plan --grid 4x3 --map-out map.yaml >/dev/null 2>"$T/plan.err"; rc=$?
[ $rc = 0 ] && [ "$(grep -c 'id:' "$T/site/map.yaml")" = 12 ] && ok || bad "plan --grid --map-out map.yaml: rc $rc: $(cat "$T/plan.err")"

# 3. serial.device: an existing file, or a link to one, is never written
#    into; the firmware says so in one line naming it, retries, and goes on
#    with the frames (here, to their end)
: >"$T/frames.txt"
ls "$D"/straight_*.png >>"$T/frames.txt"
cfg() { # SERIAL
    cat <<CFG
camera: {backend: png, device: $T/frames.txt, width: 640, height: 480, rate: 0}
calibration: $D/camera.yaml
map: $D/map.yaml
robot: $D/robot.yaml
serial: {device: $1, baud: 115200}
CFG
}
cfg "$T/robot.yaml" >"$T/file.yaml"
"$R" run --config "$T/file.yaml" 2>"$T/file.err"; rc=$?
cmp -s "$T/robot.yaml" "$T/robot.orig" && grep -q "robot.yaml: an existing file, not a serial device" "$T/file.err" &&
    grep -q ": 12 frames" "$T/file.err" && ok || bad "serial.device an existing file: rc $rc: $(tail -3 "$T/file.err")"
ln -s "$T/robot.yaml" "$T/planted"
cfg "$T/planted" >"$T/link.yaml"
"$R" run --config "$T/link.yaml" 2>"$T/link.err"; rc=$?
cmp -s "$T/robot.yaml" "$T/robot.orig" && grep -q "planted: a link to .*robot.yaml, not to a serial device" "$T/link.err" &&
    ok || bad "serial.device a link to a file: rc $rc: $(tail -3 "$T/link.err")"
# (a new file is the run's own: the frames are recorded into it)
cfg "$T/frames.bin" >"$T/new.yaml"
"$R" run --config "$T/new.yaml" 2>"$T/new.err"; rc=$?
[ $rc = 0 ] && [ -s "$T/frames.bin" ] && ok || bad "serial.device a new file: rc $rc: $(tail -3 "$T/new.err")"
# (a link to a character device is followed, as /dev/serial0 is)
ln -s /dev/null "$T/null_link"
cfg "$T/null_link" >"$T/null.yaml"
"$R" run --config "$T/null.yaml" 2>"$T/null.err"; rc=$?
[ $rc = 0 ] && grep -q ": 12 frames, 12 poses" "$T/null.err" && ok || bad "serial.device a link to /dev/null: rc $rc: $(tail -3 "$T/null.err")"

# 4. standard output that cannot be written is a failure, one line (the
#    command's words as arguments, never pasted into shell code: a path
#    may hold a quote)
to_full() { "$@" >/dev/full; }
expect 1 "ringloc detect: standard output: " -- to_full "$R" detect "$D/straight_000.png"
expect 1 "ringloc locate: standard output: " -- \
    to_full "$R" locate --camera "$D/camera.yaml" --map "$D/map.yaml" --robot "$D/robot.yaml" "$D/straight_000.png"
"$R" monitor "$T/frames.bin" >/dev/full 2>"$T/mon.err"; rc=$? # (its summary line besides)
[ $rc = 1 ] && grep -q "ringloc monitor: standard output: " "$T/mon.err" && ok || bad "monitor >/dev/full: rc $rc: $(cat "$T/mon.err")"
expect 1 "ringloc: standard output: " -- to_full "$R" --help

# 5. site-check: a file under --out that cannot be written fails the run
mkdir -p "$T/photos"
cp "$D/straight_000.png" "$T/photos/p1.png"
# (stderr through a pipe: a file would be over the limit too)
rc=$( { sh -c 'ulimit -f 0; "$@"; echo $? >&3' sh "$R" site-check --rounds 1 --out "$T/sc_out" "$T/photos" \
    2>&1 >/dev/null | cat >"$T/sc.err"; } 3>&1)
[ "$rc" = 1 ] && grep -q "File too large" "$T/sc.err" && grep -q "sc_out: [0-9]* files not written" "$T/sc.err" && ok ||
    bad "site-check --out under ulimit -f 0: rc $rc: $(cat "$T/sc.err")"

# 6. a rewritten file keeps its group and mode (root: any group; a user:
#    one of theirs other than the primary, else skipped)
if [ "$(id -u)" = 0 ]; then grp=$(awk -F: '$3 != 0 { print $3; exit }' /etc/group)
else grp=$(for g in $(id -G); do [ "$g" != "$(id -g)" ] && echo "$g" && break; done); fi
if [ -n "$grp" ]; then
    cp "$D/robot.yaml" "$T/owned.yaml"
    chgrp "$grp" "$T/owned.yaml" && chmod 0640 "$T/owned.yaml"
    "$R" calibrate-mount --camera "$D/camera.yaml" --map "$D/map.yaml" --robot "$T/owned.yaml" \
        --out "$T/owned.yaml" "$D"/straight_00*.png >/dev/null 2>"$T/owned.err"; rc=$?
    [ $rc = 0 ] && [ "$(stat -c '%a %g' "$T/owned.yaml")" = "640 $grp" ] && ! cmp -s "$D/robot.yaml" "$T/owned.yaml" &&
        ok || bad "calibrate-mount --out a 0640 file of group $grp: rc $rc, now $(stat -c '%a %g' "$T/owned.yaml"): $(cat "$T/owned.err")"
    printf 'old\n' >"$T/site/owned_map.yaml"
    chgrp "$grp" "$T/site/owned_map.yaml" && chmod 0604 "$T/site/owned_map.yaml"
    plan --grid 4x3 --map-out owned_map.yaml >/dev/null 2>"$T/plan.err"; rc=$?
    [ $rc = 0 ] && [ "$(stat -c '%a %g' "$T/site/owned_map.yaml")" = "604 $grp" ] && ok ||
        bad "plan --map-out a 0604 file of group $grp: rc $rc, now $(stat -c '%a %g' "$T/site/owned_map.yaml")"
else
    echo "skip: no second group to give a file"
fi

# 7. a name of the file system's longest length (NAME_MAX) is written
max=$(getconf NAME_MAX "$T" 2>/dev/null || echo 255)
long=$(printf "%0$((max - 5))d" 0 | tr 0 r).yaml
cp "$D/robot.yaml" "$T/$long"
"$R" calibrate-mount --camera "$D/camera.yaml" --map "$D/map.yaml" --robot "$T/$long" \
    --out "$T/$long" "$D"/straight_00*.png >/dev/null 2>"$T/long.err"; rc=$?
[ $rc = 0 ] && ! cmp -s "$D/robot.yaml" "$T/$long" && [ -z "$(ls -A "$T" | grep '^\.r')" ] && ok ||
    bad "calibrate-mount --out a $max-byte name: rc $rc: $(cat "$T/long.err")"

sh_done
