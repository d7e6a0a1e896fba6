# make web        the sandbox as one web page, build/web/sandbox.html (docs/web.md)
# make check-web  that page in headless Chromium, against the native build
# make web-bench  its figures in docs/bench.md; make web-picture  docs/web.png
#
# The engine and the app compiled with Debian's Emscripten (package
# emscripten) against SDL2, SDL2_gfx and SDL2_image built for WebAssembly
# from Debian's source packages (app/web/debian_sources.sh, app/web/libs.mk).
# Included by the top Makefile.

WEB := build/web
# Debian's emcc runs node with Debian's JavaScript modules (node-acorn), which
# a Node.js from elsewhere does not look for by itself.
WEB_ENV := NODE_PATH=/usr/share/nodejs$(if $(NODE_PATH),:$(NODE_PATH))
EMCC := $(WEB_ENV) emcc
EMAR := $(WEB_ENV) emar
WEB_APT := emscripten dpkg-dev
WEB_CHECK_APT := chromium

# 128-bit SIMD (the engine's four-lane batches become pairs of f64x2).
WEB_OPT := -O2 -msimd128
WEB_SDL_INC := -isystem $(WEB)/src/SDL2/include -isystem $(WEB)/src/SDL2_gfx \
	-isystem $(WEB)/src/SDL2_image
WEB_LIBS := $(WEB)/libSDL2_image.a $(WEB)/libSDL2_gfx.a $(WEB)/libSDL2.a

WEB_ENGINE_OBJ := $(patsubst engine/src/%.c,$(WEB)/engine/%.o,$(ENGINE_SRC)) \
	$(patsubst engine/scenefile/%.c,$(WEB)/scenefile/%.o,$(SCENEFILE_SRC))
WEB_APP_SRC := $(APP_SRC) $(wildcard app/web/*.c)
WEB_APP_OBJ := $(patsubst app/%.c,$(WEB)/app/%.o,$(WEB_APP_SRC)) \
	$(patsubst app/games/%.c,$(WEB)/app/games/%.o,$(GAMES_SRC))

# One page: the WebAssembly and the JavaScript inside the HTML (SINGLE_FILE),
# the presets inside the WebAssembly's data (opened as assets/scenes/, as in
# the tree). Asyncify lets the frame loop hand each frame to the browser
# and go on where it was: only main waits (calling web_frame_done; SDL_Delay
# is told to spin instead, app/web/web.c), so nothing else is rewritten.
WEB_LDFLAGS := -sSINGLE_FILE=1 -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=67108864 \
	-sASYNCIFY=1 -sASYNCIFY_ONLY=main \
	-sASYNCIFY_STACK_SIZE=65536 -sENVIRONMENT=web \
	-sEXPORTED_FUNCTIONS=_main,_web_open_file -sEXPORTED_RUNTIME_METHODS=ccall,FS \
	--embed-file assets/scenes@/assets/scenes

.PHONY: web check-web web-deps web-check-deps web-libs

# Installs emscripten (and dpkg-dev, to unpack source packages) when emcc is
# missing, as make run does for SDL2: as root, quietly, log in build/apt.log.
web-deps:
	@$(call web_install,emcc dpkg-source,$(WEB_APT),the compiler to WebAssembly)

web-check-deps: web-deps
	@$(call web_install,chromium,$(WEB_CHECK_APT),a browser to test the page in)

# $(call web_install,COMMANDS,PACKAGES,WHY): installs PACKAGES unless every
# one of COMMANDS is there.
web_install = if ! (for c in $(1); do command -v $$c >/dev/null 2>&1 || exit 1; done); then \
	    if [ "$$(id -u)" = 0 ]; then \
	        mkdir -p build; \
	        echo "make web: installing $(2) ($(3)) with apt-get; log in build/apt.log"; \
	        if DEBIAN_FRONTEND=noninteractive apt-get -qq update >build/apt.log 2>&1 && \
	           DEBIAN_FRONTEND=noninteractive apt-get -qq install -y --no-install-recommends $(2) >>build/apt.log 2>&1; then \
	            echo "make web: installed."; \
	        else \
	            tail -n 20 build/apt.log; echo "make web: apt-get failed (build/apt.log has the whole log)"; exit 1; \
	        fi; \
	    else \
	        echo "make web needs $(2) ($(3)). Install them with:"; \
	        echo "    sudo apt-get install -y $(2)"; \
	        echo "then run 'make web' again."; \
	        exit 1; \
	    fi; \
	fi

# The source packages, fetched once (rm -rf build/web/src to fetch again).
$(WEB)/src/.fetched: app/web/debian_sources.sh | web-deps
	@app/web/debian_sources.sh $(WEB)
	@touch $@

web-libs: $(WEB)/src/.fetched
	@$(MAKE) --no-print-directory -f app/web/libs.mk WEB=$(WEB) EMCC="$(EMCC)" EMAR="$(EMAR)" libs

$(WEB_LIBS): web-libs
	@:

$(WEB)/engine/%.o: engine/src/%.c $(ENGINE_HDR) app/web/web.mk | web-deps
	@mkdir -p $(dir $@)
	$(EMCC) $(CSTD) $(WARN) $(WEB_OPT) $(ENGINE_INC) -c $< -o $@

$(WEB)/scenefile/%.o: engine/scenefile/%.c $(SCENEFILE_HDR) app/web/web.mk | web-deps
	@mkdir -p $(dir $@)
	$(EMCC) $(CSTD) $(WARN) $(WEB_OPT) -Iengine/include -c $< -o $@

$(WEB)/app/games/%.o: app/games/%.c $(GAMES_HDR) $(wildcard engine/include/jostle/*.h) app/web/web.mk \
		| web-deps
	@mkdir -p $(dir $@)
	$(EMCC) $(CSTD) $(WARN) $(WEB_OPT) -Iengine/include -c $< -o $@

$(WEB)/app/%.o: app/%.c $(APP_HDR) $(wildcard app/web/*.h) $(wildcard engine/include/jostle/*.h) \
		app/web/web.mk | $(WEB)/src/.fetched
	@mkdir -p $(dir $@)
	$(EMCC) $(CSTD) $(WARN) $(WEB_OPT) -Iapp -Iengine/include -Iapp/games $(WEB_SDL_INC) -c $< -o $@

# emcc links the JavaScript (with the WebAssembly in it); the page is the
# shell with that script in place of its {{{ SCRIPT }}} line. (Emscripten
# 3.1.6 writes HTML itself only through an HTML minifier call that fails.)
$(WEB)/sandbox.js: $(WEB_APP_OBJ) $(WEB_ENGINE_OBJ) $(WEB_LIBS) $(wildcard assets/scenes/*.scene)
	$(EMCC) $(WEB_OPT) $(WEB_LDFLAGS) $(WEB_APP_OBJ) $(WEB_ENGINE_OBJ) $(WEB_LIBS) -o $@

$(WEB)/sandbox.html: $(WEB)/sandbox.js app/web/shell.html
	$(call web_page,$<,app/web/shell.html,$@)
	@echo "make web: $@ ($$(du -k $@ | cut -f1) KiB): open it in a browser, e.g. chromium $@"

web: $(WEB)/sandbox.html

# $(call web_page,SCRIPT.js,SHELL.html,PAGE.html): the shell with the script
# in place of its {{{ SCRIPT }}} line.
define web_page
	@if grep -q '</script' $(1); then echo "make web: $(1) holds '</script'"; exit 1; fi
	@{ echo '<script>'; cat $(1); echo '</script>'; } > $(3).script
	@sed -e '/{{{ SCRIPT }}}/{r $(3).script' -e 'd}' $(2) > $(3)
	@rm -f $(3).script
endef

# The figures of docs/bench.md: bench_engine (tests/bench/) as a page, with
# the engine's 128-bit SIMD and without, against the native build, in
# headless Chromium (tests/web/bench_web.sh).
WEB_BENCH_LDFLAGS := -sSINGLE_FILE=1 -sALLOW_MEMORY_GROWTH=1 -sINITIAL_MEMORY=67108864 \
	-sENVIRONMENT=web
WEB_BENCH_OBJ_simd := $(patsubst engine/src/%.c,$(WEB)/engine/%.o,$(ENGINE_SRC))
WEB_BENCH_OBJ_scalar := $(patsubst engine/src/%.c,$(WEB)/scalar/%.o,$(ENGINE_SRC))
$(WEB)/scalar/%.o: engine/src/%.c $(ENGINE_HDR) app/web/web.mk | web-deps
	@mkdir -p $(dir $@)
	$(EMCC) $(CSTD) $(WARN) -O2 $(ENGINE_INC) -c $< -o $@
$(WEB)/bench_engine-simd.js: $(WEB_BENCH_OBJ_simd)
$(WEB)/bench_engine-scalar.js: $(WEB_BENCH_OBJ_scalar)
$(WEB)/bench_engine-%.js: tests/bench/bench_engine.c $(BENCH_HDR)
	$(EMCC) $(CSTD) $(WARN) -O2 $(if $(filter simd,$*),-msimd128) -Iengine/include \
	    -DBENCH_ENGINE_VERSION='"web-$*"' $(WEB_BENCH_LDFLAGS) $< $(WEB_BENCH_OBJ_$*) -o $@
$(WEB)/bench_engine-%.html: $(WEB)/bench_engine-%.js tests/web/bench_shell.html
	$(call web_page,$<,tests/web/bench_shell.html,$@)

# docs/web.png: the page in headless Chromium running app/scripts/demo.txt,
# the script of docs/sandbox.png, with the page's bar above it: its quit
# replaced by a pause, and the picture taken once the script logs that.
.PHONY: web-picture
web-picture: web-check-deps $(WEB)/sandbox.html
	script=$$({ grep -v '^quit$$' app/scripts/demo.txt; printf 'key space\nlog\nwait 600s\n'; } | node -e \
	    'process.stdout.write(encodeURIComponent(require("fs").readFileSync(0, "utf8")))') && \
	node tests/web/browse.js --size 1280x753 --screenshot docs/web.png --timeout 120 --until "state:" \
	    --url "file://$$(pwd)/$(WEB)/sandbox.html?args=--headless+--elasticity+0.4&script=$$script" >/dev/null
	@echo "make web-picture: docs/web.png"

.PHONY: web-bench web-bench-pages
web-bench: web-bench-pages
	sh tests/web/bench_web.sh

# What make web-bench measures, built: `nice make web-bench-pages` then
# `sh tests/web/bench_web.sh` keeps the builds at low priority and the
# measured runs at the normal one.
web-bench-pages: web-check-deps $(WEB)/sandbox.html $(WEB)/bench_engine-simd.html \
		$(WEB)/bench_engine-scalar.html build/bench/bench_engine

# The page in headless Chromium beside the native build
# (tests/web/web_check.c). make check runs it too, and builds the page for
# it, when emcc, chromium and node are installed and SDL2 for WebAssembly
# is built (make web builds it once, about 6 minutes on 2 cores: too long
# for every make check of a fresh clone); otherwise it says it skipped its
# tests in one line.
WEB_CHECK_SRC := tests/web/web_check.c tests/app_run.c tests/app_image.c app/core/layout.c
build/tests/web_check: $(WEB_CHECK_SRC) tests/app_run.h tests/app_image.h tests/app_expect.h app/core/layout.h \
		app/draw/palette.h app/web/web.mk
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O1 -g $(SAN) $(APP_SMOKE_DEFS) -Iapp -Itests $(WEB_CHECK_SRC) \
	    $(APP_SMOKE_LIBS) -lm -o $@
CHECK_PROGRAMS += build/tests/web_check
WEB_TOOLS := $(shell for c in emcc chromium node; do command -v $$c >/dev/null 2>&1 || exit 1; done \
	&& echo yes)
ifeq ($(WEB_TOOLS)$(SANDBOX_HAVE_SDL)$(wildcard $(WEB)/libSDL2.a),yesyes$(WEB)/libSDL2.a)
check: $(WEB)/sandbox.html
endif

check-web: web-check-deps sandbox-deps
	@$(MAKE) --no-print-directory sandbox build/tests/web_check $(WEB)/sandbox.html
	build/tests/web_check
