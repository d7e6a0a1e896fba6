/* The prismatic joint (a slider): anchor2 held on body1's axis through
 * anchor1 and the relative angle held (one 2x2 block), with a motor and
 * speculative limits along the axis. */
#include "solver/joint_types.h"

static void block_mass(const joint_t *joint, double s1, double s2, double *k11, double *k12,
                       double *k22) {
    *k11 = joint->m1 + joint->m2 + joint->i1 * s1 * s1 + joint->i2 * s2 * s2;
    *k12 = joint->i1 * s1 + joint->i2 * s2;
    *k22 = joint->i1 + joint->i2;
    if (*k22 == 0.0) *k22 = 1.0; /* neither body turns: the angle row is idle */
}

static void prepare(joint_t *joint) {
    joint_line_terms(joint->delta, joint->r1, joint->r2, joint->axis, joint->perp, &joint->a1,
                     &joint->a2, &joint->s1, &joint->s2);
    joint->translation = vec_dot(joint->axis, joint->delta);
    joint->axial_mass = joint_inverse(joint->m1 + joint->m2 + joint->i1 * joint->a1 * joint->a1 +
                                      joint->i2 * joint->a2 * joint->a2);
    block_mass(joint, joint->s1, joint->s2, &joint->k11, &joint->k12, &joint->k22);
    if (!joint->def.enable_motor) joint->motor_impulse = 0.0;
    if (!joint->def.enable_limit) joint->lower_impulse = joint->upper_impulse = 0.0;
    joint_line_warm(joint, joint->motor_impulse + joint->lower_impulse - joint->upper_impulse,
                    joint->point_impulse.x, joint->angle_impulse);
}

static void solve_velocity(joint_t *joint) {
    const joint_def_t *def = &joint->def;
    if (def->enable_motor) {
        double rate = joint_line_rate(joint, joint->axis, joint->a1, joint->a2);
        double old = joint->motor_impulse, bound = def->max_motor_force * joint->dt;
        double impulse = joint->axial_mass * (def->motor_speed - rate);
        joint->motor_impulse = joint_clamp(old + impulse, -bound, bound);
        joint_line_push(joint, joint->axis, joint->a1, joint->a2, joint->motor_impulse - old);
    }
    if (def->enable_limit) joint_line_limits(joint);
    vector_t cdot = {joint_line_rate(joint, joint->perp, joint->s1, joint->s2),
                     joint->rows.v2->w - joint->rows.v1->w};
    vector_t impulse = vec_negate(joint_solve22(joint->k11, joint->k12, joint->k22, cdot));
    joint->point_impulse.x += impulse.x;
    joint->angle_impulse += impulse.y;
    joint_apply(joint, vec_multiply(impulse.x, joint->perp),
                impulse.x * joint->s1 + impulse.y, impulse.x * joint->s2 + impulse.y);
}

static void solve_position(joint_t *joint) {
    vector_t r1, r2, d;
    double angle;
    joint_current(joint, &r1, &r2, &d, &angle);
    vector_t axis = joint_turned(joint->axis, joint_pose(joint, true).turn);
    vector_t perp = vec_perpendicular(axis);
    double a1, a2, s1, s2, k11, k12, k22;
    joint_line_terms(d, r1, r2, axis, perp, &a1, &a2, &s1, &s2);
    block_mass(joint, s1, s2, &k11, &k12, &k22);
    vector_t c = {joint_clamp(vec_dot(perp, d), -JOINT_MAX_LINEAR_CORRECTION,
                              JOINT_MAX_LINEAR_CORRECTION),
                  joint_clamp(angle, -JOINT_MAX_ANGULAR_CORRECTION, JOINT_MAX_ANGULAR_CORRECTION)};
    vector_t impulse = vec_negate(joint_solve22(k11, k12, k22, c));
    joint_displace(joint, vec_multiply(impulse.x, perp), impulse.x * s1 + impulse.y,
                   impulse.x * s2 + impulse.y);
    if (joint->def.enable_limit) joint_correct_line_limits(joint, axis, perp);
}

/* The tree takes a slider without a motor or limits: across the axis and
 * the angle. */
static int tree_rows(const joint_t *joint, joint_pose_t p1, joint_pose_t p2, double error[],
                     double j1[][3], double j2[][3]) {
    if (joint->def.enable_motor || joint->def.enable_limit) return 0;
    joint_tree_across(joint, p1, p2, &error[0], j1 != NULL ? j1[0] : NULL,
                      j2 != NULL ? j2[0] : NULL);
    error[1] = p2.angle - p1.angle - joint->def.reference_angle;
    if (j1 != NULL) joint_tree_angle(j1[1], j2[1]);
    return 2;
}

static void tree_add(joint_t *joint, const double impulse[]) {
    joint->point_impulse.x += impulse[0];
    joint->angle_impulse += impulse[1];
}

const joint_kind_t JOINT_PRISMATIC_KIND = {prepare,   solve_velocity, solve_position,
                                           NULL, tree_rows, NULL, tree_add};
