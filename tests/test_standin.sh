#!/bin/sh
# The stand-in Pioneer (ringloc-standin) against the project's own ARCOS
# code (standin_client: rl_arcos, rl_packet's decoder, rl_fuse), and, where
# AriaCoda was found, against the ARIA example: a 6 s drive at 1 m/s
# turning 30 degrees a second, pose frames 10 a second arriving 100 ms
# after capture, then again over a line with delays the frames do not
# carry, a drifting and restarting camera board; the fused pose at every server information packet
# against the stand-in's truth (no bias over 4 mm ahead or across on the
# first run, the serial line's bias printed; a median within 20 mm: the frames and
# the odometry are stamped on arrival by processes that share the machine
# with the build, so a loaded host's scheduling shows here; the fusion's
# figures, 1 mm and 3 mm, are test_fuse_drive's, on simulated time).
# The sanitizer build runs several times slower on the same host, so its
# arrival stamps are later still: there it checks the protocol and the
# filter's memory, within RL_STANDIN_LIMIT_MM (set by CTest).
# usage: test_standin.sh STANDIN CLIENT TMPDIR [ARIA_EXAMPLE]
S=$1
C=$2
T=$3
A=${4:-}
LIMIT=${RL_STANDIN_LIMIT_MM:-20}
BIAS_LIMIT=${RL_STANDIN_BIAS_MM:-4}
rm -rf "$T"
mkdir -p "$T"
fail=0
# a port of our own: the process id spreads parallel runs
port=$((20000 + $$ % 20000))
# Errors of columns 2-3 (fused) and 5-6 (ARIA's pose, if any) against the
# truth, interpolated in time, from the 3rd second (or FROM). Judged by
# their MEDIAN, printed with the RMS and the largest: these runs are in
# real time, and a stall of the stand-in or of a read on a loaded host
# (load 11 on 2 cores: 15-57 mm RMS, largest 230 mm, median 14 mm) moves
# the RMS and the largest through a few packets; fewer than half the
# packets it cannot move. A broken fusion moves them all: the odometry
# alone is metres off, a frame put at its arrival (the latency ignored)
# 100 mm at 1 m/s.
# A bias of a few mm passes that median, so the signed errors' medians of
# the fused pose are judged too, in the robot's frame: across the heading within BIAS_LIMIT
# either way, and along it at most BIAS_LIMIT ahead of the truth. Load only
# ever delays (a packet read late is stamped late: the pose lags), so
# behind the truth only the median above bounds it: 8 runs beside two busy
# loops at load 4-5 gave -0.4 .. -12.6 mm along, at most 0.33 mm across;
# alone -0.5 .. +1.0 along. A capture time 10 ms early (a latency counted
# twice) puts the pose 9-11 mm ahead: it fails here, not on the median.
# Those figures are the first run's; the serial line's run (its board's
# clock learned, restarted) sat up to 1.3 mm ahead and spread by 5 mm at a
# load of 3.5-5 in 4 runs, too near the bound: its bias is printed, not
# judged (BIAS_MM empty).
judge() { # LOG NAME LIMIT_MM [ARIA [FROM [BIAS_MM]]]
    awk -v name="$2" -v lim="$3" -v blim="${6-$BIAS_LIMIT}" -v aria="${4:-}" -v from="${5:-3}" 'BEGIN { n = 0; i = 0 }
        NR == FNR { t[n] = $1; x[n] = $2; y[n] = $3; w[n] = $4; n++; next }
        { while (i < n - 2 && t[i + 1] < $1) i++
          if (n < 2 || $1 < t[0] + from || $1 > t[n - 1]) next
          f = ($1 - t[i]) / (t[i + 1] - t[i]); tx = x[i] + f * (x[i + 1] - x[i]); ty = y[i] + f * (y[i + 1] - y[i])
          c = cos(w[i]); sn = sin(w[i])
          e = ($2 - tx)^2 + ($3 - ty)^2; s += e; if (e > mx) mx = e; ef[m] = e
          al[m] = c * ($2 - tx) + sn * ($3 - ty); cr[m] = c * ($3 - ty) - sn * ($2 - tx); m++
          if (aria) { e = ($5 - tx)^2 + ($6 - ty)^2; sa += e; ea[m - 1] = e
                      ala[m - 1] = c * ($5 - tx) + sn * ($6 - ty); cra[m - 1] = c * ($6 - ty) - sn * ($5 - tx) } }
        function med(a, k, j, v) { # a[0..m-1] sorted in place (m is small); its median
            for (k = 1; k < m; k++) { v = a[k]; for (j = k - 1; j >= 0 && a[j] > v; j--) a[j + 1] = a[j]; a[j + 1] = v }
            return m % 2 ? a[(m - 1) / 2] : (a[m / 2 - 1] + a[m / 2]) / 2 }
        function abs(v) { return v < 0 ? -v : v }
        END { if (m < 25) { print "FAIL: " name ": " m + 0 " packets judged"; exit 1 }
              md = 1000 * sqrt(med(ef)); ba = 1000 * med(al); bc = 1000 * med(cr)
              printf "%s: %d packets, fused pose %.2f mm median from the truth (limit %s; %.2f RMS, largest %.2f), " \
                     "median %+.2f mm along the heading, %+.2f across (limits %s ahead, %s across)", name, m, md, lim, 1000 * sqrt(s / m),
                     1000 * sqrt(mx), ba, bc, blim == "" ? "none" : blim, blim == "" ? "none" : blim
              ok = md <= lim && (blim == "" || (ba <= blim && abs(bc) <= blim))
              if (aria) { mda = 1000 * sqrt(med(ea)); baa = 1000 * med(ala); bca = 1000 * med(cra)
                          printf ", ArRobot::getPose() %.2f mm median (%.2f RMS), %+.2f along, %+.2f across", mda,
                                 1000 * sqrt(sa / m), baa, bca
                          ok = ok && mda <= lim } # its bias printed only: not yet measured (no AriaCoda here)
              printf "\n"
              exit !ok }' "$T/$1.truth" "$T/$1.log"
}
run() { # NAME, the stand-in's own options, then the controller's command line with @PORT@ @PTY@ @LOG@
    name=$1
    line=$2
    shift 2
    # shellcheck disable=SC2086 # the options' words
    "$S" --port $port --frames-pty "$T/tty" --truth "$T/$name.truth" --start 1.5,2.0,0.3 $line \
        >"$T/$name.standin" 2>&1 &
    sp=$!
    i=0
    while [ ! -L "$T/tty" ] && [ $i -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
    # @PORT@ @PTY@ @LOG@ replaced argument by argument, each argument one
    # word (a path with a space in it is not split)
    k=$#
    while [ "$k" -gt 0 ]; do
        a=$1
        shift
        case $a in
        @PORT@) a=$port ;;
        @PTY@) a=$T/tty ;;
        @LOG@) a=$T/$name.log ;;
        esac
        set -- "$@" "$a"
        k=$((k - 1))
    done
    timeout 60 "$@" >"$T/$name.out" 2>&1 || { echo "FAIL: $name exited $?: $(tail -5 "$T/$name.out")"; fail=1; }
    i=0
    while kill -0 $sp 2>/dev/null && [ $i -lt 30 ]; do sleep 0.1; i=$((i + 1)); done
    kill $sp 2>/dev/null
    wait $sp 2>/dev/null
    port=$((port + 1))
}
run client "" "$C" @PORT@ @PTY@ 6 1000 30 @LOG@
cat "$T/client.out"
grep -q "handshake: SYNC0 SYNC1 SYNC2 answered; name ringloc-standin" "$T/client.out" || { echo "FAIL: handshake"; fail=1; }
judge client "standin_client (the project's ARCOS code)" "$LIMIT" || fail=1
# a real serial line (issue 38): 15 ms in the latency field, up to 100 ms
# more outside it, the board's clock 100 ppm fast, the board restarting
# after 5 s: the capture times from the board's clock, no pose restart;
# 12 s, judged from the 4th (the board's clock is learned in the first).
# This run is in real time: the odometry is stamped when the client reads
# each packet (ARCOS carries no time) and moved to the packet cycle
# (rl_fuse_cycle), but a shared host can stall the stand-in itself or a
# read by a whole cycle (1.6 mm RMS under a load of 3; a 300 ms stall
# costs one packet's worth). So it judges only what a busy
# machine cannot move: the board's restart seen as a clock reset (1 to 3:
# a reader stalled for a run of frames looks like a changed offset, and at
# a load of 6-10 one run showed 2), and
# none of the old rule's storm of restarts and its 96 mm (at most 4
# restarts, twice the limit: the sanitizer build beside the rest of the
# suite stalled reads enough for 3), and the median error as in the first
# run; the figures themselves (0 restarts, 3 mm) are test_fuse_drive's,
# on simulated time.
LINE=${RL_STANDIN_LINE:-"--transport 0.1 --drift 100 --restart-at 5"}
run line "$LINE" "$C" @PORT@ @PTY@ 12 1000 30 @LOG@
cat "$T/line.out"
restarts=$(sed -n 's/.* \([0-9][0-9]*\) restarts, [0-9][0-9]* clock resets.*/\1/p' "$T/line.out")
resets=$(sed -n 's/.* restarts, \([0-9][0-9]*\) clock resets.*/\1/p' "$T/line.out")
[ -n "$restarts" ] && [ "$restarts" -le 4 ] && [ -n "$resets" ] && [ "$resets" -ge 1 ] && [ "$resets" -le 3 ] ||
    { echo "FAIL: the restarted board: $(tail -1 "$T/line.out")"; fail=1; }
judge line "standin_client, $LINE" "$LIMIT" "" 4 "" || fail=1
if [ -n "$A" ]; then
    run aria "" "$A" -remoteHost localhost -remoteRobotTcpPort @PORT@ -ringlocPort @PTY@ -drive 6 -vel 1000 \
        -rotVel 30 -poseLog @LOG@
    grep -E "Connected to robot|Subtype|ringloc-aria-fuse" "$T/aria.out"
    judge aria "ringloc-aria-fuse (ARIA)" "$LIMIT" 1 || fail=1
    run aria_line "$LINE" "$A" -remoteHost localhost -remoteRobotTcpPort @PORT@ -ringlocPort @PTY@ -drive 12 \
        -vel 1000 -rotVel 30 -poseLog @LOG@
    judge aria_line "ringloc-aria-fuse (ARIA), $LINE" "$LIMIT" 1 4 "" || fail=1
else
    echo "AriaCoda not found: the ARIA example was not built (ARIA_DIR)"
fi
[ $fail = 0 ]
