#ifndef SANDBOX_RENDER_H
#define SANDBOX_RENDER_H

/*
 * Draws the world: the background grid, the bodies, the grab spring, the
 * shape about to be dropped, and the overlays. The overlays come from the
 * engine's per-step contact record (scene_get_contact) and the trail of
 * recent impulses; nothing is recomputed here.
 */

#include <SDL.h>
#include "core/app.h"

/* canvas: the surface renderer draws into when it is a software renderer
 * (the bodies are then written straight into it), else NULL. Returns the
 * seconds the overlays took (from the bounding boxes to the ring round the
 * cursor), for --stats. */
double render_world(SDL_Renderer *renderer, SDL_Surface *canvas, app_t *app, body_t *hovered);

/* Frees the buffers kept from frame to frame (at exit). */
void render_free(void);

/* The length (m) of a velocity arrow per m/s. */
#define RENDER_VELOCITY_SCALE 0.1

#endif
