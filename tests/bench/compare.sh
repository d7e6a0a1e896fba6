#!/bin/sh
# usage: tests/bench/compare.sh [-o OUTPUT] PROGRAM... [-- BENCH OPTIONS]
#
# Runs each benchmark program, one after the other, on the same scenes (the
# options after -- are given to every one of them), prints their lines as they
# come (and into OUTPUT), then a table: for each scene, size and dt, each of
# our engine's variants' median ms per step (and, for pile, the settled median
# over steps 301..600) beside every other engine's, and the ratio
# ours / other (above 1: ours is slower). POSIX sh and awk only.
output=""
if [ "$1" = "-o" ]; then
    output=$2
    shift 2
fi
programs=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    programs="$programs $1"
    shift
done
[ "$1" = "--" ] && shift
if [ -z "$programs" ]; then
    echo "usage: $0 [-o OUTPUT] PROGRAM... [-- BENCH OPTIONS]" >&2
    exit 2
fi
[ -n "$output" ] || output=${TMPDIR:-/tmp}/bench-compare.$$
: >"$output" || exit 1

status=0
for program in $programs; do
    echo "== $program $*" | tee -a "$output"
    # the exit status of the program, not of tee
    { "$program" "$@"; echo "exit=$?" >"$output.status"; } | tee -a "$output"
    code=$(sed 's/exit=//' "$output.status")
    rm -f "$output.status"
    if [ "$code" != 0 ]; then
        echo "== $program failed (exit $code)" | tee -a "$output"
        status=1
    fi
done

echo
echo "== ms per step (median over runs of each run's mean); /X = ours / X (above 1: ours slower)"
awk '
function field(name,    i, n, kv) {
    for (i = 1; i <= NF; i++) {
        n = index($i, "=")
        if (n > 0 && substr($i, 1, n - 1) == name) return substr($i, n + 1)
    }
    return ""
}
/^engine=/ {
    engine = field("engine"); median = field("median_ms")
    if (median == "") next
    dt = field("dt"); if (dt == "") dt = "-"
    key = field("scene") SUBSEP field("size") SUBSEP dt
    if (!(key in seen)) { seen[key] = 1; keys[++nkeys] = key }
    if (!((engine) in known)) {
        known[engine] = 1
        if (engine ~ /^ours/) ours[++nours] = engine; else others[++nothers] = engine
    }
    ms[engine, key, "step"] = median
    settled = field("settled_median_ms")
    if (settled != "") { ms[engine, key, "settled"] = settled; has_settled[key] = 1 }
}
END {
    for (j = 1; j <= nothers; j++) {
        w = length(others[j]); wm[j] = w > 10 ? w : 10
        w = length(others[j]) + 1; wr[j] = w > 8 ? w : 8
    }
    printf "%-8s %-6s %-8s %-8s %-15s %10s", "scene", "size", "dt", "metric", "engine", "ms"
    for (j = 1; j <= nothers; j++) printf " %" wm[j] "s", others[j]
    for (j = 1; j <= nothers; j++) printf " %" wr[j] "s", "/" others[j]
    printf "\n"
    for (k = 1; k <= nkeys; k++) {
        key = keys[k]; split(key, part, SUBSEP)
        for (m = 1; m <= 2; m++) {
            metric = m == 1 ? "step" : "settled"
            if (metric == "settled" && !(key in has_settled)) continue
            for (i = 1; i <= nours; i++) {
                e = ours[i]
                if (!((e, key, metric) in ms)) continue
                printf "%-8s %-6s %-8s %-8s %-15s %10s", part[1], part[2], part[3], metric, e, ms[e, key, metric]
                for (j = 1; j <= nothers; j++) {
                    o = others[j]
                    printf " %" wm[j] "s", ((o, key, metric) in ms) ? ms[o, key, metric] : "-"
                }
                for (j = 1; j <= nothers; j++) {
                    o = others[j]
                    if (((o, key, metric) in ms) && ms[o, key, metric] + 0 > 0)
                        printf " %" wr[j] ".3g", ms[e, key, metric] / ms[o, key, metric]
                    else
                        printf " %" wr[j] "s", "-"
                }
                printf "\n"
            }
        }
    }
}' "$output"
case "$output" in
    "${TMPDIR:-/tmp}"/bench-compare.$$) rm -f "$output" ;;
    *) echo "(raw lines in $output)" ;;
esac
exit $status
