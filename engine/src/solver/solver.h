#ifndef SOLVER_H
#define SOLVER_H

/*
 * The contact solver: a collision pass for restitution (Guendelman et al.
 * 2003) with Poisson's impulse and friction, then sequential impulses with
 * accumulated-impulse clamping (Catto), warm starting, Coulomb friction, a
 * two-point block solve for the normal impulses (so a box lands and leaves
 * flat), shock propagation before the last iteration (shock.h), impacts
 * timed within the step, landings, and non-linear Gauss-Seidel position
 * correction. docs/design.md says why each is there.
 *
 * It works on plain arrays (solver_bodies_t's rows, solver_contact_t
 * constraints) that world.c fills from the bodies and writes back; it knows
 * nothing of scenes or lists. The iterations run four contacts at a time in
 * colour batches (solver_wide.h); this file holds the rest, and the
 * one-at-a-time solves for contacts no colour could take.
 *
 * The integrator decides where a velocity puts a body: x' = x + dt ((1 - w) v
 * + w v'), with w its position weight (1/2 for the seed scheme). The solver
 * predicts positions with the same w, so a speculative contact stops a body
 * exactly at the surface, whatever the scheme.
 */

#include "solver/solver_types.h"

/* The earliest time in [0, dt] at which a gap s closing as s + v t + a t^2 / 2
 * reaches 0, or a negative number when it does not: the solver's model of
 * a point's approach over the step (m, m/s, m/s^2, s). */
double solver_time_of_impact(double s, double v, double a, double dt);

/* The approach speed (m/s) from which a contact with this restitution
 * between bodies with these rows bounces: SOLVER_FREE_RESTITUTION_THRESHOLD
 * for an elastic pair that nothing accelerates, else
 * SOLVER_RESTITUTION_THRESHOLD, which for inelastic contacts also decides
 * which approaches are timed as impacts. */
double solver_bounce_threshold(double restitution, const solver_state_t *sa,
                               const solver_state_t *sb);

#include "solver/shock.h"
#include "solver/solver_wide.h"

/* The rows of every body, body_count of each. */
typedef struct {
    solver_velocity_t *velocities;
    solver_displacement_t *displacements;
    solver_state_t *states;
    size_t body_count;
} solver_bodies_t;

/* Everything after the narrowphase: prepare, warm start, velocity
 * iterations and position iterations (in colour batches, solver_wide.h,
 * whose arrays live in wide), advance. On entry each body's v, w are its
 * free velocities; on return they are its new velocities, and its
 * displacement is the one of the step. */
void solver_solve(solver_wide_t *wide, shock_t *shock, solver_contact_t *contacts,
                  const solver_anchor_t *anchors, size_t contact_count,
                  const solver_bodies_t *bodies, const solver_settings_t *settings);

#endif // #ifndef SOLVER_H
