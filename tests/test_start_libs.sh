#!/bin/sh
# What a start of the programs loads (hal/rl_module.h): neither `ringloc`
# nor `ringloc-fw` links libcamera or Ceres Solver (modules loaded on first
# use), and their run path names the module folder with no empty entry
# (which the loader reads as the current folder). Where libcamera is
# built, a camera probe through ringloc-fw reaches libcamera itself.
# usage: test_start_libs.sh RINGLOC RINGLOC_FW MODULE_DIR TMPDIR HAVE_LIBCAMERA
R=$1 FW=$2 M=$3 T=$4 CAM=$5
pass=0 fail=0
ok() { pass=$((pass + 1)); }
bad() { echo "FAIL: $*"; fail=$((fail + 1)); }
mkdir -p "$T"
for p in "$R" "$FW"; do
    readelf -d "$p" >"$T/dyn" 2>&1 || { bad "readelf $p"; continue; }
    if grep NEEDED "$T/dyn" | grep -qiE 'camera|ceres|glog|cholmod|spqr|lapack|blas'; then
        bad "$p links $(grep NEEDED "$T/dyn" | grep -iE 'camera|ceres|glog|cholmod|spqr|lapack|blas' | tr -s ' ' | head -3)"
    else ok; fi
    rp=$(sed -n 's/.*(RUNPATH).*\[\(.*\)\]$/\1/p; s/.*(RPATH).*\[\(.*\)\]$/\1/p' "$T/dyn")
    case ":$rp:" in
        ::) bad "$p has no run path (the modules' folder is not found)" ;;
        *"::"*) bad "$p: run path '$rp' has an empty entry (the current folder)" ;;
        *":$M:"*) ok ;;
        *) bad "$p: run path '$rp' does not name $M" ;;
    esac
done
if [ "$CAM" = 1 ]; then
    printf 'camera:\n  backend: libcamera\n  device: "0"\nserial:\n  device: /dev/null\n  baud: 115200\ncalibration: c.yaml\nmap: m.yaml\nrobot: r.yaml\n' >"$T/lc.yaml"
    # run from a folder that holds a module of the same name which is not one
    echo "not a module" >"$T/ringloc-libcamera.so"
    (cd "$T" && "$FW" --config lc.yaml --probe) >"$T/out" 2>"$T/err"; rc=$?
    if [ $rc = 0 ] || { [ $rc = 1 ] && [ "$(wc -l <"$T/err")" = 1 ] && grep -q "camera: libcamera" "$T/err"; }; then
        ok
    else
        bad "ringloc-fw --probe (libcamera): rc $rc: $(head -c 300 "$T/err")"
    fi
fi
echo "$pass passed, $fail failed"
[ $fail = 0 ]
