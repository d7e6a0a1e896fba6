#ifndef APP_IMAGE_H
#define APP_IMAGE_H

/*
 * Screenshots for the sandbox's smoke tests: reading BMP (SDL_SaveBMP) and
 * PNG (libpng) files, counting colours in a region, finding a line of text
 * drawn in SDL2_gfx's 8x8 font (the one the app draws every word with), and
 * comparing two pictures pixel by pixel.
 */

#include <stdbool.h>
#include <stddef.h>

typedef struct {
    int width, height;
    unsigned char *rgb; /* top row first, 3 bytes a pixel */
} image_t;

/* Reads a BMP or PNG file (by its first bytes); false and a reason in why. */
bool image_read(const char *path, image_t *image, char *why, size_t why_size);
void image_free(image_t *image);

const unsigned char *image_pixel(const image_t *image, int x, int y);

typedef bool (*image_color_test_t)(const unsigned char *rgb);

/* Pixels passing test in [x0, x1) x [y0, y1), clipped to the image. */
long image_count(const image_t *image, image_color_test_t test, int x0, int y0, int x1, int y1);

/* The bounding box of the pixels passing test; false when there is none. */
bool image_bounds(const image_t *image, image_color_test_t test, int *x0, int *y0, int *x1,
                  int *y1);

/* Where text is drawn in the 8x8 font, in one colour, top-left corner in
 * [x0, x1) x [y0, y1): true and the corner and colour (may be NULL) when
 * found. A set bit of a glyph must be exactly that colour; a clear bit must
 * be any other colour. */
bool image_find_text(const image_t *image, const char *text, int x0, int y0, int x1, int y1,
                     int *at_x, int *at_y, unsigned char color[3]);

/* The same for text drawn `scale` times as large (each bit of a glyph a
 * scale x scale square). */
bool image_find_scaled_text(const image_t *image, const char *text, int scale, int x0, int y0,
                            int x1, int y1, int *at_x, int *at_y, unsigned char color[3]);

/* The text drawn in colour c from (x, y) on, a character every 8 pixels,
 * into out (at most max characters, trailing spaces dropped). */
void image_read_text(const image_t *image, int x, int y, const unsigned char c[3], char *out,
                     size_t max);

/* Pixels where some channel differs by more than `tolerance`; -1 when the
 * sizes differ. When diff_path is not NULL, writes a BMP there showing them
 * in red over a dimmed copy of a. */
long image_diff(const image_t *a, const image_t *b, int tolerance, const char *diff_path);

#endif
