#!/bin/sh
# The core reads as modules with one job: no .c file of 500 lines or more,
# no function of more than 100 lines (from its first line to its closing
# brace at column 0).  Usage: check_core_size.sh firmware/core
dir=${1:?usage: check_core_size.sh DIR}
status=0
for f in "$dir"/*.c; do
  n=$(wc -l < "$f")
  if [ "$n" -ge 500 ]; then
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
[ $status -eq 0 ] && echo "core size: every file under 500 lines, every function at most 100"
exit $status
