#!/bin/sh
# usage: tests/bench/bench_report.sh [--section joints] OUTPUT PROGRAM...
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
# pyramid:20 circlepile:1000"), BENCH_ROUND_SIZES (sizes of the round piles'
# table, circlepile and mixedpile, default 1000,4000; empty leaves it out),
# BENCH_CFLAGS (printed as the flags), BENCH_ARGS (more
# options for the speed table's programs, e.g. --scene pile --size 1000),
# BENCH_SEEDS_ARGS (options of seeds.sh, e.g. --quick: a trial run only),
# BENCH_STAGE_CASES (scene:size cases whose stages each engine times
# itself, default "pyramid:40 pile:4000"; empty leaves them out),
# BENCH_SCALE_SIZES (pile sizes of the scale fit, default
# 1000,2000,4000,10000,20000; empty leaves it out), BENCH_SLEEP_STEPS (how
# long the sleeping piles run to find when they are all asleep, default
# 1800 steps = 30 s). The page is rewritten whole but for a block between
# the lines <!-- web:begin --> and <!-- web:end -->, which another program
# writes (browser figures): it is kept as it was.
#
# The joints section (jointchain and ragdolls, bench-scenes.md: this
# engine, Box2D v3's SSE2 build and Chipmunk2D where their programs are
# among PROGRAM; BENCH_JOINT_VARIANTS, default ours,box2d3-sse2,chipmunk)
# lies between the lines <!-- joints:begin --> and <!-- joints:end -->.
# With --section joints only it is run (a few minutes, `make
# bench-joints`) and only that block of OUTPUT is replaced (put before the
# browser block or the Commands when OUTPUT has none), the rest of the page
# kept as it was; the block states its own run (commit, time, load).
# POSIX sh and awk only.
section=""
if [ "$1" = "--section" ]; then
    section=$2
    shift 2
    [ "$section" = joints ] || { echo "$0: unknown section '$section' (joints)" >&2; exit 2; }
fi
output=$1
shift
[ -n "$output" ] && [ $# -gt 0 ] || { echo "usage: $0 [--section joints] OUTPUT PROGRAM..." >&2; exit 2; }
rounds=${BENCH_ROUNDS:-7}
variants=${BENCH_VARIANTS:-ours,box2d3-sse2,box2d3-avx2,chipmunk,chipmunk-default,box2d-nosleep,box2d-matched}
instructions=${BENCH_INSTRUCTIONS-pile:1000 pyramid:20 circlepile:1000}
scale_sizes=${BENCH_SCALE_SIZES-1000,2000,4000,10000,20000}
sleep_steps=${BENCH_SLEEP_STEPS:-1800}
workers_size=${BENCH_WORKERS_SIZE:-10000}
round_sizes=${BENCH_ROUND_SIZES-1000,4000}
stage_cases=${BENCH_STAGE_CASES-pyramid:40 pile:4000}
joint_variants=${BENCH_JOINT_VARIANTS:-ours,box2d3-sse2,chipmunk}
dir=$(dirname "$0")
work=$(mktemp -d "${TMPDIR:-/tmp}/bench-report.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT INT TERM
# The browser figures another program writes into the page.
if [ -f "$output" ]; then
    awk '/^<!-- web:begin -->$/ { keep = 1 } keep { print } /^<!-- web:end -->$/ { keep = 0 }' \
        "$output" >"$work/web"
else
    : >"$work/web"
fi

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

# The joints section into $work/joints.md: the joint scenes alternated over
# the rounds, their instructions per step, and one table per scene of the
# times, the counts and the quality figures of the first round.
joints_part() {
    jprograms=""
    for p in "$@"; do
        case $(basename "$p") in
            bench_engine | bench_box2d3-sse2 | bench_chipmunk) jprograms="$jprograms $p" ;;
        esac
    done
    jstarted=$(date -u '+%Y-%m-%d %H:%M UTC')
    jload_start=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)
    echo "bench-report: joints, $rounds rounds" >&2
    # shellcheck disable=SC2086
    sh "$dir/alternate.sh" -o "$work/joints-raw" "$rounds" $jprograms -- \
        --variant "$joint_variants" --scene jointchain,ragdolls >"$work/joints-speed" || return 1
    : >"$work/joints-instructions"
    if command -v valgrind >/dev/null 2>&1; then
        echo "bench-report: joints, instructions" >&2
        jtargets=""
        for p in $jprograms; do
            for v in $(echo "$joint_variants" | tr , ' '); do
                grep -q "^$p round=1 engine=$v " "$work/joints-raw" && jtargets="$jtargets $p:$v"
            done
        done
        # shellcheck disable=SC2086
        sh "$dir/instructions.sh" -s "jointchain:100 ragdolls:20" $jtargets \
            >"$work/joints-instructions" || return 1
    fi
    jload_end=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)
    {
        cat <<JOINTS
<!-- joints:begin -->
## Joints: jointchain(100) and ragdolls(20), one core

The joint scenes of [bench-scenes.md](bench-scenes.md): a chain of 100
pinned links released from the horizontal, and 20 ragdolls dropped in a
pile. Run $jstarted at commit $commit ($state), apart from the rest of
this page (\`make bench-joints\`); load average (1, 5, 15 min)
$jload_start at the start, $jload_end at the end, on $cores cores shared
with other programs, so the times move with the load: the instruction
counts (callgrind, inside the step calls, one run) do not. Times: ms per
step, median over $rounds alternated rounds, pinned, CPU time, with the
least and largest. The quality figures are the first round's. Stretch: the
sum of the joints' gaps over the chain's length; a gap: the distance
between a pin's two anchors (m).

JOINTS
        awk '
        function field(line, name,    i, n, parts, k) {
            n = split(line, parts, " ")
            for (i = 1; i <= n; i++) {
                k = index(parts[i], "=")
                if (k > 0 && substr(parts[i], 1, k - 1) == name) return substr(parts[i], k + 1)
            }
            return "-"
        }
        function sort_values(a, n,    i, j, t) {
            for (i = 2; i <= n; i++) for (j = i; j > 1 && a[j - 1] > a[j]; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
        }
        function times(s, e,    k, a) {
            for (k = 1; k <= n[s, e]; k++) a[k] = ms[s, e, k]
            k = n[s, e]
            sort_values(a, k)
            return sprintf("%.4g (%.4g-%.4g)", k % 2 ? a[(k + 1) / 2] : (a[k / 2] + a[k / 2 + 1]) / 2, a[1], a[k])
        }
        function count(s, e) {
            return ((s, e) in instr) ? sprintf("%.3g M", instr[s, e] / 1e6) : "-"
        }
        FNR == 1 { file++ }
        file == 1 { if ($0 !~ /^#/ && NF >= 6) instr[$1, $4] = $5; next }
        {
            e = field($0, "engine"); s = field($0, "scene"); r = $2; sub(/^round=/, "", r)
            if (!((s, e) in n)) { engines[s, ++ne[s]] = e; size[s] = field($0, "size") }
            k = ++n[s, e]; ms[s, e, k] = field($0, "median_ms") + 0
            if (r == 1) first[s, e] = $0
        }
        # One table per scene: the times and counts, then the named fields
        # (of the first round) under their headings.
        function table(s, headings, fields,    nf, f, k, i, e, l, line, rule) {
            if (ne[s] == 0) return
            printf "### %s(%s)\n\n", s, size[s]
            print "| engine | ms per step | instructions per step | " headings " |"
            nf = split(fields, f, " ")
            rule = "|---|---|---"
            for (k = 1; k <= nf; k++) rule = rule "|---"
            print rule "|"
            for (i = 1; i <= ne[s]; i++) { e = engines[s, i]; l = first[s, e]
                line = sprintf("| %s | %s | %s |", e, times(s, e), count(s, e))
                for (k = 1; k <= nf; k++) line = line " " field(l, f[k]) " |"
                print line }
            print ""
        }
        END {
            table("jointchain", "largest stretch | final stretch | widest gap (m) | lowest tip (m)",
                  "max_stretch end_stretch max_gap tip_min_y")
            table("ragdolls", "widest gap (m) | widest gap at the end (m) | past a limit (rad) | deepest penetration (m) | below the floor | moving at the end",
                  "max_gap end_gap max_past_limit max_penetration below moving_end")
        }' "$work/joints-instructions" "$work/joints-raw"
        if grep -q 'runs_differ=1' "$work/joints-raw"; then
            echo "**A program gave different figures when a run was repeated (runs_differ=1).**"
            echo
        fi
        echo "Largest stretch and widest gap: over the 600 steps; at the end: step"
        echo "600; past a limit: the farthest any joint's angle went beyond its limits,"
        echo "any step; lowest tip: the last link's centre (-50 m for a chain that keeps"
        echo "its length); moving at the end: bodies faster than 0.1 m/s (of the 200). The"
        echo "alternation, with this engine's time over each other's:"
        echo
        echo '```'
        grep -v '^#' "$work/joints-speed"
        echo '```'
        echo "<!-- joints:end -->"
    } >"$work/joints.md"
}

if [ "$section" = joints ]; then
    joints_part "$@" || exit 1
    [ -f "$output" ] || : >"$output"
    # The old block out and the new one in its place; without one, before the
    # browser block or the Commands, or at the end.
    had=$(grep -c '^<!-- joints:begin -->$' "$output")
    awk -v block="$work/joints.md" -v had="$had" '
        function put(   line) {
            if (done) return
            while ((getline line < block) > 0) print line
            print ""
            done = 1
        }
        /^<!-- joints:begin -->$/ { put(); skip = 1; next }
        skip == 1 { if ($0 == "<!-- joints:end -->") skip = 2; next }
        skip == 2 { skip = 0; if ($0 == "") next }
        had == 0 && (/^<!-- web:begin -->$/ || /^## Commands$/) { put() }
        { print }
        END { put() }' "$output" >"$work/page"
    mv "$work/page" "$output"
    echo "bench-report: wrote the joints section of $output" >&2
    exit 0
fi

echo "bench-report: speed, $rounds rounds" >&2
# shellcheck disable=SC2086
sh "$dir/alternate.sh" -o "$work/raw" "$rounds" "$@" -- --variant "$variants" $BENCH_ARGS \
    >"$work/speed" || exit 1
if [ -n "$stage_cases" ]; then
    echo "bench-report: stages ($stage_cases)" >&2
    for case in $stage_cases; do
        for p in "$ours" $v3; do
            taskset -c "$(($(getconf _NPROCESSORS_ONLN) - 1))" "$p" --scene "${case%%:*}" \
                --size "${case#*:}" --runs 3 --stages --variant ours,box2d3-sse2 | grep '^# stages '
        done
    done >"$work/stages"
fi
if [ -n "$sleepers" ]; then
    echo "bench-report: sleeping on, pile 4000" >&2
    # shellcheck disable=SC2086
    sh "$dir/alternate.sh" "$rounds" $sleepers -- --scene pile --size 4000 \
        --variant ours-sleeping,box2d3-sse2-sleeping,box2d3-avx2-sleeping >"$work/sleeping" || exit 1
fi
if [ -n "$sleepers" ]; then
    echo "bench-report: when the sleeping piles are all asleep ($sleep_steps steps)" >&2
    for p in $sleepers; do
        "$p" --scene pile --size 4000 --runs 1 --steps "$sleep_steps" \
            --variant ours-sleeping,box2d3-sse2-sleeping,box2d3-avx2-sleeping | grep '^engine='
    done >"$work/asleep"
fi
# Round bodies: Box2D 2.4 (no capsule) is left out of both piles.
round_programs=""
for p in "$@"; do
    [ "$(basename "$p")" = bench_box2d ] || round_programs="$round_programs $p"
done
if [ -n "$round_sizes" ]; then
    echo "bench-report: round bodies, circlepile and mixedpile $round_sizes" >&2
    # shellcheck disable=SC2086
    sh "$dir/alternate.sh" -o "$work/round-raw" "$rounds" $round_programs -- --variant "$variants" \
        --scene circlepile,mixedpile --size "$round_sizes" >"$work/round" || exit 1
fi
echo "bench-report: two workers, pile $workers_size (unpinned)" >&2
for round in 1 2 3; do
    for n in 1 2; do
        "$ours" --scene pile --size "$workers_size" --runs 1 --wall --workers "$n" --variant ours |
            sed -n "s/^engine=/workers=$n engine=/p"
        if [ -n "$v3" ]; then
            "$v3" --scene pile --size "$workers_size" --runs 1 --wall --workers "$n" \
                --variant "$v3name" | sed -n "s/^engine=/workers=$n engine=/p"
        fi
    done
done >"$work/workers"
if [ -n "$scale_sizes" ]; then
    echo "bench-report: scale, pile $scale_sizes" >&2
    for p in "$ours" $v3; do
        taskset -c "$(($(getconf _NPROCESSORS_ONLN) - 1))" "$p" --scene pile --size "$scale_sizes" \
            --runs 1 --variant ours,box2d3-sse2 | grep '^engine='
    done >"$work/scale"
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
# The two-worker runs' medians, one line per engine and worker count:
# engine workers cpu_ms wall_ms (the workers table and the targets read it).
awk '{ e = ""; n = ""; c = ""; w = ""
        for (i = 1; i <= NF; i++) { split($i, kv, "=")
            if (kv[1] == "engine") e = kv[2]; if (kv[1] == "workers") n = kv[2]
            if (kv[1] == "median_ms") c = kv[2]; if (kv[1] == "wall_median_ms") w = kv[2] }
        if (!(e in seen)) { seen[e] = 1; order[++engines] = e }
        k = ++count[e, n]; cpu[e, n, k] = c; wall[e, n, k] = w }
     function median(arr, e, n, k,   i, j, t, v) {
        for (i = 1; i <= k; i++) v[i] = arr[e, n, i]
        for (i = 2; i <= k; i++) for (j = i; j > 1 && v[j - 1] + 0 > v[j] + 0; j--) {
            t = v[j]; v[j] = v[j - 1]; v[j - 1] = t }
        return v[int((k + 1) / 2)] }
     END { for (x = 1; x <= engines; x++) { e = order[x]
            for (n = 1; n <= 2; n++) if (count[e, n] > 0)
                print e, n, median(cpu, e, n, count[e, n]), median(wall, e, n, count[e, n]) } }' \
    "$work/workers" >"$work/workers-medians"
# The scale fit: engine, then its ms per step at each size (size=ms), then
# the least-squares exponent of ms per step on N.
if [ -s "$work/scale" ]; then
    awk '{ e = ""; n = 0; m = 0
            for (i = 1; i <= NF; i++) { split($i, kv, "=")
                if (kv[1] == "engine") e = kv[2]; if (kv[1] == "size") n = kv[2]
                if (kv[1] == "mean_ms") m = kv[2] }
            if (!(e in seen)) { seen[e] = 1; engines[++ne] = e }
            line[e] = line[e] " " n "=" m
            x = log(n); y = log(m); sx[e] += x; sy[e] += y; sxx[e] += x * x; sxy[e] += x * y; k[e]++ }
         END { for (i = 1; i <= ne; i++) { e = engines[i]
                printf "%s%s %.2f\n", e, line[e],
                    (k[e] * sxy[e] - sx[e] * sy[e]) / (k[e] * sxx[e] - sx[e] * sx[e]) } }' \
        "$work/scale" >"$work/scale-fit"
fi

joints_part "$@" || exit 1
load_end=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown)

{
    cat <<EOF
# Benchmarks: this engine beside Box2D v3, Chipmunk2D and Box2D 2.4

Written whole by \`make bench-report\` (tests/bench/bench_report.sh) from one
run, but for the browser block between its markers; regenerate it rather
than editing it. The scenes are those of [bench-scenes.md](bench-scenes.md),
built the same way for every engine by the programs of \`tests/bench/\` (one
per engine, the scenes written once in \`tests/bench/bench_scenes.h\`).

- Commit: $commit ($state)
- Compiler: $(${CC:-cc} --version 2>/dev/null | head -n 1); flags: ${BENCH_CFLAGS:-see tests/bench/bench.mk}
- CPU: ${cpu:-unknown}, $cores cores; each program pinned to one core (taskset) but for the two-worker runs
- Run: $started; load average (1, 5, 15 min) $load_start at the start, $load_end at the end.
  The machine is shared: other programs ran beside these, so times move with
  their load (CPU time of the process leaves out the waits, not the slowdown
  of a shared core and cache). Instruction counts do not move with the load:
  compare those first.
- Times: CPU time of the process spent in the step calls (CLOCK_PROCESS_CPUTIME_ID),
  $rounds rounds of one run per program, the programs alternated within each round
- Variants timed: $variants

## Engines and their settings

Every setting that differs from an engine's default is named here, as the
programs print it.

\`\`\`
$(grep '^# [a-z_0-9-]*: ' "$work/speed" | grep -v '^# alternate\|^# load' | sed 's/^# //')
\`\`\`

## Speed: milliseconds per step, one core

Median over the rounds, (least-largest) beside it; "settled" is the pile's
steps 301 to 600, the pile at rest. The second table divides this engine's
time by each other engine's, round by round (above 1: this engine is
slower): the figure the speed targets are stated in.

\`\`\`
$(grep -v '^#' "$work/speed")
\`\`\`
EOF
    if [ -n "$v3" ]; then
        target_files=""
        for f in speed sleeping asleep workers-medians scale-fit; do
            [ -s "$work/$f" ] && target_files="$target_files $work/$f"
        done
        cat <<EOF

## The speed targets

The targets this engine's speed is held to, with this run's figures (from
the tables of this page). A ratio is this engine's time over Box2D v3's
(its SSE2 build), the median over the rounds. Where a target is not met,
the next section shows where the time goes, part by part of the step, and
[design.md](design.md) (Memory, Four contacts at a time) why preparing and
the passes Box2D v3 has not cost what they do.

| target | figure | met |
|---|---|---|
$(awk -v v3="$v3name" -v workers_size="$workers_size" '
        function ratio_table(key,   i) {
            if ($1 == "ratio") { in_ratios = 1; col = 0; return }
            if (!in_ratios) return
            if ($1 == "scene") { for (i = 5; i <= NF; i++) if ($i == "/" key) col = 5 + 2 * (i - 5); return }
            if (col > 0) r[FILENAME, $1 "(" $2 ")", $4] = $col }
        FNR == 1 { in_ratios = 0 }
        FILENAME ~ /\/speed$/ { ratio_table(v3); speed_file = FILENAME; next }
        FILENAME ~ /\/sleeping$/ { ratio_table(v3 "-sleeping"); sleeping = FILENAME; next }
        FILENAME ~ /\/asleep$/ { for (i = 1; i <= NF; i++) { split($i, kv, "=")
                if (kv[1] == "engine") e = kv[2]; if (kv[1] == "asleep_s") at[e] = kv[2] }; next }
        FILENAME ~ /\/workers-medians$/ { wall[$1, $2] = $4; next }
        FILENAME ~ /\/scale-fit$/ { fit[$1] = $NF; next }
        function row(what, figure, met) { printf "| %s | %s | %s |\n", what, figure, met ? "yes" : "no" }
        function speed(c, metric, what,   x) {
            x = r[speed_file, c, metric]; if (x == "") return
            row("one core: " c " " what " at or below Box2D v3", x, x + 0 <= 1) }
        END { speed("pile(1000)", "step", "every step"); speed("pile(1000)", "settled", "settled")
            speed("pile(4000)", "step", "every step"); speed("pile(4000)", "settled", "settled")
            speed("pile(10000)", "step", "every step"); speed("pile(10000)", "settled", "settled")
            speed("pyramid(40)", "step", "every step")
            if (wall["ours", 1] > 0 && wall["ours", 2] > 0) {
                x = wall["ours", 2] / wall["ours", 1]
                row("two workers: pile(" workers_size ") at most 0.6 of one worker (wall time)", sprintf("%.2f", x), x <= 0.6) }
            if (wall["ours", 2] > 0 && wall[v3, 2] > 0) {
                x = wall["ours", 2] / wall[v3, 2]
                row("two workers: pile(" workers_size ") at or below Box2D v3 with two (wall time)", sprintf("%.2f", x), x <= 1) }
            if ("ours-sleeping" in at) row("sleeping on: pile(4000) all asleep by 10 s",
                at["ours-sleeping"] " s", at["ours-sleeping"] != "none" && at["ours-sleeping"] + 0 <= 10)
            x = r[sleeping, "pile(4000)", "settled"]
            if (x != "") row("sleeping on: settled pile(4000) at or below Box2D v3 with its sleeping", x, x + 0 <= 1)
            if (("ours" in fit) && (v3 in fit)) row("scale: exponent of pile(N) no steeper than Box2D v3", \
                "N^" fit["ours"] " against N^" fit[v3], fit["ours"] + 0 <= fit[v3] + 0) }' \
    $target_files)
EOF
    fi
    if [ -s "$work/stages" ]; then
        cat <<EOF

## Where a step's time goes: each engine's own stages, one core

Each engine's account of its stages (this engine's scene profile, Box2D
v3's b2World_GetProfile), in ms per step averaged over 3 runs of the case,
pinned; stages that took no time are left out. The stages are not the same:
this engine prepares its contacts once a step (prepare: colouring and
sorting, then lever arms, effective masses, targets and impacts, four
contacts at a time into the batches)
and its solver stage is the warm start, 8 velocity iterations and a relaxing
one; shock propagation with the lift's levels (shock) and the position
iterations with the lift (position) are its own. Box2D v3 prepares once and then, for each of its 4
sub-steps, warm starts, solves and relaxes every constraint (warm_start,
solve, relax) and integrates (integrate); transforms moves its bodies and
their boxes, pairs finds new pairs in its tree. Each engine reads its clock
around its own stages, so a row's sum differs a little from the step's
time in the speed table.

| scene | steps | engine | stages (ms per step) | sum |
|---|---|---|---|---|
$(awk '{ e = ""; s = ""; n = ""; part = ""; list = ""; sum = 0
        for (i = 3; i <= NF; i++) { split($i, kv, "=")
            if (kv[1] == "engine") e = kv[2]; else if (kv[1] == "scene") s = kv[2]
            else if (kv[1] == "size") n = kv[2]; else if (kv[1] == "part") part = kv[2]
            else if (kv[2] + 0 > 0) { list = list (list == "" ? "" : ", ") kv[1] " " kv[2]; sum += kv[2] } }
        printf "| %s(%s) | %s | %s | %s | %.4g |\n", s, n, part == "settled" ? "301 to 600" : "all", e, list, sum }' "$work/stages")

Where the difference lies: the stages gathered into the parts of a step
both engines have, and this engine's own passes (shock propagation, the
position iterations and the lift; its relaxing sweep is timed within its
position stage, so it counts there).

| case | part of the step | this engine | Box2D v3 | difference (ms) |
|---|---|---|---|---|
$(awk 'function part(ours, k) {
            if (k == "narrowphase" || k == "collide") return 2
            if (k == "prepare" || k == "setup") return 3
            if (k == "solver" || (!ours && (k == "warm_start" || k == "solve" || k == "relax" ||
                k == "integrate" || k == "restitution" || k == "store"))) return 4
            if (k == "shock" || k == "position") return 5
            return 1 }
        { e = ""; c = ""; ours = 0
        for (i = 3; i <= NF; i++) { split($i, kv, "=")
            if (kv[1] == "engine") { e = kv[2]; ours = e == "ours" }
            else if (kv[1] == "scene") c = kv[2]; else if (kv[1] == "size") c = c "(" kv[2] ")"
            else if (kv[1] == "part") c = c (kv[2] == "settled" ? ", steps 301 to 600" : "")
            else t[c, ours, part(ours, kv[1])] += kv[2] }
        if (!(c in seen)) { seen[c] = 1; cases[++nc] = c }
        has[c, ours] = 1 }
     END { name[1] = "bodies moved, boxes and pairs"; name[2] = "contact geometry"
        name[3] = "preparing the contacts"; name[4] = "velocity solve"
        name[5] = "this engine\047s own passes"
        for (i = 1; i <= nc; i++) { c = cases[i]
            if (!has[c, 1] || !has[c, 0]) continue
            for (k = 1; k <= 5; k++)
                printf "| %s | %s | %.3f | %.3f | %+.3f |\n", c, name[k], t[c, 1, k], t[c, 0, k],
                    t[c, 1, k] - t[c, 0, k] } }' "$work/stages")
EOF
    fi
    if [ -s "$work/instructions" ]; then
        cat <<EOF

## Instructions per step

Counted by callgrind inside the step calls only, one run each.

\`\`\`
$(cat "$work/instructions")
\`\`\`
EOF
    fi
    if [ -s "$work/round" ]; then
        cat <<EOF

## Round bodies: circlepile(N) and mixedpile(N), one core

The pile with circles, and with squares, circles and capsules in turn
(bench-scenes.md); Box2D 2.4 has no capsule and is left out. Times as in the
speed table; then each engine's deepest penetration (m) and bodies outside
the container at step 600, from the first round.

\`\`\`
$(grep -v '^#' "$work/round")
\`\`\`

| scene | size | engine | deepest penetration (m) | outside |
|---|---|---|---|---|
$(awk '$2 == "round=1" { e = ""; s = ""; n = ""; p = ""; o = ""
        for (i = 3; i <= NF; i++) { split($i, kv, "=")
            if (kv[1] == "engine") e = kv[2]; if (kv[1] == "scene") s = kv[2]
            if (kv[1] == "size") n = kv[2]; if (kv[1] == "max_penetration") p = kv[2]
            if (kv[1] == "outside") o = kv[2] }
        printf "| %s | %s | %s | %s | %s |\n", s, n, e, p, o }' "$work/round-raw")
EOF
    fi
    if [ -s "$work/sleeping" ]; then
        cat <<EOF

## Sleeping on: pile(4000)

Every engine with its sleeping on (ours-sleeping: scene_set_sleeping at its
defaults; Box2D v3: its default); the settled row is the steps 301 to 600.

\`\`\`
$(grep -v '^#' "$work/sleeping")
\`\`\`

When every movable body of the pile is asleep, one run of $sleep_steps steps
each ("none": some body was still awake at the end, with how many), and
the CPU time of a step from then on:

| engine | all asleep at (s) | bodies awake at the end | ms per step once all asleep |
|---|---|---|---|
$(awk '{ e = ""; t = ""; a = 0; m = "-"
        for (i = 1; i <= NF; i++) { split($i, kv, "=")
            if (kv[1] == "engine") e = kv[2]; if (kv[1] == "asleep_s") t = kv[2]
            if (kv[1] == "awake_end") a = kv[2]; if (kv[1] == "asleep_ms") m = kv[2] }
        printf "| %s | %s | %s | %s |\n", e, t, a, m }' "$work/asleep")
EOF
    fi
    cat <<EOF

## Two workers: pile($workers_size)

Each engine with 2 workers against 1 (this engine's scene_set_workers,
Box2D v3's worldDef.workerCount and its own scheduler), three alternated
runs each, not pinned (the second worker needs the second core). Wall time
is what a second worker can save; CPU time over wall time shows how much of
the run the second core was busy (2.0 at most: this engine's waiting
threads spin a while before they sleep, v3's wait on a semaphore between
its tasks and spin only inside its solver). The load average at the start
is in the header: a second core busy with anything else leaves nothing to
gain.

| engine | workers | CPU ms per step (median) | wall ms per step (median) | CPU / wall |
|---|---|---|---|---|
$(awk '{ printf "| %s | %d | %s | %s | %.2f |\n", $1, $2, $3, $4, $3 / $4
        if (!($1 in seen)) { seen[$1] = 1; order[++engines] = $1 }
        wall[$1, $2] = $4 }
     END { printf "\n"
        for (x = 1; x <= engines; x++) { e = order[x]
            if (wall[e, 1] > 0 && wall[e, 2] > 0)
                printf "%s: two workers over one, wall time %.2f.\n", e, wall[e, 2] / wall[e, 1] }
        if (engines > 1 && wall[order[2], 2] > 0)
            printf "Ours over %s, both with two workers, wall time: %.2f.\n", order[2],
                wall[order[1], 2] / wall[order[2], 2] }' "$work/workers-medians")
EOF
    if [ -s "$work/scale" ]; then
        cat <<EOF

## Scale: pile(N), one core

Mean ms per step over the 600 steps, one pinned run per size; the exponent
is the least-squares slope of log(ms per step) on log(N) over the sizes.

$(awk '{ e = $1; engines[++ne] = e; fit[e] = $NF
        for (j = 2; j < NF; j++) { split($j, kv, "="); ms[e, kv[1]] = kv[2]
            if (!(kv[1] in have)) { have[kv[1]] = 1; sizes[++ns] = kv[1] } } }
     END {
        printf "| engine |"; for (j = 1; j <= ns; j++) printf " %s |", sizes[j]; print " exponent |"
        printf "|---|"; for (j = 1; j <= ns; j++) printf "---|"; print "---|"
        for (i = 1; i <= ne; i++) { e = engines[i]; printf "| %s |", e
            for (j = 1; j <= ns; j++) printf " %s |", ((e, sizes[j]) in ms) ? ms[e, sizes[j]] : "-"
            printf " N^%s |\n", fit[e] } }' "$work/scale-fit")
EOF
    fi
    cat <<EOF

## Quality over the 8 layout seeds

The chaotic figures over the 8 layout seeds of bench-scenes.md (median and
least-largest over the seeds), and the exact ones once; Box2D v3's
($v3name) beside this engine's. Penetrations: this engine's from its step
record (before the last solve), Box2D v3's from the scene's shapes
(polygons, circles and capsules) collided again at the final positions.

EOF
    if [ -n "$BENCH_SEEDS_ARGS" ]; then
        echo "Run with seeds.sh $BENCH_SEEDS_ARGS (--quick leaves out pile(10000))."
        echo
    fi
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
    echo
    cat "$work/joints.md"
    if [ -s "$work/web" ]; then
        echo
        cat "$work/web"
    fi
    cat <<EOF

## Commands

    make bench-report     # this page; BENCH_ROUNDS, BENCH_VARIANTS and the rest: tests/bench/bench_report.sh
    make bench-compare    # the speed tables alone
    make bench-joints     # the joints section alone (tests/bench/bench_report.sh --section joints)
    tests/bench/alternate.sh 7 build/bench/bench_engine build/bench/bench_box2d3-sse2 -- --scene pile --size 4000
    tests/bench/alternate.sh 7 build/bench/bench_engine build/bench/bench_box2d3-sse2 -- --scene circlepile --size 4000
    tests/bench/instructions.sh -s "pile:1000" build/bench/bench_engine:ours build/bench/bench_box2d3-sse2:box2d3-sse2
    tests/bench/seeds.sh build/bench/bench_engine   # quality over the seeds; --judge OLD NEW V3 decides "no worse"
    valgrind --tool=callgrind build/bench/bench_engine --scene pile --size 1000 --runs 1
EOF
} >"$output"
echo "bench-report: wrote $output" >&2
