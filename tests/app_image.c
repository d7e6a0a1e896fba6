#include "app_image.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef APP_SMOKE_HAVE_SDL
#define APP_SMOKE_HAVE_SDL 0
#endif

#if APP_SMOKE_HAVE_SDL
/* The app's font, and libpng (which SDL2_image's Debian package brings). */
#include <SDL2_gfxPrimitives_font.h>
#include <png.h>
#else
/* Without SDL the sandbox is not built and every smoke test is skipped;
 * these stand-ins only let the program build. */
static const unsigned char gfxPrimitivesFontdata[8 * 256];
#endif

static bool failed(char *why, size_t n, const char *path, const char *problem) {
    snprintf(why, n, "%s: %s", path, problem);
    return false;
}

static uint32_t le32(const unsigned char *p) {
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* An uncompressed 24- or 32-bit BMP (what SDL_SaveBMP writes). */
static bool read_bmp(const char *path, const unsigned char *data, size_t size, image_t *image,
                     char *why, size_t n) {
    if (size < 54) return failed(why, n, path, "too short for a BMP");
    uint32_t offset = le32(data + 10);
    int32_t width = (int32_t)le32(data + 18), height = (int32_t)le32(data + 22);
    int bpp = data[28] | data[29] << 8;
    uint32_t compression = le32(data + 30);
    bool top_down = height < 0;
    if (top_down) height = -height;
    size_t stride = ((size_t)width * (size_t)(bpp / 8) + 3) & ~(size_t)3;
    if ((bpp != 24 && bpp != 32) || (compression != 0 && compression != 3) || width <= 0 ||
        height <= 0 || offset + stride * (size_t)height > size) {
        return failed(why, n, path, "unsupported BMP (not 24 or 32 bits uncompressed)");
    }
    image->width = width;
    image->height = height;
    image->rgb = malloc((size_t)width * (size_t)height * 3);
    for (int y = 0; y < height; y++) {
        const unsigned char *row = data + offset + stride * (size_t)(top_down ? y : height - 1 - y);
        for (int x = 0; x < width; x++) {
            const unsigned char *p = row + (size_t)x * (size_t)(bpp / 8);
            unsigned char *q = image->rgb + ((size_t)y * (size_t)width + (size_t)x) * 3;
            q[0] = p[2];
            q[1] = p[1];
            q[2] = p[0];
        }
    }
    return true;
}

/* Any PNG, through libpng's simplified reader, as 8-bit RGB. */
static bool read_png(const char *path, const unsigned char *data, size_t size, image_t *image,
                     char *why, size_t n) {
#if !APP_SMOKE_HAVE_SDL
    (void)data;
    (void)size;
    (void)image;
    return failed(why, n, path, "built without libpng");
#else
    png_image png;
    memset(&png, 0, sizeof(png));
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&png, data, size)) {
        return failed(why, n, path, png.message);
    }
    png.format = PNG_FORMAT_RGB;
    image->width = (int)png.width;
    image->height = (int)png.height;
    image->rgb = malloc(PNG_IMAGE_SIZE(png));
    if (image->rgb == NULL || !png_image_finish_read(&png, NULL, image->rgb, 0, NULL)) {
        failed(why, n, path, image->rgb == NULL ? "out of memory" : png.message);
        free(image->rgb);
        image->rgb = NULL;
        png_image_free(&png);
        return false;
    }
    return true;
#endif
}

bool image_read(const char *path, image_t *image, char *why, size_t why_size) {
    *image = (image_t){0, 0, NULL};
    FILE *file = fopen(path, "rb");
    if (file == NULL) return failed(why, why_size, path, "cannot open it");
    fseek(file, 0, SEEK_END);
    long size = ftell(file);
    fseek(file, 0, SEEK_SET);
    unsigned char *data = size > 8 ? malloc((size_t)size) : NULL;
    bool ok = data != NULL && fread(data, 1, (size_t)size, file) == (size_t)size;
    fclose(file);
    if (!ok) {
        free(data);
        return failed(why, why_size, path, "cannot read it (or it is empty)");
    }
    static const unsigned char PNG_SIGNATURE[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (memcmp(data, PNG_SIGNATURE, 8) == 0) {
        ok = read_png(path, data, (size_t)size, image, why, why_size);
    } else if (data[0] == 'B' && data[1] == 'M') {
        ok = read_bmp(path, data, (size_t)size, image, why, why_size);
    } else {
        ok = failed(why, why_size, path, "neither a PNG nor a BMP file");
    }
    free(data);
    return ok;
}

void image_free(image_t *image) {
    free(image->rgb);
    image->rgb = NULL;
}

const unsigned char *image_pixel(const image_t *image, int x, int y) {
    return image->rgb + ((size_t)y * (size_t)image->width + (size_t)x) * 3;
}

static void clip(const image_t *image, int *x0, int *y0, int *x1, int *y1) {
    if (*x0 < 0) *x0 = 0;
    if (*y0 < 0) *y0 = 0;
    if (*x1 > image->width) *x1 = image->width;
    if (*y1 > image->height) *y1 = image->height;
}

long image_count(const image_t *image, image_color_test_t test, int x0, int y0, int x1, int y1) {
    clip(image, &x0, &y0, &x1, &y1);
    long count = 0;
    for (int y = y0; y < y1; y++) {
        for (int x = x0; x < x1; x++) count += test(image_pixel(image, x, y));
    }
    return count;
}

bool image_bounds(const image_t *image, image_color_test_t test, int *x0, int *y0, int *x1,
                  int *y1) {
    bool any = false;
    for (int y = 0; y < image->height; y++) {
        for (int x = 0; x < image->width; x++) {
            if (!test(image_pixel(image, x, y))) continue;
            if (!any || x < *x0) *x0 = x;
            if (!any || x > *x1) *x1 = x;
            if (!any) *y0 = y;
            *y1 = y;
            any = true;
        }
    }
    return any;
}

static bool same(const unsigned char *a, const unsigned char *b) {
    return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

/* Whether text is drawn at (x, y) in colour c, each bit of its glyphs a
 * scale x scale square. */
static bool scaled_text_at(const image_t *image, const char *text, int scale, int x, int y,
                           const unsigned char *c) {
    size_t length = strlen(text);
    if (x + 8 * scale * (int)length > image->width || y + 8 * scale > image->height) return false;
    for (size_t i = 0; i < length; i++) {
        const unsigned char *glyph = gfxPrimitivesFontdata + 8 * (unsigned char)text[i];
        for (int row = 0; row < 8 * scale; row++) {
            for (int col = 0; col < 8 * scale; col++) {
                bool set = (glyph[row / scale] & (0x80 >> (col / scale))) != 0;
                const unsigned char *p =
                    image_pixel(image, x + 8 * scale * (int)i + col, y + row);
                if (set != same(p, c)) return false;
            }
        }
    }
    return true;
}

static bool text_at(const image_t *image, const char *text, int x, int y,
                    const unsigned char *c) {
    return scaled_text_at(image, text, 1, x, y, c);
}

bool image_find_text(const image_t *image, const char *text, int x0, int y0, int x1, int y1,
                     int *at_x, int *at_y, unsigned char color[3]) {
    return image_find_scaled_text(image, text, 1, x0, y0, x1, y1, at_x, at_y, color);
}

bool image_find_scaled_text(const image_t *image, const char *text, int scale, int x0, int y0,
                            int x1, int y1, int *at_x, int *at_y, unsigned char color[3]) {
    /* The first set bit of the text gives the colour to match. */
    int first_row = -1, first_col = -1, first_char = -1;
    for (int i = 0; text[i] != '\0' && first_char < 0; i++) {
        const unsigned char *glyph = gfxPrimitivesFontdata + 8 * (unsigned char)text[i];
        for (int bit = 0; bit < 64 && first_char < 0; bit++) {
            if (glyph[bit / 8] & (0x80 >> (bit % 8))) {
                first_char = i;
                first_row = bit / 8;
                first_col = bit % 8;
            }
        }
    }
    if (first_char < 0) return false;
    clip(image, &x0, &y0, &x1, &y1);
    for (int y = y0; y < y1; y++) {
        for (int x = x0; x < x1; x++) {
            int px = x + scale * (8 * first_char + first_col), py = y + scale * first_row;
            if (px >= image->width || py >= image->height) continue;
            const unsigned char *c = image_pixel(image, px, py);
            if (!scaled_text_at(image, text, scale, x, y, c)) continue;
            if (at_x != NULL) *at_x = x;
            if (at_y != NULL) *at_y = y;
            if (color != NULL) memcpy(color, c, 3);
            return true;
        }
    }
    return false;
}

void image_read_text(const image_t *image, int x, int y, const unsigned char c[3], char *out,
                     size_t max) {
    size_t n = 0;
    for (; n < max; n++, x += 8) {
        char found = '\0';
        char glyph[2] = {0, 0};
        for (int ch = 32; ch < 127 && found == '\0'; ch++) {
            glyph[0] = (char)ch;
            if (text_at(image, glyph, x, y, c)) found = (char)ch;
        }
        if (found == '\0') break;
        out[n] = found;
    }
    while (n > 0 && out[n - 1] == ' ') n--;
    out[n] = '\0';
}

static void put16(FILE *f, unsigned v) {
    fputc((int)(v & 0xff), f);
    fputc((int)(v >> 8 & 0xff), f);
}

static void put32(FILE *f, uint32_t v) {
    put16(f, v & 0xffff);
    put16(f, v >> 16);
}

/* A 24-bit bottom-up BMP. */
static void write_bmp(const char *path, const image_t *image) {
    FILE *f = fopen(path, "wb");
    if (f == NULL) return;
    uint32_t stride = ((uint32_t)image->width * 3 + 3) & ~3u;
    uint32_t data_size = stride * (uint32_t)image->height;
    fputc('B', f);
    fputc('M', f);
    put32(f, 54 + data_size);
    put32(f, 0);
    put32(f, 54);
    put32(f, 40);
    put32(f, (uint32_t)image->width);
    put32(f, (uint32_t)image->height);
    put16(f, 1);
    put16(f, 24);
    for (int i = 0; i < 6; i++) put32(f, 0);
    for (int y = image->height - 1; y >= 0; y--) {
        for (int x = 0; x < image->width; x++) {
            const unsigned char *p = image_pixel(image, x, y);
            fputc(p[2], f);
            fputc(p[1], f);
            fputc(p[0], f);
        }
        for (uint32_t pad = (uint32_t)image->width * 3; pad < stride; pad++) fputc(0, f);
    }
    fclose(f);
}

long image_diff(const image_t *a, const image_t *b, int tolerance, const char *diff_path) {
    if (a->width != b->width || a->height != b->height) return -1;
    image_t diff = {a->width, a->height, malloc((size_t)a->width * (size_t)a->height * 3)};
    long count = 0;
    for (int y = 0; y < a->height; y++) {
        for (int x = 0; x < a->width; x++) {
            const unsigned char *p = image_pixel(a, x, y), *q = image_pixel(b, x, y);
            bool differs = false;
            for (int k = 0; k < 3; k++) differs = differs || abs(p[k] - q[k]) > tolerance;
            count += differs;
            if (diff.rgb == NULL) continue;
            unsigned char *d = diff.rgb + ((size_t)y * (size_t)a->width + (size_t)x) * 3;
            for (int k = 0; k < 3; k++) d[k] = (unsigned char)(p[k] / 3);
            if (differs) {
                d[0] = 255;
                d[1] = 0;
                d[2] = 0;
            }
        }
    }
    if (diff_path != NULL && diff.rgb != NULL) write_bmp(diff_path, &diff);
    free(diff.rgb);
    return count;
}
