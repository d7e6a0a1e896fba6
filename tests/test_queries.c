/* jostle/query.h: ray casts, box queries, the body at a point and
 * explosions, against exact geometry and against a brute-force scan. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include "jostle/jostle.h"
#include "test.h"

static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};
static const double EXACT = 1e-12;

static body_t *add_box(scene_t *scene, vector_t center, double half, double angle, double mass) {
    body_t *body = body_init(polygon_make_box(center, half, half), mass, GREY);
    body_set_rotation(body, angle);
    scene_add_body(scene, body);
    return body;
}

/* The triangle (0, 0), (2, 0), (0, 2), moved by offset. */
static body_t *add_triangle(scene_t *scene, vector_t offset) {
    body_t *body = body_init(POLYGON({offset.x, offset.y}, {offset.x + 2, offset.y},
                                     {offset.x, offset.y + 2}),
                             1.0, GREY);
    scene_add_body(scene, body);
    return body;
}

static void check_hit(scene_t *scene, vector_t from, vector_t to, const body_t *body, double px,
                      double py, double nx, double ny, double fraction) {
    ray_hit_t hit;
    CHECK(scene_ray_cast(scene, from, to, &hit));
    CHECK(hit.body == body);
    CHECK_VEC(hit.point, px, py, EXACT);
    CHECK_VEC(hit.normal, nx, ny, EXACT);
    CHECK_NEAR(hit.fraction, fraction, EXACT);
}

static void ray_hits_box_at_known_angles(void) {
    scene_t *scene = scene_init();
    body_t *square = add_box(scene, (vector_t){0, 0}, 1.0, 0.0, 1.0);
    body_t *diamond = add_box(scene, (vector_t){10, 0}, 1.0, M_PI / 4, 1.0);
    /* Straight at the left face. */
    check_hit(scene, (vector_t){-3, 0.5}, (vector_t){3, 0.5}, square, -1, 0.5, -1, 0, 1.0 / 3.0);
    /* At 30 degrees up: x = -1 after 2 / cos 30 of the ray's 6 m. */
    double c = cos(M_PI / 6), s = sin(M_PI / 6);
    check_hit(scene, (vector_t){-3, -1.5}, (vector_t){-3 + 6 * c, -1.5 + 6 * s}, square, -1,
              -1.5 + 2 * s / c, -1, 0, 2.0 / (6 * c));
    /* Down onto the top face at 60 degrees. */
    check_hit(scene, (vector_t){-0.5, 3}, (vector_t){-0.5 + 4 * s, 3 - 4 * c}, square,
              -0.5 + 2 * s / c, 1, 0, 1, 2.0 / (4 * c));
    /* The diamond's upper-left edge: y = x - (10 - sqrt 2), normal (-1, 1) / sqrt 2. */
    double x = 10 - sqrt(2.0) + 0.5;
    check_hit(scene, (vector_t){7, 0.5}, (vector_t){13, 0.5}, diamond, x, 0.5, -sqrt(0.5),
              sqrt(0.5), (x - 7) / 6);
    scene_free(scene);
}

static void ray_hits_triangle_at_known_angles(void) {
    scene_t *scene = scene_init();
    body_t *triangle = add_triangle(scene, (vector_t){0, 0});
    /* Along the diagonal onto the hypotenuse x + y = 2. */
    check_hit(scene, (vector_t){3, 3}, (vector_t){0, 0}, triangle, 1, 1, sqrt(0.5), sqrt(0.5),
              2.0 / 3.0);
    /* At atan(1/2) onto the same point. */
    check_hit(scene, (vector_t){3, 2}, (vector_t){-1, 0}, triangle, 1, 1, sqrt(0.5), sqrt(0.5), 0.5);
    /* Up through the bottom edge. */
    check_hit(scene, (vector_t){0.5, -2}, (vector_t){0.5, 2}, triangle, 0.5, 0, 0, -1, 0.5);
    /* From the left, through the vertical edge x = 0. */
    check_hit(scene, (vector_t){-1, 0.5}, (vector_t){1, 0.5}, triangle, 0, 0.5, -1, 0, 0.5);
    scene_free(scene);
}

static void ray_that_misses_hits_nothing(void) {
    scene_t *scene = scene_init();
    add_box(scene, (vector_t){0, 0}, 1.0, 0.0, 1.0);
    add_triangle(scene, (vector_t){5, 0});
    ray_hit_t hit = {NULL, {7, 7}, {7, 7}, 7};
    CHECK(!scene_ray_cast(scene, (vector_t){-5, 3}, (vector_t){10, 3}, &hit));
    /* Stops short of the box. */
    CHECK(!scene_ray_cast(scene, (vector_t){-5, 0}, (vector_t){-1.5, 0}, &hit));
    /* Passes the triangle's hypotenuse by: x + y = 2.5 > 2. */
    CHECK(!scene_ray_cast(scene, (vector_t){5, 2.5}, (vector_t){7.5, 0}, &hit));
    CHECK(!scene_ray_cast(scene, (vector_t){-5, 0}, (vector_t){-5, 0}, &hit));
    CHECK(hit.body == NULL && hit.fraction == 7);
    scene_t *empty = scene_init();
    CHECK(!scene_ray_cast(empty, (vector_t){-5, 0}, (vector_t){5, 0}, &hit));
    scene_free(empty);
    scene_free(scene);
}

static void ray_from_inside_ignores_that_body(void) {
    scene_t *scene = scene_init();
    add_box(scene, (vector_t){0, 0}, 1.0, 0.0, 1.0);
    ray_hit_t hit;
    CHECK(!scene_ray_cast(scene, (vector_t){0, 0}, (vector_t){5, 0}, &hit));
    /* From a point of the boundary, inward or outward. */
    CHECK(!scene_ray_cast(scene, (vector_t){-1, 0}, (vector_t){5, 0}, &hit));
    body_t *beyond = add_box(scene, (vector_t){3, 0}, 0.5, 0.0, 1.0);
    check_hit(scene, (vector_t){0, 0}, (vector_t){5, 0}, beyond, 2.5, 0, -1, 0, 0.5);
    scene_free(scene);
}

static void ray_through_two_bodies_hits_the_nearer(void) {
    scene_t *scene = scene_init();
    body_t *far = add_box(scene, (vector_t){6, 0}, 1.0, 0.0, 1.0);
    body_t *near = add_box(scene, (vector_t){2, 0}, 0.5, 0.3, 1.0);
    ray_hit_t hit;
    CHECK(scene_ray_cast(scene, (vector_t){0, 0}, (vector_t){10, 0}, &hit));
    CHECK(hit.body == near);
    /* The other way the far one is nearer. */
    check_hit(scene, (vector_t){10, 0}, (vector_t){0, 0}, far, 7, 0, 1, 0, 0.3);
    scene_free(scene);
}

static void box_query_tests_shapes_not_boxes(void) {
    scene_t *scene = scene_init();
    /* A square turned 45 degrees: the diamond |x| + |y| <= sqrt 2, its
     * bounding box [-sqrt 2, sqrt 2]^2. */
    body_t *diamond = add_box(scene, (vector_t){0, 0}, 1.0, M_PI / 4, 1.0);
    body_t *found[4];
    CHECK(scene_query_box(scene, (vector_t){1.0, 1.0}, (vector_t){1.3, 1.3}, found, 4) == 0);
    CHECK(scene_query_box(scene, (vector_t){-1.3, -1.3}, (vector_t){-0.75, -0.75}, found, 4) == 0);
    CHECK(scene_query_box(scene, (vector_t){0.6, 0.6}, (vector_t){0.8, 0.8}, found, 4) == 1);
    CHECK(found[0] == diamond);
    /* Touching the rightmost vertex (about (sqrt 2, 0)) counts. */
    double r = body_get_bounds(diamond).max.x;
    CHECK_NEAR(r, sqrt(2.0), 1e-15);
    CHECK(scene_query_box(scene, (vector_t){r, -1}, (vector_t){r + 1, 1}, found, 4) == 1);
    CHECK(scene_query_box(scene, (vector_t){r + 1e-12, -1}, (vector_t){r + 1, 1}, found, 4) == 0);
    /* More bodies than room: the count, the first in the order added. */
    body_t *a = add_box(scene, (vector_t){3, 0}, 0.5, 0.0, 1.0);
    body_t *b = add_box(scene, (vector_t){-3, 0}, 0.5, 0.0, INFINITY);
    CHECK(scene_query_box(scene, (vector_t){-5, -5}, (vector_t){5, 5}, found, 2) == 3);
    CHECK(found[0] == diamond && found[1] == a);
    CHECK(scene_query_box(scene, (vector_t){-5, -5}, (vector_t){5, 5}, NULL, 0) == 3);
    CHECK(scene_query_box(scene, (vector_t){-5, -5}, (vector_t){-2, 5}, found, 4) == 1);
    CHECK(found[0] == b);
    body_remove(a);
    CHECK(scene_query_box(scene, (vector_t){-5, -5}, (vector_t){5, 5}, found, 4) == 2);
    scene_free(scene);
}

static void body_at_edges_inside_outside_and_on_top(void) {
    scene_t *scene = scene_init();
    body_t *lower = add_box(scene, (vector_t){0, 0}, 1.0, 0.0, 1.0);
    body_t *upper = add_box(scene, (vector_t){1.5, 0}, 1.0, 0.0, 1.0); /* overlaps [0.5, 1] */
    body_t *triangle = add_triangle(scene, (vector_t){5, 0});
    CHECK(scene_body_at(scene, (vector_t){-0.5, 0.3}) == lower);
    CHECK(scene_body_at(scene, (vector_t){-1, 0.3}) == lower);  /* on the left edge */
    CHECK(scene_body_at(scene, (vector_t){-1, -1}) == lower);   /* on a corner */
    CHECK(scene_body_at(scene, (vector_t){-1 - 1e-9, 0}) == NULL);
    CHECK(scene_body_at(scene, (vector_t){0.75, 0}) == upper);  /* both: the one added last */
    CHECK(scene_body_at(scene, (vector_t){2.5, 1}) == upper);
    CHECK(scene_body_at(scene, (vector_t){6, 1}) == triangle);  /* on the hypotenuse */
    CHECK(scene_body_at(scene, (vector_t){6, 1 + 1e-9}) == NULL);
    CHECK(scene_body_at(scene, (vector_t){5.5, 0.5}) == triangle);
    body_remove(upper);
    CHECK(scene_body_at(scene, (vector_t){0.75, 0}) == lower);
    /* A pose set between ticks is seen by the next query. */
    body_set_centroid(lower, (vector_t){20, 20});
    CHECK(scene_body_at(scene, (vector_t){0, 0}) == NULL);
    CHECK(scene_body_at(scene, (vector_t){20.5, 19.5}) == lower);
    scene_free(scene);
}

static void explosion_impulses_are_exact(void) {
    scene_t *scene = scene_init();
    /* Nearest points 2.5 m and 3.5 m from the centre, on the line through
     * the centroid: no spin. */
    body_t *right = add_box(scene, (vector_t){3, 0}, 0.5, 0.0, 2.0);
    body_t *above = add_box(scene, (vector_t){0, 4}, 0.5, 0.0, 4.0);
    body_t *outside = add_box(scene, (vector_t){-5.6, 0}, 0.5, 0.0, 1.0); /* 5.1 m away */
    body_t *fixed = add_box(scene, (vector_t){0, -2}, 0.5, 0.0, INFINITY);
    body_t *around = add_box(scene, (vector_t){0.25, -0.1}, 0.5, 0.0, 3.0); /* holds the centre */
    scene_explode(scene, (vector_t){0, 0}, 5.0, 10.0);
    scene_tick(scene, 0.01);
    /* momentum = impulse (1 - d / r) along the direction */
    vector_t p_right = vec_multiply(2.0, body_get_velocity(right));
    CHECK_VEC(p_right, 10.0 * (1 - 2.5 / 5), 0.0, EXACT);
    CHECK_NEAR(body_get_angular_velocity(right), 0.0, EXACT);
    vector_t p_above = vec_multiply(4.0, body_get_velocity(above));
    CHECK_VEC(p_above, 0.0, 10.0 * (1 - 3.5 / 5), EXACT);
    CHECK_VEC(body_get_velocity(outside), 0.0, 0.0, 0.0);
    CHECK_VEC(body_get_velocity(fixed), 0.0, 0.0, 0.0);
    /* d = 0: the whole impulse, from the centre to the centroid. */
    vector_t p_around = vec_multiply(3.0, body_get_velocity(around));
    double length = sqrt(0.25 * 0.25 + 0.1 * 0.1);
    CHECK_VEC(p_around, 10.0 * 0.25 / length, -10.0 * 0.1 / length, EXACT);
    scene_free(scene);
}

static void explosion_spins_off_centre_and_wakes_sleepers(void) {
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    body_t *box = add_box(scene, (vector_t){3, 0}, 0.5, 0.0, 1.0);
    body_t *sleeper = add_box(scene, (vector_t){0, 3}, 0.5, 0.0, 1.0);
    size_t island = 0;
    scene_restore_sleep(scene, &sleeper, &island, 1);
    CHECK(body_is_sleeping(sleeper));
    /* Nearest point: the corner (2.5, -0.5), off the line through the
     * centroid, so the impulse spins the box as well. */
    scene_explode(scene, (vector_t){0, -2}, 8.0, 8.0);
    CHECK(!body_is_sleeping(sleeper));
    scene_tick(scene, 0.01);
    double d = sqrt(8.5), magnitude = 8.0 * (1 - d / 8.0);
    vector_t j = {magnitude * 2.5 / d, magnitude * 1.5 / d};
    CHECK_VEC(body_get_velocity(box), j.x, j.y, EXACT);
    /* Lever arm (-0.5, -0.5) from the centroid: torque r x J. */
    double torque = -0.5 * j.y + 0.5 * j.x;
    CHECK_NEAR(body_get_angular_velocity(box), torque / body_get_inertia(box), EXACT);
    CHECK(body_get_velocity(sleeper).y > 0.0);
    scene_free(scene);
}

/* ---- Against a brute-force scan ------------------------------------------- */

/* The test's own geometry, from the public API: the body's world polygon. */
typedef struct {
    vector_t v[16];
    size_t n;
} shape_t;

static shape_t shape_of(body_t *body) {
    shape_t s = {.n = 0};
    polygon_t polygon = body_get_polygon(body);
    for (size_t i = 0; i < polygon.count && i < 16; i++) s.v[s.n++] = polygon.vertices[i];
    return s;
}

/* The segment's entering fraction into a convex CCW polygon, by edges
 * crossed (not half-planes): -1 when it starts inside or misses. */
static double brute_ray(const shape_t *s, vector_t from, vector_t to) {
    vector_t d = vec_subtract(to, from);
    bool inside = true;
    double best = INFINITY;
    for (size_t i = 0; i < s->n; i++) {
        vector_t a = s->v[i], b = s->v[(i + 1) % s->n];
        vector_t e = vec_subtract(b, a);
        if (vec_cross(e, vec_subtract(from, a)) < 0.0) inside = false;
        double denominator = vec_cross(d, e);
        if (denominator == 0.0) continue;
        vector_t w = vec_subtract(a, from);
        double t = vec_cross(w, e) / denominator, u = vec_cross(w, d) / denominator;
        if (t >= 0.0 && t <= 1.0 && u >= -1e-12 && u <= 1.0 + 1e-12 && t < best) best = t;
    }
    return inside || best == INFINITY ? -1.0 : best;
}

static bool brute_overlaps(const shape_t *s, vector_t min, vector_t max) {
    vector_t box[4] = {{min.x, min.y}, {max.x, min.y}, {max.x, max.y}, {min.x, max.y}};
    double lo = INFINITY, hi = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
    for (size_t i = 0; i < s->n; i++) {
        lo = fmin(lo, s->v[i].x), hi = fmax(hi, s->v[i].x);
        lo_y = fmin(lo_y, s->v[i].y), hi_y = fmax(hi_y, s->v[i].y);
    }
    if (hi < min.x || lo > max.x || hi_y < min.y || lo_y > max.y) return false;
    for (size_t i = 0; i < s->n; i++) {
        vector_t a = s->v[i], e = vec_subtract(s->v[(i + 1) % s->n], a);
        bool all_outside = true;
        for (int k = 0; k < 4; k++) all_outside &= vec_cross(e, vec_subtract(box[k], a)) < 0.0;
        if (all_outside) return false;
    }
    return true;
}

static double uniform(double lo, double hi) {
    return lo + (hi - lo) * ((double)rand() / RAND_MAX);
}

static vector_t random_point(void) {
    return (vector_t){uniform(-16, 16), uniform(-2, 30)};
}

static scene_t *random_pile(void) {
    srand(23);
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    scene_set_gravity(scene, (vector_t){0, -9.81});
    scene_add_body(scene, body_init(polygon_make_box((vector_t){0, -1}, 15, 1), INFINITY, GREY));
    scene_add_body(scene, body_init(polygon_make_box((vector_t){-14, 12}, 1, 12), INFINITY, GREY));
    scene_add_body(scene, body_init(polygon_make_box((vector_t){14, 12}, 1, 12), INFINITY, GREY));
    for (int i = 0; i < 500; i++) {
        vector_t at = {-12 + 1.2 * (i % 20) + uniform(0, 0.1), 0.8 + 1.2 * (i / 20)};
        size_t sides = 3 + (size_t)(rand() % 5);
        list_t *shape = sides == 4 ? polygon_make_box(at, 0.5, uniform(0.2, 0.5))
                                   : polygon_make_regular(sides, 0.5, at, uniform(0, 6.28));
        scene_add_body(scene, body_init(shape, 1.0, GREY));
    }
    for (int i = 0; i < 100; i++) scene_tick(scene, 1.0 / 60.0);
    return scene;
}

static void queries_agree_with_brute_force(void) {
    scene_t *scene = random_pile();
    size_t count = scene_bodies(scene);
    shape_t *shapes = malloc(count * sizeof(shape_t));
    for (size_t i = 0; i < count; i++) shapes[i] = shape_of(scene_get_body(scene, i));
    for (int k = 0; k < 300; k++) {
        vector_t from = random_point(), to = random_point();
        double best = INFINITY;
        size_t best_index = SIZE_MAX;
        for (size_t i = 0; i < count; i++) {
            double t = brute_ray(&shapes[i], from, to);
            if (t >= 0.0 && t < best) best = t, best_index = i;
        }
        ray_hit_t hit;
        bool found = scene_ray_cast(scene, from, to, &hit);
        CHECK(found == (best_index != SIZE_MAX));
        if (found && best_index != SIZE_MAX) {
            CHECK_NEAR(hit.fraction, best, 1e-9);
            /* the same body, or one entered at the same fraction */
            CHECK(hit.body == scene_get_body(scene, best_index) ||
                  fabs(brute_ray(&shapes[best_index], from, to) - hit.fraction) <= 1e-9);
        }
    }
    body_t **found = malloc(count * sizeof(body_t *));
    for (int k = 0; k < 300; k++) {
        vector_t a = random_point(), size = {uniform(0, 4), uniform(0, 4)};
        vector_t b = vec_add(a, size);
        size_t n = scene_query_box(scene, a, b, found, count), j = 0;
        bool same = true;
        for (size_t i = 0; i < count; i++) {
            if (!brute_overlaps(&shapes[i], a, b)) continue;
            same &= j < n && found[j] == scene_get_body(scene, i);
            j++;
        }
        CHECK(same && j == n);
    }
    for (int k = 0; k < 300; k++) {
        vector_t p = random_point();
        body_t *top = NULL;
        for (size_t i = 0; i < count; i++) {
            if (body_contains_point(scene_get_body(scene, i), p)) top = scene_get_body(scene, i);
        }
        CHECK(scene_body_at(scene, p) == top);
    }
    free(found);
    free(shapes);
    scene_free(scene);
}

BAD_CALL(ray_nan, {
    scene_t *scene = scene_init();
    ray_hit_t hit;
    scene_ray_cast(scene, (vector_t){NAN, 0}, (vector_t){1, 0}, &hit);
})
BAD_CALL(ray_null_hit, scene_ray_cast(scene_init(), (vector_t){0, 0}, (vector_t){1, 0}, NULL))
BAD_CALL(box_inverted, scene_query_box(scene_init(), (vector_t){1, 0}, (vector_t){0, 1}, NULL, 0))
BAD_CALL(box_null_bodies,
         scene_query_box(scene_init(), (vector_t){0, 0}, (vector_t){1, 1}, NULL, 3))
BAD_CALL(at_infinite, scene_body_at(scene_init(), (vector_t){INFINITY, 0}))
BAD_CALL(explode_zero_radius, scene_explode(scene_init(), (vector_t){0, 0}, 0.0, 1.0))
BAD_CALL(explode_nan_impulse, scene_explode(scene_init(), (vector_t){0, 0}, 1.0, NAN))

static void bad_input_stops_with_the_function_named(void) {
    CHECK_DIES(ray_nan, NULL, "engine error in scene_ray_cast:", "from is not finite");
    CHECK_DIES(ray_null_hit, NULL, "engine error in scene_ray_cast:", "hit is NULL");
    CHECK_DIES(box_inverted, NULL, "engine error in scene_query_box:", "min (1, 0)");
    CHECK_DIES(box_null_bodies, NULL, "engine error in scene_query_box:", "bodies is NULL");
    CHECK_DIES(at_infinite, NULL, "engine error in scene_body_at:", "point is not finite");
    CHECK_DIES(explode_zero_radius, NULL, "engine error in scene_explode:", "radius must be");
    CHECK_DIES(explode_nan_impulse, NULL, "engine error in scene_explode:", "impulse must be");
}


/* Round bodies and chains are queried on their exact shapes: a ray enters
 * a circle and a capsule where the closed forms say, to 1e-12, where the
 * 32-vertex outline would be up to 0.5% of the radius off. */
static void ray_hits_round_bodies_exactly(void) {
    scene_t *scene = scene_init();
    body_t *ball = body_init_circle((vector_t){0, 0}, 1.0, 1.0, GREY);
    scene_add_body(scene, ball);
    /* A ray at height h enters the unit circle at x = -sqrt(1 - h^2). */
    for (int k = 0; k < 8; k++) {
        double h = 0.11 * k;
        double x = -sqrt(1.0 - h * h);
        check_hit(scene, (vector_t){-3, h}, (vector_t){3, h}, ball, x, h, x, h, (x + 3.0) / 6.0);
    }
    body_set_centroid(ball, (vector_t){0, 10});
    body_t *rod = body_init_capsule((vector_t){-1, 0}, (vector_t){1, 0}, 0.5, 1.0, GREY);
    scene_add_body(scene, rod);
    /* Down onto the flat side, and onto an end's half-disc. */
    check_hit(scene, (vector_t){0.3, 3}, (vector_t){0.3, -3}, rod, 0.3, 0.5, 0, 1, 2.5 / 6.0);
    double y = sqrt(0.25 - 0.09);
    check_hit(scene, (vector_t){1.3, 3}, (vector_t){1.3, -3}, rod, 1.3, y, 0.3 / 0.5, y / 0.5,
              (3.0 - y) / 6.0);
    scene_free(scene);
}

/* A box query and the body at a point find a circle by its true rim: a
 * point just inside the rim between two outline vertices is in it, one
 * just outside is not. */
static void box_and_point_queries_see_the_true_rim(void) {
    scene_t *scene = scene_init();
    body_t *ball = body_init_circle((vector_t){0, 0}, 1.0, 1.0, GREY);
    scene_add_body(scene, ball);
    double angle = M_PI / 32.0; /* halfway between outline vertices */
    vector_t rim = {cos(angle), sin(angle)};
    vector_t inside = vec_multiply(1.0 - 1e-12, rim), outside = vec_multiply(1.0 + 1e-12, rim);
    CHECK(scene_body_at(scene, inside) == ball);
    CHECK(scene_body_at(scene, outside) == NULL);
    CHECK(scene_query_box(scene, inside, vec_add(inside, (vector_t){1, 1}), NULL, 0) == 1);
    CHECK(scene_query_box(scene, outside, vec_add(outside, (vector_t){1, 1}), NULL, 0) == 0);
    CHECK(body_contains_point(ball, inside) && !body_contains_point(ball, outside));
    /* A capsule's rim about an end. */
    body_t *rod = body_init_capsule((vector_t){3, 0}, (vector_t){5, 0}, 0.5, 1.0, GREY);
    scene_add_body(scene, rod);
    vector_t end_rim = {5.0 + 0.5 * cos(0.7), 0.5 * sin(0.7)};
    CHECK(scene_body_at(scene, vec_add(end_rim, (vector_t){-1e-12, 0})) == rod);
    CHECK(scene_body_at(scene, vec_add(end_rim, (vector_t){1e-12, 0})) == NULL);
    scene_free(scene);
}

/* The explosion's distance to a circle is exact: a ball of radius 1 and
 * mass 1 whose centre is 3 m from the centre of a blast of radius 4 gets
 * impulse 10 (1 - 2/4) along the line of centres, at its rim. */
static void explosion_reaches_round_bodies_exactly(void) {
    scene_t *scene = scene_init();
    /* Towards the blast, the ball's rim lies halfway between two vertices
     * of its outline. */
    double a = M_PI / 32.0;
    body_t *ball = body_init_circle((vector_t){3 * cos(a), 3 * sin(a)}, 1.0, 1.0, GREY);
    scene_add_body(scene, ball);
    scene_explode(scene, (vector_t){0, 0}, 4.0, 10.0);
    scene_tick(scene, 1e-3);
    CHECK_VEC(body_get_velocity(ball), 5.0 * cos(a), 5.0 * sin(a), EXACT);
    CHECK_NEAR(body_get_angular_velocity(ball), 0.0, EXACT);
    scene_free(scene);
}

/* A chain is queried on its segments: a ray from its free side hits the
 * segment it crosses with that segment's normal, one from behind passes;
 * a box and a point find it only on a segment. */
static void chains_are_queried_on_their_segments(void) {
    scene_t *scene = scene_init();
    vector_t points[3] = {{0, 0}, {2, 0}, {4, 2}};
    body_t *chain = body_init_chain(points, 3, false, GREY);
    scene_add_body(scene, chain);
    check_hit(scene, (vector_t){1, 1}, (vector_t){1, -1}, chain, 1, 0, 0, 1, 0.5);
    double s = sqrt(0.5);
    check_hit(scene, (vector_t){2, 2}, (vector_t){4, 0}, chain, 3, 1, -s, s, 0.5);
    ray_hit_t hit;
    CHECK(!scene_ray_cast(scene, (vector_t){1, -1}, (vector_t){1, 1}, &hit)); /* from behind */
    CHECK(scene_body_at(scene, (vector_t){1, 0}) == chain);
    CHECK(scene_body_at(scene, (vector_t){3, 1}) == chain);
    CHECK(scene_body_at(scene, (vector_t){3, 0.5}) == NULL); /* under the slope: no inside */
    CHECK(scene_query_box(scene, (vector_t){2.9, 0.1}, (vector_t){3.2, 0.5}, NULL, 0) == 0);
    CHECK(scene_query_box(scene, (vector_t){2.9, 0.1}, (vector_t){3.2, 1.0}, NULL, 0) == 1);
    scene_free(scene);
}

TEST_SUITE(queries, TEST_CASE(ray_hits_box_at_known_angles),
           TEST_CASE(ray_hits_triangle_at_known_angles), TEST_CASE(ray_that_misses_hits_nothing),
           TEST_CASE(ray_from_inside_ignores_that_body),
           TEST_CASE(ray_through_two_bodies_hits_the_nearer),
           TEST_CASE(box_query_tests_shapes_not_boxes),
           TEST_CASE(body_at_edges_inside_outside_and_on_top),
           TEST_CASE(explosion_impulses_are_exact),
           TEST_CASE(explosion_spins_off_centre_and_wakes_sleepers),
           TEST_CASE(queries_agree_with_brute_force),
           TEST_CASE(bad_input_stops_with_the_function_named),
           TEST_CASE(ray_hits_round_bodies_exactly),
           TEST_CASE(box_and_point_queries_see_the_true_rim),
           TEST_CASE(explosion_reaches_round_bodies_exactly),
           TEST_CASE(chains_are_queried_on_their_segments));
