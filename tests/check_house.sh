#!/bin/sh
# The engine's house, drawn from its objects and includes: which source file
# uses which (a symbol it calls or a private header it includes), checked for
# circles and for calls up the layers. Layers, lowest first, are the folders of
# engine/src listed in engine/src/LAYERS; a file may use its own folder and
# the folders below it. Ends with "N passed, N failed".
#
#   tests/check_house.sh [OBJDIR]         the checks (OBJDIR: build/engine)
#   tests/check_house.sh --dot [OBJDIR]   the graph in Graphviz's dot language
# The objects must have been built from the sources (make build/libjostle.a).
# make house draws the graph into docs/house.png.
objdir=build/engine
mode=check
[ "$1" = "--dot" ] && { mode=dot; shift; }
[ -n "$1" ] && objdir=$1
layers=$(grep -v '^#' engine/src/LAYERS 2>/dev/null | awk '{print $1}')
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# file -> folder, for every source file and private header
for f in engine/src/*/*.c engine/src/*/*.h engine/src/*.c engine/src/*.h; do
    [ -f "$f" ] || continue
    rel=${f#engine/src/}
    case $rel in */*) folder=${rel%%/*} ;; *) folder=. ;; esac
    name=$(basename "$rel"); name=${name%.*}; name=${name%_private}
    echo "$name $folder"
done | sort -u > "$tmp/folders"

# symbol -> defining unit, unit -> symbols it needs
for source in engine/src/*/*.c; do
    rel=${source#engine/src/}
    o="$objdir/${rel%.c}.o"
    unit=$(basename "$o" .o)
    nm --defined-only "$o" | awk -v u="$unit" '$2 ~ /^[TDRB]$/ {print $3, u}'
    nm -u "$o" | awk -v u="$unit" '{print "U", $2, u}' >> "$tmp/undef"
done | sort > "$tmp/defs"
awk 'NR == FNR {def[$1] = $2; next} ($2 in def) && def[$2] != $3 {print $3, def[$2]}' \
    "$tmp/defs" "$tmp/undef" > "$tmp/edges"

# includes of the engine's private headers, "LAYER/X.h" (X.h and X_private.h
# are X.c's unit); a public header, "jostle/X.h", is the API, not a file's
for f in engine/src/*/*.[ch] engine/src/*.[ch]; do
    [ -f "$f" ] || continue
    unit=$(basename "$f"); unit=${unit%.*}; unit=${unit%_private}
    grep -h '^#include "' "$f" | sed 's/#include "\(.*\)"/\1/' | grep -v '^jostle/' | while read -r h; do
        target=$(basename "$h" .h); target=${target%_private}
        grep -q "^$target " "$tmp/folders" && [ "$target" != "$unit" ] && echo "$unit $target"
    done
done >> "$tmp/edges"
sort -u "$tmp/edges" -o "$tmp/edges"

if [ "$mode" = dot ]; then
    # Drawn top to bottom from the highest layer to base, each folder a
    # cluster on a band of its own (invisible edges between the bands keep
    # every file of a layer above the next one down); an arrow points from a
    # file to what it uses, dark within a folder, lighter between folders;
    # base/, which every layer uses, gets one faint arrow from each folder.
    echo "digraph house {"
    echo "  rankdir=TB; newrank=true; ranksep=0.32; nodesep=0.12; compound=true;"
    echo "  graph [fontname=Helvetica, fontsize=12, bgcolor=white, labelloc=t, label=\"engine/src: an arrow goes from a file to a file it uses (calls, or includes its private header); layers from engine/src/LAYERS, lowest at the bottom\"];"
    echo "  node [shape=box, style=\"rounded,filled\", fillcolor=\"#eef3fb\", color=\"#4a6fa5\", fontname=Helvetica, fontsize=10, height=0.3];"
    echo "  edge [arrowsize=0.6];"
    for l in $layers; do
        echo "  subgraph cluster_$l { label=\"$l/\"; labeljust=l; labelloc=t; fontname=\"Helvetica-Bold\"; color=\"#9aa9c2\"; style=rounded;"
        awk -v l="$l" '$2 == l {printf "    \"%s\";\n", $1}' "$tmp/folders"
        echo "    \"band_$l\" [style=invis, label=\"\", width=0, height=0];"
        echo "  }"
    done
    # the bands, highest layer first: band_L above every file of L, each
    # file of L above the band of the layer below
    echo "$layers" | awk 'NF {l[++n] = $1} END {for (i = n; i > 1; i--) printf "  \"band_%s\" -> \"band_%s\" [style=invis];\n", l[i], l[i - 1]}'
    echo "$layers" | awk 'NF {l[++n] = $1} END {for (i = 2; i <= n; i++) print l[i], l[i - 1]}' > "$tmp/below"
    awk 'NR == FNR {below[$1] = $2; next} $2 != "." {
            printf "  \"band_%s\" -> \"%s\" [style=invis];\n", $2, $1
            if ($2 in below) printf "  \"%s\" -> \"band_%s\" [style=invis];\n", $1, below[$2]
        }' "$tmp/below" "$tmp/folders"
    # arrows between files, but into base/ one arrow per folder
    awk 'NR == FNR {folder[$1] = $2; if (!($2 in first)) first[$2] = $1; next}
        folder[$1] != "base" && folder[$2] == "base" {
            if (!(folder[$1] in drawn)) printf "  \"%s\" -> \"%s\" [ltail=cluster_%s, lhead=cluster_base, color=\"#b4bccb\"];\n", first[folder[$1]], first["base"], folder[$1]
            drawn[folder[$1]] = 1; next
        }
        {
            style = folder[$1] == folder[$2] ? "color=\"#27406b\"" : "color=\"#7d98c4\""
            printf "  \"%s\" -> \"%s\" [%s];\n", $1, $2, style
        }' "$tmp/folders" "$tmp/edges"
    echo "}"
    exit 0
fi

passed=0
failed=0
pass() { echo "PASS house.$1"; passed=$((passed + 1)); }
fail() { echo "FAIL house.$1"; shift; for line in "$@"; do echo "    $line"; done; failed=$((failed + 1)); }

# circles: tsort names the files of any cycle it finds
if cycles=$(tsort "$tmp/edges" 2>&1 >/dev/null | grep -v 'input contains a loop' | sed 's/^tsort: //' | sort -u); [ -z "$cycles" ]; then
    pass no_circles
else
    fail no_circles "files in a circle: $(echo $cycles)"
fi

# every file in a layer folder, and no call up the layers
rank() { echo "$layers" | awk -v f="$1" '$1 == f {print NR}'; }
loose=$(awk '$2 == "." {print $1}' "$tmp/folders")
[ -z "$loose" ] && pass every_file_in_a_layer || fail every_file_in_a_layer "outside any folder: $(echo $loose)"
up=$(while read -r from to; do
    ff=$(awk -v n="$from" '$1 == n {print $2}' "$tmp/folders")
    tf=$(awk -v n="$to" '$1 == n {print $2}' "$tmp/folders")
    [ -z "$ff" ] || [ -z "$tf" ] && continue
    rf=$(rank "$ff"); rt=$(rank "$tf")
    [ -n "$rf" ] && [ -n "$rt" ] && [ "$rt" -gt "$rf" ] && echo "$ff/$from -> $tf/$to"
done < "$tmp/edges")
if [ -z "$up" ]; then pass no_call_up_the_layers; else
    printf '%s\n' "$up" | { set --; while IFS= read -r line; do set -- "$@" "$line"; done; fail no_call_up_the_layers "$@"; }
    failed=$((failed + 1))
fi

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
