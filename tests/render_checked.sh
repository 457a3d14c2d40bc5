#!/bin/sh
# The sanitizer build's renderer, checked (tools/CMakeLists.txt): that
# build renders its fixtures with `ringloc-render` optimised and without
# the sanitizers (its frames the ones the sanitizer build's tests were
# written for, byte for byte, in a third less CPU), and builds the same
# sources under ASan and UBSan as `ringloc-render-checked`. Here each of
# the renderer's ways (every fixture set of the suite, a camera pipeline, paths with their map,
# rocking and tilt, a fisheye lens, a rolling shutter, a hung landmark, the
# survey's site, a large site's drives, AprilTag twins) runs once under the
# sanitizers, and its files must be the optimised renderer's, byte for byte.
# usage: render_checked.sh RENDER RENDER_CHECKED TMPDIR
set -u
FAST=$1 CHECKED=$2 T=$3
rm -rf "$T"
mkdir -p "$T/fast" "$T/checked"
M=0.12,-0.03,0.02
fail=0 n=0
subst() { # ARG FOLDER: ARG with every @DIR@ in it replaced by FOLDER
    s=$1 out=
    while :; do
        case $s in
        *@DIR@*) out=$out${s%%@DIR@*}$2 s=${s#*@DIR@} ;;
        *) break ;;
        esac
    done
    printf '%s' "$out$s"
}
run() { # BIN FOLDER ARGS...: BIN run on ARGS, each @DIR@ in them FOLDER
    bin=$1 dir=$2
    shift 2
    for a; do
        shift
        set -- "$@" "$(subst "$a" "$dir")"
    done
    "$bin" "$@"
}
one() { # NAME ARGS... (@DIR@ in ARGS: each renderer's own folder; a placeholder
         # no path holds, so a source or build folder named e.g. DIRK stays as it is)
    name=$1
    shift
    for r in fast checked; do
        [ $r = fast ] && bin=$FAST || bin=$CHECKED
        mkdir -p "$T/$r/$name"
        if ! run "$bin" "$T/$r/$name" "$@" >"$T/$r/$name.log" 2>&1; then
            echo "FAIL: $name: $r renderer failed: $(tail -3 "$T/$r/$name.log")"
            fail=1
        fi
    done
    if ! diff -r "$T/fast/$name" "$T/checked/$name" >"$T/$name.diff" 2>&1; then
        echo "FAIL: $name: the renderers' files differ: $(head -3 "$T/$name.diff")"
        fail=1
    fi
    n=$((n + 1))
}
for set in clean cluttered clutter_only glare border illum degraded lens motion repeats; do
    one "$set" --out @DIR@ --set "$set" --count 1 --seed 7
done
one moving --out @DIR@ --set moving --count 1 --seed 7 --rock 0.03 --twin
one heldout --out @DIR@ --set heldout --count 1 --seed 2026 --rock 0.03
one isp --out @DIR@ --set moving --count 1 --seed 11 --rock 0.03 --isp blur:1.0,scale:1.5,sharpen:0.8,jpeg:80,scurve:0.6,ae:1
one tilt --out @DIR@ --path rect --frames 2 --mount "$M" --rock 0.03 --look degraded \
    --write-map @DIR@/map.yaml --write-camera @DIR@/camera.yaml --write-robot @DIR@/robot.yaml
one fisheye --out @DIR@ --path circle --frames 2 --mount "$M" --camera "$(dirname "$0")/frames/fisheye_opencv.yaml"
one rolling --out @DIR@ --path circle --frames 2 --mount "$M" --rolling 33,1.0,1.6667
one lower --out @DIR@ --path straight --frames 1 --lower 2,0.4 --write-map @DIR@/map.yaml
one survey --out @DIR@ --path survey --frames 2 --seed 3 --site irregular --rock 0.02 --mount 0.1,0.02,-0.03 \
    --move 16,0.04,-0.03
# a large site's drives, on the path drives' map (fast renderer's, the same for both)
"$FAST" --out "$T/map" --path straight --frames 1 --write-map "$T/map.yaml" >/dev/null 2>&1 ||
    { echo "FAIL: the map for the site's drives"; fail=1; }
for kind in random tour edge corner; do
    one "site_$kind" --site-map "$T/map.yaml" --out @DIR@ --path "$kind" --frames 2 --seed 5 --mount "$M"
done
[ $fail = 0 ] && echo "render_checked: $n renders, each the same bytes under ASan and UBSan as optimised"
exit $fail
