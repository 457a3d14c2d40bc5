#!/bin/sh
# The renderer's frames are the suite's truth, and its tests' counts were
# set on them: a change to the renderer must draw the same bytes. Three
# renders (the moving set with rocking, glare, a rolling shutter on a
# path) against the sums of the same renders by the renderer of the
# eighth session's start (tests/frames/render_sums.txt; gcc on x86-64,
# the host build: the sanitizer build's clang frames differ and are
# held by search_twins_frame_same instead).
# usage: render_golden.sh RENDER TMPDIR
set -u
R=$1 T=$2
SUMS=$(cd "$(dirname "$0")" && pwd)/frames/render_sums.txt
rm -rf "$T"
mkdir -p "$T"
"$R" --out "$T/m" --set moving --count 2 --seed 7 --rock 0.03 >/dev/null &&
    "$R" --out "$T/g" --set glare --count 1 --seed 3 >/dev/null &&
    "$R" --out "$T/p" --path circle --frames 2 --rolling 33,1.0,1.6667 >/dev/null ||
    { echo "FAIL: render_golden: the renderer failed"; exit 1; }
cd "$T" || exit 1
if ! sha256sum -c --quiet "$SUMS"; then
    echo "FAIL: render_golden: the renderer no longer draws the frames the suite's counts were set on"
    exit 1
fi
echo "render_golden: 10 files, the same bytes"
