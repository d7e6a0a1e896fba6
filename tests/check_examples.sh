#!/bin/sh
# Builds each program in tests/examples/ against the release library with
# nothing but the public headers (cc -std=c11 -Iengine/include ...
# build/libjostle.a -pthread -lm), runs it, and checks that README.md shows every line
# of each example it quotes (falling_hexagon.c), so the README cannot drift
# from code that compiles. Ends with "N passed, N failed".
passed=0
failed=0
CC=${CC:-cc}
mkdir -p build/examples
for source in tests/examples/*.c; do
    name=$(basename "$source" .c)
    if $CC -std=c11 -Wall -Wextra -Werror -Iengine/include "$source" build/libjostle.a -pthread -lm \
        -o "build/examples/$name" && output=$("build/examples/$name"); then
        echo "$output" | sed 's/^/    /'
        echo "PASS examples.$name"
        passed=$((passed + 1))
    else
        echo "FAIL examples.$name (did not build or exited non-zero)"
        failed=$((failed + 1))
    fi
done
# The README quotes falling_hexagon.c: every line of it must be there.
missing=$(grep -v '^$' tests/examples/falling_hexagon.c | while IFS= read -r line; do
    grep -qxF -- "$line" README.md || echo "$line"
done)
if [ -z "$missing" ]; then
    echo "PASS examples.readme_quotes_falling_hexagon"
    passed=$((passed + 1))
else
    echo "FAIL examples.readme_quotes_falling_hexagon: README.md lacks:"
    echo "$missing" | sed 's/^/    /'
    failed=$((failed + 1))
fi
# A program of bodies, forces and seed collisions links none of the world
# contact pipeline (scene_contacts.c is its only door); one that enables
# world contacts does, which shows the check can see them. The worker
# threads (workers.c) come only with the world.
contact_symbols='broadphase_|manifold_|coloring_|solver_|shock_|world_step|workers_'
linked() {
    nm "$1" 2>/dev/null | grep -E " [TtDdRrBb] ($contact_symbols)" | head -n 3
}
if [ -x build/examples/seed_api ] && [ -x build/examples/falling_hexagon ] &&
    [ -z "$(linked build/examples/seed_api)" ] && [ -n "$(linked build/examples/falling_hexagon)" ]; then
    echo "    sizes (text+data+bss, bytes): seed_api $(size build/examples/seed_api | awk 'NR==2 {print $4}'), falling_hexagon $(size build/examples/falling_hexagon | awk 'NR==2 {print $4}')"
    echo "PASS examples.forces_only_program_links_no_contact_code"
    passed=$((passed + 1))
else
    echo "FAIL examples.forces_only_program_links_no_contact_code: seed_api links:"
    linked build/examples/seed_api | sed 's/^/    /'
    failed=$((failed + 1))
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
