#ifndef SANDBOX_ROUND_OUTLINE_H
#define SANDBOX_ROUND_OUTLINE_H

/*
 * The outline the sandbox draws for a circle or capsule, in pixels: a
 * convex polygon whose vertices lie on the true boundary, with enough of
 * them that no chord strays more than a quarter of a pixel inside it (up to
 * the batch's limit), so that a body looks round at any zoom while a small
 * one costs few vertices. The engine's own outline (body_get_polygon) is
 * coarser and fixed; this one is for the eye only. Plain C, no SDL.
 */

#include "jostle/vector.h"

/* The most vertices round_outline gives (the batch's limit). */
#define ROUND_OUTLINE_MAX 64

/* Fills `out` (room for ROUND_OUTLINE_MAX) with the outline of the capsule
 * of end centres c1, c2 and radius r (pixels; c1 == c2 for a circle),
 * counter-clockwise on screen as the ends are given; returns the count (0
 * when r is not finite and > 0 or a centre is not finite). */
int round_outline(vector_t c1, vector_t c2, double r, vector_t *out);

/* The radius line that shows a round body's rotation: from `centre` to the
 * rim at `angle` (rad, counter-clockwise in the world, so clockwise on a
 * screen whose y grows downward), radius r (pixels). */
vector_t round_rim_point(vector_t centre, double r, double angle);

#endif
