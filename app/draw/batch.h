#ifndef SANDBOX_BATCH_H
#define SANDBOX_BATCH_H

/*
 * A geometry batch: the convex polygons of a frame's layer (the bodies, the
 * axes' arrows, the impulses' arrows, the edge markers), in pixels, collected
 * as one vertex buffer and one index buffer of triangles, so that thousands
 * of them cost one SDL_RenderGeometryRaw call, which takes the buffers as
 * they are (float x, y and four colour bytes per vertex, int indices). A
 * polygon of k vertices adds k vertices and its fan of k - 2 triangles, and
 * a run (its first vertex, its count, its outline colour), from which the
 * outlines are drawn, and the fills too when they are scan-converted
 * straight into a software canvas (raster.h).
 *
 * The buffers grow by doubling and are kept across frames: batch_clear
 * empties them without freeing, so once the largest frame has been seen,
 * filling the batch allocates nothing. Plain C, no SDL.
 */

#include <stdbool.h>
#include <stddef.h>
#include "draw/palette.h"
#include "jostle/vector.h"

/* The layout SDL_RenderGeometryRaw reads: x, y at offset 0, an SDL_Color's
 * bytes (r, g, b, a) at offset 8; the stride is sizeof(batch_vertex_t). */
typedef struct {
    float x, y;
    unsigned char r, g, b, a;
} batch_vertex_t;

/* One polygon: vertices [first, first + count) of the batch. */
typedef struct {
    int first, count;
    bool outlined;
    palette_rgb_t outline;
} batch_run_t;

typedef struct {
    batch_vertex_t *vertices;
    int *indices;
    batch_run_t *runs;
    size_t vertex_count, index_count, run_count;
    size_t vertex_capacity, index_capacity, run_capacity;
    bool translucent; /* some polygon has alpha < 255 */
    bool failed;      /* an allocation failed: some polygons were left out */
} batch_t;

/* The most vertices one polygon may have; more are left out. */
#define BATCH_MAX_POLYGON 64

/* Empties the batch and keeps its buffers for the next frame. */
void batch_clear(batch_t *batch);

/* Frees the buffers; the batch is then empty and usable again. */
void batch_free(batch_t *batch);

/* Adds a convex polygon of 3 to BATCH_MAX_POLYGON vertices (either winding)
 * as a triangle fan from its first vertex. False when n is out of range or
 * memory ran out. */
bool batch_polygon(batch_t *batch, const vector_t *pixels, int n, palette_rgb_t color,
                   unsigned char alpha);

/* The same, opaque, with a one-pixel outline in `outline` over the fill. */
bool batch_outlined(batch_t *batch, const vector_t *pixels, int n, palette_rgb_t fill,
                    palette_rgb_t outline);

/* An arrow from tail to head (pixels): a shaft `width` pixels wide (at least
 * one) and a head scaled to the arrow (at most half its length); two
 * polygons, or only the head when the arrow is too short for a shaft.
 * Nothing (false) for an arrow under a pixel long or alpha 0. */
bool batch_arrow(batch_t *batch, vector_t tail, vector_t head, palette_rgb_t color,
                 unsigned char alpha, int width);

/* Whether a polygon can touch the view [0, width) x [0, height) (pixels):
 * what lies wholly outside is culled, as is a polygon with a vertex that is
 * not finite. */
bool batch_polygon_visible(const vector_t *pixels, int n, int width, int height);

#endif
