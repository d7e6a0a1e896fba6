#ifndef SHAPE_QUERY_H
#define SHAPE_QUERY_H

/*
 * The exact tests of jostle/query.h, one function per shape kind and
 * question. Convex polygons only today: counter-clockwise world vertices
 * v[0 .. count) and the outward unit normals n[i] of edges v[i] -> v[i + 1]
 * (a body's world polygon). A round shape adds its own function beside
 * each, and the scene's queries pick by the body's kind.
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

#endif // #ifndef SHAPE_QUERY_H
