#!/bin/sh
# usage: tests/bench/alternate.sh [-c CPU] [-o RAW] [-i INSTRUCTIONS] ROUNDS PROGRAM...
#                                 [-- BENCH OPTIONS]
#
# Runs the benchmark programs one after the other, one run each (--runs 1),
# ROUNDS times over, so that a change in the machine's load during the
# measurement falls on every program alike, each pinned to one CPU (taskset
# -c CPU, default the last CPU; left unpinned when taskset is missing).
# Times are the programs' own: CPU time of the process spent in the step
# calls (CLOCK_PROCESS_CPUTIME_ID). Then prints, per scene, size and dt, one
# row per metric (step: every step; settled: pile's steps 301..600) with,
# for each engine, the median ms per step over the rounds and its range
# (min-max), and the ratio of the first engine (this engine, "ours") to each
# other engine: the median and range over the rounds of the ratio of the two
# runs of the same round. Engines are told apart by program path and engine
# name, so two builds of this engine can be compared too.
#   -o RAW           keeps the raw result lines (prefixed by the program)
#   -i INSTRUCTIONS  a table of tests/bench/instructions.sh: its instructions
#                    per step are printed in a second table
# POSIX sh and awk only.
cpu=""
raw=""
instructions=""
while [ $# -gt 0 ]; do
    case $1 in
        -c) cpu=$2; shift 2 ;;
        -o) raw=$2; shift 2 ;;
        -i) instructions=$2; shift 2 ;;
        *) break ;;
    esac
done
rounds=$1
[ $# -gt 0 ] && shift
programs=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    programs="$programs $1"
    shift
done
[ "$1" = "--" ] && shift
case $rounds in
    '' | *[!0-9]*) echo "usage: $0 [-c CPU] [-o RAW] [-i INSTRUCTIONS] ROUNDS PROGRAM... [-- BENCH OPTIONS]" >&2; exit 2 ;;
esac
if [ -z "$programs" ]; then
    echo "usage: $0 [-c CPU] [-o RAW] [-i INSTRUCTIONS] ROUNDS PROGRAM... [-- BENCH OPTIONS]" >&2
    exit 2
fi
pin=""
if command -v taskset >/dev/null 2>&1; then
    [ -n "$cpu" ] || cpu=$(($(getconf _NPROCESSORS_ONLN 2>/dev/null || echo 1) - 1))
    taskset -c "$cpu" true 2>/dev/null && pin="taskset -c $cpu"
fi
lines=${TMPDIR:-/tmp}/bench-alternate.$$
: >"$lines" || exit 1
trap 'rm -f "$lines"' EXIT INT TERM
echo "# alternate.sh: $rounds rounds; ${pin:-not pinned (no taskset)}; CPU time of the step calls; $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "# load average at the start: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)"
round=1
while [ "$round" -le "$rounds" ]; do
    for program in $programs; do
        $pin "$program" "$@" --runs 1 >"$lines.one" || {
            echo "$program failed" >&2
            rm -f "$lines.one"
            exit 1
        }
        [ "$round" = 1 ] && grep '^# ' "$lines.one" | grep -v '^# compiler\|^# timing\|canonical scenes' |
            sed "s|^# |# $(basename "$program"): |"
        grep '^engine=' "$lines.one" | sed "s|^|$program round=$round |" >>"$lines"
    done
    round=$((round + 1))
done
rm -f "$lines.one"
echo "# load average at the end: $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)"
[ -n "$raw" ] && cp "$lines" "$raw"
awk -v instructions="$instructions" '
function field(name,    i, n) {
    for (i = 1; i <= NF; i++) {
        n = index($i, "=")
        if (n > 0 && substr($i, 1, n - 1) == name) return substr($i, n + 1)
    }
    return ""
}
function sort_values(a, n,    i, j, t) {
    for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] > a[j]; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
}
function median(a, n) { return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2 }
function add(metric, value) {
    if (value == "") return
    row = case_ SUBSEP metric
    if (!(row in seen_row)) { seen_row[row] = 1; rows[++nrows] = row }
    ms[row, engine, $2] = value
}
{
    program = $1; sub(/^round=/, "", $2)
    engine = program " " field("engine")
    if (!(engine in seen_engine)) { seen_engine[engine] = 1; engines[++nengines] = engine }
    dt = field("dt"); if (dt == "") dt = "-"
    case_ = field("scene") " " field("size") " " dt
    add("step", field("median_ms"))
    add("settled", field("settled_median_ms"))
    if ($2 > nrounds) nrounds = $2
}
END {
    for (e = 1; e <= nengines; e++) {
        name = engines[e]; sub(/^[^ ]* /, "", name); label[e] = name
        w = length(name) + 2; width[e] = w < 22 ? 22 : w
    }
    printf "%-22s %-8s", "scene size dt", "metric"
    for (e = 1; e <= nengines; e++) printf " %" width[e] "s", label[e]
    printf "\n"
    for (r = 1; r <= nrows; r++) {
        row = rows[r]; split(row, part, SUBSEP)
        printf "%-22s %-8s", part[1], part[2]
        for (e = 1; e <= nengines; e++) {
            n = 0
            for (k = 1; k <= nrounds; k++) if ((row, engines[e], k) in ms) a[++n] = ms[row, engines[e], k] + 0
            if (n == 0) { printf " %" width[e] "s", "-"; continue }
            sort_values(a, n)
            printf " %" width[e] "s", sprintf("%.4g (%.4g-%.4g)", median(a, n), a[1], a[n])
        }
        printf "\n"
    }
    printf "\nratio %s / each engine, per round (median (min-max) over the rounds; above 1: %s slower)\n", label[1], label[1]
    printf "%-22s %-8s", "scene size dt", "metric"
    for (e = 2; e <= nengines; e++) printf " %" width[e] "s", "/" label[e]
    printf "\n"
    for (r = 1; r <= nrows; r++) {
        row = rows[r]; split(row, part, SUBSEP)
        printf "%-22s %-8s", part[1], part[2]
        for (e = 2; e <= nengines; e++) {
            n = 0
            for (k = 1; k <= nrounds; k++)
                if ((row, engines[1], k) in ms && (row, engines[e], k) in ms && ms[row, engines[e], k] > 0)
                    a[++n] = ms[row, engines[1], k] / ms[row, engines[e], k]
            if (n == 0) { printf " %" width[e] "s", "-"; continue }
            sort_values(a, n)
            printf " %" width[e] "s", sprintf("%.3g (%.3g-%.3g)", median(a, n), a[1], a[n])
        }
        printf "\n"
    }
    if (instructions != "") {
        printf "\ninstructions per step (callgrind, %s)\n", instructions
        while ((getline line < instructions) > 0) if (line !~ /^#/) print line
    }
}' "$lines"
