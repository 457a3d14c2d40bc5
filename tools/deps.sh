#!/bin/sh
# Check, and install when possible, what ringloc needs to build and test.
#
#   tools/deps.sh [--check] [host]
#
# As root it installs what is missing with apt-get (Debian, Ubuntu,
# Raspberry Pi OS); otherwise it prints the exact apt-get line and fails.
# --check only reports. Called first by `make host`, `make host-test`,
# `make demo` and `make bench`.
set -eu

check_only=0
profile=host
for arg in "$@"; do
    case "$arg" in
    --check) check_only=1 ;;
    host) profile=$arg ;;
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
have() { command -v "$1"; }
pc() { have pkg-config && pkg-config --exists "$1"; }

need_pkg cmake have cmake
need_pkg make have make
need_pkg gcc have cc
need_pkg g++ have c++
need_pkg pkg-config have pkg-config
need_pkg libcmocka-dev pc cmocka
need_pkg libpng-dev pc libpng
need_pkg libyaml-dev pc yaml-0.1
need_pkg libcairo2-dev pc cairo
need_pkg libopencv-dev pc opencv4
need_pkg libapriltag-dev pc apriltag
need_pkg poppler-utils have pdftoppm

[ -z "$missing" ] && exit 0

if [ "$check_only" = 1 ]; then
    echo "ringloc: missing packages:$missing" >&2
    exit 1
fi
if [ "$(id -u)" = 0 ] && have apt-get >/dev/null 2>&1; then
    echo "ringloc: installing$missing" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq >&2
    # shellcheck disable=SC2086
    apt-get install -y -qq --no-install-recommends $missing >&2
    exit 0
fi
echo "ringloc: missing packages:$missing" >&2
echo "ringloc: install them with: sudo apt-get install -y$missing" >&2
exit 1
