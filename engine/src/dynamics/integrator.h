#ifndef INTEGRATOR_H
#define INTEGRATOR_H

/*
 * How bodies move: the one place that turns forces into motion. A step of
 * scene_tick goes through it twice:
 *   - integrator_predict, the force stage: calls the force creators (once,
 *     or at every stage of a multi-stage scheme) and writes each body's free
 *     motion, what the step would do to it if no contact acted;
 *   - the world's contact solver may then change each motion's velocities
 *     and displacement (a velocity change dv moves the body by
 *     weight * dt * dv, the scheme's integrator_position_weight: contacts
 *     act on the body as a constant force over the step would);
 *   - integrator_apply, the integrate stage: moves the body by its motion.
 * body_tick does both for one body with the seed scheme.
 *
 * The schemes, for x'' = a(x, v) at step h (omega the highest frequency of
 * a spring, for the stability limits on omega h):
 *   seed              v' = v + h a, x' = x + h (v + v') / 2. Order 1 (2 for
 *                     constant a, which it follows exactly); adds energy to
 *                     every oscillator: by 1 + (omega h)^2 / 2 a step (no
 *                     stable h).
 *   explicit Euler    v' = v + h a, x' = x + h v. Order 1; energy times
 *                     1 + (omega h)^2 a step (no stable h).
 *   symplectic Euler  v' = v + h a, x' = x + h v'. Order 1, symplectic;
 *                     stable for omega h < 2.
 *   velocity Verlet   kick h/2, drift h, kick h/2; 2 force evaluations,
 *                     1 when the first is reused (integrator_begin).
 *                     Order 2, symplectic; stable for omega h < 2.
 *   RK4               classical Runge-Kutta; 4 evaluations. Order 4, not
 *                     symplectic (damps oscillators slowly); stable for
 *                     omega h < 2 sqrt(2).
 *   symplectic4       Yoshida's composition of three Verlet steps of
 *                     h / (2 - 2^(1/3)), -2^(1/3) h / (2 - 2^(1/3)),
 *                     h / (2 - 2^(1/3)); 4 evaluations, 3 when the first
 *                     is reused. Order 4, symplectic; stable for
 *                     omega h < 1.573.
 *   implicit Euler    symplectic Euler with the forces whose Jacobians are
 *                     known (create_spring, create_drag) taken at the end
 *                     of the step, solved over the bodies they join
 *                     (implicit_euler.h); 1 evaluation. Order 1; stable
 *                     for every omega h on those springs, energy times
 *                     1 / (1 + (omega h)^2) a step.
 * Every scheme sees the force creators' forces and torques at its stages;
 * impulses act at the start of the step.
 */

#include <stdbool.h>
#include <stdint.h>
#include "jostle/body.h"
#include "dynamics/motion.h"
#include "jostle/scene.h"

/* The weight w of a contact's velocity change in the position update of a
 * scheme: a change dv moves the body by w dt dv, as a constant force does
 * under the scheme (1/2 in the seed scheme and those exact for constant
 * forces, 1 in symplectic Euler, 0 in explicit Euler). The contact solver
 * predicts with it where a velocity it chooses will put the bodies. */
double integrator_position_weight(integrator_t integrator);

/* The factor by which a step of the scheme multiplies the energy of an
 * undamped oscillator at theta = omega h (its amplification matrix's
 * spectral radius squared): 1 where it is stable and symplectic. */
double integrator_oscillator_growth(integrator_t integrator, double theta);

/* The number of force evaluations a step of the scheme makes, the first
 * included even when it is reused (inline: the scene asks at every tick). */
static inline int integrator_stage_count(integrator_t integrator) {
    switch (integrator) {
    case INTEGRATOR_VELOCITY_VERLET: return 2;
    case INTEGRATOR_RK4:
    case INTEGRATOR_SYMPLECTIC4: return 4;
    default: return 1;
    }
}

/* Whether each body's free motion depends on its own forces alone (the
 * explicit one-stage schemes): it may then be computed body by body, on
 * any thread, or as the body is moved. Implicit Euler's couples the
 * bodies its springs join. */
static inline bool integrator_is_per_body(integrator_t integrator) {
    return integrator_stage_count(integrator) == 1 && integrator != INTEGRATOR_IMPLICIT_EULER;
}

/* Per-body storage for the multi-stage schemes, kept across steps so that
 * a warm scene allocates nothing. */
typedef struct integrator_stages integrator_stages_t;
void integrator_stages_free(integrator_stages_t *stages);

/* Before the first evaluation of a step: a multi-stage scheme keeps the
 * forces set on the bodies since their last step, which act at every
 * stage.
 *
 * First same as last: velocity Verlet and symplectic4 end their step with
 * an evaluation at the pose the step moves the bodies to. When reuse_key
 * is not 0 (the scene's promise that its force creators depend on the
 * bodies' centroids and masses only, and a number that changes whenever a
 * creator is added or dropped), the same key was recorded at the end of
 * the last step, and every body is the same, at the same centroid and mass
 * to the bit, with the same force and torque set since, the forces of that
 * evaluation are put on the bodies and true is returned: the caller skips
 * the first evaluation, whose result would be the same bits. */
bool integrator_begin(integrator_t integrator, body_t **bodies, size_t count,
                      integrator_stages_t **stages, uint64_t reuse_key);


/*
 * The force stage, after the first evaluation of the forces (the bodies
 * hold the force, torque and impulses of the start of the step): a
 * multi-stage scheme evaluates them at its later stages; then motions[i]
 * is written for bodies[i]. The bodies are left at their start pose and
 * velocity, with the forces and impulses of the first evaluation. *stages
 * is made or grown as needed.
 */
void integrator_predict(const integrator_step_t *step, body_t **bodies, size_t count,
                        integrator_motion_t *motions, integrator_stages_t **stages);

/* integrator_predict for bodies [begin, end) of a per-body scheme
 * (integrator_is_per_body), which calls no force creator: each body's
 * motion is its own, so ranges may run on several threads at once. A
 * sleeping body's motion is only marked still (motion.h). */
void integrator_predict_range(const integrator_step_t *step, body_t **bodies,
                              integrator_motion_t *motions, size_t begin, size_t end);

/* After the world's contacts changed the motions, before they are applied:
 * implicit Euler passes each body's contact impulse on to the bodies its
 * springs join (implicit_euler_respond); nothing for the other schemes. */
void integrator_respond(const integrator_step_t *step, body_t **bodies,
                        integrator_motion_t *motions, integrator_stages_t *stages);

/* Moves one body by motion and gives it the motion's velocities (body_tick;
 * the scene moves its bodies with integrator_move). The caller checks the
 * result and then clears the body's accumulators (which explain a result
 * that overflowed). */
void integrator_apply(body_t *body, const integrator_motion_t *motion);

/* What the integrate stage found. */
typedef struct {
    /* The first body whose pose or velocity no longer fits a double, or the
     * count when none: it is moved but keeps its accumulators, which
     * explain the result (body_explain_non_finite); later bodies are not
     * moved. */
    size_t failed;
    vector_t failed_start; /* that body's centroid before the step */
    bool removed;          /* some body is marked removed (those are not moved) */
} integrator_outcome_t;

/*
 * The integrate stage: moves each body not marked removed by motions[i]
 * (integrator_predict's, as the world changed it) and clears its
 * accumulators; a still motion (motion.h) leaves its body as it is. With
 * motions NULL, for a per-body scheme when nothing
 * acts between the forces and the move (no world contacts), each body's
 * free motion is computed as it is moved: one pass over the bodies, the
 * motion never stored.
 */
integrator_outcome_t integrator_move(const integrator_step_t *step, body_t **bodies,
                                     size_t count, const integrator_motion_t *motions);

#endif // #ifndef INTEGRATOR_H
