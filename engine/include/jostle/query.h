#ifndef JOSTLE_QUERY_H
#define JOSTLE_QUERY_H

/*
 * Questions about a scene's bodies where they are now, answered exactly
 * against each body's shape (a convex polygon, a circle's or capsule's
 * true boundary, a chain's one-sided segments: a ray crosses a segment
 * from its free side only, and a chain contains the points on its
 * segments), and an explosion.
 *
 * How: the scene keeps a grid of the bodies' bounding boxes (the
 * broadphase's, collision/broadphase.h), built at the first query after
 * something moved (a scene_tick, a body added, a pose set on one of its
 * bodies) in O(N), then kept for every later query until the next such
 * change. A query then reads only the grid cells its box or ray crosses and
 * tests the shapes found there, so many queries between two ticks cost
 * about what they find, whether or not the scene has world contacts. A body
 * covering more than 1024 cells (a huge floor) is tested by every query.
 * The grid is the queries' own, not the world's broadphase, which holds
 * only the awake bodies' boxes swept over a step.
 *
 * Every query skips the bodies marked removed (body_remove) and reads
 * every other body, asleep or not, static or not, whatever its collision
 * filter. A point on a body's boundary is in the body. Called from inside
 * a scene_tick (a force creator or collision handler) a query sees the
 * bodies' poses of the stage that runs (scene_get_stage).
 *
 * Bad input stops the program ("engine error in scene_ray_cast: from is
 * not finite (nan, 0)"): non-finite points, min > max, radius <= 0, a
 * NULL hit or a NULL bodies array with capacity > 0.
 */

#include <stdbool.h>
#include <stddef.h>
#include "body.h"
#include "scene.h"
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

/* The first hit of a ray: the body, the point where the ray enters it, the
 * unit outward normal of the body's edge there (the edge the ray enters
 * through; at a vertex, the first edge counter-clockwise whose line the
 * ray crosses last), and the fraction t in [0, 1] with point = from + t (to
 * - from). */
typedef struct {
    body_t *body;
    vector_t point;
    vector_t normal;
    double fraction;
} ray_hit_t;

/* The first body the segment from -> to enters; false when it enters none
 * (hit is then left as it was). A body that contains `from` (inside or on
 * its boundary) is not hit: the ray leaves it, it does not enter it, as
 * Box2D v3 ignores a shape containing the ray's origin; the ray still hits
 * the bodies beyond. from == to hits nothing. Of two bodies entered at the
 * same fraction, the one added last is the hit. */
bool scene_ray_cast(scene_t *scene, vector_t from, vector_t to, ray_hit_t *hit);

/* The bodies whose shape overlaps the box [min, max] (touching counts;
 * min.x <= max.x and min.y <= max.y), in the order they were added:
 * writes the first `capacity` of them to bodies and returns how many
 * there are (call with capacity 0 to count). A body whose bounding box
 * overlaps the box but whose polygon does not is not one. */
size_t scene_query_box(scene_t *scene, vector_t min, vector_t max, body_t **bodies,
                       size_t capacity);

/* The body containing the point (inside or on its boundary) that was added
 * last (drawn on top), or NULL for none. */
body_t *scene_body_at(scene_t *scene, vector_t point);

/*
 * An explosion: every body of finite mass whose shape comes within radius
 * (m, > 0) of center gets an impulse of magnitude impulse (N s, >= 0) (1 -
 * d / radius), d its shape's distance from center (0 when center is inside
 * it), directed from center to the shape's nearest point and applied
 * there (so it may spin the body), or, for a body containing center, from
 * center to its centroid and applied at the centroid (a body whose
 * centroid is center itself then gets nothing). The impulses act at the
 * next scene_tick as body_add_impulse_at's do, and wake the bodies that
 * get one. Bodies of infinite mass are not moved.
 */
void scene_explode(scene_t *scene, vector_t center, double radius, double impulse);

JOSTLE_API_END

#endif // #ifndef JOSTLE_QUERY_H
