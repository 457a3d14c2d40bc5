#!/bin/sh
# Code that reads as short functions: no function of more than 100 lines
# (from its first line to its closing brace at column 0) in the .c and
# .cpp files of each DIR; with --files, no file of 500 lines or more
# either (the core's modules, one job each).
# Usage: check_size.sh [--files] DIR...
files=0
[ "$1" = --files ] && { files=1; shift; }
[ $# -ge 1 ] || { echo "usage: check_size.sh [--files] DIR..." >&2; exit 2; }
status=0
for dir in "$@"; do
  [ -d "$dir" ] || { echo "$dir: not a folder" >&2; exit 2; }
  for f in "$dir"/*.c "$dir"/*.cpp; do
    [ -f "$f" ] || continue
    n=$(wc -l < "$f")
    if [ "$files" = 1 ] && [ "$n" -ge 500 ]; then
      echo "$f: $n lines (limit: under 500)"
      status=1
    fi
    awk -v file="$f" '
      /^[A-Za-z].*\(/ && !/;[ \t]*$/ && start == 0 { start = NR; name = $0 }
      /^}/ && start > 0 {
        if (NR - start + 1 > 100) { printf "%s:%d: %d lines: %s\n", file, start, NR - start + 1, name; bad = 1 }
        start = 0
      }
      END { exit bad }' "$f" || status=1
  done
done
exit $status
