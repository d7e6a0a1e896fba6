#ifndef WORLD_H
#define WORLD_H

/*
 * The world contact pipeline of a scene (stage 2 of scene_tick): bounding
 * boxes -> broadphase pairs -> narrowphase manifolds -> solver, from the
 * bodies' free motions (integrator.h), which it changes into the motions
 * the integrator applies in stage 3. The step's contacts
 * stay readable until the next step.
 *
 * It keeps last step's contacts, keyed by the pair's body ids, to warm-start
 * this step's with their impulses, and the contacts of the step before, so
 * that a step of another length starts from their force instead (narrowphase.c,
 * warm_rescaled). All arrays are reused: a warm step allocates nothing.
 */

#include <stdbool.h>
#include <stddef.h>
#include "jostle/body.h"
#include "dynamics/integrator.h"
#include "jostle/scene.h"
#include "jostle/scene_state.h"
#include "base/stage_clock.h"
#include "base/workers.h"
#include "solver/joint_solver.h"

typedef struct world world_t;

world_t *world_init(size_t velocity_iterations, size_t position_iterations);
void world_free(world_t *world);

void world_set_iterations(world_t *world, size_t velocity_iterations, size_t position_iterations);

/* The threads a step uses (scene_set_workers; >= 1): the caller's and
 * workers - 1 of the world's own, started at the first step that needs them
 * and stopped here when the count changes, and by world_free. */
void world_set_workers(world_t *world, size_t workers);

/* fn over the chunks of [0, count) on the world's threads (workers.h), for
 * the scene's loops over bodies; on the caller's alone with 1 worker. */
void world_for_bodies(world_t *world, size_t count, workers_fn_t fn, void *context);

typedef struct {
    double dt;
    /* integrator_position_weight of the scene's integrator */
    double position_weight;
    /* Whether slow islands sleep (sleep.h): asleep bodies take no part. */
    bool sleeping;
    /* At least the vertex count of the largest polygon in the step: scratch
     * room is sized by it once, so a new pair never allocates. */
    size_t largest_polygon;
    /* The scene's solver settings (scene.h): warm starting, restitution
     * threshold (m/s), sleep tolerances (m/s, rad/s) and sleep time (s). */
    bool warm_starting;
    double restitution_threshold;
    double sleep_linear, sleep_angular, sleep_time;
    /* The stage times of the tick (NULL: not timed); the world laps its
     * stages from the moment it is called. */
    stage_clock_t *clock;
    /* How many segments the chains among the bodies have (body.h): the
     * world collides those in their chains' place. */
    size_t chain_parts;
    /* The scene's joints (joint.h), solved with the contacts. */
    joint_step_t joints;
    /* Every body of the scene when the step's bodies are only its awake
     * ones (NULL: they are all of them): the index of sleeping bodies is
     * kept over these. */
    body_t **all_bodies;
    size_t all_count;
    /* The scene's count of changes to which bodies sleep (body_private.h):
     * while it stands still and no island fell asleep, that index does
     * too, and is not checked; NULL: checked every step. */
    const uint64_t *sleep_changes;
} world_step_t;

/* Wakes the sleeping islands that a body of bodies[0 .. count) (all the
 * scene's, or all but its sleeping ones, which are not marked) changed
 * since the last step (body_mark_changed) touched or may touch in the next
 * step of dt (sleep_wake_changed), and, when this step is longer than the
 * last, those that a moving body may reach in it (sleep_wake_ahead), under
 * the scene's gravity. The scene calls it after the force creators and
 * before the free motions, so that what wakes moves in the step;
 * world_step clears the marks. */
void world_wake_changed(world_t *world, body_t **bodies, size_t count, double dt,
                        vector_t gravity);

/* Runs the pipeline over bodies[0..count) (removed and sleeping bodies
 * take no part), all the scene's, or only its awake ones when
 * step->all_bodies is set: motions[i] holds body i's free motion on entry
 * and the motion with its contacts on return. Adds to the counters of
 * stats. */
void world_step(world_t *world, body_t **bodies, integrator_motion_t *motions, size_t count,
                const world_step_t *step, scene_stats_t *stats);

/* The contacts of the last world_step, for the scene's record (built only
 * when someone reads it). Their bodies are alive until the next step: a
 * body marked removed takes no part in contacts. */
size_t world_contact_count(const world_t *world);
contact_t world_get_contact(const world_t *world, size_t index);

/* Whether world contacts resolve the pair when both bodies are in the
 * world: their collision filters allow it and at least one can move (the
 * broadphase's rule). Whether a body is marked removed does not enter. */
bool world_pair_collides(const body_t *body1, const body_t *body2);

/* The pair's contact of the last world_step, as world_get_contact gives it
 * but with body1 and body2 as asked and the axis from body1 toward body2,
 * whichever way the world ordered the pair; false when the pair had no
 * contact (not even a speculative one). The world finds it among body1's or
 * body2's contacts, a handful, without a search of the step. */
bool world_pair_contact(const world_t *world, body_t *body1, body_t *body2, contact_t *contact);

/* The state a continuation needs (scene_state.h). world_get_memory reads
 * contact index (below world_contact_count) of the last step;
 * world_restore_memory makes the memories the contacts of a last step
 * (checked by the caller, and sorted by pair: body_a's id, then body_b's);
 * world_forget_removed drops the contacts and sleeping bodies that name a
 * body marked removed, before a tick without a step frees it. A memory
 * carries the pair's points of the step before last, which
 * world_restore_memory makes that step's. The phase is sleep.h's
 * island check count; world_index_sleepers indexes the bodies of
 * bodies[0 .. count) that were put to sleep outside a step. The step
 * lengths are those of the last step and the one before (s, 0: none). */
void world_get_memory(const world_t *world, size_t index, scene_contact_memory_t *memory);
void world_restore_memory(world_t *world, const scene_contact_memory_t *memories, size_t count);
void world_forget_removed(world_t *world);
unsigned world_get_sleep_phase(const world_t *world);
void world_set_sleep_phase(world_t *world, unsigned phase);
/* The steps the solver has taken (scene_get_solver_steps). */
uint64_t world_get_solver_steps(const world_t *world);
void world_set_solver_steps(world_t *world, uint64_t steps);
void world_index_sleepers(world_t *world, body_t **bodies, size_t count);
void world_get_step_lengths(const world_t *world, double *last, double *before);
void world_set_step_lengths(world_t *world, double last, double before);

#endif // #ifndef WORLD_H
