#!/bin/sh
# rl_fuse from the truth (issue 27): `ringloc run` with the PNG-sequence
# camera over the drives rendered for it (straight and circle, 0.1 m a
# frame) and over the path drives' rect, pose frames into a file, decoded
# by `ringloc monitor`; then test_fuse_drive times them along the drives
# beside simulated odometry and judges the fused pose at every tick.
# usage: test_fuse_drive.sh RINGLOC TEST_FUSE_DRIVE FUSE_DIR PATHS_DIR TMPDIR
R=$1
X=$2
F=$(cd "$3" && pwd)
P=$(cd "$4" && pwd)
T=$5
rm -rf "$T"
mkdir -p "$T"
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
frames "$F" "straight_*.png circle_*.png" fuse
frames "$P" "straight_*.png rect_*.png" paths
"$X" "$F" "$T/fuse.jsonl" "$P" "$T/paths.jsonl" "$T/fuse.png"
