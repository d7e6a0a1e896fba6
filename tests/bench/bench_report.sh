#!/bin/sh
# usage: tests/bench/bench_report.sh OUTPUT PROGRAM...
#
# Writes the benchmark page (docs/bench.md, `make bench-report`) from one
# run: the provenance (commit, compiler and flags, CPU, load before and
# after), the engines' settings, the speed of every engine on the benchmark
# set from one alternation (tests/bench/alternate.sh, BENCH_ROUNDS rounds,
# pinned, CPU time), the instructions per step (tests/bench/instructions.sh,
# unless BENCH_INSTRUCTIONS is empty), the settled pile with sleeping on,
# and the quality figures over the 8 layout seeds (tests/bench/seeds.sh) of
# this engine and of Box2D v3 when its program is among PROGRAM.
# Environment: BENCH_ROUNDS (default 7), BENCH_VARIANTS (the variants of
# the speed table), BENCH_INSTRUCTIONS (cases, default "pile:1000
# pyramid:20"), BENCH_CFLAGS (printed as the flags), BENCH_ARGS (more
# options for the speed table's programs, e.g. --scene pile --size 1000),
# BENCH_SEEDS_ARGS (options of seeds.sh, e.g. --quick: a trial run only).
# POSIX sh and awk only.
output=$1
shift
[ -n "$output" ] && [ $# -gt 0 ] || { echo "usage: $0 OUTPUT PROGRAM..." >&2; exit 2; }
rounds=${BENCH_ROUNDS:-7}
variants=${BENCH_VARIANTS:-ours,box2d3-sse2,box2d3-avx2,chipmunk,chipmunk-default,box2d-nosleep,box2d-matched}
instructions=${BENCH_INSTRUCTIONS-pile:1000 pyramid:20}
dir=$(dirname "$0")
work=$(mktemp -d "${TMPDIR:-/tmp}/bench-report.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT INT TERM

ours="" v3="" v3name="" sleepers=""
for p in "$@"; do
    case $(basename "$p") in
        bench_engine) ours=$p; sleepers="$sleepers $p" ;;
        bench_box2d3-sse2) v3=$p; v3name=box2d3-sse2; sleepers="$sleepers $p" ;;
        bench_box2d3-*) sleepers="$sleepers $p" ;;
    esac
done
[ -n "$ours" ] || { echo "$0: build/bench/bench_engine is not among the programs" >&2; exit 2; }

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
if git diff --quiet HEAD 2>/dev/null; then
    state="clean tree"
else
    state="**uncommitted changes in the tree: these figures are not of commit $commit alone**"
fi
cpu=$(sed -n 's/^model name[^:]*: *//p' /proc/cpuinfo 2>/dev/null | head -n 1)
cores=$(getconf _NPROCESSORS_ONLN 2>/dev/null || echo "?")
load_start=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)
started=$(date -u '+%Y-%m-%d %H:%M UTC')

echo "bench-report: speed, $rounds rounds" >&2
# shellcheck disable=SC2086
sh "$dir/alternate.sh" -o "$work/raw" "$rounds" "$@" -- --variant "$variants" $BENCH_ARGS \
    >"$work/speed" || exit 1
if [ -n "$sleepers" ]; then
    echo "bench-report: sleeping on, pile 4000" >&2
    # shellcheck disable=SC2086
    sh "$dir/alternate.sh" "$rounds" $sleepers -- --scene pile --size 4000 \
        --variant ours-sleeping,box2d3-sse2-sleeping,box2d3-avx2-sleeping >"$work/sleeping" || exit 1
fi
if [ -n "$instructions" ] && command -v valgrind >/dev/null 2>&1; then
    echo "bench-report: instructions ($instructions)" >&2
    targets=""
    for p in "$@"; do
        for v in $(echo "$variants" | tr , ' '); do
            grep -q "^$p round=1 engine=$v " "$work/raw" && targets="$targets $p:$v"
        done
    done
    # shellcheck disable=SC2086
    sh "$dir/instructions.sh" -s "$instructions" $targets >"$work/instructions" || exit 1
fi
echo "bench-report: quality over the layout seeds" >&2
# shellcheck disable=SC2086
sh "$dir/seeds.sh" -j 2 $BENCH_SEEDS_ARGS "$ours" >"$work/seeds-ours" || exit 1
if [ -n "$v3" ]; then
    # shellcheck disable=SC2086
    sh "$dir/seeds.sh" -j 2 $BENCH_SEEDS_ARGS --variant "$v3name" "$v3" >"$work/seeds-v3" || exit 1
else
    : >"$work/seeds-v3"
fi
load_end=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)

{
    cat <<EOF
# Benchmarks: this engine beside Box2D v3, Chipmunk2D and Box2D 2.4

Written by \`make bench-report\` (tests/bench/bench_report.sh) from one run;
regenerate it rather than editing it. The scenes are those of
[bench-scenes.md](bench-scenes.md), built the same way for every engine by
the programs of \`tests/bench/\` (one per engine, the scenes written once in
\`tests/bench/bench_scenes.h\`).

- Commit: $commit ($state)
- Compiler: $(${CC:-cc} --version 2>/dev/null | head -n 1); flags: ${BENCH_CFLAGS:-see tests/bench/bench.mk}
- CPU: ${cpu:-unknown}, $cores cores; each program pinned to one core (taskset)
- Run: $started; load average (1, 5, 15 min) $load_start at the start, $load_end at the end
- Times: CPU time of the process spent in the step calls (CLOCK_PROCESS_CPUTIME_ID),
  $rounds rounds of one run per program, the programs alternated within each round

## Engines and their settings

Every setting that differs from an engine's default is named here, as the
programs print it.

\`\`\`
$(grep '^# [a-z_0-9-]*: ' "$work/speed" | grep -v '^# alternate\|^# load' | sed 's/^# //')
\`\`\`

## Speed: milliseconds per step

Median over the rounds, (least-largest) beside it; "settled" is the pile's
steps 301 to 600. The second table divides this engine's time by each other
engine's, round by round (above 1: this engine is slower).

\`\`\`
$(grep -v '^#' "$work/speed")
\`\`\`
EOF
    if [ -s "$work/instructions" ]; then
        cat <<EOF

## Instructions per step

Counted by callgrind inside the step calls only, one run each; a count does
not move with the machine's load.

\`\`\`
$(cat "$work/instructions")
\`\`\`
EOF
    fi
    if [ -s "$work/sleeping" ]; then
        cat <<EOF

## Sleeping on: pile(4000)

Every engine with its sleeping on (ours-sleeping: scene_set_sleeping; Box2D
v3: its default); the settled row is the steps 301 to 600.

\`\`\`
$(grep -v '^#' "$work/sleeping")
\`\`\`
EOF
    fi
    cat <<EOF

## Quality over the 8 layout seeds

The chaotic figures over the 8 layout seeds of bench-scenes.md (median and
least-largest over the seeds), and the exact ones once; Box2D v3's
($v3name) beside this engine's. Penetrations: this engine's from its step
record (before the last solve), Box2D v3's on the polygons at the final
positions.

EOF
    if [ ! -s "$work/seeds-v3" ]; then
        echo "Box2D v3 was not built for this run (no BOX2D3_DIR and no shared archive): its column is left out."
        echo
    fi
    awk '
    FNR == 1 { file++ }
    /^#/ || NF < 6 { next }
    {
        cell = $2 == "exact" ? $3 : sprintf("%s (%s-%s)", $3, $4, $5)
        if (file == 1) { order[++n] = $1; ours[$1] = cell } else v3[$1] = cell
    }
    END {
        print "| figure | this engine | Box2D v3 |"
        print "|---|---|---|"
        for (i = 1; i <= n; i++) {
            f = order[i]
            printf "| %s | %s | %s |\n", f, ours[f], (f in v3) ? v3[f] : "-"
        }
    }' "$work/seeds-ours" "$work/seeds-v3"
} >"$output"
echo "bench-report: wrote $output" >&2
