#!/bin/sh
# The edge reads as short functions too: no function of more than 100
# lines (from its first line to its closing brace at column 0, as
# check_core_size.sh measures the core) in the camera and serial backends
# (hal/), the loaders (hal/io/), the firmware's loop (firmware/app/), the
# desktop commands (host/) and the tools (tools/*/).
# Usage: check_edge_size.sh SOURCE_DIR
src=${1:?usage: check_edge_size.sh SOURCE_DIR}
cd "$src" || exit 1
status=0
for dir in hal hal/io firmware/app host tools/*; do
  [ -d "$dir" ] || continue
  for f in "$dir"/*.c "$dir"/*.cpp; do
    [ -f "$f" ] || continue
    awk -v file="$f" '
      /^[A-Za-z].*\(/ && !/;[ \t]*$/ && start == 0 { start = NR; name = $0 }
      /^}/ && start > 0 {
        if (NR - start + 1 > 100) { printf "%s:%d: %d lines: %s\n", file, start, NR - start + 1, name; bad = 1 }
        start = 0
      }
      END { exit bad }' "$f" || status=1
  done
done
[ $status -eq 0 ] && echo "edge size: every function at most 100 lines"
exit $status
