#!/bin/sh
# make check's run of the stability suite: build/stability/stability --quick
# --check asserts every case's verdict on this engine (about a minute) and
# prints PASS/FAIL lines and "N passed, N failed"; then the page it writes
# must hold every section. The full suite with the peers is `make stability`.
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
build/stability/stability --quick --check --doc "$out/stability.md" 2>"$out/log" >"$out/check"
status=$?
grep -v -E '^[0-9]+ passed, [0-9]+ failed' "$out/check"
summary=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$out/check" | tail -n 1)
if [ -z "$summary" ]; then
    cat "$out/log"
    echo "FAIL stability.quick_run_completes (exit $status)"
    echo "0 passed, 1 failed"
    exit 1
fi
passed=$(echo "$summary" | sed -E 's/^([0-9]+) passed.*/\1/')
failed=$(echo "$summary" | sed -E 's/^[0-9]+ passed, ([0-9]+) failed.*/\1/')
missing=""
for section in "Stiff springs" "Mass ratios" "Speed and step size" "Overlap recovery" \
    "Stacks and piles" "Restitution" "Size and place" "Degenerate shapes and bad input" \
    "Long run and determinism" "Stiff and extreme cases"; do
    grep -q "^## [0-9]*\. $section\$" "$out/stability.md" || missing="$missing '$section'"
done
if [ -z "$missing" ]; then
    echo "PASS stability.page_has_every_section"
    passed=$((passed + 1))
else
    echo "FAIL stability.page_has_every_section: missing$missing"
    failed=$((failed + 1))
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
