#include "draw/video.h"
#include <SDL2_gfxPrimitives.h>
#include <SDL_image.h>
#include <stdio.h>
#include <string.h>
#include "core/layout.h"
#ifdef __EMSCRIPTEN__
#include "web/web.h"
#endif

/* The canvas is the window's own surface when there is a window (no copy
 * before it is shown), else a surface of ours. */
static bool make_canvas(video_t *video, int width, int height) {
    /* SDL2_gfx caches its font glyphs as textures of the renderer it first
     * drew with; drop them before that renderer goes. */
    gfxPrimitivesSetFont(NULL, 0, 0);
    if (video->renderer != NULL) SDL_DestroyRenderer(video->renderer);
    if (video->canvas != NULL && video->window == NULL) SDL_FreeSurface(video->canvas);
    video->renderer = NULL;
    video->canvas = NULL;
    if (video->window != NULL) {
        video->canvas = SDL_GetWindowSurface(video->window);
    } else {
        video->canvas =
            SDL_CreateRGBSurfaceWithFormat(0, width, height, 32, SDL_PIXELFORMAT_ARGB8888);
    }
    if (video->canvas == NULL) {
        fprintf(stderr, "sandbox: cannot make a %dx%d canvas: %s\n", width, height,
                SDL_GetError());
        return false;
    }
    video->renderer = SDL_CreateSoftwareRenderer(video->canvas);
    if (video->renderer == NULL) {
        fprintf(stderr, "sandbox: cannot make a software renderer: %s\n", SDL_GetError());
        return false;
    }
    video->width = video->canvas->w;
    video->height = video->canvas->h;
    return true;
}

bool video_open(video_t *video, bool headless, bool gpu, bool vsync, int width, int height) {
    *video = (video_t){0};
    video->refresh_hz = 60.0;
    if (headless) return make_canvas(video, width, height);

    if (!gpu) {
        /* The canvas goes to the window as the system's own framebuffer (on
         * X11 a shared-memory image). By default SDL may instead upload it as
         * a texture through an OpenGL renderer, which without a GPU (Mesa's
         * software GL, e.g. on Xvfb) took 9 ms a frame against 0.3 ms. The
         * environment variable SDL_FRAMEBUFFER_ACCELERATION still wins. */
        SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    }
    video->window = SDL_CreateWindow("sandbox - 2D rigid bodies (H: help)", SDL_WINDOWPOS_CENTERED,
                                     SDL_WINDOWPOS_CENTERED, width, height, SDL_WINDOW_RESIZABLE);
    if (video->window == NULL) {
        fprintf(stderr, "sandbox: cannot open a window: %s (no display? try --headless)\n",
                SDL_GetError());
        return false;
    }
    /* The side bar and the whole container need this much (layout.h). */
    SDL_SetWindowMinimumSize(video->window, LAYOUT_MIN_WIDTH, LAYOUT_MIN_HEIGHT);
    SDL_DisplayMode mode;
    if (SDL_GetWindowDisplayMode(video->window, &mode) == 0 && mode.refresh_rate > 0) {
        video->refresh_hz = mode.refresh_rate;
    }
    if (gpu) {
        Uint32 flags = SDL_RENDERER_ACCELERATED | (vsync ? SDL_RENDERER_PRESENTVSYNC : 0);
        video->renderer = SDL_CreateRenderer(video->window, -1, flags);
        if (video->renderer != NULL) {
            SDL_RendererInfo info;
            SDL_GetRendererInfo(video->renderer, &info);
            video->vsync = (info.flags & SDL_RENDERER_PRESENTVSYNC) != 0;
            SDL_GetRendererOutputSize(video->renderer, &video->width, &video->height);
            return true;
        }
        fprintf(stderr, "sandbox: no accelerated renderer (%s); drawing in software\n",
                SDL_GetError());
    }
    SDL_GetWindowSize(video->window, &width, &height);
    return make_canvas(video, width, height);
}

/* The smallest window the side bar fits (layout.h): nothing holds a window
 * to its minimum without a window manager, so the app does. */
static void at_least_minimum(int *width, int *height) {
    if (*width < LAYOUT_MIN_WIDTH) *width = LAYOUT_MIN_WIDTH;
    if (*height < LAYOUT_MIN_HEIGHT) *height = LAYOUT_MIN_HEIGHT;
}

bool video_request_size(video_t *video, int width, int height) {
    at_least_minimum(&width, &height);
    if (width > 8192) width = 8192;
    if (height > 8192) height = 8192;
    if (video->window != NULL) {
        SDL_SetWindowSize(video->window, width, height);
        return false;
    }
    if (width == video->width && height == video->height) return false;
    return make_canvas(video, width, height);
}

bool video_sync_size(video_t *video) {
    if (video->window == NULL) return false;
    int width, height;
    if (video->canvas == NULL) {
        if (SDL_GetRendererOutputSize(video->renderer, &width, &height) != 0) return false;
        bool changed = width != video->width || height != video->height;
        video->width = width;
        video->height = height;
        return changed;
    }
    SDL_GetWindowSize(video->window, &width, &height);
    if (width == video->width && height == video->height) return false;
    if (width < 1 || height < 1) return false;
    int least_w = width, least_h = height;
    at_least_minimum(&least_w, &least_h);
    if (least_w != width || least_h != height) {
        /* Too small for the side bar: grow back (followed at a later frame). */
        SDL_SetWindowSize(video->window, least_w, least_h);
        return false;
    }
    if (!make_canvas(video, width, height)) {
        fprintf(stderr, "sandbox: cannot follow the window's new size\n");
        return false;
    }
    return true;
}

static bool ends_with(const char *text, const char *suffix) {
    size_t n = strlen(text), m = strlen(suffix);
    return n > m && SDL_strcasecmp(text + n - m, suffix) == 0;
}

video_format_t video_format_of(const char *path) {
    if (ends_with(path, ".png")) return VIDEO_FORMAT_PNG;
    if (ends_with(path, ".bmp")) return VIDEO_FORMAT_BMP;
    return VIDEO_FORMAT_NONE;
}

/* SDL_image's PNG writer, or SDL's BMP writer; 0 on success. */
static int save_surface(SDL_Surface *shot, const char *path) {
    switch (video_format_of(path)) {
    case VIDEO_FORMAT_PNG: return IMG_SavePNG(shot, path);
    case VIDEO_FORMAT_BMP: return SDL_SaveBMP(shot, path);
    case VIDEO_FORMAT_NONE: break;
    }
    SDL_SetError("%s", VIDEO_FORMAT_HINT);
    return -1;
}

bool video_screenshot(video_t *video, const char *path) {
    SDL_Surface *shot =
        SDL_CreateRGBSurfaceWithFormat(0, video->width, video->height, 24, SDL_PIXELFORMAT_BGR24);
    if (shot == NULL) {
        fprintf(stderr, "sandbox: cannot make the screenshot surface: %s\n", SDL_GetError());
        return false;
    }
    bool ok = SDL_RenderReadPixels(video->renderer, NULL, shot->format->format, shot->pixels,
                                   shot->pitch) == 0;
    if (!ok) {
        fprintf(stderr, "sandbox: cannot read the frame's pixels: %s\n", SDL_GetError());
    } else if (save_surface(shot, path) != 0) {
        fprintf(stderr, "sandbox: cannot save the screenshot '%s': %s\n", path, SDL_GetError());
        ok = false;
    } else {
#ifdef __EMSCRIPTEN__
        web_offer_file(path); /* a page's files live in memory: the browser downloads it */
#endif
    }
    SDL_FreeSurface(shot);
    return ok;
}

void video_present(video_t *video) {
    SDL_RenderPresent(video->renderer);
    if (video->window != NULL && video->canvas != NULL) SDL_UpdateWindowSurface(video->window);
}

void video_close(video_t *video) {
    gfxPrimitivesSetFont(NULL, 0, 0);
    if (video->renderer) SDL_DestroyRenderer(video->renderer);
    if (video->canvas && video->window == NULL) SDL_FreeSurface(video->canvas);
    if (video->window) SDL_DestroyWindow(video->window);
    *video = (video_t){0};
}
