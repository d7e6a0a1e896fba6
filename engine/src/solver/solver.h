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
 * colour batches (solver_wide.h); solver.c runs the stages in order, and
 * the one-at-a-time solves for contacts no colour could take:
 * velocity_solve.h (preparing, warm starting, velocity iterations),
 * collision_pass.h (restitution), position_pass.h (advance, position
 * iterations, the cap on the correction).
 *
 * The integrator decides where a velocity puts a body: x' = x + dt ((1 - w) v
 * + w v'), with w its position weight (1/2 for the seed scheme). The solver
 * predicts positions with the same w, so a speculative contact stops a body
 * exactly at the surface, whatever the scheme.
 */

#include "solver/solver_types.h"
#include "solver/joint_solver.h"
#include "solver/shock.h"
#include "solver/solver_wide.h"

/* Whether a world's step n (counted from 0) sweeps its contacts in the
 * reverse order (solver_settings_t): the Thue-Morse sequence, the parity of
 * n's one bits. Every aligned block of 2^k steps splits evenly along any
 * period 2^j < 2^k, and any arithmetic progression of steps in the long run
 * (Gelfond 1968), so a periodic pattern of step lengths does not keep its
 * long steps on one order, as plain alternation did with steps of
 * alternating lengths (docs/design.md, Sweep order). */
static inline bool solver_sweeps_reversed(uint64_t n) {
    for (int shift = 32; shift > 0; shift /= 2) n ^= n >> shift;
    return (n & 1) != 0;
}

/* Everything after the narrowphase: prepare, warm start, velocity
 * iterations and position iterations (in colour batches, solver_wide.h,
 * whose arrays live in wide), advance, with the step's joints solved
 * after the contacts in each iteration (joint_solver.h). On entry each
 * body's v, w are its free velocities; on return they are its new
 * velocities, and its displacement is the one of the step. */
void solver_solve(solver_wide_t *wide, shock_t *shock, solver_contact_t *contacts,
                  const solver_anchor_t *anchors, size_t contact_count,
                  const solver_bodies_t *bodies, const solver_settings_t *settings,
                  const joint_step_t *joints);

#endif // #ifndef SOLVER_H
