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
