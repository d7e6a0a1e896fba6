#!/bin/sh
# make check's part of docs/leave-out.md (make bench-stages): the column
# "what it runs as it is" of the first table, figures that are not timings
# (force evaluations, contact points, bodies asleep), must come out of the
# sources as the committed page has them: build/bench/bench_stages --facts
# prints each scene's row start, which must be in the page. The settled
# piles' asleep counts take minutes and are left to make bench-stages.
# Ends with "N passed, N failed".
passed=0
failed=0
facts=$(build/bench/bench_stages --facts) || { echo "FAIL stages.facts_run"; echo "0 passed, 1 failed"; exit 1; }
while IFS= read -r line; do
    scene=$(printf '%s\n' "$line" | cut -d'|' -f2 | sed 's/^ *//; s/ *$//' | tr ' ' '_')
    if grep -qF -- "$line" docs/leave-out.md; then
        echo "PASS stages.reproduces.$scene"
        passed=$((passed + 1))
    else
        echo "FAIL stages.reproduces.$scene: docs/leave-out.md has no row starting '$line'"
        failed=$((failed + 1))
    fi
done <<EOF2
$facts
EOF2
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
