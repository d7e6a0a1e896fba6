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
 *
 * Against a static body with flush static neighbours (seams.h), the contact
 * keeps to the faces of their combined surface, as against one body.
 */

#include <stdint.h>
#include "jostle/body.h"
#include "jostle/vector.h"

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

/*
 * A manifold's features in the bodies' own frames: which polygon holds the
 * reference face, the face's normal and a point on it (reference frame),
 * and the clipped incident points (incident frame). While two bodies keep
 * nearly the same relative pose, the features stay right and only the
 * separations and world points need recomputing (manifold_evaluate), which
 * is much cheaper than the separating-axis search and clipping.
 */
typedef struct {
    bool flip; /* the reference face is b's */
    /* Both points are the incident edge's own ends (no clipping cut it):
     * the edge lies on the reference face. */
    bool edge_ends;
    /* The reference face is one of a run of flush static faces (seams.h):
     * which face of the run holds the contact depends on where the other
     * body is, so the features are not reused from step to step. */
    bool on_run;
    int point_count;
    vector_t normal;     /* reference frame */
    vector_t face_point; /* reference frame */
    vector_t points[2];  /* incident frame */
    uint32_t ids[2];
} manifold_features_t;

/* The manifold of two bodies' current polygons (point_count 0 when they are
 * further apart than margin). When it has points, *features receives them,
 * including clipped points beyond the margin (a later evaluate may keep
 * them). *separation receives the largest separation of a face found, a
 * lower bound on the distance between the polygons when it exceeds margin
 * (no points then). Both bodies' world polygons must be up to date. */
manifold_t manifold_collide(body_t *a, body_t *b, double margin, manifold_features_t *features,
                            double *separation);

/* The manifold the features give at the bodies' current poses. */
manifold_t manifold_evaluate(const manifold_features_t *features, const body_t *a,
                             const body_t *b, double margin);

#endif // #ifndef MANIFOLD_H
