#!/bin/sh
# The tree stands alone: no file names a path outside it (a clone has
# nothing beside it), and every relative Markdown link and every
# docs/ Markdown file a file names exists in the tree.
# Usage: check_standalone.sh SOURCE_DIR
src=${1:?usage: check_standalone.sh SOURCE_DIR}
cd "$src" || exit 2
status=0
# folders of a workplace or a user's machine (built from pieces: this file names none)
machine_dirs="(wo""rk|ho""me|Us""ers)"
# file names split at line ends only (a name may hold spaces)
IFS='
'

if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    files=$(git ls-files --cached --others --exclude-standard | grep -v '^build')
else
    files=$(find . -type f ! -path './build*' ! -path './.git/*' | sed 's#^\./##')
fi
# 1. paths that leave the tree: the steering folder beside it, a folder
#    of the machine a file was written on, or a build file reaching above
#    the source's top
texts=$(for f in $files; do
    case $f in *.png|*.pdf|*.jpg|*.bin) continue ;; esac
    [ -f "$f" ] && printf '%s\n' "$f"
done)
leave() { # message, pattern: one grep over every text file
    hits=$(printf '%s\n' "$texts" | tr '\n' '\0' | xargs -0 grep -InHE "$2" 2>/dev/null)
    if [ -n "$hits" ]; then
        printf '%s\n' "$hits"
        printf '%s\n' "$hits" | cut -d: -f1 | uniq | while IFS= read -r f; do echo "standalone: $f $1"; done
        status=1
    fi
}
leave "names the folder beside the tree (the contract is docs/landmark-spec.md)" \
    '\.\./shared|(^|[^a-z_/])shared/(landmark-spec|paper|style)'
leave "names a folder of the machine it was written on (name the build by its commit, a folder by a placeholder)" \
    "(^|[^A-Za-z0-9._~/:-])/$machine_dirs/[^[:space:]]"
leave "reaches above the source tree" '(PROJECT_SOURCE_DIR|CMAKE_SOURCE_DIR|CURDIR)\)?\}?/\.\.(/|$|[ "])'
# 2. every Markdown file under docs named anywhere exists
for d in $(grep -ahoE 'docs/[A-Za-z0-9_-]+\.md' $files 2>/dev/null | sort -u); do
    [ -f "$d" ] || { echo "standalone: $d is named but not in the tree"; status=1; }
done
# 3. relative links of the Markdown files resolve
for f in $(printf '%s\n' $files | grep '\.md$'); do
    dir=$(dirname "$f")
    for l in $(grep -oE '\]\([^)# ]+' "$f" | sed 's/^](//' | grep -v '^[a-z]*:'); do
        [ -e "$dir/$l" ] || { echo "standalone: $f links to $l, which is not there"; status=1; }
    done
done
[ $status -eq 0 ] && echo "standalone: the tree names nothing outside it"
exit $status
