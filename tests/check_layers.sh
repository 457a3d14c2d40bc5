#!/bin/sh
# Dependencies run one way: nothing under hal/ or firmware/ includes a
# header of host/, the core includes none of hal/ (devices and the I/O
# library hal/io) or firmware/app, and the I/O library none of the
# devices or the app.  Usage: check_layers.sh SOURCE_DIR
src=${1:?usage: check_layers.sh SOURCE_DIR}
status=0
names() { ls "$@" 2>/dev/null | xargs -n1 basename | tr '\n' '|' | sed 's/|$//'; }
forbid() { # what: folders, headers
    what=$1; dirs=$2; headers=$3
    if [ -n "$headers" ] && grep -rnE "#include \"($headers)\"" $dirs; then
        echo "layers: $what"
        status=1
    fi
}
forbid "hal/ or firmware/ includes host/" "$src/hal $src/firmware" "$(names "$src"/host/*.h)"
forbid "the core includes hal/ or firmware/app" "$src/firmware/core $src/firmware/include" \
    "$(names "$src"/hal/*.h "$src"/hal/io/*.h "$src"/firmware/app/*.h)"
forbid "the I/O library includes a device of hal/ or firmware/app" "$src/hal/io" \
    "$(names "$src"/hal/*.h "$src"/firmware/app/*.h)"
forbid "the public API includes an internal header" "$src/firmware/include" \
    "$(names "$src"/firmware/core/*.h "$src"/firmware/fuse/*.h)"
forbid "the controller's filter (firmware/fuse) includes more than the public API" "$src/firmware/fuse" \
    "$(names "$src"/firmware/core/*.h "$src"/hal/*.h "$src"/hal/io/*.h "$src"/firmware/app/*.h)"
# The recognizer's hub (rl_recog.c) runs the passes; none of them calls
# back into it (rl_local -> rl_locate -> rl_recog -> rl_local was a circle).
if grep -nE 'rl_recog_[a-z_]+ *\(' $(ls "$src"/firmware/core/*.c | grep -v '/rl_recog\.c$'); then
    echo "layers: a pass calls into the recognizer's hub (rl_recog.c)"
    status=1
fi
[ $status -eq 0 ] && echo "layers: dependencies run one way"
exit $status
