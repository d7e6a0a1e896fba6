#ifndef POLYGON_H
#define POLYGON_H

/*
 * Polygons given as a list_t of heap-allocated vector_t * (vertices, metres).
 *
 * The seed functions (area, centroid, translate, rotate) accept either
 * winding; their results for a counter-clockwise polygon are the usual ones
 * (the area is positive for counter-clockwise, negative for clockwise). They
 * do not require a usable body shape: with fewer than 3 vertices or no area
 * the area is 0 and the centroid is the mean of the vertices (the origin for
 * an empty list). A NULL list or a NULL vertex stops the program with a
 * message naming the function ("engine error in polygon_area: vertex 2 is
 * NULL").
 * Bodies need convex counter-clockwise polygons: polygon_check tells whether
 * a list is usable and why not, without stopping the program, so that user
 * data (a click in the sandbox, a scene file) can be refused softly.
 */

#include <stdbool.h>
#include <stddef.h>
#include "list.h"
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

/* The signed area (m^2): positive when the vertices run counter-clockwise. */
double polygon_area(list_t *polygon);

/* The centroid of the polygon's area (not the mean of its vertices). */
vector_t polygon_centroid(list_t *polygon);

/* Moves every vertex by translation. */
void polygon_translate(list_t *polygon, vector_t translation);

/* Rotates every vertex counter-clockwise by angle (radians) about point. */
void polygon_rotate(list_t *polygon, double angle, vector_t point);

/* Additions beyond the seed API. */

/* The moment of inertia (kg m^2) about the area centroid of a uniform
 * polygon of the given mass. Either winding. */
double polygon_moment_of_inertia(list_t *polygon, double mass);

/* NULL when the list is a usable body shape: at least 3 vertices, none NULL,
 * all finite, not so large that its area (or the square of its size)
 * overflows a double, non-zero area, no repeated vertex (consecutive
 * duplicates), strictly convex (three collinear consecutive vertices are
 * refused too) and winding around once; clockwise is usable (bodies reverse
 * it). Where the polygon lies does not matter: a 1 m box at 1e10 m is usable.
 * Convexity is judged on the sine of the turn between consecutive edges (at
 * most 1e-12 counts as a straight angle), so a regular polygon with 100000
 * sides is usable. Otherwise a static message naming the problem, one of:
 * "polygon is NULL", "polygon has fewer than 3 vertices", "polygon has a
 * NULL vertex", "polygon has a vertex that is not finite", "polygon is too
 * large: its area overflows", "polygon has zero area", "polygon repeats a
 * vertex", "polygon is not strictly convex: a vertex turns against the
 * winding", "polygon is not strictly convex: three consecutive vertices are
 * collinear", "polygon winds around more than once". */
const char *polygon_check(list_t *polygon);

/* True when the vertices run counter-clockwise (positive signed area). */
bool polygon_is_counterclockwise(list_t *polygon);

/* A new list of new vertices: a regular polygon with `sides` vertices on a
 * circle of radius `radius` about `center`, the first vertex at angle `angle`
 * (radians) from the +x axis, counter-clockwise. sides >= 3, radius finite
 * and > 0, center and angle finite. */
list_t *polygon_make_regular(size_t sides, double radius, vector_t center, double angle);

/* A new list of new vertices: the axis-aligned rectangle with the given
 * centre (finite) and half extents (both finite and > 0), counter-clockwise,
 * starting at the lower-left corner. */
list_t *polygon_make_box(vector_t center, double half_width, double half_height);

/* A read-only view of a body's convex polygon in world coordinates,
 * counter-clockwise: count vertices and, for each edge i (from vertex i to
 * vertex i + 1), its outward unit normal. It points into the body's own
 * storage: valid until the body next moves, changes or is freed. */
typedef struct {
    size_t count;
    const vector_t *vertices;
    const vector_t *normals;
} polygon_t;

JOSTLE_API_END

#endif // #ifndef POLYGON_H
