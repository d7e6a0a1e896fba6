/* The solver's settings (scene.h), the step's profile and the inspector's
 * counts. */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "jostle/jostle.h"
#include "test.h"

static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};

static body_t *add_box(scene_t *scene, vector_t center, double half, double mass) {
    body_t *body = body_init(polygon_make_box(center, half, half), mass, GREY);
    scene_add_body(scene, body);
    return body;
}

/* The floor: the top of a 20 m x 1 m static box at y = 0. */
static body_t *add_floor(scene_t *scene) {
    body_t *body = body_init(polygon_make_box((vector_t){0, -0.5}, 10, 0.5), INFINITY, GREY);
    scene_add_body(scene, body);
    return body;
}

static scene_t *stack_scene(void) {
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    scene_set_gravity(scene, (vector_t){0, -9.81});
    add_floor(scene);
    for (int i = 0; i < 6; i++) add_box(scene, (vector_t){0.05 * (i % 2), 0.5 + 1.01 * i}, 0.5, 1.0);
    return scene;
}

static void defaults_and_reset(void) {
    scene_t *scene = scene_init();
    size_t velocity, position;
    double linear, angular;
    scene_get_solver_iterations(scene, &velocity, &position);
    scene_get_sleep_tolerance(scene, &linear, &angular);
    CHECK(velocity == 8 && position == 4);
    CHECK(scene_get_warm_starting(scene));
    CHECK(scene_get_restitution_threshold(scene) == 1.0);
    CHECK(linear == 0.01 && angular == INFINITY);
    CHECK(scene_get_sleep_time(scene) == 0.5);
    scene_set_solver_iterations(scene, 3, 2);
    scene_set_warm_starting(scene, false);
    scene_set_restitution_threshold(scene, 0.25);
    scene_set_sleep_tolerance(scene, 0.2, 0.5);
    scene_set_sleep_time(scene, 2.0);
    scene_get_solver_iterations(scene, &velocity, &position);
    scene_get_sleep_tolerance(scene, &linear, &angular);
    CHECK(velocity == 3 && position == 2 && !scene_get_warm_starting(scene));
    CHECK(scene_get_restitution_threshold(scene) == 0.25 && linear == 0.2 && angular == 0.5);
    CHECK(scene_get_sleep_time(scene) == 2.0);
    scene_reset_solver_settings(scene);
    scene_get_solver_iterations(scene, &velocity, &position);
    scene_get_sleep_tolerance(scene, &linear, &angular);
    CHECK(velocity == 8 && position == 4 && scene_get_warm_starting(scene));
    CHECK(scene_get_restitution_threshold(scene) == 1.0 && linear == 0.01 && angular == INFINITY);
    CHECK(scene_get_sleep_time(scene) == 0.5);
    scene_free(scene);
}

/* The bodies' poses after `steps` steps, hashed bit for bit. */
static uint64_t run_stack(bool warm_off_first, bool warm_final, int steps) {
    scene_t *scene = stack_scene();
    if (warm_off_first) scene_set_warm_starting(scene, false);
    scene_set_warm_starting(scene, warm_final);
    for (int i = 0; i < steps; i++) scene_tick(scene, 1.0 / 60.0);
    uint64_t hash = 1469598103934665603u;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        vector_t c = body_get_centroid(scene_get_body(scene, i));
        double a = body_get_rotation(scene_get_body(scene, i));
        unsigned char bytes[24];
        memcpy(bytes, &c, 16);
        memcpy(bytes + 16, &a, 8);
        for (int k = 0; k < 24; k++) hash = (hash ^ bytes[k]) * 1099511628211u;
    }
    scene_free(scene);
    return hash;
}

static void warm_starting_off_changes_results_on_restores_bits(void) {
    uint64_t on = run_stack(false, true, 120);
    CHECK(run_stack(false, false, 120) != on);
    CHECK(run_stack(true, true, 120) == on);
}

/* A box dropped at elasticity 0.5 onto a floor, landing at about 3.1
 * m/s: its highest velocity after the landing. */
static double rebound(double threshold) {
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    scene_set_gravity(scene, (vector_t){0, -9.81});
    scene_set_restitution_threshold(scene, threshold);
    add_floor(scene);
    body_t *box = add_box(scene, (vector_t){0, 1.0}, 0.5, 1.0);
    body_set_elasticity(box, 0.5);
    double highest = -INFINITY;
    for (int i = 0; i < 60; i++) {
        scene_tick(scene, 1.0 / 60.0);
        if (i > 20) highest = fmax(highest, body_get_velocity(box).y);
    }
    scene_free(scene);
    return highest;
}

static void restitution_threshold_decides_which_landings_bounce(void) {
    CHECK(rebound(1.0) > 1.0);   /* about half the landing speed */
    CHECK(rebound(5.0) < 1e-3);  /* the landing is slower than the threshold */
}

/* A lone 8 m box (radius 5.7 m: its tolerance is not cut for size)
 * drifting at `speed` and turning at `spin` through empty space: whether
 * it sleeps within 2 s. */
static bool sleeps(double speed, double spin, double linear, double angular, double time) {
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    scene_set_sleep_tolerance(scene, linear, angular);
    scene_set_sleep_time(scene, time);
    body_t *box = add_box(scene, (vector_t){0, 0}, 4.0, 1.0);
    body_set_velocity(box, (vector_t){speed, 0});
    body_set_angular_velocity(box, spin);
    for (int i = 0; i < 120; i++) scene_tick(scene, 1.0 / 60.0);
    bool asleep = body_is_sleeping(box);
    scene_free(scene);
    return asleep;
}

static void sleep_tolerances_and_time_decide_who_sleeps(void) {
    CHECK(!sleeps(0.05, 0.0, 0.01, INFINITY, 0.5));
    CHECK(sleeps(0.05, 0.0, 0.1, INFINITY, 0.5));
    CHECK(sleeps(0.0, 0.001, 0.01, INFINITY, 0.5));  /* rim speed 5.7 mm/s */
    CHECK(!sleeps(0.0, 0.001, 0.01, 0.0005, 0.5));
    CHECK(sleeps(0.005, 0.0, 0.01, INFINITY, 1.5));
    CHECK(!sleeps(0.005, 0.0, 0.01, INFINITY, 2.5)); /* not slow for long enough yet */
}

BAD_CALL(threshold_negative, scene_set_restitution_threshold(scene_init(), -1.0))
BAD_CALL(threshold_nan, scene_set_restitution_threshold(scene_init(), NAN))
BAD_CALL(linear_zero, scene_set_sleep_tolerance(scene_init(), 0.0, 1.0))
BAD_CALL(angular_negative, scene_set_sleep_tolerance(scene_init(), 0.01, -1.0))
BAD_CALL(time_zero, scene_set_sleep_time(scene_init(), 0.0))
BAD_CALL(profiling_null, scene_set_profiling(NULL, true))
BAD_CALL(stage_unknown, scene_stage_name(SCENE_STAGE_COUNT))

static void bad_settings_stop_with_the_function_named(void) {
    CHECK_DIES(threshold_negative, NULL, "engine error in scene_set_restitution_threshold:",
               "[0, 100]");
    CHECK_DIES(threshold_nan, NULL, "engine error in scene_set_restitution_threshold:", "nan");
    CHECK_DIES(linear_zero, NULL, "engine error in scene_set_sleep_tolerance:", "linear");
    CHECK_DIES(angular_negative, NULL, "engine error in scene_set_sleep_tolerance:", "angular");
    CHECK_DIES(time_zero, NULL, "engine error in scene_set_sleep_time:", "(0, 1000]");
    CHECK_DIES(profiling_null, NULL, "engine error in scene_set_profiling:", "NULL");
    CHECK_DIES(stage_unknown, NULL, "engine error in scene_stage_name:", "unknown stage");
}

static void profile_of_orbits_runs_no_contact_stage(void) {
    scene_t *scene = scene_init();
    scene_set_integrator(scene, INTEGRATOR_SYMPLECTIC_EULER);
    body_t *sun = add_box(scene, (vector_t){0, 0}, 0.1, 1e6);
    body_t *planet = add_box(scene, (vector_t){10, 0}, 0.1, 1.0);
    body_set_velocity(planet, (vector_t){0, 1});
    create_newtonian_gravity(scene, 1e-4, sun, planet);
    scene_profile_t before = scene_get_profile(scene);
    for (int k = 0; k < SCENE_STAGE_COUNT; k++) CHECK(!before.ran[k] && before.seconds[k] == 0.0);
    scene_tick(scene, 1e-3);
    scene_profile_t p = scene_get_profile(scene);
    CHECK(p.ran[SCENE_STAGE_FORCES] && p.ran[SCENE_STAGE_INTEGRATE]);
    for (int k = SCENE_STAGE_BROADPHASE; k <= SCENE_STAGE_POSITION; k++) {
        CHECK(!p.ran[k] && p.seconds[k] == 0.0);
    }
    CHECK(!p.ran[SCENE_STAGE_SLEEP] && !p.ran[SCENE_STAGE_REMOVAL]);
    CHECK(p.seconds[SCENE_STAGE_FORCES] >= 0.0 && p.seconds[SCENE_STAGE_INTEGRATE] >= 0.0);
    CHECK(p.islands == 0 && p.awake_bodies == 2 && p.sleeping_bodies == 0 && p.static_bodies == 0);
    CHECK(strcmp(scene_stage_name(SCENE_STAGE_FORCES), "forces") == 0);
    CHECK(strcmp(scene_stage_name(SCENE_STAGE_PREPARE), "prepare") == 0);
    CHECK(strcmp(scene_stage_name(SCENE_STAGE_REMOVAL), "removal") == 0);
    scene_free(scene);
}

static void profile_of_a_pile_and_the_inspector_counts(void) {
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    scene_set_gravity(scene, (vector_t){0, -9.81});
    body_t *floor = add_floor(scene);
    body_t *bottom = add_box(scene, (vector_t){0, 0.5}, 0.5, 1.0);
    body_t *top = add_box(scene, (vector_t){0, 1.5}, 0.5, 1.0);
    body_t *alone = add_box(scene, (vector_t){5, 0.5}, 0.5, 1.0);
    body_t *flying = add_box(scene, (vector_t){-5, 8}, 0.5, 1.0);
    scene_tick(scene, 1.0 / 60.0);
    scene_profile_t p = scene_get_profile(scene);
    for (int k = SCENE_STAGE_FORCES; k <= SCENE_STAGE_SLEEP; k++) CHECK(p.ran[k]);
    CHECK(!p.ran[SCENE_STAGE_REMOVAL]);
    /* {bottom, top}, {alone}, {flying}; the floor is in none. */
    CHECK(p.islands == 3 && p.awake_bodies == 4 && p.sleeping_bodies == 0 && p.static_bodies == 1);
    CHECK(scene_body_contact_count(scene, bottom) == 2);
    CHECK(scene_body_contact_count(scene, top) == 1);
    CHECK(scene_body_contact_count(scene, floor) == 2);
    CHECK(scene_body_contact_count(scene, flying) == 0);
    CHECK(scene_body_island(scene, bottom) == 1 && scene_body_island(scene, top) == 1);
    CHECK(scene_body_island(scene, alone) == 3 && scene_body_island(scene, flying) == 4);
    CHECK(scene_body_island(scene, floor) == SIZE_MAX);
    body_remove(flying);
    scene_tick(scene, 1.0 / 60.0);
    p = scene_get_profile(scene);
    CHECK(p.ran[SCENE_STAGE_REMOVAL] && p.islands == 2 && p.awake_bodies == 3);
    for (int i = 0; i < 120; i++) scene_tick(scene, 1.0 / 60.0);
    p = scene_get_profile(scene);
    /* Asleep, the stack is still one island and the lone box another. */
    CHECK(body_is_sleeping(bottom) && body_is_sleeping(top) && body_is_sleeping(alone));
    CHECK(p.islands == 2 && p.awake_bodies == 0 && p.sleeping_bodies == 3);
    CHECK(scene_body_island(scene, top) == 1 && scene_body_contact_count(scene, top) == 0);
    /* The floor never sleeps: the contact stages still run, over it alone. */
    CHECK(p.ran[SCENE_STAGE_BROADPHASE] && scene_get_stats(scene).contacts == 0);
    scene_set_contacts_enabled(scene, false);
    CHECK(scene_get_profile(scene).islands == 0 && scene_body_island(scene, top) == SIZE_MAX);
    scene_free(scene);
}

/* A stack stepped twice, profiling on in one: the same bits; seconds only
 * where profiling is on and the stage ran. */
static void profiling_times_the_stages_only_when_on(void) {
    scene_t *scenes[2];
    body_t *tops[2];
    for (int s = 0; s < 2; s++) {
        scenes[s] = scene_init();
        scene_set_contacts_enabled(scenes[s], true);
        scene_set_gravity(scenes[s], (vector_t){0, -9.81});
        add_floor(scenes[s]);
        add_box(scenes[s], (vector_t){0, 0.5}, 0.5, 1.0);
        tops[s] = add_box(scenes[s], (vector_t){0.1, 1.6}, 0.5, 1.0);
    }
    CHECK(!scene_get_profiling(scenes[0]));
    scene_set_profiling(scenes[1], true);
    CHECK(scene_get_profiling(scenes[1]));
    for (int i = 0; i < 60; i++) {
        scene_tick(scenes[0], 1.0 / 60.0);
        scene_tick(scenes[1], 1.0 / 60.0);
    }
    vector_t a = body_get_centroid(tops[0]), b = body_get_centroid(tops[1]);
    CHECK(a.x == b.x && a.y == b.y);
    scene_profile_t off = scene_get_profile(scenes[0]), on = scene_get_profile(scenes[1]);
    double total = 0.0;
    for (int k = 0; k < SCENE_STAGE_COUNT; k++) {
        CHECK(off.ran[k] == on.ran[k]);
        CHECK(off.seconds[k] == 0.0);
        CHECK(on.ran[k] ? on.seconds[k] >= 0.0 : on.seconds[k] == 0.0);
        total += on.seconds[k];
    }
    CHECK(on.ran[SCENE_STAGE_PREPARE] && on.ran[SCENE_STAGE_SOLVER] && total > 0.0);
    scene_set_profiling(scenes[1], false);
    scene_tick(scenes[1], 1.0 / 60.0);
    CHECK(scene_get_profile(scenes[1]).seconds[SCENE_STAGE_SOLVER] == 0.0);
    scene_free(scenes[0]);
    scene_free(scenes[1]);
}

TEST_SUITE(settings, TEST_CASE(defaults_and_reset),
           TEST_CASE(warm_starting_off_changes_results_on_restores_bits),
           TEST_CASE(restitution_threshold_decides_which_landings_bounce),
           TEST_CASE(sleep_tolerances_and_time_decide_who_sleeps),
           TEST_CASE(bad_settings_stop_with_the_function_named),
           TEST_CASE(profile_of_orbits_runs_no_contact_stage),
           TEST_CASE(profile_of_a_pile_and_the_inspector_counts),
           TEST_CASE(profiling_times_the_stages_only_when_on));
