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

/* The side bar, a game's end screen and the help, at the UI's scale
 * (layout.h); canvas as for render_world. */
void ui_draw(SDL_Renderer *renderer, SDL_Surface *canvas, app_t *app, body_t *hovered);

/* Frees the layers kept from frame to frame (at exit). */
void ui_free(void);

/* A window pixel in the side bar's UI units, where the panels are laid out. */
vector_t ui_to_panels(const app_t *app, vector_t pixel);

/* A left press at a window pixel of the side bar: the panel under it acts
 * (the slider takes the value, an overlay's line toggles it); returns the
 * drag it starts (DRAG_SLIDER or DRAG_NONE). */
drag_t ui_press(app_t *app, vector_t pixel);

/* Whether the window pixel is on the elasticity slider (the wheel there
 * sets the value rather than the size). */
bool ui_slider_hit(const app_t *app, vector_t pixel);

/* The slider value under the window pixel's x, clamped to its range. */
double ui_slider_value_at(const app_t *app, vector_t pixel);

#endif
