#!/bin/sh
# Dependencies run one way: nothing under hal/ or firmware/ includes a
# header of host/, the core includes none of hal/ (devices and the I/O
# library hal/io) or firmware/app, and the I/O library none of the
# devices or the app.  Usage: check_layers.sh SOURCE_DIR
src=${1:?usage: check_layers.sh SOURCE_DIR}
status=0
# (every path is one word, quoted, so a source folder with a space in its
# path is searched, not split into names grep cannot open)
names() { for f; do [ -e "$f" ] && printf '%s\n' "${f##*/}"; done | tr '\n' '|' | sed 's/|$//'; }
forbid() { # what, headers, folders...
    what=$1; headers=$2
    shift 2
    if [ -n "$headers" ] && grep -rnE "#include \"($headers)\"" "$@"; then
        echo "layers: $what"
        status=1
    fi
}
forbid "hal/ or firmware/ includes host/" "$(names "$src"/host/*.h)" "$src/hal" "$src/firmware"
forbid "the core includes hal/ or firmware/app" \
    "$(names "$src"/hal/*.h "$src"/hal/io/*.h "$src"/firmware/app/*.h)" "$src/firmware/core" "$src/firmware/include"
forbid "the I/O library includes a device of hal/ or firmware/app" \
    "$(names "$src"/hal/*.h "$src"/firmware/app/*.h)" "$src/hal/io"
forbid "the public API includes an internal header" \
    "$(names "$src"/firmware/core/*.h "$src"/firmware/fuse/*.h)" "$src/firmware/include"
forbid "the controller's filter (firmware/fuse) includes more than the public API" \
    "$(names "$src"/firmware/core/*.h "$src"/hal/*.h "$src"/hal/io/*.h "$src"/firmware/app/*.h)" "$src/firmware/fuse"
# The recognizer's hub (rl_recog.c) runs the passes; none of them calls
# back into it (rl_local -> rl_locate -> rl_recog -> rl_local was a circle).
set --
for f in "$src"/firmware/core/*.c; do
    [ "${f##*/}" = rl_recog.c ] || set -- "$@" "$f"
done
if grep -nE 'rl_recog_[a-z_]+ *\(' "$@"; then
    echo "layers: a pass calls into the recognizer's hub (rl_recog.c)"
    status=1
fi
[ $status -eq 0 ] && echo "layers: dependencies run one way"
exit $status
