#ifndef MANIFOLD_TYPES_H
#define MANIFOLD_TYPES_H

/* A contact manifold and the features it was found from: what the
 * polygon narrowphase (manifold.h) and the round one (round_manifold.h)
 * produce for the world. */

#include <stdbool.h>
#include <stdint.h>
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
    /* How much the reference face's separation led every other axis that
     * could take its place when found (m; manifold.c's reference_lead):
     * the features are reused only while the bodies have moved less than
     * half of it and MANIFOLD_KEEP_TOLERANCE (manifold.h). INFINITY for a pair with a round shape or a segment,
     * whose contact is found again each step. */
    double lead;
    vector_t normal;     /* reference frame */
    vector_t face_point; /* reference frame */
    vector_t points[2];  /* incident frame */
    uint32_t ids[2];
} manifold_features_t;

#endif // #ifndef MANIFOLD_TYPES_H
