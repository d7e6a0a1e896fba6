#ifndef INTEGRATOR_H
#define INTEGRATOR_H

/* Advancing one body by one step with a chosen scheme; body_tick and
 * scene_tick both come here, so each scheme is written once. */

#include "body.h"
#include "scene.h"

/*
 * The weight w of the new velocity in the position update of a scheme:
 * x' = x + dt ((1 - w) v + w v'). The contact solver uses it to predict where
 * a velocity it chooses will put the bodies at the end of the step.
 */
double integrator_position_weight(integrator_t integrator);

/* The body's linear acceleration from its force and gravity (m/s^2). */
vector_t integrator_acceleration(const body_t *body, vector_t gravity);

/* The velocity and angular velocity the body would end the step with if
 * nothing but its accumulated force, torque and impulses acted. */
void integrator_free_velocity(const body_t *body, double dt, vector_t gravity, vector_t *velocity,
                              double *angular_velocity);

/* Advances body by dt with gravity (m/s^2, ignored for infinite mass), its
 * accumulated force, torque, impulses and contact corrections; then clears
 * those accumulators. */
void integrator_advance(body_t *body, double dt, vector_t gravity, integrator_t integrator);

#endif // #ifndef INTEGRATOR_H
