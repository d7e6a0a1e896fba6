#!/bin/sh
# usage: tests/bench/alternate.sh ROUNDS PROGRAM... [-- BENCH OPTIONS]
#
# Runs the benchmark programs one after the other, one run each (--runs 1),
# ROUNDS times over, so that a change in the machine's load during the
# measurement falls on every program alike; then prints, per program, scene
# and size, the minimum and the median over the rounds of each run's mean ms
# per step, and each program's median over the first program's. Two builds
# of this engine can be compared too: the program's path tells them apart. Use it when
# the machine is shared: make bench-compare runs each program's five runs
# back to back, and a load that comes or goes between two programs shifts
# their ratio. POSIX sh and awk only.
rounds=$1
shift
programs=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    programs="$programs $1"
    shift
done
[ "$1" = "--" ] && shift
case $rounds in
    '' | *[!0-9]*) echo "usage: $0 ROUNDS PROGRAM... [-- BENCH OPTIONS]" >&2; exit 2 ;;
esac
if [ -z "$programs" ]; then
    echo "usage: $0 ROUNDS PROGRAM... [-- BENCH OPTIONS]" >&2
    exit 2
fi
lines=${TMPDIR:-/tmp}/bench-alternate.$$
: >"$lines" || exit 1
round=1
while [ "$round" -le "$rounds" ]; do
    for program in $programs; do
        "$program" "$@" --runs 1 | grep '^engine=' | sed "s|^|$program |" >>"$lines" || {
            echo "$program failed" >&2
            rm -f "$lines"
            exit 1
        }
    done
    round=$((round + 1))
done
awk '
function field(name,    i, n) {
    for (i = 1; i <= NF; i++) {
        n = index($i, "=")
        if (n > 0 && substr($i, 1, n - 1) == name) return substr($i, n + 1)
    }
    return ""
}
{
    key = $1 " " field("engine") " " field("scene") " " field("size") " " field("dt")
    if (!(key in count)) order[++keys] = key
    values[key, ++count[key]] = field("median_ms") + 0
}
function median_of(key,    n, i, j, t, a) {
    n = count[key]
    for (i = 1; i <= n; i++) a[i] = values[key, i]
    for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] > a[j]; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
    minimum[key] = a[1]
    return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}
END {
    printf "%-60s %10s %10s %4s %s\n", "program engine scene size dt", "min_ms", "median_ms", "n", "median / first program\x27s"
    for (k = 1; k <= keys; k++) {
        key = order[k]
        m = median_of(key)
        split(key, part, " ")
        scene = part[3] " " part[4] " " part[5]
        if (!(scene in first)) first[scene] = m
        printf "%-60s %10.4g %10.4g %4d %.3f\n", key, minimum[key], m, count[key], m / first[scene]
    }
}' "$lines"
rm -f "$lines"
