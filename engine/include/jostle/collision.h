#ifndef COLLISION_H
#define COLLISION_H

/*
 * Separating-axis collision detection between the convex polygons of two
 * bodies.
 */

#include <stdbool.h>
#include "body.h"
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

typedef struct {
    /* Whether the two bodies' polygons overlap (touching counts). */
    bool collided;
    /* When collided: the unit axis of least overlap, pointing from body1
     * toward body2. Unspecified otherwise. */
    vector_t axis;
    /* When collided: the overlap (m, >= 0) of the projections on axis, i.e.
     * how far body2 must move along axis to stop overlapping. */
    double depth;
} collision_info_t;

/*
 * Projects both polygons onto the outward edge normals of both and stops at
 * the first axis whose projections do not overlap. A pair with a circle or
 * capsule (or a chain) gives the contact the world builds for it on the
 * exact shapes, body1 as its first body: the axis is the contact's normal
 * (along the line between the nearest features, or a face's normal where
 * the contact lies on a face), collided when its deepest point touches,
 * the depth that point's overlap along the axis. Allocates nothing.
 * Neither body may be NULL.
 */
collision_info_t find_collision(body_t *body1, body_t *body2);

JOSTLE_API_END

#endif // #ifndef COLLISION_H
