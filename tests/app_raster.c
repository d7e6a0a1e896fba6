/*
 * The sandbox's scan converter (app/raster.c) splits a large batch over two
 * threads, each drawing its own rows: it must write the very pixels one
 * thread writes. Draws batches of overlapping outlined polygons and arrows,
 * crowded at the bottom as a pile is (where the split row goes), into a
 * software canvas both ways and compares them byte for byte. Needs SDL2
 * (built only when the sandbox is); no window.
 * Ends with "N passed, N failed" like every test program make check runs.
 */
#include <SDL.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "app_expect.h"
#include "draw/batch.h"
#include "draw/raster.h"

enum { WIDTH = 640, HEIGHT = 480 };

static unsigned long long random_state;

static double uniform(void) {
    random_state = random_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(random_state >> 11) / 9007199254740992.0;
}

/* count polygons of 3 to 8 sides, a quarter of them arrows, most in the
 * bottom third; some cross the canvas's edges. */
static void fill_batch(batch_t *batch, size_t count) {
    random_state = 7;
    for (size_t i = 0; i < count; i++) {
        double y = uniform() < 0.8 ? HEIGHT * (0.6 + 0.45 * uniform()) : HEIGHT * uniform();
        vector_t centre = {WIDTH * (1.1 * uniform() - 0.05), y};
        palette_rgb_t fill = {(unsigned char)(40 * (i % 6)), 200, (unsigned char)(i % 251)};
        palette_rgb_t edge = {255, (unsigned char)(i % 200), 0};
        if (i % 4 == 0) {
            vector_t head = {centre.x + 60.0 * (uniform() - 0.5), centre.y + 60.0 * (uniform() - 0.5)};
            batch_arrow(batch, centre, head, fill, 255, 2);
            continue;
        }
        int sides = 3 + (int)(i % 6);
        double radius = 3.0 + 12.0 * uniform(), turn = 2.0 * M_PI * uniform();
        vector_t pixels[8];
        for (int k = 0; k < sides; k++) {
            double angle = turn + 2.0 * M_PI * k / sides;
            pixels[k] = (vector_t){centre.x + radius * cos(angle), centre.y + radius * sin(angle)};
        }
        batch_outlined(batch, pixels, sides, fill, edge);
    }
}

static SDL_Surface *draw(const batch_t *batch, bool split) {
    SDL_Surface *canvas = SDL_CreateRGBSurfaceWithFormat(0, WIDTH, HEIGHT, 32,
                                                         SDL_PIXELFORMAT_ARGB8888);
    SDL_Renderer *renderer = canvas != NULL ? SDL_CreateSoftwareRenderer(canvas) : NULL;
    if (renderer == NULL) {
        app_fail("no software canvas: %s", SDL_GetError());
        if (canvas != NULL) SDL_FreeSurface(canvas);
        return NULL;
    }
    SDL_FillRect(canvas, NULL, 0);
    raster_set_split(split);
    raster_begin(renderer, canvas);
    raster_batch(batch);
    SDL_DestroyRenderer(renderer);
    return canvas;
}

static size_t lit_pixels(const SDL_Surface *canvas) {
    size_t lit = 0;
    for (int y = 0; y < canvas->h; y++) {
        const Uint32 *row = (const Uint32 *)((const Uint8 *)canvas->pixels + y * canvas->pitch);
        for (int x = 0; x < canvas->w; x++) lit += row[x] != 0;
    }
    return lit;
}

static void compare(size_t count) {
    batch_t batch = {0};
    fill_batch(&batch, count);
    SDL_Surface *one = draw(&batch, false), *two = draw(&batch, true);
    if (one != NULL && two != NULL) {
        size_t differing = 0;
        for (int y = 0; y < HEIGHT; y++) {
            const Uint8 *a = (const Uint8 *)one->pixels + y * one->pitch;
            const Uint8 *b = (const Uint8 *)two->pixels + y * two->pitch;
            if (memcmp(a, b, (size_t)WIDTH * 4) != 0) differing++;
        }
        EXPECT(differing == 0, "%zu polygons: %zu rows differ between one thread and two",
               count, differing);
        size_t lit = lit_pixels(one);
        EXPECT(lit > 20 * count, "%zu polygons lit only %zu pixels", count, lit);
    }
    if (one != NULL) SDL_FreeSurface(one);
    if (two != NULL) SDL_FreeSurface(two);
    batch_free(&batch);
}

static void two_threads_draw_the_pixels_of_one(void) {
    compare(3000);
}

/* Small batches stay on one thread; still the same pixels. */
static void a_small_batch_draws_the_same(void) {
    compare(200);
}

static const app_test_t TESTS[] = {
    {"raster.two_threads_draw_the_pixels_of_one", two_threads_draw_the_pixels_of_one},
    {"raster.a_small_batch_draws_the_same", a_small_batch_draws_the_same},
};

int main(void) {
    int status = app_run_tests(TESTS, sizeof(TESTS) / sizeof(TESTS[0]), NULL);
    raster_free();
    return status;
}
