#ifndef SANDBOX_HELP_H
#define SANDBOX_HELP_H

/* The help screen (H, F1): every key and mouse action, from the controls
 * table in input.c, over the whole window until closed. */

#include <SDL.h>
#include "core/app.h"

void help_draw(SDL_Renderer *renderer, app_t *app);

#endif
