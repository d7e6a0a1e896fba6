/* body.h: construction, ownership, pose, the seed tick, accumulators,
 * removal marks, rotation and the geometric queries. */
#include <stdlib.h>
#include <string.h>
#include "jostle/body.h"
#include "jostle/polygon.h"
#include "test.h"


static const rgb_color_t RED = {1, 0, 0};


/* A w x h box centred at c. */
static body_t *box_body(vector_t c, double w, double h, double mass) {
    return body_init(polygon_make_box(c, w / 2, h / 2), mass, RED);
}

static vector_t shape_vertex(list_t *shape, size_t i) {
    return *(vector_t *)list_get(shape, i);
}


static void init_starts_at_rest_at_the_area_centroid(void) {
    /* Area centroid (10/9, 7/9); the vertex mean would be (1, 3/4). */
    rgb_color_t color = {0.25, 0.5, 0.75};
    body_t *body = body_init(POLYGON({0, 0}, {2, 0}, {2, 2}, {0, 1}), 3.0, color);
    CHECK_VEC(body_get_centroid(body), 10.0 / 9.0, 7.0 / 9.0, 1e-15);
    CHECK(body_get_velocity(body).x == 0.0 && body_get_velocity(body).y == 0.0);
    CHECK(body_get_rotation(body) == 0.0);
    CHECK(body_get_angular_velocity(body) == 0.0);
    CHECK(body_get_mass(body) == 3.0);
    rgb_color_t got = body_get_color(body);
    CHECK(got.r == 0.25 && got.g == 0.5 && got.b == 0.75);
    CHECK(body_get_info(body) == NULL);
    CHECK(!body_is_removed(body));
    CHECK(body_get_elasticity(body) == 0.0);
    CHECK(body_get_friction(body) == 0.6);
    CHECK(body_get_kinetic_energy(body) == 0.0);
    body_free(body);
}

static void init_takes_the_shape_and_free_releases_everything(void) {
    list_t *shape = POLYGON({0, 0}, {1, 0}, {1, 1}, {0, 1});
    body_t *body = body_init(shape, 1.0, RED);
    /* The caller must not free shape: the body did or will. */
    body_free(body);
    CHECK(test_no_leaks());
    body_t *other = body_init_with_info(polygon_make_regular(7, 1.0, VEC_ZERO, 0), 1.0, RED,
                                        NULL, NULL);
    body_free(other);
    CHECK(test_no_leaks());
}

static int info_freed = 0;
static void *info_freed_pointer = NULL;
static void count_info_free(void *info) {
    info_freed++;
    info_freed_pointer = info;
    free(info);
}

static void info_is_returned_and_freed_with_its_freer(void) {
    int *info = malloc(sizeof *info);
    *info = 42;
    body_t *body = body_init_with_info(polygon_make_box(VEC_ZERO, 1, 1), 2.0, RED, info,
                                       count_info_free);
    CHECK(body_get_info(body) == info);
    CHECK(*(int *)body_get_info(body) == 42);
    CHECK(info_freed == 0);
    body_free(body);
    CHECK(info_freed == 1);
    CHECK(info_freed_pointer == info);

    /* Without a freer the info stays the caller's. */
    int mine = 7;
    body_t *plain = body_init_with_info(polygon_make_box(VEC_ZERO, 1, 1), 2.0, RED, &mine, NULL);
    CHECK(body_get_info(plain) == &mine);
    body_free(plain);
    CHECK(mine == 7 && info_freed == 1);
    CHECK(test_no_leaks());
}

static void get_shape_is_a_new_copy_of_the_world_vertices(void) {
    const vector_t points[4] = {{1, 1}, {3, 1}, {3, 2}, {1, 2}};
    body_t *body = body_init(test_make_polygon(points, 4), 1.0, RED);
    list_t *shape = body_get_shape(body);
    CHECK(list_size(shape) == 4);
    for (size_t i = 0; i < 4; i++) {
        CHECK_VEC(shape_vertex(shape, i), points[i].x, points[i].y, 1e-15);
    }
    /* Changing the copy changes nothing in the body. */
    ((vector_t *)list_get(shape, 0))->x = 100;
    list_t *again = body_get_shape(body);
    CHECK(again != shape);
    CHECK(list_get(again, 0) != list_get(shape, 0));
    CHECK_VEC(shape_vertex(again, 0), 1, 1, 1e-15);
    CHECK_VEC(body_get_centroid(body), 2, 1.5, 1e-15);
    list_free(shape); /* frees the vectors too */
    list_free(again);
    body_free(body);
    CHECK(test_no_leaks());
}

static void clockwise_shape_is_reversed(void) {
    body_t *body = body_init(POLYGON({0, 0}, {0, 2}, {2, 2}, {2, 0}), 1.0, RED);
    list_t *shape = body_get_shape(body);
    CHECK(polygon_is_counterclockwise(shape));
    CHECK_NEAR(polygon_area(shape), 4.0, 1e-15);
    /* Same vertex set. */
    for (size_t i = 0; i < 4; i++) {
        vector_t v = shape_vertex(shape, i);
        CHECK((v.x == 0.0 || v.x == 2.0) && (v.y == 0.0 || v.y == 2.0));
    }
    CHECK_VEC(body_get_centroid(body), 1, 1, 1e-15);
    list_free(shape);
    /* Its polygon view is counter-clockwise with outward normals. */
    polygon_t view = body_get_polygon(body);
    for (size_t i = 0; i < view.count; i++) {
        vector_t mid = vec_multiply(0.5, vec_add(view.vertices[i], view.vertices[(i + 1) % 4]));
        CHECK(vec_dot(view.normals[i], vec_subtract(mid, (vector_t){1, 1})) > 0.0);
    }
    CHECK_NEAR(body_get_inertia(body), 1.0 * (4 + 4) / 12.0, 1e-14);
    body_free(body);
}

static void polygon_view_has_vertices_and_outward_unit_normals(void) {
    body_t *body = body_init(POLYGON({0, 0}, {4, 0}, {0, 3}), 1.0, RED);
    polygon_t view = body_get_polygon(body);
    CHECK(view.count == 3);
    CHECK_VEC(view.vertices[0], 0, 0, 1e-15);
    CHECK_VEC(view.vertices[1], 4, 0, 1e-15);
    CHECK_VEC(view.vertices[2], 0, 3, 1e-15);
    CHECK_VEC(view.normals[0], 0, -1, 1e-15);       /* bottom edge */
    CHECK_VEC(view.normals[1], 0.6, 0.8, 1e-15);    /* hypotenuse */
    CHECK_VEC(view.normals[2], -1, 0, 1e-15);       /* left edge */
    /* After a move, a new view shows the new pose. */
    body_set_centroid(body, vec_add(body_get_centroid(body), (vector_t){10, 0}));
    body_set_rotation(body, M_PI);
    view = body_get_polygon(body);
    CHECK_VEC(view.normals[0], 0, 1, 1e-15);
    CHECK_VEC(view.normals[2], 1, 0, 1e-15);
    vector_t c = body_get_centroid(body); /* (4/3, 1) + (10, 0) */
    CHECK_VEC(c, 10 + 4.0 / 3.0, 1, 1e-14);
    CHECK_VEC(view.vertices[0], c.x + 4.0 / 3.0, c.y + 1.0, 1e-14);
    body_free(body);
}

static void set_centroid_translates_the_shape(void) {
    body_t *body = box_body((vector_t){1, 1}, 2, 2, 1.0);
    body_set_centroid(body, (vector_t){-3, 5});
    CHECK_VEC(body_get_centroid(body), -3, 5, 0);
    list_t *shape = body_get_shape(body);
    CHECK_VEC(polygon_centroid(shape), -3, 5, 1e-14);
    CHECK_VEC(shape_vertex(shape, 0), -4, 4, 1e-14);
    CHECK_VEC(shape_vertex(shape, 2), -2, 6, 1e-14);
    CHECK_NEAR(polygon_area(shape), 4.0, 1e-14);
    list_free(shape);
    CHECK(body_get_rotation(body) == 0.0);
    body_free(body);
}

static void set_rotation_is_absolute_about_the_centroid(void) {
    body_t *body = box_body((vector_t){2, 3}, 4, 2, 1.0);
    body_set_rotation(body, M_PI / 2);
    body_set_rotation(body, M_PI / 2); /* absolute: not a half turn */
    CHECK(body_get_rotation(body) == M_PI / 2);
    CHECK_VEC(body_get_centroid(body), 2, 3, 0);
    list_t *shape = body_get_shape(body);
    /* The lower-left corner (-2, -1) from the centre, turned a quarter. */
    CHECK_VEC(shape_vertex(shape, 0), 2 + 1, 3 - 2, 1e-14);
    CHECK_VEC(polygon_centroid(shape), 2, 3, 1e-14);
    list_free(shape);
    aabb_t bounds = body_get_bounds(body);
    CHECK_VEC(bounds.min, 1, 1, 1e-14);
    CHECK_VEC(bounds.max, 3, 5, 1e-14);
    /* Back to 0: the original shape. */
    body_set_rotation(body, 0.0);
    shape = body_get_shape(body);
    CHECK_VEC(shape_vertex(shape, 0), 0, 2, 1e-14);
    list_free(shape);
    /* Moving after rotating keeps the rotation. */
    body_set_rotation(body, 0.3);
    body_set_centroid(body, VEC_ZERO);
    CHECK(body_get_rotation(body) == 0.3);
    shape = body_get_shape(body);
    vector_t expected = vec_rotate((vector_t){-2, -1}, 0.3);
    CHECK_VEC(shape_vertex(shape, 0), expected.x, expected.y, 1e-14);
    list_free(shape);
    body_free(body);
}

static void setters_and_getters(void) {
    body_t *body = box_body(VEC_ZERO, 1, 1, 2.0);
    body_set_velocity(body, (vector_t){3, -4});
    CHECK_VEC(body_get_velocity(body), 3, -4, 0);
    body_set_color(body, (rgb_color_t){0.1, 0.2, 0.3});
    CHECK(body_get_color(body).r == 0.1 && body_get_color(body).g == 0.2 &&
          body_get_color(body).b == 0.3);
    body_set_angular_velocity(body, -2.5);
    CHECK(body_get_angular_velocity(body) == -2.5);
    body_set_elasticity(body, 0.8);
    CHECK(body_get_elasticity(body) == 0.8);
    body_set_elasticity(body, 1.5); /* > 1 is allowed */
    CHECK(body_get_elasticity(body) == 1.5);
    body_set_friction(body, 0.0);
    CHECK(body_get_friction(body) == 0.0);
    body_set_inertia(body, 7.0);
    CHECK(body_get_inertia(body) == 7.0);
    body_set_collision_filter(body, 2, 0xF0, 3); /* accepted; world contacts use it */
    body_free(body);
}

static void tick_follows_the_seed_scheme(void) {
    /* v' = v + (F / m) dt + J / m; x' = x + dt (v + v') / 2. */
    const double m = 2.0, dt = 0.25;
    body_t *body = box_body((vector_t){1, -1}, 1, 1, m);
    vector_t v = {0.5, -1.5}, f = {4, 2}, j = {-1, 3};
    body_set_velocity(body, v);
    body_add_force(body, f);
    body_add_impulse(body, j);
    body_tick(body, dt);
    vector_t v2 = {v.x + f.x / m * dt + j.x / m, v.y + f.y / m * dt + j.y / m};
    CHECK_VEC(body_get_velocity(body), v2.x, v2.y, 1e-15);
    CHECK_VEC(body_get_centroid(body), 1 + dt * (v.x + v2.x) / 2, -1 + dt * (v.y + v2.y) / 2,
              1e-15);
    /* Cleared: the next tick moves at constant velocity. */
    body_tick(body, dt);
    CHECK_VEC(body_get_velocity(body), v2.x, v2.y, 1e-15);
    CHECK_VEC(body_get_centroid(body), 1 + dt * (v.x + v2.x) / 2 + dt * v2.x,
              -1 + dt * (v.y + v2.y) / 2 + dt * v2.y, 1e-14);
    /* The shape went along. */
    list_t *shape = body_get_shape(body);
    vector_t c = polygon_centroid(shape);
    CHECK_VEC(c, body_get_centroid(body).x, body_get_centroid(body).y, 1e-14);
    list_free(shape);
    CHECK(body_get_rotation(body) == 0.0); /* no torque, no turn */
    body_free(body);
}

static void constant_force_matches_free_fall_exactly(void) {
    /* The seed scheme is exact for a constant force: x = x0 + v0 t + a t^2 / 2. */
    const double m = 3.0, dt = 0.01;
    body_t *body = box_body(VEC_ZERO, 1, 1, m);
    body_set_velocity(body, (vector_t){2, 5});
    for (int i = 0; i < 100; i++) {
        body_add_force(body, (vector_t){0, -9.8 * m});
        body_tick(body, dt);
    }
    CHECK_VEC(body_get_centroid(body), 2.0, 5.0 - 4.9, 1e-12);
    CHECK_VEC(body_get_velocity(body), 2.0, 5.0 - 9.8, 1e-12);
    body_free(body);
}

static void forces_and_impulses_accumulate(void) {
    body_t *body = box_body(VEC_ZERO, 1, 1, 4.0);
    body_add_force(body, (vector_t){1, 0});
    body_add_force(body, (vector_t){3, 2});
    body_add_impulse(body, (vector_t){0, 1});
    body_add_impulse(body, (vector_t){2, 1});
    body_tick(body, 0.5);
    /* (4, 2) / 4 * 0.5 + (2, 2) / 4 */
    CHECK_VEC(body_get_velocity(body), 0.5 + 0.5, 0.25 + 0.5, 1e-15);
    body_free(body);
}

static void reset_clears_force_torque_and_impulses(void) {
    body_t *body = box_body((vector_t){1, 2}, 1, 1, 1.0);
    body_add_force(body, (vector_t){5, 5});
    body_add_impulse(body, (vector_t){-1, 2});
    body_add_torque(body, 3.0);
    body_add_impulse_at(body, (vector_t){0, 1}, (vector_t){1.5, 2});
    body_reset(body);
    body_tick(body, 0.1);
    CHECK_VEC(body_get_velocity(body), 0, 0, 0);
    CHECK_VEC(body_get_centroid(body), 1, 2, 0);
    CHECK(body_get_angular_velocity(body) == 0.0);
    CHECK(body_get_rotation(body) == 0.0);
    /* Accumulating again after a reset works. */
    body_add_impulse(body, (vector_t){1, 0});
    body_tick(body, 0.1);
    CHECK_VEC(body_get_velocity(body), 1, 0, 1e-15);
    body_free(body);
}

static void infinite_mass_is_immovable_but_can_be_kinematic(void) {
    body_t *wall = box_body((vector_t){5, 0}, 1, 10, INFINITY);
    CHECK(isinf(body_get_mass(wall)));
    CHECK(isinf(body_get_inertia(wall)));
    body_add_force(wall, (vector_t){1e6, -1e6});
    body_add_impulse(wall, (vector_t){-1e3, 1e3});
    body_add_torque(wall, 1e6);
    body_add_force_at(wall, (vector_t){0, 1e6}, (vector_t){5.5, 5});
    body_add_impulse_at(wall, (vector_t){0, 1e6}, (vector_t){5.5, 5});
    body_tick(wall, 0.1);
    CHECK_VEC(body_get_velocity(wall), 0, 0, 0);
    CHECK_VEC(body_get_centroid(wall), 5, 0, 0);
    CHECK(body_get_angular_velocity(wall) == 0.0);
    CHECK(body_get_rotation(wall) == 0.0);
    /* Given a velocity it moves at that velocity whatever pushes on it. */
    body_set_velocity(wall, (vector_t){1, 0});
    body_add_impulse(wall, (vector_t){-1e3, 0});
    body_tick(wall, 0.5);
    CHECK_VEC(body_get_velocity(wall), 1, 0, 0);
    CHECK_VEC(body_get_centroid(wall), 5.5, 0, 1e-15);
    CHECK(body_get_kinetic_energy(wall) == 0.0);
    body_free(wall);
}

static void remove_marks_and_is_idempotent(void) {
    body_t *body = box_body(VEC_ZERO, 1, 1, 1.0);
    CHECK(!body_is_removed(body));
    body_remove(body);
    CHECK(body_is_removed(body));
    body_remove(body);
    CHECK(body_is_removed(body));
    /* A mark does not free anything by itself. */
    CHECK(body_get_mass(body) == 1.0);
    body_free(body);
}

static void inertia_of_a_box(void) {
    /* m (w^2 + h^2) / 12, whatever the position, winding or rotation. */
    body_t *body = box_body((vector_t){7, -3}, 3, 1, 6.0);
    CHECK_RELATIVE(body_get_inertia(body), 6.0 * (9 + 1) / 12.0, 1e-14);
    body_set_rotation(body, 1.0);
    CHECK_RELATIVE(body_get_inertia(body), 5.0, 1e-14);
    body_free(body);
    body_t *cw = body_init(POLYGON({0, 0}, {0, 1}, {3, 1}, {3, 0}), 6.0, RED);
    CHECK_RELATIVE(body_get_inertia(cw), 5.0, 1e-14);
    body_free(cw);
}

static void init_accepts_a_unit_box_far_from_the_origin(void) {
    /* Mass 2, 1 m box: inertia 2 (1 + 1) / 12. A centre off the grid of
     * doubles rounds the corners to its spacing (1.2e-10 m at 1e6 m, 1.9e-6 m
     * at 1e10 m), which moves each side and the centroid by up to about that
     * much, and the inertia by twice that, relative. At 1e8 m the centre is
     * on the grid and the corners exact. */
    const struct {
        vector_t center;
        double position_tolerance, inertia_tolerance;
    } cases[] = {
        {{1e6 + 0.3, -1e6 - 0.7}, 1e-9, 1e-9},
        {{-1e8, 1e8}, 1e-9, 1e-9},
        {{1e10 + 0.3, -1e10 - 0.7}, 4e-6, 1e-5},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        vector_t c = cases[i].center;
        body_t *body = body_init(polygon_make_box(c, 0.5, 0.5), 2.0, RED);
        CHECK_VEC(body_get_centroid(body), c.x, c.y, cases[i].position_tolerance);
        CHECK(body_get_mass(body) == 2.0);
        CHECK_RELATIVE(body_get_inertia(body), 2.0 * 2.0 / 12.0, cases[i].inertia_tolerance);
        body_free(body);
    }
}

static void init_accepts_a_regular_100000_gon(void) {
    /* Turns of 6.3e-5 rad between edges 6.3e-5 m long are convex; the
     * inertia tends to the disc's, m R^2 / 2. */
    body_t *body = body_init(polygon_make_regular(100000, 1.0, (vector_t){2, 1}, 0.0), 4.0, RED);
    CHECK_VEC(body_get_centroid(body), 2, 1, 1e-12);
    CHECK(body_get_mass(body) == 4.0);
    CHECK_RELATIVE(body_get_inertia(body), 2.0, 1e-8);
    body_free(body);
}

static void impulse_at_a_point_gives_the_right_spin(void) {
    /* Box 2 x 1, m = 3: I = 3 (4 + 1) / 12 = 1.25. Impulse (0, 2) at the
     * right edge's middle, r = (1, 0): v = (0, 2/3), w = r x J / I = 1.6. */
    body_t *body = box_body((vector_t){4, 4}, 2, 1, 3.0);
    body_add_impulse_at(body, (vector_t){0, 2}, (vector_t){5, 4});
    const double dt = 0.01;
    body_tick(body, dt);
    CHECK_VEC(body_get_velocity(body), 0, 2.0 / 3.0, 1e-15);
    CHECK_NEAR(body_get_angular_velocity(body), 1.6, 1e-14);
    CHECK_NEAR(body_get_rotation(body), dt * 1.6 / 2, 1e-15); /* mean of 0 and 1.6 */
    /* Through the centroid: no spin. */
    body_t *straight = box_body(VEC_ZERO, 2, 1, 3.0);
    body_add_impulse_at(straight, (vector_t){3, -1}, VEC_ZERO);
    body_tick(straight, dt);
    CHECK(body_get_angular_velocity(straight) == 0.0);
    CHECK_VEC(body_get_velocity(straight), 1, -1.0 / 3.0, 1e-15);
    /* Opposite impulses at opposite corners: a pure couple. */
    body_t *couple = box_body(VEC_ZERO, 2, 2, 1.0); /* I = 2 * 4 / 12 = 2/3 */
    body_add_impulse_at(couple, (vector_t){1, 0}, (vector_t){0, -1});
    body_add_impulse_at(couple, (vector_t){-1, 0}, (vector_t){0, 1});
    body_tick(couple, dt);
    CHECK_VEC(body_get_velocity(couple), 0, 0, 1e-15);
    CHECK_NEAR(body_get_angular_velocity(couple), 2.0 / (2.0 / 3.0), 1e-14);
    body_free(body);
    body_free(straight);
    body_free(couple);
}

static void force_at_a_point_and_torque(void) {
    /* Square 2 x 2, m = 1.5: I = 1.5 * 8 / 12 = 1. Force (0, 3) at r = (1, 1):
     * torque 3, plus a torque 2 added directly: w' = 5 dt. */
    const double dt = 0.1;
    body_t *body = box_body((vector_t){-2, 0}, 2, 2, 1.5);
    body_add_force_at(body, (vector_t){0, 3}, (vector_t){-1, 1});
    body_add_torque(body, 2.0);
    body_tick(body, dt);
    CHECK_NEAR(body_get_angular_velocity(body), 5.0 * dt, 1e-15);
    CHECK_NEAR(body_get_rotation(body), dt * (0 + 5.0 * dt) / 2, 1e-15);
    CHECK_VEC(body_get_velocity(body), 0, 3 / 1.5 * dt, 1e-15);
    /* The angle keeps advancing at the new rate. */
    body_tick(body, dt);
    CHECK_NEAR(body_get_rotation(body), dt * 5.0 * dt / 2 + dt * 5.0 * dt, 1e-15);
    /* Spin turns the shape about the centroid. */
    list_t *shape = body_get_shape(body);
    vector_t c = body_get_centroid(body);
    vector_t expected = vec_add(c, vec_rotate((vector_t){-1, -1}, body_get_rotation(body)));
    CHECK_VEC(shape_vertex(shape, 0), expected.x, expected.y, 1e-14);
    list_free(shape);
    body_free(body);
}

static void set_inertia_overrides_and_infinity_stops_turning(void) {
    body_t *body = box_body(VEC_ZERO, 2, 2, 1.0);
    body_set_inertia(body, 4.0);
    body_add_torque(body, 8.0);
    body_tick(body, 0.5);
    CHECK_NEAR(body_get_angular_velocity(body), 8.0 / 4.0 * 0.5, 1e-15);
    body_set_angular_velocity(body, 0.0);
    body_set_inertia(body, INFINITY);
    body_add_torque(body, 8.0);
    body_add_impulse_at(body, (vector_t){0, 1}, (vector_t){1, 0});
    body_tick(body, 0.5);
    CHECK(body_get_angular_velocity(body) == 0.0);
    CHECK_VEC(body_get_velocity(body), 0, 1, 1e-15); /* still moves */
    body_free(body);
}

static void point_velocity_adds_spin(void) {
    body_t *body = box_body((vector_t){1, 1}, 2, 2, 1.0);
    body_set_velocity(body, (vector_t){1, 2});
    body_set_angular_velocity(body, 3.0);
    /* r = (0.5, -1): w x r = (3, 1.5). */
    CHECK_VEC(body_get_point_velocity(body, (vector_t){1.5, 0}), 4, 3.5, 1e-15);
    CHECK_VEC(body_get_point_velocity(body, (vector_t){1, 1}), 1, 2, 0); /* the centroid */
    body_free(body);
}

static void contains_point(void) {
    body_t *body = box_body((vector_t){2, 2}, 2, 2, 1.0);
    CHECK(body_contains_point(body, (vector_t){2, 2}));
    CHECK(body_contains_point(body, (vector_t){2.9, 1.1}));
    CHECK(body_contains_point(body, (vector_t){3, 2}));   /* on an edge */
    CHECK(body_contains_point(body, (vector_t){1, 1}));   /* a corner */
    CHECK(!body_contains_point(body, (vector_t){3.01, 2}));
    CHECK(!body_contains_point(body, (vector_t){2, 0.99}));
    CHECK(!body_contains_point(body, (vector_t){-2, -2}));
    /* Turned 45 degrees the corners stick out to sqrt(2) along the axes and
     * the old corner region is outside. */
    body_set_rotation(body, M_PI / 4);
    CHECK(body_contains_point(body, (vector_t){2 + 1.4, 2}));
    CHECK(!body_contains_point(body, (vector_t){2.9, 2.9}));
    /* A triangle: inside its box but outside the hypotenuse. */
    body_t *triangle = body_init(POLYGON({0, 0}, {1, 0}, {0, 1}), 1.0, RED);
    CHECK(body_contains_point(triangle, (vector_t){0.2, 0.2}));
    CHECK(!body_contains_point(triangle, (vector_t){0.6, 0.6}));
    body_free(body);
    body_free(triangle);
}

static void bounds(void) {
    body_t *body = box_body((vector_t){1, -1}, 4, 2, 1.0);
    aabb_t b = body_get_bounds(body);
    CHECK_VEC(b.min, -1, -2, 1e-15);
    CHECK_VEC(b.max, 3, 0, 1e-15);
    body_set_rotation(body, M_PI / 4);
    b = body_get_bounds(body);
    double half = 3.0 / sqrt(2.0); /* (2 + 1) / sqrt 2 */
    CHECK_VEC(b.min, 1 - half, -1 - half, 1e-14);
    CHECK_VEC(b.max, 1 + half, -1 + half, 1e-14);
    body_set_centroid(body, (vector_t){10, 10});
    b = body_get_bounds(body);
    CHECK_VEC(b.min, 10 - half, 10 - half, 1e-14);
    /* After a tick too. */
    body_set_velocity(body, (vector_t){2, 0});
    body_tick(body, 0.5);
    b = body_get_bounds(body);
    CHECK_NEAR(b.min.x, 11 - half, 1e-14);
    body_free(body);
}

static void kinetic_energy(void) {
    body_t *body = box_body(VEC_ZERO, 3, 1, 6.0); /* I = 5 */
    body_set_velocity(body, (vector_t){3, 4});
    CHECK_NEAR(body_get_kinetic_energy(body), 0.5 * 6 * 25, 1e-12);
    body_set_angular_velocity(body, 2.0);
    CHECK_NEAR(body_get_kinetic_energy(body), 0.5 * 6 * 25 + 0.5 * 5 * 4, 1e-12);
    body_free(body);
}

/* Programmer errors. Each helper makes one bad call. */

static body_t *ok_body(void) {
    return box_body(VEC_ZERO, 1, 1, 1.0);
}

BAD_CALL(init_null_shape, body_init(NULL, 1.0, RED))
BAD_CALL(init_with_info_null_shape, body_init_with_info(NULL, 1.0, RED, NULL, NULL))
BAD_CALL(init_two_vertices, body_init(POLYGON({0, 0}, {1, 0}), 1.0, RED))
BAD_CALL(init_empty_shape, body_init(list_init(0, free), 1.0, RED))
BAD_CALL(init_dart, body_init(POLYGON({0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}), 1.0, RED))
BAD_CALL(init_line, body_init(POLYGON({0, 0}, {1, 1}, {2, 2}), 1.0, RED))
BAD_CALL(init_huge_box, body_init(polygon_make_box(VEC_ZERO, 1e200, 1e200), 1.0, RED))
BAD_CALL(init_straight_angle,
         body_init(POLYGON({0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}), 1.0, RED))
BAD_CALL(init_nan_vertex, body_init(POLYGON({0, 0}, {1, NAN}, {0, 1}), 1.0, RED))
BAD_CALL(init_nan_mass, body_init(polygon_make_box(VEC_ZERO, 1, 1), NAN, RED))
BAD_CALL(init_zero_mass, body_init(polygon_make_box(VEC_ZERO, 1, 1), 0.0, RED))
BAD_CALL(init_negative_mass, body_init(polygon_make_box(VEC_ZERO, 1, 1), -2.0, RED))
BAD_CALL(init_minus_infinite_mass, body_init(polygon_make_box(VEC_ZERO, 1, 1), -INFINITY, RED))
BAD_CALL(init_with_info_nan_mass,
         body_init_with_info(polygon_make_box(VEC_ZERO, 1, 1), NAN, RED, NULL, NULL))
BAD_CALL(init_with_info_dart, body_init_with_info(POLYGON({0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}),
                                                  1.0, RED, NULL, NULL))
BAD_CALL(tick_negative_dt, body_tick(ok_body(), -0.1))
BAD_CALL(tick_zero_dt, body_tick(ok_body(), 0.0))
BAD_CALL(tick_nan_dt, body_tick(ok_body(), NAN))
BAD_CALL(tick_infinite_dt, body_tick(ok_body(), INFINITY))
BAD_CALL(set_centroid_nan, body_set_centroid(ok_body(), (vector_t){NAN, 0}))
BAD_CALL(set_velocity_infinite, body_set_velocity(ok_body(), (vector_t){0, INFINITY}))
BAD_CALL(set_rotation_nan, body_set_rotation(ok_body(), NAN))
BAD_CALL(set_angular_velocity_infinite, body_set_angular_velocity(ok_body(), -INFINITY))
BAD_CALL(add_force_nan, body_add_force(ok_body(), (vector_t){NAN, NAN}))
BAD_CALL(add_impulse_infinite, body_add_impulse(ok_body(), (vector_t){INFINITY, 0}))
BAD_CALL(add_torque_nan, body_add_torque(ok_body(), NAN))
BAD_CALL(add_force_at_nan_point, body_add_force_at(ok_body(), (vector_t){1, 0}, (vector_t){NAN, 0}))
BAD_CALL(add_force_at_nan_force, body_add_force_at(ok_body(), (vector_t){NAN, 0}, VEC_ZERO))
BAD_CALL(add_impulse_at_nan_point,
         body_add_impulse_at(ok_body(), (vector_t){1, 0}, (vector_t){0, NAN}))
BAD_CALL(add_impulse_at_nan_impulse,
         body_add_impulse_at(ok_body(), (vector_t){0, INFINITY}, VEC_ZERO))
BAD_CALL(contains_nan_point, body_contains_point(ok_body(), (vector_t){NAN, NAN}))
BAD_CALL(point_velocity_infinite_point,
         body_get_point_velocity(ok_body(), (vector_t){INFINITY, 0}))
BAD_CALL(set_inertia_zero, body_set_inertia(ok_body(), 0.0))
BAD_CALL(set_inertia_negative, body_set_inertia(ok_body(), -1.0))
BAD_CALL(set_inertia_nan, body_set_inertia(ok_body(), NAN))
BAD_CALL(set_elasticity_negative, body_set_elasticity(ok_body(), -0.5))
BAD_CALL(set_elasticity_nan, body_set_elasticity(ok_body(), NAN))
BAD_CALL(set_elasticity_infinite, body_set_elasticity(ok_body(), INFINITY))
BAD_CALL(set_friction_negative, body_set_friction(ok_body(), -1.0))
BAD_CALL(set_friction_nan, body_set_friction(ok_body(), NAN))

static void bad_input_aborts_with_message(void) {
    CHECK_DIES(init_null_shape, NULL, "engine error in body_init:", "shape is NULL");
    CHECK_DIES(init_with_info_null_shape, NULL, "engine error in body_init_with_info:",
               "shape is NULL");
    CHECK_DIES(init_two_vertices, NULL, "engine error in body_init:", "fewer than 3 vertices");
    CHECK_DIES(init_empty_shape, NULL, "engine error in body_init:", "fewer than 3 vertices");
    CHECK_DIES(init_dart, NULL, "engine error in body_init:", "convex");
    CHECK_DIES(init_line, NULL, "engine error in body_init:", "zero area");
    CHECK_DIES(init_huge_box, NULL,
               "engine error in body_init: bad shape: polygon is too large: its area overflows");
    CHECK_DIES(init_straight_angle, NULL,
               "engine error in body_init: bad shape: polygon is not strictly convex: three "
               "consecutive vertices are collinear");
    CHECK_DIES(init_nan_vertex, NULL, "engine error in body_init:", "not finite");
    CHECK_DIES(init_nan_mass, NULL, "engine error in body_init:", "mass", "NaN");
    CHECK_DIES(init_zero_mass, NULL, "engine error in body_init:", "mass", "got 0");
    CHECK_DIES(init_negative_mass, NULL, "engine error in body_init:", "mass", "got -2");
    CHECK_DIES(init_minus_infinite_mass, NULL, "engine error in body_init:", "mass", "-inf");
    CHECK_DIES(init_with_info_nan_mass, NULL, "engine error in body_init_with_info:", "mass",
               "NaN");
    CHECK_DIES(init_with_info_dart, NULL, "engine error in body_init_with_info:", "convex");
    CHECK_DIES(tick_negative_dt, NULL, "engine error in body_tick:", "dt", "-0.1");
    CHECK_DIES(tick_zero_dt, NULL, "engine error in body_tick:", "dt", "got 0");
    CHECK_DIES(tick_nan_dt, NULL, "engine error in body_tick:", "dt", "nan");
    CHECK_DIES(tick_infinite_dt, NULL, "engine error in body_tick:", "dt", "inf");
    CHECK_DIES(set_centroid_nan, NULL, "engine error in body_set_centroid:", "not finite");
    CHECK_DIES(set_velocity_infinite, NULL, "engine error in body_set_velocity:", "not finite");
    CHECK_DIES(set_rotation_nan, NULL, "engine error in body_set_rotation:", "not finite");
    CHECK_DIES(set_angular_velocity_infinite, NULL, "engine error in body_set_angular_velocity:",
               "not finite");
    CHECK_DIES(add_force_nan, NULL, "engine error in body_add_force:", "force", "not finite");
    CHECK_DIES(add_impulse_infinite, NULL, "engine error in body_add_impulse:", "impulse",
               "not finite");
    CHECK_DIES(add_torque_nan, NULL, "engine error in body_add_torque:", "torque", "not finite");
    CHECK_DIES(add_force_at_nan_point, NULL, "engine error in body_add_force_at:", "point",
               "not finite");
    CHECK_DIES(add_force_at_nan_force, NULL, "engine error in body_add_force_at:", "force",
               "not finite");
    CHECK_DIES(add_impulse_at_nan_point, NULL, "engine error in body_add_impulse_at:", "point",
               "not finite");
    CHECK_DIES(add_impulse_at_nan_impulse, NULL, "engine error in body_add_impulse_at:",
               "impulse", "not finite");
    CHECK_DIES(contains_nan_point, NULL, "engine error in body_contains_point:", "point",
               "not finite");
    CHECK_DIES(point_velocity_infinite_point, NULL, "engine error in body_get_point_velocity:",
               "point", "not finite");
    CHECK_DIES(set_inertia_zero, NULL, "engine error in body_set_inertia:", "inertia");
    CHECK_DIES(set_inertia_negative, NULL, "engine error in body_set_inertia:", "inertia");
    CHECK_DIES(set_inertia_nan, NULL, "engine error in body_set_inertia:", "inertia");
    CHECK_DIES(set_elasticity_negative, NULL, "engine error in body_set_elasticity:",
               "elasticity");
    CHECK_DIES(set_elasticity_nan, NULL, "engine error in body_set_elasticity:", "elasticity");
    CHECK_DIES(set_elasticity_infinite, NULL, "engine error in body_set_elasticity:",
               "elasticity");
    CHECK_DIES(set_friction_negative, NULL, "engine error in body_set_friction:", "friction");
    CHECK_DIES(set_friction_nan, NULL, "engine error in body_set_friction:", "friction");
}

/* Masses and moments whose inverse is not finite: 1 / m overflows, so the
 * first step would make the state NaN. */
BAD_CALL(init_subnormal_mass, body_init(polygon_make_box(VEC_ZERO, 1, 1), 1e-310, RED))
BAD_CALL(init_least_subnormal_mass, body_init(polygon_make_box(VEC_ZERO, 1, 1), 5e-324, RED))
BAD_CALL(init_with_info_subnormal_mass,
         body_init_with_info(polygon_make_box(VEC_ZERO, 1, 1), 1e-310, RED, NULL, NULL))
/* I = m (w^2 + h^2) / 12: about 2e-313 kg m^2 for a 1 um square of 1e-300 kg. */
BAD_CALL(init_subnormal_inertia, body_init(polygon_make_box(VEC_ZERO, 5e-7, 5e-7), 1e-300, RED))
/* About 1e311 kg m^2 for a 200 m square of 1e307 kg. */
BAD_CALL(init_infinite_inertia, body_init(polygon_make_box(VEC_ZERO, 100, 100), 1e307, RED))
BAD_CALL(set_inertia_subnormal, body_set_inertia(ok_body(), 1e-310))
/* A shape polygon_check accepts whose centroid overflows (its sums grow as
 * the size cubed); the immovable mass leaves the moment out of it. */
BAD_CALL(init_huge_shape, body_init(polygon_make_box(VEC_ZERO, 1e110, 1e110), INFINITY, RED))

static void mass_inertia_or_centroid_that_cannot_work_are_refused(void) {
    CHECK_DIES(init_subnormal_mass, NULL, "engine error in body_init:", "mass 1e-310 kg",
               "inverse is not finite");
    CHECK_DIES(init_least_subnormal_mass, NULL, "engine error in body_init:", "mass 4.94066e-324",
               "inverse is not finite");
    CHECK_DIES(init_with_info_subnormal_mass, NULL, "engine error in body_init_with_info:",
               "mass 1e-310 kg", "inverse is not finite");
    CHECK_DIES(init_subnormal_inertia, NULL, "engine error in body_init:", "moment of inertia",
               "inverse is not finite");
    CHECK_DIES(init_infinite_inertia, NULL, "engine error in body_init:", "moment of inertia",
               "mass 1e+307 kg", "is not finite", "INFINITY");
    CHECK_DIES(set_inertia_subnormal, NULL, "engine error in body_set_inertia:",
               "inertia 1e-310", "inverse is not finite");
    CHECK_DIES(init_huge_shape, NULL, "engine error in body_init:", "bad shape",
               "centroid is not finite");
    /* The edges that still work: about the least normal mass on a shape
     * large enough for a normal moment, and a huge mass on a shape small
     * enough for a finite one (computed without overflowing on the way). */
    body_t *light = box_body(VEC_ZERO, 10, 10, 2.3e-308);
    CHECK(isfinite(body_get_inertia(light)) && body_get_inertia(light) > 0.0);
    body_free(light);
    body_t *heavy = box_body(VEC_ZERO, 2e4, 2e4, 1e300); /* I = 1e300 8e8 / 12 */
    CHECK_RELATIVE(body_get_inertia(heavy), 1e300 * 8e8 / 12, 1e-12);
    body_free(heavy);
}

static body_t *fast_body(double speed) {
    body_t *body = ok_body();
    body_set_velocity(body, (vector_t){speed, 0});
    return body;
}

BAD_CALL(tick_overflowing_the_position, body_tick(fast_body(1e308), 10.0))
BAD_CALL(tick_overflowing_the_velocity, {
    body_t *body = ok_body();
    body_add_force(body, (vector_t){0, 1e300});
    body_tick(body, 1e10);
})

static void tick_that_overflows_the_state_aborts(void) {
    CHECK_DIES(tick_overflowing_the_position, NULL, "engine error in body_tick:",
               "position is not finite", "dt = 10 s", "too large for its velocity (1e+308, 0)");
    CHECK_DIES(tick_overflowing_the_velocity, NULL, "engine error in body_tick:",
               "velocity is not finite", "dt = 1e+10 s", "force (0, 1e+300) N");
}

/* A NULL body, for every function that takes one. */
BAD_CALL(null_free, body_free(NULL))
BAD_CALL(null_get_shape, body_get_shape(NULL))
BAD_CALL(null_get_polygon, body_get_polygon(NULL))
BAD_CALL(null_get_centroid, body_get_centroid(NULL))
BAD_CALL(null_get_velocity, body_get_velocity(NULL))
BAD_CALL(null_get_mass, body_get_mass(NULL))
BAD_CALL(null_get_color, body_get_color(NULL))
BAD_CALL(null_get_rotation, body_get_rotation(NULL))
BAD_CALL(null_get_info, body_get_info(NULL))
BAD_CALL(null_set_centroid, body_set_centroid(NULL, VEC_ZERO))
BAD_CALL(null_set_velocity, body_set_velocity(NULL, VEC_ZERO))
BAD_CALL(null_set_rotation, body_set_rotation(NULL, 0.0))
BAD_CALL(null_set_color, body_set_color(NULL, RED))
BAD_CALL(null_add_force, body_add_force(NULL, VEC_ZERO))
BAD_CALL(null_add_impulse, body_add_impulse(NULL, VEC_ZERO))
BAD_CALL(null_tick, body_tick(NULL, 0.1))
BAD_CALL(null_reset, body_reset(NULL))
BAD_CALL(null_remove, body_remove(NULL))
BAD_CALL(null_is_removed, body_is_removed(NULL))
BAD_CALL(null_get_angular_velocity, body_get_angular_velocity(NULL))
BAD_CALL(null_set_angular_velocity, body_set_angular_velocity(NULL, 0.0))
BAD_CALL(null_get_inertia, body_get_inertia(NULL))
BAD_CALL(null_set_inertia, body_set_inertia(NULL, 1.0))
BAD_CALL(null_add_torque, body_add_torque(NULL, 1.0))
BAD_CALL(null_add_force_at, body_add_force_at(NULL, VEC_ZERO, VEC_ZERO))
BAD_CALL(null_add_impulse_at, body_add_impulse_at(NULL, VEC_ZERO, VEC_ZERO))
BAD_CALL(null_get_point_velocity, body_get_point_velocity(NULL, VEC_ZERO))
BAD_CALL(null_get_elasticity, body_get_elasticity(NULL))
BAD_CALL(null_set_elasticity, body_set_elasticity(NULL, 0.5))
BAD_CALL(null_get_friction, body_get_friction(NULL))
BAD_CALL(null_set_friction, body_set_friction(NULL, 0.5))
BAD_CALL(null_set_collision_filter, body_set_collision_filter(NULL, 1, 1, 0))
BAD_CALL(null_get_bounds, body_get_bounds(NULL))
BAD_CALL(null_contains_point, body_contains_point(NULL, VEC_ZERO))
BAD_CALL(null_get_kinetic_energy, body_get_kinetic_energy(NULL))

static void null_body_aborts_naming_the_function(void) {
    static const struct {
        void (*call)(void *);
        const char *message;
    } cases[] = {
        {null_free, "engine error in body_free:"},
        {null_get_shape, "engine error in body_get_shape:"},
        {null_get_polygon, "engine error in body_get_polygon:"},
        {null_get_centroid, "engine error in body_get_centroid:"},
        {null_get_velocity, "engine error in body_get_velocity:"},
        {null_get_mass, "engine error in body_get_mass:"},
        {null_get_color, "engine error in body_get_color:"},
        {null_get_rotation, "engine error in body_get_rotation:"},
        {null_get_info, "engine error in body_get_info:"},
        {null_set_centroid, "engine error in body_set_centroid:"},
        {null_set_velocity, "engine error in body_set_velocity:"},
        {null_set_rotation, "engine error in body_set_rotation:"},
        {null_set_color, "engine error in body_set_color:"},
        {null_add_force, "engine error in body_add_force:"},
        {null_add_impulse, "engine error in body_add_impulse:"},
        {null_tick, "engine error in body_tick:"},
        {null_reset, "engine error in body_reset:"},
        {null_remove, "engine error in body_remove:"},
        {null_is_removed, "engine error in body_is_removed:"},
        {null_get_angular_velocity, "engine error in body_get_angular_velocity:"},
        {null_set_angular_velocity, "engine error in body_set_angular_velocity:"},
        {null_get_inertia, "engine error in body_get_inertia:"},
        {null_set_inertia, "engine error in body_set_inertia:"},
        {null_add_torque, "engine error in body_add_torque:"},
        {null_add_force_at, "engine error in body_add_force_at:"},
        {null_add_impulse_at, "engine error in body_add_impulse_at:"},
        {null_get_point_velocity, "engine error in body_get_point_velocity:"},
        {null_get_elasticity, "engine error in body_get_elasticity:"},
        {null_set_elasticity, "engine error in body_set_elasticity:"},
        {null_get_friction, "engine error in body_get_friction:"},
        {null_set_friction, "engine error in body_set_friction:"},
        {null_set_collision_filter, "engine error in body_set_collision_filter:"},
        {null_get_bounds, "engine error in body_get_bounds:"},
        {null_contains_point, "engine error in body_contains_point:"},
        {null_get_kinetic_energy, "engine error in body_get_kinetic_energy:"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *expected[] = {cases[i].message, "body is NULL"};
        if (!test_dies_with(cases[i].call, NULL, expected, 2)) {
            test_fail(__FILE__, __LINE__, "a NULL body did not abort with \"%s body is NULL\"",
                      cases[i].message);
        }
    }
}

/* A body rebuilt from another's local polygon with body_init_centred, moved
 * to its pose, is the same to the bit: vertices, inertia, world polygon
 * (body_init would subtract a centroid of rounding size again). */
static void init_centred_keeps_the_shape_as_given(void) {
    body_t *a = body_init(polygon_make_regular(7, 0.45, (vector_t){3.7, -1.2}, 0.3), 2.5, RED);
    body_set_rotation(a, 0.8);
    polygon_t local = body_get_local_polygon(a);
    body_t *b = body_init_centred(test_make_polygon(local.vertices, local.count), 2.5, RED, NULL,
                                  NULL);
    CHECK(body_get_centroid(b).x == 0.0 && body_get_centroid(b).y == 0.0);
    body_set_centroid(b, body_get_centroid(a));
    body_set_rotation(b, 0.8);
    polygon_t other = body_get_local_polygon(b);
    CHECK(other.count == local.count);
    for (size_t i = 0; i < local.count; i++) {
        CHECK(memcmp(&other.vertices[i], &local.vertices[i], sizeof(vector_t)) == 0);
        CHECK(memcmp(&other.normals[i], &local.normals[i], sizeof(vector_t)) == 0);
    }
    CHECK(body_get_inertia(a) == body_get_inertia(b));
    polygon_t pa = body_get_polygon(a), pb = body_get_polygon(b);
    for (size_t i = 0; i < pa.count; i++) {
        CHECK(memcmp(&pa.vertices[i], &pb.vertices[i], sizeof(vector_t)) == 0);
    }
    body_free(a);
    body_free(b);
}

BAD_CALL(centred_off_centre, body_init_centred(POLYGON({1, 1}, {2, 1}, {1, 2}), 1.0, RED, NULL,
                                               NULL))

static void init_centred_refuses_a_shape_off_the_origin(void) {
    CHECK_DIES(centred_off_centre, NULL, "engine error in body_init_centred:",
               "bad shape: its centroid (1.33333, 1.33333) is not at the origin");
}

TEST_SUITE(body, TEST_CASE(init_starts_at_rest_at_the_area_centroid),
           TEST_CASE(init_centred_keeps_the_shape_as_given),
           TEST_CASE(init_centred_refuses_a_shape_off_the_origin),
           TEST_CASE(init_takes_the_shape_and_free_releases_everything),
           TEST_CASE(info_is_returned_and_freed_with_its_freer),
           TEST_CASE(get_shape_is_a_new_copy_of_the_world_vertices),
           TEST_CASE(clockwise_shape_is_reversed),
           TEST_CASE(polygon_view_has_vertices_and_outward_unit_normals),
           TEST_CASE(set_centroid_translates_the_shape),
           TEST_CASE(set_rotation_is_absolute_about_the_centroid), TEST_CASE(setters_and_getters),
           TEST_CASE(tick_follows_the_seed_scheme),
           TEST_CASE(constant_force_matches_free_fall_exactly),
           TEST_CASE(forces_and_impulses_accumulate),
           TEST_CASE(reset_clears_force_torque_and_impulses),
           TEST_CASE(infinite_mass_is_immovable_but_can_be_kinematic),
           TEST_CASE(remove_marks_and_is_idempotent), TEST_CASE(inertia_of_a_box),
           TEST_CASE(init_accepts_a_unit_box_far_from_the_origin),
           TEST_CASE(init_accepts_a_regular_100000_gon),
           TEST_CASE(impulse_at_a_point_gives_the_right_spin),
           TEST_CASE(force_at_a_point_and_torque),
           TEST_CASE(set_inertia_overrides_and_infinity_stops_turning),
           TEST_CASE(point_velocity_adds_spin), TEST_CASE(contains_point), TEST_CASE(bounds),
           TEST_CASE(kinetic_energy), TEST_CASE(bad_input_aborts_with_message),
           TEST_CASE(mass_inertia_or_centroid_that_cannot_work_are_refused),
           TEST_CASE(tick_that_overflows_the_state_aborts),
           TEST_CASE(null_body_aborts_naming_the_function));
