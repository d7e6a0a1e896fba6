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

/* What preparing contacts found: an impact within the step, an elastic
 * contact, a touching point whose target was raised above 0 (a resting
 * approach, velocity_solve.c). */
typedef struct {
    bool impact, elastic, raised;
} prepared_t;

/* Prepares contacts [begin, end) for the step (their anchors are anchors[i]
 * of contact i); returns what they hold. Each contact writes only itself:
 * ranges may run on several threads. */
prepared_t solver_prepare_range(solver_contact_t *contacts, const solver_anchor_t *anchors,
                                const solver_bodies_t *bodies, const solver_settings_t *settings,
                                size_t begin, size_t end);

/* Applies prepared contact c's accumulated impulses to its bodies' rows. */
void solver_warm_start(const solver_contact_t *c, solver_velocity_t *velocities);

/* One velocity iteration of prepared contact c. */
void solver_solve_velocity(solver_contact_t *c, solver_velocity_t *velocities);

/* The same, of c's normals alone, each raised target counted as 0 (the
 * relaxation, solver.c). */
void solver_relax_velocity(solver_contact_t *c, solver_velocity_t *velocities);

#endif // #ifndef VELOCITY_SOLVE_H
