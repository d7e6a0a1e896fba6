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
 *
 * A pair with a round body (a circle or capsule) takes the exact round
 * path of round_manifold.h, and one with a chain's segment that of
 * segment_manifold.h; polygons never reach them.
 */

#include "jostle/body.h"
#include "collision/manifold_types.h"

/* How far another face may lead last step's reference face before a fresh
 * search gives it up, and reused features may have been overtaken (m): a
 * tenth of the solver's linear slop, so the overlap a kept face overstates
 * is never pushed apart (docs/design.md, Narrowphase). */
extern const double MANIFOLD_KEEP_TOLERANCE;

/* The manifold of two bodies' current polygons (point_count 0 when they are
 * further apart than margin). When it has points, *features receives them,
 * including clipped points beyond the margin (a later evaluate may keep
 * them). *separation receives the largest separation of a face found, a
 * lower bound on the distance between the polygons when it exceeds margin
 * (no points then). last: the pair's features of last step, or NULL; its
 * reference face is kept while within MANIFOLD_KEEP_TOLERANCE of the best.
 * Both bodies' world polygons must be up to date. */
manifold_t manifold_collide(body_t *a, body_t *b, double margin, const manifold_features_t *last,
                            manifold_features_t *features, double *separation);

/* The manifold the features give at the bodies' current poses (a round
 * pair's: found again). */
manifold_t manifold_evaluate(const manifold_features_t *features, const body_t *a,
                             const body_t *b, double margin);

#endif // #ifndef MANIFOLD_H
