# Shared by the shell tests: their arguments (RINGLOC PATHS_DIR TMPDIR), a
# fresh scratch folder, and the pass / fail counts. Sourced: `. sh_lib.sh`.
set -u
R=$1
D=$(cd "$2" && pwd)
T=$3
rm -rf "$T"
mkdir -p "$T"
pass=0
fail=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }
