/* The integrators of scene.h: their orders on scenes with exact answers
 * (tests/reference.c, the quick version of make report), conservation,
 * stability limits, and how the multi-stage schemes call force creators. */
#include <stdlib.h>
#include <string.h>
#include "jostle/jostle.h"
#include "dynamics/integrator.h"
#include "reference.h"
#include "test.h"

static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};

static body_t *added_square(scene_t *scene, vector_t center, double half, double mass) {
    body_t *body = body_init(polygon_make_box(center, half, half), mass, GREY);
    scene_add_body(scene, body);
    return body;
}

static const integrator_t ALL[INTEGRATOR_COUNT] = {
    INTEGRATOR_SEED,           INTEGRATOR_EXPLICIT_EULER, INTEGRATOR_SYMPLECTIC_EULER,
    INTEGRATOR_VELOCITY_VERLET, INTEGRATOR_RK4,            INTEGRATOR_SYMPLECTIC4,
    INTEGRATOR_IMPLICIT_EULER};
static const double ORDER[INTEGRATOR_COUNT] = {1, 1, 1, 2, 4, 4, 1};

/* The slope of log error against log h between h and h / 4. */
static double fitted_order(reference_scene_t scene, integrator_t integrator, double h,
                           double periods) {
    reference_result_t coarse = reference_run(scene, integrator, h, periods);
    reference_result_t fine = reference_run(scene, integrator, h / 4.0, periods);
    CHECK(!coarse.diverged && !fine.diverged);
    return log(coarse.error / fine.error) / log(4.0);
}

/* 10.25 periods: at whole periods symplectic Euler's first-order error
 * cancels (it is Verlet seen through a half kick), and its order would
 * read 2. */
static void oscillator_errors_fall_at_each_schemes_order(void) {
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        double order = fitted_order(REFERENCE_OSCILLATOR, ALL[i], 1.0 / 480.0, 10.25);
        if (fabs(order - ORDER[i]) > 0.3) {
            test_fail(__FILE__, __LINE__, "%s: order %.3f, theory %g",
                      integrator_get_name(ALL[i]), order, ORDER[i]);
        }
    }
}

/* Kepler at e = 0.6 over 2.25 orbits, each scheme between steps where its
 * error is past the start-up and above round-off. */
static void kepler_errors_fall_at_each_schemes_order(void) {
    const double period = reference_period(REFERENCE_KEPLER);
    const double steps_per_orbit[INTEGRATOR_COUNT] = {32768, 32768, 8192, 2048, 2048, 2048, 8192};
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        double order =
            fitted_order(REFERENCE_KEPLER, ALL[i], period / steps_per_orbit[i], 2.25);
        if (fabs(order - ORDER[i]) > 0.3) {
            test_fail(__FILE__, __LINE__, "%s: order %.3f, theory %g",
                      integrator_get_name(ALL[i]), order, ORDER[i]);
        }
    }
}

/* A central force changes no angular momentum, and a symplectic scheme's
 * kicks and drifts each keep it; its energy error stays bounded: no larger
 * over 100 orbits than over the first 10. */
static void symplectic_schemes_keep_the_orbit(void) {
    const integrator_t symplectic[] = {INTEGRATOR_SYMPLECTIC_EULER, INTEGRATOR_VELOCITY_VERLET,
                                       INTEGRATOR_SYMPLECTIC4};
    const double h = reference_period(REFERENCE_KEPLER) / 1024.0;
    for (size_t i = 0; i < 3; i++) {
        reference_result_t ten = reference_run(REFERENCE_KEPLER, symplectic[i], h, 10.0);
        reference_result_t hundred = reference_run(REFERENCE_KEPLER, symplectic[i], h, 100.0);
        CHECK(!hundred.diverged);
        CHECK(hundred.momentum_drift < 1e-12);
        CHECK(hundred.energy_drift <= 1.01 * ten.energy_drift);
        CHECK(hundred.energy_drift < 0.1);
    }
}

/* Explicit Euler maps (x, v / omega) by 1 + omega h J, J a quarter turn:
 * every step multiplies the energy by exactly 1 + (omega h)^2. */
static void explicit_euler_oscillator_energy_grows_by_the_formula(void) {
    const double k = 4.0, h = 0.05, theta = 2.0 * h; /* omega = 2 */
    scene_t *scene = scene_init();
    scene_set_integrator(scene, INTEGRATOR_EXPLICIT_EULER);
    body_t *anchor = added_square(scene, VEC_ZERO, 0.05, INFINITY);
    body_t *body = added_square(scene, (vector_t){1.0, 0.0}, 0.05, 1.0);
    body_set_velocity(body, (vector_t){0.3, 0.0});
    create_spring(scene, k, anchor, body);
    double energy = 0.5 * 0.09 + 0.5 * k;
    for (int i = 0; i < 200; i++) {
        scene_tick(scene, h);
        double x = body_get_centroid(body).x, v = body_get_velocity(body).x;
        double next = 0.5 * v * v + 0.5 * k * x * x;
        CHECK_RELATIVE(next / energy, 1.0 + theta * theta, 1e-12);
        energy = next;
    }
    scene_free(scene);
}

/* The growth per step of an oscillator's energy is at most 1 below each
 * scheme's stability limit and above 1 past it; the schemes without a
 * limit gain at every step. Measured too: 10^4 steps at 0.95 of the limit
 * keep the energy within the factor its tilted invariant ellipse allows
 * (under 100), 1.05 of it multiplies it by more than 10^6. */
static double oscillator_energy_after(integrator_t integrator, double theta, int steps) {
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    body_t *anchor = added_square(scene, VEC_ZERO, 0.05, INFINITY);
    body_t *body = added_square(scene, (vector_t){1.0, 0.0}, 0.05, 1.0);
    create_spring(scene, 1.0, anchor, body);
    double x = 1.0, v = 0.0;
    for (int i = 0; i < steps; i++) {
        scene_tick(scene, theta);
        x = body_get_centroid(body).x;
        v = body_get_velocity(body).x;
        if (x * x + v * v > 1e12) break;
    }
    scene_free(scene);
    return x * x + v * v; /* over the start's */
}

static void stability_limits_hold_in_theory_and_in_runs(void) {
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        double limit = integrator_get_stability_limit(ALL[i]);
        if (limit == 0.0) {
            CHECK(integrator_oscillator_growth(ALL[i], 0.01) > 1.0);
            CHECK(integrator_oscillator_growth(ALL[i], 1.0) > 1.0);
            continue;
        }
        if (isinf(limit)) {
            /* Stable at every step: the energy falls, in theory and in runs. */
            for (double theta = 0.01; theta < 1e4; theta *= 1.5) {
                CHECK(integrator_oscillator_growth(ALL[i], theta) < 1.0);
            }
            CHECK(oscillator_energy_after(ALL[i], 1e3, 10) < 1.0);
            continue;
        }
        for (double theta = 0.01; theta < 0.999 * limit; theta += 0.01) {
            CHECK(integrator_oscillator_growth(ALL[i], theta) <= 1.0 + 1e-12);
        }
        CHECK(integrator_oscillator_growth(ALL[i], 1.001 * limit) > 1.0);
        CHECK(oscillator_energy_after(ALL[i], 0.95 * limit, 10000) < 100.0);
        CHECK(oscillator_energy_after(ALL[i], 1.05 * limit, 10000) > 1e6);
    }
    CHECK_NEAR(integrator_oscillator_growth(INTEGRATOR_EXPLICIT_EULER, 0.5), 1.25, 1e-15);
    CHECK_NEAR(integrator_oscillator_growth(INTEGRATOR_SEED, 0.5), 1.125, 1e-15);
}

/* A 1 kg body under create_drag at z = gamma dt / m for 200 steps: its
 * speed over the start's. */
static double drag_speed_after(integrator_t integrator, double z) {
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    body_t *body = added_square(scene, VEC_ZERO, 0.5, 1.0);
    body_set_velocity(body, (vector_t){1.0, 0.0});
    const double dt = 0.01;
    create_drag(scene, z / dt, body);
    for (int i = 0; i < 200; i++) scene_tick(scene, dt);
    double speed = fabs(body_get_velocity(body).x);
    scene_free(scene);
    return speed;
}

/* Each scheme's largest stable gamma dt / m on drag, against runs on both
 * sides of it; 2.785 and 1.372 are the real roots of |factor| = 1 of RK4's
 * quartic and of symplectic4's three Verlet steps (tests/stability). */
static void drag_limits_hold_in_runs(void) {
    const double expected[INTEGRATOR_COUNT] = {2.0, 2.0, 2.0, 2.0, 2.785293563405282,
                                               1.3719235554837272, INFINITY};
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        double limit = integrator_get_drag_limit(ALL[i]);
        if (isinf(expected[i])) {
            CHECK(isinf(limit));
            CHECK(drag_speed_after(ALL[i], 1e6) < 1e-12);
            continue;
        }
        CHECK_RELATIVE(limit, expected[i], 1e-12);
        CHECK(drag_speed_after(ALL[i], 0.99 * limit) < 1.0);
        CHECK(drag_speed_after(ALL[i], 1.01 * limit) > 1.0);
    }
}

/* Velocity Verlet, RK4 and symplectic4 follow a constant force exactly,
 * impulses acting at the start of the step and forces set between ticks
 * at every stage. */
static void multi_stage_schemes_are_exact_for_constant_forces(void) {
    const integrator_t staged[] = {INTEGRATOR_VELOCITY_VERLET, INTEGRATOR_RK4,
                                   INTEGRATOR_SYMPLECTIC4};
    for (size_t i = 0; i < 3; i++) {
        scene_t *scene = scene_init();
        scene_set_integrator(scene, staged[i]);
        scene_set_gravity(scene, (vector_t){0.0, -2.0});
        body_t *body = added_square(scene, VEC_ZERO, 0.5, 4.0);
        const double dt = 0.1, j = 0.5;
        body_add_impulse(body, (vector_t){4.0 * j, 0.0});
        const int n = 20;
        for (int step = 0; step < n; step++) {
            body_add_force(body, (vector_t){4.0, 0.0}); /* 1 m/s^2 */
            scene_tick(scene, dt);
        }
        double t = n * dt;
        CHECK_VEC(body_get_centroid(body), j * t + 0.5 * t * t, -t * t, 1e-12);
        CHECK_VEC(body_get_velocity(body), j + t, -2.0 * t, 1e-12);
        scene_free(scene);
    }
}

typedef struct {
    scene_t *scene;
    body_t *body;
    int calls[4];
} stage_log_t;

static void log_stage(void *aux) {
    stage_log_t *log = aux;
    int stage = scene_get_stage(log->scene);
    CHECK(stage >= 0 && stage < 4);
    if (stage >= 0 && stage < 4) log->calls[stage]++;
    /* Every call adds an impulse; only the first call's may count. */
    body_add_impulse(log->body, (vector_t){1.0, 0.0});
}

static void force_creators_run_at_every_stage(void) {
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        scene_t *scene = scene_init();
        scene_set_integrator(scene, ALL[i]);
        stage_log_t *log = calloc(1, sizeof *log);
        log->scene = scene;
        log->body = added_square(scene, VEC_ZERO, 0.5, 2.0);
        scene_add_force_creator(scene, log_stage, log, free);
        CHECK(scene_get_stage(scene) == 0);
        scene_tick(scene, 0.01);
        CHECK(scene_get_stage(scene) == 0);
        int stages = integrator_stage_count(ALL[i]);
        for (int s = 0; s < 4; s++) CHECK(log->calls[s] == (s < stages ? 1 : 0));
        CHECK_VEC(body_get_velocity(log->body), 0.5, 0.0, 1e-15);
        scene_free(scene);
    }
}

static void count_hits(body_t *body1, body_t *body2, vector_t axis, void *aux,
                       double force_const) {
    (void)body1, (void)body2, (void)axis, (void)force_const;
    (*(int *)aux)++;
}

/* A collision is an event of the step: its handler runs at stage 0 only,
 * so a multi-stage scheme sees each collision as often as the seed does,
 * and create_physics_collision resolves it once. */
static void collisions_run_at_the_first_stage_only(void) {
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        scene_t *scene = scene_init();
        scene_set_integrator(scene, ALL[i]);
        body_t *left = added_square(scene, (vector_t){-1.0, 0.0}, 0.5, 1.0);
        body_t *right = added_square(scene, (vector_t){1.0, 0.0}, 0.5, 1.0);
        body_set_velocity(left, (vector_t){2.0, 0.0});
        int hits = 0;
        create_collision(scene, left, right, count_hits, &hits, 0.0);
        create_physics_collision(scene, left, right, 1.0);
        for (int step = 0; step < 100; step++) scene_tick(scene, 0.01);
        CHECK(hits == 1);
        CHECK_NEAR(body_get_velocity(left).x, 0.0, 1e-12);
        CHECK_NEAR(body_get_velocity(right).x, 2.0, 1e-12);
        scene_free(scene);
    }
}

typedef struct {
    scene_t *scene;
} spawner_t;

static void spawn_at_every_stage(void *aux) {
    spawner_t *spawner = aux;
    body_t *body = body_init(polygon_make_box(VEC_ZERO, 0.5, 0.5), 1.0, GREY);
    scene_add_body(spawner->scene, body);
}

static void add_body_at_a_later_stage(void *unused) {
    (void)unused;
    scene_t *scene = scene_init();
    scene_set_integrator(scene, INTEGRATOR_RK4);
    spawner_t spawner = {scene};
    scene_add_force_creator(scene, spawn_at_every_stage, &spawner, NULL);
    scene_tick(scene, 0.01);
}

static void adding_a_body_at_a_later_stage_is_refused(void) {
    CHECK_DIES(add_body_at_a_later_stage, NULL, "engine error in scene_add_body:",
               "a force creator added a body at stage 1 of the RK4 integrator",
               "scene_get_stage");
}

/* The names and limits the docs quote. */
static void integrators_have_names_and_limits(void) {
    const char *names[INTEGRATOR_COUNT] = {"seed",        "explicit Euler", "symplectic Euler",
                                           "velocity Verlet", "RK4",        "symplectic4",
                                           "implicit Euler"};
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        CHECK(strcmp(integrator_get_name(ALL[i]), names[i]) == 0);
        scene_t *scene = scene_init();
        scene_set_integrator(scene, ALL[i]);
        CHECK(scene_get_integrator(scene) == ALL[i]);
        scene_free(scene);
    }
    CHECK_NEAR(integrator_get_stability_limit(INTEGRATOR_RK4), 2.0 * sqrt(2.0), 1e-15);
    CHECK(integrator_get_stability_limit(INTEGRATOR_SEED) == 0.0);
    CHECK(isinf(integrator_get_stability_limit(INTEGRATOR_IMPLICIT_EULER)));
}

TEST_SUITE(integrators, TEST_CASE(oscillator_errors_fall_at_each_schemes_order),
           TEST_CASE(kepler_errors_fall_at_each_schemes_order),
           TEST_CASE(symplectic_schemes_keep_the_orbit),
           TEST_CASE(explicit_euler_oscillator_energy_grows_by_the_formula),
           TEST_CASE(stability_limits_hold_in_theory_and_in_runs),
           TEST_CASE(drag_limits_hold_in_runs),
           TEST_CASE(multi_stage_schemes_are_exact_for_constant_forces),
           TEST_CASE(force_creators_run_at_every_stage),
           TEST_CASE(collisions_run_at_the_first_stage_only),
           TEST_CASE(adding_a_body_at_a_later_stage_is_refused),
           TEST_CASE(integrators_have_names_and_limits));
