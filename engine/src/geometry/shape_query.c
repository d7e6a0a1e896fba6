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

/* ---- Capsules (a circle: equal ends; a segment: radius 0) ------------------ */

double capsule_distance(vector_t c1, vector_t c2, double radius, vector_t point,
                        vector_t *nearest) {
    vector_t core = nearest_on_segment(c1, c2, point);
    vector_t away = vec_subtract(point, core);
    double length = vec_get_length(away);
    if (length <= radius) {
        *nearest = point;
        return 0.0;
    }
    *nearest = vec_add(core, vec_multiply(radius / length, away));
    return length - radius;
}

/* The least t >= 0 where from + t d enters the circle (centre c, radius r)
 * from outside; INFINITY when it never does. */
static double circle_entry(vector_t c, double r, vector_t from, vector_t d) {
    vector_t m = vec_subtract(from, c);
    double a = vec_dot(d, d), b = vec_dot(m, d), k = vec_dot(m, m) - r * r;
    if (k <= 0.0 || b >= 0.0) return INFINITY; /* inside, or moving away */
    double discriminant = b * b - a * k;
    if (discriminant < 0.0) return INFINITY;
    /* The nearer root, in the form without cancellation. */
    return k / (-b + sqrt(discriminant));
}

bool capsule_ray_cast(vector_t c1, vector_t c2, double radius, vector_t from, vector_t d,
                      double max_fraction, double *fraction, vector_t *normal) {
    vector_t unused;
    if (capsule_distance(c1, c2, radius, from, &unused) == 0.0) return false;
    double best = INFINITY;
    vector_t best_normal = VEC_ZERO;
    for (int end = 0; end < 2; end++) {
        vector_t c = end == 0 ? c1 : c2;
        double t = circle_entry(c, radius, from, d);
        if (t < best) {
            best = t;
            vector_t p = vec_add(from, vec_multiply(t, d));
            best_normal = vec_normalize(vec_subtract(p, c));
        }
    }
    vector_t axis = vec_subtract(c2, c1);
    double length = vec_get_length(axis);
    if (length > 0.0) {
        vector_t u = vec_multiply(1.0 / length, axis), m = {-u.y, u.x};
        for (int side = -1; side <= 1; side += 2) {
            double rate = side * vec_dot(m, d);
            if (!(rate < 0.0)) continue; /* not moving in through this side */
            double t = (side * vec_dot(m, vec_subtract(from, c1)) - radius) / -rate;
            double along = vec_dot(u, vec_subtract(vec_add(from, vec_multiply(t, d)), c1));
            if (t >= 0.0 && along >= 0.0 && along <= length && t < best) {
                best = t;
                best_normal = vec_multiply(side, m);
            }
        }
    }
    if (!(best <= max_fraction)) return false;
    *fraction = best;
    *normal = best_normal;
    return true;
}

/* Whether segment a-b crosses the box (Liang-Barsky clipping). */
static bool segment_crosses_box(vector_t a, vector_t b, aabb_t box) {
    double lower = 0.0, upper = 1.0;
    double start[2] = {a.x, a.y}, delta[2] = {b.x - a.x, b.y - a.y};
    double lo[2] = {box.min.x, box.min.y}, hi[2] = {box.max.x, box.max.y};
    for (int k = 0; k < 2; k++) {
        if (delta[k] == 0.0) {
            if (start[k] < lo[k] || start[k] > hi[k]) return false;
            continue;
        }
        double t1 = (lo[k] - start[k]) / delta[k], t2 = (hi[k] - start[k]) / delta[k];
        lower = fmax(lower, fmin(t1, t2));
        upper = fmin(upper, fmax(t1, t2));
        if (upper < lower) return false;
    }
    return true;
}

/* The distance from p to the box (0 inside). */
static double box_distance(aabb_t box, vector_t p) {
    double dx = fmax(0.0, fmax(box.min.x - p.x, p.x - box.max.x));
    double dy = fmax(0.0, fmax(box.min.y - p.y, p.y - box.max.y));
    return hypot(dx, dy);
}

bool capsule_overlaps_box(vector_t c1, vector_t c2, double radius, aabb_t box) {
    if (segment_crosses_box(c1, c2, box)) return true;
    /* Apart, the core's nearest point to the box is an end of it, or the
     * box's nearest point to the core is a corner. */
    double least = fmin(box_distance(box, c1), box_distance(box, c2));
    vector_t corners[4] = {box.min, {box.max.x, box.min.y}, box.max, {box.min.x, box.max.y}};
    for (int k = 0; k < 4; k++) {
        vector_t q = nearest_on_segment(c1, c2, corners[k]);
        least = fmin(least, vec_get_length(vec_subtract(q, corners[k])));
    }
    return least <= radius;
}

bool segment_ray_cast(vector_t p1, vector_t p2, vector_t normal, vector_t from, vector_t d,
                      double max_fraction, double *fraction) {
    double rate = vec_dot(normal, d);
    if (!(rate < 0.0)) return false; /* parallel, or from behind: one-sided */
    double height = vec_dot(normal, vec_subtract(from, p1));
    if (height <= 0.0) return false; /* starts on the segment's line or behind it */
    double t = height / -rate;
    if (!(t <= max_fraction)) return false;
    vector_t e = vec_subtract(p2, p1);
    double along = vec_dot(e, vec_subtract(vec_add(from, vec_multiply(t, d)), p1));
    if (along < 0.0 || along > vec_dot(e, e)) return false;
    *fraction = t;
    return true;
}
