/* The wheel joint: anchor2 held on body1's axis through anchor1 (the
 * suspension's line), an implicit spring along it toward translation 0,
 * speculative limits along it, and a motor turning body2. */
#include "solver/joint_types.h"

static void prepare(joint_t *joint) {
    const joint_def_t *def = &joint->def;
    joint_line_terms(joint->delta, joint->r1, joint->r2, joint->axis, joint->perp, &joint->a1,
                     &joint->a2, &joint->s1, &joint->s2);
    joint->translation = vec_dot(joint->axis, joint->delta);
    joint->axial_mass = joint_inverse(joint->m1 + joint->m2 + joint->i1 * joint->a1 * joint->a1 +
                                      joint->i2 * joint->a2 * joint->a2);
    joint->k11 = joint_inverse(joint->m1 + joint->m2 + joint->i1 * joint->s1 * joint->s1 +
                               joint->i2 * joint->s2 * joint->s2);
    joint->motor_mass = joint_inverse(joint->i1 + joint->i2);
    joint->soft = joint_make_soft(def->frequency, def->damping_ratio, joint->dt);
    if (def->frequency == 0.0) joint->spring_impulse = 0.0;
    if (!def->enable_motor) joint->motor_impulse = 0.0;
    if (!def->enable_limit) joint->lower_impulse = joint->upper_impulse = 0.0;
    joint_line_warm(joint, joint->spring_impulse + joint->lower_impulse - joint->upper_impulse,
                    joint->point_impulse.x, joint->motor_impulse);
}

static void solve_velocity(joint_t *joint) {
    const joint_def_t *def = &joint->def;
    if (def->enable_motor) {
        double spin = joint->rows.v2->w - joint->rows.v1->w;
        double old = joint->motor_impulse, bound = def->max_motor_torque * joint->dt;
        double impulse = -joint->motor_mass * (spin - def->motor_speed);
        joint->motor_impulse = joint_clamp(old + impulse, -bound, bound);
        impulse = joint->motor_impulse - old;
        joint_apply(joint, VEC_ZERO, impulse, impulse);
    }
    if (def->frequency > 0.0) {
        const joint_soft_t *soft = &joint->soft;
        double rate = joint_line_rate(joint, joint->axis, joint->a1, joint->a2);
        double impulse = -soft->mass_scale * joint->axial_mass *
                             (rate + soft->bias_rate * joint->translation) -
                         soft->impulse_scale * joint->spring_impulse;
        joint->spring_impulse += impulse;
        joint_line_push(joint, joint->axis, joint->a1, joint->a2, impulse);
    }
    if (def->enable_limit) joint_line_limits(joint);
    double rate = joint_line_rate(joint, joint->perp, joint->s1, joint->s2);
    double impulse = -joint->k11 * rate;
    joint->point_impulse.x += impulse;
    joint_line_push(joint, joint->perp, joint->s1, joint->s2, impulse);
}

static void solve_position(joint_t *joint) {
    vector_t r1, r2, d;
    double angle;
    joint_current(joint, &r1, &r2, &d, &angle);
    vector_t axis = joint_turned(joint->axis, joint_pose(joint, true).turn);
    vector_t perp = vec_perpendicular(axis);
    double a1, a2, s1, s2;
    joint_line_terms(d, r1, r2, axis, perp, &a1, &a2, &s1, &s2);
    double c = vec_dot(perp, d);
    if (c > 0.0) {
        joint_correct_axial(joint, -c, vec_negate(perp), -s1, -s2);
    } else {
        joint_correct_axial(joint, c, perp, s1, s2);
    }
    if (joint->def.enable_limit) joint_correct_line_limits(joint, axis, perp);
}

/* The tree takes a wheel without a spring, a motor or limits: its row
 * across the axis. */
static int tree_rows(const joint_t *joint, joint_pose_t p1, joint_pose_t p2, double error[],
                     double j1[][3], double j2[][3]) {
    const joint_def_t *def = &joint->def;
    if (def->frequency > 0.0 || def->enable_motor || def->enable_limit) return 0;
    joint_tree_across(joint, p1, p2, &error[0], j1 != NULL ? j1[0] : NULL,
                      j2 != NULL ? j2[0] : NULL);
    return 1;
}

static void tree_add(joint_t *joint, const double impulse[]) {
    joint->point_impulse.x += impulse[0];
}

const joint_kind_t JOINT_WHEEL_KIND = {prepare,   solve_velocity, solve_position,
                                       NULL, tree_rows, NULL, tree_add};
