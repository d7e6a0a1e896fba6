#ifndef MOTION_H
#define MOTION_H

/*
 * What a step of an integrator works with, shared by the integrators
 * (integrator.h), implicit Euler's solve (implicit_euler.h) and the world's
 * contact pipeline: a body's motion over the step, and the step itself.
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "jostle/scene.h"
#include "jostle/vector.h"
#include "dynamics/jacobian.h"

/* One body's motion over one step. */
typedef struct {
    vector_t velocity;     /* at the end of the step (m/s) */
    double angular_velocity;
    vector_t displacement; /* of the centroid over the step (m) */
    double rotation;       /* rad */
    /* The displacement due to the velocity at the start and to the forces,
     * beside the end velocity's share: displacement = dt (drift + weight
     * velocity) for the free motion. */
    vector_t drift;
    double spin_drift;
    /* The mean acceleration of the free motion (m/s^2), for times of impact. */
    vector_t acceleration;
    /* 1 / the mass (1/kg) an impulse on the body meets within the step, for
     * the contact solver: the body's own, but under implicit Euler that of
     * the body with what its springs and drag join to it over the step
     * (implicit_euler.h). */
    double inverse_mass;
    /* The body slept at the start of the step (integrator_predict): it has
     * no motion (sleeping zeroed its velocities, and anything put in its
     * accumulators woke it), the other fields are not written (a sleeping
     * body is in no solve: the world leaves it out, implicit Euler holds
     * it), and integrator_move leaves it as it is: a sleeping body costs
     * neither its lines read nor its motion written (docs/design.md,
     * Sleeping). */
    bool still;
} integrator_motion_t;

/* Calls the force creators again with the bodies at a later stage's trial
 * pose and velocities (scene.h says which creators run there). */
typedef void (*integrator_evaluate_t)(void *context);

typedef struct {
    integrator_t integrator;
    double dt;
    vector_t gravity;          /* for every body of finite mass */
    integrator_evaluate_t evaluate; /* later stages; NULL: no force creators */
    void *context;
    /* Implicit Euler's: the Jacobians of the forces of the first
     * evaluation that have one (jacobian.h). */
    const force_jacobian_t *jacobians;
    size_t jacobian_count;
    uint64_t reuse_key; /* integrator_begin's; 0: record nothing for the next step */
} integrator_step_t;

#endif // #ifndef MOTION_H
