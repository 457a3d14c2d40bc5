#!/bin/sh
# make demo: the firmware on a bundled drive, no camera and no robot.
#
# A robot drives straight, around a rectangle and in a circle under a
# ceiling of ring landmarks (the paper's set-up: 640x480 camera 1.87 m
# below the ceiling, 0.21 m landmarks 0.61 m apart, a camera mounted off
# the robot's centre and 1.4 degrees off vertical, the robot rocking about
# half a degree). `ringloc calibrate-mount` first measures the mount's
# tilt from the drive's frames. `ringloc-fw` (the robot's firmware) plays the frames through its
# PNG-sequence camera and sends pose frames over a pseudo-terminal, as it
# would over the serial line to the Pioneer; `ringloc monitor` decodes the
# other end. Then a table per frame, a summary against the ground truth, an
# annotated frame and a trajectory plot.
set -eu
cd "$(dirname "$0")/.."
B=${BUILD:-build}
OUT=$B/demo
DRIVE=$OUT/drive
R=$B/host/ringloc
FW=$B/firmware/app/ringloc-fw
REN=$B/tools/ringloc-render
mkdir -p "$OUT"
# the drive: rendered once with its ground truth, then reused
if [ ! -f "$DRIVE/complete" ]; then
    echo "demo: rendering the drive (55 frames with ground truth) ..."
    rm -rf "$DRIVE"
    sh tools/demo_drive.sh "$REN" "$DRIVE"
fi
DRIVE=$(cd "$DRIVE" && pwd)
# the robot file as a user writes it (the tape measure's offsets, no tilt),
# then the mount's tilt measured from the frames
printf 'camera_mount: {x: 0.12, y: -0.03, z: 0.88, yaw: 0.02}\n' >"$DRIVE/robot_measured.yaml"
echo "demo: ringloc calibrate-mount (the camera's tilt on the robot, from the drive's frames)"
"$R" calibrate-mount --camera "$DRIVE/camera.yaml" --map "$DRIVE/map.yaml" --robot "$DRIVE/robot_measured.yaml" \
    --out "$DRIVE/robot.yaml" "$DRIVE"/straight_*.png "$DRIVE"/rect_*.png
echo "demo: the renderer's truth: $(grep -o 'roll: [-0-9.]*, pitch: [-0-9.]*' "$DRIVE/robot_true.yaml")"
(cd "$DRIVE" && ls straight_*.png && ls rect_*.png && ls circle_*.png) >"$DRIVE/frames.txt"
cat >"$OUT/ringloc.yaml" <<CFG
# the firmware's configuration for the demo (see README: Files)
camera:
  backend: png
  device: $DRIVE/frames.txt
  width: 640
  height: 480
  rate: 15
calibration: $DRIVE/camera.yaml
map: $DRIVE/map.yaml
robot: $DRIVE/robot.yaml
serial:
  device: ttyRINGLOC
  baud: 115200
recognition:
  local: always
CFG

rm -f "$OUT/ttyRINGLOC" "$OUT/poses.jsonl"
"$R" monitor --pty "$OUT/ttyRINGLOC" >"$OUT/poses.jsonl" 2>"$OUT/monitor.log" &
MON=$!
i=0
while [ ! -L "$OUT/ttyRINGLOC" ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
echo "demo: ringloc-fw --config $OUT/ringloc.yaml  (pose frames -> $OUT/ttyRINGLOC -> ringloc monitor)"
"$FW" --config "$OUT/ringloc.yaml"
i=0
while kill -0 $MON 2>/dev/null && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
kill $MON 2>/dev/null || true
wait $MON 2>/dev/null || true
echo "demo: first frames decoded by ringloc monitor:"
head -3 "$OUT/poses.jsonl"
echo
"$R" locate --camera "$DRIVE/camera.yaml" --map "$DRIVE/map.yaml" --robot "$DRIVE/robot.yaml" \
    --annotate "$OUT/annotated.png" "$DRIVE/rect_007.png" >/dev/null
"$B/tools/ringloc-demo-report" "$DRIVE/frames.txt" "$OUT/poses.jsonl" "$DRIVE/map.yaml" "$OUT/trajectory.png"
echo
echo "demo: wrote $OUT/annotated.png (what was recognized in one frame)"
echo "demo:       $OUT/trajectory.png (poses sent against the true path)"
echo "demo:       $OUT/poses.jsonl (every decoded frame)"
