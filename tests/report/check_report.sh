#!/bin/sh
# make check's part of the accuracy report (docs/accuracy.md):
#   report.regions.*     each scheme's stability limits measured on the engine
#                        against the closed forms (accuracy --check-regions)
#   report.quick_run_*   accuracy --quick writes every section
#   report.reproduces.*  the committed figures that are not timings come out
#                        the same from the sources: the diagnosed columns of
#                        docs/report/{oscillator,kepler,drag,bounce,
#                        friction_spring,incline_above,cradle3}.csv, the rows
#                        of docs/report/horizon-*.csv up to 1000 periods,
#                        docs/report/regions.csv and collisions.csv
#                        (accuracy --reproduce; the
#                        other cases, the longer horizons and the peers' table
#                        take minutes and are left to make report)
# Ends with "N passed, N failed".
program=build/report/accuracy
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
passed=0
failed=0
pass() { echo "PASS $1"; passed=$((passed + 1)); }
fail() { echo "FAIL $1${2:+: $2}"; failed=$((failed + 1)); }

"$program" --check-regions >"$out/regions" 2>&1
grep -E '^(PASS|FAIL) ' "$out/regions"
passed=$((passed + $(grep -c '^PASS ' "$out/regions")))
failed=$((failed + $(grep -c '^FAIL ' "$out/regions")))
grep -q 'passed, 0 failed' "$out/regions" || grep -q '^FAIL ' "$out/regions" ||
    fail report.regions_complete "$(tail -n 3 "$out/regions")"

mkdir -p "$out/quick"
if "$program" --quick --out "$out/quick" --doc "$out/quick/accuracy.md" 2>"$out/quick.log"; then
    pass report.quick_run_completes
    missing=""
    for section in "## 1. Error against step size" "## 2. Long horizons" "## 3. Stability regions" \
        "## 4. Contacts against exact answers" "### oscillator" "### kepler09" "### friction_spring" \
        "### rocking" "### cradle5"; do
        grep -q "^$section" "$out/quick/accuracy.md" || missing="$missing '$section'"
    done
    if [ -z "$missing" ]; then pass report.quick_run_writes_every_section; else
        fail report.quick_run_writes_every_section "missing$missing"; fi
else
    fail report.quick_run_completes "$(tail -n 5 "$out/quick.log")"
fi

mkdir -p "$out/again"
if ! "$program" --reproduce --out "$out/again" 2>"$out/again.log"; then
    fail report.reproduces "$(tail -n 5 "$out/again.log")"
else
    for name in oscillator kepler drag bounce friction_spring incline_above cradle3; do
        committed=docs/report/$name.csv
        if [ ! -f "$committed" ]; then fail "report.reproduces.$name" "no $committed"; continue; fi
        if cut -d, -f1-9 "$committed" | cmp -s - "$(cut -d, -f1-9 "$out/again/$name.csv" >"$out/$name.cut"; echo "$out/$name.cut")"; then
            pass "report.reproduces.$name"
        else
            fail "report.reproduces.$name" "docs/report/$name.csv differs (first 9 columns): $(cut -d, -f1-9 "$committed" | diff - "$out/$name.cut" | head -n 3 | tr '\n' ' ')"
        fi
    done
    for name in oscillator kepler kepler09; do
        committed=docs/report/horizon-$name.csv
        if [ ! -f "$committed" ]; then fail "report.reproduces.horizon_$name" "no $committed"; continue; fi
        awk -F, 'NR == 1 || $3 <= 1000.000001' "$committed" | sort >"$out/h-committed"
        sort "$out/again/horizon-$name.csv" >"$out/h-again"
        if cmp -s "$out/h-committed" "$out/h-again"; then
            pass "report.reproduces.horizon_$name"
        else
            fail "report.reproduces.horizon_$name" "$(diff "$out/h-committed" "$out/h-again" | head -n 3 | tr '\n' ' ')"
        fi
    done
    for name in regions collisions; do
        if [ -f "docs/report/$name.csv" ] && cmp -s "docs/report/$name.csv" "$out/again/$name.csv"; then
            pass "report.reproduces.$name"
        else
            fail "report.reproduces.$name" "docs/report/$name.csv differs or is missing"
        fi
    done
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
