# Benchmarks of the canonical scenes (docs/bench-scenes.md, docs/bench.md).
# Included by the top-level Makefile; nothing here is part of `make check`.
#
#   make bench          builds build/bench/bench_engine and runs the benchmark set
#   make bench-compare  the same scenes on this engine, Box2D v3 (SSE2 and AVX2
#                       builds), Chipmunk2D 7 and Box2D 2.4.1 (Debian
#                       libchipmunk-dev libbox2d-dev), alternated over
#                       BENCH_ROUNDS rounds, pinned, in CPU time: each engine's
#                       ms per step (median and range) and this engine's over
#                       each other's (tests/bench/alternate.sh)
#   make bench-report   writes docs/bench.md from one such run, with the
#                       instructions per step, the sleeping pile and the
#                       quality figures over the layout seeds (tens of minutes;
#                       run it on an idle machine)
#   make bench-joints   the joints section of docs/bench.md alone (jointchain
#                       and ragdolls: this engine, Box2D v3 SSE2 and Chipmunk2D
#                       when built; a few minutes), the rest of the page kept
#   make bench-instructions  instructions per step under callgrind
#                       (BENCH_INSTRUCTIONS="pile:1000 pyramid:20")
#   make bench-build    builds whichever of the programs can be built
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
BENCH_HDR := tests/bench/bench_common.h tests/bench/bench_scenes.h tests/bench/bench_ours.h \
	tests/bench/bench_joint_scenes.h
BENCH_CFLAGS := $(CSTD) $(WARN) -O2
BENCH_CXXFLAGS := -std=c++17 -Wall -Wextra -Werror -Wshadow -O2
# Recursive (=): evaluated only when a bench rule runs.
# The last commit that touched engine/, and -dirty when engine/ has changes since.
BENCH_ENGINE_VERSION = $(shell { git log -1 --format=%h -- engine 2>/dev/null || echo unknown; } | tr -d '\n'; git diff --quiet HEAD -- engine 2>/dev/null || echo -dirty)
BENCH_BOX2D_PACKAGE = $(shell dpkg-query -W -f='$${Version}' libbox2d-dev 2>/dev/null || echo unknown)
BENCH_HAVE_CHIPMUNK = $(shell printf '\043include <chipmunk/chipmunk.h>\n' | $(CC) -E -x c - >/dev/null 2>&1 && echo yes)
BENCH_HAVE_BOX2D = $(shell printf '\043include <box2d/box2d.h>\n' | $(CXX) -E -x c++ - >/dev/null 2>&1 && echo yes)

# Box2D v3: built from BOX2D3_DIR (a source tree: CMakeLists.txt, include/,
# src/) when set, else from the shared archive extracted into build/peers;
# left out, with a note, when neither is there. Its library is built with
# cmake (Release) into build/peers/box2d-sse2 and, when the CPU has AVX2,
# build/peers/box2d-avx2. Nothing of it enters the project.
BOX2D3_ARCHIVE ?= ../shared/peers/box2d-617d32ab.tar.gz
BOX2D3_DIR ?=
BOX2D3_EXTRACTED := build/peers/box2d-617d32ab
BOX2D3_TREE = $(if $(BOX2D3_DIR),$(BOX2D3_DIR),$(if $(wildcard $(BOX2D3_ARCHIVE)),$(BOX2D3_EXTRACTED)))
BOX2D3_BUILDS = $(if $(BOX2D3_TREE),sse2 $(if $(shell grep -qw avx2 /proc/cpuinfo 2>/dev/null && echo y),avx2))
BOX2D3_PROGRAMS = $(foreach b,$(BOX2D3_BUILDS),$(BENCH_DIR)/bench_box2d3-$(b))
BOX2D3_NOTE = $(if $(BOX2D3_TREE),,bench: Box2D v3 left out (set BOX2D3_DIR to its source, or put $(BOX2D3_ARCHIVE) back))

BENCH_PROGRAMS = $(BENCH_DIR)/bench_engine $(BOX2D3_PROGRAMS) \
	$(if $(BENCH_HAVE_CHIPMUNK),$(BENCH_DIR)/bench_chipmunk) \
	$(if $(BENCH_HAVE_BOX2D),$(BENCH_DIR)/bench_box2d)

.PHONY: bench bench-compare bench-compare-run bench-build bench-stages bench-scale bench-seeds \
	bench-report bench-report-run bench-instructions bench-joints

comma := ,
# Which program each variant of BENCH_VARIANTS belongs to (bench-instructions).
BENCH_VARIANT_PROGRAM_ours := bench_engine
BENCH_VARIANT_PROGRAM_box2d3-sse2 := bench_box2d3-sse2
BENCH_VARIANT_PROGRAM_box2d3-avx2 := bench_box2d3-avx2
BENCH_VARIANT_PROGRAM_chipmunk := bench_chipmunk
BENCH_VARIANT_PROGRAM_chipmunk-default := bench_chipmunk
BENCH_VARIANT_PROGRAM_box2d := bench_box2d
BENCH_VARIANT_PROGRAM_box2d-nosleep := bench_box2d
BENCH_VARIANT_PROGRAM_box2d-matched := bench_box2d

$(BENCH_DIR)/bench_engine: tests/bench/bench_engine.c $(BENCH_HDR) build/libjostle.a
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -Iengine/include -DBENCH_ENGINE_VERSION='"$(BENCH_ENGINE_VERSION)"' \
		$< build/libjostle.a -pthread -lm -o $@

$(BENCH_DIR)/bench_scale: tests/bench/bench_scale.c $(BENCH_HDR) build/libjostle.a
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -Iengine/include $< build/libjostle.a -lm -o $@

$(BENCH_DIR)/bench_chipmunk: tests/bench/bench_chipmunk.c $(BENCH_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) $< -lchipmunk -lm -o $@

$(BENCH_DIR)/bench_box2d: tests/bench/bench_box2d.cpp $(BENCH_HDR)
	@mkdir -p $(dir $@)
	$(CXX) $(BENCH_CXXFLAGS) -DBENCH_BOX2D_PACKAGE='"$(BENCH_BOX2D_PACKAGE)"' $< -lbox2d -lm -o $@

$(BOX2D3_EXTRACTED)/CMakeLists.txt: $(BOX2D3_ARCHIVE)
	@mkdir -p build/peers
	tar -xzf $< -C build/peers
	@touch $@

.PRECIOUS: build/peers/box2d-%/src/libbox2d.a
build/peers/box2d-%/src/libbox2d.a: $(BOX2D3_TREE)/CMakeLists.txt
	cmake -S $(BOX2D3_TREE) -B build/peers/box2d-$* -DCMAKE_BUILD_TYPE=Release \
		-DBOX2D_SAMPLES=OFF -DBOX2D_UNIT_TESTS=OFF -DBOX2D_BENCHMARKS=OFF -DBOX2D_DOCS=OFF \
		-DBOX2D_AVX2=$(if $(filter avx2,$*),ON,OFF) >build/peers/box2d-$*.cmake.log
	cmake --build build/peers/box2d-$* -j2 >>build/peers/box2d-$*.cmake.log

$(BENCH_DIR)/bench_box2d3-%: tests/bench/bench_box2d3.c $(BENCH_HDR) build/peers/box2d-%/src/libbox2d.a
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -I$(BOX2D3_TREE)/include -DBENCH_BOX2D3_BUILD='"$*"' $< \
		build/peers/box2d-$*/src/libbox2d.a -pthread -lm -o $@

bench: $(BENCH_DIR)/bench_engine
	$(BENCH_DIR)/bench_engine $(BENCH_ARGS)

bench-build: $(BENCH_PROGRAMS)
	@$(if $(BOX2D3_NOTE),echo "$(BOX2D3_NOTE)")

# The other engines' packages are installed first when missing (as root), so
# the programs to build are decided by a second make once they are there.
bench-compare: build/libjostle.a
	@CC="$(CC)" CXX="$(CXX)" sh tests/bench/deps.sh
	@$(MAKE) --no-print-directory bench-compare-run

# The variants compared: each peer at its defaults (sleeping off) and at the
# settings matched to this engine's (tests/bench/bench_*.c say which).
BENCH_ROUNDS ?= 5
BENCH_VARIANTS ?= ours,box2d3-sse2,box2d3-avx2,chipmunk,chipmunk-default,box2d-nosleep,box2d-matched
BENCH_INSTRUCTIONS ?= pile:1000 pyramid:20
export BENCH_ROUNDS BENCH_VARIANTS BENCH_INSTRUCTIONS BENCH_ARGS

bench-compare-run: $(BENCH_PROGRAMS)
	@$(if $(BOX2D3_NOTE),echo "$(BOX2D3_NOTE)")
	@sh tests/bench/alternate.sh -o $(BENCH_DIR)/compare.txt $(BENCH_ROUNDS) $(BENCH_PROGRAMS) \
		-- --variant $(BENCH_VARIANTS) $(BENCH_ARGS)
	@echo "(raw lines in $(BENCH_DIR)/compare.txt)"

bench-instructions: $(BENCH_PROGRAMS)
	@$(if $(BOX2D3_NOTE),echo "$(BOX2D3_NOTE)")
	sh tests/bench/instructions.sh -s "$(BENCH_INSTRUCTIONS)" \
		$(foreach p,$(BENCH_PROGRAMS),$(foreach v,$(subst $(comma), ,$(BENCH_VARIANTS)),$(if \
		$(filter $(notdir $(p)),$(BENCH_VARIANT_PROGRAM_$(v))),$(p):$(v))))

bench-report: build/libjostle.a
	@CC="$(CC)" CXX="$(CXX)" sh tests/bench/deps.sh
	@$(MAKE) --no-print-directory bench-report-run

bench-report-run: $(BENCH_PROGRAMS)
	@$(if $(BOX2D3_NOTE),echo "$(BOX2D3_NOTE)")
	@tests/provenance.sh begin build/bench/report.provenance
	BENCH_CFLAGS="$(BENCH_CFLAGS)" sh tests/bench/bench_report.sh docs/bench.md $(BENCH_PROGRAMS)
	@CC="$(CC)" PROVENANCE_FLAGS="$(BENCH_CFLAGS)" \
		tests/provenance.sh stamp docs/bench.md build/bench/report.provenance

# The joints section alone: only the programs it compares.
BENCH_JOINT_PROGRAMS = $(BENCH_DIR)/bench_engine $(if $(BOX2D3_TREE),$(BENCH_DIR)/bench_box2d3-sse2) \
	$(if $(BENCH_HAVE_CHIPMUNK),$(BENCH_DIR)/bench_chipmunk)
bench-joints: $(BENCH_JOINT_PROGRAMS)
	@$(if $(BOX2D3_NOTE),echo "$(BOX2D3_NOTE)")
	sh tests/bench/bench_report.sh --section joints docs/bench.md $(BENCH_JOINT_PROGRAMS)

# make bench-stages: what a scene pays for the stages it does not use
# (docs/leave-out.md, about a minute and a half).
$(BENCH_DIR)/bench_stages: tests/bench/bench_stages.c build/libjostle.a
	@mkdir -p $(dir $@)
	$(CC) $(BENCH_CFLAGS) -Iengine/include $< build/libjostle.a -pthread -lm -o $@

bench-stages: $(BENCH_DIR)/bench_stages
	@tests/provenance.sh begin build/bench/stages.provenance
	$(BENCH_DIR)/bench_stages docs/leave-out.md
	@CC="$(CC)" PROVENANCE_FLAGS="$(BENCH_CFLAGS)" \
		tests/provenance.sh stamp docs/leave-out.md build/bench/stages.provenance

# make check: the joint scenes on this engine hold their bounds and repeat
# bit for bit (tests/bench/check_joints.sh, a few seconds).
CHECK_PROGRAMS += tests/bench/check_joints.sh
check: $(BENCH_DIR)/bench_engine

# make check: the leave-out page's figures that are not timings (what each
# scene runs, bodies asleep) come out the same from the sources.
CHECK_PROGRAMS += tests/bench/check_stages.sh
check: $(BENCH_DIR)/bench_stages

bench-scale: $(BENCH_DIR)/bench_scale
	@$(MAKE) --no-print-directory bench-build
	@tests/provenance.sh begin build/bench/scale.provenance
	tests/bench/scale.sh docs/scale.md
	@CC="$(CC)" PROVENANCE_FLAGS="$(BENCH_CFLAGS)" \
		tests/provenance.sh stamp docs/scale.md build/bench/scale.provenance

SEEDS_ARGS ?=
bench-seeds: $(BENCH_DIR)/bench_engine
	sh tests/bench/seeds.sh $(SEEDS_ARGS) -o $(BENCH_DIR)/seeds.txt $(BENCH_DIR)/bench_engine >/dev/null
	sh tests/bench/seeds.sh --judge tests/bench/baseline-seeds.txt $(BENCH_DIR)/seeds.txt \
		$(wildcard tests/bench/v3-seeds.txt)
