#!/bin/sh
# Fetches Debian's source packages of SDL2, SDL2_gfx and SDL2_image into
# DIR/src/SDL2, DIR/src/SDL2_gfx and DIR/src/SDL2_image, for `make web` to
# build them for WebAssembly.
#
# Usage: app/web/debian_sources.sh DIR
#
# The system's apt sources are read, never changed: their Debian entries
# (those of this release's suites) are copied as deb-src entries into
# DIR/apt/, and apt-get runs with its own options pointing there
# (Dir::Etc::SourceList, Dir::Etc::SourceParts, Dir::State::Lists,
# Dir::Cache), so no host is named here and /etc/apt is left alone.
# apt's output goes to DIR/apt.log. Needs apt-get and dpkg-source
# (dpkg-dev).
set -eu

dir=${1:?usage: debian_sources.sh DIR}
mkdir -p "$dir"
dir=$(cd "$dir" && pwd)
apt_dir=$dir/apt
log=$dir/apt.log
src=$dir/src
: >"$log"

fail() {
    echo "make web: $*" >&2
    if [ -s "$log" ]; then
        tail -n 15 "$log" >&2
        echo "make web: (the whole log is in $log)" >&2
    fi
    exit 1
}

command -v dpkg-source >/dev/null 2>&1 || fail "dpkg-source is missing (apt-get install dpkg-dev)"

codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-}")
[ -n "$codename" ] || fail "cannot tell this system's Debian release (VERSION_CODENAME in /etc/os-release)"

# Where this system keeps its sources, as apt itself says.
eval "$(apt-config shell LIST Dir::Etc::sourcelist/f PARTS Dir::Etc::sourceparts/d)"
LIST=${LIST:-/etc/apt/sources.list}
PARTS=${PARTS:-/etc/apt/sources.list.d/}

mkdir -p "$apt_dir/sources.list.d" "$apt_dir/lists/partial" "$apt_dir/cache/archives/partial"
rm -f "$apt_dir/sources.list.d/"*
# One-line entries ("deb [options] URI SUITE COMPONENTS...") of this
# release's suites, as deb-src.
for file in "$LIST" "$PARTS"*.list; do
    [ -f "$file" ] || continue
    awk -v code="$codename" '
        $1 == "deb" {
            i = 2
            if ($2 ~ /^\[/) { while (i <= NF && $i !~ /\]$/) i++; i++ }
            suite = $(i + 1)
            if (suite == code || index(suite, code "-") == 1) { $1 = "deb-src"; print }
        }' "$file"
done >"$apt_dir/sources.list.d/debian-src.list"
# deb822 stanzas ("Types: deb", "Suites: ...") of this release's suites,
# as deb-src; comments dropped.
for file in "$PARTS"*.sources; do
    [ -f "$file" ] || continue
    awk -v code="$codename" '
        function flush() {
            if (n > 0 && types && suites) {
                for (j = 1; j <= n; j++) print (lines[j] ~ /^Types:/ ? "Types: deb-src" : lines[j])
                print ""
            }
            n = 0; types = 0; suites = 0
        }
        /^[ \t]*$/ { flush(); next }
        /^#/ { next }
        {
            lines[++n] = $0
            if ($1 == "Types:") for (k = 2; k <= NF; k++) if ($k == "deb") types = 1
            if ($1 == "Suites:") {
                for (k = 2; k <= NF; k++) if ($k == code || index($k, code "-") == 1) suites = 1
            }
        }
        END { flush() }' "$file"
done >"$apt_dir/sources.list.d/debian-src.sources"
[ -s "$apt_dir/sources.list.d/debian-src.list" ] || [ -s "$apt_dir/sources.list.d/debian-src.sources" ] ||
    fail "no Debian '$codename' entries in $LIST or $PARTS to make deb-src entries from"

apt_get() {
    apt-get -q -o Dir::Etc::SourceList="$apt_dir/sources.list.d/debian-src.list" \
        -o Dir::Etc::SourceParts="$apt_dir/sources.list.d" \
        -o Dir::State::Lists="$apt_dir/lists" -o Dir::Cache="$apt_dir/cache" \
        -o APT::Sandbox::User=root "$@"
}

apt_get update >>"$log" 2>&1 || fail "apt-get update of the deb-src entries failed"

mkdir -p "$src/download"
for pair in libsdl2:SDL2 libsdl2-gfx:SDL2_gfx libsdl2-image:SDL2_image; do
    package=${pair%%:*}
    name=${pair#*:}
    rm -rf "${src:?}/$name"
    # apt-get verifies each file against the signed index; a file it cannot
    # fetch is reported and the rest is kept.
    (cd "$src/download" && apt_get source --download-only "$package") >>"$log" 2>&1 || true
    dsc=$(ls -t "$src/download/${package}_"*.dsc 2>/dev/null | head -n 1)
    [ -n "$dsc" ] || fail "apt-get could not fetch the source package $package"
    if dpkg-source -x "$dsc" "$src/$name" >>"$log" 2>&1; then
        echo "make web: $name from Debian's source package $(basename "$dsc" .dsc)"
        continue
    fi
    # The Debian part (packaging and patches) missing: the upstream
    # tarball alone, checked against the .dsc's SHA-256.
    orig=$(awk '/^Checksums-Sha256:/ {on = 1; next} /^[^ ]/ {on = 0} on && $3 ~ /\.orig\.tar\./ {print $1 " " $3}' "$dsc")
    [ -n "$orig" ] || fail "$dsc names no upstream tarball"
    sum=${orig%% *}
    file=${orig#* }
    [ -f "$src/download/$file" ] || fail "apt-get could not fetch $file"
    echo "$sum  $src/download/$file" | sha256sum -c - >>"$log" 2>&1 ||
        fail "$file does not match the SHA-256 in $(basename "$dsc")"
    mkdir -p "$src/$name"
    tar -xf "$src/download/$file" -C "$src/$name" --strip-components=1 ||
        fail "cannot unpack $file"
    echo "make web: $name from the upstream tarball of Debian's $(basename "$dsc" .dsc)" \
        "(its Debian patches could not be fetched)"
done
