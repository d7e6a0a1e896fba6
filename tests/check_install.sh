#!/bin/sh
# make install into a temporary DESTDIR (PREFIX=/usr), then, outside the
# tree, the README's example built with pkg-config against the installed
# static library and then the shared one, and the seed-API example with the
# seed's bare header names (seed_cflags); each must run. Then make
# uninstall must leave nothing. Ends with "N passed, N failed".
root=$(pwd)
stage=$(mktemp -d)
work=$(mktemp -d)
trap 'rm -rf "$stage" "$work"' EXIT
passed=0
failed=0
pass() { echo "PASS install.$1"; passed=$((passed + 1)); }
fail() { echo "FAIL install.$1"; shift; printf '    %s\n' "$@"; failed=$((failed + 1)); }

if env -u MAKEFLAGS -u MAKELEVEL make -s -C "$root" install DESTDIR="$stage" PREFIX=/usr \
        >"$work/install.log" 2>&1; then
    pass make_install
else
    fail make_install "$(tail -n 5 "$work/install.log")"
fi
lib="$stage/usr/lib"
for f in include/jostle/jostle.h include/jostle/body.h lib/libjostle.a lib/pkgconfig/jostle.pc; do
    [ -f "$stage/usr/$f" ] || fail "installs_$(basename "$f" | tr . _)" "missing: /usr/$f"
done
soname=$(readelf -d "$lib/libjostle.so" 2>/dev/null | sed -n 's/.*Library soname: \[\(.*\)\].*/\1/p')
case "$soname" in
    libjostle.so.[0-9]*) [ -e "$lib/$soname" ] && pass versioned_soname || fail versioned_soname "no $soname" ;;
    *) fail versioned_soname "soname: '$soname'" ;;
esac
# Only the public API is exported: nothing of the solver, the world or the
# allocator.
leaked=$(nm -D --defined-only "$lib/libjostle.so" 2>/dev/null | awk '{print $3}' |
    grep -E '^(solver_|world_|memory_|shock_|coloring_|broadphase_|manifold_|sleep_|workers_|check_)' | head -n 3)
[ -z "$leaked" ] && pass exports_only_the_api || fail exports_only_the_api "exported: $leaked"

export PKG_CONFIG_SYSROOT_DIR="$stage" PKG_CONFIG_PATH="$lib/pkgconfig" PKG_CONFIG_LIBDIR="$lib/pkgconfig"
cp "$root/tests/examples/falling_hexagon.c" "$root/tests/examples/seed_api.c" "$work/"
cd "$work" || exit 1
CC=${CC:-cc}
# shellcheck disable=SC2046
if $CC -static -std=c11 $(pkg-config --cflags jostle) falling_hexagon.c \
        $(pkg-config --static --libs jostle) -o static_example 2>build.log &&
    ./static_example >run.log && grep -q 'rests at y' run.log &&
    ! readelf -d static_example 2>/dev/null | grep -q NEEDED; then
    pass static_library_with_pkg_config
else
    fail static_library_with_pkg_config "$(cat build.log run.log 2>/dev/null | tail -n 5)"
fi
# shellcheck disable=SC2046
if $CC -std=c11 $(pkg-config --cflags jostle) falling_hexagon.c $(pkg-config --libs jostle) \
        -o shared_example 2>build.log &&
    readelf -d shared_example | grep -q "NEEDED.*$soname" &&
    LD_LIBRARY_PATH="$lib" ./shared_example >run.log && grep -q 'rests at y' run.log; then
    pass shared_library_with_pkg_config
else
    fail shared_library_with_pkg_config "$(cat build.log run.log 2>/dev/null | tail -n 5)"
fi
seed_cflags=$(pkg-config --variable=seed_cflags jostle)
# shellcheck disable=SC2046
if $CC -std=c11 $(pkg-config --cflags jostle) $seed_cflags seed_api.c \
        $(pkg-config --libs jostle) -lm -o seed_example 2>build.log &&
    LD_LIBRARY_PATH="$lib" ./seed_example >run.log; then
    pass seed_headers_by_their_bare_names
else
    fail seed_headers_by_their_bare_names "$(cat build.log run.log 2>/dev/null | tail -n 5)"
fi
cd "$root" || exit 1

env -u MAKEFLAGS -u MAKELEVEL make -s uninstall DESTDIR="$stage" PREFIX=/usr >/dev/null 2>&1
left=$(find "$stage" -type f -o -type l | head -n 3)
[ -z "$left" ] && pass uninstall_removes_everything || fail uninstall_removes_everything "left: $left"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
