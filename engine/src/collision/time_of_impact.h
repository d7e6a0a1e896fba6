#ifndef TIME_OF_IMPACT_H
#define TIME_OF_IMPACT_H

/*
 * When two moving polygons first touch within a step, and their contact at
 * that moment: the geometry an impact within the step acts through. The
 * narrowphase finds a pair's manifold where the bodies are at the start of
 * the step; a body that moves sideways or turns before it hits meets the
 * other with other points, lever arms, even another face (docs/design.md,
 * "Impacts within the step").
 *
 * Each body moves as the solver's times of impact assume: its centroid by
 * v t + a t^2 / 2, its angle by w t, from its pose at the start of the step
 * (the pose body_t holds). The search is conservative advancement along
 * separating axes: the separating-axis test at time t names the face that
 * separates most; that face's separation changes no faster than a bound
 * from the two motions, so advancing by the separation over the bound never
 * passes its first root, which is found by regula falsi once bracketed and
 * comes no later than the first touch; the test there either finds the
 * polygons touching or names the next face. Translation without a pull
 * apart makes each face's separation concave in t, and the answer is exact
 * to rounding; with turning, the advancement gives up after 32 steps on one
 * face (a grazing pass), taking the pair as not touching.
 *
 * A pair with a circle, a capsule or a chain's segment advances on the
 * exact distance between the shapes instead (round_manifold.h), by the
 * distance over the same bound, and gives up after 200 steps.
 */

#include <stdbool.h>
#include <stddef.h>
#include "jostle/body.h"
#include "collision/manifold.h"
#include "jostle/vector.h"

/* A body's motion over the step (m/s, m/s^2, rad/s). */
typedef struct {
    vector_t velocity;
    vector_t acceleration;
    double angular_velocity;
} toi_motion_t;

/* Room for the polygons posed at trial times: the caller keeps it between
 * calls, sized with toi_scratch_reserve for the largest polygon it will
 * pose, so a warm step allocates nothing. */
typedef struct {
    vector_t *vectors;
    size_t capacity;
} toi_scratch_t;

/* Makes room for two polygons of up to largest_polygon vertices each. */
void toi_scratch_reserve(toi_scratch_t *scratch, size_t largest_polygon);

typedef struct {
    bool touches;            /* within the duration */
    double time;             /* of the first touch, or the duration (s) */
    manifold_t manifold;     /* at that moment, points within the margin */
    manifold_features_t features;
    vector_t centroid_a, centroid_b; /* the bodies' centroids then */
    double angle_a, angle_b;
} toi_contact_t;

/*
 * Whether bodies a and b, moving from their poses as motion_a and motion_b
 * say, touch within [0, duration] (s): *contact receives the first moment
 * they do and their manifold then (points within margin, as
 * manifold_collide's), or, when they do not, the moment `duration` and
 * their manifold then, every point clipping gives however far apart. Touch
 * means the separating-axis separation is at most `tolerance` (m, > 0).
 * Returns whether that manifold has points. Both bodies' world polygons
 * must be up to date; neither is changed.
 */
bool time_of_impact(const body_t *a, const toi_motion_t *motion_a, const body_t *b,
                    const toi_motion_t *motion_b, double duration, double margin,
                    double tolerance, toi_scratch_t *scratch, toi_contact_t *contact);

#endif // #ifndef TIME_OF_IMPACT_H
