#ifndef SEGMENT_MANIFOLD_H
#define SEGMENT_MANIFOLD_H

/*
 * The contact of a chain's segment (body_private.h, BODY_SHAPE_SEGMENT)
 * with another shape: the exact manifold of round_manifold.h, kept to the
 * surface the chain makes, so that a body crossing a join meets one
 * surface (the ghost-collision problem that Box2D's chain shapes and the
 * seams of seams.h answer):
 *
 * - one-sided: a body whose centroid lies behind the segment's line, and
 *   behind the lines of its neighbours where the chain bends away from the
 *   free side there (a convex join), makes no contact;
 * - a normal that leans toward a join where the chain is flat or bends
 *   toward the free side (a concave join) is the segment's face normal
 *   instead: the contact is the other shape against the face;
 * - at a convex join, a normal between the two segments' face normals is
 *   the corner's, and the segment whose face normal is nearer it keeps it
 *   (the one that starts there on a tie), so the corner gives one contact;
 *   one beyond them belongs to the neighbour's face, and the segment makes
 *   none;
 * - a face contact clips the other shape to the whole straight run of
 *   segments the face belongs to, and the segment whose stretch holds the
 *   middle of the points keeps it, so a run acts as one long segment;
 * - an open chain's ends are free corners, but where a static polygon's
 *   face (or another chain) continues the segment flush (seams.h): that
 *   end is a flat join, the run reaches over the neighbour's face and the
 *   claim there is shared with it, as between flush static boxes.
 *
 * The manifold_collide contract: the normal points from a toward b;
 * *separation is the segment's distance from the other shape less its
 * radius when it keeps no points, a lower bound on the separation of any
 * point it may keep at a pose as far away.
 */

#include "dynamics/body_private.h"
#include "collision/manifold_types.h"

manifold_t segment_manifold_collide(const body_t *a, const body_t *b, double margin,
                                    manifold_features_t *features, double *separation);

#endif // #ifndef SEGMENT_MANIFOLD_H
