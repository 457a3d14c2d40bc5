#!/bin/sh
# make sim: ringloc closing the loop on a simulated Pioneer 3-DX.
#
# AMRISim simulates the robot (its drive, speed ramps, odometry with an
# error); ringloc-aria-fuse (the ARIA example) asks it for the true pose
# (SIM_STAT) and streams it into ringloc-render --path stream, which draws
# the ceiling the robot's camera sees there; ringloc-fw reads those frames
# through the sim camera (capture time = the pose's time) and writes its
# pose frames to a pseudo-terminal; ringloc-sim-line carries them, with a
# serial line's delays, to the ARIA example, which fuses them with
# AMRISim's odometry (rl_fuse) and drives the route's waypoints with
# ArActionGoto on the fused pose. Then ringloc-sim-report judges the run
# against the truth and draws it.
#
# usage: sim.sh BUILD OUT [--cut] [--push] [--slow K] [--seconds S]
#   BUILD  the build folder (configured with -DARIA_DIR=...)
#   OUT    the run's folder (made; its old contents replaced)
#   AMRISIM=DIR  AMRISim's built tree (the AMRISim binary and PioneerRobotModels.world.inc)
set -u
[ $# -ge 2 ] || { echo "usage: sim.sh BUILD OUT [--cut] [--push] [--slow K] [--seconds S]" >&2; exit 2; }
BUILD=$(cd "$1" && pwd) || exit 2
OUT=$2
shift 2
CUT= PUSH= SLOW=4 SECONDS_MAX=900 PORT=${SIM_PORT:-8141}
CUT_AT=30 PUSH_AT=52 PUSH_BY=200,-150,8
while [ $# -gt 0 ]; do
    case $1 in
    --cut) CUT=1 ;;
    --push) PUSH=1 ;;
    --slow) SLOW=$2; shift ;;
    --seconds) SECONDS_MAX=$2; shift ;;
    *) echo "sim.sh: unknown option '$1'" >&2; exit 2 ;;
    esac
    shift
done
case $SLOW in
1 | 2 | 4 | 5 | 10 | 20) ;;
*) echo "sim.sh: --slow $SLOW: one of 1, 2, 4, 5, 10, 20 (a 100 ms step simulates 100/K ms)" >&2; exit 2 ;;
esac
RL=$BUILD/host/ringloc RENDER=$BUILD/tools/ringloc-render FW=$BUILD/firmware/app/ringloc-fw
LINE=$BUILD/tools/sim/ringloc-sim-line REPORT=$BUILD/tools/sim/ringloc-sim-report
ARIA=$BUILD/tools/aria/ringloc-aria-fuse
SIMBIN=${AMRISIM:-}/AMRISim

missing() {
    cat >&2 <<MSG
make sim: $1
  make sim needs AMRISim and AriaCoda (neither is in Debian), built outside this tree:
    apt-get install libgtk2.0-dev autoconf automake libtool xvfb
    git clone https://github.com/reedhedges/AriaCoda && make -C AriaCoda -j1
    git clone https://github.com/reedhedges/AMRISim
    sed -i '535s|(s/i)|(s/r)|' AMRISim/stage/src/gui.c      # a typo at its head
    make -C AMRISim -j1 ARIA=\$PWD/AriaCoda AMRISIM_INCLUDE_ROS1=no LIBARIA= \\
        "ARIA_LINK=-L\$PWD/AriaCoda/lib -Wl,-rpath,\$PWD/AriaCoda/lib -lAria"
  then: make sim ARIA_DIR=\$PWD/AriaCoda AMRISIM=\$PWD/AMRISim
MSG
    exit 2
}
[ -n "${AMRISIM:-}" ] || missing "AMRISIM is not set (AMRISim's built tree)"
[ -x "$SIMBIN" ] || missing "$SIMBIN: no AMRISim binary there"
[ -f "$AMRISIM/PioneerRobotModels.world.inc" ] || missing "$AMRISIM/PioneerRobotModels.world.inc: not there"
[ -x "$ARIA" ] || missing "$ARIA: not built (configure with -DARIA_DIR=AriaCoda's tree)"
command -v Xvfb > /dev/null || missing "Xvfb: not installed (apt-get install xvfb)"
for b in "$RL" "$RENDER" "$FW" "$LINE" "$REPORT"; do
    [ -x "$b" ] || { echo "make sim: $b: not built" >&2; exit 2; }
done

# OUT is replaced only if it is empty or an earlier run's (its marker)
if [ -e "$OUT" ] && [ -n "$(ls -A "$OUT" 2> /dev/null)" ] && [ ! -f "$OUT/.ringloc-sim-run" ]; then
    echo "make sim: $OUT: exists and is not an earlier run's folder; not replaced" >&2
    exit 1
fi
rm -rf "$OUT" && mkdir -p "$OUT/st" && : > "$OUT/.ringloc-sim-run" || exit 1
OUT=$(cd "$OUT" && pwd)
cd "$OUT" || exit 1
PIDS=
stop_all() {
    for p in $PIDS; do kill "$p" 2> /dev/null; wait "$p" 2> /dev/null; done
    PIDS=
}
trap 'stop_all; exit 1' INT TERM

# The site: an 8 x 6 m room planned by ringloc; its frame is AMRISim's
# world frame (metres here, millimetres there).
"$RL" plan --area 8x6 --pitch 0.8 --resolution 640x480 --hfov 70 --ceiling-height 2.75 --camera-height 0.88 \
    --map-out site.yaml > plan.txt 2>&1 || { cat plan.txt; exit 1; }
# The camera 10 cm ahead of the wheels' axle, tilted 0.5 degrees in roll and
# 1 degree in pitch (the robot's mount, known to ringloc), rocking 0.06
# degrees a frame (robot.yaml's rocking says so; 1.9 mm on the ceiling 1.87 m
# above the camera). The frames are drawn at the truth AMRISim reports, in whole mm
# and degrees: each frame is up to 0.5 mm and 0.5 degree off the simulated
# robot whose odometry is fused with it. With the frames' own 1 mm steps,
# about 3 mm and 0.3 degrees a frame that the frames' sigmas do not carry:
# the ARIA example is told so (-frameFloor, -frameFloorYaw).
MOUNT=0.1,0,0,0.0087,0.0175 ROCK=${SIM_ROCK:-0.001} FLOOR=${SIM_FLOOR:-3} FLOOR_YAW=${SIM_FLOOR_YAW:-0.3}
"$RENDER" --site-map site.yaml --mount $MOUNT --rock $ROCK --write-camera cam.yaml --write-robot robot.yaml || exit 1
# The route: 22 m, twice round a 5 x 3 m loop less a leg, from the start (1.5, 1.5)
cat > route.txt <<'R'
# waypoints X Y (m, the site's frame)
6.5 1.5
6.5 4.5
1.5 4.5
1.5 1.5
6.5 1.5
6.5 4.5
R
cat > fw.yaml <<'YAML'
camera:
  backend: sim
  device: st/frames
calibration: cam.yaml
map: site.yaml
robot: robot.yaml
serial:
  device: fw.tty
  baud: 115200
YAML

# AMRISim's models, with the Pioneer's odometry 10 % off: Stage scales the
# forward speed and the turn rate it integrates (odom_error [x y a], the
# angle read in degrees: 5.7296 degrees is 0.1 rad per rad).
cat > PioneerRobotModels.world.inc <<INC
include "$AMRISIM/PioneerRobotModels.world.inc"
define p3dx-ringloc p3dx-sh (
  odom_error [ 0.10 0 5.7296 ]
)
INC
# slowed K times: each 100 ms step simulates 100/K ms
STEP=$((100 / SLOW))
# AMRISim wants an X display even without its window: a virtual one of our own
Xvfb -displayfd 3 -nolisten tcp -screen 0 320x240x24 3> display.txt 2> xvfb.log &
PIDS="$! $PIDS"
i=0
until [ -s display.txt ]; do
    i=$((i + 1))
    [ $i -lt 100 ] || { cat xvfb.log; echo "make sim: Xvfb did not start (xvfb.log)" >&2; stop_all; exit 1; }
    sleep 0.1
done
DISPLAY=:$(cat display.txt) AMRISIM=$OUT "$SIMBIN" --nogui --nomap -r p3dx-ringloc:r1 --bind-to-address 127.0.0.1 \
    --no-crash-debug --no-crash-restart --no-network-discovery --odom-error-mode constant \
    --update-interval 100 --update-sim-time $STEP -p $PORT --start 1500,1500,0 > amrisim.log 2>&1 &
PIDS="$! $PIDS"
i=0
until grep -q "ready for a client to connect to address 127.0.0.1 on TCP port $PORT" amrisim.log; do
    i=$((i + 1))
    [ $i -lt 100 ] || { cat amrisim.log; echo "make sim: AMRISim did not start (amrisim.log)" >&2; stop_all; exit 1; }
    sleep 0.1
done

mkfifo poses.fifo st/frames || { stop_all; exit 1; }
"$RENDER" --out st --path stream --site-map site.yaml --mount $MOUNT --rock $ROCK --newest \
    < poses.fifo > st/frames 2> render.log &
PIDS="$! $PIDS"
# the serial line: 115200 baud and up to 50 ms more of the wall clock (the
# clock every program runs on; 12.5 simulated ms of the robot's motion),
# outside the frames' latency field (a USB adapter, a loaded controller)
"$LINE" --from fw.tty --to aria.tty --baud 115200 --transport "${SIM_TRANSPORT:-0.05}" \
    --record line.bin 2> line.log &
PIDS="$! $PIDS"
i=0
until [ -L aria.tty ] && [ -L fw.tty ]; do
    i=$((i + 1)); [ $i -lt 50 ] || { cat line.log; stop_all; exit 1; }
    sleep 0.1
done
"$FW" --config fw.yaml > fw.out 2> fw.log &
PIDS="$! $PIDS"
# the disturbances, in simulated seconds after the route's start (the ARIA
# example counts in its own, K times as many)
OPTS= JUDGE=
# SIM_SHARED_CLOCK=1: the ARIA example takes each frame's capture time as it
# is (ringloc-fw runs on the same clock) instead of learning the board's clock
[ -n "${SIM_SHARED_CLOCK:-}" ] && OPTS="-sharedClock true"
[ -n "$CUT" ] && OPTS="$OPTS -cutAt $((CUT_AT * SLOW)) -cutFor $((3 * SLOW))" JUDGE="$JUDGE --cut-at $CUT_AT --cut-for 3"
[ -n "$PUSH" ] && OPTS="$OPTS -pushAt $((PUSH_AT * SLOW)) -push $PUSH_BY" JUDGE="$JUDGE --push-at $PUSH_AT"
"$ARIA" -remoteHost 127.0.0.1 -remoteRobotTcpPort $PORT -ringlocPort aria.tty -simPoses poses.fifo \
    -route route.txt -routeLog route.log -poseLog poses.log -arrivalsLog arrivals.log -drive $SECONDS_MAX \
    -routeVel 400 -closeDist 20 -frameFloor $FLOOR -frameFloorYaw $FLOOR_YAW $OPTS > aria.log 2>&1
RC=$?
stop_all
grep "ringloc-aria-fuse:" aria.log
[ $RC = 0 ] || { tail -n 20 aria.log; echo "make sim: ringloc-aria-fuse failed ($RC; aria.log)" >&2; exit $RC; }
"$REPORT" --poses poses.log --route route.log --plot sim.png --slow $SLOW $JUDGE \
    --title "make sim: AMRISim's Pioneer 3-DX driven on ringloc's fused pose${CUT:+, frames cut 3 s}${PUSH:+, pushed}" \
    > report.txt
RC=$?
cat report.txt
exit $RC
