#include "draw/draw.h"
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

void draw_text_scaled(SDL_Renderer *renderer, int x, int y, int scale, palette_rgb_t color,
                      const char *text) {
    if (text_canvas != NULL) SDL_RenderFlush(renderer);
    Uint32 pixel =
        text_canvas != NULL ? SDL_MapRGB(text_canvas->format, color.r, color.g, color.b) : 0;
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    SDL_SetRenderDrawColor(renderer, color.r, color.g, color.b, 255);
    for (; *text != '\0'; text++, x += 8 * scale) {
        const unsigned char *glyph = gfxPrimitivesFontdata + 8 * (unsigned char)*text;
        for (int row = 0; row < 8; row++) {
            for (int col = 0; col < 8; col++) {
                if (!(glyph[row] & (0x80 >> col))) continue;
                SDL_Rect square = {x + col * scale, y + row * scale, scale, scale};
                if (text_canvas != NULL) {
                    SDL_FillRect(text_canvas, &square, pixel);
                } else {
                    SDL_RenderFillRect(renderer, &square);
                }
            }
        }
    }
}

void draw_panel(SDL_Renderer *renderer, int x, int y, int w, int h, palette_rgb_t color,
                Uint8 alpha) {
    boxRGBA(renderer, draw_coord(x), draw_coord(y), draw_coord(x + w - 1), draw_coord(y + h - 1),
            color.r, color.g, color.b, alpha);
    rectangleRGBA(renderer, draw_coord(x), draw_coord(y), draw_coord(x + w - 1),
                  draw_coord(y + h - 1), 52, 56, 68, 255);
}
