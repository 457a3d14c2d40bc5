#!/bin/sh
# Run libFuzzer targets, JOBS at a time, each for SECONDS, from the
# committed seeds (tests/fuzz/corpus/NAME, never written to) into a working
# corpus beside the binary; a crash leaves its input as crash-NAME-* there.
# Prints each target's executions and peak RSS; exits 1 if any failed.
#
#   tools/fuzz.sh SECONDS JOBS BUILD_DIR:TARGET...
#   (e.g. tools/fuzz.sh 60 2 build-fuzz:recog build-fuzz-msan:recog)
set -u
[ $# -ge 3 ] || { sed -n '2,8s/^# \{0,1\}//p' "$0"; exit 2; }
secs=$1 jobs=$2
shift 2
seeds=$(cd "$(dirname "$0")/../tests/fuzz/corpus" && pwd)
# a smaller ASan quarantine: the PNG target decodes images up to the size
# limit, and the default 256 MB of freed memory kept aside nears the RSS cap
export ASAN_OPTIONS=${ASAN_OPTIONS:-quarantine_size_mb=64}
one() { # BUILD_DIR TARGET
    d=$1 t=$2
    mkdir -p "$d/corpus/$t"
    "$d/tests/fuzz/fuzz_$t" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$d/crash-$t-" "$d/corpus/$t" "$seeds/$t" >"$d/fuzz_$t.log" 2>&1
    echo $? >"$d/fuzz_$t.rc"
}
fail=0
report() { # BUILD_DIR:TARGET...
    for p in "$@"; do
        d=${p%%:*} t=${p#*:}
        if [ "$(cat "$d/fuzz_$t.rc" 2>/dev/null)" = 0 ]; then
            printf '%s fuzz_%s: %s s, %s\n' "$(basename "$d")" "$t" "$secs" \
                "$(grep -E 'stat::number_of_executed_units|stat::peak_rss_mb' "$d/fuzz_$t.log" | tr -s ' \n' ' ')"
        else
            tail -40 "$d/fuzz_$t.log"
            echo "$(basename "$d") fuzz_$t: FAILED (its input: $d/crash-$t-*)"
            fail=1
        fi
    done
}
batch=""
n=0
for p in "$@"; do
    one "${p%%:*}" "${p#*:}" &
    batch="$batch $p"
    n=$((n + 1))
    if [ $n -ge "$jobs" ]; then
        wait
        report $batch
        batch="" n=0
    fi
done
wait
[ -n "$batch" ] && report $batch
exit $fail
