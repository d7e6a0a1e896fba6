#!/bin/sh
# Makes sure the headers of the engines bench-compare compares with are there:
# Chipmunk2D 7 and Box2D 2.4 (Debian: libchipmunk-dev libbox2d-dev). As root
# it installs the missing packages with apt-get; otherwise it prints the
# command to run and returns 0, so that bench-compare runs what it can.
CC=${CC:-cc}
CXX=${CXX:-c++}
missing=""
printf '#include <chipmunk/chipmunk.h>\n' | $CC -E -x c - >/dev/null 2>&1 || missing="$missing libchipmunk-dev"
printf '#include <box2d/box2d.h>\n' | $CXX -E -x c++ - >/dev/null 2>&1 || missing="$missing libbox2d-dev"
[ -z "$missing" ] && exit 0
command="apt-get install -y$missing"
if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "bench-compare: installing$missing"
    DEBIAN_FRONTEND=noninteractive $command ||
        { apt-get update && DEBIAN_FRONTEND=noninteractive $command; } ||
        echo "bench-compare: could not install$missing; comparing with what is there" >&2
else
    echo "bench-compare: missing$missing; to compare with them, run:" >&2
    echo "    sudo $command" >&2
    echo "bench-compare: comparing with what is there" >&2
fi
exit 0
