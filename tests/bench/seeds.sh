#!/bin/sh
# The quality figures of the benchmark over the 8 layout seeds of
# docs/bench-scenes.md, and the "no worse" judge between two such tables.
#
#   tests/bench/seeds.sh [OPTIONS] PROGRAM          prints a table (stdout)
#   tests/bench/seeds.sh --judge OLD NEW [PEER]     PASS/FAIL per figure
#
# Table mode runs PROGRAM (a benchmark program of tests/bench/, one variant)
# once per seed on the chaotic scenes: pile 1000, 4000, 10000; circlepile,
# capsulepile and mixedpile 1000, 4000 (circlepile only for bench_box2d,
# Box2D 2.4 having no capsule); pyramid 20, 40; column 10, 20; overlap;
# ragdolls 20; and once (they do not depend on the seed) on the exact
# scenes: bounce 0.8 at dt 1/60 and 1/600, cradle 5, stack2, tunnel, and
# jointchain 100 (no random draw: every seed gives the same bits, so its
# figures must stay as they are, or at rounding level).
# Options:
#   --variant NAME  the variant to run (default: ours)
#   --seeds N       only the first N seeds (default 8)
#   --quick         leaves out pile 10000 (two fifths of the time)
#   --no-exact      leaves out the exact scenes
#   -j J            J programs at once (default 1)
#   -o FILE         writes the table to FILE too
# The figures are deterministic: the machine's load does not move them.
#
# A table line: FIGURE KIND MEDIAN MIN MAX N VALUES, with FIGURE
# scene/size[/dt]/key, KIND lower (lower is better; signed figures are taken
# as absolute values, the key then ends in _abs) or exact (VALUES holds the
# one value, MEDIAN/MIN/MAX are that value), VALUES the per-seed values in
# seed order, comma separated. Lines starting with '#' are comments.
#
# Judge mode: for each figure of OLD, a lower-is-better figure passes when
# NEW's median <= max(OLD's median + (OLD's max - OLD's min) / 2, PEER's
# median), PEER (optional) being the table of Box2D v3 (tests/bench/
# v3-seeds.txt); an exact figure passes when NEW's value equals OLD's, or
# when both are numbers within round-off of the exact answer (|x| <= 1e-12:
# the bounce's, cradle's and stack2's errors; shown as PASS~). Figures
# missing from NEW (a --quick or --seeds subset) are listed as MISSING and
# counted apart. Exit status 1 when any figure fails.
# POSIX sh and awk only.

SEEDS="12345 1 42 777 2024 31337 65521 1234567"

usage() {
    echo "usage: $0 [--variant NAME] [--seeds N] [--quick] [--no-exact] [-j J] [-o FILE] PROGRAM" >&2
    echo "       $0 --judge OLD NEW [PEER]" >&2
    exit 2
}

judge() {
    [ $# -ge 2 ] && [ $# -le 3 ] || usage
    for f in "$@"; do
        [ -r "$f" ] || { echo "$0: cannot read $f" >&2; exit 2; }
    done
    awk -v nfiles=$# '
    function roundoff(x) { return x ~ /^[-+]?[0-9.]+(e[-+]?[0-9]+)?$/ && x + 0 <= 1e-12 && x + 0 >= -1e-12 }
    FNR == 1 { file++ }
    /^#/ || NF < 6 { next }
    {
        fig = $1
        kind[file, fig] = $2; med[file, fig] = $3; lo[file, fig] = $4; hi[file, fig] = $5
        have[file, fig] = 1
        if (file == 1) order[++n] = fig
    }
    END {
        printf "%-38s %-5s %11s %11s %11s %11s %11s  %s\n", "figure", "kind", "old_median",
               "old_range", "peer_median", "bound", "new_median", "verdict"
        pass = fail = 0
        for (i = 1; i <= n; i++) {
            f = order[i]
            peer = (nfiles >= 3 && (3, f) in have) ? med[3, f] : "-"
            if (!((2, f) in have)) {
                verdict = "MISSING"; missing++
                printf "%-38s %-5s %11s %11s %11s %11s %11s  %s\n", f, kind[1, f], med[1, f],
                       hi[1, f] - lo[1, f], peer, "-", "-", verdict
                continue
            }
            if (kind[1, f] == "exact") {
                bound = med[1, f]
                ok = med[2, f] "" == med[1, f] ""
                if (!ok && roundoff(med[1, f]) && roundoff(med[2, f])) ok = 2
                range = 0
            } else {
                range = hi[1, f] - lo[1, f]
                bound = med[1, f] + range / 2
                if (peer != "-" && peer + 0 > bound) bound = peer + 0
                ok = med[2, f] + 0 <= bound + 0
                bound = sprintf("%.4g", bound)
            }
            if (ok) pass++; else fail++
            printf "%-38s %-5s %11s %11.4g %11s %11s %11s  %s\n", f, kind[1, f], med[1, f], range,
                   peer, bound, med[2, f], ok == 2 ? "PASS~" : ok ? "PASS" : "FAIL"
        }
        for (k in have) {
            split(k, part, SUBSEP)
            if (part[1] == 2 && !((1, part[2]) in have)) extra++
        }
        printf "%d PASS, %d FAIL, %d MISSING from NEW (of %d figures in OLD)%s\n", pass, fail,
               missing, n, extra ? sprintf("; %d figures of NEW not in OLD", extra) : ""
        exit fail > 0
    }' "$@"
}

[ "$1" = "--judge" ] && { shift; judge "$@"; exit $?; }

variant=ours
nseeds=8
quick=0
exact=1
jobs=1
output=""
while [ $# -gt 1 ]; do
    case $1 in
        --variant) variant=$2; shift 2 ;;
        --seeds) nseeds=$2; shift 2 ;;
        --quick) quick=1; shift ;;
        --no-exact) exact=0; shift ;;
        -j) jobs=$2; shift 2 ;;
        -o) output=$2; shift 2 ;;
        *) usage ;;
    esac
done
[ $# -eq 1 ] || usage
program=$1
[ -x "$program" ] || { echo "$0: $program is not an executable" >&2; exit 2; }
case $nseeds$jobs in *[!0-9]*) usage ;; esac
[ "$nseeds" -ge 1 ] && [ "$nseeds" -le 8 ] && [ "$jobs" -ge 1 ] || usage

seeds=""
i=0
for s in $SEEDS; do
    [ $i -lt "$nseeds" ] && seeds="$seeds $s"
    i=$((i + 1))
done

work=$(mktemp -d "${TMPDIR:-/tmp}/bench-seeds.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT INT TERM

# The tasks, one a line, the longest first: SEED SCENE SIZES.
piles="1000,4000"
[ "$quick" = 1 ] || piles="10000 $piles"
for size in $piles; do
    for s in $seeds; do echo "$s pile $size"; done
done >"$work/tasks"
rounds="mixedpile capsulepile circlepile"
# Box2D 2.4 has no capsule (docs/bench-scenes.md): its program runs circlepile only.
[ "$(basename "$program")" = bench_box2d ] && rounds=circlepile
for scene in $rounds; do
    for s in $seeds; do echo "$s $scene 1000,4000"; done
done >>"$work/tasks"
for s in $seeds; do
    echo "$s pyramid 20,40"
    echo "$s column 10,20"
    echo "$s overlap 10"
    echo "$s ragdolls 20"
done >>"$work/tasks"
if [ "$exact" = 1 ]; then
    for scene in bounce cradle stack2 tunnel jointchain; do
        echo "12345 $scene -"
    done >>"$work/tasks"
fi

# Worker w runs the tasks whose line number is w modulo jobs.
w=0
while [ $w -lt "$jobs" ]; do
    awk -v w=$w -v j="$jobs" '(NR - 1) % j == w' "$work/tasks" | while read -r seed scene sizes; do
        if [ "$sizes" = - ]; then set -- ; else set -- --size "$sizes"; fi
        "$program" --runs 1 --variant "$variant" --layout-seed "$seed" --scene "$scene" "$@" \
            >"$work/out.$seed.$scene.$(echo "$sizes" | tr , _)" 2>&1 ||
            echo "$program failed on seed $seed, $scene $sizes" >"$work/failed.$w"
    done &
    w=$((w + 1))
done
wait
if ls "$work"/failed.* >/dev/null 2>&1; then
    cat "$work"/failed.* >&2
    exit 1
fi

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
git diff --quiet HEAD -- engine 2>/dev/null || commit="$commit (engine/ modified)"
{
    echo "# tests/bench/seeds.sh: $program, variant $variant, commit $commit, $(date -u '+%Y-%m-%d %H:%M UTC')"
    echo "# seeds:$seeds$([ "$quick" = 1 ] && echo ' (--quick: no pile 10000)')"
    grep -h "^# $variant\|^# ${variant%%-*}" "$work"/out.* 2>/dev/null | sort -u | head -3
    echo "# figure kind median min max n values"
    for s in $seeds; do
        cat "$work"/out."$s".* | grep "^engine=$variant " | sed "s/^/seed=$s /"
    done | awk -v seeds="$seeds" '
    function field(name,    i, n) {
        for (i = 1; i <= NF; i++) {
            n = index($i, "=")
            if (n > 0 && substr($i, 1, n - 1) == name) return substr($i, n + 1)
        }
        return ""
    }
    function abs(x) { return x < 0 ? -x : x }
    function put(key, kind_, value,    name) {
        name = base "/" key
        if (!(name in kind)) { kind[name] = kind_; order[++n] = name }
        count[name]++
        values[name, count[name]] = value
    }
    {
        scene = field("scene"); size = field("size"); dt = field("dt")
        base = scene "/" size (dt == "" ? "" : "/" dt)
        if (scene == "pile" || scene == "circlepile" || scene == "capsulepile" || scene == "mixedpile") {
            put("max_penetration", "lower", field("max_penetration"))
            put("outside", "lower", field("outside"))
        } else if (scene == "pyramid") {
            put("top_drop_abs", "lower", abs(field("top_drop")))
            put("top_drift_abs", "lower", abs(field("top_drift")))
            put("max_penetration", "lower", field("max_penetration"))
        } else if (scene == "column") {
            put("top_drift", "lower", field("top_drift"))
            put("top_drop_abs", "lower", abs(field("top_drop")))
            put("max_tilt", "lower", field("max_tilt"))
        } else if (scene == "overlap") {
            put("max_speed", "lower", field("max_speed"))
            put("max_push_speed", "lower", field("max_push_speed"))
            put("max_penetration", "lower", field("max_penetration"))
            put("out_of_bounds", "lower", 1 - field("in_bounds"))
        } else if (scene == "ragdolls") {
            put("max_gap", "lower", field("max_gap"))
            put("end_gap", "lower", field("end_gap"))
            put("max_past_limit", "lower", field("max_past_limit"))
            put("max_penetration", "lower", field("max_penetration"))
            put("below", "lower", field("below"))
            put("outside", "lower", field("outside"))
            put("vmax_end", "lower", field("vmax_end"))
            put("moving_end", "lower", field("moving_end"))
        } else if (scene == "jointchain") {
            put("max_stretch", "exact", field("max_stretch"))
            put("end_stretch", "exact", field("end_stretch"))
            put("max_gap", "exact", field("max_gap"))
            put("tip_min_y", "exact", field("tip_min_y"))
        } else if (scene == "bounce") {
            for (k = 1; k <= 5; k++) put("apex" k "_rel_err", "exact", field("apex" k "_rel_err"))
        } else if (scene == "cradle") {
            put("max_dev", "exact", field("max_dev"))
            put("momentum_rel_err", "exact", field("momentum_rel_err"))
            put("energy_rel_err", "exact", field("energy_rel_err"))
        } else if (scene == "stack2") {
            put("pen_ground_a", "exact", field("pen_ground_a"))
            put("pen_a_b", "exact", field("pen_a_b"))
            put("b_on_a", "exact", field("b_on_a"))
        } else if (scene == "tunnel" && size == "summary") {
            put("first_tunnel_v", "exact", field("first_tunnel_v"))
            put("max_return_speed", "exact", field("max_return_speed"))
        } else if (scene == "tunnel") {
            put("tunnelled", "exact", field("tunnelled"))
        }
    }
    END {
        for (i = 1; i <= n; i++) {
            f = order[i]; c = count[f]
            list = values[f, 1]
            for (k = 2; k <= c; k++) list = list "," values[f, k]
            if (kind[f] == "exact") {
                printf "%s exact %s %s %s %d %s\n", f, values[f, 1], values[f, 1], values[f, 1], c, list
                continue
            }
            for (k = 1; k <= c; k++) a[k] = values[f, k] + 0
            for (k = 2; k <= c; k++)
                for (m = k; m > 1 && a[m - 1] > a[m]; m--) { t = a[m]; a[m] = a[m - 1]; a[m - 1] = t }
            median = c % 2 ? a[(c + 1) / 2] : (a[c / 2] + a[c / 2 + 1]) / 2
            printf "%s lower %.4g %.4g %.4g %d %s\n", f, median, a[1], a[c], c, list
        }
    }'
} >"$work/table"
[ -n "$output" ] && cp "$work/table" "$output"
cat "$work/table"
