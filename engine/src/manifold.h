#ifndef MANIFOLD_H
#define MANIFOLD_H

/*
 * The narrowphase: the separating-axis test of find_collision, extended to
 * a signed separation (positive when apart), and a contact manifold of up to
 * two points found by clipping the incident edge of one polygon against the
 * reference edge of the other (the edge of least penetration).
 *
 * Points are reported while the separation is at most `margin` (metres), so
 * the solver sees contacts that are about to form (speculative contacts) and
 * can stop bodies before they touch instead of after they overlap.
 */

#include <stdint.h>
#include "body.h"
#include "vector.h"

typedef struct {
    /* World contact point: midway between the two surfaces. */
    vector_t point;
    /* Signed distance along the normal (m): < 0 overlapping. */
    double separation;
    /* Names the pair of features (reference edge, incident vertex, which
     * polygon is the reference) so the same contact is recognised next step
     * and its impulse reused (warm starting). */
    uint32_t id;
} manifold_point_t;

typedef struct {
    /* Unit normal from body a toward body b. */
    vector_t normal;
    int point_count;
    manifold_point_t points[2];
} manifold_t;

/* The manifold of two bodies' current polygons (point_count 0 when they are
 * further apart than margin). */
manifold_t manifold_collide(body_t *a, body_t *b, double margin);

#endif // #ifndef MANIFOLD_H
