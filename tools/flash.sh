#!/bin/sh
# Install a ringloc .deb on a board over ssh and restart the service.
#
#   tools/flash.sh [--dry-run] USER@HOST build-rpi4/package/ringloc_*.deb
#   make flash BOARD=rpi4 TARGET=pi@robot.local [DRY_RUN=1]
#
# Copies the package with scp, installs it with apt (dependencies come from
# the board's own repositories), and restarts ringloc.service. --dry-run
# prints the commands instead of running them.
set -eu
dry=0
if [ "${1:-}" = "--dry-run" ]; then dry=1; shift; fi
if [ "${1:-}" = "-h" ] || [ "${1:-}" = "--help" ]; then sed -n '2,10s/^# \{0,1\}//p' "$0"; exit 0; fi
target=${1:-}
deb=${2:-}
if [ -z "$target" ] || [ -z "$deb" ]; then
    echo "flash: usage: tools/flash.sh [--dry-run] USER@HOST PACKAGE.deb (make flash BOARD=... TARGET=USER@HOST)" >&2
    exit 2
fi
case "$target" in
*@*) ;;
*) echo "flash: TARGET '$target' is not USER@HOST" >&2; exit 2 ;;
esac
if [ ! -f "$deb" ]; then
    echo "flash: $deb: no such package (make package BOARD=...)" >&2
    exit 1
fi
name=$(basename "$deb")
run() {
    if [ $dry = 1 ]; then echo "$*"; else "$@"; fi
}
run scp "$deb" "$target:/tmp/$name"
run ssh "$target" "sudo apt-get install -y /tmp/$name && sudo systemctl daemon-reload && sudo systemctl enable ringloc.service && sudo systemctl restart ringloc.service && rm -f /tmp/$name"
if [ $dry = 0 ]; then
    echo "flash: installed $name on $target; check with: ssh $target journalctl -u ringloc -n 20"
fi
