#ifndef SLEEP_H
#define SLEEP_H

/*
 * Sleeping: islands of touching bodies that have stayed slow for
 * the sleep time (sleep_step_t) are taken out of the step, and woken when a moving body comes
 * within a step of them (body.c wakes them when the user sets a pose,
 * velocity, force or impulse, or removes a body of the island), or when a
 * body they touch, static ones included, changed between steps
 * (sleep_wake_changed).
 *
 * The world calls it at the end of its step: sleep_time_bodies advances the
 * timers, sleep_islands (only when some body is ready) joins the step's
 * bodies into islands over their touching contacts and puts to sleep the
 * islands that qualify, sleep_wake_reached wakes the sleeping islands that
 * a moving body's box for the next step reaches. Sleeping bodies are kept in an
 * index sorted by the left edge of their boxes, rebuilt only when the set
 * of sleeping bodies changed, so a scene that is all asleep costs one
 * check per body per step.
 *
 * Allocation: arrays grow to the largest scene seen and are reused.
 */

#include <stddef.h>
#include <stdint.h>
#include "jostle/aabb.h"
#include "jostle/body.h"
#include "collision/broadphase.h"
#include "solver/solver.h"

typedef struct {
    struct sleep_entry *entries;
    size_t count, capacity;
    double widest; /* the widest box in the index (m) */
    size_t slept;  /* bodies put to sleep since the index was built */
    /* The scene's count of changes to who sleeps when the index was last
     * checked (sleep_wake_reached); checked: whether it has been. */
    uint64_t checked_changes;
    bool checked;
    unsigned steps; /* since islands were last joined */
    uint32_t *parent;
    size_t parent_capacity;
    struct sleep_island *islands;
    size_t island_capacity;
} sleep_t;

void sleep_free(sleep_t *sleep);

/* Whether some body may be asleep; when not, the world steps every body
 * without gathering the awake ones. */
static inline bool sleep_any(const sleep_t *sleep) {
    return sleep->count > 0;
}

/* The step as sleep.c reads it, one row per body the world stepped, in
 * solver row order: the body, its end velocities (set to 0 for a body put
 * to sleep) and displacement, its free acceleration (a body pushed by a
 * force or gravity sleeps only resting on something immovable), and its
 * broadphase box over the step, from which its reach over the next step
 * is found with margin. */
typedef struct {
    body_t **bodies;
    solver_velocity_t *velocities;
    const solver_displacement_t *displacements;
    const solver_state_t *states;
    const broadphase_proxy_t *proxies;
    size_t count;
    double dt;
    double margin;
    /* scene_set_sleep_tolerance (m/s at its rim, less for bodies under half
     * a metre, five times more for a body gravity or a force pulls; rad/s)
     * and scene_set_sleep_time (s): slower than these for that long, a
     * body may sleep. */
    double linear_tolerance, angular_tolerance, time;
} sleep_step_t;

/* Two rows whose contact touches this step, or that a joint joins; b is
 * SLEEP_WORLD for a joint that holds row a to the world (it supports a's
 * island as a floor does). */
typedef struct {
    uint32_t a, b;
} sleep_link_t;
#define SLEEP_WORLD UINT32_MAX

/* Advances the sleep timer of each movable body of rows [begin, end);
 * returns how many of them have been slow for the step's sleep time. When none of all
 * the rows has, no island can sleep: the caller need not list its contacts
 * for sleep_islands. Each row writes only its own body, so ranges may run
 * on different threads. */
size_t sleep_time_bodies(const sleep_step_t *step, size_t begin, size_t end);

/* Islands are joined at most every SLEEP_CHECK_STEPS steps: true when
 * this is such a step (and counts it). */
enum { SLEEP_CHECK_STEPS = 8 };
bool sleep_is_check_step(sleep_t *sleep);

/* Puts to sleep the islands whose every body is ready, joined over the
 * touching links. */
void sleep_islands(sleep_t *sleep, const sleep_step_t *step, const sleep_link_t *links,
                   size_t link_count);

/* Keeps the index of sleeping bodies current (all_bodies[0 .. all_count)
 * is every body of the scene; changes, when not NULL, the scene's count of
 * changes to who sleeps, which spares the check while it stands still) and
 * wakes the sleeping islands that a body moving faster than the tolerances
 * may reach in the next step. */
void sleep_wake_reached(sleep_t *sleep, const sleep_step_t *step, body_t **all_bodies,
                        size_t all_count, const uint64_t *changes);

/* Drops the bodies marked removed from the index, before they are freed
 * without a step (a tick of dt 0), which would rebuild it. */
void sleep_forget_removed(sleep_t *sleep);

/* Indexes the sleeping bodies of bodies[0 .. count) (every body of the
 * scene) after they were put to sleep outside a step (scene_restore_sleep),
 * so that the next step leaves them out and wakes them as any others. */
void sleep_index_asleep(sleep_t *sleep, body_t **bodies, size_t count);

/* Before a step: wakes the sleeping islands that a body marked changed
 * (body_mark_changed) touched before its change or may touch in the step,
 * its box then and its box now each grown by margin and by how far it may
 * go in dt (at its velocities now or at those that gravity, its force,
 * torque and impulses give it by the end of the step, the larger). The
 * index is the one of the last step (bodies woken since are skipped in
 * it). */
void sleep_wake_changed(const sleep_t *sleep, body_t *body, double dt, vector_t gravity,
                        double margin);

/* Before a step longer than the last, whose reach sleep_wake_reached
 * sized: wakes the sleeping islands that an awake body moving faster than
 * the tolerances (as sleep_wake_reached counts it) may reach in this step,
 * its box grown as sleep_wake_changed grows it. */
void sleep_wake_ahead(const sleep_t *sleep, body_t *body, double dt, vector_t gravity,
                      double margin);

#endif // #ifndef SLEEP_H
