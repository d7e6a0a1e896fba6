#ifndef VELOCITY_SOLVE_H
#define VELOCITY_SOLVE_H

/*
 * One contact's velocity constraint, one contact at a time: prepared for
 * the step (effective masses, each point's target end velocity and impact
 * within the step, the block solve's matrix), warm started, and solved
 * (friction, then the normal impulses, both at once by the block solve
 * when it is well conditioned). The colour batches (solver_wide.h) do the
 * same four contacts at a time; solver.c solves here the contacts no colour
 * could take.
 */

#include <stdbool.h>
#include <stddef.h>
#include "solver/solver_types.h"

/* The earliest time in [0, dt] at which a gap s closing as s + v t + a t^2 / 2
 * reaches 0, or a negative number when it does not: the solver's model of
 * a point's approach over the step (m, m/s, m/s^2, s). */
double solver_time_of_impact(double s, double v, double a, double dt);

/* The approach speed (m/s) from which a contact with this restitution
 * between bodies with these rows bounces: SOLVER_FREE_RESTITUTION_THRESHOLD
 * for an elastic pair that nothing accelerates, else
 * `threshold` (solver_settings_t's), which for inelastic contacts also
 * decides which approaches are timed as impacts. */
double solver_bounce_threshold(double restitution, const solver_state_t *sa,
                               const solver_state_t *sb, double threshold);

/* Whether contact c, with these anchors between bodies with rows a and b,
 * is solved by the block solve: two points whose 2x2 normal
 * effective-mass matrix is well conditioned. Whoever writes a contact's
 * geometry sets its block field with this (the narrowphase, impacts):
 * the batches are arranged by kind before the contacts are prepared. */
bool solver_contact_blocks(const solver_contact_t *c, const solver_anchor_t *anchor,
                           const solver_velocity_t *a, const solver_velocity_t *b);

/* Prepares contact c (anchors `anchor`, block decided) for the step: lever
 * terms, effective masses, targets, impacts within the step, which body
 * rests on which, and a block contact's inverse matrix. Returns whether a
 * point has an impact within the step; sets *raised when a touching
 * point's target was raised. Writes only c. The batches prepare their
 * contacts four at a time (solver_wide_prepare) with the same bits. */
bool solver_prepare_contact(solver_contact_t *c, const solver_anchor_t *anchor,
                            const solver_bodies_t *bodies, const solver_settings_t *settings,
                            bool *raised);

/* Applies prepared contact c's accumulated impulses to its bodies' rows. */
void solver_warm_start(const solver_contact_t *c, solver_velocity_t *velocities);

/* One velocity iteration of prepared contact c. */
void solver_solve_velocity(solver_contact_t *c, solver_velocity_t *velocities);

/* The same, of c's normals alone, each raised target counted as 0 (the
 * relaxation, solver.c). */
void solver_relax_velocity(solver_contact_t *c, solver_velocity_t *velocities);

#endif // #ifndef VELOCITY_SOLVE_H
