#ifndef SANDBOX_RASTER_H
#define SANDBOX_RASTER_H

/*
 * Filled and outlined convex polygons for the bodies, the bulk of a frame's
 * drawing. When the frame is drawn in software into a canvas surface (the
 * default), the pixels are written straight into it; otherwise (--gpu) the
 * fills are scan-converted into spans batched by colour into one
 * SDL_RenderFillRects call each. Both are much faster with thousands of bodies
 * than SDL2_gfx's filledPolygonRGBA, which issues a draw call per scanline
 * (docs/sandbox.md has the numbers). A pixel is filled when its centre is
 * inside the polygon, so neighbouring polygons neither overlap nor leave gaps.
 */

#include <SDL.h>
#include <stdbool.h>
#include "palette.h"
#include "vector.h"

/* Starts a batch: drawing goes into canvas (a 32-bit surface that renderer
 * draws into) when it is not NULL, else through renderer. Flushes what the
 * renderer has queued so that the order of drawing is kept. */
void raster_begin(SDL_Renderer *renderer, SDL_Surface *canvas);

/* Whether drawing goes straight into a canvas (raster_begin was given one). */
bool raster_direct(void);

/* A convex polygon of n vertices (pixels, either winding), clipped to the
 * canvas or the renderer's output. */
void raster_fill(const vector_t *pixels, int n, palette_rgb_t color);

/* Its outline, one pixel wide. */
void raster_outline(const vector_t *pixels, int n, palette_rgb_t color);

/* Draws whatever is still batched (fills through the renderer). Fills
 * given before raster_end are drawn before outlines given after it. */
void raster_end(void);

#endif
