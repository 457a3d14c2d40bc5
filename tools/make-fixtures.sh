#!/bin/sh
# Regenerate the committed golden fixtures (tests/fixtures), or render a
# bigger set anywhere:
#
#   tools/make-fixtures.sh                    # the committed set
#   tools/make-fixtures.sh OUT COUNT [SEED]   # COUNT frames of every set into OUT
#
# Needs a built tree (make host). Every frame comes with its ground truth
# (NAME.yaml); tests compare recognition with that truth, never with
# earlier output.
set -eu
cd "$(dirname "$0")/.."
R=${RINGLOC_RENDER:-build/tools/ringloc-render}
[ -x "$R" ] || { echo "make-fixtures: $R not built; run 'make host' first" >&2; exit 1; }
if [ $# -ge 2 ]; then
    out=$1; count=$2; seed=${3:-11}
    for set in clean cluttered clutter_only glare border dim blur motion; do
        "$R" --out "$out" --set "$set" --count "$count" --seed "$seed" &
    done
    wait
    exit 0
fi
out=tests/fixtures
rm -rf "$out"
mkdir -p "$out"
"$R" --out "$out" --set clean --count 3 --seed 1
"$R" --out "$out" --set cluttered --count 4 --seed 1
"$R" --out "$out" --set clutter_only --count 3 --seed 1
"$R" --out "$out" --set glare --count 3 --seed 1
"$R" --out "$out" --set border --count 3 --seed 1
"$R" --out "$out" --set dim --count 2 --seed 1
"$R" --out "$out" --set blur --count 2 --seed 1
"$R" --out "$out" --set motion --count 2 --seed 1
"$R" --write-map "$out/site_map.yaml" --write-camera "$out/camera.yaml"
