#ifndef SANDBOX_LAYER_H
#define SANDBOX_LAYER_H

/*
 * A layer drawn at the UI's scale: the side bar (or the help) is drawn at
 * scale 1 into a surface of its own, then copied, enlarged, into its place
 * in the frame. The surface is kept from frame to frame (made anew when its
 * size changes).
 */

#include <SDL.h>

typedef struct {
    SDL_Surface *surface;
    SDL_Renderer *renderer;
} layer_t;

/* A renderer drawing into the layer's surface of w x h pixels (cleared to
 * transparent black), set as draw.h's canvas; NULL when it cannot be made. */
SDL_Renderer *layer_begin(layer_t *layer, int w, int h);

/* Copies the layer, enlarged to fill `place`, into the frame (the canvas,
 * or through target when there is none) and makes the frame draw.h's
 * canvas again. */
void layer_end(layer_t *layer, SDL_Renderer *target, SDL_Surface *canvas, SDL_Rect place);

void layer_free(layer_t *layer);

#endif
