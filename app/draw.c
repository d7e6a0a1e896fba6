#include "draw.h"
#include "raster.h"
#include <SDL2_gfxPrimitives.h>
#include <SDL2_gfxPrimitives_font.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>

Sint16 draw_coord(double pixel) {
    if (!(pixel > -30000.0)) return -30000;
    if (pixel > 30000.0) return 30000;
    return (Sint16)lround(pixel);
}

void draw_arrow(SDL_Renderer *renderer, vector_t tail, vector_t head, palette_rgb_t color,
                Uint8 alpha, int width) {
    vector_t d = vec_subtract(head, tail);
    double length = vec_get_length(d);
    if (!(length >= 1.0) || alpha == 0) return;
    vector_t u = vec_multiply(1.0 / length, d);
    vector_t n = vec_perpendicular(u);
    double head_length = fmin(0.5 * length, 6.0 + 2.0 * width);
    double head_half = 0.55 * head_length;
    vector_t base = vec_subtract(head, vec_multiply(head_length, u));
    vector_t left = vec_add(base, vec_multiply(head_half, n));
    vector_t right = vec_subtract(base, vec_multiply(head_half, n));
    bool shaft = length - head_length >= 1.0;
    if (alpha == 255 && raster_direct()) {
        /* Opaque arrows (the axes: thousands in a pile) straight into the
         * canvas: the shaft as a thin quadrilateral, the head a triangle. */
        SDL_RenderFlush(renderer);
        if (shaft) {
            vector_t side = vec_multiply(0.5 * (width < 1 ? 1 : width), n);
            vector_t quad[4] = {vec_add(tail, side), vec_add(base, side),
                                vec_subtract(base, side), vec_subtract(tail, side)};
            raster_fill(quad, 4, color);
        }
        vector_t triangle[3] = {head, left, right};
        raster_fill(triangle, 3, color);
        return;
    }
    if (shaft && width <= 1) {
        lineRGBA(renderer, draw_coord(tail.x), draw_coord(tail.y), draw_coord(base.x),
                 draw_coord(base.y), color.r, color.g, color.b, alpha);
    } else if (shaft) {
        thickLineRGBA(renderer, draw_coord(tail.x), draw_coord(tail.y), draw_coord(base.x),
                      draw_coord(base.y), (Uint8)width, color.r, color.g, color.b, alpha);
    }
    filledTrigonRGBA(renderer, draw_coord(head.x), draw_coord(head.y), draw_coord(left.x),
                     draw_coord(left.y), draw_coord(right.x), draw_coord(right.y), color.r,
                     color.g, color.b, alpha);
}

static SDL_Surface *text_canvas;

void draw_set_canvas(SDL_Renderer *renderer, SDL_Surface *canvas) {
    text_canvas = canvas != NULL && canvas->format->BytesPerPixel == 4 ? canvas : NULL;
    if (text_canvas != NULL) SDL_RenderFlush(renderer);
}

/* SDL2_gfx's 8x8 font (the one stringRGBA draws), set straight into the
 * canvas: stringRGBA copies one cached texture per character through the
 * renderer, which took a sixth of a frame's drawing for the HUD. */
static void canvas_text(int x, int y, palette_rgb_t color, const char *text) {
    Uint32 pixel = SDL_MapRGB(text_canvas->format, color.r, color.g, color.b);
    int pitch = text_canvas->pitch / 4;
    for (; *text != '\0'; text++, x += 8) {
        if (x + 8 <= 0 || x >= text_canvas->w) continue;
        const unsigned char *glyph = gfxPrimitivesFontdata + 8 * (unsigned char)*text;
        for (int row = 0; row < 8; row++) {
            int py = y + row;
            if (py < 0 || py >= text_canvas->h || glyph[row] == 0) continue;
            Uint32 *line = (Uint32 *)text_canvas->pixels + (size_t)py * (size_t)pitch;
            for (int col = 0; col < 8; col++) {
                int px = x + col;
                if ((glyph[row] & (0x80 >> col)) && px >= 0 && px < text_canvas->w) {
                    line[px] = pixel;
                }
            }
        }
    }
}

void draw_text(SDL_Renderer *renderer, int x, int y, palette_rgb_t color, const char *format,
               ...) {
    char text[256];
    va_list args;
    va_start(args, format);
    vsnprintf(text, sizeof(text), format, args);
    va_end(args);
    if (text_canvas != NULL) {
        SDL_RenderFlush(renderer);
        canvas_text(x, y, color, text);
    } else {
        stringRGBA(renderer, draw_coord(x), draw_coord(y), text, color.r, color.g, color.b, 255);
    }
}

void draw_panel(SDL_Renderer *renderer, int x, int y, int w, int h, palette_rgb_t color,
                Uint8 alpha) {
    boxRGBA(renderer, draw_coord(x), draw_coord(y), draw_coord(x + w - 1), draw_coord(y + h - 1),
            color.r, color.g, color.b, alpha);
    rectangleRGBA(renderer, draw_coord(x), draw_coord(y), draw_coord(x + w - 1),
                  draw_coord(y + h - 1), 52, 56, 68, 255);
}
