#!/bin/sh
# `ringloc` for the shell-script tests (tests/CMakeLists.txt copies this
# beside ringloc.argv): the words of ringloc.argv, one a line (the
# emulator's when cross-built, then the program's path), run with this
# script's arguments after them. The words are data: a path with a space,
# a quote, a $ or a backtick stays one word.
case $0 in */*) argv=${0%/*}/ringloc.argv ;; *) argv=./ringloc.argv ;; esac
[ -r "$argv" ] || { echo "ringloc.sh: $argv: cannot read the command's words" >&2; exit 127; }
n=$#
while IFS= read -r word || [ -n "$word" ]; do
    set -- "$@" "$word"
done <"$argv"
# the file's words first: rotate the n arguments given past them
while [ "$n" -gt 0 ]; do
    set -- "$@" "$1"
    shift
    n=$((n - 1))
done
exec "$@"
