#ifndef VECTOR_H
#define VECTOR_H

/*
 * 2D vectors in SI units (metres, metres per second, newtons: the meaning
 * comes from the caller). Every function is pure and takes and returns by
 * value. They are defined inline here because the contact solver calls them
 * millions of times per step.
 */

#include <math.h>
#include "export.h"

JOSTLE_API_BEGIN

typedef struct {
    double x;
    double y;
} vector_t;

/* The zero vector. */
extern const vector_t VEC_ZERO;

static inline vector_t vec_add(vector_t v1, vector_t v2) {
    return (vector_t){v1.x + v2.x, v1.y + v2.y};
}

static inline vector_t vec_subtract(vector_t v1, vector_t v2) {
    return (vector_t){v1.x - v2.x, v1.y - v2.y};
}

static inline vector_t vec_negate(vector_t v) {
    return (vector_t){-v.x, -v.y};
}

static inline vector_t vec_multiply(double scalar, vector_t v) {
    return (vector_t){scalar * v.x, scalar * v.y};
}

static inline double vec_dot(vector_t v1, vector_t v2) {
    return v1.x * v2.x + v1.y * v2.y;
}

/* The z component of the 3D cross product (v1.x, v1.y, 0) x (v2.x, v2.y, 0). */
static inline double vec_cross(vector_t v1, vector_t v2) {
    return v1.x * v2.y - v1.y * v2.x;
}

/* v rotated counter-clockwise by angle (radians) about the origin. */
static inline vector_t vec_rotate(vector_t v, double angle) {
    double c = cos(angle), s = sin(angle);
    return (vector_t){c * v.x - s * v.y, s * v.x + c * v.y};
}

static inline double vec_get_length(vector_t v) {
    return sqrt(v.x * v.x + v.y * v.y);
}

/* Additions beyond the seed API. */

static inline double vec_get_length_squared(vector_t v) {
    return v.x * v.x + v.y * v.y;
}

/* v turned a quarter counter-clockwise: (-y, x). */
static inline vector_t vec_perpendicular(vector_t v) {
    return (vector_t){-v.y, v.x};
}

/* The cross product of a scalar (an angular velocity about z) with v:
 * w x v = (-w v.y, w v.x). */
static inline vector_t vec_cross_scalar(double w, vector_t v) {
    return (vector_t){-w * v.y, w * v.x};
}

/* v scaled to length 1; VEC_ZERO stays VEC_ZERO. */
static inline vector_t vec_normalize(vector_t v) {
    double length = vec_get_length(v);
    return length > 0.0 ? vec_multiply(1.0 / length, v) : v;
}

/* v rotated by the angle whose cosine and sine are given (avoids trig in
 * loops that rotate many vectors by one angle). */
static inline vector_t vec_rotate_cs(vector_t v, double cos_angle, double sin_angle) {
    return (vector_t){cos_angle * v.x - sin_angle * v.y, sin_angle * v.x + cos_angle * v.y};
}

static inline int vec_is_finite(vector_t v) {
    return isfinite(v.x) && isfinite(v.y);
}

JOSTLE_API_END

#endif // #ifndef VECTOR_H
