#!/bin/sh
# Where a generated page's figures come from, for the page's head
# (docs/accuracy.md, stability.md, leave-out.md, scale.md, bench.md):
#
#   tests/provenance.sh begin STATE      before the run: the time, the load,
#                                        the processors' counters
#   tests/provenance.sh block STATE      after it: a markdown block on stdout
#   tests/provenance.sh stamp PAGE STATE the block put under PAGE's title
#
# The block states the commit (and, in bold, that the tree had uncommitted
# changes outside docs/, naming them), the compiler and the flags
# (PROVENANCE_FLAGS), the processor, the run's start and length, the load
# average at its start and end, and how busy the processors were during it
# (from /proc/stat: a run of one thread on an otherwise idle machine of n
# processors reads about 100/n %). PROVENANCE_REQUIRE_CLEAN=1 makes `begin`
# refuse a tree with uncommitted changes.
set -e
command=$1
state=$2

cpu_counters() {
    # total and idle (idle + iowait) jiffies over all processors
    awk '/^cpu / { total = 0; for (i = 2; i <= NF; i++) total += $i; print total, $5 + $6; exit }' /proc/stat
}

dirty_files() {
    git status --porcelain --untracked-files=no -- . ':(exclude)docs' 2>/dev/null | awk '{ print $2 }'
}

case $command in
begin)
    if [ "${PROVENANCE_REQUIRE_CLEAN:-0}" = 1 ] && [ -n "$(dirty_files)" ]; then
        echo "provenance: the tree has uncommitted changes outside docs/ (commit them, or unset PROVENANCE_REQUIRE_CLEAN):" >&2
        dirty_files >&2
        exit 1
    fi
    mkdir -p "$(dirname "$state")"
    {
        echo "start_epoch=$(date +%s)"
        echo "start_utc='$(date -u '+%Y-%m-%d %H:%M UTC')'"
        echo "start_load=$(cut -d' ' -f1 /proc/loadavg)"
        echo "start_counters='$(cpu_counters)'"
    } >"$state"
    ;;
block)
    . "$state"
    end_epoch=$(date +%s)
    end_load=$(cut -d' ' -f1 /proc/loadavg)
    busy=$(printf '%s %s\n' "$start_counters" "$(cpu_counters)" |
           awk '{ total = $3 - $1; idle = $4 - $2; if (total > 0) printf "%.0f", 100 * (total - idle) / total; else print "?" }')
    commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
    date=$(git log -1 --format=%cd --date=short 2>/dev/null || echo unknown)
    dirty=$(dirty_files)
    compiler=$(${CC:-cc} --version 2>/dev/null | head -n 1)
    processor=$(awk -F': ' '/^model name/ { print $2; exit }' /proc/cpuinfo 2>/dev/null)
    processors=$(nproc 2>/dev/null || echo "?")
    echo "- **Commit** $commit ($date)."
    if [ -n "$dirty" ]; then
        count=$(printf '%s\n' "$dirty" | wc -l | tr -d ' ')
        names=$(printf '%s\n' "$dirty" | head -n 5 | tr '\n' ' ' | sed 's/ $//')
        echo "  **Built from a tree with uncommitted changes ($count files outside docs/: $names): these figures need not reproduce from $commit.**"
    fi
    echo "- **Compiler** $compiler; flags \`${PROVENANCE_FLAGS:-unknown}\`."
    echo "- **Processor** ${processor:-unknown}, $processors processors."
    echo "- **Run** $start_utc, $((end_epoch - start_epoch)) s; load average $start_load at the start, $end_load at the end; the processors were $busy% busy during it (one thread alone on an idle machine: about $((100 / processors))%)."
    ;;
stamp)
    page=$2
    state=$3
    block=$(mktemp)
    sh "$0" block "$state" >"$block"
    { head -n 1 "$page"; echo; cat "$block"; tail -n +2 "$page"; } >"$page.tmp"
    mv "$page.tmp" "$page"
    rm -f "$block"
    ;;
*)
    echo "usage: $0 begin STATE | block STATE | stamp PAGE STATE" >&2
    exit 2
    ;;
esac
