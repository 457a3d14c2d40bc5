#!/bin/sh
# Check, and install when possible, what ringloc needs to build and test.
#
#   tools/deps.sh [--check] [host|cross|fuzz|asan]
#
# cross: the aarch64 cross build too (Debian's gcc-aarch64-linux-gnu,
# arm64 libraries through multiarch, qemu-user to run its tests).
#
# As root it installs what is missing with apt-get (Debian, Ubuntu,
# Raspberry Pi OS); otherwise it prints the exact apt-get line and fails.
# fuzz: clang and its libFuzzer runtime, libpng, libyaml, libturbojpeg
# (the survey's PNG frames go through the firmware's loop) and json-c.
# asan: the host's packages and clang (the sanitizer test build).
# host and asan include Chromium, its driver and python3-selenium: the web
# view's tests drive a real browser (test_view_page, test_view_hostile).
# --check only reports. Called first by `make host`, `make host-test`,
# `make demo` and `make bench`.
# Not here: AriaCoda, for the ARIA example (tools/aria), is not in Debian;
# build it from github.com/reedhedges/AriaCoda (`make lib/libAria.so`, g++
# and make only) and configure with -DARIA_DIR=its tree. The stand-in robot
# and the rest of the controller's side need nothing more.
set -eu

check_only=0
profile=host
for arg in "$@"; do
    case "$arg" in
    --check) check_only=1 ;;
    host|cross|fuzz|asan) profile=$arg ;;
    -h|--help) sed -n '2,10s/^# \{0,1\}//p' "$0"; exit 0 ;;
    *) echo "deps.sh: unknown argument '$arg' (try --help)" >&2; exit 2 ;;
    esac
done

missing=""
need_pkg() { # package-name test-command...
    pkg=$1; shift
    if ! "$@" >/dev/null 2>&1; then
        case " $missing " in *" $pkg "*) ;; *) missing="$missing $pkg" ;; esac
    fi
}
# A package installed as root, never asked for otherwise: the build works
# without it (ninja-build: the Makefile falls back to CMake's default).
want_pkg() { # package-name test-command...
    if [ "$(id -u)" = 0 ] && [ "$check_only" != 1 ] && have apt-get >/dev/null 2>&1; then need_pkg "$@"; fi
}
have() { command -v "$1"; }
ceres() { ls /usr/lib/*/cmake/Ceres/CeresConfig.cmake /usr/lib/cmake/Ceres/CeresConfig.cmake 2>/dev/null | grep -q .; }
pc() { have pkg-config && pkg-config --exists "$1"; }

fuzzer() { printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { return 0; }\n' |
    clang -fsanitize=fuzzer -x c - -o /dev/null; }
if [ "$profile" = fuzz ] || [ "$profile" = asan ]; then
    need_pkg cmake have cmake
    need_pkg make have make
    want_pkg ninja-build have ninja # the Makefile's generator for new build folders, where it can
    need_pkg pkg-config have pkg-config
    need_pkg clang have clang
    need_pkg libclang-rt-dev fuzzer
    need_pkg libpng-dev pc libpng
    need_pkg libyaml-dev pc yaml-0.1
    need_pkg libjson-c-dev pc json-c
    need_pkg libturbojpeg0-dev pc libturbojpeg
fi
if [ "$profile" != fuzz ]; then
    need_pkg cmake have cmake
    need_pkg make have make
    want_pkg ninja-build have ninja
    need_pkg gcc have cc
    need_pkg g++ have c++
    need_pkg pkg-config have pkg-config
    need_pkg libcmocka-dev pc cmocka
    need_pkg libpng-dev pc libpng
    need_pkg libyaml-dev pc yaml-0.1
    need_pkg libturbojpeg0-dev pc libturbojpeg
    need_pkg libmicrohttpd-dev pc libmicrohttpd # the web view (--http)
    need_pkg libcairo2-dev pc cairo
    need_pkg libopencv-dev pc opencv4
    need_pkg libapriltag-dev pc apriltag
    need_pkg libceres-dev ceres
    need_pkg libjson-c-dev pc json-c
    need_pkg poppler-utils have pdftoppm

    need_pkg file have file
    need_pkg systemd have systemd-analyze # the service unit's security check (test_package)
    need_pkg passwd have useradd          # the package's postinst, run by test_package
fi
[ "$profile" = host ] || [ "$profile" = asan ] && need_pkg libcamera-dev pc libcamera
if [ "$profile" = host ] || [ "$profile" = asan ]; then
    # the web view's browser tests (test_view_page, test_view_hostile)
    need_pkg chromium have chromium
    need_pkg chromium-driver have chromedriver
    need_pkg python3-selenium /usr/bin/python3 -c "import selenium"
fi
foreign=""
if [ "$profile" = cross ]; then
    arm() { [ -f "/usr/lib/aarch64-linux-gnu/pkgconfig/$1.pc" ]; }
    need_pkg gcc-aarch64-linux-gnu have aarch64-linux-gnu-gcc
    need_pkg g++-aarch64-linux-gnu have aarch64-linux-gnu-g++
    need_pkg qemu-user have qemu-aarch64
    need_pkg libpng-dev:arm64 arm libpng
    need_pkg libyaml-dev:arm64 arm yaml-0.1
    need_pkg libturbojpeg0-dev:arm64 arm libturbojpeg
    need_pkg libmicrohttpd-dev:arm64 arm libmicrohttpd
    need_pkg libcairo2-dev:arm64 arm cairo
    need_pkg libcmocka-dev:arm64 arm cmocka
    if ! dpkg --print-foreign-architectures 2>/dev/null | grep -qx arm64; then
        foreign=arm64
    fi
fi

[ -z "$missing" ] && exit 0

if [ "$check_only" = 1 ]; then
    echo "ringloc: missing packages:$missing" >&2
    exit 1
fi
if [ "$(id -u)" = 0 ] && have apt-get >/dev/null 2>&1; then
    echo "ringloc: installing$missing" >&2
    export DEBIAN_FRONTEND=noninteractive
    [ -n "$foreign" ] && dpkg --add-architecture "$foreign" >&2
    apt-get update -qq >&2
    # shellcheck disable=SC2086
    apt-get install -y -qq --no-install-recommends $missing >&2
    exit 0
fi
echo "ringloc: missing packages:$missing" >&2
if [ -n "$foreign" ]; then
    echo "ringloc: install them with: sudo dpkg --add-architecture arm64 && sudo apt-get update && sudo apt-get install -y$missing" >&2
else
    echo "ringloc: install them with: sudo apt-get install -y$missing" >&2
fi
exit 1
