#ifndef SANDBOX_UI_H
#define SANDBOX_UI_H

/*
 * The user interface drawn over the world: the HUD (frame rate, timings,
 * bodies, collisions, energy, momentum), the shape and elasticity panel with
 * its slider, the overlay legend, a status line and the help screen. Text uses
 * SDL2_gfx's built-in 8x8 font: no font files.
 */

#include <SDL.h>
#include <stdbool.h>
#include "app.h"

void ui_draw(SDL_Renderer *renderer, app_t *app, body_t *hovered);

/* Whether the pixel is on the elasticity slider (a click there sets the
 * value rather than dropping a body). */
bool ui_slider_hit(const app_t *app, vector_t pixel);

/* The slider value under pixel's x, clamped to the slider's range. */
double ui_slider_value_at(const app_t *app, vector_t pixel);

/* Whether the pixel is on a panel that takes clicks (no preview there). */
bool ui_captures(const app_t *app, vector_t pixel);

#endif
