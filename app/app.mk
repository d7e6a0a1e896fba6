# The SDL2 + SDL2_gfx + SDL2_image sandbox (app/) and its smoke tests
# (tests/app_smoke.c). Included by the top Makefile. `make` builds ./sandbox
# when pkg-config finds the three libraries; without them `make` still builds
# the engine, and the smoke tests build without SDL and report themselves
# skipped. SDL2_image writes the PNG screenshots (IMG_SavePNG).

SANDBOX_PKGS := sdl2 SDL2_gfx SDL2_image
SANDBOX_APT := libsdl2-dev libsdl2-gfx-dev libsdl2-image-dev pkg-config
SANDBOX_HAVE_SDL := $(shell pkg-config --exists $(SANDBOX_PKGS) 2>/dev/null && echo yes)

# app/main.c and the folders of app/ (app/README.md says what each owns);
# sources include each other's headers as "FOLDER/X.h" from app/.
APP_DIRS := scene core draw input panels tools
APP_SRC := app/main.c $(foreach d,$(APP_DIRS),$(wildcard app/$(d)/*.c))
APP_HDR := $(foreach d,$(APP_DIRS),$(wildcard app/$(d)/*.h)) $(GAMES_HDR)
APP_OBJ := $(patsubst app/%.c,build/app/%.o,$(APP_SRC))
# The game rules (app/games/, no SDL), which the tests link too.
APP_GAMES_OBJ := $(patsubst app/games/%.c,build/app/games/%.o,$(GAMES_SRC))

.PHONY: run sandbox-deps

ifeq ($(SANDBOX_HAVE_SDL),yes)
# SDL's headers as system headers, so that -Werror judges our code only.
SANDBOX_CFLAGS := $(patsubst -I%,-isystem %,$(shell pkg-config --cflags $(SANDBOX_PKGS)))
SANDBOX_LIBS := $(shell pkg-config --libs $(SANDBOX_PKGS))

all: sandbox

build/app/games/%.o: app/games/%.c $(GAMES_HDR) $(wildcard engine/include/jostle/*.h) app/app.mk
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) $(OPT) -Iengine/include -c $< -o $@

build/app/%.o: app/%.c $(APP_HDR) $(wildcard engine/include/jostle/*.h) app/app.mk
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) $(OPT) -Iengine/include -Iapp -Iapp/games $(SANDBOX_CFLAGS) -c $< -o $@

sandbox: $(APP_OBJ) $(APP_GAMES_OBJ) build/libjostle.a
	$(CC) $(APP_OBJ) $(APP_GAMES_OBJ) build/libjostle.a $(SANDBOX_LIBS) -pthread -lm -o $@

APP_SMOKE_DEPS := sandbox
INSTALL_SANDBOX := sandbox

# The scan converter's two threads against one (tests/app_raster.c): SDL2
# only, no window.
APP_RASTER_SRC := tests/app_raster.c app/draw/raster.c app/draw/batch.c app/core/job_thread.c
build/tests/app_raster: $(APP_RASTER_SRC) tests/app_expect.h app/draw/raster.h app/draw/batch.h \
                        app/core/job_thread.h app/draw/palette.h app/app.mk
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O1 -g $(SAN) -Iapp -Iengine/include $(SANDBOX_CFLAGS) \
	    $(APP_RASTER_SRC) $(SANDBOX_LIBS) -pthread -lm -o $@
CHECK_PROGRAMS += build/tests/app_raster
# The smoke tests read the app's 8x8 font (SDL2_gfx's header) to find text in
# screenshots, and PNG files with libpng (a dependency of libsdl2-image-dev).
APP_SMOKE_DEFS := -DAPP_SMOKE_HAVE_SDL=1 \
    $(patsubst -I%,-isystem %,$(shell pkg-config --cflags SDL2_gfx libpng))
APP_SMOKE_LIBS := $(shell pkg-config --libs libpng)
else
sandbox:
	@echo "sandbox: SDL2, SDL2_gfx or SDL2_image was not found by pkg-config ($(SANDBOX_PKGS))."
	@echo "Install them with: sudo apt-get install -y $(SANDBOX_APT)   (or run: make run)"
	@exit 1

APP_SMOKE_DEPS :=
APP_SMOKE_DEFS := -DAPP_SMOKE_HAVE_SDL=0
APP_SMOKE_LIBS :=
endif

# The app's plain-C parts (no SDL: text, the side bar's lines, the step
# clock, the layout, the energy drift, the integrators by name, the list of
# scenes, the SCENE panel's words, the sandbox's scenes with the game rules,
# the geometry batch, a round body's outline, the state a script logs),
# tested directly against the sanitized engine; they build and run without
# SDL.
APP_UNIT_SRC := tests/app_units.c app/panels/text.c app/panels/stats_text.c app/core/step_clock.c \
                app/core/layout.c app/core/energy_drift.c app/scene/integrator_choice.c \
                app/scene/samples.c app/panels/scene_text.c app/scene/sandbox_scene.c app/draw/batch.c \
                app/core/frame_meter.c app/draw/focus.c app/core/stage_chart.c app/core/plot.c \
                app/scene/state_log.c app/draw/round_outline.c
build/tests/app_units: $(APP_UNIT_SRC) tests/app_expect.h $(APP_HDR) app/app.mk \
                       build/libjostle-san.a $(GAMES_SAN_OBJ)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O1 -g $(SAN) -Iapp -Iapp/games -Iengine/include $(APP_UNIT_SRC) \
	    $(GAMES_SAN_OBJ) build/libjostle-san.a -pthread -lm -o $@

# The smoke tests drive ./sandbox from outside and read its screenshots; they
# link no SDL, but the sanitized engine, to load the scene files the sandbox
# saves (scene_file_load), and the list of presets.
APP_SMOKE_SRC := tests/app_smoke.c tests/app_smoke_edges.c tests/app_smoke_learn.c tests/app_run.c \
                 tests/app_image.c \
                 app/core/layout.c app/scene/samples.c
build/tests/app_smoke: $(APP_SMOKE_SRC) tests/app_run.h tests/app_image.h tests/app_expect.h app/draw/palette.h \
                       app/core/layout.h app/scene/samples.h app/app.mk build/libjostle-san.a $(APP_SMOKE_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(WARN) -O1 -g $(SAN) $(APP_SMOKE_DEFS) -Iapp -Itests -Iengine/include \
	    $(APP_SMOKE_SRC) build/libjostle-san.a $(APP_SMOKE_LIBS) -pthread -lm -o $@

CHECK_PROGRAMS += build/tests/app_units build/tests/app_smoke

# Installs the Debian packages when they are missing (as root; otherwise it
# prints the command), quietly: one line says what and why, apt's output goes
# to build/apt.log and is shown only when it fails.
sandbox-deps:
	@if ! pkg-config --exists $(SANDBOX_PKGS) 2>/dev/null; then \
	    if [ "$$(id -u)" = 0 ]; then \
	        mkdir -p build; \
	        echo "make run: installing $(SANDBOX_APT) (the sandbox's window, drawing and screenshots) with apt-get; log in build/apt.log"; \
	        if DEBIAN_FRONTEND=noninteractive apt-get -qq update >build/apt.log 2>&1 && \
	           DEBIAN_FRONTEND=noninteractive apt-get -qq install -y --no-install-recommends $(SANDBOX_APT) >>build/apt.log 2>&1; then \
	            echo "make run: installed."; \
	        else \
	            tail -n 20 build/apt.log; echo "make run: apt-get failed (build/apt.log has the whole log)"; exit 1; \
	        fi; \
	    else \
	        echo "The sandbox needs SDL2, SDL2_gfx and SDL2_image. Install them with:"; \
	        echo "    sudo apt-get install -y $(SANDBOX_APT)"; \
	        echo "then run 'make run' again."; \
	        exit 1; \
	    fi; \
	fi

run: sandbox-deps
	@$(MAKE) --no-print-directory sandbox
	./sandbox
