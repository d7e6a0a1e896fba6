#!/bin/sh
# Runs every test program given, shows their output, and ends with one line
# "N passed, N failed" totalling theirs (the line CI reads). A program that
# exits non-zero without printing its own summary counts as one failure.
passed=0
failed=0
status=0
for program in "$@"; do
    echo "== $program"
    output=$($program 2>&1)
    code=$?
    printf '%s\n' "$output" | grep -v -E '^[0-9]+ passed, [0-9]+ failed' 
    summary=$(printf '%s\n' "$output" | grep -E '^[0-9]+ passed, [0-9]+ failed' | tail -n 1)
    if [ -n "$summary" ]; then
        p=$(echo "$summary" | sed -E 's/^([0-9]+) passed.*/\1/')
        f=$(echo "$summary" | sed -E 's/^[0-9]+ passed, ([0-9]+) failed.*/\1/')
        passed=$((passed + p))
        failed=$((failed + f))
        echo "-- $summary"
    else
        failed=$((failed + 1))
        echo "-- no summary from $program (exit $code): counted as 1 failed"
    fi
    [ "$code" -ne 0 ] && status=1
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ] || status=1
exit $status
