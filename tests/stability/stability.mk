# make stability: numerical stability on stiff and extreme cases beside theory
# and beside Chipmunk2D and Box2D 2.4 (docs/stability.md), by
# tests/stability/stability.sh. Included by the top-level Makefile after
# tests/bench/bench.mk; `make check` runs the --quick version of the suite
# (tests/stability/check_stability.sh), which asserts every verdict.

STABILITY_DIR := build/stability

$(STABILITY_DIR)/stability: tests/stability/stability.c tests/stability/theory.h \
		tests/stability/extreme_cases.h $(BENCH_HDR) \
		build/libjostle.a
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O2 -Iengine/include -Itests/bench -Itests/stability \
		-DBENCH_ENGINE_VERSION='"$(BENCH_ENGINE_VERSION)"' $< build/libjostle.a -pthread -lm -o $@

CHECK_PROGRAMS += tests/stability/check_stability.sh
check: $(STABILITY_DIR)/stability

.PHONY: stability
# The peers' programs are built when their headers are there (installed as
# root when missing, tests/bench/deps.sh); without them the peers' columns
# say "not run".
stability: build/libjostle.a $(STABILITY_DIR)/stability
	@CC="$(CC)" CXX="$(CXX)" sh tests/bench/deps.sh
	@$(MAKE) --no-print-directory bench-build
	@tests/provenance.sh begin $(STABILITY_DIR)/provenance.state
	@sh tests/stability/stability.sh
	@CC="$(CC)" PROVENANCE_FLAGS="$(CSTD) $(WARN) -O2" \
		tests/provenance.sh stamp docs/stability.md $(STABILITY_DIR)/provenance.state
