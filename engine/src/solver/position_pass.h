#ifndef POSITION_PASS_H
#define POSITION_PASS_H

/*
 * After the velocity iterations: where the integrator will put each body
 * (solver_advance, with an impact's velocity change timed at its moment
 * and a landing placed on its surface), the position pass one contact at a
 * time (the colour batches do it four at a time, solver_wide.h), and the
 * cap on how far the position pass moved a body in the step. Each body or
 * contact writes only its own: ranges of bodies may run on several
 * threads.
 */

#include <stddef.h>
#include "solver/solver_types.h"

/* Counts each contact that pushed in its bodies' pushing contacts, and
 * marks each movable body of an impact with its earliest one (for
 * solver_advance). */
void solver_mark_impacts(const solver_contact_t *contacts, size_t count,
                         const solver_velocity_t *velocities, solver_state_t *states);

/* Each body's displacement in [begin, end) for its solved velocity. */
void solver_advance(const solver_bodies_t *bodies, const solver_settings_t *s, size_t begin,
                    size_t end);

/* How far point p of contact c is to be pushed back now (<= 0, m): its
 * separation after the displacements so far, toward minus the contact's
 * slop by rate, at most SOLVER_MAX_POSITION_CORRECTION. */
double solver_position_error(const solver_contact_t *c, const solver_point_t *p, double rate,
                             const solver_displacement_t *a, const solver_displacement_t *b);

/* One position iteration of contact c. */
void solver_solve_position(const solver_contact_t *c, const solver_velocity_t *velocities,
                           solver_displacement_t *displacements);

/* Caps what the position pass moved bodies [begin, end) (SOLVER_MAX_PUSH_SPEED). */
void solver_limit_corrections(const solver_bodies_t *bodies, double dt, size_t begin, size_t end);

#endif // #ifndef POSITION_PASS_H
