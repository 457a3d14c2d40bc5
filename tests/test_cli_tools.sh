#!/bin/sh
# The tools' command lines (issue 30): every number parsed by the checked
# helpers of rl_cli.h and rl_cli_num.h, one error line naming the option.
# usage: test_cli_tools.sh RENDER SURVEY_SYNTH SOAK TMPDIR
set -u
RENDER=$1
SYNTH=$2
SOAK=$3
T=$4
mkdir -p "$T"
. "$(dirname "$0")/sh_check.sh"

expect 2 "ringloc-render: --count: 'x' is not an integer" -- "$RENDER" --out "$T/r" --set clean --count x
expect 2 "ringloc-render: --frames: '12abc' is not an integer" -- "$RENDER" --out "$T/r" --path rect --frames 12abc
expect 2 "ringloc-render: --seed: '-1' is not a non-negative integer" -- "$RENDER" --out "$T/r" --set clean --seed -1
expect 2 "ringloc-render: --mount: '1,2' is not X,Y,YAW" -- "$RENDER" --out "$T/r" --path rect --mount 1,2
expect 2 "ringloc-render: --mount: '1,2,z' is not X,Y,YAW" -- "$RENDER" --out "$T/r" --path rect --mount 1,2,z
expect 2 "ringloc-render: --move: '3.5,0,0' is not ID,DX,DY" -- "$RENDER" --out "$T/r" --path rect --move 3.5,0,0
expect 2 "ringloc-render: --rock: 1 is out of range" -- "$RENDER" --out "$T/r" --path rect --rock 1
expect 2 "ringloc-render: --size: '10x10' is not a size" -- "$RENDER" --out "$T/r" --set clean --size 10x10
expect 2 "ringloc-render: unknown option '--frobnicate'" -- "$RENDER" --frobnicate
expect 1 "ringloc-render: /nonexistent/camera.yaml" -- "$RENDER" --out "$T/r" --set clean --camera /nonexistent/camera.yaml
expect 2 "ringloc-survey-synth: --cols: 'x' is not an integer" -- "$SYNTH" --camera c.yaml --out "$T/s" --cols x
expect 2 "ringloc-survey-synth: --noise: '0.1mm' is not a number" -- "$SYNTH" --camera c.yaml --out "$T/s" --noise 0.1mm
expect 2 "ringloc-survey-synth: --seed: '' is not a non-negative integer" -- "$SYNTH" --camera c.yaml --out "$T/s" --seed ""
expect 1 "ringloc-survey-synth: /nonexistent/camera.yaml" -- "$SYNTH" --camera /nonexistent/camera.yaml --out "$T/s"
expect 2 "ringloc-soak: --frames: 10 is out of range" -- "$SOAK" --frames 10 "$T"
expect 2 "ringloc-soak: --reopen-every: 'x' is not a number" -- "$SOAK" --reopen-every x "$T"
expect 1 "ringloc-soak: $T/none/camera.yaml" -- "$SOAK" "$T/none"

sh_done
