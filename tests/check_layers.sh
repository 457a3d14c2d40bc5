#!/bin/sh
# Dependencies run one way: nothing under hal/ or firmware/ includes a
# header of host/, the core includes none of hal/ (devices and the I/O
# library hal/io) or firmware/app, and the I/O library none of the
# devices or the app.  Usage: check_layers.sh SOURCE_DIR
#
# It checks exactly the files under the folders each rule names, every
# one given to grep as a quoted word (a path with a space or a quote is
# one file), grep's standard input closed; a folder that is missing or
# holds no C file, or a file grep cannot read, fails the check loudly
# (exit 2), never passes it unread.
[ $# = 1 ] || { echo "usage: check_layers.sh SOURCE_DIR" >&2; exit 2; }
src=$1
status=0
broken() { echo "layers: $*" >&2; exit 2; }
for d in host hal hal/io firmware firmware/core firmware/include firmware/fuse firmware/app; do
    [ -d "$src/$d" ] || broken "$src/$d: not a folder (is $src the source folder?)"
done
names() { for f; do [ -e "$f" ] && printf '%s\n' "${f##*/}"; done | tr '\n' '|' | sed 's/|$//'; }
# grep_files PATTERN FILE...: the lines of the files matching PATTERN, each
# with its file's name (one file too); 0 some, 1 none, else broken
grep_files() {
    pattern=$1
    shift
    [ $# -gt 0 ] || broken "no files to search for $pattern"
    grep -nHE -- "$pattern" "$@" </dev/null
    rc=$?
    [ $rc -le 1 ] || broken "grep could not read every file of $* (status $rc)"
    return $rc
}
# the C and C++ sources and headers under the folders, one a line
c_files() { find "$@" -type f \( -name '*.c' -o -name '*.cpp' -o -name '*.h' \); }
# forbid WHAT HEADERS FOLDER...: no C file under the folders includes one
# of HEADERS (names joined by |)
forbid() {
    what=$1; headers=$2
    shift 2
    [ -n "$headers" ] || return 0
    for d; do
        # the folder's C files, each one word (find prints one a line; a
        # name with a line break is refused, not split)
        [ -n "$(c_files "$d")" ] || broken "$d: no C files ($what)"
        if [ -n "$(find "$d" -name '*
*')" ]; then broken "$d: a name with a line break"; fi
    done
    set -f
    IFS='
'
    # shellcheck disable=SC2046 # split at line ends only, globbing off
    set -- $(c_files "$@" | sort)
    unset IFS
    set +f
    if grep_files "#include \"($headers)\"" "$@"; then
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
    [ -f "$f" ] && [ "${f##*/}" != rl_recog.c ] && set -- "$@" "$f"
done
if grep_files 'rl_recog_[a-z_]+ *\(' "$@"; then
    echo "layers: a pass calls into the recognizer's hub (rl_recog.c)"
    status=1
fi
[ $status -eq 0 ] && echo "layers: dependencies run one way"
exit $status
