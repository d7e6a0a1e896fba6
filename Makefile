# make            the library (build/libjostle.a, build/libjostle.so) and, when SDL2 is there, ./sandbox
# make check      builds and runs every test (sanitized, warnings are errors)
# make run        installs the sandbox's Debian packages when it can, builds and starts it
# make install    headers, libraries, jostle.pc, the sandbox and its scenes under PREFIX (and DESTDIR)
# make bench      the benchmark scenes (docs/bench.md)
# make report     numerical error against run time (docs/accuracy.md)
# make stability  stiff and extreme cases beside theory and the peers (docs/stability.md)
# make tsan       the threaded tests (scene_set_workers) under ThreadSanitizer
# make house      docs/house.png: the engine's files by layer, drawn from tests/check_house.sh
# make web        the sandbox as one web page, build/web/sandbox.html (docs/web.md)

# Every build uses all cores unless the command line says otherwise (make -j1).
ifeq ($(filter -j%,$(MAKEFLAGS)),)
MAKEFLAGS += -j$(shell nproc 2>/dev/null || echo 2)
endif

CC ?= cc
CSTD := -std=c11 -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE
WARN := -Wall -Wextra -Werror -Wshadow -Wstrict-prototypes
OPT := -O2 -g
SAN := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined

# The library's version, from its umbrella header (docs/api.md, "Headers and
# versions"): the soname carries the major number.
JOSTLE_VERSION := $(shell awk '/define JOSTLE_VERSION_(MAJOR|MINOR|PATCH)/ {printf "%s%s", sep, $$3; sep = "."}' engine/include/jostle/jostle.h)
JOSTLE_MAJOR := $(firstword $(subst ., ,$(JOSTLE_VERSION)))

# engine/src/LAYER/*.c, the layers listed lowest first in engine/src/LAYERS;
# sources include public headers as "jostle/X.h" and private ones as
# "LAYER/X.h".
ENGINE_INC := -Iengine/include -Iengine/src
ENGINE_SRC := $(wildcard engine/src/*/*.c)
ENGINE_HDR := $(wildcard engine/include/*.h engine/include/jostle/*.h engine/src/*/*.h)
ENGINE_OBJ := $(patsubst engine/src/%.c,build/engine/%.o,$(ENGINE_SRC))
ENGINE_SAN_OBJ := $(patsubst engine/src/%.c,build/engine-san/%.o,$(ENGINE_SRC))
ENGINE_PIC_OBJ := $(patsubst engine/src/%.c,build/engine-pic/%.o,$(ENGINE_SRC))

# Scene files (engine/scenefile/, docs/scenes.md): built on the public API only,
# and archived into the engine's libraries.
SCENEFILE_SRC := $(wildcard engine/scenefile/*.c)
SCENEFILE_HDR := $(wildcard engine/include/jostle/*.h engine/scenefile/*.h)
ENGINE_OBJ += $(patsubst engine/scenefile/%.c,build/scenefile/%.o,$(SCENEFILE_SRC))
ENGINE_SAN_OBJ += $(patsubst engine/scenefile/%.c,build/scenefile-san/%.o,$(SCENEFILE_SRC))
ENGINE_PIC_OBJ += $(patsubst engine/scenefile/%.c,build/scenefile-pic/%.o,$(SCENEFILE_SRC))

# Game rules for scene files (app/games/): no SDL, so the tests link them.
GAMES_SRC := $(wildcard app/games/*.c)
GAMES_HDR := $(wildcard app/games/*.h)
GAMES_SAN_OBJ := $(patsubst app/games/%.c,build/games-san/%.o,$(GAMES_SRC))

TEST_SRC := $(wildcard tests/test_*.c) tests/test.c tests/main.c tests/reference.c \
	tests/scene_file_check.c
TEST_SAN_OBJ := $(patsubst tests/%.c,build/tests/%.o,$(TEST_SRC))

.PHONY: all check clean tsan install uninstall
all: build/libjostle.a build/libjostle.so

build/engine/%.o: engine/src/%.c $(ENGINE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) $(OPT) $(ENGINE_INC) -c $< -o $@

build/libjostle.a: $(ENGINE_OBJ)
	@rm -f $@
	ar rcs $@ $^

build/engine-san/%.o: engine/src/%.c $(ENGINE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O1 -g $(SAN) $(ENGINE_INC) -c $< -o $@

build/libjostle-san.a: $(ENGINE_SAN_OBJ)
	@rm -f $@
	ar rcs $@ $^

# The shared library: position-independent objects, and only what the public
# headers declare exported (they set default visibility; the rest is hidden).
build/engine-pic/%.o: engine/src/%.c $(ENGINE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) $(OPT) -fPIC -fvisibility=hidden $(ENGINE_INC) -c $< -o $@

build/libjostle.so: $(ENGINE_PIC_OBJ) engine/jostle.map
	$(CC) -shared -Wl,-soname,libjostle.so.$(JOSTLE_MAJOR) -Wl,--version-script=engine/jostle.map \
	    $(ENGINE_PIC_OBJ) -pthread -lm -o $@

build/scenefile/%.o: engine/scenefile/%.c $(SCENEFILE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) $(OPT) -Iengine/include -c $< -o $@

build/scenefile-san/%.o: engine/scenefile/%.c $(SCENEFILE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O1 -g $(SAN) -Iengine/include -c $< -o $@

build/scenefile-pic/%.o: engine/scenefile/%.c $(SCENEFILE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) $(OPT) -fPIC -fvisibility=hidden -Iengine/include -c $< -o $@

build/games-san/%.o: app/games/%.c $(GAMES_HDR) $(ENGINE_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O1 -g $(SAN) -Iengine/include -c $< -o $@

build/tests/%.o: tests/%.c tests/test.h tests/suites.h tests/reference.h tests/scene_file_check.h \
		$(ENGINE_HDR) $(GAMES_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O1 -g $(SAN) -Iengine/include -Iengine/src -Itests -Iapp/games -c $< -o $@

build/tests/engine_tests: $(TEST_SAN_OBJ) $(GAMES_SAN_OBJ) build/libjostle-san.a
	$(CC) $(SAN) $^ -pthread -lm -o $@

# Programs `make check` runs; app/app.mk adds the sandbox's smoke tests.
# check_examples.sh builds tests/examples/ (and the README's example) against
# the release library with the public headers only; check_house.sh reads the
# release objects for circles and calls up the layers; check_install.sh
# installs into a temporary DESTDIR and builds the examples with pkg-config.
CHECK_PROGRAMS := build/tests/engine_tests tests/check_examples.sh tests/report/check_report.sh \
	tests/check_house.sh tests/check_install.sh

-include app/app.mk
-include app/web/web.mk
-include tests/bench/bench.mk
-include tests/report/report.mk
-include tests/fuzz/fuzz.mk
-include tests/stability/stability.mk

check: $(CHECK_PROGRAMS) build/libjostle.a build/libjostle.so build/report/accuracy
	@tests/run_all.sh $(CHECK_PROGRAMS)

# make tsan: the test program built with ThreadSanitizer (whole, so the
# engine's threads and the tests' calls are seen together), running the
# suites that step scenes on several workers; any race report fails it.
TSAN := -fsanitize=thread -fno-omit-frame-pointer
TSAN_SUITES ?= workers
build/tsan/engine_tests: $(ENGINE_SRC) $(SCENEFILE_SRC) $(GAMES_SRC) $(TEST_SRC) $(ENGINE_HDR) \
		$(SCENEFILE_HDR) $(GAMES_HDR) tests/test.h tests/suites.h
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O1 -g $(TSAN) -Iengine/include -Iengine/src -Itests -Iapp/games \
		$(ENGINE_SRC) $(SCENEFILE_SRC) $(GAMES_SRC) $(TEST_SRC) -pthread -lm -o $@

tsan: build/tsan/engine_tests
	@for suite in $(TSAN_SUITES); do \
		TSAN_OPTIONS="halt_on_error=1 exitcode=66 second_deadlock_stack=1" \
			build/tsan/engine_tests $$suite || exit 1; \
	done

# make house: docs/house.png, the engine's house (which file uses which, by
# layer) drawn from tests/check_house.sh --dot with Graphviz's dot; and
# docs/pipeline.png from docs/pipeline.dot. Both need the Debian package
# graphviz, which graphviz-deps installs quietly when it is missing.
GRAPHVIZ_APT := graphviz
.PHONY: house graphviz-deps
graphviz-deps:
	@if ! command -v dot >/dev/null 2>&1; then \
	    if [ "$$(id -u)" = 0 ]; then \
	        mkdir -p build; \
	        echo "make: installing $(GRAPHVIZ_APT) (dot, which draws the docs' diagrams) with apt-get; log in build/apt.log"; \
	        if DEBIAN_FRONTEND=noninteractive apt-get -qq update >build/apt.log 2>&1 && \
	           DEBIAN_FRONTEND=noninteractive apt-get -qq install -y --no-install-recommends $(GRAPHVIZ_APT) >>build/apt.log 2>&1; then \
	            echo "make: installed."; \
	        else \
	            tail -n 20 build/apt.log; echo "make: apt-get failed (build/apt.log has the whole log)"; exit 1; \
	        fi; \
	    else \
	        echo "The diagrams need Graphviz's dot. Install it with:"; \
	        echo "    sudo apt-get install -y $(GRAPHVIZ_APT)"; \
	        exit 1; \
	    fi; \
	fi

house: graphviz-deps build/libjostle.a
	tests/check_house.sh --dot > build/house.dot
	dot -Tpng build/house.dot -o docs/house.png

docs/pipeline.png: docs/pipeline.dot | graphviz-deps
	dot -Tpng $< -o $@

# make install: the public headers (PREFIX/include/jostle/), the static and
# shared libraries with its soname link (PREFIX/lib/), jostle.pc
# (PREFIX/lib/pkgconfig/), and, when SDL2 is there, the sandbox as
# PREFIX/bin/jostle-sandbox with its scenes in PREFIX/share/jostle/scenes/.
# DESTDIR stages it all elsewhere (packaging, tests/check_install.sh).
PREFIX ?= /usr/local
INSTALL_ROOT = $(DESTDIR)$(PREFIX)
SONAME := libjostle.so.$(JOSTLE_MAJOR)
build/jostle.pc: engine/jostle.pc.in engine/include/jostle/jostle.h
	@mkdir -p $(dir $@)
	sed -e 's|@PREFIX@|$(PREFIX)|' -e 's|@VERSION@|$(JOSTLE_VERSION)|' $< > $@

# The .pc file names PREFIX: made anew for each install.
.PHONY: build/jostle.pc
install: build/libjostle.a build/libjostle.so build/jostle.pc $(INSTALL_SANDBOX)
	install -d $(INSTALL_ROOT)/include/jostle $(INSTALL_ROOT)/lib/pkgconfig
	install -m 644 engine/include/jostle/*.h $(INSTALL_ROOT)/include/jostle/
	install -m 644 build/libjostle.a $(INSTALL_ROOT)/lib/
	install -m 755 build/libjostle.so $(INSTALL_ROOT)/lib/libjostle.so.$(JOSTLE_VERSION)
	ln -sf libjostle.so.$(JOSTLE_VERSION) $(INSTALL_ROOT)/lib/$(SONAME)
	ln -sf $(SONAME) $(INSTALL_ROOT)/lib/libjostle.so
	install -m 644 build/jostle.pc $(INSTALL_ROOT)/lib/pkgconfig/
	@if [ -n "$(INSTALL_SANDBOX)" ]; then \
	    install -d $(INSTALL_ROOT)/bin $(INSTALL_ROOT)/share/jostle/scenes && \
	    install -m 755 sandbox $(INSTALL_ROOT)/bin/jostle-sandbox && \
	    install -m 644 assets/scenes/*.scene $(INSTALL_ROOT)/share/jostle/scenes/; \
	fi

uninstall:
	rm -rf $(INSTALL_ROOT)/include/jostle $(INSTALL_ROOT)/share/jostle
	rm -f $(INSTALL_ROOT)/lib/libjostle.a $(INSTALL_ROOT)/lib/libjostle.so \
	    $(INSTALL_ROOT)/lib/$(SONAME) $(INSTALL_ROOT)/lib/libjostle.so.$(JOSTLE_VERSION) \
	    $(INSTALL_ROOT)/lib/pkgconfig/jostle.pc $(INSTALL_ROOT)/bin/jostle-sandbox

clean:
	rm -rf build sandbox
