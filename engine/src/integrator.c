#include "integrator.h"
#include "body_private.h"
#include "check.h"

double integrator_position_weight(integrator_t integrator) {
    switch (integrator) {
    case INTEGRATOR_SEED: return 0.5;
    case INTEGRATOR_EXPLICIT_EULER: return 0.0;
    case INTEGRATOR_SYMPLECTIC_EULER: return 1.0;
    }
    engine_fail(__func__, "unknown integrator %d", (int)integrator);
}

void integrator_advance(body_t *body, double dt, vector_t gravity, integrator_t integrator) {
    double w = integrator_position_weight(integrator);
    vector_t acceleration = vec_multiply(body->inverse_mass, body->force);
    if (body->inverse_mass > 0.0) acceleration = vec_add(acceleration, gravity);
    vector_t old_velocity = body->velocity;
    double old_omega = body->angular_velocity;
    body->velocity = vec_add(old_velocity, vec_add(vec_multiply(dt, acceleration),
                                                   vec_multiply(body->inverse_mass, body->impulse)));
    body->angular_velocity =
        old_omega + body->inverse_inertia * (dt * body->torque + body->angular_impulse);

    vector_t mean_velocity =
        vec_add(vec_multiply(1.0 - w, old_velocity), vec_multiply(w, body->velocity));
    body->centroid = vec_add(body->centroid, vec_multiply(dt, mean_velocity));
    body->centroid = vec_add(body->centroid, body->position_correction);
    body->angle += dt * ((1.0 - w) * old_omega + w * body->angular_velocity) + body->angle_correction;
    body->world_valid = false;

    body->force = VEC_ZERO;
    body->torque = 0.0;
    body->impulse = VEC_ZERO;
    body->angular_impulse = 0.0;
    body->position_correction = VEC_ZERO;
    body->angle_correction = 0.0;
}
