#!/bin/sh
# make check's smoke run of the accuracy report: build/report/accuracy
# --quick into a scratch directory must write every scene's CSV, the plot
# script and a page with a section per scene. The figures themselves are
# asserted by tests/test_integrators.c. Ends with "N passed, N failed".
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
if ! build/report/accuracy --quick --out "$out" --doc "$out/accuracy.md" 2>"$out/log"; then
    cat "$out/log"
    echo "FAIL report.quick_run_completes"
    echo "0 passed, 1 failed"
    exit 1
fi
echo "PASS report.quick_run_completes"
missing=""
for scene in oscillator kepler orbit drag bounce; do
    [ -s "$out/$scene.csv" ] || missing="$missing $scene.csv"
    grep -q "^### $scene\$" "$out/accuracy.md" || missing="$missing section:$scene"
done
[ -s "$out/collisions.csv" ] || missing="$missing collisions.csv"
grep -q "set output 'work-kepler.svg'" "$out/plots.gp" || missing="$missing plots.gp"
if [ -z "$missing" ]; then
    echo "PASS report.writes_every_scene"
    echo "2 passed, 0 failed"
else
    echo "FAIL report.writes_every_scene: missing$missing"
    echo "1 passed, 1 failed"
    exit 1
fi
