#!/bin/sh
# check_layers.sh looks at what it is given and fails loudly when it
# cannot: on copies of the tree's layered folders (hal, firmware, host)
# under a path with a space, a quote and a $,
# - the copy as it is passes;
# - a host/ header included from one file of hal/ is found, the file
#   named; included from many (one in each of several folders), each
#   of them named;
# - a tree whose hal/ holds that one file only (and each rule's folders
#   one file) is checked the same;
# - given a file, a folder without the layers, or a layer with no C
#   file, it exits 2 without the pass line; its standard input (a planted
#   include fed there) is never read for the files it was not given.
# usage: test_check_layers.sh SOURCE_DIR TMPDIR
set -u
SRC=$1
T=$2
rm -rf "$T"
mkdir -p "$T"
. "$(dirname "$0")/sh_check.sh"
C="$(dirname "$0")/check_layers.sh"
W="$T/src 'q\$x"

fresh() { # a copy of the tree's layers in $W
    rm -rf "$W"
    mkdir -p "$W"
    cp -R "$SRC/hal" "$SRC/firmware" "$SRC/host" "$W/"
}
# layers RC MESSAGE FILE...: check_layers.sh on $W exits RC, its output
# holds MESSAGE and names every FILE (relative to $W) on a line of its own
# include found
layers() {
    want=$1; msg=$2
    shift 2
    sh "$C" "$W" </dev/null >"$T/out" 2>&1
    rc=$?
    for f; do
        grep -qF "$W/$f:" "$T/out" || { bad "$f not named: rc $rc, $(cat "$T/out")"; return; }
    done
    [ $rc = "$want" ] && grep -qF -- "$msg" "$T/out" && ok || bad "want rc $want and '$msg', got rc $rc: $(cat "$T/out")"
}
HOST_H=$(cd "$SRC/host" && ls ./*.h | head -1)
HOST_H=${HOST_H#./}
plant() { printf '#include "%s"\n' "$HOST_H" >>"$W/$1"; }

fresh
layers 0 "layers: dependencies run one way"
plant hal/rl_view.c
layers 1 "layers: hal/ or firmware/ includes host/" hal/rl_view.c
fresh
plant hal/rl_view.c
plant hal/io/rl_png.c
plant firmware/core/rl_track.c
plant firmware/app/rl_run.c
layers 1 "layers: hal/ or firmware/ includes host/" hal/rl_view.c hal/io/rl_png.c firmware/core/rl_track.c \
    firmware/app/rl_run.c

# one file a folder: hal/ holds the one file that includes host/'s one header
rm -rf "$W"
for d in host hal hal/io firmware firmware/core firmware/include firmware/fuse firmware/app; do mkdir -p "$W/$d"; done
cp "$SRC/host/$HOST_H" "$W/host/"
printf 'int io;\n' >"$W/hal/io/io.c"
printf 'int core;\n' >"$W/firmware/core/rl_one.c"
printf 'int inc;\n' >"$W/firmware/include/rl_inc.h"
printf 'int fuse;\n' >"$W/firmware/fuse/fuse.c"
printf 'int app;\n' >"$W/firmware/app/app.c"
printf 'int hal;\n' >"$W/hal/cam.c"
layers 0 "layers: dependencies run one way"
plant hal/cam.c
layers 1 "layers: hal/ or firmware/ includes host/" hal/cam.c
# its standard input is no file to check: with the hub (rl_recog.c) the
# core's only file there is no pass to search, which fails loudly (2),
# while a call into the hub fed on its standard input is not read
printf 'int hal;\n' >"$W/hal/cam.c"
mv "$W/firmware/core/rl_one.c" "$W/firmware/core/rl_recog.c"
printf 'rl_recog_run(x);\n' | sh "$C" "$W" >"$T/stdin.out" 2>&1; rc=$?
[ $rc = 2 ] && ! grep -q "hub" "$T/stdin.out" && ! grep -q "run one way" "$T/stdin.out" && ok ||
    bad "only the hub in the core, a call into it on stdin: rc $rc, $(cat "$T/stdin.out")"

# what it cannot check fails loudly (2), never with the pass line
cannot() { # WHAT ARG...
    what=$1
    shift
    sh "$C" "$@" </dev/null >"$T/out" 2>&1
    rc=$?
    [ $rc = 2 ] && ! grep -q "run one way" "$T/out" && ok || bad "$what: rc $rc, $(cat "$T/out")"
}
cannot "a file for the source folder" "$W/hal/cam.c"
cannot "a folder without the layers" "$T/nothing"
cannot "no argument"
rm -f "$W/hal/cam.c" "$W/hal/io/io.c"
cannot "hal/ without a C file" "$W"

sh_done
