#ifndef COLLISION_PASS_H
#define COLLISION_PASS_H

/*
 * The collision pass: restitution before the contact solve, contact by
 * contact with Poisson's impulse and friction, repeated (at most passes
 * times) until no contact approaches faster than its bounce threshold
 * (`threshold`, m/s, solver_settings_t's, for all but free elastic pairs).
 * Contacts without elasticity take no part. The contacts must be prepared
 * (velocity_solve.h); returns whether a point that was apart at the start
 * of the step became an impact.
 */

#include <stdbool.h>
#include <stddef.h>
#include "solver/solver_types.h"

bool solver_collision_pass(solver_contact_t *contacts, size_t count, solver_velocity_t *velocities,
                           const solver_state_t *states, double dt, double threshold,
                           int passes);

#endif // #ifndef COLLISION_PASS_H
