#!/bin/sh
# Bad input through every command, as a user or a broken file gives it
# (issue 18): each case must end within its time limit in exactly one
# error line that names the option or the file, with the exit status the
# command documents (2: a bad option, 1: a bad file), and print no NaN or
# infinity. The cases come in families: every numeric option with every
# kind of bad number, every file option with every kind of bad file,
# every key of every YAML loader with every kind of bad value.
# usage: test_bad_inputs.sh RINGLOC PATHS_DIR TMPDIR [K/N]
# K/N (0 <= K < N): only cases K+1, K+1+N, K+1+2N ..., each shard in
# its own TMPDIR; CTest runs N such shards side by side (some 820 program
# starts in all, 0.1 s of CPU each in the sanitizer build). Without it,
# every case.
. "$(dirname "$0")/sh_lib.sh"
shard=${4:-0/1}
shard_k=${shard%/*} shard_n=${shard#*/}
case $shard in
[0-9]/[1-9]) [ "$shard_k" -lt "$shard_n" ] ;;
*) false ;;
esac || { echo "test_bad_inputs.sh: K/N (0 <= K < N < 10) expected, not '$shard'" >&2; exit 2; }
ran=0

frame=$(ls "$D"/straight_*.png | head -1)
cam=$D/camera.yaml map=$D/map.yaml robot=$D/robot.yaml
n=0 desc=
# expect_case RC PATTERN COMMAND...: the case ends with status RC and exactly
# one line on stderr containing PATTERN
expect_case() {
    want=$1 pat=$2
    shift 2
    n=$((n + 1))
    [ $(((n - 1) % shard_n)) = "$shard_k" ] || return 0 # another shard's case
    ran=$((ran + 1))
    timeout 20 "$@" >"$T/out" 2>"$T/err" </dev/null; rc=$?
    lines=$(wc -l <"$T/err")
    if [ $rc = "$want" ] && [ "$lines" = 1 ] && grep -qF -- "$pat" "$T/err" &&
        ! grep -qiE '(^|[^a-z])(nan|inf)([^a-z]|$)' "$T/out"; then
        ok
    else
        bad "case $n${desc:+ ($desc)}: $* -> rc $rc (want $want), $lines lines: $(head -c 300 "$T/err")"
    fi
}

# --- numbers on the command line -------------------------------------------
# opt CMD OPTION "EXTRA BAD VALUES" ARGS...: CMD --OPTION v ARGS for every
# kind of bad number and the option's own out-of-range values
opt() {
    cmd=$1 o=$2 extra=$3
    shift 3
    for v in nan inf -inf 1e309 abc 1.5x "" 1e300 -1e300 $extra; do
        expect_case 2 "$o" "$R" "$cmd" "--$o" "$v" "$@"
    done
}
geom="--resolution 640x480 --hfov 70"
opt gen diameter "0 -0.21 0.001 20" --id 5 --pdf "$T/g.pdf"
opt gen margin "-1 200" --id 5 --pdf "$T/g.pdf"
opt gen px "0 2.5 -400 8001" --id 5 --png "$T/g.png"
opt plan distance "0 -1" --landmarks 30 $geom
opt plan hfov "0 180 -70" --landmarks 30 --resolution 640x480 --distance 1.87
opt plan landmarks "0 -3 2.5" $geom --distance 1.87
opt plan min-ring-px "0 -2" --landmarks 30 $geom --distance 1.87
opt plan diameter "0 -0.2" --landmarks 30 $geom --distance 1.87
opt plan ceiling-height "0 -2.75" --landmarks 30 $geom --camera-height 0.88
opt plan camera-height "-1" --landmarks 30 $geom --ceiling-height 2.75
opt plan pitch "0 -0.61" $geom --distance 1.87 --ceiling-height 2.75 --grid 6x5 --map-out "$T/m.yaml"
# plan --area's options in "$@" (the script's own arguments are read), so
# that a scratch path with a space stays one word
set -- --area 6x5 --pitch 0.61 $geom --distance 1.87 --ceiling-height 2.75 --map-out "$T/m.yaml"
opt plan hamming "0 3 2.5 -2" "$@"
opt plan min-view "0 2 101 2.5" "$@"
opt plan seed "-1 2.5 1e10" "$@"
for v in abc 0x10 10x0 nanxnan infx5 1e9x1 -5x5 10 "" 5x5x5x; do
    expect_case 2 "--area" "$R" plan --area "$v" --pitch 0.61 $geom --distance 1.87 --ceiling-height 2.75
done
expect_case 2 "--area needs --pitch" "$R" plan --area 6x5 $geom --distance 1.87 --ceiling-height 2.75
expect_case 2 "--area needs --ceiling-height" "$R" plan --area 6x5 --pitch 0.61 $geom --distance 1.87
expect_case 2 "give --area or --grid" "$R" plan "$@" --grid 6x5
expect_case 2 "--family" "$R" plan "$@" --family ring9
expect_case 2 "go with --area" "$R" plan $geom --distance 1.87 --landmarks 30 --hamming 2
expect_case 2 "would overlap" "$R" plan --area 6x5 --pitch 0.1 $geom --distance 1.87 --ceiling-height 2.75
expect_case 2 "more than a map holds" "$R" plan --area 600x600 --pitch 0.61 $geom --distance 1.87 --ceiling-height 2.75
expect_case 2 "too few whole landmarks" "$R" plan --area 60x40 --pitch 2.5 $geom --distance 1.87 --ceiling-height 2.75
expect_case 1 "/nonexistent/m.yaml" "$R" plan --area 6x5 --pitch 0.61 $geom --distance 1.87 --ceiling-height 2.75 \
    --map-out /nonexistent/m.yaml
opt site-check radius-px "0 -25 100000" --rounds 1 "$frame"
opt site-check diameter "0 -0.21" --camera "$cam" --distance 1.87 --rounds 1 "$frame"
opt site-check distance "0 -1.87" --camera "$cam" --rounds 1 "$frame"
opt site-check rounds "0 -1 2.5 100000000" "$frame"
opt site-check seed "-1 2.5" --rounds 1 "$frame"
opt detect min-score "-2 1.5" "$frame"
opt locate min-score "-2 1.5" --camera "$cam" --map "$map" --robot "$robot" "$frame"
opt locate readout "-1 201" --camera "$cam" --map "$map" --robot "$robot" "$frame"
expect_case 2 "--alone" "$R" locate --alone --readout 30 --camera "$cam" --map "$map" --robot "$robot" "$frame"
opt calibrate-offsets degree "0 4 2.5" --map "$map" --robot "$robot" --pose 1,1,0 --out "$T/o.yaml" "$frame"
opt run frames "-1 2.5" --config "$D/none.yaml"
# survey's options in "$@", as plan --area's above
set -- --camera "$cam" --robot "$robot" --origin 1 --axis 8 --out "$T/s.yaml"
opt survey diameter "0 -0.21 10" "$@" "$frame"
opt survey ceiling-height "0 -2.75" "$@" "$frame"
opt survey axis-distance "0 -1" "$@" "$frame"
opt survey gate "0 -0.3" "$@" "$frame"
opt survey origin "0 -1 2.5" --camera "$cam" --robot "$robot" --axis 8 --out "$T/s.yaml" "$frame"
opt survey axis "0 -1 2.5" --camera "$cam" --robot "$robot" --origin 1 --out "$T/s.yaml" "$frame"
opt monitor baud "0 -9600 12345 2.5" "$T/none.bin"
opt fuse rate "0 -1 1001 0.5" --odometry "$T/none.txt" "$T/none.bin"
opt fuse track "0 -0.33 11" --odometry "$T/none.txt" "$T/none.bin"
opt fuse wheel-noise "-0.001 2" --odometry "$T/none.txt" "$T/none.bin"
opt fuse time-offset "" --odometry "$T/none.txt" "$T/none.bin"
opt fuse baud "0 -9600 12345 2.5" --odometry "$T/none.txt" "$T/none.bin"

# option values that are not numbers but are still wrong
for v in 0x0 640x 640 x480 -640x480 640x-480 99999x480 640x480x3 abc 1e309x480; do
    expect_case 2 "resolution" "$R" plan --resolution "$v" --hfov 70 --landmarks 30 --distance 1.87
done
for v in 0x5 5x0 65536x65536 100000x100000 5 5x x5 axb -3x5; do
    expect_case 2 "grid" "$R" plan $geom --distance 1.87 --ceiling-height 2.75 --grid "$v" --pitch 0.61
done
for v in nan,nan,nan inf,0,0 1,2 1,2,3,4 1,,3 a,b,c 1e309,0,0 1,2,3x ""; do
    expect_case 2 "pose" "$R" calibrate-offsets --map "$map" --robot "$robot" --pose "$v" --out "$T/o.yaml" "$frame"
done
for v in 0 31 -1 abc 5,,6 5, ,5 1e3 2.5; do
    expect_case 2 "id" "$R" gen --id "$v" --pdf "$T/g.pdf"
done
for v in ring1 ring9 ring ring5x "" RING5; do
    expect_case 2 "family" "$R" detect --family "$v" "$frame"
done
for v in sometimes "" ALWAYS 1; do
    expect_case 2 "local" "$R" detect --local "$v" "$frame"
done
for v in a5 A4 "" b4; do
    expect_case 2 "paper" "$R" gen --id 5 --paper "$v" --pdf "$T/g.pdf"
done
expect_case 2 "bogus" "$R" detect --bogus "$frame"
expect_case 2 "bogus" "$R" bogus
expect_case 2 "diameter" "$R" gen --id 5 --pdf "$T/g.pdf" --diameter
expect_case 2 "fit" "$R" gen --id 5 --paper a4 --diameter 0.25 --pdf "$T/g.pdf"

# --- files -----------------------------------------------------------------
mkdir -p "$T/folder"
: >"$T/empty.yaml"
head -c 4096 /dev/urandom >"$T/garbage.yaml"
printf '\211PNG\r\n\032\n' >"$T/trunc.png"
head -c 3000 "$frame" >"$T/half.png"
: >"$T/empty.png"
printf 'P5\n640 480\n255\n' >"$T/pnm.png"
mkfifo "$T/fifo" # a FIFO where a file is expected: refused at once, never waited on (issue 28)
# file CMD OPTION ARGS...: CMD --OPTION f ARGS for every kind of bad file
file() {
    cmd=$1 o=$2
    shift 2
    for f in "$T/absent.yaml" "$T/folder" "$T/empty.yaml" "$T/garbage.yaml" "$frame" "$T/fifo"; do
        expect_case 1 "$(basename "$f")" "$R" "$cmd" "--$o" "$f" "$@"
    done
}
file locate camera --map "$map" --robot "$robot" "$frame"
file locate map --camera "$cam" --robot "$robot" "$frame"
file locate robot --camera "$cam" --map "$map" "$frame"
file locate offsets --camera "$cam" --map "$map" --robot "$robot" "$frame"
file run config
file gen map --pdf "$T/g.pdf"
file detect map "$frame"
file plan camera --landmarks 30 --distance 1.87
file survey camera --robot "$robot" --origin 1 --axis 8 --out "$T/s.yaml" "$frame"
file survey robot --camera "$cam" --origin 1 --axis 8 --out "$T/s.yaml" "$frame"
file survey map "$@" "$frame"
printf '0 0 0 0\n0.1 0.1 0 0\n' >"$T/odo.txt"
file fuse odometry "$T/odo.txt"
for f in "$T/absent.bin" "$T/folder" "$T/empty.yaml" "$T/garbage.yaml" "$frame" "$T/fifo"; do
    expect_case 1 "$(basename "$f")" "$R" fuse --odometry "$T/odo.txt" "$f"
done
for bad in '0 0 0' '0 0 0 0 0' '0 a 0 0' '0 nan 0 0' '0 1e309 0 0'; do
    printf '0.5 0 0 0\n%s\n' "$bad" >"$T/bad_odo.txt"
    desc="$bad" expect_case 1 "bad_odo.txt:2" "$R" fuse --odometry "$T/bad_odo.txt" "$T/odo.txt"
done
# odometry whose times jump (epoch seconds after relative ones): refused, never replayed for hours
for last in 1700000000 1e300; do
    printf '0 0 0 0\n0.1 0.1 0 0\n%s 0.2 0 0\n' "$last" >"$T/jump_odo.txt"
    desc="$last" expect_case 1 "more than a day: do they jump" "$R" fuse --odometry "$T/jump_odo.txt" "$T/odo.txt"
done
desc=
expect_case 2 "origin" "$R" survey "$@" --origin 40 "$frame"
expect_case 2 "same landmark" "$R" survey --camera "$cam" --robot "$robot" --origin 8 --axis 8 --out "$T/s.yaml" "$frame"
expect_case 2 "not both" "$R" survey "$@" --ceiling-height 2.75 --axis-distance 3 "$frame"
expect_case 2 "required" "$R" survey --camera "$cam" "$frame"
# detect's JSON lines as survey frames
"$R" detect "$frame" >"$T/good.jsonl"
for bad in 'not json' '[1, 2]' '{"image": "a.png"}' '{"landmarks": [{"id": 40, "u": 1, "v": 2, "radius": 20}]}' \
    '{"landmarks": [{"id": 5, "u": "x", "v": 2, "radius": 20}]}' '{"width": 320, "height": 240, "landmarks": []}' \
    '{"landmarks": [{"id": 5, "u": 1e309, "v": 2, "radius": 20}]}' '{"landmarks": [{"id": 5, "u": 1, "v": 2, "radius": -3}]}'; do
    { cat "$T/good.jsonl"; printf '%s\n' "$bad"; } >"$T/bad.jsonl"
    desc="$bad" expect_case 1 "bad.jsonl:2" "$R" survey "$@" "$T/bad.jsonl"
done
desc=
: >"$T/empty.jsonl"
expect_case 1 "empty.jsonl" "$R" survey "$@" "$T/empty.jsonl"
expect_case 1 "folder" "$R" survey "$@" "$T/folder"
expect_case 1 "absent.png" "$R" survey "$@" "$T/absent.png"
for f in "$T/absent.png" "$T/folder" "$T/empty.png" "$T/trunc.png" "$T/half.png" "$T/pnm.png" "$T/garbage.yaml" \
    "$T/fifo"; do
    expect_case 1 "$(basename "$f")" "$R" detect "$f"
done
expect_case 1 "site-check" "$R" site-check --rounds 1 "$T/folder"

# --- keys of the YAML loaders ----------------------------------------------
# key LOADER-OPTION FILE KEY-PATTERN SED: the file with SED applied, given
# to locate as LOADER-OPTION; the error names the new file
keyed=0
key() {
    o=$1 src=$2 what=$3 s=$4
    keyed=$((keyed + 1))
    f=$T/k$keyed.yaml desc="$what: $s"
    sed "$s" "$src" >"$f"
    cmp -s "$f" "$src" && { bad "case $((n + 1)): sed '$s' changed nothing in $src"; n=$((n + 1)); return; }
    set -- --camera "$cam" --map "$map" --robot "$robot"
    case $o in
    camera) set -- --camera "$f" --map "$map" --robot "$robot" ;;
    map) set -- --camera "$cam" --map "$f" --robot "$robot" ;;
    robot) set -- --camera "$cam" --map "$map" --robot "$f" ;;
    esac
    expect_case 1 "k$keyed.yaml:" "$R" locate "$@" "$frame"
}
for v in nan .nan .inf -.inf 1e309 abc "[1]" "{a: 1}" "" 0 -0.21 100; do
    key map "$map" diameter "s/^diameter: .*/diameter: $v/"
done
for v in nan .inf abc "[2]" 0 -2.75 1e6; do
    key map "$map" ceiling_height "s/^ceiling_height: .*/ceiling_height: $v/"
done
for v in ring9 ring1 "" 5 "[ring5]"; do
    key map "$map" family "s/^family: .*/family: $v/"
done
for v in 0 31 -1 1000 abc 2.5 nan; do
    key map "$map" id "0,/{id: 1,/s//{id: $v,/"
done
for v in nan .inf abc 1e308 "[0]"; do
    key map "$map" x "0,/x: 0.3050/s//x: $v/"
    key map "$map" y "0,/y: 0.3050}/s//y: $v}/"
done
# issue 28: one document per file; a quoted, tagged or hex number is no
# number; sigmas come in pairs, above 0; an id past 2^31 is out of range
key map "$map" "a second document" '$a ---\nfamily: ring6'
key map "$map" "a malformed second document" '$a ---\nfamily: ['
key map "$map" "text after the end marker" '$a ...\njunk'
key map "$map" "sigma_x alone" "0,/{id: 1, x: 0.3050, y: 0.3050}/s//{id: 1, x: 0.3050, y: 0.3050, sigma_x: 0.001}/"
key map "$map" "sigma 0" "0,/{id: 1, x: 0.3050, y: 0.3050}/s//{id: 1, x: 0.3050, y: 0.3050, sigma_x: 0, sigma_y: 0.001}/"
for v in '!!str 0.88' '"0.88"' "'0.88'" 0x1.cp-1 0X1P0; do
    key robot "$robot" "z $v" "s/z: 0.8800/z: $v/"
done
# the robot's rocking (rad, 0 .. 0.3)
for v in nan .inf abc -0.01 0.5 "[0]" '"0.01"'; do
    key robot "$robot" rocking "s/^rocking: .*/rocking: $v/"
done
sed "0,/{id: 1,/s//{id: 2147483648,/" "$map" >"$T/id31.yaml"
expect_case 1 "landmarks[0].id: 2147483648 is out of range" "$R" detect --map "$T/id31.yaml" "$frame"
key map "$map" "overlapping landmarks" "0,/{id: 8, x: 0.9150/s//{id: 8, x: 0.4050/"
key map "$map" "doubled key" "0,/{id: 1, x: 0.3050/s//{id: 1, x: 0.3050, x: 1/"
key map "$map" "no family" "/^family:/d"
key map "$map" "no diameter" "/^diameter:/d"
key map "$map" "no ceiling" "/^ceiling_height:/d"
key map "$map" "no landmarks" "/^landmarks:/,\$d"
key map "$map" "landmark without x" "0,/{id: 1, x: 0.3050, y/s//{id: 1, y/"
key map "$map" "landmarks a number" "s/^landmarks:.*/landmarks: 5/;/^  - /d"
key map "$map" "landmark a list" "0,/  - {id: 1, x: 0.3050, y: 0.3050}/s//  - [1, 0.3, 0.3]/"
key map "$map" "tabs" "s/^diameter: /diameter:\t/;s/^  - /\t- /"
key map "$map" "unterminated" "s/^  - {id: 1, x: 0.3050, y: 0.3050}/  - {id: 1, x: 0.3050, y: 0.3050/"
for v in nan .inf abc 1e309 "[0]" ""; do
    for k in x y z yaw; do
        key robot "$robot" "$k" "s/\\b$k: [-0-9.]*/$k: $v/"
    done
done
for v in nan 1 -0.6 abc "[0]"; do
    key robot "$robot" roll "s/yaw: \([-0-9.]*\)}/yaw: \1, roll: $v}/"
    key robot "$robot" pitch "s/yaw: \([-0-9.]*\)}/yaw: \1, pitch: $v}/"
done
key robot "$robot" "z negative" "s/z: 0.8800/z: -0.88/"
key robot "$robot" "z above the ceiling" "s/z: 0.8800/z: 3/"
key robot "$robot" "no mount" "s/camera_mount/camera_mnt/"
key robot "$robot" "doubled z" "s/z: 0.8800/z: 0.88, z: 5/"
for v in 0 -640 abc 1e9 nan 2.5; do
    key camera "$cam" image_width "s/^image_width: .*/image_width: $v/"
    key camera "$cam" image_height "s/^image_height: .*/image_height: $v/"
done
for v in "1e-300, 0, 322.7, 0, 1e-300" "nan, 0, 322.7, 0, 457" "-457, 0, 322.7, 0, 457" "457, 0, 1e9, 0, 457" \
    "457, 0, 322.7, 0, .inf" "457, 0, abc, 0, 457" "457, 0, 322.7"; do
    key camera "$cam" camera_matrix "0,/data: \[457.007362, 0, 322.7, 0, 457.921377/s//data: [$v/"
done
for v in "nan, 0, 0, 0, 0" "1e9, 0, 0, 0, 0" "0, 0, 0" "0, 0, 0, 0, 0, 0, 0" "abc, 0, 0, 0, 0"; do
    key camera "$cam" distortion "s/data: \[-0.12, 0.08, 0.0004, -0.0003, 0\]/data: [$v]/"
done
for v in fisheye_x "" "[plumb_bob]" 5; do
    key camera "$cam" distortion_model "s/^distortion_model: .*/distortion_model: $v/"
done
key camera "$cam" "4 coefficients, no model" "/^distortion_model/d;s/data: \[-0.12, 0.08, 0.0004, -0.0003, 0\]/data: [-0.12, 0.08, 0.0004, -0.0003]/;0,/cols: 5/s//cols: 4/"
key camera "$cam" "fisheye with 5" "s/^distortion_model: .*/distortion_model: equidistant/"
key camera "$cam" "fisheye_model 1 with plumb_bob" "s/^distortion_model: .*/distortion_model: plumb_bob\nfisheye_model: 1/"
key camera "$cam" "fisheye_model 2" "s/^distortion_model: .*/fisheye_model: 2/"
key camera "$cam" "tilted sensor" "s/^distortion_model: .*/distortion_model: rational_polynomial/;s/data: \[-0.12, 0.08, 0.0004, -0.0003, 0\]/data: [-0.12, 0.08, 0.0004, -0.0003, 0, 0, 0, 0, 0, 0, 0, 0, 0.01, 0]/;0,/cols: 5/s//cols: 14/"
key camera "$cam" "7 coefficients" "/^distortion_model/d;s/data: \[-0.12, 0.08, 0.0004, -0.0003, 0\]/data: [-0.12, 0.08, 0.0004, -0.0003, 0, 0, 0]/;0,/cols: 5/s//cols: 7/"
key camera "$cam" "no size, none given" "/^image_width/d;/^image_height/d"
key camera "$cam" "rows 65536" "0,/rows: 3/s//rows: 65536/;0,/cols: 3/s//cols: 65536/"
key camera "$cam" "rows 0" "0,/rows: 3/s//rows: 0/"
key camera "$cam" "rows -3" "0,/rows: 3/s//rows: -3/"
key camera "$cam" "no camera_matrix" "/^camera_matrix:/,/^  data/d"
key camera "$cam" "doubled image_width" "s/^image_width: 640/image_width: 640\nimage_width: 320/"
key camera "$cam" "rows 3 cols 3 data 12" "0,/data: \[457.007362, 0, 322.7, 0, 457.921377, 237.4, 0, 0, 1\]/s//data: [457, 0, 322, 0, 457, 237, 0, 0, 1, 0, 0, 0]/"

# the run configuration
cfg() {
    cat <<CFG
camera: {backend: png, device: $T/frames.txt, width: 640, height: 480, rate: 20}
calibration: $cam
map: $map
robot: $robot
serial: {device: $T/serial.bin, baud: 115200}
CFG
}
ls "$D"/straight_*.png >"$T/frames.txt"
cfg >"$T/run.yaml"
rkey() { # SED [PATTERN]: run --config with the edited file; the error names
    # PATTERN (default: the edited file)
    keyed=$((keyed + 1))
    f=$T/k$keyed.yaml desc=$1
    sed "$1" "$T/run.yaml" >"$f"
    cmp -s "$f" "$T/run.yaml" && { bad "case $((n + 1)): sed '$1' changed nothing"; n=$((n + 1)); return; }
    expect_case 1 "${2:-k$keyed.yaml}" "$R" run --config "$f" --frames 3
}
for v in bogus "" 5 "[png]"; do rkey "s/backend: png/backend: $v/"; done
for v in -640 abc 100000 nan 320; do rkey "s/width: 640/width: $v/"; rkey "s/height: 480/height: $v/"; done
for v in -20 nan .inf abc 1e9; do rkey "s/rate: 20/rate: $v/"; done
for v in 0 -9600 12345 abc nan; do rkey "s/baud: 115200/baud: $v/"; done
for v in -5 1e300 nan abc; do rkey "\$a log_interval: $v"; done
for v in sometimes 5; do rkey "\$a local: $v"; done
rkey "s|calibration: .*|calibration: $T/absent.yaml|" absent.yaml
rkey "s|map: .*|map: $T/garbage.yaml|" garbage.yaml
rkey "s|robot: .*|robot: $T/folder|" folder
rkey "s|device: $T/frames.txt|device: $T/absent.txt|" absent.txt
: >"$T/empty_list.txt"
rkey "s|device: $T/frames.txt|device: $T/empty_list.txt|" "empty_list.txt: no PNG frames"
rkey "s|device: $T/frames.txt|device: $T/folder|" "folder: no PNG frames"
for v in maybe 2 "[true]"; do rkey "s/rate: 20/rate: 20, loop: $v/" camera.loop; done
for v in -5 0 abc 1e9 nan manual; do rkey "s/rate: 20/rate: 20, exposure: $v/" camera.exposure; done
for v in -1 0 abc 1e9 .inf; do rkey "s/rate: 20/rate: 20, gain: $v/" camera.gain; done
for v in -1 abc 500 nan .inf; do rkey "s/rate: 20/rate: 20, readout: $v/" camera.readout; done
for v in sometimes 5 start; do rkey "s/rate: 20/rate: 20, stamp: $v/" camera.stamp; done
rkey "/^map:/d"
rkey "/^serial:/d"
rkey "s/^camera: {backend: png/camera: {backend: png, rate: 5/"
rkey "\$a camera: {backend: png}"
rkey "s/^robot:/robt:/"
rkey "s/^log_interval/log_intervl/;\$a log_intervl: 5" log_intervl
for v in "{dir: r, every: 0}" "{dir: r, every: abc}" "{dir: r, max_mb: 0}" "{dir: r, max_mb: nan}" "{every: 3}" "5" "{dir: r, evry: 3}"; do
    rkey "\$a record: $v" record
done
rkey "\$a recognition: {locl: auto}" recognition.locl
rkey "\$a recognition: 5" recognition

# every case of this shard ran (none passed over by a variable a case's loop reused)
[ "$ran" = $(((n - shard_k + shard_n - 1) / shard_n)) ] || bad "shard $shard ran $ran of its cases"
echo "$ran of $n bad inputs (shard $shard): $pass passed, $fail failed"
[ "$fail" = 0 ]
