#ifndef SANDBOX_END_SCREEN_H
#define SANDBOX_END_SCREEN_H

/*
 * The end of a game, over the field: once the open scene's game is won or
 * lost, a panel in the middle of the view says so in large letters ("WON" or
 * "GAME OVER"), with the score and "R to play again", so that a field that
 * stopped moving does not look like a hang. Drawn after the side bar, under
 * the help screen.
 */

#include <SDL.h>
#include "core/app.h"

void end_screen_draw(SDL_Renderer *renderer, const app_t *app);

#endif
