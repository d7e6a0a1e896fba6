#!/bin/sh
# make report: measures the contact solver of the three engines at several
# iteration counts (the benchmark programs of tests/bench), then runs the
# integrator sweeps (build/report/accuracy), which write docs/accuracy.md,
# and draws the plots with gnuplot. Everything lands in docs/report/.
set -e
out=docs/report
mkdir -p "$out"
csv="$out/solver.csv"

# engine=NAME ... key=value ...: the value of one key on the first line.
field() {
    printf '%s\n' "$1" | tr ' ' '\n' | sed -n "s/^$2=//p" | head -n 1
}

echo "engine,iterations,pyramid_ms,top_drop,max_penetration,column_ms,column_drift" > "$csv"
for program in build/bench/bench_engine build/bench/bench_chipmunk build/bench/bench_box2d; do
    [ -x "$program" ] || { echo "report: $program not built; its points are left out" >&2; continue; }
    for iterations in 1 2 4 8 16 32; do
        printf '\r  solver     %-28s iterations %-3s' "$program" "$iterations" >&2
        pyramid=$("$program" --scene pyramid --size 20 --iterations "$iterations" --runs 3 |
                  grep '^engine=' | head -n 1)
        column=$("$program" --scene column --size 10 --iterations "$iterations" --runs 1 |
                 grep '^engine=' | head -n 1)
        echo "$(field "$pyramid" engine),$iterations,$(field "$pyramid" median_ms),$(field "$pyramid" top_drop),$(field "$pyramid" max_penetration),$(field "$column" median_ms),$(field "$column" top_drift)" >> "$csv"
    done
done
echo >&2

build/report/accuracy --solver "$csv"
(cd "$out" && gnuplot plots.gp)
rm -f "$out"/*.dat
echo "report: wrote docs/accuracy.md and $(ls "$out"/*.svg | wc -l) plots in $out" >&2
