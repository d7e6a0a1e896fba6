#ifndef COLLISION_PRIVATE_H
#define COLLISION_PRIVATE_H

/* What the collision force creators need beyond find_collision. */

#include "jostle/body.h"

/* The largest separation of the two polygons along an edge normal of
 * either (m): positive when they are apart, then a lower bound on their
 * distance (equal to it when a vertex of one faces an edge of the other);
 * zero or negative when they touch or overlap. */
double collision_separation(body_t *body1, body_t *body2);

#endif // #ifndef COLLISION_PRIVATE_H
