#include "solver/joint_solver.h"
#include <math.h>

static const joint_kind_t *kind_of(const joint_t *joint) {
    static const joint_kind_t *const KINDS[JOINT_TYPE_COUNT] = {
        &JOINT_REVOLUTE_KIND, &JOINT_DISTANCE_KIND,  &JOINT_MOUSE_KIND, &JOINT_WELD_KIND,
        &JOINT_PRISMATIC_KIND, &JOINT_WHEEL_KIND, &JOINT_MOTOR_KIND,
    };
    return KINDS[joint->def.type];
}

/* Whether the body is in the step's rows: the world (NULL) always is. */
static bool in_step(const body_t *body, const solver_bodies_t *bodies) {
    if (body == NULL) return true;
    return !body->asleep && !body->removed && body->in_scene &&
           body->solver_index < bodies->body_count;
}

static void take_rows(joint_t *joint, const body_t *body, const solver_bodies_t *bodies,
                      bool first) {
    solver_velocity_t *v = &joint->ground_velocity;
    solver_displacement_t *d = &joint->ground_displacement;
    vector_t drift = VEC_ZERO;
    double spin = 0.0;
    if (body != NULL) {
        v = &bodies->velocities[body->solver_index];
        d = &bodies->displacements[body->solver_index];
        drift = bodies->states[body->solver_index].drift;
        spin = bodies->states[body->solver_index].spin_drift;
    } else {
        *v = (solver_velocity_t){VEC_ZERO, 0.0, 0.0, 0.0};
        *d = (solver_displacement_t){VEC_ZERO, 0.0, 0.0};
    }
    if (first) {
        joint->rows.v1 = v;
        joint->rows.d1 = d;
        joint->m1 = v->inverse_mass;
        joint->i1 = v->inverse_inertia;
        joint->drift1 = drift;
        joint->spin1 = spin;
    } else {
        joint->rows.v2 = v;
        joint->rows.d2 = d;
        joint->m2 = v->inverse_mass;
        joint->i2 = v->inverse_inertia;
        joint->drift2 = drift;
        joint->spin2 = spin;
    }
}

/* Last step's impulses scaled to this step's length (they stand for the
 * same forces), or forgotten. */
static void carry_impulses(joint_t *joint, double dt, bool warm_starting) {
    double scale = warm_starting && joint->impulse_dt > 0.0 ? dt / joint->impulse_dt : 0.0;
    joint->point_impulse = vec_multiply(scale, joint->point_impulse);
    joint->angle_impulse *= scale;
    joint->axial_impulse *= scale;
    joint->spring_impulse *= scale;
    joint->motor_impulse *= scale;
    joint->lower_impulse *= scale;
    joint->upper_impulse *= scale;
    joint->impulse_dt = dt;
}

/* The geometry at the start of the step: lever arms, separation, angle
 * and axis in the world. */
static void take_geometry(joint_t *joint) {
    const body_t *b1 = joint->def.body1, *b2 = joint->def.body2;
    double angle1 = b1 != NULL ? b1->angle : 0.0;
    vector_t c1 = b1 != NULL ? b1->centroid : VEC_ZERO;
    joint->r1 = vec_rotate(joint->def.anchor1, angle1);
    joint->r2 = vec_rotate(joint->def.anchor2, b2->angle);
    joint->delta = vec_subtract(vec_add(b2->centroid, joint->r2), vec_add(c1, joint->r1));
    joint->angle = b2->angle - angle1 - joint->def.reference_angle;
    joint->axis = vec_rotate(vec_normalize(joint->def.axis), angle1);
    joint->perp = vec_perpendicular(joint->axis);
}

/* Whether the body of the row turns by at most JOINT_EXACT_TURN in the
 * step at its angular velocity now. */
static bool slow_turn(const joint_t *joint, const solver_velocity_t *row, double spin) {
    return fabs(joint->dt * (spin + joint->weight * row->w)) <= JOINT_EXACT_TURN;
}

/* Position sweeps of the joints per position iteration of the contacts:
 * a chain passes its correction one link per sweep, and joints are few
 * beside contacts, so they get more (a 20-link chain swinging at 1/240 s
 * stretched 0.44% with one, 0.16% with four). */
static const int JOINT_POSITION_SWEEPS = 4;

void joint_solver_prepare(const joint_step_t *step, const solver_bodies_t *bodies,
                          const solver_settings_t *settings) {
    double dt = settings->dt;
    for (size_t i = 0; i < step->count; i++) {
        joint_t *joint = step->joints[i];
        joint->active = in_step(joint->def.body1, bodies) && in_step(joint->def.body2, bodies);
        if (!joint->active) continue;
        take_rows(joint, joint->def.body1, bodies, true);
        take_rows(joint, joint->def.body2, bodies, false);
        joint->dt = dt;
        joint->weight = settings->position_weight;
        carry_impulses(joint, dt, settings->warm_starting);
        take_geometry(joint);
        joint->closes_gap = joint->weight > 0.0 && slow_turn(joint, joint->rows.v1, joint->spin1) &&
                            slow_turn(joint, joint->rows.v2, joint->spin2);
        kind_of(joint)->prepare(joint);
    }
}

void joint_solver_iterate(const joint_step_t *step) {
    for (size_t i = 0; i < step->count; i++) {
        joint_t *joint = step->joints[i];
        if (joint->active) kind_of(joint)->solve_velocity(joint);
    }
}

void joint_solver_correct(const joint_step_t *step) {
    for (int sweep = 0; sweep < JOINT_POSITION_SWEEPS; sweep++) {
        for (size_t i = 0; i < step->count; i++) {
            joint_t *joint = step->joints[i];
            const joint_kind_t *kind = kind_of(joint);
            if (joint->active && kind->solve_position != NULL) kind->solve_position(joint);
        }
    }
}

void joint_solver_settle(const joint_step_t *step) {
    for (size_t i = 0; i < step->count; i++) {
        joint_t *joint = step->joints[i];
        const joint_kind_t *kind = kind_of(joint);
        if (joint->active && kind->settle_velocity != NULL) kind->settle_velocity(joint);
    }
}
