#include "geometry/shape_query.h"
#include <math.h>

bool polygon_ray_cast(const vector_t *v, const vector_t *n, size_t count, vector_t from,
                      vector_t d, double max_fraction, double *fraction, size_t *edge) {
    /* Clip [0, max_fraction] by each edge's half-plane n . (x - v) <= 0
     * (Cyrus-Beck); the ray enters where the last entering edge cuts it.
     * No entering edge cut it: it starts inside. */
    double lower = 0.0, upper = max_fraction;
    size_t entered = count;
    for (size_t i = 0; i < count; i++) {
        double numerator = vec_dot(n[i], vec_subtract(v[i], from));
        double denominator = vec_dot(n[i], d);
        if (denominator == 0.0) {
            if (numerator < 0.0) return false; /* parallel, outside this edge */
        } else if (denominator < 0.0) {
            if (numerator < lower * denominator) {
                lower = numerator / denominator;
                entered = i;
            }
        } else if (numerator < upper * denominator) {
            upper = numerator / denominator;
        }
        if (upper < lower) return false;
    }
    if (entered == count) return false;
    *fraction = lower;
    *edge = entered;
    return true;
}

bool polygon_contains_point(const vector_t *v, const vector_t *n, size_t count, vector_t point) {
    for (size_t i = 0; i < count; i++) {
        if (vec_dot(n[i], vec_subtract(point, v[i])) > 0.0) return false;
    }
    return true;
}

bool polygon_overlaps_box(const vector_t *v, const vector_t *n, size_t count, aabb_t bounds,
                          aabb_t box) {
    if (!aabb_overlaps(bounds, box)) return false;
    for (size_t i = 0; i < count; i++) {
        /* The box's corner deepest along -n[i], against the edge's line. */
        vector_t corner = {n[i].x > 0.0 ? box.min.x : box.max.x,
                           n[i].y > 0.0 ? box.min.y : box.max.y};
        if (vec_dot(n[i], vec_subtract(corner, v[i])) > 0.0) return false;
    }
    return true;
}

/* The point of segment a-b nearest p. */
static vector_t nearest_on_segment(vector_t a, vector_t b, vector_t p) {
    vector_t ab = vec_subtract(b, a);
    double length_squared = vec_dot(ab, ab);
    double t = length_squared > 0.0 ? vec_dot(vec_subtract(p, a), ab) / length_squared : 0.0;
    if (t <= 0.0) return a;
    if (t >= 1.0) return b;
    return vec_add(a, vec_multiply(t, ab));
}

double polygon_distance(const vector_t *v, const vector_t *n, size_t count, vector_t point,
                        vector_t *nearest) {
    if (polygon_contains_point(v, n, count, point)) {
        *nearest = point;
        return 0.0;
    }
    double best = INFINITY;
    for (size_t i = 0; i < count; i++) {
        vector_t q = nearest_on_segment(v[i], v[(i + 1) % count], point);
        double distance = vec_get_length(vec_subtract(point, q));
        if (distance < best) {
            best = distance;
            *nearest = q;
        }
    }
    return best;
}
