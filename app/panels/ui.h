#ifndef SANDBOX_UI_H
#define SANDBOX_UI_H

/*
 * The user interface: the side bar of stacked panels right of the view
 * (layout.h), and the help screen over everything when asked for. Text uses
 * SDL2_gfx's built-in 8x8 font: no font files.
 */

#include <SDL.h>
#include <stdbool.h>
#include "core/app.h"

void ui_draw(SDL_Renderer *renderer, app_t *app, body_t *hovered);

/* A left press at a pixel of the side bar: the panel under it acts (the
 * slider takes the value, an overlay's line toggles it); returns the drag it
 * starts (DRAG_SLIDER or DRAG_NONE). */
drag_t ui_press(app_t *app, vector_t pixel);

/* Whether the pixel is on the elasticity slider (the wheel there sets the
 * value rather than the size). */
bool ui_slider_hit(const app_t *app, vector_t pixel);

/* The slider value under pixel's x, clamped to the slider's range. */
double ui_slider_value_at(const app_t *app, vector_t pixel);

#endif
