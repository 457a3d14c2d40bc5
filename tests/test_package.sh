#!/bin/sh
# The .deb a board receives: built by CPack from this build, then inspected
# as a user's dpkg would see it.
# usage: test_package.sh BUILD_DIR TMPDIR ARCH SERIAL_DEVICE [CC]
set -u
B=$1
T=$2
ARCH=$3
SERIAL=$4
CC=${5:-cc}
SRC=$(cd "$(dirname "$0")/.." && pwd)
rm -rf "$T"
mkdir -p "$T"
pass=0
fail=0
check() { # description command...
    what=$1; shift
    if "$@" >/dev/null 2>&1; then pass=$((pass + 1)); else echo "FAIL: $what"; fail=$((fail + 1)); fi
}
not() { ! "$@"; }
# Every path reaches a command as one argument, never pasted into shell
# code (a build folder may hold a space, a quote, a $ or a backtick). Where
# a path must be written into another language's text (systemd's command
# line, pkg-config's flags), it is written as $SAFE/t: a link to $T from a
# folder of plain characters (mktemp's under /tmp), removed at the end.
SAFE=$(mktemp -d /tmp/rl_package.XXXXXX) && ln -s "$T" "$SAFE/t" || { echo "0 passed, 1 failed"; exit 1; }
trap 'rm -rf "$SAFE"' EXIT
case $SAFE in *[!A-Za-z0-9/._-]*) echo "FAIL: mktemp gave '$SAFE'"; echo "0 passed, 1 failed"; exit 1 ;; esac
# the fuse header's example, built with pkg-config's flags ($1, shell words
# of $SAFE's paths) by CC (the compiler's words: cc, or a sanitizer
# build's compiler with its flags), and run on the package's shared library
build_fuse_example() {
    # shellcheck disable=SC2086 # the compiler's and the flags' words
    $CC -std=c99 -Wall -Werror -DRL_FUSE_HISTORY=16 -o "$T/use_fuse" "$T/use_fuse.c" $1 &&
        LD_LIBRARY_PATH="$T/fuse/usr/lib" "$T/use_fuse"
}
(cd "$B" && cpack -G DEB -B "$T/out" >"$T/cpack.log" 2>&1) || { cat "$T/cpack.log"; echo "0 passed, 1 failed"; exit 1; }
deb=$(ls "$T"/out/ringloc_*_"$ARCH".deb 2>/dev/null | head -1)
check "a ringloc_*_$ARCH.deb is built" test -f "$deb"
dpkg-deb -f "$deb" >"$T/control"
check "architecture is $ARCH" grep -qx "Architecture: $ARCH" "$T/control"
check "dependencies declared" grep -qE '^Depends: .*libc6.*libpng16-16.*libyaml.*libturbojpeg0' "$T/control"
check "the robot's package needs no cairo" not grep -q cairo "$T/control"
dpkg-deb -c "$deb" >"$T/files"
check "firmware binary in /usr/bin" grep -q '\./usr/bin/ringloc-fw$' "$T/files"
check "no desktop tools on the robot" not grep -q '\./usr/bin/ringloc$' "$T/files"
check "default configuration" grep -q '\./etc/ringloc/ringloc.yaml$' "$T/files"
check "systemd unit" grep -q '\./lib/systemd/system/ringloc.service$' "$T/files"
check "docs" grep -q '\./usr/share/doc/ringloc/README.md$' "$T/files"
check "the landmark contract" grep -q '\./usr/share/doc/ringloc/docs/landmark-spec.md$' "$T/files"
mkdir -p "$T/ctl" "$T/root"
dpkg-deb -e "$deb" "$T/ctl"
dpkg-deb -x "$deb" "$T/root"
check "configuration is a conffile" grep -qx '/etc/ringloc/ringloc.yaml' "$T/ctl/conffiles"
check "postinst enables the service" grep -q 'systemctl enable ringloc.service' "$T/ctl/postinst"
check "binary is for $ARCH" sh -c 'file "$1" | grep -q "$2"' sh "$T/root/usr/bin/ringloc-fw" \
    "$( [ "$ARCH" = arm64 ] && echo aarch64 || echo x86-64 )"
# what the firmware binary links: no cairo, no OpenCV (readelf reads any arch)
readelf -d "$T/root/usr/bin/ringloc-fw" >"$T/needed" 2>&1
check "ringloc-fw links libpng, libyaml and libturbojpeg" sh -c \
    'grep -q libpng "$1" && grep -q libyaml "$1" && grep -q libturbojpeg "$1"' sh "$T/needed"
check "the web view's library, when linked, is declared" sh -c \
    '! grep -q libmicrohttpd "$1" || grep -qE "^Depends: .*libmicrohttpd12" "$2"' sh "$T/needed" "$T/control"
check "ringloc-fw links neither cairo nor OpenCV" not grep -qiE 'cairo|opencv' "$T/needed"
check "ringloc-fw has no run path into the build tree" not grep -qF -- "$B" "$T/needed"
# the modules (hal/rl_module.h): a package carries each one its build made
if [ -f "$B/lib/ringloc/ringloc-libcamera.so" ]; then
    check "the robot's package carries the libcamera module" grep -q '\./usr/lib/ringloc/ringloc-libcamera.so$' "$T/files"
    check "ringloc-fw links no libcamera (its module does)" not grep -q 'NEEDED.*libcamera' "$T/needed"
    if [ "$ARCH" = "$(dpkg --print-architecture)" ]; then
        # the unpacked package's own module, found next to its binary's folder
        printf 'camera:\n  backend: libcamera\n  device: "0"\nserial:\n  device: /dev/null\n  baud: 115200\ncalibration: c.yaml\nmap: m.yaml\nrobot: r.yaml\n' >"$T/lc.yaml"
        "$T/root/usr/bin/ringloc-fw" --config "$T/lc.yaml" --probe >/dev/null 2>"$T/lc.err"; rc=$?
        check "the unpacked ringloc-fw loads its libcamera module" sh -c \
            '[ "$1" = 0 ] || grep -q "camera: libcamera camera" "$2"' sh "$rc" "$T/lc.err"
    fi
fi
tools=$(ls "$T"/out/ringloc-tools_*_"$ARCH".deb 2>/dev/null | head -1)
check "a ringloc-tools_*_$ARCH.deb is built" test -f "$tools"
check "the tools package has the ringloc command" sh -c 'dpkg-deb -c "$1" | grep -q "\./usr/bin/ringloc$"' sh "$tools"
check "the tools package declares cairo" sh -c 'dpkg-deb -f "$1" Depends | grep -q libcairo2' sh "$tools"
dpkg-deb -c "$tools" >"$T/tools_files" 2>/dev/null
if [ -f "$B/lib/ringloc/ringloc-ceres.so" ]; then
    check "the tools package carries the survey's solver module" grep -q '\./usr/lib/ringloc/ringloc-ceres.so$' "$T/tools_files"
    mkdir -p "$T/tools"
    dpkg-deb -x "$tools" "$T/tools" 2>/dev/null
    check "ringloc links no Ceres (its module does)" sh -c \
        '! readelf -d "$1" | grep -qiE "NEEDED.*(ceres|glog)"' sh "$T/tools/usr/bin/ringloc"
    if [ "$ARCH" = "$(dpkg --print-architecture)" ]; then
        # a survey from the unpacked package finds its solver before it
        # reads a frame: the one error is then the missing frame's
        printf 'camera_mount: {x: 0, y: 0, z: 0.88, yaw: 0}\n' >"$T/robot.yaml"
        "$T/tools/usr/bin/ringloc" survey --camera "$SRC/tests/fixtures/camera.yaml" --robot "$T/robot.yaml" \
            --origin 1 --axis 2 --out "$T/m.yaml" "$T/no_frames.jsonl" 2>"$T/sv.err" </dev/null >/dev/null
        check "the unpacked ringloc finds the survey's solver" sh -c \
            'grep -q no_frames.jsonl "$1" && ! grep -q solver "$1"' sh "$T/sv.err"
    fi
fi
# the controller's package (issue 27): rl_fuse to build against, checked by
# building its header's usage example through its pkg-config file
fuse=$(ls "$T"/out/ringloc-fuse_*_"$ARCH".deb 2>/dev/null | head -1)
check "a ringloc-fuse_*_$ARCH.deb is built" test -f "$fuse"
mkdir -p "$T/fuse"
dpkg-deb -x "$fuse" "$T/fuse" 2>/dev/null
for f in usr/lib/libringloc_fuse.a usr/lib/libringloc_fuse.so usr/lib/pkgconfig/ringloc-fuse.pc \
    usr/include/ringloc/rl_fuse.h usr/include/ringloc/rl_packet.h usr/include/ringloc/rl_error.h \
    usr/share/doc/ringloc-fuse/examples/ringloc_aria_fuse.cpp usr/share/doc/ringloc-fuse/examples/rl_outfile.c \
    usr/share/doc/ringloc-fuse/examples/rl_outfile.h; do
    check "ringloc-fuse has /$f" test -e "$T/fuse/$f"
done
check "the fuse package needs only libc" sh -c 'dpkg-deb -f "$1" Depends | grep -qx "libc6 (>= 2.34)"' sh "$fuse"
if [ "$ARCH" = "$(dpkg --print-architecture)" ] && command -v pkg-config >/dev/null 2>&1; then
    # the header's usage example (its first comment's last block of ' *   ' lines)
    awk '/\*\// { exit } /^ \*   / { if (!inb) { body = ""; inb = 1 } sub(/^ \*   /, "    "); body = body $0 "\n"; next }
         { inb = 0 } END { printf "%s", body }' "$T/fuse/usr/include/ringloc/rl_fuse.h" >"$T/body.c"
    { printf '#include <string.h>\n#include "rl_fuse.h"\nstatic void use(double a, double b, double c, double d) { (void)a; (void)b; (void)c; (void)d; }\n'
      printf 'int main(void)\n{\n'; sed 's/return;/return 1;/' "$T/body.c"; printf '    return 0;\n}\n'; } >"$T/use_fuse.c"
    # pkg-config's flags are shell words: the unpacked package reached
    # through $SAFE's link, so that
    # no path of this build lands in them
    flags=$(PKG_CONFIG_PATH="$SAFE/t/fuse/usr/lib/pkgconfig" pkg-config --cflags --libs ringloc-fuse)
    check "a program builds against ringloc-fuse.pc and runs on its shared library" build_fuse_example "$flags"
fi
check "configuration names the board's serial device" grep -q "device: $SERIAL" "$T/root/etc/ringloc/ringloc.yaml"
unit="$T/root/lib/systemd/system/ringloc.service"
check "unit restarts whatever the end (SIGHUP's status 0 too)" grep -qx 'Restart=always' "$unit"
check "unit is Type=notify with a watchdog" sh -c 'grep -qx Type=notify "$1" && grep -qx WatchdogSec=10 "$1"' sh "$unit"
check "the web drop-in orders the service after the network" sh -c \
    'grep -qx After=network-online.target "$1" && grep -qx Wants=network-online.target "$1"' sh \
    "$T/root/usr/share/doc/ringloc/ringloc-web.conf"
check "unit waits for the serial device" grep -q '^After=.*\.device' "$unit"
check "unit runs the firmware on the packaged configuration" grep -qx 'ExecStart=/usr/bin/ringloc-fw --config /etc/ringloc/ringloc.yaml' "$unit"
# the service: an unprivileged user, sandboxed (issue 28)
check "unit runs as the ringloc user" grep -qx 'User=ringloc' "$unit"
check "unit has its state folder" grep -qx 'StateDirectory=ringloc' "$unit"
check "unit allows the serial line's device class" grep -qx 'DeviceAllow=char-ttyAMA rw' "$unit"
check "unit allows V4L2 cameras" grep -qx 'DeviceAllow=char-video4linux rw' "$unit"
check "the package declares passwd (useradd)" grep -qE '^Depends: .*passwd' "$T/control"
if command -v systemd-analyze >/dev/null 2>&1; then
    systemd-analyze security --offline=true "$unit" >"$T/security.txt" 2>&1
    exposure=$(sed -n 's/.*Overall exposure level for [^:]*: \([0-9.]*\).*/\1/p' "$T/security.txt")
    if [ -n "$exposure" ] && awk "BEGIN { exit !($exposure <= 3.5) }"; then
        pass=$((pass + 1))
        echo "systemd-analyze security: exposure $exposure"
    else
        echo "FAIL: systemd-analyze security: exposure '${exposure:-?}' (at most 3.5):"; tail -5 "$T/security.txt"
        fail=$((fail + 1))
    fi
else
    echo "FAIL: systemd-analyze is missing (tools/deps.sh installs the systemd package)"; fail=$((fail + 1))
fi
# the postinst as dpkg runs it (root, twice: an upgrade), systemctl a stub
# so that nothing on this machine is enabled; what it made is removed again
if [ "$(id -u)" = 0 ] && command -v useradd >/dev/null 2>&1; then
    had_user=0; getent passwd ringloc >/dev/null && had_user=1
    had_dir=0; [ -e /var/lib/ringloc ] && had_dir=1
    mkdir -p "$T/stub"
    printf '#!/bin/sh\nexit 0\n' >"$T/stub/systemctl"
    chmod +x "$T/stub/systemctl"
    PATH="$T/stub:$PATH" sh "$T/ctl/postinst" configure >"$T/postinst.log" 2>&1 &&
        PATH="$T/stub:$PATH" sh "$T/ctl/postinst" configure >>"$T/postinst.log" 2>&1; rc=$?
    check "postinst runs twice (rc $rc: $(head -2 "$T/postinst.log"))" test $rc = 0
    check "postinst makes the system user ringloc" sh -c '[ "$(getent passwd ringloc | cut -d: -f3)" -lt 1000 ]'
    check "ringloc cannot log in" sh -c 'getent passwd ringloc | grep -q ":/usr/sbin/nologin$"'
    for group in video dialout; do
        getent group "$group" >/dev/null &&
            check "ringloc is in $group" sh -c 'id -nG ringloc | tr " " "\n" | grep -qx -- "$1"' sh "$group"
    done
    check "/var/lib/ringloc is ringloc's, 0750" sh -c '[ "$(stat -c %U:%a /var/lib/ringloc)" = ringloc:750 ]'
    [ "$(dpkg --print-architecture)" = "$ARCH" ] && check "the firmware runs as ringloc" sh -c \
        'setpriv --reuid=ringloc --regid=ringloc --init-groups "$1" --help | grep -q usage' sh "$T/root/usr/bin/ringloc-fw"
    [ $had_user = 1 ] || { userdel ringloc 2>/dev/null; getent group ringloc >/dev/null && groupdel ringloc; }
    [ $had_dir = 1 ] || rmdir /var/lib/ringloc 2>/dev/null
else
    echo "postinst not run: needs root and useradd"
fi
if command -v systemd-analyze >/dev/null 2>&1; then
    # verify the unit as packaged, but with ExecStart on the unpacked binary
    # (this machine has no /usr/bin/ringloc-fw installed), named through
    # $SAFE's link: a unit's command line is systemd's syntax, in which
    # a space or a quote of the build's path would be code
    mkdir -p "$T/verify"
    sed "s|^ExecStart=/usr/bin/ringloc-fw|ExecStart=$SAFE/t/root/usr/bin/ringloc-fw|" "$unit" \
        >"$T/verify/ringloc.service"
    if systemd-analyze verify "$T/verify/ringloc.service" >"$T/verify.log" 2>&1 &&
       ! grep -qiE 'error|invalid|unknown' "$T/verify.log"; then
        pass=$((pass + 1))
    else
        echo "FAIL: systemd-analyze verify:"; cat "$T/verify.log"; fail=$((fail + 1))
    fi
    # with the web view's drop-in (network for http:) the unit still verifies
    mkdir -p "$T/verify/ringloc.service.d"
    cp "$T/root/usr/share/doc/ringloc/ringloc-web.conf" "$T/verify/ringloc.service.d/web.conf" 2>/dev/null
    if [ -f "$T/verify/ringloc.service.d/web.conf" ] &&
       systemd-analyze verify "$T/verify/ringloc.service" >"$T/verify_web.log" 2>&1 &&
       ! grep -qiE 'error|invalid|unknown' "$T/verify_web.log"; then
        pass=$((pass + 1))
    else
        echo "FAIL: the web view's drop-in (usr/share/doc/ringloc/ringloc-web.conf):"; cat "$T/verify_web.log"
        fail=$((fail + 1))
    fi
fi
echo "$pass passed, $fail failed"
[ "$fail" = 0 ]
