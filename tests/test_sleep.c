/* Sleeping (scene_set_sleeping): resting islands leave the step and wake
 * when touched, pushed, moved or undermined; nothing sleeps in mid-air. */
#include <math.h>
#include "jostle/jostle.h"
#include "dynamics/body_private.h"
#include "dynamics/integrator.h"
#include "world/sleep.h"
#include "test.h"

static const double DT = 1.0 / 60.0;
static const rgb_color_t GREY = {0.5, 0.5, 0.5};

static scene_t *sleep_scene(void) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -10.0});
    scene_set_contacts_enabled(scene, true);
    scene_add_body(scene, body_init(polygon_make_box((vector_t){0, -0.5}, 40, 0.5), INFINITY,
                                    GREY));
    return scene;
}

static body_t *add_box(scene_t *scene, double x, double y) {
    body_t *box = body_init(polygon_make_box((vector_t){x, y}, 0.5, 0.5), 1.0, GREY);
    scene_add_body(scene, box);
    return box;
}

static void run(scene_t *scene, int steps) {
    for (int i = 0; i < steps; i++) scene_tick(scene, DT);
}

/* A stack of `count` boxes standing at x. */
static void add_stack(scene_t *scene, double x, body_t **boxes, int count) {
    for (int j = 0; j < count; j++) boxes[j] = add_box(scene, x, 0.5 + j);
}

static int count_asleep(body_t **bodies, int count) {
    int asleep = 0;
    for (int i = 0; i < count; i++) asleep += body_is_sleeping(bodies[i]);
    return asleep;
}

/* Thirty polygons dropped on the floor settle and all fall asleep; then a
 * step computes no contact, and nothing moves. */
static void settled_pile_falls_asleep(void) {
    scene_t *scene = sleep_scene();
    body_t *bodies[30];
    for (int i = 0; i < 30; i++) {
        list_t *shape = polygon_make_regular((size_t)(3 + i % 5), 0.5,
                                             (vector_t){(i % 10) * 1.2 - 6.0, 1.0 + (i / 10) * 1.2},
                                             0.3 * i);
        bodies[i] = body_init(shape, 1.0, GREY);
        scene_add_body(scene, bodies[i]);
    }
    run(scene, 20);
    CHECK(count_asleep(bodies, 30) == 0); /* still falling */
    run(scene, 1200);
    CHECK(count_asleep(bodies, 30) == 30);
    vector_t where[30];
    for (int i = 0; i < 30; i++) where[i] = body_get_centroid(bodies[i]);
    run(scene, 60);
    scene_stats_t stats = scene_get_stats(scene);
    CHECK(stats.contacts == 0);
    CHECK(stats.broadphase_pairs == 0);
    for (int i = 0; i < 30; i++) {
        CHECK(body_get_centroid(bodies[i]).x == where[i].x);
        CHECK(body_get_centroid(bodies[i]).y == where[i].y);
        CHECK(body_get_velocity(bodies[i]).y == 0.0);
    }
    scene_free(scene);
}

/* Two stacks 20 m apart sleep; a box dropped on one wakes that one alone,
 * which goes back to sleep once the box rests on it. */
/* A box sliding on ice sleeps below the tolerance speed (5 cm/s for its
 * size) and never above it, though a resting body's velocity may jitter by
 * a step of gravity (17 cm/s) and still count as slow: what counts beyond
 * that is how far the body goes. */
static void sliding_sleeps_only_below_the_tolerance(void) {
    const double speeds[2] = {0.04, 0.06};
    for (int k = 0; k < 2; k++) {
        scene_t *scene = sleep_scene();
        body_set_friction(scene_get_body(scene, 0), 0.0);
        body_t *box = add_box(scene, 0.0, 0.5);
        body_set_friction(box, 0.0);
        run(scene, 10);
        body_set_velocity(box, (vector_t){speeds[k], 0.0});
        run(scene, 180);
        CHECK(body_is_sleeping(box) == (k == 0));
        if (k == 1) CHECK_NEAR(body_get_velocity(box).x, speeds[k], 1e-9);
        scene_free(scene);
    }
}

/* Without gravity nothing presses a body: one gliding at 3 cm/s keeps
 * gliding, under the tolerance for a body in free motion (1 cm/s). */
static void slow_free_flight_keeps_moving(void) {
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    body_t *box = add_box(scene, 0.0, 0.0);
    body_set_velocity(box, (vector_t){0.03, 0.0});
    run(scene, 180);
    CHECK(!body_is_sleeping(box));
    CHECK_NEAR(body_get_centroid(box).x, 0.03 * 180 * DT, 1e-9);
    scene_free(scene);
}

/* Twenty boxes stacked 10 cm into each other: the lift pushes the column
 * apart within a second, and it sleeps 1.7 cm under the top's resting
 * height (19.497 m), about the nineteen contacts' slops of 1 mm each.
 * Frozen mid-way, it would be up to 1.9 m under. */
static void a_column_sleeps_only_once_pushed_apart(void) {
    scene_t *scene = sleep_scene();
    body_t *boxes[20];
    for (int j = 0; j < 20; j++) boxes[j] = add_box(scene, 0.0, 0.5 + 0.9 * j);
    int step = 0;
    while (step < 3600 && !body_is_sleeping(boxes[19])) {
        scene_tick(scene, DT);
        step++;
    }
    CHECK(body_is_sleeping(boxes[19]));
    CHECK(body_get_centroid(boxes[19]).y > 19.497 - 0.02);
    scene_free(scene);
}

static void a_dropped_body_wakes_its_island_only(void) {
    scene_t *scene = sleep_scene();
    body_t *left[3], *right[3];
    add_stack(scene, -10.0, left, 3);
    add_stack(scene, 10.0, right, 3);
    run(scene, 120);
    CHECK(count_asleep(left, 3) == 3 && count_asleep(right, 3) == 3);
    body_t *dropped = add_box(scene, -10.0, 6.0);
    bool left_woke = false;
    for (int i = 0; i < 600; i++) {
        scene_tick(scene, DT);
        left_woke |= count_asleep(left, 3) == 0;
        CHECK(count_asleep(right, 3) == 3);
    }
    CHECK(left_woke);
    CHECK(count_asleep(left, 3) == 3 && body_is_sleeping(dropped));
    CHECK_NEAR(body_get_centroid(dropped).y, 3.5, 0.01);
    scene_free(scene);
}

/* Removing the bottom box of a sleeping stack wakes the two above, which
 * fall onto the floor's height. */
static void removing_a_support_wakes_what_rested_on_it(void) {
    scene_t *scene = sleep_scene();
    body_t *boxes[3];
    add_stack(scene, 0.0, boxes, 3);
    run(scene, 120);
    CHECK(count_asleep(boxes, 3) == 3);
    body_remove(boxes[0]);
    CHECK(!body_is_sleeping(boxes[1]) && !body_is_sleeping(boxes[2]));
    run(scene, 180);
    CHECK_NEAR(body_get_centroid(boxes[1]).y, 0.5, 0.01);
    CHECK_NEAR(body_get_centroid(boxes[2]).y, 1.5, 0.02);
    scene_free(scene);
}

/* A box thrown straight up stops for an instant at its apex, slower than
 * the sleep speed for a step or two, and must not sleep there: only resting
 * on something immovable does. It sleeps once it has landed. */
static void no_body_sleeps_in_mid_air(void) {
    scene_t *scene = sleep_scene();
    body_t *box = add_box(scene, 0.0, 0.5);
    body_set_velocity(box, (vector_t){0.0, 5.0});
    for (int i = 0; i < 70; i++) {
        scene_tick(scene, DT);
        if (body_get_centroid(box).y > 0.51) CHECK(!body_is_sleeping(box));
    }
    run(scene, 120);
    CHECK(body_is_sleeping(box));
    /* Without gravity a body alone feels nothing and may sleep where it is;
     * with a spring pulling it, never. */
    scene_t *space = scene_init();
    scene_set_contacts_enabled(space, true);
    body_t *still = add_box(space, 0.0, 10.0);
    body_t *anchor = body_init(polygon_make_box((vector_t){5, 10}, 0.1, 0.1), INFINITY, GREY);
    scene_add_body(space, anchor);
    body_t *pulled = add_box(space, 3.0, 10.0);
    create_spring(space, 1.0, anchor, pulled);
    for (int i = 0; i < 120; i++) {
        scene_tick(space, DT);
        CHECK(!body_is_sleeping(pulled));
    }
    CHECK(body_is_sleeping(still));
    scene_free(space);
    scene_free(scene);
}

/* Setting a velocity, a pose, a nonzero force or impulse wakes the island;
 * a zero force (drag on a body at rest) does not. */
static void setters_wake_the_island(void) {
    scene_t *scene = sleep_scene();
    body_t *boxes[2];
    add_stack(scene, 0.0, boxes, 2);
    run(scene, 120);
    CHECK(count_asleep(boxes, 2) == 2);
    body_add_force(boxes[1], VEC_ZERO);
    body_add_impulse(boxes[1], VEC_ZERO);
    CHECK(count_asleep(boxes, 2) == 2);
    body_add_force(boxes[1], (vector_t){0.0, 1.0});
    CHECK(count_asleep(boxes, 2) == 0);
    run(scene, 120);
    CHECK(count_asleep(boxes, 2) == 2);
    body_set_velocity(boxes[0], (vector_t){0.5, 0.0});
    CHECK(count_asleep(boxes, 2) == 0);
    run(scene, 240);
    CHECK(count_asleep(boxes, 2) == 2);
    body_add_impulse(boxes[0], (vector_t){0.1, 0.0});
    CHECK(count_asleep(boxes, 2) == 0);
    scene_free(scene);
}

/* With sleeping off nothing sleeps, and switching it off wakes all. */
static void switching_sleeping_off_wakes_everything(void) {
    scene_t *scene = sleep_scene();
    CHECK(scene_get_sleeping(scene));
    body_t *boxes[2];
    add_stack(scene, 0.0, boxes, 2);
    run(scene, 120);
    CHECK(count_asleep(boxes, 2) == 2);
    scene_set_sleeping(scene, false);
    CHECK(!scene_get_sleeping(scene));
    CHECK(count_asleep(boxes, 2) == 0);
    run(scene, 240);
    CHECK(count_asleep(boxes, 2) == 0);
    scene_set_sleeping(scene, true);
    run(scene, 60);
    CHECK(count_asleep(boxes, 2) == 2);
    scene_set_contacts_enabled(scene, false);
    CHECK(count_asleep(boxes, 2) == 0);
    scene_free(scene);
}

static void count_calls(body_t *body1, body_t *body2, vector_t axis, void *aux,
                        double force_const) {
    (void)body1, (void)body2, (void)axis, (void)force_const;
    (*(int *)aux)++;
}

/* A box resting on another fires its handler once; sleeping and waking
 * while it still rests there does not fire it again. */
static void a_sleeping_pair_does_not_fire_again(void) {
    scene_t *scene = sleep_scene();
    body_t *boxes[2];
    add_stack(scene, 0.0, boxes, 2);
    int calls = 0;
    create_collision(scene, boxes[0], boxes[1], count_calls, &calls, 0.0);
    run(scene, 120);
    CHECK(count_asleep(boxes, 2) == 2);
    CHECK(calls == 1);
    body_add_force(boxes[1], (vector_t){0.0, 1.0});
    run(scene, 120);
    CHECK(calls == 1);
    scene_free(scene);
}

/* Falling asleep and waking again, once warm, allocate nothing: the index
 * and the island arrays keep their size. */
static void sleeping_and_waking_allocate_nothing_once_warm(void) {
    scene_t *scene = sleep_scene();
    body_t *boxes[3];
    add_stack(scene, 0.0, boxes, 3);
    run(scene, 120);
    size_t before = 0;
    for (int cycle = 0; cycle < 3; cycle++) {
        if (cycle == 2) before = engine_allocation_count();
        body_set_velocity(boxes[2], (vector_t){0.3, 0.0});
        CHECK(count_asleep(boxes, 3) == 0);
        run(scene, 240);
        CHECK(count_asleep(boxes, 3) == 3);
    }
    CHECK(engine_allocation_count() == before);
    scene_free(scene);
}

/* ---- Changes to the static world, to gravity and to materials ------------
 * A sleeping island must see every change that would move it: each case
 * below left the island asleep, unmoved, in mid-air or overlapped. Gravity
 * is 9.8 m/s^2 here, so a body free for 1 s falls (or rises) g / 2 = 4.9 m:
 * the seed scheme is exact under a constant force. */

static const double G = 9.8;

/* A scene with a static slab of the given half extents at `at` (body 0). */
static scene_t *slab_scene(vector_t at, double half_width, double half_height) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -G});
    scene_set_contacts_enabled(scene, true);
    scene_add_body(scene, body_init(polygon_make_box(at, half_width, half_height), INFINITY,
                                    GREY));
    return scene;
}

/* A stack of three unit boxes asleep on the floor (body 0, top at y = 0). */
static scene_t *sleeping_stack(body_t **boxes) {
    scene_t *scene = slab_scene((vector_t){0.0, -0.5}, 20.0, 0.5);
    add_stack(scene, 0.0, boxes, 3);
    run(scene, 120);
    CHECK(count_asleep(boxes, 3) == 3);
    return scene;
}

/* Every box of the stack fell freely for 1 s from where it slept. */
static void check_stack_fell_freely(scene_t *scene, body_t **boxes) {
    double y[3];
    for (int j = 0; j < 3; j++) y[j] = body_get_centroid(boxes[j]).y;
    run(scene, 60);
    for (int j = 0; j < 3; j++) {
        CHECK(!body_is_sleeping(boxes[j]));
        CHECK_NEAR(body_get_centroid(boxes[j]).y, y[j] - 0.5 * G, 1e-9);
    }
}

static void removing_the_floor_by_index_wakes_the_stack(void) {
    body_t *boxes[3];
    scene_t *scene = sleeping_stack(boxes);
    scene_remove_body(scene, 0);
    check_stack_fell_freely(scene, boxes);
    scene_free(scene);
}

static void removing_the_floor_wakes_the_stack(void) {
    body_t *boxes[3];
    scene_t *scene = sleeping_stack(boxes);
    body_remove(scene_get_body(scene, 0));
    check_stack_fell_freely(scene, boxes);
    scene_free(scene);
}

/* The floor moved 100 m down: what rested on it at its old pose wakes. */
static void moving_the_floor_away_wakes_the_stack(void) {
    body_t *boxes[3];
    scene_t *scene = sleeping_stack(boxes);
    body_set_centroid(scene_get_body(scene, 0), (vector_t){0.0, -100.0});
    check_stack_fell_freely(scene, boxes);
    scene_free(scene);
}

/* A 2 m slab turned upright about its centre (x in [-0.25, 0.25]) no
 * longer holds the box standing on its right half (x in [0.3, 1.3]). */
static void turning_the_floor_wakes_what_it_held(void) {
    scene_t *scene = slab_scene((vector_t){0.0, -0.25}, 1.0, 0.25);
    body_t *box = add_box(scene, 0.8, 0.5);
    run(scene, 120);
    CHECK(body_is_sleeping(box));
    double y = body_get_centroid(box).y;
    body_set_rotation(scene_get_body(scene, 0), M_PI / 2.0);
    run(scene, 60);
    CHECK(!body_is_sleeping(box));
    CHECK_NEAR(body_get_centroid(box).y, y - 0.5 * G, 1e-9);
    CHECK_NEAR(body_get_centroid(box).x, 0.8, 1e-9);
    scene_free(scene);
}

/* A floor filtered out of every contact lets the stack fall through. */
static void filtering_the_floor_out_wakes_the_stack(void) {
    body_t *boxes[3];
    scene_t *scene = sleeping_stack(boxes);
    body_set_collision_filter(scene_get_body(scene, 0), 1, 0, 0);
    check_stack_fell_freely(scene, boxes);
    scene_free(scene);
}

/* Gravity flipped: the stack rises g / 2 = 4.9 m in 1 s, as one. */
static void flipping_gravity_wakes_the_stack(void) {
    body_t *boxes[3];
    scene_t *scene = sleeping_stack(boxes);
    double y[3];
    for (int j = 0; j < 3; j++) y[j] = body_get_centroid(boxes[j]).y;
    scene_set_gravity(scene, (vector_t){0.0, G});
    run(scene, 60);
    for (int j = 0; j < 3; j++) CHECK_NEAR(body_get_centroid(boxes[j]).y, y[j] + 0.5 * G, 1e-9);
    scene_free(scene);
}

/* Gravity turned to (g, -g): a box on the floor (friction 0.6 against 0.6,
 * mixed to 0.6) slides at g - 0.6 g = 3.92 m/s^2, 1.96 m in 1 s, and stays
 * on the floor. Setting the same gravity again is no change and wakes
 * nothing. */
static void turning_gravity_wakes_what_it_pulls_sideways(void) {
    scene_t *scene = slab_scene((vector_t){0.0, -0.5}, 20.0, 0.5);
    body_t *box = add_box(scene, 0.0, 0.5);
    run(scene, 120);
    CHECK(body_is_sleeping(box));
    scene_set_gravity(scene, (vector_t){0.0, -G});
    CHECK(body_is_sleeping(box));
    vector_t at = body_get_centroid(box);
    scene_set_gravity(scene, (vector_t){G, -G});
    CHECK(!body_is_sleeping(box));
    run(scene, 60);
    double mu = sqrt(0.6 * 0.6);
    CHECK_NEAR(body_get_centroid(box).x, at.x + 0.5 * (G - mu * G), 1e-3);
    CHECK_NEAR(body_get_centroid(box).y, at.y, 1e-3);
    CHECK_NEAR(body_get_rotation(box), 0.0, 1e-3);
    scene_free(scene);
}

/* A unit box asleep on a static slope of 0.3 rad (friction 0.6 holds it:
 * tan 0.3 = 0.31); body 0 is the slope, the box is returned. */
static const double SLOPE = 0.3;

static body_t *box_asleep_on_a_slope(scene_t **scene) {
    *scene = slab_scene((vector_t){0.0, 0.0}, 10.0, 0.25);
    body_t *slope = scene_get_body(*scene, 0);
    body_set_rotation(slope, SLOPE);
    vector_t normal = {-sin(SLOPE), cos(SLOPE)};
    body_t *box = add_box(*scene, 0.0, 0.0);
    body_set_rotation(box, SLOPE);
    body_set_centroid(box, vec_multiply(0.75, normal));
    run(*scene, 180);
    CHECK(body_is_sleeping(box));
    return box;
}

/* Friction set to 0, on the sleeping box or on the slope under it: the box
 * slides g sin(0.3) / 2 = 1.448 m down the slope in 1 s. */
static void removing_friction_wakes_a_box_on_a_slope(void) {
    for (int on_slope = 0; on_slope < 2; on_slope++) {
        scene_t *scene;
        body_t *box = box_asleep_on_a_slope(&scene);
        vector_t at = body_get_centroid(box);
        body_set_friction(on_slope ? scene_get_body(scene, 0) : box, 0.0);
        run(scene, 60);
        vector_t moved = vec_subtract(body_get_centroid(box), at);
        vector_t down = {-cos(SLOPE), -sin(SLOPE)};
        CHECK_NEAR(vec_dot(moved, down), 0.5 * G * sin(SLOPE), 1e-3);
        CHECK_NEAR(vec_cross(down, moved), 0.0, 1e-3); /* along the slope */
        scene_free(scene);
    }
}

/* Elasticity is a material property too: set on the sleeping box it wakes
 * it at once, set on the slope at the next step. */
static void changing_elasticity_wakes_what_it_touches(void) {
    scene_t *scene;
    body_t *box = box_asleep_on_a_slope(&scene);
    body_set_elasticity(box, 0.5);
    CHECK(!body_is_sleeping(box));
    run(scene, 120);
    CHECK(body_is_sleeping(box));
    body_set_elasticity(scene_get_body(scene, 0), 0.5);
    run(scene, 1);
    CHECK(!body_is_sleeping(box));
    scene_free(scene);
}

/* A static box placed 0.2 m into a sleeping one: it wakes and is pushed out
 * within the second (the solver leaves at most its 1 mm slop). */
static void check_pushed_out(scene_t *scene, body_t *box) {
    run(scene, 1);
    CHECK(!body_is_sleeping(box));
    run(scene, 59);
    CHECK(body_get_bounds(box).max.x <= 0.3 + 0.002);
}

static void adding_a_static_body_into_a_sleeping_one_wakes_it(void) {
    scene_t *scene = slab_scene((vector_t){0.0, -0.5}, 20.0, 0.5);
    body_t *box = add_box(scene, 0.0, 0.5);
    run(scene, 120);
    CHECK(body_is_sleeping(box));
    scene_add_body(scene, body_init(polygon_make_box((vector_t){0.8, 0.5}, 0.5, 0.5), INFINITY,
                                    GREY));
    check_pushed_out(scene, box);
    scene_free(scene);
}

static void moving_a_static_body_into_a_sleeping_one_wakes_it(void) {
    scene_t *scene = slab_scene((vector_t){0.0, -0.5}, 20.0, 0.5);
    body_t *box = add_box(scene, 0.0, 0.5);
    body_t *block =
        body_init(polygon_make_box((vector_t){10.0, 0.5}, 0.5, 0.5), INFINITY, GREY);
    scene_add_body(scene, block);
    run(scene, 120);
    CHECK(body_is_sleeping(box));
    body_set_centroid(block, (vector_t){0.8, 0.5});
    check_pushed_out(scene, box);
    scene_free(scene);
}

/* A sleeping body removed and reaped by a tick of dt 0 (a paused game),
 * then a change next to its island: the index of sleepers no longer names
 * the freed body (AddressSanitizer would stop a read of it), and the rest
 * of the stack falls when the floor goes. */
static void a_body_reaped_while_paused_leaves_the_index(void) {
    body_t *boxes[3];
    scene_t *scene = sleeping_stack(boxes);
    body_remove(boxes[2]);
    scene_tick(scene, 0.0);
    CHECK(scene_bodies(scene) == 3);
    body_set_friction(scene_get_body(scene, 0), 0.5);
    run(scene, 60);
    CHECK(count_asleep(boxes, 2) == 2);
    body_remove(scene_get_body(scene, 0));
    double y = body_get_centroid(boxes[1]).y;
    run(scene, 60);
    CHECK_NEAR(body_get_centroid(boxes[1]).y, y - 0.5 * G, 1e-9);
    scene_free(scene);
}

/* A deep pile: 600 polygons of 0.5 m radius (triangles to octagons, mass
 * by area, friction 0.6) dropped 15 wide and 40 rows high into a box 18.9 m
 * wide comes to rest and is fully asleep within 10 s of simulated time (at
 * 7.8 s). It slept at 22 s while the heap kept compacting under the
 * frictionless position pass, before resting approaches were undone within
 * the step and relaxed out of the end velocities (velocity_solve.c's
 * raised targets, solver.c's relaxation); at 11.6 s before the overlaps
 * the landing left were lifted out from the ground up (shock.h's lift),
 * which the position iterations' pushes had slid bodies along one another
 * trying to remove. */
static void a_deep_pile_falls_asleep(void) {
    enum { COLUMNS = 15, ROWS = 40, COUNT = COLUMNS * ROWS };
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -10.0});
    scene_set_contacts_enabled(scene, true);
    double width = 1.12 * COLUMNS + 2.1;
    body_t *walls[3] = {
        body_init(polygon_make_box((vector_t){width / 2, -0.5}, width / 2 + 1, 0.5), INFINITY,
                  GREY),
        body_init(polygon_make_box((vector_t){-0.5, 50}, 0.5, 50), INFINITY, GREY),
        body_init(polygon_make_box((vector_t){width, 50}, 0.5, 50), INFINITY, GREY)};
    for (int k = 0; k < 3; k++) {
        body_set_friction(walls[k], 0.6);
        scene_add_body(scene, walls[k]);
    }
    static body_t *bodies[COUNT];
    const int sides[5] = {3, 4, 5, 6, 8};
    unsigned long long seed = 12345;
    for (int i = 0; i < COUNT; i++) {
        double u[3];
        for (int k = 0; k < 3; k++) {
            seed = (1103515245ull * seed + 12345ull) % 2147483648ull;
            u[k] = (double)seed / 2147483648.0;
        }
        vector_t at = {1.0 + 1.12 * (i % COLUMNS) + 0.1 * (u[0] - 0.5),
                       1.0 + 1.12 * (i / COLUMNS) + 0.1 * (u[1] - 0.5)};
        int n = sides[i % 5];
        double area = 0.5 * n * 0.25 * sin(2 * M_PI / n);
        bodies[i] = body_init(polygon_make_regular(n, 0.5, at, 2 * M_PI * u[2]), area, GREY);
        body_set_friction(bodies[i], 0.6);
        scene_add_body(scene, bodies[i]);
    }
    for (int second = 0; second < 10 && count_asleep(bodies, COUNT) < COUNT; second++) {
        run(scene, 60);
    }
    CHECK(count_asleep(bodies, COUNT) == COUNT);
    scene_free(scene);
}

/* A pulled body's travel counts whichever way it goes: a box under
 * gravity that creeps 9 mm/s up (against its pull) or sideways for a
 * second is slow by the 0.05 m/s tolerance either way, its timer runs and
 * it is ready at 0.5 s. A rule that held a rising body to 5 mm/s kept the
 * upward one from ever being ready, and with it the flanks of a heap that
 * creep up its walls while its middle settles (pile(4000) slept at 9.55 s
 * instead of 7.8 s). sleep_time_bodies is called as the world calls it,
 * with the step's displacement applied to the body after each call. */
static bool creeping_body_is_ready(vector_t step_move) {
    body_t *box = body_init(polygon_make_box((vector_t){0.0, 0.5}, 0.5, 0.5), 1.0, GREY);
    solver_velocity_t row = {vec_multiply(1.0 / DT, step_move), 0.0, 1.0, 1.0};
    solver_displacement_t moved = {step_move, 0.0, 0.0};
    solver_state_t state = {0};
    state.acceleration = (vector_t){0.0, -10.0};
    body_t *bodies[1] = {box};
    sleep_step_t step = {bodies, &row, &moved, &state, NULL, 1, DT, 0.0, 0.01, INFINITY, 0.5};
    bool ready = false;
    for (int i = 0; i < 60; i++) {
        ready = sleep_time_bodies(&step, 0, 1) == 1;
        box->centroid = vec_add(box->centroid, step_move);
    }
    body_free(box);
    return ready;
}

static void travel_counts_whichever_way_it_goes(void) {
    CHECK(creeping_body_is_ready((vector_t){0.009 * DT, 0.0}));
    CHECK(creeping_body_is_ready((vector_t){0.0, 0.009 * DT}));
    /* At 0.06 m/s, past the tolerance, neither is. */
    CHECK(!creeping_body_is_ready((vector_t){0.06 * DT, 0.0}));
    CHECK(!creeping_body_is_ready((vector_t){0.0, 0.06 * DT}));
}

/* The step leaves sleeping bodies out of its loops, listing the awake ones
 * anew only when who sleeps changes (scene.c, choose_step_bodies): every
 * change must reach that list. With every box asleep, on one worker and on
 * two: a box added in mid-air falls in the next step; a box woken by a
 * push between steps moves in the next one, and its stack sleeps again;
 * removing a sleeping box drops it from the scene and wakes the boxes on
 * it, which fall. */
static void the_step_lists_what_sleeping_leaves_out_anew(void) {
    for (size_t workers = 1; workers <= 2; workers++) {
        scene_t *scene = sleep_scene();
        scene_set_workers(scene, workers);
        body_t *left[3], *right[3];
        add_stack(scene, -10.0, left, 3);
        add_stack(scene, 10.0, right, 3);
        run(scene, 120);
        CHECK(count_asleep(left, 3) == 3 && count_asleep(right, 3) == 3);
        body_t *added = add_box(scene, 0.0, 6.0);
        run(scene, 1);
        CHECK(body_get_centroid(added).y < 6.0);
        run(scene, 120);
        CHECK(body_is_sleeping(added));
        body_add_impulse(right[2], (vector_t){0.5, 0.0});
        run(scene, 1);
        CHECK(body_get_centroid(right[2]).x > 10.0);
        run(scene, 240);
        CHECK(count_asleep(right, 3) == 3);
        CHECK(count_asleep(left, 3) == 3);
        double top = body_get_centroid(left[2]).y;
        body_remove(left[0]);
        run(scene, 1);
        CHECK(scene_bodies(scene) == 7); /* the floor, 5 boxes, the added one */
        CHECK(body_get_centroid(left[2]).y < top);
        run(scene, 120);
        CHECK_NEAR(body_get_centroid(left[2]).y, 1.5, 0.01);
        scene_free(scene);
    }
}

/* The integrator's contract for a sleeping body (integrator.h, motion.h):
 * predicting marks its motion still and writes nothing else of it, and
 * moving leaves the body as it is, whatever the rest of that motion holds;
 * a body put to sleep within the step (its motion made by the solve, not
 * still) is moved by it; an awake one moves as ever. */
static void a_sleeping_body_is_neither_predicted_nor_moved(void) {
    body_t *bodies[3];
    for (int i = 0; i < 3; i++) {
        bodies[i] = body_init(polygon_make_box((vector_t){2.0 * i, 0.0}, 0.5, 0.5), 1.0, GREY);
    }
    bodies[0]->asleep = true;
    integrator_step_t step = {INTEGRATOR_SEED, DT, {0.0, -10.0}, NULL, NULL, NULL, 0, 0};
    integrator_motion_t motions[3];
    for (int i = 0; i < 3; i++) {
        motions[i] = (integrator_motion_t){.displacement = {NAN, NAN}, .rotation = NAN};
    }
    integrator_predict_range(&step, bodies, motions, 0, 3);
    CHECK(motions[0].still);
    CHECK(isnan(motions[0].displacement.x)); /* not written */
    CHECK(!motions[1].still && !motions[2].still);
    CHECK(motions[1].velocity.y < 0.0);
    bodies[2]->asleep = true; /* put to sleep by this step's solve */
    motions[2].displacement = (vector_t){0.25, 0.0};
    integrator_outcome_t outcome = integrator_move(&step, bodies, 3, motions);
    CHECK(outcome.failed == 3 && !outcome.removed);
    CHECK(body_get_centroid(bodies[0]).x == 0.0 && body_get_centroid(bodies[0]).y == 0.0);
    CHECK(body_get_rotation(bodies[0]) == 0.0);
    CHECK(body_get_centroid(bodies[1]).y < 0.0);
    CHECK(body_get_centroid(bodies[2]).x == 4.25);
    for (int i = 0; i < 3; i++) body_free(bodies[i]);
}

TEST_SUITE(sleep, TEST_CASE(sleeping_and_waking_allocate_nothing_once_warm), TEST_CASE(settled_pile_falls_asleep),
           TEST_CASE(a_sleeping_body_is_neither_predicted_nor_moved),
           TEST_CASE(the_step_lists_what_sleeping_leaves_out_anew),
           TEST_CASE(a_deep_pile_falls_asleep), TEST_CASE(travel_counts_whichever_way_it_goes),
           TEST_CASE(sliding_sleeps_only_below_the_tolerance),
           TEST_CASE(slow_free_flight_keeps_moving),
           TEST_CASE(a_column_sleeps_only_once_pushed_apart),
           TEST_CASE(a_dropped_body_wakes_its_island_only),
           TEST_CASE(removing_a_support_wakes_what_rested_on_it),
           TEST_CASE(no_body_sleeps_in_mid_air), TEST_CASE(setters_wake_the_island),
           TEST_CASE(switching_sleeping_off_wakes_everything),
           TEST_CASE(a_sleeping_pair_does_not_fire_again),
           TEST_CASE(removing_the_floor_by_index_wakes_the_stack),
           TEST_CASE(removing_the_floor_wakes_the_stack),
           TEST_CASE(moving_the_floor_away_wakes_the_stack),
           TEST_CASE(turning_the_floor_wakes_what_it_held),
           TEST_CASE(filtering_the_floor_out_wakes_the_stack),
           TEST_CASE(flipping_gravity_wakes_the_stack),
           TEST_CASE(turning_gravity_wakes_what_it_pulls_sideways),
           TEST_CASE(removing_friction_wakes_a_box_on_a_slope),
           TEST_CASE(changing_elasticity_wakes_what_it_touches),
           TEST_CASE(adding_a_static_body_into_a_sleeping_one_wakes_it),
           TEST_CASE(moving_a_static_body_into_a_sleeping_one_wakes_it),
           TEST_CASE(a_body_reaped_while_paused_leaves_the_index));
