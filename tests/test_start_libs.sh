#!/bin/sh
# What a start of the programs loads (hal/rl_module.h): neither `ringloc`
# nor `ringloc-fw` links libcamera or Ceres Solver (modules loaded on first
# use), and a command that needs neither (gen, detect) loads neither, nor
# libcamera's tracer. A module is found only next to the program's folder:
# with the library path naming the current folder (an empty entry) and a
# decoy of the camera's module there, a libcamera probe through ringloc-fw
# still reaches libcamera itself (where libcamera is built).
# usage: test_start_libs.sh RINGLOC RINGLOC_FW TMPDIR HAVE_LIBCAMERA
R=$1 FW=$2 T=$3 CAM=$4
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }
heavy='camera|ceres|glog|cholmod|spqr|lapack|blas|lttng'
mkdir -p "$T"
for p in "$R" "$FW"; do
    readelf -d "$p" >"$T/dyn" 2>&1 || { bad "readelf $p"; continue; }
    if grep NEEDED "$T/dyn" | grep -qiE "$heavy"; then
        bad "$p links $(grep NEEDED "$T/dyn" | grep -iE "$heavy" | tr -s ' ' | head -3)"
    else ok; fi
done
"$R" gen --id 5 --png "$T/five.png" >/dev/null 2>&1 || bad "ringloc gen"
for cmd in "gen --id 6 --png $T/six.png" "detect $T/five.png"; do
    # shellcheck disable=SC2086
    LD_DEBUG=files "$R" $cmd 2>"$T/ld" >/dev/null
    if grep -iE "file=[^ ]*($heavy|ringloc-)" "$T/ld" >"$T/loaded"; then
        bad "ringloc $cmd loads $(sed 's/.*file=\([^ ;]*\).*/\1/' "$T/loaded" | sort -u | tr '\n' ' ')"
    else ok; fi
done
if [ "$CAM" = 1 ]; then
    printf 'camera:\n  backend: libcamera\n  device: "0"\nserial:\n  device: /dev/null\n  baud: 115200\ncalibration: c.yaml\nmap: m.yaml\nrobot: r.yaml\n' >"$T/lc.yaml"
    echo "not a module" >"$T/ringloc-libcamera.so"
    (cd "$T" && LD_LIBRARY_PATH=: "$FW" --config lc.yaml --probe) >"$T/out" 2>"$T/err"; rc=$?
    if [ $rc = 0 ] || { [ $rc = 1 ] && [ "$(wc -l <"$T/err")" = 1 ] && grep -q "camera: libcamera camera" "$T/err"; }; then
        ok
    else
        bad "ringloc-fw --probe (libcamera) from a folder with a decoy module: rc $rc: $(head -c 300 "$T/err")"
    fi
fi
echo "$pass passed, $fail failed"
[ $fail = 0 ]
