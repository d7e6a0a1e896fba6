/*
 * Round bodies (body.h): circles and capsules, their exact mass properties,
 * box and point test, and the polygon outline the seed's functions see.
 */
#include <math.h>
#include "jostle/body.h"
#include "dynamics/body_private.h"
#include "base/check.h"
#include "geometry/polygon_array.h"

/* Outline vertices: a circle's, and each end of a capsule's (both ends of
 * its half-turn included). */
enum { CIRCLE_OUTLINE = 32, CAP_OUTLINE = 17 };

/* Capsule ends closer than this share of the radius (but not equal) would
 * make an outline with a vanishing edge. */
static const double SHORTEST_CAPSULE = 1e-9;

/* The moment of inertia per kilogram about the centroid (m^2) of a capsule
 * of core length `length` (0: a disc) and radius r: the rectangle's
 * (L^2 + 4 r^2) / 12, and the two half-discs' r^2 / 2 about their flat
 * sides' centres, moved by the parallel-axis theorem from their centroids
 * (4 r / (3 pi) beyond the ends) to the capsule's; each weighted by its
 * share of the area. Scaled by the capsule's half-size s first, so that
 * only a moment that does not fit a double overflows. */
static double capsule_moment_per_kg(double length, double r) {
    double s = 0.5 * length + r;
    double l = length / s, q = r / s;
    double rectangle = 2.0 * q * l, discs = M_PI * q * q;
    double rectangle_moment = (l * l + 4.0 * q * q) / 12.0;
    double discs_moment = 0.5 * q * q + 0.25 * l * l + 4.0 * q * l / (3.0 * M_PI);
    double per_kg = (rectangle * rectangle_moment + discs * discs_moment) / (rectangle + discs);
    return per_kg * s * s;
}

static double round_moment(double length, double r, double mass, const char *function) {
    if (isinf(mass)) return INFINITY;
    return body_checked_moment(mass * capsule_moment_per_kg(length, r), mass, function);
}

/* The outline in the body frame, counter-clockwise: half-turns of radius r
 * about the core ends (a full turn for a circle), vertices on the boundary. */
static void fill_outline(body_t *body, vector_t axis, double r) {
    vector_t side = {-axis.y, axis.x};
    vector_t *v = body->local_vertices;
    if (body->kind == BODY_SHAPE_CIRCLE) {
        for (size_t k = 0; k < CIRCLE_OUTLINE; k++) {
            double angle = 2.0 * M_PI * (double)k / CIRCLE_OUTLINE;
            v[k] = (vector_t){r * cos(angle), r * sin(angle)};
        }
    } else {
        for (size_t end = 0; end < 2; end++) {
            vector_t centre = body->core[1 - end];
            for (size_t k = 0; k < CAP_OUTLINE; k++) {
                double angle = M_PI * ((double)k / (CAP_OUTLINE - 1) - 0.5) + M_PI * (double)end;
                vector_t d = vec_add(vec_multiply(cos(angle), axis), vec_multiply(sin(angle), side));
                v[end * CAP_OUTLINE + k] = vec_add(centre, vec_multiply(r, d));
            }
        }
    }
    size_t n = body->count;
    for (size_t i = 0; i < n; i++) {
        vector_t edge = vec_subtract(v[(i + 1) % n], v[i]);
        body->local_normals[i] = vec_normalize((vector_t){edge.y, -edge.x});
    }
}

static body_t *round_create(vector_t p1, vector_t p2, double r, double mass, rgb_color_t color,
                            void *info, free_func_t info_freer, const char *function) {
    if (!vec_is_finite(p1) || !vec_is_finite(p2)) {
        engine_fail(function, "centre is not finite (%g, %g), (%g, %g)", p1.x, p1.y, p2.x, p2.y);
    }
    if (!(isfinite(r) && r > 0.0)) engine_fail(function, "radius must be finite and > 0 (got %g)", r);
    body_check_mass(mass, function);
    vector_t d = vec_subtract(p2, p1);
    double length = vec_get_length(d);
    if (!isfinite(length)) engine_fail(function, "bad shape: capsule is too large: its length is not finite");
    if (length > 0.0 && length < SHORTEST_CAPSULE * r) {
        engine_fail(function,
                    "ends (%g, %g) and (%g, %g) are closer than %g of the radius %g m but not "
                    "equal; give equal ends for a circle",
                    p1.x, p1.y, p2.x, p2.y, SHORTEST_CAPSULE, r);
    }
    bool circle = length == 0.0;
    vector_t centroid = circle ? p1 : vec_add(p1, vec_multiply(0.5, d));
    double reach = 0.5 * length + r;
    if (!vec_is_finite(centroid) || !isfinite(reach)) {
        engine_fail(function, "bad shape: round shape is too large: its centroid is not finite");
    }
    double inertia = round_moment(length, r, mass, function);
    body_t *body = body_allocate(circle ? CIRCLE_OUTLINE : 2 * CAP_OUTLINE);
    body->kind = circle ? BODY_SHAPE_CIRCLE : BODY_SHAPE_CAPSULE;
    vector_t axis = circle ? (vector_t){1.0, 0.0} : vec_multiply(1.0 / length, d);
    body->core[0] = circle ? VEC_ZERO : vec_multiply(-0.5 * length, axis);
    body->core[1] = circle ? VEC_ZERO : vec_multiply(0.5 * length, axis);
    body->round_radius = r;
    body->radius = reach;
    body->centroid = centroid;
    fill_outline(body, axis, r);
    body_set_defaults(body, mass, inertia, color, info, info_freer);
    return body;
}

body_t *body_init_circle(vector_t center, double radius, double mass, rgb_color_t color) {
    return round_create(center, center, radius, mass, color, NULL, NULL, __func__);
}

body_t *body_init_circle_with_info(vector_t center, double radius, double mass,
                                   rgb_color_t color, void *info, free_func_t info_freer) {
    return round_create(center, center, radius, mass, color, info, info_freer, __func__);
}

body_t *body_init_capsule(vector_t p1, vector_t p2, double radius, double mass,
                          rgb_color_t color) {
    return round_create(p1, p2, radius, mass, color, NULL, NULL, __func__);
}

body_t *body_init_capsule_with_info(vector_t p1, vector_t p2, double radius, double mass,
                                    rgb_color_t color, void *info, free_func_t info_freer) {
    return round_create(p1, p2, radius, mass, color, info, info_freer, __func__);
}

body_shape_kind_t body_get_shape_kind(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return (body_shape_kind_t)body->kind;
}

double body_get_round_radius(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->round_radius;
}

void body_get_core(body_t *body, vector_t *p1, vector_t *p2) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_NOT_NULL(p1);
    REQUIRE_NOT_NULL(p2);
    body_update_world(body);
    vector_t core[2];
    body_world_core(body, core);
    *p1 = core[0];
    *p2 = core[1];
}
