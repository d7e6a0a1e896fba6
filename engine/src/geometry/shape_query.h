#ifndef SHAPE_QUERY_H
#define SHAPE_QUERY_H

/*
 * The exact tests of jostle/query.h, one function per shape kind and
 * question: convex polygons given by counter-clockwise world vertices
 * v[0 .. count) and the outward unit normals n[i] of edges v[i] -> v[i + 1]
 * (a body's world polygon); capsules given by the world ends c1, c2 of
 * their core and their radius (a circle: equal ends; a bare segment:
 * radius 0); a chain's one-sided segments. The scene's queries pick by
 * the body's kind.
 */

#include <stdbool.h>
#include <stddef.h>
#include "jostle/aabb.h"
#include "jostle/vector.h"

/* Where the segment from + t d, t in [0, max_fraction], enters the
 * polygon: true with *fraction = t and *edge the edge it enters through;
 * false when it misses or when `from` is inside or on the boundary (the
 * ray leaves the polygon there rather than entering it). */
bool polygon_ray_cast(const vector_t *v, const vector_t *n, size_t count, vector_t from,
                      vector_t d, double max_fraction, double *fraction, size_t *edge);

/* Whether the point is inside the polygon or on its boundary. */
bool polygon_contains_point(const vector_t *v, const vector_t *n, size_t count, vector_t point);

/* Whether the polygon (whose bounding box is `bounds`) and the box share
 * a point, boundaries included: separating axes, the box's two and the
 * polygon's normals. */
bool polygon_overlaps_box(const vector_t *v, const vector_t *n, size_t count, aabb_t bounds,
                          aabb_t box);

/* The distance (m) from the point to the polygon, 0 when inside or on it,
 * and in *nearest the polygon's point nearest to it (the point itself when
 * inside). */
double polygon_distance(const vector_t *v, const vector_t *n, size_t count, vector_t point,
                        vector_t *nearest);

/* The distance (m) from the point to the capsule, 0 when inside or on it,
 * and in *nearest the capsule's point nearest to it (the point itself when
 * inside). */
double capsule_distance(vector_t c1, vector_t c2, double radius, vector_t point,
                        vector_t *nearest);

/* Where from + t d, t in [0, max_fraction], enters the capsule: true with
 * *fraction = t and *normal the outward unit normal there; false when it
 * misses or `from` is inside or on the boundary. */
bool capsule_ray_cast(vector_t c1, vector_t c2, double radius, vector_t from, vector_t d,
                      double max_fraction, double *fraction, vector_t *normal);

/* Whether the capsule and the box share a point, boundaries included: the
 * core's distance from the box is at most the radius. */
bool capsule_overlaps_box(vector_t c1, vector_t c2, double radius, aabb_t box);

/* Where from + t d, t in [0, max_fraction], crosses the segment p1-p2
 * from the side its unit normal faces (a chain's free side); false when
 * it misses, crosses from behind, runs along it or starts on its line. */
bool segment_ray_cast(vector_t p1, vector_t p2, vector_t normal, vector_t from, vector_t d,
                      double max_fraction, double *fraction);

#endif // #ifndef SHAPE_QUERY_H
