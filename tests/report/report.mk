# make report: numerical error against run time (docs/accuracy.md), by
# tests/report/report.sh. Included by the top-level Makefile.

REPORT_DIR := build/report
REPORT_SRC := $(wildcard tests/report/*.c) tests/reference.c
REPORT_HDR := $(wildcard tests/report/*.h) tests/reference.h
REPORT_CFLAGS := $(CSTD) $(WARN) -O2

$(REPORT_DIR)/accuracy: $(REPORT_SRC) $(REPORT_HDR) build/libjostle.a
	@mkdir -p $(dir $@)
	$(CC) $(REPORT_CFLAGS) -Iengine/include -Itests -Itests/report $(REPORT_SRC) \
		build/libjostle.a -pthread -lm -o $@

.PHONY: report report-deps
# gnuplot (Debian gnuplot-nox) and the peers' headers, installed as root when
# missing; otherwise the command to run is printed and the report stops.
report-deps:
	@command -v gnuplot >/dev/null 2>&1 || { \
		if [ "$$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then \
			echo "report: installing gnuplot-nox"; \
			DEBIAN_FRONTEND=noninteractive apt-get install -y gnuplot-nox || \
			{ apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y gnuplot-nox; }; \
		else \
			echo "report: gnuplot is missing; run: sudo apt-get install -y gnuplot-nox" >&2; exit 1; \
		fi; }
	@CC="$(CC)" CXX="$(CXX)" sh tests/bench/deps.sh

report: report-deps build/libjostle.a $(REPORT_DIR)/accuracy
	@$(MAKE) --no-print-directory bench-build
	@CC="$(CC)" PROVENANCE_FLAGS="$(REPORT_CFLAGS)" sh tests/report/report.sh
