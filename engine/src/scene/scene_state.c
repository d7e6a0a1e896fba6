#include "jostle/scene_state.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "dynamics/body_private.h"
#include "base/check.h"
#include "base/memory.h"
#include "scene/scene_private.h"
#include "solver/joint_types.h"

body_sleep_timer_t body_get_sleep_timer(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return (body_sleep_timer_t){body->sleep_time, body->sleep_window, body->sleep_anchor,
                                body->sleep_anchor_angle};
}

void body_set_sleep_timer(body_t *body, body_sleep_timer_t timer) {
    REQUIRE_NOT_NULL(body);
    REQUIRE(isfinite(timer.slow_time) && timer.slow_time >= 0.0,
            "slow_time must be finite and >= 0 (got %g)", timer.slow_time);
    REQUIRE(isfinite(timer.window) && timer.window >= 0.0,
            "window must be finite and >= 0 (got %g)", timer.window);
    REQUIRE_FINITE_VECTOR(timer.anchor);
    REQUIRE_FINITE(timer.anchor_angle);
    body->sleep_time = timer.slow_time;
    body->sleep_window = timer.window;
    body->sleep_anchor = timer.anchor;
    body->sleep_anchor_angle = timer.anchor_angle;
}

joint_state_t joint_get_state(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    return (joint_state_t){joint->point_impulse,  joint->angle_impulse, joint->axial_impulse,
                           joint->spring_impulse, joint->motor_impulse, joint->lower_impulse,
                           joint->upper_impulse,  joint->impulse_dt};
}

void joint_set_state(joint_t *joint, joint_state_t state) {
    REQUIRE_NOT_NULL(joint);
    REQUIRE_FINITE_VECTOR(state.point_impulse);
    REQUIRE_FINITE(state.angle_impulse);
    REQUIRE_FINITE(state.axial_impulse);
    REQUIRE_FINITE(state.spring_impulse);
    REQUIRE_FINITE(state.motor_impulse);
    REQUIRE_FINITE(state.lower_impulse);
    REQUIRE_FINITE(state.upper_impulse);
    REQUIRE(isfinite(state.step_length) && state.step_length >= 0.0,
            "step_length must be finite and >= 0 (got %g)", state.step_length);
    joint->point_impulse = state.point_impulse;
    joint->angle_impulse = state.angle_impulse;
    joint->axial_impulse = state.axial_impulse;
    joint->spring_impulse = state.spring_impulse;
    joint->motor_impulse = state.motor_impulse;
    joint->lower_impulse = state.lower_impulse;
    joint->upper_impulse = state.upper_impulse;
    joint->impulse_dt = state.step_length;
}

body_t *body_get_island_next(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->asleep ? body->sleep_next : NULL;
}

/* The scene's world, refused (naming `function`) while contacts are off. */
static world_t *world_of(const scene_t *scene, const world_ops_t **ops, const char *function) {
    world_t *world = scene_world(scene, ops);
    if (world == NULL) {
        engine_fail(function, "world contacts are off (scene_set_contacts_enabled): they hold "
                              "what is asked");
    }
    return world;
}

/* Stops the program (naming `function` and the body as `what`) unless the
 * body is this scene's and not marked removed. */
static void require_live(const scene_t *scene, const body_t *body, const char *what,
                         const char *function) {
    if (body == NULL) engine_fail(function, "%s is NULL", what);
    if (!body->in_scene || body->scene != scene) {
        engine_fail(function, "%s is not a body of this scene", what);
    }
    if (body->removed) engine_fail(function, "%s is marked removed", what);
}

/* Bodies in island order, for linking each island's circle. */
typedef struct {
    size_t island;
    body_t *body;
} island_entry_t;

static int compare_islands(const void *p, const void *q) {
    size_t a = ((const island_entry_t *)p)->island, b = ((const island_entry_t *)q)->island;
    return (a > b) - (a < b);
}

void scene_restore_sleep(scene_t *scene, body_t *const *bodies, const size_t *islands,
                         size_t count) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE(count == 0 || (bodies != NULL && islands != NULL),
            "bodies and islands must not be NULL (count %zu)", count);
    const world_ops_t *ops;
    world_t *world = world_of(scene, &ops, __func__);
    REQUIRE(scene_get_sleeping(scene), "sleeping is off (scene_set_sleeping)");
    island_entry_t *entries = memory_alloc((count + 1) * sizeof *entries);
    for (size_t i = 0; i < count; i++) {
        body_t *body = bodies[i];
        char what[48];
        snprintf(what, sizeof what, "bodies[%zu]", i);
        require_live(scene, body, what, __func__);
        REQUIRE(body_is_movable(body), "bodies[%zu] cannot move (infinite mass and inertia): it "
                                       "never sleeps", i);
        REQUIRE(!body->asleep, "bodies[%zu] is asleep already (listed twice?)", i);
        body_fall_asleep(body);
        entries[i] = (island_entry_t){islands[i], body};
    }
    qsort(entries, count, sizeof *entries, compare_islands);
    for (size_t i = 0, first = 0; i < count; i++) {
        body_t *body = entries[i].body;
        if (i > 0 && entries[i - 1].island != entries[i].island) first = i;
        bool last = i + 1 == count || entries[i + 1].island != entries[i].island;
        body->sleep_next = last ? entries[first].body : entries[i + 1].body;
        body->velocity = VEC_ZERO;
        body->angular_velocity = 0.0;
    }
    memory_free(entries);
    /* What was done to the bodies so far is the state they sleep in. */
    body_t **all = scene_body_array(scene);
    for (size_t i = 0; i < scene_bodies(scene); i++) all[i]->changed = false;
    ops->index_sleepers(world, all, scene_bodies(scene));
}

unsigned scene_get_sleep_phase(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    const world_ops_t *ops;
    world_t *world = scene_world(scene, &ops);
    return world != NULL ? ops->get_sleep_phase(world) : 0;
}

void scene_set_sleep_phase(scene_t *scene, unsigned phase) {
    REQUIRE_NOT_NULL(scene);
    const world_ops_t *ops;
    world_t *world = world_of(scene, &ops, __func__);
    REQUIRE(phase < 8, "phase must be 0 to 7 (got %u)", phase);
    ops->set_sleep_phase(world, phase);
}

uint64_t scene_get_solver_steps(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    const world_ops_t *ops;
    world_t *world = scene_world(scene, &ops);
    return world != NULL ? ops->get_solver_steps(world) : 0;
}

void scene_set_solver_steps(scene_t *scene, uint64_t steps) {
    REQUIRE_NOT_NULL(scene);
    const world_ops_t *ops;
    world_t *world = world_of(scene, &ops, __func__);
    ops->set_solver_steps(world, steps);
}

void scene_get_step_lengths(scene_t *scene, double *last, double *before) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE(last != NULL && before != NULL, "last and before must not be NULL");
    const world_ops_t *ops;
    world_t *world = scene_world(scene, &ops);
    *last = *before = 0.0;
    if (world != NULL) ops->get_step_lengths(world, last, before);
}

void scene_set_step_lengths(scene_t *scene, double last, double before) {
    REQUIRE_NOT_NULL(scene);
    const world_ops_t *ops;
    world_t *world = world_of(scene, &ops, __func__);
    REQUIRE(isfinite(last) && last >= 0.0, "last must be finite and >= 0 (got %g)", last);
    REQUIRE(isfinite(before) && before >= 0.0, "before must be finite and >= 0 (got %g)",
            before);
    REQUIRE(last > 0.0 || before == 0.0,
            "a step before the last needs a last step (got last 0, before %g)", before);
    ops->set_step_lengths(world, last, before);
}

size_t scene_contact_memory_count(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    const world_ops_t *ops;
    world_t *world = scene_world(scene, &ops);
    return world != NULL ? ops->contact_count(world) : 0;
}

scene_contact_memory_t scene_get_contact_memory(scene_t *scene, size_t index) {
    REQUIRE_NOT_NULL(scene);
    size_t count = scene_contact_memory_count(scene);
    REQUIRE(index < count, "index %zu out of range (%zu contacts)", index, count);
    const world_ops_t *ops;
    world_t *world = scene_world(scene, &ops);
    scene_contact_memory_t memory;
    ops->get_memory(world, index, &memory);
    return memory;
}

static bool finite_vector(vector_t v) {
    return isfinite(v.x) && isfinite(v.y);
}

/* Whether every number of the memory is finite (face_lead may be
 * INFINITY: a pair whose contact is found again each step). */
static bool memory_is_finite(const scene_contact_memory_t *m) {
    bool finite = finite_vector(m->normal) && finite_vector(m->face_normal) &&
                  finite_vector(m->face_point) && finite_vector(m->pose) &&
                  isfinite(m->pose_angle) && !isnan(m->face_lead) && m->face_lead != -INFINITY;
    for (int j = 0; j < m->point_count; j++) {
        const scene_memory_point_t *p = &m->points[j];
        finite = finite && finite_vector(p->point) && isfinite(p->separation) &&
                 isfinite(p->normal_impulse) && isfinite(p->tangent_impulse) &&
                 isfinite(p->restitution_impulse) && isfinite(p->restitution_tangent_impulse);
    }
    for (int j = 0; j < m->feature_count; j++) {
        finite = finite && finite_vector(m->feature_points[j]);
    }
    for (int j = 0; j < m->previous_count; j++) {
        finite = finite && isfinite(m->previous[j].normal_impulse) &&
                 isfinite(m->previous[j].tangent_impulse);
    }
    return finite;
}

static void check_memory(const scene_t *scene, const scene_contact_memory_t *m, size_t i) {
    char what[48];
    snprintf(what, sizeof what, "memories[%zu].body_a", i);
    require_live(scene, m->body_a, what, "scene_restore_contact_memory");
    snprintf(what, sizeof what, "memories[%zu].body_b", i);
    require_live(scene, m->body_b, what, "scene_restore_contact_memory");
    if (m->body_a == m->body_b) {
        engine_fail("scene_restore_contact_memory", "memories[%zu] pairs a body with itself", i);
    }
    if (m->body_a->kind == BODY_SHAPE_CHAIN) {
        engine_fail("scene_restore_contact_memory",
                    "memories[%zu].body_a is a chain: a chain is always body_b", i);
    }
    size_t segments = m->body_b->part_count;
    if (segments > 0 ? m->segment >= segments : m->segment != 0) {
        engine_fail("scene_restore_contact_memory",
                    "memories[%zu].segment %zu is not a segment of body_b (%zu segments)", i,
                    m->segment, segments);
    }
    if (m->point_count < 0 || m->point_count > 2 || m->feature_count < 0 || m->feature_count > 2 ||
        m->previous_count < 0 || m->previous_count > 2) {
        engine_fail("scene_restore_contact_memory",
                    "memories[%zu]: point_count, feature_count and previous_count must be 0 to 2 "
                    "(got %d, %d, %d)",
                    i, m->point_count, m->feature_count, m->previous_count);
    }
    if (!memory_is_finite(m)) {
        engine_fail("scene_restore_contact_memory",
                    "memories[%zu] holds a value that is not finite", i);
    }
}

static uint64_t memory_key(const scene_contact_memory_t *m) {
    return (uint64_t)m->body_a->id << 32 | m->body_b->id;
}

static int compare_memories(const void *p, const void *q) {
    uint64_t x = memory_key(p), y = memory_key(q);
    return (x > y) - (x < y);
}

void scene_restore_contact_memory(scene_t *scene, const scene_contact_memory_t *memories,
                                  size_t count) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE(count == 0 || memories != NULL, "memories is NULL (count %zu)", count);
    const world_ops_t *ops;
    world_t *world = world_of(scene, &ops, __func__);
    for (size_t i = 0; i < count; i++) check_memory(scene, &memories[i], i);
    /* The world keeps a step's contacts grouped by body a. */
    scene_contact_memory_t *sorted = memory_alloc((count + 1) * sizeof *sorted);
    for (size_t i = 0; i < count; i++) {
        sorted[i] = memories[i];
        /* The world's pair is with the chain's segment. */
        if (sorted[i].body_b->part_count > 0) {
            sorted[i].body_b = sorted[i].body_b->parts[sorted[i].segment];
        }
    }
    qsort(sorted, count, sizeof *sorted, compare_memories);
    for (size_t i = 1; i < count; i++) {
        if (memory_key(&sorted[i - 1]) == memory_key(&sorted[i])) {
            engine_fail(__func__, "the pair of bodies %zu and %zu is listed twice",
                        scene_body_index(scene, sorted[i].body_a),
                        scene_body_index(scene, body_public(sorted[i].body_b)));
        }
    }
    ops->restore_memory(world, sorted, count);
    memory_free(sorted);
}
