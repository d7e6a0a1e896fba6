#!/bin/sh
# The browser's figures of docs/bench.md (make web-bench): the page's size and
# its time to first frame, and ms per step of pile(1000) and pyramid(40) in
# headless Chromium (bench_engine compiled to WebAssembly with the engine's
# 128-bit SIMD and without) against the native bench_engine on one worker,
# all in wall time (a page has no CPU clock), ROUNDS rounds taken in turn;
# each figure is the median of the rounds' medians, with their range.
#
# ROUNDS=5 sh tests/web/bench_web.sh
set -eu
rounds=${ROUNDS:-5}
web=build/web
native=build/bench/bench_engine
page() { echo "file://$(pwd)/$web/$1"; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The median and range of the numbers in a file, one a line.
summary() {
    sort -g "$1" | awk '{v[NR] = $1} END {
        m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
        printf "%.3g (%.3g to %.3g)", m, v[1], v[NR]
    }'
}

wall_of() { sed -n 's/.*engine=ours .*wall_median_ms=\([0-9.]*\).*/\1/p' | head -n 1; }

echo "page: $web/sandbox.html, $(wc -c <$web/sandbox.html) bytes" \
    "($(gzip -9 -c $web/sandbox.html | wc -c) gzipped)"
for i in $(seq "$rounds"); do
    node tests/web/browse.js --url "$(page sandbox.html)" --until "first frame" --timeout 60 |
        sed -n 's/.*first frame after \([0-9]*\) ms.*/\1/p' >>"$tmp/first"
done
echo "first frame: $(summary "$tmp/first") ms after the page began loading (file://, $rounds loads)"

for scene in "pile 1000" "pyramid 40"; do
    set -- $scene
    name=$1
    size=$2
    args="--scene $name --size $size --runs 1 --wall"
    for i in $(seq "$rounds"); do
        $native $args --workers 1 | wall_of >>"$tmp/$name.native"
        for build in simd scalar; do
            node tests/web/browse.js --url "$(page bench_engine-$build.html)?args=$(echo "$args" | tr ' ' '+')" \
                --until "bench: done" --timeout 300 | wall_of >>"$tmp/$name.$build"
        done
    done
    echo "$name($size) ms per step: native $(summary "$tmp/$name.native")," \
        "page with SIMD $(summary "$tmp/$name.simd"), page without $(summary "$tmp/$name.scalar")"
done
