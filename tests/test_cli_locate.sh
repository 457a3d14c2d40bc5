#!/bin/sh
# ringloc locate and calibrate-offsets as a user runs them, on rendered
# path frames (DIR holds map.yaml, camera.yaml, robot.yaml, frames + truth).
# usage: test_cli_locate.sh RINGLOC DIR TMPDIR
set -u
R=$1
D=$2
T=$3
mkdir -p "$T"
. "$(dirname "$0")/sh_check.sh"

# truth of a frame: "x y yaw"
truth() { sed -n 's/^robot: {x: \([-0-9.]*\), y: \([-0-9.]*\), yaw: \([-0-9.]*\)}/\1 \2 \3/p' "$D/$1.yaml"; }
# pose of a JSON line: "x y yaw"
pose() { sed -n 's/.*"pose": {"x": \([-0-9.]*\), "y": \([-0-9.]*\), "yaw": \([-0-9.]*\).*/\1 \2 \3/p' "$1"; }
near() { # a b tol
    awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { split(a, p, " "); split(b, q, " ");
        dx = p[1] - q[1]; dy = p[2] - q[2]; exit !(sqrt(dx*dx + dy*dy) <= t) }'
}

# locate with the folder's camera, map and robot (each path one word, a
# space in it or not), then ARGS...
locate() { "$R" locate --camera "$D/camera.yaml" --map "$D/map.yaml" --robot "$D/robot.yaml" "$@"; }
expect 0 'usage: ringloc locate' -- "$R" locate --help
expect 2 '--camera, --map and --robot are required' -- "$R" locate "$D/straight_000.png"

# the happy path: pose within a centimetre of the truth, JSON fields there
locate "$D/straight_004.png" >"$T/loc.json" 2>"$T/err"
if [ $? = 0 ] && grep -q '"landmarks_used": ' "$T/loc.json" && near "$(pose "$T/loc.json")" "$(truth straight_004)" 0.01; then ok
else bad "locate straight_004: $(cat "$T/loc.json" "$T/err")"; fi

# bad input: one clear line naming the file and key
"$R" gen --id 3 --png "$T/small.png" --px 100 2>/dev/null
expect 1 "small.png: image is [0-9]+x[0-9]+ but .*camera.yaml \(image_width, image_height\) is for 640x480" -- locate "$T/small.png"
printf 'camera_mount: {x: 0, y: 0}\n' >"$T/robot_noz.yaml"
expect 1 "robot_noz.yaml:1: camera_mount.z: missing key" -- "$R" locate --camera "$D/camera.yaml" --map "$D/map.yaml" --robot "$T/robot_noz.yaml" "$D/straight_000.png"
sed 's/distortion_model: plumb_bob/distortion_model: rational_polynomial/; s/data: \[-0.12, 0.08, 0.0004, -0.0003, 0\]/data: [-0.12, 0.08, 0.0004, -0.0003]/; 0,/cols: 5/s//cols: 4/' "$D/camera.yaml" >"$T/cam_bad.yaml"
expect 1 "cam_bad.yaml:[0-9]+: distortion_coefficients: rational_polynomial has 5, 8, 12 or 14 coefficients, not 4" -- "$R" locate --camera "$T/cam_bad.yaml" --map "$D/map.yaml" --robot "$D/robot.yaml" "$D/straight_000.png"
printf 'camera_mount: {x: 0, y: 0, z: 3.5}\n' >"$T/robot_high.yaml"
expect 1 "camera_mount.z 3.500 m is not below the ceiling" -- "$R" locate --camera "$D/camera.yaml" --map "$D/map.yaml" --robot "$T/robot_high.yaml" "$D/straight_000.png"
# an unreadable image: an error line, and the next image still gets its pose
printf 'garbage' >"$T/broken.png"
locate "$T/broken.png" "$D/straight_001.png" >"$T/two.json" 2>"$T/err"
if [ $? = 1 ] && grep -q 'broken.png: not a PNG file' "$T/err" && grep -q '"pose": {' "$T/two.json"; then ok
else bad "broken + good: $(cat "$T/err")"; fi

# the paper's offset maps: calibrate at a known pose, locate with them
set -- $(truth straight_000)
expect 0 "calibrate-offsets: [0-9]+ landmarks, degree 2" -- "$R" calibrate-offsets --map "$D/map.yaml" --robot "$D/robot.yaml" --pose "$1,$2,$3" --out "$T/offsets.yaml" "$D/straight_000.png"
locate --offsets "$T/offsets.yaml" "$D/straight_006.png" >"$T/off.json" 2>"$T/err"
if [ $? = 0 ] && near "$(pose "$T/off.json")" "$(truth straight_006)" 0.03; then ok
else bad "locate --offsets: $(cat "$T/off.json" "$T/err")"; fi
expect 2 "--pose: 'a,b' is not X,Y,YAW" -- "$R" calibrate-offsets --map "$D/map.yaml" --robot "$D/robot.yaml" --pose a,b --out "$T/o.yaml" "$D/straight_000.png"

sh_done
