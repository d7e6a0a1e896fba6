#ifndef IMPLICIT_EULER_H
#define IMPLICIT_EULER_H

/*
 * INTEGRATOR_IMPLICIT_EULER's step, linearly implicit (backward) Euler in
 * the manner of Baraff and Witkin's cloth ("Large steps in cloth
 * simulation", 1998): with the forces f(x, v) whose Jacobians are known
 * (jacobian.h: stiffness S, damping C) taken at the end of the step,
 *     v' = v + M^-1 (J + h f(x', v')) + h g,   x' = x + h v',
 * f linearised about the start of the step:
 *     (M + h C + h^2 S) (v' - v) = J + h (F + M g) - h^2 S v,
 * F every force at the start of the step (the body's accumulated force), C
 * and S assembled over the bodies the forces join (relative velocities,
 * jacobian.h). Forces without a Jacobian act as in symplectic Euler; a body
 * that no Jacobian reaches moves exactly as under symplectic Euler. For
 * the linear springs and drag of forces.h the linearisation is exact: an
 * undamped spring's (x, v / omega) turns by atan(omega h) and shrinks by
 * 1 / sqrt(1 + (omega h)^2) every step, drag's velocity by 1 / (1 +
 * gamma h / m).
 *
 * Bodies of infinite mass, asleep, or not in the scene (named by a force
 * creator but never added) are held: their velocity is taken as given.
 * Rotation is not coupled (the forces act at centroids).
 *
 * Contacts: within the step a body meets an impulse with the mass of what
 * its springs hold to it, 1 / (A^-1)_ii (a body on a spring of omega h = 100
 * to an anchor weighs 10^4 times its mass; two bodies on a stiff spring,
 * their sum). Each motion's inverse_mass tells the contact solver so, and
 * implicit_euler_respond then passes every body's contact impulse on to the
 * bodies its springs join (v' = v_free + A^-1 P), so that the contacts see
 * the loads the springs carry. Where the springs close loops, (A^-1)_ii is
 * taken from the spanning forest (spring_system.h), which makes the mass
 * smaller than it is: the body then moves less under its contact than the
 * solver asked, and the next step finishes the push.
 */

#include <stddef.h>
#include "jostle/body.h"
#include "dynamics/motion.h"
#include "dynamics/jacobian.h"

typedef struct implicit_euler implicit_euler_t;

void implicit_euler_free(implicit_euler_t *workspace);

/*
 * motions[i] holds body i's symplectic Euler free motion (position weight
 * 1); replaces the velocity, displacement and mean acceleration of every
 * body that step->jacobians reach by the implicit step's. Writes each
 * body's index into its solver_index, and the bodies' inverse_mass (below).
 * *workspace is made or grown; a warm
 * one allocates nothing.
 */
void implicit_euler_correct(const integrator_step_t *step, body_t **bodies, size_t count,
                            integrator_motion_t *motions, implicit_euler_t **workspace);

/* After the world's contacts changed the motions of this step's correct:
 * v' = v_free + A^-1 P for the bodies it solved, P each one's contact
 * impulse as the solver saw it (velocity change over inverse_mass); their
 * displacements move alike (h v'). Nothing without a workspace or when no
 * contact touched them. */
void implicit_euler_respond(const integrator_step_t *step, body_t **bodies,
                            integrator_motion_t *motions, implicit_euler_t *workspace);

#endif // #ifndef IMPLICIT_EULER_H
