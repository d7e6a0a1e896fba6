/* Calls back into a scene from inside its own tick (a force creator, a
 * collision handler or a freer that the tick runs): those that would pull
 * the scene out from under the tick stop with a message saying what to do
 * instead; the others act as docs/api.md says. */
#include <stdlib.h>
#include "jostle/jostle.h"
#include "test.h"

static const rgb_color_t GREY = {0.5, 0.5, 0.5};

static body_t *box_at(vector_t center, double mass) {
    return body_init(polygon_make_box(center, 0.5, 0.5), mass, GREY);
}

static body_t *added(scene_t *scene, body_t *body) {
    scene_add_body(scene, body);
    return body;
}

/* What a callback does to its scene. */
typedef enum {
    DO_TICK,
    DO_FREE_SCENE,
    DO_FREE_BODY,
    DO_CONTACTS_ON,
    DO_INTEGRATOR,
    DO_SLEEPING,
    DO_ITERATIONS,
    DO_WORKERS,
} action_t;

typedef struct {
    scene_t *scene;
    action_t action;
    body_t *body; /* for DO_FREE_BODY */
} reentry_t;

static void act(reentry_t *r) {
    switch (r->action) {
    case DO_TICK: scene_tick(r->scene, 0.01); break;
    case DO_FREE_SCENE: scene_free(r->scene); break;
    case DO_FREE_BODY: body_free(r->body); break;
    case DO_CONTACTS_ON: scene_set_contacts_enabled(r->scene, true); break;
    case DO_INTEGRATOR: scene_set_integrator(r->scene, INTEGRATOR_RK4); break;
    case DO_SLEEPING: scene_set_sleeping(r->scene, false); break;
    case DO_ITERATIONS: scene_set_solver_iterations(r->scene, 4, 2); break;
    case DO_WORKERS: scene_set_workers(r->scene, 2); break;
    }
}

static void acting_force(void *aux) {
    act(aux);
}

static void acting_handler(body_t *body1, body_t *body2, vector_t axis, void *aux,
                           double force_const) {
    (void)body1, (void)body2, (void)axis, (void)force_const;
    act(aux);
}

/* Two overlapping boxes, world contacts off: a collision of the pair fires
 * at the first tick. */
static scene_t *overlapping_pair(body_t **a, body_t **b) {
    scene_t *scene = scene_init();
    *a = added(scene, box_at(VEC_ZERO, 1.0));
    *b = added(scene, box_at((vector_t){0.5, 0}, 1.0));
    return scene;
}

static void from_force_creator(void *data) {
    static reentry_t r;
    body_t *a, *b;
    r = (reentry_t){overlapping_pair(&a, &b), *(const action_t *)data, a};
    scene_add_force_creator(r.scene, acting_force, &r, NULL);
    scene_tick(r.scene, 0.01);
}

static void from_handler(void *data) {
    static reentry_t r;
    body_t *a, *b;
    r = (reentry_t){overlapping_pair(&a, &b), *(const action_t *)data, a};
    create_collision(r.scene, a, b, acting_handler, &r, 0.0);
    scene_tick(r.scene, 0.01);
}

/* The freer of a force creator dropped in the reap of a tick. */
static reentry_t freer_reentry;
static void acting_freer(void *aux) {
    (void)aux;
    act(&freer_reentry);
}

static void no_force(void *aux) {
    (void)aux;
}

static void from_freer(void *data) {
    body_t *a, *b;
    freer_reentry = (reentry_t){overlapping_pair(&a, &b), *(const action_t *)data, b};
    list_t *bodies = list_init(1, NULL);
    list_add(bodies, a);
    scene_add_bodies_force_creator(freer_reentry.scene, no_force, NULL, bodies, acting_freer);
    body_remove(a);
    scene_tick(freer_reentry.scene, 0.0);
}

static void free_body_in_scene(void *unused) {
    (void)unused;
    scene_t *scene = scene_init();
    body_t *body = added(scene, box_at(VEC_ZERO, 1.0));
    body_free(body);
}

static void free_body_named_by_a_force_creator(void *unused) {
    (void)unused;
    scene_t *scene = scene_init();
    body_t *a = added(scene, box_at(VEC_ZERO, 1.0));
    body_t *pending = box_at((vector_t){3, 0}, 1.0); /* named, not yet added */
    create_spring(scene, 1.0, a, pending);
    body_free(pending);
}

static void refused_calls_stop_with_a_message(void) {
    const action_t tick = DO_TICK, free_scene = DO_FREE_SCENE, free_body = DO_FREE_BODY;
    CHECK_DIES(from_force_creator, (void *)&tick, "engine error in scene_tick:",
               "inside scene_tick of the same scene", "after scene_tick returns");
    CHECK_DIES(from_handler, (void *)&tick, "engine error in scene_tick:",
               "inside scene_tick of the same scene", "after scene_tick returns");
    CHECK_DIES(from_handler, (void *)&free_scene, "engine error in scene_free:",
               "inside scene_tick of the same scene", "free the scene after scene_tick returns");
    CHECK_DIES(from_force_creator, (void *)&free_scene, "engine error in scene_free:",
               "inside scene_tick of the same scene");
    CHECK_DIES(from_freer, (void *)&free_scene, "engine error in scene_free:",
               "inside scene_tick of the same scene");
    CHECK_DIES(from_freer, (void *)&tick, "engine error in scene_tick:",
               "inside scene_tick of the same scene");
    /* A body of the scene, in a tick or between ticks. */
    CHECK_DIES(from_handler, (void *)&free_body, "engine error in body_free:",
               "belongs to a scene", "body_remove");
    CHECK_DIES(from_force_creator, (void *)&free_body, "engine error in body_free:",
               "belongs to a scene", "body_remove");
    CHECK_DIES(free_body_in_scene, NULL, "engine error in body_free:", "belongs to a scene",
               "body_remove");
    CHECK_DIES(free_body_named_by_a_force_creator, NULL, "engine error in body_free:",
               "named by a force creator", "after scene_free");
    /* The settings the step is running with. */
    const action_t settings[] = {DO_CONTACTS_ON, DO_INTEGRATOR, DO_SLEEPING, DO_ITERATIONS,
                                 DO_WORKERS};
    const char *const names[] = {
        "engine error in scene_set_contacts_enabled:", "engine error in scene_set_integrator:",
        "engine error in scene_set_sleeping:", "engine error in scene_set_solver_iterations:",
        "engine error in scene_set_workers:"};
    for (size_t i = 0; i < sizeof settings / sizeof settings[0]; i++) {
        CHECK_DIES(from_handler, (void *)&settings[i], names[i],
                   "inside scene_tick of the same scene", "between ticks");
        CHECK_DIES(from_force_creator, (void *)&settings[i], names[i],
                   "inside scene_tick of the same scene", "between ticks");
    }
}

/* A freer that registers another force creator (as a game might, to
 * replace what it lost), counting its calls. */
typedef struct {
    scene_t *scene;
    int calls;
} replacer_t;

static void count_force(void *aux) {
    ((replacer_t *)aux)->calls++;
}

static void replacing_freer(void *aux) {
    replacer_t *r = aux;
    /* Enough creators to move the scene's array of them. */
    for (int i = 0; i < 40; i++) scene_add_force_creator(r->scene, count_force, r, NULL);
}

/* A force creator that turns gravity on at its first call. */
typedef struct {
    scene_t *scene;
    int calls;
} gravity_switch_t;

static void switch_gravity(void *aux) {
    gravity_switch_t *s = aux;
    if (s->calls++ == 0) scene_set_gravity(s->scene, (vector_t){0, -10});
}

/* A handler that adds a body and ticks another scene. */
typedef struct {
    scene_t *scene, *other;
    body_t *spawned;
} spawner_t;

static void spawn_handler(body_t *body1, body_t *body2, vector_t axis, void *aux,
                          double force_const) {
    (void)body1, (void)body2, (void)axis, (void)force_const;
    spawner_t *s = aux;
    s->spawned = added(s->scene, box_at((vector_t){10, 0}, 1.0));
    body_set_velocity(s->spawned, (vector_t){1, 0});
    scene_tick(s->other, 0.5);
}

static void allowed_calls_act_as_documented(void) {
    /* Gravity set inside a tick acts from the next step: the step in
     * progress keeps the gravity it started with. */
    scene_t *scene = scene_init();
    body_t *ball = added(scene, box_at(VEC_ZERO, 1.0));
    gravity_switch_t s = {scene, 0};
    scene_add_force_creator(scene, switch_gravity, &s, NULL);
    scene_tick(scene, 0.1);
    CHECK_VEC(body_get_velocity(ball), 0, 0, 0);
    CHECK_VEC(scene_get_gravity(scene), 0, -10, 0);
    scene_tick(scene, 0.1);
    CHECK_VEC(body_get_velocity(ball), 0, -1, 1e-15);
    scene_free(scene);

    /* A handler adds a body (it moves in this same step, as bodies added by
     * force creators at stage 0 do) and ticks another scene. */
    body_t *a, *b;
    spawner_t spawner = {overlapping_pair(&a, &b), scene_init(), NULL};
    body_t *other_body = added(spawner.other, box_at(VEC_ZERO, 1.0));
    body_set_velocity(other_body, (vector_t){0, 2});
    create_collision(spawner.scene, a, b, spawn_handler, &spawner, 0.0);
    scene_tick(spawner.scene, 0.1);
    CHECK(scene_bodies(spawner.scene) == 3);
    CHECK(spawner.spawned == scene_get_body(spawner.scene, 2));
    CHECK_VEC(body_get_centroid(spawner.spawned), 10.1, 0, 1e-12);
    CHECK_VEC(body_get_centroid(other_body), 0, 1, 1e-12);
    scene_free(spawner.scene);
    scene_free(spawner.other);

    /* A freer run by the reap, or by scene_free, may register force
     * creators: they run from the next tick (and are freed with the
     * scene). */
    scene = scene_init();
    body_t *doomed = added(scene, box_at(VEC_ZERO, 1.0));
    replacer_t replacer = {scene, 0};
    list_t *bodies = list_init(1, NULL);
    list_add(bodies, doomed);
    scene_add_bodies_force_creator(scene, count_force, &replacer, bodies, replacing_freer);
    body_remove(doomed);
    scene_tick(scene, 0.1);
    CHECK(replacer.calls == 1);
    scene_tick(scene, 0.1);
    CHECK(replacer.calls == 41);
    scene_t *freed = scene_init();
    replacer_t at_free = {freed, 0};
    scene_add_force_creator(freed, count_force, &at_free, replacing_freer);
    scene_free(freed);
    scene_free(scene);

    /* A body named by a force creator and never added is the caller's
     * again once that scene is freed. */
    scene = scene_init();
    body_t *anchor = added(scene, box_at(VEC_ZERO, 1.0));
    body_t *pending = box_at((vector_t){3, 0}, 1.0);
    create_spring(scene, 1.0, anchor, pending);
    scene_free(scene);
    body_free(pending);
    CHECK(test_no_leaks());
}

TEST_SUITE(reentry, TEST_CASE(refused_calls_stop_with_a_message),
           TEST_CASE(allowed_calls_act_as_documented));
