# SDL2, SDL2_gfx and SDL2_image compiled for WebAssembly from the Debian
# source packages app/web/debian_sources.sh unpacked into $(WEB)/src (run by
# app/web/web.mk once they are there, so that the wildcards see them).
#
# SDL2 uses its own configuration for Emscripten (include/SDL_config.h picks
# SDL_config_emscripten.h): the Emscripten video driver, no threads. Every
# file of the folders that configuration draws on is compiled; a backend it
# does not enable compiles to nothing. SDL2_gfx: its primitives and font, and the rotation they use for text.
# SDL2_image: the PNG writer alone, through its bundled miniz (no libpng).

WEB ?= build/web
EMCC ?= emcc
EMAR ?= emar
SDL := $(WEB)/src/SDL2
GFX := $(WEB)/src/SDL2_gfx
IMG := $(WEB)/src/SDL2_image

SDL_DIRS := . atomic audio audio/emscripten audio/disk audio/dummy cpuinfo dynapi events file \
	filesystem/emscripten haptic haptic/dummy hidapi joystick joystick/emscripten libm \
	loadso/dlopen locale locale/emscripten misc misc/emscripten power power/emscripten render \
	render/software render/opengles2 sensor sensor/dummy stdlib thread thread/generic timer \
	timer/unix video video/emscripten video/dummy video/offscreen video/yuv2rgb
SDL_SRC := $(foreach d,$(SDL_DIRS),$(wildcard $(SDL)/src/$(d)/*.c))
SDL_OBJ := $(patsubst $(SDL)/src/%.c,$(WEB)/sdl/%.o,$(SDL_SRC))

# Third-party code at its own warning level: -w.
LIB_CFLAGS := -O2 -w

.PHONY: libs
libs: $(WEB)/libSDL2.a $(WEB)/libSDL2_gfx.a $(WEB)/libSDL2_image.a
	@:

$(WEB)/sdl/%.o: $(SDL)/src/%.c
	@mkdir -p $(dir $@)
	@$(EMCC) $(LIB_CFLAGS) -I$(SDL)/include -c $< -o $@

$(WEB)/libSDL2.a: $(SDL_OBJ)
	@rm -f $@
	@$(EMAR) rcs $@ $^
	@echo "make web: built $@ ($(words $^) files of SDL2)"

$(WEB)/gfx/%.o: $(GFX)/%.c
	@mkdir -p $(dir $@)
	@$(EMCC) $(LIB_CFLAGS) -I$(SDL)/include -c $< -o $@

$(WEB)/libSDL2_gfx.a: $(WEB)/gfx/SDL2_gfxPrimitives.o $(WEB)/gfx/SDL2_rotozoom.o
	@rm -f $@
	@$(EMAR) rcs $@ $^

$(WEB)/img/%.o: $(IMG)/%.c
	@mkdir -p $(dir $@)
	@$(EMCC) $(LIB_CFLAGS) -DUSE_STBIMAGE -I$(SDL)/include -c $< -o $@

$(WEB)/libSDL2_image.a: $(WEB)/img/IMG_png.o
	@rm -f $@
	@$(EMAR) rcs $@ $^
