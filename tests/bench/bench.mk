# Benchmarks of the canonical scenes (docs/bench-scenes.md, docs/bench.md).
# Included by the top-level Makefile; nothing here is part of `make check`.
#
#   make bench          builds build/bench/bench_engine and runs the benchmark set
#   make bench-compare  the same scenes on this engine, Chipmunk2D 7 and Box2D 2.4.1
#                       (Debian libchipmunk-dev libbox2d-dev), then a table of
#                       this engine's ms per step over each other engine's
#   make bench-build    builds whichever of the three programs can be built
#   make bench-stages   what a scene pays for the stages it leaves out (docs/leave-out.md)
#   make bench-scale    pile(N) from 1000 to 40000 bodies, with the peers (docs/scale.md)
#   make bench-seeds    this engine's quality figures over the 8 layout seeds
#                       (build/bench/seeds.txt), judged against
#                       tests/bench/baseline-seeds.txt (SEEDS_ARGS="--quick -j 2")
#
# Options for the programs: make bench BENCH_ARGS="--quick" or
# BENCH_ARGS="--scene pile --size 4000 --runs 3" (see tests/bench/bench_scenes.h).

BENCH_ARGS ?=
BENCH_DIR := build/bench
BENCH_HDR := tests/bench/bench_common.h tests/bench/bench_scenes.h tests/bench/bench_ours.h
BENCH_CFLAGS := $(CSTD) $(WARN) -O2
BENCH_CXXFLAGS := -std=c++17 -Wall -Wextra -Werror -Wshadow -O2
# Recursive (=): evaluated only when a bench rule runs.
# The last commit that touched engine/, and -dirty when engine/ has changes since.
BENCH_ENGINE_VERSION = $(shell { git log -1 --format=%h -- engine 2>/dev/null || echo unknown; } | tr -d '\n'; git diff --quiet HEAD -- engine 2>/dev/null || echo -dirty)
BENCH_BOX2D_PACKAGE = $(shell dpkg-query -W -f='$${Version}' libbox2d-dev 2>/dev/null || echo unknown)
BENCH_HAVE_CHIPMUNK = $(shell printf '\043include <chipmunk/chipmunk.h>\n' | $(CC) -E -x c - >/dev/null 2>&1 && echo yes)
BENCH_HAVE_BOX2D = $(shell printf '\043include <box2d/box2d.h>\n' | $(CXX) -E -x c++ - >/dev/null 2>&1 && echo yes)
BENCH_PROGRAMS = $(BENCH_DIR)/bench_engine \
	$(if $(BENCH_HAVE_CHIPMUNK),$(BENCH_DIR)/bench_chipmunk) \
	$(if $(BENCH_HAVE_BOX2D),$(BENCH_DIR)/bench_box2d)

.PHONY: bench bench-compare bench-compare-run bench-build bench-stages bench-scale bench-seeds

$(BENCH_DIR)/bench_engine: tests/bench/bench_engine.c $(BENCH_HDR) build/libengine.a
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -Iengine/include -DBENCH_ENGINE_VERSION='"$(BENCH_ENGINE_VERSION)"' \
		$< build/libengine.a -pthread -lm -o $@

$(BENCH_DIR)/bench_scale: tests/bench/bench_scale.c $(BENCH_HDR) build/libengine.a
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -Iengine/include $< build/libengine.a -lm -o $@

$(BENCH_DIR)/bench_chipmunk: tests/bench/bench_chipmunk.c $(BENCH_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) $< -lchipmunk -lm -o $@

$(BENCH_DIR)/bench_box2d: tests/bench/bench_box2d.cpp $(BENCH_HDR)
	@mkdir -p $(dir $@)
	$(CXX) $(BENCH_CXXFLAGS) -DBENCH_BOX2D_PACKAGE='"$(BENCH_BOX2D_PACKAGE)"' $< -lbox2d -lm -o $@

bench: $(BENCH_DIR)/bench_engine
	$(BENCH_DIR)/bench_engine $(BENCH_ARGS)

bench-build: $(BENCH_PROGRAMS)

# The other engines' packages are installed first when missing (as root), so
# the programs to build are decided by a second make once they are there.
bench-compare: build/libengine.a
	@CC="$(CC)" CXX="$(CXX)" sh tests/bench/deps.sh
	@$(MAKE) --no-print-directory bench-compare-run

bench-compare-run: $(BENCH_PROGRAMS)
	@sh tests/bench/compare.sh -o $(BENCH_DIR)/compare.txt $(BENCH_PROGRAMS) -- $(BENCH_ARGS)

# make bench-stages: what a scene pays for the stages it does not use
# (docs/leave-out.md, about a minute and a half).
$(BENCH_DIR)/bench_stages: tests/bench/bench_stages.c build/libengine.a
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -Iengine/include $< build/libengine.a -pthread -lm -o $@

bench-stages: $(BENCH_DIR)/bench_stages
	$(BENCH_DIR)/bench_stages docs/leave-out.md

bench-scale: $(BENCH_DIR)/bench_scale
	@$(MAKE) --no-print-directory bench-build
	tests/bench/scale.sh docs/scale.md

SEEDS_ARGS ?=
bench-seeds: $(BENCH_DIR)/bench_engine
	sh tests/bench/seeds.sh $(SEEDS_ARGS) -o $(BENCH_DIR)/seeds.txt $(BENCH_DIR)/bench_engine >/dev/null
	sh tests/bench/seeds.sh --judge tests/bench/baseline-seeds.txt $(BENCH_DIR)/seeds.txt \
		$(wildcard tests/bench/v3-seeds.txt)
