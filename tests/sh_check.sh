# Shared by the shell tests: the pass / fail counts, and the check of one
# command's exit code and message. Sourced: `. sh_check.sh` (after which
# T names the scratch folder), then `sh_done` last.
pass=0
fail=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }

# expect RC PATTERN -- COMMAND...: exit code RC; for an error (RC not 0)
# exactly one line on stderr, matching PATTERN (an extended regular
# expression); else PATTERN on stdout or stderr.
expect() {
    want_rc=$1; pattern=$2; shift 3
    "$@" >"$T/out" 2>"$T/err"
    rc=$?
    lines=$(grep -c . "$T/err")
    if [ "$want_rc" = 0 ]; then seen() { grep -qE -- "$pattern" "$T/err" "$T/out"; }
    else seen() { grep -qE -- "$pattern" "$T/err"; }; fi
    if [ "$rc" != "$want_rc" ] || ! seen ||
        { [ "$want_rc" != 0 ] && [ "$lines" != 1 ]; }; then
        bad "$* -> rc $rc (want $want_rc), stderr: $(cat "$T/err")"
    else
        ok
    fi
}

# ere TEXT: an extended regular expression matching TEXT literally (a
# path in expect's PATTERN: its dots, $ or brackets not the pattern's)
ere() { printf '%s\n' "$1" | sed 's/[][\\.*^$+?(){}|]/\\&/g'; }

# The summary line, and the script's status.
sh_done() {
    echo "$pass passed, $fail failed"
    [ "$fail" = 0 ]
}
