/* A step that varies from tick to tick, as a game's that steps with its
 * frame time: resting bodies rest as they do at a fixed step, because warm
 * starting carries last step's contact forces into this step's length
 * rather than its impulses (docs/api.md, Step size). Run from the
 * repository root, as make check does. */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "jostle/jostle.h"
#include "jostle/scene_file.h"
#include "test.h"

static const rgb_color_t GREY = {0.5, 0.5, 0.5};

/* The steps a pattern gives, k counting from 0 (s). */
typedef double (*step_pattern_t)(uint32_t *state, int k);

/* Uniform in [1/240, 1/30] from a fixed seed (the benchmark scenes'
 * generator, docs/bench.md). */
static double random_step(uint32_t *state, int k) {
    (void)k;
    *state = (uint32_t)((1103515245ull * *state + 12345u) % 2147483648u);
    return 1.0 / 240.0 + (*state / 2147483648.0) * (1.0 / 30.0 - 1.0 / 240.0);
}

/* 1/240 s and 1/30 s by turns: the largest change, every step. */
static double alternating_step(uint32_t *state, int k) {
    (void)state;
    return k % 2 == 0 ? 1.0 / 240.0 : 1.0 / 30.0;
}

/* Steps the scene for `seconds` by the pattern; returns the largest
 * distance body went from where it was at the start. */
static double largest_drift(scene_t *scene, body_t *body, step_pattern_t pattern,
                            double seconds) {
    uint32_t state = 12345;
    vector_t start = body_get_centroid(body);
    double drift = 0.0, t = 0.0;
    for (int k = 0; t < seconds; k++) {
        double dt = pattern(&state, k);
        scene_tick(scene, dt);
        t += dt;
        drift = fmax(drift, vec_get_length(vec_subtract(body_get_centroid(body), start)));
    }
    return drift;
}

static bool all_movable_asleep(scene_t *scene) {
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (isfinite(body_get_mass(body)) && !body_is_sleeping(body)) return false;
    }
    return true;
}

/* The pyramid preset (55 boxes on a floor) for 20 s of the pattern's steps:
 * its top moves less than `most` (m) and, with sleeping, all of it sleeps.
 * At a fixed 1/30 s the top moves 3 mm and the pyramid sleeps after 0.8 s. */
static void check_pyramid_rests(step_pattern_t pattern, bool sleeping, double most) {
    scene_file_error_t error;
    scene_file_t *file = scene_file_load("assets/scenes/pyramid.scene", &error);
    if (file == NULL) {
        test_fail(__FILE__, __LINE__, "%s", error.message);
        return;
    }
    scene_t *scene = scene_file_get_scene(file);
    scene_set_sleeping(scene, sleeping);
    body_t *top = scene_file_find_body(file, "top");
    CHECK(top != NULL);
    if (top != NULL) {
        CHECK(largest_drift(scene, top, pattern, 20.0) < most);
        if (sleeping) CHECK(all_movable_asleep(scene));
    }
    scene_file_free(file);
}

/* Before: the top went 5 cm (random) and 0.20 m (alternating) sideways,
 * and at alternating steps no body ever slept. Now 2.5 and 1.9 mm. */
static void pyramid_sleeps_under_random_steps(void) {
    check_pyramid_rests(random_step, true, 0.01);
}

static void pyramid_sleeps_under_alternating_steps(void) {
    check_pyramid_rests(alternating_step, true, 0.01);
}

/* Sleeping off, so nothing hides a creep: before, the top went 0.20 m at
 * alternating steps and 4 cm at random ones, now 3 mm; at a fixed 1/30 s
 * it goes 5 mm. */
static void awake_pyramid_holds_under_varying_steps(void) {
    check_pyramid_rests(alternating_step, false, 0.02);
    check_pyramid_rests(random_step, false, 0.02);
}

/* A unit box at rest on a floor tilted by `slope` (rad), friction mu on
 * both, sleeping off, for 20 s of the pattern's steps: how far it went. */
static double box_drift(double slope, double mu, step_pattern_t pattern) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -9.81});
    scene_set_contacts_enabled(scene, true);
    scene_set_sleeping(scene, false);
    body_t *floor = body_init(polygon_make_box((vector_t){0.0, -0.5}, 20.0, 0.5), INFINITY, GREY);
    body_set_rotation(floor, slope);
    body_set_friction(floor, mu);
    scene_add_body(scene, floor);
    /* Resting on the floor's top face, whose middle is 0.5 m from the
     * floor's centroid along its normal. */
    vector_t normal = {-sin(slope), cos(slope)};
    body_t *box = body_init(polygon_make_box(VEC_ZERO, 0.5, 0.5), 1.0, GREY);
    body_set_rotation(box, slope);
    body_set_centroid(box, vec_add((vector_t){0.0, -0.5}, normal));
    body_set_friction(box, mu);
    scene_add_body(scene, box);
    /* Settled at a fixed step first: what follows measures the varying
     * step alone. */
    for (int i = 0; i < 120; i++) scene_tick(scene, 1.0 / 60.0);
    double drift = largest_drift(scene, box, pattern, 20.0);
    scene_free(scene);
    return drift;
}

/* Friction holds the box on a 0.35 rad slope (it needs tan 0.35 = 0.365 of
 * the 0.45 there is), at a fixed step exactly. Before, under a varying step
 * it crept down 2.7 cm (alternating) and 5 mm (random) in 20 s: a long step
 * after a short one started from an eighth of the friction it needed, and
 * its iterations fell 2% short. */
static void box_on_slope_holds_under_varying_steps(void) {
    CHECK(box_drift(0.35, 0.45, alternating_step) <= 1e-9);
    CHECK(box_drift(0.35, 0.45, random_step) <= 1e-9);
}

/* On a level floor a box's contact is solved exactly at any warm start. */
static void box_on_floor_holds_under_varying_steps(void) {
    CHECK(box_drift(0.0, 0.5, alternating_step) <= 1e-9);
    CHECK(box_drift(0.0, 0.5, random_step) <= 1e-9);
}

/* The rescaled warm start reads the contacts of two steps back while the
 * narrowphase runs over threads: 2 s of random steps of the awake pyramid
 * give the same bytes with 1 and 3 workers. */
static void varying_steps_give_the_same_bytes_on_workers(void) {
    enum { MAX_BODIES = 64 };
    double state[2][MAX_BODIES][6];
    size_t count[2] = {0, 0};
    for (int run = 0; run < 2; run++) {
        scene_file_error_t error;
        scene_file_t *file = scene_file_load("assets/scenes/pyramid.scene", &error);
        if (file == NULL) {
            test_fail(__FILE__, __LINE__, "%s", error.message);
            return;
        }
        scene_t *scene = scene_file_get_scene(file);
        scene_set_sleeping(scene, false);
        scene_set_workers(scene, run == 0 ? 1 : 3);
        uint32_t seed = 12345;
        for (double t = 0.0; t < 2.0;) {
            double dt = random_step(&seed, 0);
            scene_tick(scene, dt);
            t += dt;
        }
        count[run] = scene_bodies(scene);
        for (size_t i = 0; i < count[run] && i < MAX_BODIES; i++) {
            body_t *body = scene_get_body(scene, i);
            vector_t c = body_get_centroid(body), v = body_get_velocity(body);
            double row[6] = {c.x, c.y, v.x, v.y, body_get_rotation(body),
                             body_get_angular_velocity(body)};
            memcpy(state[run][i], row, sizeof row);
        }
        scene_file_free(file);
    }
    CHECK(count[0] == count[1] && count[0] <= MAX_BODIES);
    size_t compared = count[0] < MAX_BODIES ? count[0] : MAX_BODIES;
    CHECK(memcmp(state[0], state[1], compared * sizeof state[0][0]) == 0);
}

/* How deep two convex polygons overlap (m): the least overlap of their
 * projections on the edge normals of both; 0 when some axis parts them. */
static double overlap_depth(body_t *a, body_t *b) {
    polygon_t p = body_get_polygon(a), q = body_get_polygon(b);
    double depth = INFINITY;
    for (int side = 0; side < 2; side++) {
        const polygon_t *axes = side == 0 ? &p : &q;
        for (size_t k = 0; k < axes->count; k++) {
            vector_t n = axes->normals[k];
            double p_min = INFINITY, p_max = -INFINITY, q_min = INFINITY, q_max = -INFINITY;
            for (size_t i = 0; i < p.count; i++) {
                double x = vec_dot(p.vertices[i], n);
                p_min = fmin(p_min, x);
                p_max = fmax(p_max, x);
            }
            for (size_t i = 0; i < q.count; i++) {
                double x = vec_dot(q.vertices[i], n);
                q_min = fmin(q_min, x);
                q_max = fmax(q_max, x);
            }
            depth = fmin(depth, fmin(p_max, q_max) - fmax(p_min, q_min));
        }
    }
    return fmax(depth, 0.0);
}

/* How far a box of half extents (0.5, 0.5) moving along `direction` goes
 * before it touches a sleeper of half extents `half` (both axis-aligned). */
static double gap_along(body_t *mover, body_t *sleeper, vector_t half, vector_t direction) {
    vector_t apart = vec_subtract(body_get_centroid(sleeper), body_get_centroid(mover));
    double gap = -INFINITY;
    if (fabs(direction.x) > 1e-12) {
        gap = fmax(gap, (fabs(apart.x) - 0.5 - half.x) / fabs(direction.x));
    }
    if (fabs(direction.y) > 1e-12) {
        gap = fmax(gap, (fabs(apart.y) - 0.5 - half.y) / fabs(direction.y));
    }
    return gap;
}

/* A unit box at `speed` along `angle` toward the middle of a face of a
 * box at rest, at steps of short_dt until the next step of long_dt would
 * carry it most of the way in, then at steps of long_dt. */
typedef struct {
    double speed, angle, short_dt, long_dt;
    vector_t half; /* the half extents of the box at rest */
    bool on_floor; /* gravity, and a floor that the box at rest stands on */
} approach_t;

/* The deepest the mover goes into the box at rest, which sleeps when it
 * reaches it if `sleeping`; whether it wakes (if it slept) and whether the
 * mover passes its middle. */
typedef struct {
    double deepest;
    bool woke, passed;
} approach_result_t;

static approach_result_t approach(approach_t run, bool sleeping) {
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    scene_set_sleeping(scene, sleeping);
    if (run.on_floor) {
        scene_set_gravity(scene, (vector_t){0.0, -9.81});
        scene_add_body(scene, body_init(polygon_make_box((vector_t){0.0, -0.5}, 40.0, 0.5),
                                        INFINITY, GREY));
    }
    vector_t middle = {0.0, run.half.y};
    body_t *rest = body_init(polygon_make_box(middle, run.half.x, run.half.y), 1.0, GREY);
    scene_add_body(scene, rest);
    for (double t = 0.0; t < 1.0; t += run.short_dt) scene_tick(scene, run.short_dt);
    CHECK(body_is_sleeping(rest) == sleeping);

    /* A metre and a long step from the face it heads for. */
    vector_t direction = {cos(run.angle), sin(run.angle)};
    vector_t face = fabs(direction.x) > fabs(direction.y)
                        ? (vector_t){direction.x > 0.0 ? -run.half.x - 0.5 : run.half.x + 0.5, 0.0}
                        : (vector_t){0.0, direction.y > 0.0 ? -run.half.y - 0.5 : run.half.y + 0.5};
    double along = fabs(vec_dot(face, direction)) / vec_get_length(face);
    double distance = (1.0 + run.speed * run.long_dt) / along;
    vector_t start = vec_subtract(vec_add(middle, face), vec_multiply(distance, direction));
    body_t *mover = body_init(polygon_make_box(start, 0.5, 0.5), 1.0, GREY);
    body_set_friction(mover, 0.0);
    body_set_velocity(mover, vec_multiply(run.speed, direction));
    scene_add_body(scene, mover);

    approach_result_t result = {0.0, false, false};
    bool switched = false;
    for (double t = 0.0; t < 1.0;) {
        switched |= gap_along(mover, rest, run.half, direction) < 0.6 * run.speed * run.long_dt;
        double dt = switched ? run.long_dt : run.short_dt;
        scene_tick(scene, dt);
        t += switched ? dt : 0.0;
        result.deepest = fmax(result.deepest, overlap_depth(mover, rest));
        result.woke |= !body_is_sleeping(rest);
        vector_t apart = vec_subtract(body_get_centroid(rest), body_get_centroid(mover));
        result.passed |= vec_dot(apart, vec_multiply(-1.0, face)) < 0.0;
    }
    scene_free(scene);
    return result;
}

/* Whatever the steps, a sleeping box lets the mover in no further than the
 * solver's slop (1 mm) beyond where the same box awake lets it, and
 * wakes. */
static void check_wakes_before_entering(approach_t run) {
    approach_result_t awake = approach(run, false), asleep = approach(run, true);
    if (asleep.deepest > awake.deepest + 0.001 || asleep.passed || !asleep.woke) {
        test_fail(__FILE__, __LINE__,
                  "at %g m/s, angle %g rad, steps %g then %g s%s: %g m deep (awake %g), "
                  "passed %d, woke %d",
                  run.speed, run.angle, run.short_dt, run.long_dt,
                  run.on_floor ? " on a floor" : "", asleep.deepest, awake.deepest,
                  asleep.passed, asleep.woke);
    }
}

/* Before, a box at 10 m/s went 17 cm into a sleeping box in a step of
 * 1/30 s after steps of 1/240 s: the reach that wakes a sleeper was sized
 * by the last step's length. */
static void a_longer_step_wakes_sleepers_before_entering(void) {
    const double steps[][2] = {{1.0 / 240.0, 1.0 / 30.0}, {1.0 / 1000.0, 1.0 / 10.0}};
    const double speeds[] = {2.0, 10.0, 30.0};
    const double angles[] = {0.0, 0.5, -1.0, M_PI, M_PI + 0.5, -M_PI / 2.0, 1.2};
    for (size_t s = 0; s < 2; s++) {
        for (size_t v = 0; v < sizeof speeds / sizeof speeds[0]; v++) {
            for (size_t a = 0; a < sizeof angles / sizeof angles[0]; a++) {
                check_wakes_before_entering((approach_t){speeds[v], angles[a], steps[s][0],
                                                         steps[s][1], {4.0, 4.0}, false});
            }
            check_wakes_before_entering((approach_t){speeds[v], 0.0, steps[s][0], steps[s][1],
                                                     {0.5, 0.5}, false});
            /* Sliding along the floor, and falling onto the box at rest from
             * above, gravity adding to what a long step covers. */
            check_wakes_before_entering((approach_t){speeds[v], 0.0, steps[s][0], steps[s][1],
                                                     {0.5, 0.5}, true});
            check_wakes_before_entering((approach_t){speeds[v], -M_PI / 2.0, steps[s][0],
                                                     steps[s][1], {0.5, 0.5}, true});
        }
    }
}

TEST_SUITE(step_size, TEST_CASE(pyramid_sleeps_under_random_steps),
           TEST_CASE(pyramid_sleeps_under_alternating_steps),
           TEST_CASE(awake_pyramid_holds_under_varying_steps),
           TEST_CASE(box_on_slope_holds_under_varying_steps),
           TEST_CASE(box_on_floor_holds_under_varying_steps),
           TEST_CASE(varying_steps_give_the_same_bytes_on_workers),
           TEST_CASE(a_longer_step_wakes_sleepers_before_entering));
