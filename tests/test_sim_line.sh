#!/bin/sh
# ringloc-sim-line (issue 42): the serial line between ringloc-fw's pty and
# the controller's. Whole ARCOS packets go through in order and unchanged
# (bytes compared with the ones written, packets built by hand here:
# FA FB, count, payload, checksum = the payload's 16-bit words summed);
# stray bytes and a packet with a bad checksum do not; --record keeps what
# was written. No timing is judged here (the delays are make sim's).
# usage: test_sim_line.sh RINGLOC_SIM_LINE TMPDIR
set -u
LINE=$1 T=$2/sim_line
rm -rf "$T" && mkdir -p "$T" || exit 1
cd "$T" || exit 1
fail() { echo "FAIL: $*"; [ -n "${LP:-}" ] && kill "$LP" 2> /dev/null; exit 1; }
"$LINE" --from fw.tty --to aria.tty --transport 0.02 --record rec.bin 2> line.log &
LP=$!
i=0
until [ -L fw.tty ] && [ -L aria.tty ]; do
    i=$((i + 1)); [ $i -lt 100 ] || fail "no links: $(cat line.log)"
    sleep 0.05
done
stty -F aria.tty raw -echo && stty -F fw.tty raw -echo || fail "stty"
cat aria.tty > got.bin &
CP=$!
sleep 0.2
# packet 1 (payload 01 02 03 04), stray bytes, a bad checksum, packet 2 (05 06 07 08)
P1='\372\373\006\001\002\003\004\004\006' P2='\372\373\006\005\006\007\010\014\016'
printf "$P1"'\000\021\372\373\006\001\001\001\001\000\000'"$P2" > fw.tty || fail "write to fw.tty"
printf "$P1$P2" > want.bin
i=0
until cmp -s got.bin want.bin; do
    i=$((i + 1))
    [ $i -lt 100 ] || { od -An -tx1 got.bin; kill "$CP"; fail "the controller's side did not get the two packets"; }
    sleep 0.05
done
kill "$LP" && wait "$LP" || fail "ringloc-sim-line did not end on SIGTERM"
LP=
kill "$CP" 2> /dev/null
grep -q "2 frames in, 2 passed, 0 dropped, 1 with a bad count or checksum skipped" line.log ||
    fail "counts: $(cat line.log)"
cmp -s rec.bin want.bin || fail "--record: $(od -An -tx1 rec.bin)"
[ ! -e fw.tty ] && [ ! -e aria.tty ] || fail "the links were left behind"
"$LINE" --from x 2> err.txt
[ $? -eq 2 ] && grep -q "ringloc-sim-line: --from and --to are needed" err.txt || fail "usage: $(cat err.txt)"
echo ok
