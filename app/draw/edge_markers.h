#ifndef SANDBOX_EDGE_MARKERS_H
#define SANDBOX_EDGE_MARKERS_H

/* A body wholly outside the view gets a marker at the view's edge, in its
 * colour, pointing at it: a thrown body never vanishes without a trace. */

#include <SDL.h>
#include "core/app.h"

void edge_markers_draw(SDL_Renderer *renderer, SDL_Surface *canvas, app_t *app);

/* Frees the markers' batch, kept from frame to frame (at exit). */
void edge_markers_free(void);

/* How far inside the view's edge a marker sits (pixels). */
#define EDGE_MARKER_INSET 14

#endif
