/* The revolute joint (a pin): a rigid point constraint, an angular motor
 * with a torque bound, and speculative angle limits. */
#include "solver/joint_types.h"

static void prepare(joint_t *joint) {
    joint_point_mass(joint, joint->r1, joint->r2, &joint->k11, &joint->k12, &joint->k22);
    joint->angular_mass = joint_inverse(joint->i1 + joint->i2);
    if (!joint->def.enable_motor) joint->motor_impulse = 0.0;
    if (!joint->def.enable_limit) joint->lower_impulse = joint->upper_impulse = 0.0;
    vector_t p = joint->point_impulse;
    double axial = joint->motor_impulse + joint->lower_impulse - joint->upper_impulse;
    joint_apply(joint, p, vec_cross(joint->r1, p) + axial, vec_cross(joint->r2, p) + axial);
}

static double relative_spin(const joint_t *joint) {
    return joint->rows.v2->w - joint->rows.v1->w;
}

static void solve_velocity(joint_t *joint) {
    const joint_def_t *def = &joint->def;
    if (def->enable_motor) {
        double bound = def->max_motor_torque * joint->dt;
        double old = joint->motor_impulse;
        double impulse = -joint->angular_mass * (relative_spin(joint) - def->motor_speed);
        joint->motor_impulse = joint_clamp(old + impulse, -bound, bound);
        impulse = joint->motor_impulse - old;
        joint_apply(joint, VEC_ZERO, impulse, impulse);
    }
    if (def->enable_limit) {
        /* The step turns the joint by dt (drift + weight spin): the
         * limit is reached when that closes the gap to it. */
        double drift = joint->dt * (joint->spin2 - joint->spin1);
        double reach = joint->weight > 0.0 ? joint->dt * joint->weight : joint->dt;
        double impulse = joint_limit_impulse(joint->angular_mass,
                                             joint->angle + drift - def->lower_angle,
                                             relative_spin(joint), reach, &joint->lower_impulse);
        joint_apply(joint, VEC_ZERO, impulse, impulse);
        impulse = joint_limit_impulse(joint->angular_mass, def->upper_angle - joint->angle - drift,
                                      -relative_spin(joint), reach, &joint->upper_impulse);
        joint_apply(joint, VEC_ZERO, -impulse, -impulse);
    }
    vector_t gap = joint_predicted_gap(joint, NULL), rate = joint_relative_velocity(joint);
    vector_t cdot = {joint_closing_rate(joint, gap.x, rate.x),
                     joint_closing_rate(joint, gap.y, rate.y)};
    vector_t p = vec_negate(joint_solve22(joint->k11, joint->k12, joint->k22, cdot));
    joint->point_impulse = vec_add(joint->point_impulse, p);
    joint_apply(joint, p, vec_cross(joint->r1, p), vec_cross(joint->r2, p));
}

/* Solves the 3x3 symmetric K x = b by Cramer's rule; a singular K
 * gives 0. */
static void solve33(const double k[3][3], const double b[3], double x[3]) {
    double c00 = k[1][1] * k[2][2] - k[1][2] * k[2][1];
    double c01 = k[1][2] * k[2][0] - k[1][0] * k[2][2];
    double c02 = k[1][0] * k[2][1] - k[1][1] * k[2][0];
    double det = k[0][0] * c00 + k[0][1] * c01 + k[0][2] * c02;
    if (det == 0.0) {
        x[0] = x[1] = x[2] = 0.0;
        return;
    }
    double inv = 1.0 / det;
    x[0] = inv * (b[0] * c00 + b[1] * (k[0][2] * k[2][1] - k[0][1] * k[2][2]) +
                  b[2] * (k[0][1] * k[1][2] - k[0][2] * k[1][1]));
    x[1] = inv * (b[0] * c01 + b[1] * (k[0][0] * k[2][2] - k[0][2] * k[2][0]) +
                  b[2] * (k[0][2] * k[1][0] - k[0][0] * k[1][2]));
    x[2] = inv * (b[0] * c02 + b[1] * (k[0][1] * k[2][0] - k[0][0] * k[2][1]) +
                  b[2] * (k[0][0] * k[1][1] - k[0][1] * k[1][0]));
}

/* The position sweep past a limit: the point and the angle together (one
 * 3x3 block), since a correction of the angle alone moves the anchor off
 * the pin, which the point's correction then turns back. */
static void correct_at_limit(joint_t *joint, vector_t r1, vector_t r2, vector_t gap,
                             double angle_error) {
    double m = joint->m1 + joint->m2, i1 = joint->i1, i2 = joint->i2;
    double k[3][3];
    k[0][0] = m + i1 * r1.y * r1.y + i2 * r2.y * r2.y;
    k[0][1] = k[1][0] = -i1 * r1.x * r1.y - i2 * r2.x * r2.y;
    k[0][2] = k[2][0] = -i1 * r1.y - i2 * r2.y;
    k[1][1] = m + i1 * r1.x * r1.x + i2 * r2.x * r2.x;
    k[1][2] = k[2][1] = i1 * r1.x + i2 * r2.x;
    k[2][2] = i1 + i2;
    double c[3] = {gap.x, gap.y,
                   joint_clamp(angle_error, -JOINT_MAX_ANGULAR_CORRECTION,
                               JOINT_MAX_ANGULAR_CORRECTION)};
    double x[3];
    solve33(k, c, x);
    vector_t p = {-x[0], -x[1]};
    joint_displace(joint, p, vec_cross(r1, p) - x[2], vec_cross(r2, p) - x[2]);
}

static void solve_position(joint_t *joint) {
    const joint_def_t *def = &joint->def;
    if (def->enable_limit) {
        vector_t r1, r2, gap;
        double angle;
        joint_current(joint, &r1, &r2, &gap, &angle);
        if (angle < def->lower_angle) {
            correct_at_limit(joint, r1, r2, gap, angle - def->lower_angle);
            return;
        }
        if (angle > def->upper_angle) {
            correct_at_limit(joint, r1, r2, gap, angle - def->upper_angle);
            return;
        }
    }
    joint_correct_point(joint);
}

const joint_kind_t JOINT_REVOLUTE_KIND = {prepare, solve_velocity, solve_position};
