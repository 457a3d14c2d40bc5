#!/bin/sh
# The demo's drive, rendered with its ground truth: the paper's set-up
# (tools/demo.sh says what it is), a robot driving straight (15 frames),
# around a rectangle (20) and in a circle (20), its camera mounted off the
# robot's centre and off vertical, the robot rocking about half a degree.
# `make demo` plays it through the firmware; `make bench` tracks it.
# usage: demo_drive.sh RENDERER DIR  (writes DIR/map.yaml, camera.yaml,
# robot_true.yaml and the frames with their truth; DIR/complete last, when
# every render has finished)
set -eu
REN=$1 DRIVE=$2
MOUNT=0.12,-0.03,0.02,0.02,-0.015
ROCK=0.01
mkdir -p "$DRIVE"
"$REN" --write-map "$DRIVE/map.yaml" --write-camera "$DRIVE/camera.yaml" \
    --write-robot "$DRIVE/robot_true.yaml" --mount $MOUNT --rock $ROCK
pids=
for path in straight:15 rect:20 circle:20; do
    "$REN" --out "$DRIVE" --path "${path%:*}" --frames "${path#*:}" --mount $MOUNT --rock $ROCK &
    pids="$pids $!"
done
failed=0
for p in $pids; do
    wait "$p" || failed=1
done
if [ $failed = 1 ]; then
    echo "demo_drive.sh: the renderer failed ($REN); $DRIVE is incomplete" >&2
    exit 1
fi
: >"$DRIVE/complete"
