#ifndef SANDBOX_RASTER_H
#define SANDBOX_RASTER_H

/*
 * Draws a geometry batch (batch.h): its filled convex polygons, then the
 * one-pixel outlines of those that have one. When the frame is drawn in
 * software into a canvas surface (the default) and the batch is opaque, the
 * polygons are scan-converted straight into the canvas: with thousands of
 * small bodies that costs less than half of what SDL's software renderer
 * takes for the same triangles through SDL_RenderGeometry. A pixel is filled when its centre is inside the polygon,
 * so neighbouring polygons neither overlap nor leave gaps. Otherwise (--gpu,
 * or translucent arrows) every triangle of the batch goes to the renderer in
 * one SDL_RenderGeometryRaw call, blended when the batch is translucent.
 */

#include <SDL.h>
#include <stdbool.h>
#include "draw/batch.h"

/* Batches are drawn into canvas (a 32-bit surface that renderer draws into)
 * when it is not NULL, else through renderer. Flushes what the renderer has
 * queued so that the order of drawing is kept. */
void raster_begin(SDL_Renderer *renderer, SDL_Surface *canvas);

/* Draws the batch over what is there, clipped to the canvas or the
 * renderer's output. A large batch going into the canvas is drawn by two
 * threads, each in its own rows: the same pixels as one thread draws. */
void raster_batch(const batch_t *batch);

/* Whether a large batch may go to two threads (true until set): the tests
 * draw the same batch both ways and compare. */
void raster_set_split(bool split);

/* Stops the second drawing thread, if one was started. */
void raster_free(void);

#endif
