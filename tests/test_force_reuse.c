/* First same as last (integrator_begin): velocity Verlet and symplectic4
 * reuse the forces of a step's last evaluation as the next step's first
 * when every force creator is a spring or Newtonian gravity and nothing
 * moved or changed in between; the result is the same to the bit as
 * evaluating again. */
#include <string.h>
#include "jostle/jostle.h"
#include "test.h"

static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};

static body_t *added_square(scene_t *scene, vector_t center, double mass) {
    body_t *body = body_init(polygon_make_box(center, 0.05, 0.05), mass, GREY);
    scene_add_body(scene, body);
    return body;
}

/* A force creator that adds nothing: a creator the engine does not know,
 * so no step may reuse forces. */
static void no_force(void *aux) {
    (void)aux;
}

/* An anchored spring with a rest length, a second body pulled by gravity
 * towards the first: every built-in positional force. */
static scene_t *positional_scene(integrator_t integrator, bool blocked) {
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    scene_set_gravity(scene, (vector_t){0.0, -1.0});
    body_t *anchor = added_square(scene, VEC_ZERO, INFINITY);
    body_t *bob = added_square(scene, (vector_t){1.0, 0.3}, 1.0);
    body_t *moon = added_square(scene, (vector_t){3.0, 0.0}, 0.01);
    body_set_velocity(moon, (vector_t){0.0, 0.5});
    create_spring_with_length(scene, 40.0, 0.5, anchor, bob);
    create_spring(scene, 3.0, bob, moon);
    create_newtonian_gravity(scene, 1.0, bob, moon);
    if (blocked) scene_add_force_creator(scene, no_force, NULL, NULL);
    return scene;
}

static bool same_state(scene_t *a, scene_t *b) {
    for (size_t i = 0; i < scene_bodies(a); i++) {
        body_t *x = scene_get_body(a, i), *y = scene_get_body(b, i);
        vector_t p = body_get_centroid(x), q = body_get_centroid(y);
        vector_t u = body_get_velocity(x), v = body_get_velocity(y);
        if (memcmp(&p, &q, sizeof p) != 0 || memcmp(&u, &v, sizeof u) != 0) return false;
    }
    return true;
}

/* Ticks both scenes; returns the evaluations of the first over the steps
 * after its first, and checks the second evaluated every stage. */
static size_t tick_both(scene_t *reusing, scene_t *fresh, int steps, size_t stages) {
    size_t evaluations = 0;
    for (int i = 0; i < steps; i++) {
        scene_tick(reusing, 1e-2);
        scene_tick(fresh, 1e-2);
        if (i > 0) evaluations += scene_get_stats(reusing).force_evaluations;
        CHECK(scene_get_stats(fresh).force_evaluations == stages);
    }
    return evaluations;
}

static void verlet_and_symplectic4_evaluate_once_fewer_per_step(void) {
    const integrator_t schemes[3] = {INTEGRATOR_VELOCITY_VERLET, INTEGRATOR_SYMPLECTIC4,
                                     INTEGRATOR_RK4};
    const size_t stages[3] = {2, 4, 4}, reusing[3] = {1, 3, 4};
    for (int s = 0; s < 3; s++) {
        scene_t *a = positional_scene(schemes[s], false), *b = positional_scene(schemes[s], true);
        size_t evaluations = tick_both(a, b, 1001, stages[s]);
        /* A step whose start lands off the last evaluation's pose by a
         * rounding (q0 + (q - q0) != q) evaluates afresh: a few at most. */
        CHECK(evaluations >= 1000 * reusing[s] && evaluations <= 1000 * reusing[s] + 20);
        CHECK(same_state(a, b));
        scene_free(a);
        scene_free(b);
    }
}

/* Anything that changes the forces at the start of the step makes the
 * step evaluate them (a new velocity does not: no reused force reads it);
 * the result stays that of a scene that never reuses. A removed body
 * still counts in the tick that reaps it, then its creators are gone. */
static void a_change_between_ticks_evaluates_afresh(void) {
    /* In the tick after the change, and in the one after that (a force set
     * once is gone again: the forces change back). */
    const size_t evaluations[5] = {2, 1, 2, 2, 1}, then[5] = {1, 1, 2, 1, 2};
    for (int change = 0; change < 5; change++) {
        scene_t *a = positional_scene(INTEGRATOR_VELOCITY_VERLET, false);
        scene_t *b = positional_scene(INTEGRATOR_VELOCITY_VERLET, true);
        tick_both(a, b, 10, 2);
        for (int k = 0; k < 2; k++) {
            scene_t *scene = k == 0 ? a : b;
            body_t *bob = scene_get_body(scene, 1), *moon = scene_get_body(scene, 2);
            switch (change) {
            case 0:
                body_set_centroid(bob, vec_add(body_get_centroid(bob), (vector_t){1e-9, 0}));
                break;
            case 1: body_set_velocity(moon, (vector_t){0.1, 0.0}); break;
            case 2: body_add_force(bob, (vector_t){0.5, 0.0}); break;
            case 3: create_spring(scene, 1.0, scene_get_body(scene, 0), moon); break;
            case 4: body_remove(moon); break;
            }
        }
        scene_tick(a, 1e-2);
        scene_tick(b, 1e-2);
        CHECK(scene_get_stats(a).force_evaluations == evaluations[change]);
        CHECK(same_state(a, b));
        scene_tick(a, 1e-2);
        scene_tick(b, 1e-2);
        CHECK(scene_get_stats(a).force_evaluations == then[change]);
        tick_both(a, b, 10, 2);
        CHECK(same_state(a, b));
        scene_free(a);
        scene_free(b);
    }
}

/* Drag reads velocities, a creator of the caller's may read anything, and
 * world contacts change the motion: no reuse with any of them. */
static void velocity_forces_and_contacts_evaluate_every_stage(void) {
    for (int variant = 0; variant < 2; variant++) {
        scene_t *scene = positional_scene(INTEGRATOR_SYMPLECTIC4, false);
        if (variant == 0) create_drag(scene, 0.1, scene_get_body(scene, 1));
        if (variant == 1) scene_set_contacts_enabled(scene, true);
        for (int i = 0; i < 20; i++) {
            scene_tick(scene, 1e-2);
            CHECK(scene_get_stats(scene).force_evaluations == 4);
        }
        scene_free(scene);
    }
}

TEST_SUITE(force_reuse, TEST_CASE(verlet_and_symplectic4_evaluate_once_fewer_per_step),
           TEST_CASE(a_change_between_ticks_evaluates_afresh),
           TEST_CASE(velocity_forces_and_contacts_evaluate_every_stage));
