#include "jostle/scene.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "dynamics/body_private.h"
#include "base/check.h"
#include "dynamics/integrator.h"
#include "base/memory.h"
#include "scene/scene_private.h"
#include "base/stage_clock.h"
#include "base/workers.h"
#include "world/world.h"
#include "solver/joint_list.h"

/* A force creator, as scene_add_creator takes it (scene_private.h). */
typedef scene_creator_t force_entry_t;

struct scene {
    body_t **bodies;
    size_t body_count, body_capacity;
    uint32_t next_body_id;
    /* The most vertices of any body ever added: what a step's scratch room
     * for posed polygons must hold (world_step_t). */
    size_t largest_polygon;
    /* How many segments the chains among the bodies have (world_step_t). */
    size_t chain_parts;

    force_entry_t *forces;
    size_t force_count, force_capacity;
    /* Changes whenever a force creator is added or dropped (integrator.h's
     * reuse key). */
    uint64_t forces_version;

    vector_t gravity;
    integrator_t integrator;
    /* Whether slow islands sleep while world contacts are on. */
    bool sleeping;
    /* The bodies the step in progress moves (choose_step_bodies): bodies,
     * or awake, the bodies not asleep in scene order with their indices in
     * bodies, listed anew only when sleep_changes (the bodies' count of
     * changes to who sleeps, body_private.h) has moved since awake_changes
     * or bodies came or went (awake_stale). */
    body_t **step_bodies;
    size_t step_count;
    body_t **awake;
    size_t *awake_index;
    size_t awake_count, awake_capacity, awake_index_capacity;
    uint64_t sleep_changes, awake_changes;
    bool awake_stale;
    /* Each body's motion over the step in progress (integrator.h), and the
     * multi-stage schemes' storage; reused from step to step. */
    integrator_motion_t *motions;
    size_t motion_capacity;
    integrator_stages_t *stages;
    /* Implicit Euler's: the Jacobians of the step's forces that have one. */
    force_jacobian_t *jacobians;
    size_t jacobian_capacity;
    /* The stage of the step whose force creators are running (0 outside a
     * tick) and how many creators the first one ran. */
    int stage;
    size_t stage_force_count;
    /* The dt of the tick in progress, for the message of one that fails. */
    double dt;
    /* "scene_tick" or "scene_free" while one runs (and calls back), else
     * NULL: what may not be called back into then (scene_require_idle). */
    const char *running;

    /* The world contact pipeline and its functions; NULL while contacts
     * are off. */
    world_t *world;
    const world_ops_t *world_ops;
    size_t velocity_iterations, position_iterations;
    size_t workers;
    /* The solver's other settings (scene.h), handed to the world each step. */
    bool warm_starting;
    double restitution_threshold;
    double sleep_linear, sleep_angular, sleep_time;

    /* Seed collisions are recorded as they happen; world contacts are
     * appended the first time the record is read after a tick. */
    contact_t *record;
    size_t record_count, record_capacity;
    bool record_needs_world;
    scene_stats_t stats;
    /* The stage times of the last tick and the clock that laps them. */
    scene_profile_t profile;
    stage_clock_t clock;
    /* Changes whenever the bodies may have moved, been added or removed
     * (scene_query.c keeps its grid while it stays the same). */
    uint64_t moves;
    void *queries;
    void (*free_queries)(void *queries);
    /* The joints (joint.h), which the scene owns. */
    joint_list_t joints;
};

scene_t *scene_init(void) {
    scene_t *scene = memory_calloc(1, sizeof(scene_t));
    scene->integrator = INTEGRATOR_SEED;
    scene->sleeping = true;
    scene->awake_stale = true;
    scene->workers = 1;
    scene_reset_solver_settings(scene);
    return scene;
}

/* Frees a bodies list without letting its freer touch the bodies, which the
 * scene owns. */
static void free_body_list(list_t *bodies) {
    if (bodies == NULL) return;
    while (list_size(bodies) > 0) list_remove(bodies, list_size(bodies) - 1);
    list_free(bodies);
}

/* By value: its freer may add force creators, which moves the array. */
static void force_entry_free(force_entry_t entry) {
    if (entry.freer != NULL) entry.freer(entry.aux);
    free_body_list(entry.bodies);
}

/* Whether the body is another scene's, owned or named by its force
 * creators: this scene's creators must not read it. */
static bool belongs_elsewhere(const scene_t *scene, const body_t *body) {
    return body->scene != NULL && body->scene != scene;
}

/* Bodies that force creators named but that were never added go back to
 * the caller, free to join another scene now that no creator reads them. */
static void release_unowned_bodies(scene_t *scene) {
    for (size_t i = 0; i < scene->force_count; i++) {
        list_t *bodies = scene->forces[i].bodies;
        for (size_t j = 0; bodies != NULL && j < list_size(bodies); j++) {
            body_t *body = list_get(bodies, j);
            if (!body->in_scene) body->scene = NULL;
        }
    }
}

void scene_require_idle(const scene_t *scene, const char *function, const char *instead) {
    if (scene->running == NULL) return;
    engine_fail(function,
                "called inside %s of the same scene (by a force creator, collision handler or "
                "freer it ran), which is still using the scene; %s",
                scene->running, instead);
}

/* A body the scene owns, freed by the scene (body_free refuses a body that
 * is still a scene's). */
static void free_owned_body(body_t *body) {
    body->scene = NULL;
    body->moves = NULL;
    body->sleep_changes = NULL;
    body->in_scene = false;
    body_free(body);
}

void scene_free(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, "free the scene after scene_tick returns");
    scene->running = "scene_free";
    scene_install_world(scene, NULL, NULL);
    joint_list_free(&scene->joints);
    release_unowned_bodies(scene);
    for (size_t i = 0; i < scene->force_count; i++) force_entry_free(scene->forces[i]);
    for (size_t i = 0; i < scene->body_count; i++) free_owned_body(scene->bodies[i]);
    memory_free(scene->forces);
    memory_free(scene->bodies);
    memory_free(scene->record);
    memory_free(scene->motions);
    memory_free(scene->awake);
    memory_free(scene->awake_index);
    memory_free(scene->jacobians);
    integrator_stages_free(scene->stages);
    if (scene->queries != NULL) scene->free_queries(scene->queries);
    memory_free(scene);
}

size_t scene_bodies(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->body_count;
}

body_t *scene_get_body(scene_t *scene, size_t index) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE(index < scene->body_count, "index %zu out of range (%zu bodies)", index,
            scene->body_count);
    return scene->bodies[index];
}

void scene_add_body(scene_t *scene, body_t *body) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(body);
    REQUIRE(!body->in_scene, "body already belongs to a scene (added twice?)");
    REQUIRE(!belongs_elsewhere(scene, body), "body is used by a force creator of another scene");
    REQUIRE(scene->stage == 0,
            "a force creator added a body at stage %d of the %s integrator; add bodies at "
            "stage 0 (scene_get_stage)",
            scene->stage, integrator_get_name(scene->integrator));
    body->in_scene = true;
    body->scene = scene;
    body->moves = &scene->moves;
    body->sleep_changes = &scene->sleep_changes;
    scene->moves++;
    scene->awake_stale = true;
    memory_reserve((void **)&scene->bodies, &scene->body_capacity, scene->body_count + 1,
                   sizeof(body_t *));
    body->id = scene->next_body_id++;
    scene->bodies[scene->body_count++] = body;
    /* A chain collides through its segments, which the world's pairs tell
     * apart by their own ids. */
    for (size_t k = 0; k < body->part_count; k++) {
        body->parts[k]->id = scene->next_body_id++;
        body_mark_changed(body->parts[k]);
    }
    scene->chain_parts += body->part_count;
    size_t polygon = body->kind == BODY_SHAPE_CHAIN ? 2 : body->count;
    if (polygon > scene->largest_polygon) scene->largest_polygon = polygon;
    body_mark_changed(body); /* sleeping bodies it lands in wake */
}

void scene_remove_body(scene_t *scene, size_t index) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE(index < scene->body_count, "index %zu out of range (%zu bodies)", index,
            scene->body_count);
    body_remove(scene->bodies[index]);
}

void scene_add_creator(scene_t *scene, const scene_creator_t *creator) {
    memory_reserve((void **)&scene->forces, &scene->force_capacity, scene->force_count + 1,
                   sizeof(force_entry_t));
    scene->forces[scene->force_count++] = *creator;
    scene->forces_version++;
}

static void add_force_entry(scene_t *scene, force_creator_t forcer, void *aux, list_t *bodies,
                            free_func_t freer) {
    scene_add_creator(scene, &(scene_creator_t){.forcer = forcer, .aux = aux, .freer = freer,
                                                .bodies = bodies});
}

void scene_add_force_creator(scene_t *scene, force_creator_t forcer, void *aux,
                             free_func_t freer) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(forcer);
    add_force_entry(scene, forcer, aux, NULL, freer);
}

void scene_add_bodies_force_creator(scene_t *scene, force_creator_t forcer, void *aux,
                                    list_t *bodies, free_func_t freer) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(forcer);
    if (bodies != NULL) {
        for (size_t i = 0; i < list_size(bodies); i++) {
            body_t *body = list_get(bodies, i);
            REQUIRE(body != NULL, "bodies[%zu] is NULL", i);
            REQUIRE(!belongs_elsewhere(scene, body), "bodies[%zu] belongs to another scene", i);
        }
        for (size_t i = 0; i < list_size(bodies); i++) {
            ((body_t *)list_get(bodies, i))->scene = scene;
        }
    }
    add_force_entry(scene, forcer, aux, bodies, freer);
}

void scene_require_added(const scene_t *scene, const body_t *body, const char *function,
                         const char *name, size_t index) {
    char label[64];
    if (index == SIZE_MAX) {
        snprintf(label, sizeof label, "%s", name);
    } else {
        snprintf(label, sizeof label, "%s[%zu]", name, index);
    }
    if (body == NULL) engine_fail(function, "%s is NULL", label);
    if (!body->in_scene || body->scene != scene) {
        engine_fail(function, "%s is not in the scene (add it with scene_add_body first)", label);
    }
}

void scene_claim_body(scene_t *scene, body_t *body, const char *name, const char *function) {
    if (belongs_elsewhere(scene, body)) engine_fail(function, "%s belongs to another scene", name);
    body->scene = scene;
}

/* The solver's defaults (scene_reset_solver_settings). Contacts approaching
 * slower than 1 m/s do not bounce: a resting body must not bounce on the
 * speed gravity gives it in one step. Box2D v2's sleep tolerance and time
 * for a body in free motion (0.01 m/s, half a second); no angular
 * tolerance of its own, the turn counting through the rim's speed. */
static const double SCENE_DEFAULT_RESTITUTION_THRESHOLD = 1.0;
static const double SCENE_DEFAULT_SLEEP_LINEAR = 0.01;
static const double SCENE_DEFAULT_SLEEP_TIME = 0.5;

/* What scene_require_idle says for the settings a tick is running with. */
static const char *const SETTING_ADVICE = "change the setting between ticks";

void scene_set_gravity(scene_t *scene, vector_t gravity) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_FINITE_VECTOR(gravity);
    if (gravity.x != scene->gravity.x || gravity.y != scene->gravity.y) {
        /* Gravity pulls every body of finite mass: none may rest as it was. */
        for (size_t i = 0; i < scene->body_count; i++) {
            body_t *body = scene->bodies[i];
            if (body->asleep && body->inverse_mass > 0.0) body_wake(body);
        }
    }
    scene->gravity = gravity;
}

vector_t scene_get_gravity(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->gravity;
}

void scene_set_integrator(scene_t *scene, integrator_t integrator) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, SETTING_ADVICE);
    REQUIRE((unsigned)integrator < INTEGRATOR_COUNT, "unknown integrator %d", (int)integrator);
    scene->integrator = integrator;
}

integrator_t scene_get_integrator(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->integrator;
}

int scene_get_stage(const scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->stage;
}

static void wake_all(scene_t *scene) {
    for (size_t i = 0; i < scene->body_count; i++) {
        if (scene->bodies[i]->asleep) body_wake(scene->bodies[i]);
    }
}

void scene_set_sleeping(scene_t *scene, bool enabled) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, SETTING_ADVICE);
    scene->sleeping = enabled;
    if (!enabled) wake_all(scene);
}

bool scene_get_sleeping(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->sleeping;
}

void scene_install_world(scene_t *scene, world_t *world, const world_ops_t *ops) {
    if (scene->world != NULL) scene->world_ops->free(scene->world);
    if (world == NULL) wake_all(scene);
    scene->world = world;
    scene->world_ops = ops;
}

world_t *scene_world(const scene_t *scene, const world_ops_t **ops) {
    *ops = scene->world_ops;
    return scene->world;
}

body_t **scene_body_array(const scene_t *scene) {
    return scene->bodies;
}

void scene_get_iterations(const scene_t *scene, size_t *velocity_iterations,
                          size_t *position_iterations) {
    *velocity_iterations = scene->velocity_iterations;
    *position_iterations = scene->position_iterations;
}

bool scene_get_contacts_enabled(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->world != NULL;
}

void scene_set_solver_iterations(scene_t *scene, size_t velocity_iterations,
                                 size_t position_iterations) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, SETTING_ADVICE);
    REQUIRE(velocity_iterations >= 1 && velocity_iterations <= 1000,
            "velocity_iterations must be in [1, 1000] (got %zu)", velocity_iterations);
    REQUIRE(position_iterations >= 1 && position_iterations <= 1000,
            "position_iterations must be in [1, 1000] (got %zu)", position_iterations);
    scene->velocity_iterations = velocity_iterations;
    scene->position_iterations = position_iterations;
    if (scene->world != NULL) {
        scene->world_ops->set_iterations(scene->world, velocity_iterations, position_iterations);
    }
}

void scene_get_solver_iterations(const scene_t *scene, size_t *velocity_iterations,
                                 size_t *position_iterations) {
    REQUIRE_NOT_NULL(scene);
    if (velocity_iterations != NULL) *velocity_iterations = scene->velocity_iterations;
    if (position_iterations != NULL) *position_iterations = scene->position_iterations;
}

void scene_set_profiling(scene_t *scene, bool enabled) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, SETTING_ADVICE);
    scene->clock.timing = enabled;
}

bool scene_get_profiling(const scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->clock.timing;
}

void scene_set_warm_starting(scene_t *scene, bool enabled) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, SETTING_ADVICE);
    scene->warm_starting = enabled;
}

bool scene_get_warm_starting(const scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->warm_starting;
}

void scene_set_restitution_threshold(scene_t *scene, double threshold) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, SETTING_ADVICE);
    REQUIRE(threshold >= 0.0 && threshold <= 100.0,
            "threshold must be in [0, 100] m/s (got %g)", threshold);
    scene->restitution_threshold = threshold;
}

double scene_get_restitution_threshold(const scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->restitution_threshold;
}

void scene_set_sleep_tolerance(scene_t *scene, double linear, double angular) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, SETTING_ADVICE);
    REQUIRE(linear > 0.0 && linear <= 10.0, "linear must be in (0, 10] m/s (got %g)", linear);
    REQUIRE(angular == INFINITY || (angular > 0.0 && angular <= 100.0),
            "angular must be in (0, 100] rad/s or INFINITY (got %g)", angular);
    scene->sleep_linear = linear;
    scene->sleep_angular = angular;
}

void scene_get_sleep_tolerance(const scene_t *scene, double *linear, double *angular) {
    REQUIRE_NOT_NULL(scene);
    if (linear != NULL) *linear = scene->sleep_linear;
    if (angular != NULL) *angular = scene->sleep_angular;
}

void scene_set_sleep_time(scene_t *scene, double seconds) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, SETTING_ADVICE);
    REQUIRE(seconds > 0.0 && seconds <= 1000.0, "seconds must be in (0, 1000] (got %g)",
            seconds);
    scene->sleep_time = seconds;
}

double scene_get_sleep_time(const scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->sleep_time;
}

void scene_reset_solver_settings(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, SETTING_ADVICE);
    scene_set_solver_iterations(scene, 8, 4);
    scene->warm_starting = true;
    scene->restitution_threshold = SCENE_DEFAULT_RESTITUTION_THRESHOLD;
    scene->sleep_linear = SCENE_DEFAULT_SLEEP_LINEAR;
    scene->sleep_angular = INFINITY;
    scene->sleep_time = SCENE_DEFAULT_SLEEP_TIME;
}

void scene_set_workers(scene_t *scene, size_t workers) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, SETTING_ADVICE);
    REQUIRE(workers >= 1 && workers <= SCENE_MAX_WORKERS, "workers must be in [1, %d] (got %zu)",
            SCENE_MAX_WORKERS, workers);
    scene->workers = workers;
    if (scene->world != NULL) scene->world_ops->set_workers(scene->world, workers);
}

size_t scene_get_workers(const scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->workers;
}

/* Stage 5, on demand: a scene nobody observes pays nothing for its record. */
static void publish_world_record(scene_t *scene) {
    if (!scene->record_needs_world) return;
    scene->record_needs_world = false;
    if (scene->world == NULL) return;
    size_t count = scene->world_ops->contact_count(scene->world);
    memory_reserve((void **)&scene->record, &scene->record_capacity, scene->record_count + count,
                   sizeof(contact_t));
    for (size_t i = 0; i < count; i++) {
        scene->record[scene->record_count++] = scene->world_ops->get_contact(scene->world, i);
    }
}

size_t scene_contact_count(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    publish_world_record(scene);
    return scene->record_count;
}

const contact_t *scene_get_contact(scene_t *scene, size_t index) {
    REQUIRE_NOT_NULL(scene);
    publish_world_record(scene);
    REQUIRE(index < scene->record_count, "index %zu out of range (%zu contacts)", index,
            scene->record_count);
    return &scene->record[index];
}

scene_stats_t scene_get_stats(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene->stats;
}

void scene_record_contact(scene_t *scene, const contact_t *entry) {
    memory_reserve((void **)&scene->record, &scene->record_capacity, scene->record_count + 1,
                   sizeof(contact_t));
    scene->record[scene->record_count++] = *entry;
}

void scene_count_broadphase_tests(scene_t *scene, size_t tests) {
    scene->stats.broadphase_tests += tests;
}

size_t scene_world_contact_count(const scene_t *scene) {
    return scene->world != NULL ? scene->world_ops->contact_count(scene->world) : 0;
}

contact_t scene_world_get_contact(const scene_t *scene, size_t index) {
    return scene->world_ops->get_contact(scene->world, index);
}

bool scene_world_resolves(const scene_t *scene, const body_t *body1, const body_t *body2) {
    return scene->world != NULL && scene->world_ops->pair_collides(body1, body2);
}

bool scene_world_pair_contact(const scene_t *scene, body_t *body1, body_t *body2,
                              contact_t *contact) {
    return scene->world != NULL &&
           scene->world_ops->pair_contact(scene->world, body1, body2, contact);
}

size_t scene_body_index(const scene_t *scene, const body_t *body) {
    for (size_t i = 0; i < scene->body_count; i++) {
        if (scene->bodies[i] == body) return i;
    }
    return SIZE_MAX;
}

double scene_step_dt(const scene_t *scene) {
    return scene->dt;
}

void *scene_query_state(scene_t *scene, void *(*init)(void), void (*freer)(void *queries)) {
    if (scene->queries == NULL) {
        scene->queries = init();
        scene->free_queries = freer;
    }
    return scene->queries;
}

uint64_t scene_moves(const scene_t *scene) {
    return scene->moves;
}

scene_profile_t scene_stage_times(const scene_t *scene) {
    scene_profile_t profile = scene->profile;
    if (!scene->clock.timing) memset(profile.seconds, 0, sizeof profile.seconds);
    return profile;
}

/* Stage 1 at the start of the step. A force creator may add force creators
 * (they run from the next tick on, since the count is read once) and may
 * remove bodies. */
static void stage_forces(scene_t *scene) {
    size_t count = scene->force_count;
    scene->stage_force_count = count;
    scene->stats.force_evaluations++;
    for (size_t i = 0; i < count; i++) scene->forces[i].forcer(scene->forces[i].aux);
}

/* Stage 1 at a later stage of a multi-stage integrator: the creators of the
 * first call again, but for the collisions, which are events of the step. */
static void stage_forces_again(void *context) {
    scene_t *scene = context;
    scene->stage++;
    scene->moves++; /* the bodies stand at the stage's trial poses */
    scene->stats.force_evaluations++;
    for (size_t i = 0; i < scene->stage_force_count; i++) {
        const force_entry_t *entry = &scene->forces[i];
        if (!entry->event) entry->forcer(entry->aux);
    }
}

/* Whether the loops over bodies run on the world's workers. */
static bool splits_bodies(const scene_t *scene) {
    return scene->world != NULL && scene->workers > 1;
}

/* Whether the step leaves the sleeping bodies out of its loops: with world
 * contacts and sleeping on, under a scheme that moves each body by itself
 * (integrator_is_per_body; the others work on all the bodies at once), so
 * that a sleeping body costs nothing per step. */
static bool steps_awake_only(const scene_t *scene) {
    return scene->world != NULL && scene->sleeping && integrator_is_per_body(scene->integrator);
}

/* Lists the bodies not asleep, in scene order. */
static void list_awake(scene_t *scene) {
    memory_reserve((void **)&scene->awake, &scene->awake_capacity, scene->body_count,
                   sizeof(body_t *));
    memory_reserve((void **)&scene->awake_index, &scene->awake_index_capacity, scene->body_count,
                   sizeof(size_t));
    size_t count = 0;
    for (size_t i = 0; i < scene->body_count; i++) {
        if (scene->bodies[i]->asleep) continue;
        scene->awake[count] = scene->bodies[i];
        scene->awake_index[count++] = i;
    }
    scene->awake_count = count;
    scene->awake_changes = scene->sleep_changes;
    scene->awake_stale = false;
}

/* Sets the bodies the step moves (step_bodies): every body, or the awake
 * ones (steps_awake_only), listed anew when who sleeps has changed. */
static void choose_step_bodies(scene_t *scene) {
    if (!steps_awake_only(scene)) {
        scene->step_bodies = scene->bodies;
        scene->step_count = scene->body_count;
        return;
    }
    if (scene->awake_stale || scene->awake_changes != scene->sleep_changes) list_awake(scene);
    scene->step_bodies = scene->awake;
    scene->step_count = scene->awake_count;
}

/* The scene's index of the step's body k. */
static size_t scene_index_of(const scene_t *scene, size_t k) {
    return scene->step_bodies == scene->bodies ? k : scene->awake_index[k];
}

/* The one-stage schemes' free motions over the world's workers: no force
 * creator runs in them, and each body's motion is its own. */
typedef struct {
    const integrator_step_t *step;
    scene_t *scene;
} predict_split_t;

static void predict_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const predict_split_t *split = context;
    (void)chunk;
    integrator_predict_range(split->step, split->scene->step_bodies, split->scene->motions, begin,
                             end);
}

/* The integrator's reuse key (integrator.h): the forces version while
 * every creator's force depends on centroids and masses alone and world
 * contacts are off (their sleeping reads the creators' pushes); else 0. */
static uint64_t reuse_key(const scene_t *scene) {
    if (scene->world != NULL || scene->force_count == 0) return 0;
    for (size_t i = 0; i < scene->force_count; i++) {
        if (!scene->forces[i].positional) return 0;
    }
    return scene->forces_version;
}

/* Implicit Euler's input: the Jacobians of the creators that ran at the
 * start of the step, where they have one. */
static void gather_jacobians(scene_t *scene, integrator_step_t *step) {
    size_t count = 0;
    for (size_t i = 0; i < scene->stage_force_count; i++) {
        const force_entry_t *entry = &scene->forces[i];
        force_jacobian_t jacobian;
        if (entry->jacobian == NULL || !entry->jacobian(entry->aux, &jacobian)) continue;
        memory_reserve((void **)&scene->jacobians, &scene->jacobian_capacity, count + 1,
                       sizeof(force_jacobian_t));
        scene->jacobians[count++] = jacobian;
    }
    step->jacobians = scene->jacobians;
    step->jacobian_count = count;
}

/* Stage 1: the forces, and from them each body's free motion when
 * something needs it before the bodies move: the world's contacts change
 * it, a multi-stage scheme evaluates the forces again, implicit Euler
 * solves for it over the bodies. Otherwise the integrate stage works it
 * out as it moves each body; NULL is returned. */
static const integrator_motion_t *stage_motion(scene_t *scene, integrator_step_t *step) {
    bool one_stage = integrator_stage_count(scene->integrator) == 1, reused = false;
    bool per_body = integrator_is_per_body(scene->integrator);
    if (!one_stage) {
        step->reuse_key = reuse_key(scene);
        reused = integrator_begin(scene->integrator, scene->bodies, scene->body_count,
                                  &scene->stages, step->reuse_key);
    }
    if (reused) {
        scene->stage_force_count = scene->force_count;
    } else if (scene->force_count > 0) {
        stage_forces(scene);
    }
    if (!one_stage || scene->force_count > 0) stage_clock_lap(&scene->clock, SCENE_STAGE_FORCES);
    choose_step_bodies(scene);
    if (scene->world != NULL && scene->sleeping) {
        scene->world_ops->wake_changed(scene->world, scene->step_bodies, scene->step_count,
                                       step->dt, scene->gravity);
        choose_step_bodies(scene); /* with what woke */
        stage_clock_lap(&scene->clock, SCENE_STAGE_SLEEP);
    }
    if (per_body && scene->world == NULL) return NULL;
    memory_reserve((void **)&scene->motions, &scene->motion_capacity, scene->body_count,
                   sizeof(integrator_motion_t));
    step->evaluate = scene->stage_force_count > 0 ? stage_forces_again : NULL;
    if (scene->integrator == INTEGRATOR_IMPLICIT_EULER) gather_jacobians(scene, step);
    if (splits_bodies(scene) && per_body) {
        predict_split_t split = {step, scene};
        scene->world_ops->for_bodies(scene->world, scene->step_count, predict_chunk, &split);
    } else {
        integrator_predict(step, scene->step_bodies, scene->step_count, scene->motions,
                           &scene->stages);
    }
    scene->stage = 0;
    stage_clock_lap(&scene->clock, SCENE_STAGE_FORCES);
    return scene->motions;
}

/* A body whose pose or velocity no longer fits a double stops the tick:
 * every later stage would spread its NaN. The springs are the usual cause
 * (they bound the stable dt), so the stiffest is named. */
#if defined(__GNUC__)
__attribute__((noreturn, cold))
#endif
static void fail_integrate(const scene_t *scene, size_t index, vector_t start) {
    char what[512], springs[768] = "";
    /* The accumulators still hold the step's forces and impulses. */
    body_motion_t before = body_motion(scene->bodies[index]);
    before.centroid = start;
    body_explain_non_finite(scene->bodies[index], &before, scene->dt, what, sizeof what);
    double stiffest = 0.0;
    size_t spring = SIZE_MAX;
    for (size_t i = 0; i < scene->force_count; i++) {
        const force_entry_t *entry = &scene->forces[i];
        double omega = entry->stiffness != NULL ? entry->stiffness(entry->aux) : 0.0;
        if (omega > stiffest) {
            stiffest = omega;
            spring = i;
        }
    }
    if (spring != SIZE_MAX) {
        char explanation[700];
        scene->forces[spring].explain(scene->forces[spring].aux, explanation, sizeof explanation);
        snprintf(springs, sizeof springs, "; the scene's stiffest %s", explanation);
    }
    engine_fail("scene_tick", "integrate stage: body %zu (centroid (%g, %g) before the step): %s%s",
                index, start.x, start.y, what, springs);
}

/* The integrate stage over the world's workers (motions are then the
 * world's): each body is its own, and the chunks' outcomes are joined in
 * chunk order, so the body a failure names is the one a single thread
 * stops at. */
typedef struct {
    const integrator_step_t *step;
    scene_t *scene;
    const integrator_motion_t *motions;
    integrator_outcome_t found[WORKERS_MAX_CHUNKS];
    size_t end[WORKERS_MAX_CHUNKS]; /* SIZE_MAX for a chunk the call did not make */
} integrate_split_t;

static void integrate_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    integrate_split_t *split = context;
    split->found[chunk] = integrator_move(split->step, split->scene->step_bodies + begin,
                                          end - begin, split->motions + begin);
    split->found[chunk].failed += begin; /* end when the chunk did not fail */
    split->end[chunk] = end;
}

static integrator_outcome_t integrate_split(scene_t *scene, const integrator_step_t *step,
                                            const integrator_motion_t *motions) {
    integrate_split_t split = {step, scene, motions, {{0}}, {0}};
    for (size_t k = 0; k < WORKERS_MAX_CHUNKS; k++) split.end[k] = SIZE_MAX;
    scene->world_ops->for_bodies(scene->world, scene->step_count, integrate_chunk, &split);
    integrator_outcome_t outcome = {scene->step_count, VEC_ZERO, false};
    for (size_t k = 0; k < WORKERS_MAX_CHUNKS && split.end[k] != SIZE_MAX; k++) {
        outcome.removed |= split.found[k].removed;
        if (outcome.failed == scene->step_count && split.found[k].failed < split.end[k]) {
            outcome.failed = split.found[k].failed;
            outcome.failed_start = split.found[k].failed_start;
        }
    }
    return outcome;
}

/* Stage 3. Returns whether any body is marked removed (those are not
 * advanced: they are freed next). */
static bool stage_integrate(scene_t *scene, const integrator_step_t *step,
                            const integrator_motion_t *motions) {
    integrator_outcome_t outcome = splits_bodies(scene) && motions != NULL
                                       ? integrate_split(scene, step, motions)
                                       : integrator_move(step, scene->step_bodies,
                                                         scene->step_count, motions);
    if (outcome.failed < scene->step_count) {
        fail_integrate(scene, scene_index_of(scene, outcome.failed), outcome.failed_start);
    }
    return outcome.removed;
}

static bool depends_on_removed_body(const force_entry_t *entry) {
    if (entry->bodies == NULL) return false;
    for (size_t j = 0; j < list_size(entry->bodies); j++) {
        if (body_is_removed(list_get(entry->bodies, j))) return true;
    }
    return false;
}

/* Drops record entries that name a removed body, which is about to be freed. */
static void forget_removed_in_record(scene_t *scene) {
    size_t kept = 0;
    for (size_t i = 0; i < scene->record_count; i++) {
        const contact_t *entry = &scene->record[i];
        if (entry->body1->removed || entry->body2->removed) continue;
        scene->record[kept++] = *entry;
    }
    scene->record_count = kept;
}

/* Stage 4: force creators first, since their aux may still point at the
 * bodies; then the bodies, keeping the order of the rest. */
static void stage_reap(scene_t *scene) {
    size_t kept = 0;
    for (size_t i = 0; i < scene->force_count; i++) {
        /* A copy: a freer may add force creators (they are kept too). */
        force_entry_t entry = scene->forces[i];
        if (entry.forget != NULL) entry.forget(entry.aux);
        if (depends_on_removed_body(&entry)) {
            force_entry_free(entry);
            scene->forces_version++;
        } else {
            scene->forces[kept++] = entry;
        }
    }
    scene->force_count = kept;

    forget_removed_in_record(scene);
    joint_list_reap(&scene->joints);
    kept = 0;
    for (size_t i = 0; i < scene->body_count; i++) {
        body_t *body = scene->bodies[i];
        if (body->removed) {
            scene->chain_parts -= body->part_count;
            free_owned_body(body);
            scene->stats.removed_bodies++;
        } else {
            scene->bodies[kept++] = body;
        }
    }
    scene->body_count = kept;
    scene->awake_stale = true;
    if (scene->stats.removed_bodies > 0) stage_clock_lap(&scene->clock, SCENE_STAGE_REMOVAL);
}

static void tick(scene_t *scene, double dt) {
    scene->record_count = 0;
    scene->record_needs_world = false;
    scene->stats = (scene_stats_t){0};
    scene->dt = dt;
    /* The seconds are read only while timing (scene_stage_times). */
    memset(scene->profile.ran, 0, sizeof scene->profile.ran);
    if (scene->clock.timing) memset(scene->profile.seconds, 0, sizeof scene->profile.seconds);
    scene->clock.profile = &scene->profile;
    stage_clock_start(&scene->clock);
    scene->moves++;
    if (dt == 0.0) {
        /* No time passes, so nothing may move or collide; the caller only
         * wants the pending removals applied (a paused game). The world
         * keeps its last contacts and its sleepers for the next step, but
         * forgets the bodies about to be freed. */
        if (scene->world != NULL) scene->world_ops->forget_removed(scene->world);
        stage_reap(scene);
        return;
    }
    scene->stage_force_count = 0;
    integrator_step_t step = {scene->integrator, dt, scene->gravity, NULL, scene, NULL, 0, 0};
    const integrator_motion_t *motions = stage_motion(scene, &step);
    if (scene->world != NULL && scene->body_count > 0) {
        world_step_t world_step = {dt,
                                   integrator_position_weight(scene->integrator),
                                   scene->sleeping,
                                   scene->largest_polygon,
                                   scene->warm_starting,
                                   scene->restitution_threshold,
                                   scene->sleep_linear,
                                   scene->sleep_angular,
                                   scene->sleep_time,
                                   &scene->clock,
                                   scene->chain_parts,
                                   {scene->joints.joints, scene->joints.count, NULL},
                                   scene->step_bodies != scene->bodies ? scene->bodies : NULL,
                                   scene->body_count,
                                   &scene->sleep_changes};
        scene->world_ops->step(scene->world, scene->step_bodies, scene->motions,
                               scene->step_count, &world_step, &scene->stats);
        scene->record_needs_world = true;
        integrator_respond(&step, scene->bodies, scene->motions, scene->stages);
    }
    bool removed = stage_integrate(scene, &step, motions);
    stage_clock_lap(&scene->clock, SCENE_STAGE_INTEGRATE);
    if (removed) stage_reap(scene);
}

void scene_tick(scene_t *scene, double dt) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, "tick the scene again after scene_tick returns");
    REQUIRE(isfinite(dt) && dt >= 0.0, "dt must be finite and >= 0 (got %g)", dt);
    scene->running = __func__;
    tick(scene, dt);
    scene->running = NULL;
    scene->moves++;
}

joint_list_t *scene_joint_list(scene_t *scene) {
    return &scene->joints;
}
