#ifndef SLEEP_H
#define SLEEP_H

/*
 * Sleeping: islands of touching bodies that have stayed slow for
 * SLEEP_TIME are taken out of the step, and woken when a moving body comes
 * within a step of them (body.c wakes them when the user sets a pose,
 * velocity, force or impulse, or removes a body of the island).
 *
 * The world calls sleep_update at the end of its step: it joins the step's
 * active bodies into islands over their touching contacts, puts to sleep
 * the islands that qualify, and wakes the sleeping islands that a moving
 * body's box for the next step reaches. Sleeping bodies are kept in an
 * index sorted by the left edge of their boxes, rebuilt only when the set
 * of sleeping bodies changed, so a scene that is all asleep costs one
 * check per body per step.
 *
 * Allocation: arrays grow to the largest scene seen and are reused.
 */

#include <stddef.h>
#include <stdint.h>
#include "aabb.h"
#include "body.h"
#include "solver.h"

/* Below these speeds (m/s, rad/s; the linear one less for bodies under
 * half a metre) for SLEEP_TIME (s) a body may sleep. */
extern const double SLEEP_LINEAR_SPEED, SLEEP_ANGULAR_SPEED, SLEEP_TIME;

typedef struct {
    struct sleep_entry *entries;
    size_t count, capacity;
    double widest; /* the widest box in the index (m) */
    uint32_t *parent;
    size_t parent_capacity;
    struct sleep_island *islands;
    size_t island_capacity;
} sleep_t;

void sleep_free(sleep_t *sleep);

/* The step as sleep_update reads it, one row per active body, in solver
 * row order: the body, its end velocities (which sleep_update sets to 0 for
 * a body it puts to sleep) and displacement, its free acceleration (a body pushed by a force
 * or gravity sleeps only resting on something immovable) and the box it
 * may reach by the end of the next step. */
typedef struct {
    body_t **bodies;
    solver_velocity_t *velocities;
    const solver_displacement_t *displacements;
    const solver_state_t *states;
    const aabb_t *reach;
    size_t count;
    double dt;
} sleep_step_t;

/* Two active rows whose contact touches this step; settled when its
 * overlap is within what the position pass leaves alone (an island still
 * pushing an overlap out, with no velocity, must not sleep before it is
 * out). */
typedef struct {
    uint32_t a, b;
    bool settled;
} sleep_link_t;

/* Updates the sleep timers, puts qualifying islands to sleep, and wakes the
 * sleeping islands within reach of moving bodies. all_bodies[0 ..
 * all_count) is every body of the scene, for the index. */
void sleep_update(sleep_t *sleep, const sleep_step_t *step, const sleep_link_t *links,
                  size_t link_count, body_t **all_bodies, size_t all_count);

#endif // #ifndef SLEEP_H
