/* The state a scene carries from step to step (scene_state.h): a scene
 * rebuilt from another's bodies and that state continues bit for bit, and
 * bad input to the restoring functions stops with a message. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "jostle/jostle.h"
#include "test.h"

static const double DT = 1.0 / 60.0;
static const rgb_color_t GREY = {0.5, 0.5, 0.5};
enum { PILE = 40 };

/* Body i of the test scene: a floor and two walls, then PILE polygons. */
static body_t *make_body(int i) {
    if (i == 0) return body_init(polygon_make_box((vector_t){0, -0.5}, 6, 0.5), INFINITY, GREY);
    if (i <= 2) {
        double x = i == 1 ? -5.5 : 5.5;
        return body_init(polygon_make_box((vector_t){x, 5}, 0.5, 5), INFINITY, GREY);
    }
    int k = i - 3;
    list_t *shape = polygon_make_regular((size_t)(3 + k % 5), 0.45,
                                         (vector_t){-4.0 + (k % 8), 0.6 + 1.1 * (k / 8)},
                                         0.37 * k);
    return body_init(shape, 1.0 + 0.1 * (k % 3), GREY);
}

static scene_t *new_scene(void) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -9.81});
    scene_set_contacts_enabled(scene, true);
    for (int i = 0; i < PILE + 3; i++) {
        body_t *body = make_body(i);
        if (i >= 3) body_set_friction(body, 0.3 + 0.1 * (i % 4));
        scene_add_body(scene, body);
    }
    return scene;
}

static void run(scene_t *scene, int steps) {
    for (int i = 0; i < steps; i++) scene_tick(scene, DT);
}

static size_t index_in(scene_t *scene, body_t *body) {
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        if (scene_get_body(scene, i) == body) return i;
    }
    abort();
}

/* A new scene with `from`'s bodies where they are now and, when `state`,
 * the state scene_state.h describes. */
static scene_t *copy_of(scene_t *from, bool state) {
    scene_t *to = new_scene();
    size_t n = scene_bodies(from);
    for (size_t i = 0; i < n; i++) {
        body_t *a = scene_get_body(from, i), *b = scene_get_body(to, i);
        body_set_centroid(b, body_get_centroid(a));
        body_set_rotation(b, body_get_rotation(a));
        body_set_velocity(b, body_get_velocity(a));
        body_set_angular_velocity(b, body_get_angular_velocity(a));
        if (state) body_set_sleep_timer(b, body_get_sleep_timer(a));
    }
    if (!state) return to;
    body_t **sleepers = malloc(n * sizeof *sleepers);
    size_t *islands = malloc(n * sizeof *islands);
    size_t asleep = 0;
    for (size_t i = 0; i < n; i++) {
        body_t *a = scene_get_body(from, i);
        if (!body_is_sleeping(a)) continue;
        /* The island's number: its member of lowest index. */
        size_t island = i;
        for (body_t *m = body_get_island_next(a); m != a; m = body_get_island_next(m)) {
            size_t k = index_in(from, m);
            if (k < island) island = k;
        }
        sleepers[asleep] = scene_get_body(to, i);
        islands[asleep++] = island;
    }
    scene_restore_sleep(to, sleepers, islands, asleep);
    free(sleepers);
    free(islands);
    scene_set_sleep_phase(to, scene_get_sleep_phase(from));
    scene_set_solver_steps(to, scene_get_solver_steps(from));
    double last, before;
    scene_get_step_lengths(from, &last, &before);
    scene_set_step_lengths(to, last, before);
    size_t count = scene_contact_memory_count(from);
    scene_contact_memory_t *memories = malloc((count + 1) * sizeof *memories);
    for (size_t k = 0; k < count; k++) {
        memories[k] = scene_get_contact_memory(from, k);
        memories[k].body_a = scene_get_body(to, index_in(from, memories[k].body_a));
        memories[k].body_b = scene_get_body(to, index_in(from, memories[k].body_b));
    }
    scene_restore_contact_memory(to, memories, count);
    free(memories);
    return to;
}

static bool same_bits(double a, double b) {
    return memcmp(&a, &b, sizeof a) == 0;
}

/* How many bodies differ in a bit of pose, velocity or sleep. */
static int bodies_differing(scene_t *a, scene_t *b) {
    int differing = 0;
    for (size_t i = 0; i < scene_bodies(a); i++) {
        body_t *x = scene_get_body(a, i), *y = scene_get_body(b, i);
        vector_t p = body_get_centroid(x), q = body_get_centroid(y);
        vector_t u = body_get_velocity(x), v = body_get_velocity(y);
        bool same = same_bits(p.x, q.x) && same_bits(p.y, q.y) &&
                    same_bits(body_get_rotation(x), body_get_rotation(y)) && same_bits(u.x, v.x) &&
                    same_bits(u.y, v.y) &&
                    same_bits(body_get_angular_velocity(x), body_get_angular_velocity(y)) &&
                    body_is_sleeping(x) == body_is_sleeping(y);
        differing += !same;
    }
    return differing;
}

static int count_sleeping(scene_t *scene) {
    int asleep = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        asleep += body_is_sleeping(scene_get_body(scene, i));
    }
    return asleep;
}

/* A pile part asleep, part settling, with contacts warm: its copy with the
 * state continues bit for bit for 5 s (every body, every step); a copy of
 * the poses and velocities alone departs at once. */
static void a_copy_with_its_state_continues_bit_for_bit(void) {
    scene_t *original = new_scene();
    run(original, 150);
    int asleep = count_sleeping(original);
    CHECK(asleep > 0 && asleep < PILE);
    CHECK(scene_contact_memory_count(original) > 20);
    scene_t *copy = copy_of(original, true);
    scene_t *bare = copy_of(original, false);
    CHECK(bodies_differing(original, copy) == 0);
    CHECK(count_sleeping(copy) == asleep && count_sleeping(bare) == 0);
    bool bare_departed = false;
    for (int step = 0; step < 300; step++) {
        scene_tick(original, DT);
        scene_tick(copy, DT);
        scene_tick(bare, DT);
        if (bodies_differing(original, copy) != 0) {
            test_fail(__FILE__, __LINE__, "%d bodies differ at step %d",
                      bodies_differing(original, copy), step + 1);
            break;
        }
        bare_departed |= bodies_differing(original, bare) > 0;
    }
    CHECK(bare_departed);
    CHECK(count_sleeping(original) > asleep); /* the run went on settling */
    scene_free(original);
    scene_free(copy);
    scene_free(bare);
}

/* A step length drawn uniformly from 1/240 to 1/30 s (a fixed generator). */
static double random_dt(uint32_t *seed) {
    *seed = (uint32_t)((1103515245ull * *seed + 12345u) % 2147483648u);
    return 1.0 / 240.0 + (*seed / 2147483648.0) * (1.0 / 30.0 - 1.0 / 240.0);
}

/* The same under steps that vary: the copy takes the lengths of the last
 * two steps and, in each memory, the pair's points of the step before
 * last, which a step of another length reads. Without them (a copy of the
 * rest alone) it departs at the first step. */
static void a_copy_continues_bit_for_bit_under_varying_steps(void) {
    scene_t *original = new_scene();
    uint32_t seed = 99u;
    for (int i = 0; i < 80; i++) scene_tick(original, random_dt(&seed));
    double last, before;
    scene_get_step_lengths(original, &last, &before);
    CHECK(last > 0.0 && before > 0.0 && last != before);
    size_t with_previous = 0;
    for (size_t k = 0; k < scene_contact_memory_count(original); k++) {
        with_previous += scene_get_contact_memory(original, k).previous_count > 0;
    }
    CHECK(with_previous > 20);
    scene_t *copy = copy_of(original, true);
    scene_t *forgetful = copy_of(original, true);
    scene_set_step_lengths(forgetful, 0.0, 0.0);
    CHECK(bodies_differing(original, copy) == 0);
    bool forgetful_departed = false;
    for (int step = 0; step < 300; step++) {
        double dt = random_dt(&seed);
        scene_tick(original, dt);
        scene_tick(copy, dt);
        scene_tick(forgetful, dt);
        if (bodies_differing(original, copy) != 0) {
            test_fail(__FILE__, __LINE__, "%d bodies differ at step %d",
                      bodies_differing(original, copy), step + 1);
            break;
        }
        forgetful_departed |= bodies_differing(original, forgetful) > 0;
    }
    CHECK(forgetful_departed);
    scene_free(original);
    scene_free(copy);
    scene_free(forgetful);
}

/* The lengths read back as the last two steps were, and as set; a tick of
 * dt 0 takes no step and keeps them; contacts off reads 0. */
static void step_lengths_read_back(void) {
    scene_t *scene = new_scene();
    double last = -1.0, before = -1.0;
    scene_get_step_lengths(scene, &last, &before);
    CHECK(last == 0.0 && before == 0.0);
    scene_tick(scene, 0.02);
    scene_get_step_lengths(scene, &last, &before);
    CHECK(last == 0.02 && before == 0.0);
    scene_tick(scene, 0.005);
    scene_tick(scene, 0.0);
    scene_get_step_lengths(scene, &last, &before);
    CHECK(last == 0.005 && before == 0.02);
    scene_set_step_lengths(scene, 0.25, 0.125);
    scene_get_step_lengths(scene, &last, &before);
    CHECK(last == 0.25 && before == 0.125);
    scene_set_contacts_enabled(scene, false);
    scene_get_step_lengths(scene, &last, &before);
    CHECK(last == 0.0 && before == 0.0);
    scene_free(scene);
}

/* The contact memory is kept through a tick of dt 0 (a paused game), but
 * for the contacts of the bodies it reaps. */
static void a_paused_tick_keeps_the_memory_of_the_bodies_it_keeps(void) {
    scene_t *scene = new_scene();
    run(scene, 30);
    size_t before = scene_contact_memory_count(scene);
    body_t *gone = scene_get_body(scene, 10);
    size_t naming = 0;
    for (size_t k = 0; k < before; k++) {
        scene_contact_memory_t m = scene_get_contact_memory(scene, k);
        naming += m.body_a == gone || m.body_b == gone;
    }
    CHECK(naming > 0);
    body_remove(gone);
    scene_tick(scene, 0.0);
    CHECK(scene_contact_memory_count(scene) == before - naming);
    for (size_t k = 0; k < scene_contact_memory_count(scene); k++) {
        scene_contact_memory_t m = scene_get_contact_memory(scene, k);
        CHECK(m.body_a != gone && m.body_b != gone);
    }
    scene_free(scene);
}

/* A body's timer and filter read back as set; an island's circle visits
 * each of its bodies once. */
static void timers_filters_and_islands_read_back(void) {
    scene_t *scene = new_scene();
    body_t *body = scene_get_body(scene, 5);
    body_sleep_timer_t timer = {0.25, 0.125, {1.5, -2.0}, 0.75};
    body_set_sleep_timer(body, timer);
    body_sleep_timer_t read = body_get_sleep_timer(body);
    CHECK(read.slow_time == 0.25 && read.window == 0.125 && read.anchor.x == 1.5 &&
          read.anchor.y == -2.0 && read.anchor_angle == 0.75);
    uint32_t category, mask, group;
    body_get_collision_filter(body, &category, &mask, &group);
    CHECK(category == 1 && mask == UINT32_MAX && group == 0);
    body_set_collision_filter(body, 4, 6, 9);
    body_get_collision_filter(body, &category, NULL, &group);
    CHECK(category == 4 && group == 9);
    CHECK(body_get_island_next(body) == NULL);
    body_t *three[3] = {scene_get_body(scene, 3), scene_get_body(scene, 7),
                        scene_get_body(scene, 9)};
    size_t islands[3] = {42, 42, 42};
    scene_restore_sleep(scene, three, islands, 3);
    int seen[3] = {0, 0, 0};
    body_t *member = three[1];
    for (int k = 0; k < 3; k++) {
        for (int j = 0; j < 3; j++) seen[j] += member == three[j];
        member = body_get_island_next(member);
    }
    CHECK(member == three[1] && seen[0] == 1 && seen[1] == 1 && seen[2] == 1);
    body_set_velocity(three[2], (vector_t){1.0, 0.0});
    CHECK(count_sleeping(scene) == 0);
    scene_free(scene);
}

static scene_t *bad_scene;

/* A memory of bodies a and b of bad_scene, the rest zero. */
static scene_contact_memory_t bad_pair(size_t a, size_t b) {
    return (scene_contact_memory_t){.body_a = scene_get_body(bad_scene, a),
                                    .body_b = scene_get_body(bad_scene, b)};
}

static scene_contact_memory_t bad_nan, bad_count;
BAD_CALL(restore_static, scene_restore_sleep(bad_scene, (body_t *[]){scene_get_body(bad_scene, 0)},
                                             (size_t[]){0}, 1))
BAD_CALL(restore_twice, scene_restore_sleep(bad_scene,
                                            (body_t *[]){scene_get_body(bad_scene, 4),
                                                         scene_get_body(bad_scene, 4)},
                                            (size_t[]){0, 1}, 2))
BAD_CALL(restore_contacts_off, scene_set_contacts_enabled(bad_scene, false);
         scene_restore_sleep(bad_scene, NULL, NULL, 0))
BAD_CALL(restore_foreign, body_t *stranger = make_body(5);
         scene_restore_sleep(bad_scene, &stranger, (size_t[]){0}, 1))
BAD_CALL(phase_eight, scene_set_sleep_phase(bad_scene, 8))
BAD_CALL(timer_negative, body_set_sleep_timer(scene_get_body(bad_scene, 3),
                                              (body_sleep_timer_t){-1.0, 0.0, {0, 0}, 0.0}))
BAD_CALL(memory_self, bad_nan = bad_pair(3, 3);
         scene_restore_contact_memory(bad_scene, &bad_nan, 1))
BAD_CALL(memory_nan, bad_nan = bad_pair(3, 4); bad_nan.pose_angle = NAN;
         scene_restore_contact_memory(bad_scene, &bad_nan, 1))
BAD_CALL(memory_count, bad_count = bad_pair(3, 4); bad_count.point_count = 3;
         scene_restore_contact_memory(bad_scene, &bad_count, 1))
BAD_CALL(lengths_negative, scene_set_step_lengths(bad_scene, -0.01, 0.0))
BAD_CALL(lengths_nan, scene_set_step_lengths(bad_scene, 0.01, NAN))
BAD_CALL(lengths_before_alone, scene_set_step_lengths(bad_scene, 0.0, 0.01))
BAD_CALL(lengths_contacts_off, scene_set_contacts_enabled(bad_scene, false);
         scene_set_step_lengths(bad_scene, 0.01, 0.0))
BAD_CALL(solver_steps_contacts_off, scene_set_contacts_enabled(bad_scene, false);
         scene_set_solver_steps(bad_scene, 3))
BAD_CALL(memory_previous_count, bad_count = bad_pair(3, 4); bad_count.previous_count = 3;
         scene_restore_contact_memory(bad_scene, &bad_count, 1))
BAD_CALL(memory_previous_nan, bad_nan = bad_pair(3, 4); bad_nan.previous_count = 1;
         bad_nan.previous[0].tangent_impulse = NAN;
         scene_restore_contact_memory(bad_scene, &bad_nan, 1))
BAD_CALL(memory_twice, scene_restore_contact_memory(bad_scene,
                                                    (scene_contact_memory_t[]){bad_pair(3, 4),
                                                                               bad_pair(3, 4)},
                                                    2))

static void bad_state_stops_with_a_message(void) {
    bad_scene = new_scene();
    CHECK_DIES(restore_static, NULL, "engine error in scene_restore_sleep:",
               "bodies[0] cannot move");
    CHECK_DIES(restore_twice, NULL, "engine error in scene_restore_sleep:",
               "bodies[1] is asleep already");
    CHECK_DIES(restore_contacts_off, NULL, "engine error in scene_restore_sleep:",
               "world contacts are off");
    CHECK_DIES(restore_foreign, NULL, "engine error in scene_restore_sleep:",
               "bodies[0] is not a body of this scene");
    CHECK_DIES(phase_eight, NULL, "engine error in scene_set_sleep_phase:", "0 to 7");
    CHECK_DIES(timer_negative, NULL, "engine error in body_set_sleep_timer:", "slow_time");
    CHECK_DIES(memory_self, NULL, "engine error in scene_restore_contact_memory:",
               "memories[0] pairs a body with itself");
    CHECK_DIES(memory_nan, NULL, "engine error in scene_restore_contact_memory:", "not finite");
    CHECK_DIES(memory_count, NULL, "engine error in scene_restore_contact_memory:", "0 to 2");
    CHECK_DIES(lengths_negative, NULL, "engine error in scene_set_step_lengths:",
               "last must be finite and >= 0 (got -0.01)");
    CHECK_DIES(lengths_nan, NULL, "engine error in scene_set_step_lengths:",
               "before must be finite and >= 0 (got nan)");
    CHECK_DIES(lengths_before_alone, NULL, "engine error in scene_set_step_lengths:",
               "a step before the last needs a last step");
    CHECK_DIES(lengths_contacts_off, NULL, "engine error in scene_set_step_lengths:",
               "world contacts are off");
    CHECK_DIES(solver_steps_contacts_off, NULL, "engine error in scene_set_solver_steps:",
               "world contacts are off");
    CHECK_DIES(memory_previous_count, NULL, "engine error in scene_restore_contact_memory:",
               "previous_count must be 0 to 2");
    CHECK_DIES(memory_previous_nan, NULL, "engine error in scene_restore_contact_memory:",
               "not finite");
    CHECK_DIES(memory_twice, NULL, "engine error in scene_restore_contact_memory:",
               "bodies 3 and 4 is listed twice");
    scene_free(bad_scene);
}

TEST_SUITE(scene_state, TEST_CASE(a_copy_with_its_state_continues_bit_for_bit),
           TEST_CASE(a_copy_continues_bit_for_bit_under_varying_steps),
           TEST_CASE(step_lengths_read_back),
           TEST_CASE(a_paused_tick_keeps_the_memory_of_the_bodies_it_keeps),
           TEST_CASE(timers_filters_and_islands_read_back),
           TEST_CASE(bad_state_stops_with_a_message));
