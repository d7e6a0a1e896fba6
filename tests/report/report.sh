#!/bin/sh
# make report: docs/accuracy.md. First the contact solver beside the peers
# (the benchmark programs of tests/bench, alternated over ROUNDS rounds),
# then build/report/accuracy (the integrators: sweeps, long horizons,
# stability regions, contacts), then the plots (gnuplot) and the page's
# provenance (tests/provenance.sh). Everything lands in docs/report/.
#   REPORT_ROUNDS (default 3): rounds of the peers' runs
set -e
out=docs/report
state=build/report/provenance.state
rounds=${REPORT_ROUNDS:-3}
mkdir -p "$out" build/report
tests/provenance.sh begin "$state"
lines="$out/solver-lines.txt"
settings="$out/solver-settings.txt"
: >"$lines"
: >"$settings"

# One program, one variant, one scene: its result line, prefixed, and its
# '#' lines (settings) once.
run() {
    round=$1 iterations=$2 program=$3 variant=$4 scene=$5 size=$6
    [ -x "$program" ] || return 0
    set -- --variant "$variant" --scene "$scene" --size "$size" --runs 1
    [ "$iterations" = default ] || set -- "$@" --iterations "$iterations"
    output=$("$program" "$@") || { echo "report: $program $* failed" >&2; return 0; }
    printf '%s\n' "$output" | grep '^engine=' | sed "s/^/round=$round iterations=$iterations /" >>"$lines"
    printf '%s\n' "$output" | grep '^# ' | grep -v -e '--iterations' -e '^# build/' |
    while IFS= read -r line; do
        grep -qxF "$line" "$settings" || printf '%s\n' "$line" >>"$settings"
    done
}

# A variant at the iteration counts it has (matched) or at its defaults.
peers="build/bench/bench_engine:ours:matched build/bench/bench_chipmunk:chipmunk:matched
build/bench/bench_box2d:box2d-matched:matched build/bench/bench_chipmunk:chipmunk-default:default
build/bench/bench_box2d:box2d-nosleep:default build/bench/bench_box2d3-sse2:box2d3-sse2:default"
for program in build/bench/bench_chipmunk build/bench/bench_box2d build/bench/bench_box2d3-sse2; do
    [ -x "$program" ] || echo "report: $program not built; its rows are left out" >&2
done
for round in $(seq 1 "$rounds"); do
    for iterations in default 1 2 4 8 16 32; do
        printf '\r  peers: round %s/%s, iterations %-8s' "$round" "$rounds" "$iterations" >&2
        for peer in $peers; do
            program=${peer%%:*} rest=${peer#*:}
            variant=${rest%%:*} kind=${rest#*:}
            if [ "$iterations" = default ] || [ "$kind" = matched ]; then
                run "$round" "$iterations" "$program" "$variant" pyramid 20
                run "$round" "$iterations" "$program" "$variant" column 10
            fi
        done
    done
done
echo >&2

build/report/accuracy --out "$out" --doc docs/accuracy.md --solver "$lines"
(cd "$out" && gnuplot plots.gp)
rm -f "$out"/*.dat "$out"/*.grid "$out"/*.contour
tests/provenance.sh stamp docs/accuracy.md "$state"
echo "report: wrote docs/accuracy.md and $(ls "$out"/*.svg | wc -l) plots in $out" >&2
