#!/bin/sh
# Command-line behaviour as a user meets it: --help, exit codes, and one
# clear error line naming the option or file for every kind of bad input.
# usage: test_cli.sh RINGLOC TMPDIR
set -u
R=$1
T=$2
mkdir -p "$T"
. "$(dirname "$0")/sh_check.sh"

expect 0 'usage: ringloc COMMAND' -- "$R" --help
expect 2 "unknown command 'frobnicate'" -- "$R" frobnicate
expect 0 'usage: ringloc gen' -- "$R" gen --help
expect 0 'usage: ringloc plan' -- "$R" plan --help

# gen: bad ids, families, sizes, papers, files
expect 2 '--id: 31 is not in ring5 \(valid ids 1 .. 30\)' -- "$R" gen --id 31 --pdf "$T/x.pdf"
expect 2 '--id: 0 is not in ring5' -- "$R" gen --id 0 --pdf "$T/x.pdf"
expect 2 "--id: '3,x' is not a list of ids" -- "$R" gen --id 3,x --pdf "$T/x.pdf"
expect 2 "--id: '3,,4' is not a list of ids" -- "$R" gen --id 3,,4 --pdf "$T/x.pdf"
expect 2 "--id: '3,' is not a list of ids" -- "$R" gen --id 3, --pdf "$T/x.pdf"
expect 2 "--id: no ids given" -- "$R" gen --id "" --pdf "$T/x.pdf"
expect 2 "--family: 'ring9' is not a family" -- "$R" gen --family ring9 --id 3 --pdf "$T/x.pdf"
expect 2 "--family: 'ring1' is not a family" -- "$R" gen --family ring1 --id 1 --pdf "$T/x.pdf"
expect 2 '--diameter: 0.300 m fits no paper \(a4, letter, a3, tabloid\) within 5 mm margins' -- "$R" gen --id 3 --diameter 0.3 --pdf "$T/x.pdf"
expect 2 '--diameter: 0.210 m does not fit a4 paper within 5 mm margins: the largest that does is 0.199 m; or --paper a3' -- "$R" gen --id 3 --diameter 0.21 --paper a4 --pdf "$T/x.pdf"
expect 0 '1 landmark of ring5, 210 mm on a3' -- "$R" gen --id 3 --diameter 0.21 --pdf "$T/x.pdf"
expect 2 '--diameter: 0.005 m is below the smallest printable, 0.020 m' -- "$R" gen --id 3 --diameter 0.005 --pdf "$T/x.pdf"
expect 2 "--diameter: 'abc' is not a number" -- "$R" gen --id 3 --diameter abc --pdf "$T/x.pdf"
expect 2 "--paper: unknown paper 'b5'" -- "$R" gen --id 3 --paper b5 --pdf "$T/x.pdf"
expect 2 '--px: 5 is out of range \(16 .. 8000\)' -- "$R" gen --id 3 --png "$T/x.png" --px 5
expect 2 'nothing to write' -- "$R" gen --id 3
expect 2 'either --id or --map' -- "$R" gen --pdf "$T/x.pdf"
expect 1 '/nonexistent/dir/x.pdf' -- "$R" gen --id 3 --diameter 0.15 --pdf /nonexistent/dir/x.pdf
expect 1 "$(ere "$T/nomap.yaml"): No such file" -- "$R" gen --map "$T/nomap.yaml" --pdf "$T/x.pdf"
printf 'family: ring5\ndiameter: 0.2\nceiling_height: 2.5\nlandmarks:\n  - {id: 3, x: 0, y: 0}\n  - {id: 40, x: 1, y: 0}\n' >"$T/badid.yaml"
expect 1 "badid.yaml:6: landmarks\[1\].id: id 40 is not in ring5" -- "$R" gen --map "$T/badid.yaml" --pdf "$T/x.pdf"
printf 'family: ring5\ndiameter: 0.2\nceiling_height: 2.5\nlandmarks:\n  - {id: 3, x: 0, y: 0}\n  - {id: 4, x: 0.15, y: 0}\n' >"$T/overlap.yaml"
expect 1 "overlap.yaml:6: landmarks\[1\]: id 4 at \(0.15, 0\) overlaps landmarks\[0\] \(id 3 at \(0, 0\)\)" -- "$R" gen --map "$T/overlap.yaml" --pdf "$T/x.pdf"
# a map may repeat ids (a large site reuses a small family's): each entry is its own landmark
printf 'family: ring5\ndiameter: 0.2\nceiling_height: 2.5\nlandmarks:\n  - {id: 3, x: 0, y: 0}\n  - {id: 3, x: 1, y: 0}\n' >"$T/dup.yaml"
expect 0 "2 landmarks of ring5" -- "$R" gen --map "$T/dup.yaml" --pdf "$T/x.pdf"
printf 'family: ring5\ndiameter: 0.2\nlandmarks: []\n' >"$T/nokey.yaml"
expect 1 "nokey.yaml:1: ceiling_height: missing key" -- "$R" gen --map "$T/nokey.yaml" --pdf "$T/x.pdf"
printf 'family: ring5\ndiameter: [0.2\n' >"$T/broken.yaml"
expect 1 "broken.yaml:[0-9]+: malformed YAML" -- "$R" gen --map "$T/broken.yaml" --pdf "$T/x.pdf"
printf 'family: ring5\ndiameter: 0.2\nceiling_height: 2.5\nlandmarks:\n  - {id: 3, x: zero, y: 0}\n' >"$T/nan.yaml"
expect 1 "nan.yaml:5: landmarks\[0\].x: expected a number, got 'zero'" -- "$R" gen --map "$T/nan.yaml" --pdf "$T/x.pdf"
expect 0 'ringloc gen: 1 landmark' -- "$R" gen --id 25 --diameter 0.15 --pdf "$T/ok.pdf"

# plan --area: a small site from ring5's 30 ids, so they repeat; the JSON's counts by hand
# (6 m / 0.61 = 9 columns, 5 m / 0.61 = 8 rows) and the map it wrote
expect 0 '"cols": 9, "rows": 8, "landmarks": 72, "ids": [0-9]+, "even_parity": false, "min_view": 3, "k_achieved": 3, "all_unique": true' -- \
    "$R" plan --area 6x5 --pitch 0.61 --hfov 70 --distance 1.87 --ceiling-height 2.75 --map-out "$T/site.yaml"
n_lm=$(grep -c '{id:' "$T/site.yaml")
n_ids=$(grep -o '{id: [0-9]*' "$T/site.yaml" | sort -u | wc -l)
if [ "$n_lm" = 72 ] && [ "$n_ids" -le 30 ]; then ok; else
    bad "plan --area wrote $n_lm landmarks with $n_ids ids (want 72, at most 30)"; fi
expect 0 '"even_parity": true' -- "$R" plan --area 6x5 --pitch 0.61 --hfov 70 --distance 1.87 --ceiling-height 2.75 \
    --hamming 2 --map-out "$T/site2.yaml"
# even parity: each id's code has an even number of black zones
odd=$(grep -o '{id: [0-9]*' "$T/site2.yaml" | sed 's/{id: //' | sort -un | while read -r i; do
    b=0; v=$i; while [ "$v" -gt 0 ]; do b=$((b + v % 2)); v=$((v / 2)); done; [ $((b % 2)) = 1 ] && echo "$i"; done)
if [ -z "$odd" ]; then ok; else bad "--hamming 2 used odd-parity ids: $odd"; fi

# plan
expect 2 'give --camera FILE, or --hfov' -- "$R" plan --landmarks 30 --distance 1.87
expect 2 'give --distance' -- "$R" plan --landmarks 30 --hfov 70
expect 2 '--landmarks: how many' -- "$R" plan --hfov 70 --distance 1.87
expect 1 'need more than the 254 ids' -- "$R" plan --landmarks 300 --hfov 70 --distance 1.87
expect 1 'does not fit a4 paper' -- "$R" plan --landmarks 100 --hfov 70 --distance 1.87
expect 2 "--resolution: '640' is not a size" -- "$R" plan --landmarks 30 --hfov 70 --distance 1.87 --resolution 640
expect 1 "$(ere "$T/nocam.yaml"): No such file" -- "$R" plan --landmarks 30 --camera "$T/nocam.yaml" --distance 1.87
printf 'image_width: 640\nimage_height: 480\ncamera_matrix: {rows: 3, cols: 3, data: [457, 0, 319.5, 0, 457, 239.5, 0, 0]}\n' >"$T/badcam.yaml"
expect 1 'badcam.yaml:3: camera_matrix: rows x cols is 3x3 but data has 8 values' -- "$R" plan --landmarks 30 --camera "$T/badcam.yaml" --distance 1.87
printf 'image_width: 640\nimage_height: 480\ncamera_matrix: {rows: 3, cols: 3, data: [457, 0, 319.5, 0, 457, 239.5, 0, 0, 1]}\ndistortion_model: plumb_bob\ndistortion_coefficients: {rows: 1, cols: 5, data: [0, 0, 0, 0, 0]}\n' >"$T/cam.yaml"
expect 0 'family +ring5' -- "$R" plan --landmarks 30 --camera "$T/cam.yaml" --distance 1.87
expect 2 '--grid needs --ceiling-height' -- "$R" plan --hfov 70 --distance 1.87 --grid 3x2 --pitch 0.6
expect 0 'map +.*plan_map.yaml: 3x2 landmarks' -- "$R" plan --hfov 70 --ceiling-height 2.75 --camera-height 0.88 --grid 3x2 --pitch 0.6 --map-out "$T/plan_map.yaml" --pdf "$T/plan_map.pdf"
# the written map loads back and prints
expect 0 'ringloc gen: 6 landmarks of ring3' -- "$R" gen --map "$T/plan_map.yaml" --pdf "$T/plan_map2.pdf"

sh_done
