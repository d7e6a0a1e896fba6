#!/bin/sh
# usage: tests/bench/instructions.sh [-o FILE] [-s "SCENE:SIZE ..."] PROGRAM[:VARIANT]...
#                                    [-- BENCH OPTIONS]
#
# Instructions per step of each engine, counted by callgrind inside the
# step calls only (--toggle-collect='bench_step*': the engine's step and what
# it calls; building the scene and reading the quality figures are left
# out). Unlike a time, the count does not move with the machine's load.
# Each PROGRAM runs once per case under valgrind, with --runs 1, the given
# VARIANT (--variant) and the BENCH OPTIONS; the cases are SCENE:SIZE words
# (default "pile:1000 pyramid:20"; callgrind runs about 50 times slower than
# the program, so pile 4000 takes minutes per engine and pile 10000 longer).
# Prints one line per case and engine: scene, size, program, engine,
# instructions per step and the number of steps (a table alternate.sh -i
# prints beside its times). POSIX sh and awk only; needs valgrind.
output=""
cases="pile:1000 pyramid:20"
while [ $# -gt 0 ]; do
    case $1 in
        -o) output=$2; shift 2 ;;
        -s) cases=$2; shift 2 ;;
        *) break ;;
    esac
done
programs=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    programs="$programs $1"
    shift
done
[ "$1" = "--" ] && shift
if [ -z "$programs" ]; then
    echo "usage: $0 [-o FILE] [-s \"SCENE:SIZE ...\"] PROGRAM[:VARIANT]... [-- BENCH OPTIONS]" >&2
    exit 2
fi
command -v valgrind >/dev/null 2>&1 || { echo "$0: valgrind is not installed" >&2; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/bench-instructions.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT INT TERM
{
    echo "# instructions.sh: callgrind instructions (Ir) inside bench_step per step; $(valgrind --version)"
    printf "%-10s %-6s %-22s %-22s %14s %6s\n" "# scene" size program engine instructions steps
    for c in $cases; do
        scene=${c%%:*}
        size=${c#*:}
        for pv in $programs; do
            program=${pv%%:*}
            if [ "$program" != "$pv" ]; then variant="--variant ${pv#*:}"; else variant=""; fi
            valgrind --tool=callgrind --callgrind-out-file="$work/cg" --toggle-collect='bench_step*' \
                "$program" --runs 1 --count-steps --scene "$scene" --size "$size" $variant "$@" \
                >"$work/out" 2>"$work/err" || { cat "$work/err" >&2; exit 1; }
            total=$(sed -n 's/^\(summary\|totals\): *\([0-9]*\).*/\2/p' "$work/cg" | tail -n 1)
            grep '^engine=' "$work/out" | awk -v total="$total" -v program="$(basename "$program")" '
            function field(name,    i, n) {
                for (i = 1; i <= NF; i++) {
                    n = index($i, "=")
                    if (n > 0 && substr($i, 1, n - 1) == name) return substr($i, n + 1)
                }
                return ""
            }
            {
                steps = field("timed_steps") + 0
                lines++
                printf "%-10s %-6s %-22s %-22s %14.4g %6d\n", field("scene"), field("size"), program,
                       field("engine"), (steps > 0 ? total / steps : 0), steps
            }
            END { if (lines > 1) print "# (several variants ran: the count is their sum; give PROGRAM:VARIANT)" }'
        done
    done
} >"$work/table"
[ -n "$output" ] && cp "$work/table" "$output"
cat "$work/table"
