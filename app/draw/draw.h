#ifndef SANDBOX_DRAW_H
#define SANDBOX_DRAW_H

/* Small drawing helpers over SDL2_gfx shared by render.c and ui.c. */

#include <SDL.h>
#include <stdbool.h>
#include "core/layout.h"
#include "draw/palette.h"
#include "jostle/vector.h"

/* Pixel coordinates clamped to what SDL2_gfx's Sint16 can hold. */
Sint16 draw_coord(double pixel);

/* Text goes straight into canvas (a 32-bit surface that renderer draws
 * into) when it is not NULL, else through the renderer. */
void draw_set_canvas(SDL_Renderer *renderer, SDL_Surface *canvas);

/* printf-style text in SDL2_gfx's built-in 8x8 font, top-left at (x, y). */
void draw_text(SDL_Renderer *renderer, int x, int y, palette_rgb_t color, const char *format,
               ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 5, 6)))
#endif
    ;

/* The same font drawn `scale` times as large (each bit a scale x scale
 * square), for headings over the view. */
void draw_text_scaled(SDL_Renderer *renderer, int x, int y, int scale, palette_rgb_t color,
                      const char *text);

/* A filled rectangle, translucent when alpha < 255. */
void draw_panel(SDL_Renderer *renderer, int x, int y, int w, int h, palette_rgb_t color,
                Uint8 alpha);

#define DRAW_CHAR_W LAYOUT_CHAR_W
#define DRAW_LINE_H LAYOUT_LINE_H

#endif
