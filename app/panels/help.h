#ifndef SANDBOX_HELP_H
#define SANDBOX_HELP_H

/* The help screen (H, F1): every key and mouse action, from the controls
 * table in input.c, on a page that closes the view while it shows (the side
 * bar stays readable beside it). */

#include <SDL.h>
#include "core/app.h"

/* Draws the page into `page` (the view, in the renderer's pixels): two
 * columns, keys and actions, wrapped to its width, lines as close as its
 * height needs. */
void help_draw(SDL_Renderer *renderer, app_t *app, layout_rect_t page);

#endif
