# Shared by the shell tests on the rendered paths: their arguments (RINGLOC
# PATHS_DIR TMPDIR), a fresh scratch folder, and sh_check.sh (the counts,
# ok, bad, expect). Sourced: `. sh_lib.sh`.
set -u
R=$1
D=$(cd "$2" && pwd)
T=$3
rm -rf "$T"
mkdir -p "$T"
. "$(dirname "$0")/sh_check.sh"

# locate LIST ARGS...: `ringloc locate` with the paths' camera, map and
# robot over the frames listed in file LIST, in order, one argument a line
# (split at line ends only: a path may hold a space)
locate_frames_in() {
    list=$1
    shift
    IFS='
'
    set -f
    # shellcheck disable=SC2046
    set -- "$@" $(cat "$list")
    set +f
    unset IFS
    "$R" locate --camera "$D/camera.yaml" --map "$D/map.yaml" --robot "$D/robot.yaml" "$@"
}
