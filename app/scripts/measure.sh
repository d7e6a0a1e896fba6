#!/bin/sh
# Measures the sandbox with many bodies in software rendering (docs/sandbox-reference.md).
# Usage: app/scripts/measure.sh [BODIES] [FRAMES]   (from the repository root)
# 1. headless: SDL's dummy video driver and software renderer, no display;
# 2. in a window, drawn in software, paced to the display as a person sees
#    it: on $DISPLAY, or on a private Xvfb when there is no display and Xvfb
#    is installed.
# Each run spawns BODIES bodies (0.2 m) in a grid that falls into a pile, and
# prints frame, physics, render and present times averaged over FRAMES frames.
set -e
bodies=${1:-2000}
frames=${2:-600}
run() {
    echo "== ./sandbox $*"
    ./sandbox --spawn "$bodies" --frames "$frames" --stats "$@"
}
run --headless --overlays none
run --headless
xvfb_pid=
if [ -z "$DISPLAY" ] && command -v Xvfb >/dev/null 2>&1; then
    Xvfb :77 -screen 0 1600x900x24 >/dev/null 2>&1 &
    xvfb_pid=$!
    export DISPLAY=:77
    sleep 1
fi
if [ -n "$DISPLAY" ]; then
    run --overlays none
    run
else
    echo "(no display and no Xvfb: window runs skipped)"
fi
[ -n "$xvfb_pid" ] && kill "$xvfb_pid"
exit 0
