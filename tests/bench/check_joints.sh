#!/bin/sh
# make check's run of the joint scenes (tests/bench/bench_joint_scenes.h) on
# this engine, build/bench/bench_engine, each twice (--runs 2: the figures
# must come out the same, runs_differ absent):
#   jointchain(20): the chain's stretch at the end under 0.5%;
#   jointchain(100), the benchmark's size: the chain's stretch at the end
#     under 10% (the sum of the joint gaps over the chain's length; 5.9%
#     measured, Box2D v3 6.0%);
#   ragdolls(20): no body below the floor or outside the box at the end,
#     every pin within 1 cm, and at most 10 of the 200 bodies still moving
#     (3 measured).
# Ends with "N passed, N failed".
program=build/bench/bench_engine
passed=0
failed=0

# check NAME "SCENE SIZE" AWK-CONDITION: the condition on the scene's
# result line, whose key=value fields are v[KEY] (num(KEY): the number, or
# 1e300 when it is not one, so that a NaN fails).
check() {
    line=$("$program" --variant ours --runs 2 --scene "$2" --size "$3" | grep '^engine=ours ')
    if [ -n "$line" ] && echo "$line" | awk '
        function num(key) { return v[key] ~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/ ? v[key] + 0 : 1e300 }
        { for (i = 1; i <= NF; i++) { n = index($i, "="); v[substr($i, 1, n - 1)] = substr($i, n + 1) } }
        END { exit !('"$4"') }' && ! echo "$line" | grep -q 'runs_differ=1'; then
        echo "PASS joints_bench.$1"
        passed=$((passed + 1))
    else
        echo "FAIL joints_bench.$1: ${line:-no result line from $program}"
        failed=$((failed + 1))
    fi
}

check jointchain_20_holds_its_length jointchain 20 'num("end_stretch") < 0.005'
check jointchain_100_holds_its_length jointchain 100 'num("end_stretch") < 0.1'
check ragdolls_stay_in_the_box ragdolls 20 \
    'v["below"] == "0" && v["outside"] == "0" && num("end_gap") < 0.01 && num("moving_end") <= 10'
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
