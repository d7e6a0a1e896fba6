#!/bin/sh
# The browser's figures (make web-bench): the page's size and its time to
# first frame, and ms per step of pile(1000) and pyramid(40) in headless
# Chromium (bench_engine compiled to WebAssembly with 128-bit SIMD and
# without) against the native bench_engine on one worker, all in wall time
# (a page has no CPU clock) and in processor time of the whole run (the
# page's renderer process, from Chromium's metrics), ROUNDS rounds taken in
# turn; each figure is the smallest of the rounds, the one the other
# programs of a shared machine disturbed least, with the largest. Prints them and writes them into
# docs/bench.md between <!-- web:begin --> and <!-- web:end --> (the block
# is added at the end the first time; the rest of the file is left alone).
#
# ROUNDS=5 sh tests/web/bench_web.sh
set -eu
rounds=${ROUNDS:-5}
web=build/web
native=build/bench/bench_engine
doc=docs/bench.md
page() { echo "file://$(pwd)/$web/$1"; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The smallest of the numbers in a file (one a line), with the largest;
# FORMAT (printf's, default %.3g) for each.
summary() {
    sort -g "$1" | awk -v f="${2:-%.3g}" '{v[NR] = $1} END {
        printf f, v[1]; if (NR > 1) printf " (to " f ")", v[NR]
    }'
}
fastest() { sort -g "$1" | head -n 1; }
ratio() { awk -v a="$(fastest "$1")" -v b="$(fastest "$2")" 'BEGIN { printf "%.2f", a / b }'; }
load() { cut -d' ' -f1 /proc/loadavg; }

wall_of() { sed -n 's/.*engine=ours .*wall_median_ms=\([0-9.]*\).*/\1/p' | head -n 1; }
in_page() {
    node tests/web/browse.js --url "$(page "$1")" --until "$2" --timeout 300
}

load_before=$(load)
bytes=$(wc -c <$web/sandbox.html)
gzipped=$(gzip -9 -c $web/sandbox.html | wc -c)
for i in $(seq "$rounds"); do
    in_page sandbox.html "first frame" |
        sed -n 's/.*first frame after \([0-9]*\) ms.*/\1/p' >>"$tmp/first"
done

# Each run's wall ms per step into NAME.BUILD, and the processor time of
# the whole run (s: the native process, the page's renderer process) into
# NAME.BUILD.cpu.
for scene in "pile 1000" "pyramid 40"; do
    set -- $scene
    args="--scene $1 --size $2 --runs 1 --wall"
    for i in $(seq "$rounds"); do
        (
            $native $args --workers 1 >"$tmp/out"
            times >"$tmp/times"
        )
        wall_of <"$tmp/out" >>"$tmp/$1.native"
        # times: the shell's user and system time, then its children's.
        sed -n 2p "$tmp/times" | tr 'ms' '  ' |
            awk '{printf "%.3f\n", 60 * $1 + $2 + 60 * $3 + $4}' >>"$tmp/$1.native.cpu"
        for build in simd scalar; do
            node tests/web/browse.js --cpu 1 --timeout 300 --until "bench: done" \
                --url "$(page "bench_engine-$build.html?args=$(echo "$args" | tr ' ' '+')")" >"$tmp/out"
            wall_of <"$tmp/out" >>"$tmp/$1.$build"
            sed -n 's/^cpu: renderer process \([0-9.]*\) s$/\1/p' "$tmp/out" >>"$tmp/$1.$build.cpu"
        done
    done
done
load_after=$(load)

row() {
    echo "| $1($2) | $(summary "$tmp/$1.native") | $(summary "$tmp/$1.simd") |" \
        "$(summary "$tmp/$1.scalar") | $(ratio "$tmp/$1.simd" "$tmp/$1.native") |" \
        "$(ratio "$tmp/$1.scalar" "$tmp/$1.simd") |"
}
cpu_row() {
    echo "| $1($2) | $(summary "$tmp/$1.native.cpu") | $(summary "$tmp/$1.simd.cpu") |" \
        "$(summary "$tmp/$1.scalar.cpu") | $(ratio "$tmp/$1.simd.cpu" "$tmp/$1.native.cpu") |" \
        "$(ratio "$tmp/$1.scalar.cpu" "$tmp/$1.simd.cpu") |"
}
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
emcc_version=$(NODE_PATH=/usr/share/nodejs emcc --version 2>/dev/null | head -n 1 | grep -o '[0-9][0-9.]*' | tail -n 1)
chromium_version=$(chromium --version 2>/dev/null | awk '{print $2}')
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
{
    echo "<!-- web:begin -->"
    echo "## The sandbox in a browser"
    echo
    echo "\`make web-bench\` (tests/web/bench_web.sh) measures the web page of"
    echo "\`make web\` and the engine compiled to WebAssembly by Emscripten"
    echo "$emcc_version, run in headless Chromium $chromium_version from file://,"
    echo "against the native build on the same machine ($cpu, $(nproc) cores),"
    echo "at commit $commit. Each figure is the smallest of $rounds rounds taken in"
    echo "turn, with the largest."
    echo "The machine was shared with other builds (load average $load_before"
    echo "at the start, $load_after at the end), which the slowest rounds show."
    echo
    echo "- **Page**: \`build/web/sandbox.html\` is one file of $bytes bytes"
    echo "  ($gzipped gzipped): the WebAssembly, its JavaScript, SDL2 and the"
    echo "  presets inside."
    echo "- **Time to first frame**: $(summary "$tmp/first" %d) ms from the start of"
    echo "  the page's loading to its first frame handed to the browser."
    echo
    echo "bench_engine's scenes (docs/bench-scenes.md) on one thread, as"
    echo "\`bench_engine --scene NAME --size N --runs 1 --wall\` (pile runs its"
    echo "variant with sleeping too). Wall ms per step:"
    echo
    echo "| scene | native, 1 worker | page, SIMD | page, no SIMD | page (SIMD) / native | page: no SIMD / SIMD |"
    echo "|---|---|---|---|---|---|"
    row pile 1000
    row pyramid 40
    echo
    echo "Processor time of the whole run in seconds (the native process; the"
    echo "page's renderer process, loading and compiling included), which the"
    echo "other programs on the machine disturb much less than wall time:"
    echo
    echo "| scene | native, 1 worker | page, SIMD | page, no SIMD | page (SIMD) / native | page: no SIMD / SIMD |"
    echo "|---|---|---|---|---|---|"
    cpu_row pile 1000
    cpu_row pyramid 40
    echo
    echo "The page is built with \`-O2 -msimd128\`: Emscripten 3.1.6 supports"
    echo "WebAssembly's 128-bit SIMD, and the engine's four-lane contact batches"
    echo "become pairs of f64x2 operations (no SIMD: the same source at \`-O2\`"
    echo "alone). The native build is \`-O2\` with the batches cloned for AVX2"
    echo "where the processor has it, on one worker as the page has one thread."
    echo "<!-- web:end -->"
} >"$tmp/block"
cat "$tmp/block"

if grep -q '^<!-- web:begin -->$' "$doc"; then
    awk -v block="$tmp/block" '
        /^<!-- web:begin -->$/ { while ((getline line < block) > 0) print line; skip = 1; next }
        /^<!-- web:end -->$/ { skip = 0; next }
        !skip { print }' "$doc" >"$tmp/doc"
else
    { cat "$doc"; echo; cat "$tmp/block"; } >"$tmp/doc"
fi
cp "$tmp/doc" "$doc"
echo "make web-bench: written into $doc"
