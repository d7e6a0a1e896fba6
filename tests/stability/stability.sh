#!/bin/sh
# make stability: runs the stability scenes of tests/bench/bench_scenes.h on
# Chipmunk2D and Box2D 2.4 (their benchmark programs, in the background, on
# the second core) while build/stability/stability measures this engine; the
# latter waits for the peers' lines and writes docs/stability.md, the table
# of every row (docs/stability/stability.csv) and every figure's raw line
# (docs/stability/lines.txt). Progress on stderr; about ten minutes.
set -e
out=build/stability
mkdir -p "$out" docs/stability
peers="$out/peers.txt"
: >"$peers"

# One program on one scene: its key=value lines, appended.
run() {
    program=$1
    shift
    [ -x "$program" ] || { echo "stability: $program not built; its columns say 'not run'" >&2; return 0; }
    echo "  $(basename "$program") $*" >&2
    "$program" --runs 1 "$@" | grep '^engine=' >>"$peers" || echo "stability: $program $* failed" >&2
}

speeds=1,2,5,10,20,50,100,200,500,1000,2000,5000,10000
run_peers() {
    for p in build/bench/bench_chipmunk build/bench/bench_box2d; do
        v=""
        [ "$p" = build/bench/bench_box2d ] && v="--variant box2d"
        run $p $v --scene spring --size 0,0.1,0.5
        run $p $v --scene springpair --size 1000
        run $p $v --scene chain --size 20
        run $p --scene stack2
        run $p --scene heavytop --size 10,100,1000
        run $p $v --scene headon
        run $p $v --scene tunnel,tunnelmove,bullet --size $speeds
        run $p $v --scene rod
        run $p --scene drop
        run $p --scene overlap,coincide --size 1,0.5,10
        run $p --scene column --size 20 --steps 3600
        run $p --scene pyramid --size 40 --steps 3600
        run $p $v --scene gas,settle --size 1,0
        run $p $v --scene wallbounce --size 1,1.1
        run $p --scene scaled --size 0.01 --dt 1/60,1/600
        run $p --scene scaled --size 1 --dt 1/60
        run $p --scene scaled --size 1000 --dt 1/60,0.527046276694730
        run $p --scene far --size 0,1e6,1e8,1e10,1e12
    done
    # The piles last: the longest runs. Box2D without sleeping (the case is
    # about settling by itself) and with its defaults; pile(10000) with
    # continuous collision off (with it, about five minutes).
    run build/bench/bench_chipmunk --scene pile --size 2000 --steps 4200
    run build/bench/bench_box2d --variant box2d-nosleep --scene pile --size 2000 --steps 4200
    run build/bench/bench_box2d --variant box2d --scene pile --size 2000 --steps 4200
    run build/bench/bench_chipmunk --scene circlepile,capsulepile --size 2000 --steps 4200
    run build/bench/bench_box2d --variant box2d-nosleep --scene circlepile --size 2000 --steps 4200
    run build/bench/bench_box2d --variant box2d --scene circlepile --size 2000 --steps 4200
    run build/bench/bench_chipmunk --scene pile --size 10000
    run build/bench/bench_box2d --variant box2d-discrete --scene pile --size 10000
    echo "# peers done" >>"$peers"
}

echo "stability: the peers in the background (lines in $peers)" >&2
run_peers 2>"$out/peers.log" &
build/stability/stability --peers "$peers" --doc docs/stability.md --out docs/stability \
    --raw docs/stability/lines.txt
wait
if command -v gnuplot >/dev/null 2>&1; then
    (cd docs/stability && gnuplot plots.gp) && echo "stability: drew docs/stability/springs.svg" >&2
else
    echo "stability: gnuplot missing: docs/stability/springs.svg not redrawn (apt-get install gnuplot-nox)" >&2
fi
echo "stability: wrote docs/stability.md" >&2
