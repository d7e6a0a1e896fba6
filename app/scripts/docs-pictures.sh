#!/bin/sh
# Redraws the pictures of docs/sandbox.md and docs/sandbox-reference.md
# (docs/sandbox.png, docs/drop.png, docs/integrator.png, and docs/NAME.png
# for each NAME of $PAGES below: the games, the samples browser, the joint
# tool and the joint presets, the
# settings, the stage chart and the tools) by running the very commands
# docs/sandbox-reference.md shows, so the pictures and the text agree.
# make check's smoke test app_smoke.docs_pictures_regenerate runs the same
# commands and compares the result with the committed pictures; run this
# when a change to the app or the engine changes them on purpose.
# Usage (from the repository root, after make): app/scripts/docs-pictures.sh
set -e
PAGES="breakout space_invaders pegs samples solver stages ray box explode inspect joint_tool
joint_cradle joint_bridge joint_double_pendulum joint_ragdoll joint_crank joint_car"
cd "$(dirname "$0")/../.."
root=$(pwd)
doc=docs/sandbox-reference.md
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# docs/sandbox.png: the line that runs app/scripts/demo.txt and saves it there.
demo=$(grep -E '^\./sandbox .*--script app/scripts/demo\.txt .*--screenshot docs/sandbox\.png' "$doc")
echo "$demo"
eval "$demo"

# docs/integrator.png: the line that runs app/scripts/integrator.txt.
integrator=$(grep -E '^\./sandbox .*--script app/scripts/integrator\.txt .*--screenshot docs/integrator\.png' "$doc")
echo "$integrator"
eval "$integrator"

# The games, the samples browser, the solver's settings, the stage chart and
# each tool: the lines that run app/scripts/NAME.txt and save docs/NAME.png.
for name in $PAGES; do
    line=$(grep -E "^\./sandbox .*--script app/scripts/$name\.txt .*--screenshot docs/$name\.png" "$doc")
    echo "$line"
    eval "$line"
done

# docs/drop.png: the drop.txt example, run in a scratch directory.
sed -n "/^cat > drop.txt <<'EOF'\$/,/^EOF\$/p" "$doc" | sed '1d;$d' > "$tmp/drop.txt"
drop=$(grep -E '^\./sandbox .*--script drop\.txt .*--screenshot drop\.png' "$doc")
echo "$drop"
ln -s "$root/sandbox" "$tmp/sandbox"
(cd "$tmp" && eval "$drop")
cp "$tmp/drop.png" docs/drop.png
echo "redrew docs/sandbox.png, docs/drop.png, docs/integrator.png and docs/NAME.png for: $PAGES"
