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

vector_t integrator_acceleration(const body_t *body, vector_t gravity) {
    if (body->inverse_mass == 0.0) return VEC_ZERO;
    return vec_add(vec_multiply(body->inverse_mass, body->force), gravity);
}

void integrator_free_velocity(const body_t *body, double dt, vector_t gravity, vector_t *velocity,
                              double *angular_velocity) {
    vector_t acceleration = integrator_acceleration(body, gravity);
    *velocity = vec_add(body->velocity, vec_add(vec_multiply(dt, acceleration),
                                                vec_multiply(body->inverse_mass, body->impulse)));
    *angular_velocity = body->angular_velocity +
                        body->inverse_inertia * (dt * body->torque + body->angular_impulse);
}

void integrator_advance(body_t *body, double dt, vector_t gravity, integrator_t integrator) {
    double w = integrator_position_weight(integrator);
    vector_t old_velocity = body->velocity;
    double old_omega = body->angular_velocity;
    integrator_free_velocity(body, dt, gravity, &body->velocity, &body->angular_velocity);

    vector_t mean_velocity =
        vec_add(vec_multiply(1.0 - w, old_velocity), vec_multiply(w, body->velocity));
    vector_t dx = vec_add(vec_multiply(dt, mean_velocity), body->position_correction);
    double dtheta = dt * ((1.0 - w) * old_omega + w * body->angular_velocity) + body->angle_correction;
    /* A body that did not move keeps its cached world polygon (walls). */
    if (dx.x != 0.0 || dx.y != 0.0 || dtheta != 0.0) {
        body->centroid = vec_add(body->centroid, dx);
        body->angle += dtheta;
        body->world_valid = false;
    }

    body->force = VEC_ZERO;
    body->torque = 0.0;
    body->impulse = VEC_ZERO;
    body->angular_impulse = 0.0;
    body->position_correction = VEC_ZERO;
    body->angle_correction = 0.0;
}
