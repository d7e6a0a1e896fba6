#ifndef AABB_H
#define AABB_H

/* An axis-aligned bounding box (metres): min is the lower-left corner, max the
 * upper-right one. Used by the broadphase and shown by the sandbox. */

#include <stdbool.h>
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

typedef struct {
    vector_t min;
    vector_t max;
} aabb_t;

static inline bool aabb_overlaps(aabb_t a, aabb_t b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y &&
           b.min.y <= a.max.y;
}

static inline aabb_t aabb_union(aabb_t a, aabb_t b) {
    return (aabb_t){{fmin(a.min.x, b.min.x), fmin(a.min.y, b.min.y)},
                    {fmax(a.max.x, b.max.x), fmax(a.max.y, b.max.y)}};
}

JOSTLE_API_END

#endif // #ifndef AABB_H
