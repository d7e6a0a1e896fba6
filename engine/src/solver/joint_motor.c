/* The motor joint: body2 driven toward an offset and angle relative to
 * body1, closing a share of the error each step within a force and a
 * torque bound. */
#include "solver/joint_types.h"

static void prepare(joint_t *joint) {
    /* Between the centroids: the anchors are not read. */
    const body_t *b1 = joint->def.body1, *b2 = joint->def.body2;
    double angle1 = b1 != NULL ? b1->angle : 0.0;
    vector_t c1 = b1 != NULL ? b1->centroid : VEC_ZERO;
    joint->r1 = joint->r2 = VEC_ZERO;
    joint->delta = vec_subtract(vec_subtract(b2->centroid, c1),
                                vec_rotate(joint->def.linear_offset, angle1));
    joint->angle = b2->angle - angle1 - joint->def.angular_offset;
    joint_point_mass(joint, joint->r1, joint->r2, &joint->k11, &joint->k12, &joint->k22);
    joint->angular_mass = joint_inverse(joint->i1 + joint->i2);
    double l = joint->angle_impulse;
    joint_apply(joint, joint->point_impulse, l, l);
}

static void solve_velocity(joint_t *joint) {
    const joint_def_t *def = &joint->def;
    double rate = def->correction_factor / joint->dt;
    double spin = joint->rows.v2->w - joint->rows.v1->w;
    double old = joint->angle_impulse, bound = def->max_torque * joint->dt;
    double l = -joint->angular_mass * (spin + rate * joint->angle);
    joint->angle_impulse = joint_clamp(old + l, -bound, bound);
    l = joint->angle_impulse - old;
    joint_apply(joint, VEC_ZERO, l, l);

    vector_t cdot = vec_add(joint_relative_velocity(joint), vec_multiply(rate, joint->delta));
    vector_t p = vec_negate(joint_solve22(joint->k11, joint->k12, joint->k22, cdot));
    vector_t before = joint->point_impulse, total = vec_add(before, p);
    double force_bound = def->max_force * joint->dt, length = vec_get_length(total);
    if (length > force_bound) total = vec_multiply(force_bound / length, total);
    joint->point_impulse = total;
    joint_apply(joint, vec_subtract(total, before), 0.0, 0.0);
}

const joint_kind_t JOINT_MOTOR_KIND = {prepare, solve_velocity, NULL, NULL, NULL, NULL, NULL};
