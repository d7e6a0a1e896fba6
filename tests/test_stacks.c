/* Tall and heavy stacks with world contacts: a column of twenty boxes and
 * a heavy box on a light one, the cases a few velocity iterations alone
 * cannot hold (engine/src/solver/shock.h). */
#include <math.h>
#include <stdint.h>
#include "jostle/jostle.h"
#include "test.h"

static const double DT = 1.0 / 60.0;
static const rgb_color_t GREY = {0.5, 0.5, 0.5};

/* Sleeping off: these measure the solver holding the stacks, and a
 * sleeping stack holds trivially (test_sleep.c). */
static scene_t *stack_scene(void) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -10.0});
    scene_set_contacts_enabled(scene, true);
    scene_set_sleeping(scene, false);
    scene_add_body(scene, body_init(polygon_make_box((vector_t){0, -0.5}, 20, 0.5), INFINITY,
                                    GREY));
    return scene;
}

static body_t *add_box(scene_t *scene, double x, double y, double mass) {
    body_t *box = body_init(polygon_make_box((vector_t){x, y}, 0.5, 0.5), mass, GREY);
    scene_add_body(scene, box);
    return box;
}

/* The benchmark scenes' generator (docs/bench.md): u in [0, 1). */
static double next_uniform(uint32_t *state) {
    *state = (uint32_t)((1103515245ull * *state + 12345u) % 2147483648u);
    return *state / 2147483648.0;
}

/* Twenty unit boxes, each `gap` above the one below and shifted sideways
 * by up to `jitter` / 2, for 60 s: every box stays where it was put. */
static void check_column_stands(double gap, double jitter) {
    enum { BOXES = 20 };
    scene_t *scene = stack_scene();
    uint32_t seed = 12345;
    body_t *boxes[BOXES];
    double x0[BOXES];
    for (int j = 0; j < BOXES; j++) {
        x0[j] = jitter * (next_uniform(&seed) - 0.5);
        boxes[j] = add_box(scene, x0[j], 0.5 + j * (1.0 + gap), 1.0);
    }
    for (int i = 0; i < 3600; i++) scene_tick(scene, DT);
    for (int j = 0; j < BOXES; j++) {
        CHECK_NEAR(body_get_centroid(boxes[j]).x, x0[j], 0.01);
        /* each contact may overlap by the solver's 1 mm slop */
        CHECK_NEAR(body_get_centroid(boxes[j]).y, 0.5 + j, 0.0011 * (j + 1));
        CHECK_NEAR(body_get_rotation(boxes[j]), 0.0, 0.001);
        CHECK(vec_get_length(body_get_velocity(boxes[j])) < 1e-3);
    }
    scene_free(scene);
}

/* Before shock propagation: the exact column fell at 2 s, with a 1 cm gap
 * at 8 s, with 1 cm of jitter at 7 s. Before the position pass pushed both
 * points of a flat contact at once, dropped with gaps of 1.01 and 1.2 cm
 * the top box slid 1.8 and 1.5 cm as the boxes landed (see
 * box_dropped_flat_lands_without_turning). */
static void column_of_twenty_stands_a_minute(void) {
    check_column_stands(0.0, 0.0);
    check_column_stands(0.01, 0.0);
    check_column_stands(0.0101, 0.0);
    check_column_stands(0.012, 0.0);
    check_column_stands(0.0, 0.02);
}

/* A box dropped flat onto a box resting on the floor lands flat: no spin
 * and no slide, to round-off, from any height. The landing overlaps the
 * boxes by centimetres, which the position pass removes; pushed one point
 * after the other, the first push turned the box and the second undid only
 * part of it: from 0.5 m the pair turned at 0.083 rad/s and slid 4.7 mm,
 * from 3 m 10 mm. */
static void box_dropped_flat_lands_without_turning(void) {
    const double heights[] = {0.4, 0.5, 0.7, 0.8, 0.9, 3.0};
    for (size_t h = 0; h < sizeof heights / sizeof heights[0]; h++) {
        scene_t *scene = stack_scene();
        body_t *boxes[2] = {add_box(scene, 0.0, 0.5, 1.0), add_box(scene, 0.0, 1.5 + heights[h], 1.0)};
        double spin = 0.0, slide = 0.0;
        for (int step = 0; step < 300; step++) {
            scene_tick(scene, DT);
            for (int j = 0; j < 2; j++) {
                spin = fmax(spin, fabs(body_get_angular_velocity(boxes[j])));
                slide = fmax(slide, fabs(body_get_centroid(boxes[j]).x));
            }
        }
        CHECK(spin < 1e-12);
        CHECK(slide < 1e-9);
        CHECK_NEAR(body_get_centroid(boxes[1]).y, 1.5, 0.0022); /* two contacts' 1 mm slop */
        scene_free(scene);
    }
}

/* The stack2 benchmark scene: a box of density r on a box of density 1.
 * Before: the heavy box slid off at r = 1000 and 10^4. */
static void heavy_box_stays_on_light_box(void) {
    const double ratios[] = {1, 10, 100, 1000, 10000};
    for (size_t i = 0; i < 5; i++) {
        scene_t *scene = stack_scene();
        body_t *light = add_box(scene, 0.0, 0.5, 1.0);
        body_t *heavy = add_box(scene, 0.0, 1.5, ratios[i]);
        for (int step = 0; step < 600; step++) scene_tick(scene, DT);
        vector_t a = body_get_centroid(light), b = body_get_centroid(heavy);
        CHECK(fabs(b.x - a.x) < 0.01);
        CHECK(b.y - a.y > 0.99);
        CHECK(a.y > 0.49);
        scene_free(scene);
    }
}

/* Thirty boxes made 4 mm into the box below: the lift (shock_lift) raises
 * each out of its support from the ground up, so within a second every
 * overlap is back to the 1 mm slop. Pushed by the position iterations
 * alone, each of both boxes and none knowing what rests above, the
 * deepest overlap shrank by 0.13 mm a second (4.0 mm after 4.5 s). */
static void overlapping_column_is_lifted_apart(void) {
    enum { BOXES = 30 };
    const double overlap = 0.004;
    scene_t *scene = stack_scene();
    body_t *boxes[BOXES];
    for (int j = 0; j < BOXES; j++) {
        boxes[j] = add_box(scene, 0.0, 0.5 + j * (1.0 - overlap) - overlap, 1.0);
    }
    for (int i = 0; i < 60; i++) scene_tick(scene, DT);
    CHECK(body_get_centroid(boxes[0]).y > 0.5 - 0.0011);
    for (int j = 1; j < BOXES; j++) {
        double gap = body_get_centroid(boxes[j]).y - body_get_centroid(boxes[j - 1]).y - 1.0;
        CHECK(gap > -0.0011);
        CHECK_NEAR(body_get_centroid(boxes[j]).x, 0.0, 1e-9);
    }
    scene_free(scene);
}

/* A box at rest on one that slides over ice (no friction below, mu 1
 * between them): nothing pushes the pair sideways, so their momentum along
 * the floor may only fall (shock propagation holds the lower box still and
 * may take momentum out, never put it in). Friction between them moves
 * momentum from one to the other. When shock propagation welded the upper
 * box to the lower one's motion whenever friction allowed it, the pair
 * gained 9.4% in the first step. */
static void box_on_a_sliding_box_gains_no_momentum(void) {
    const double speeds[] = {0.01, 0.05, 0.08};
    for (size_t k = 0; k < 3; k++) {
        scene_t *scene = stack_scene();
        body_set_friction(scene_get_body(scene, 0), 0.0);
        body_t *lower = add_box(scene, 0.0, 0.5, 1.0);
        body_t *upper = add_box(scene, 0.0, 1.5, 1.0);
        body_set_friction(lower, 1.0);
        body_set_friction(upper, 1.0);
        for (int step = 0; step < 60; step++) scene_tick(scene, DT);
        CHECK_NEAR(body_get_velocity(upper).x, 0.0, 1e-12);
        body_set_velocity(lower, (vector_t){speeds[k], body_get_velocity(lower).y});
        double most = 0.0;
        for (int step = 0; step < 120; step++) {
            scene_tick(scene, DT);
            double p = body_get_velocity(lower).x + body_get_velocity(upper).x;
            most = fmax(most, p);
        }
        CHECK(most <= speeds[k] * (1.0 + 1e-5));
        CHECK(most >= speeds[k] * (1.0 - 1e-5)); /* nor lost it at once */
        scene_free(scene);
    }
}

TEST_SUITE(stacks, TEST_CASE(column_of_twenty_stands_a_minute),
           TEST_CASE(box_on_a_sliding_box_gains_no_momentum),
           TEST_CASE(overlapping_column_is_lifted_apart),
           TEST_CASE(box_dropped_flat_lands_without_turning),
           TEST_CASE(heavy_box_stays_on_light_box));
