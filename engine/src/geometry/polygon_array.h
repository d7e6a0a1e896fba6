#ifndef POLYGON_ARRAY_H
#define POLYGON_ARRAY_H

/* The polygon computations on plain arrays of vertices, shared by the list
 * API in polygon.c and by bodies (which keep their vertices in arrays). */

#include <stddef.h>
#include "jostle/vector.h"

double polygon_array_signed_area(const vector_t *vertices, size_t count);
vector_t polygon_array_centroid(const vector_t *vertices, size_t count);
/* Second moment of area about the centroid times mass / area. */
double polygon_array_moment(const vector_t *vertices, size_t count, double mass);
/* NULL when usable as a body shape (either winding), else a static message. */
const char *polygon_array_check(const vector_t *vertices, size_t count);

#endif // #ifndef POLYGON_ARRAY_H
