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

static void solve_position(joint_t *joint) {
    const joint_def_t *def = &joint->def;
    if (def->enable_limit) {
        vector_t r1, r2, gap;
        double angle;
        joint_current(joint, &r1, &r2, &gap, &angle);
        if (angle < def->lower_angle) {
            joint_correct_block(joint, r1, r2, gap, angle - def->lower_angle);
            return;
        }
        if (angle > def->upper_angle) {
            joint_correct_block(joint, r1, r2, gap, angle - def->upper_angle);
            return;
        }
    }
    joint_correct_point(joint);
}

/* RATTLE's half kick for the pin's point, as the tree's rows have it
 * (joint_solver.c): while the sweeps close the gap, the point impulse P
 * moved the bodies by w dt M^-1 P but changed their velocities by all of
 * M^-1 P; left in, the (1 - w) share pushes along the arm's start
 * direction and a swing gains energy every step. Taken back just before
 * this pin's own settle, which gives back what the end pose needs, so a
 * pin at rest is left as it was. */
static void take_back_kick(joint_t *joint) {
    if (!joint->closes_gap || joint->weight >= 1.0) return;
    vector_t p = vec_multiply(-(1.0 - joint->weight), joint->point_impulse);
    joint_apply(joint, p, vec_cross(joint->r1, p), vec_cross(joint->r2, p));
}

/* The pin's sweeps close the gap the step ends with, and where the scheme
 * moves a body by its start velocity too (weight < 1) that sets the
 * anchors' end relative velocity to their start one mirrored: any relative
 * velocity a contact or a limit left at a pin came back, reversed, every
 * step (a ragdoll's head on the floor kept swinging at 1.2 m/s). With the
 * displacements fixed, the end velocities are made to agree with the pin
 * at the pose the step ends in (as RATTLE does after SHAKE): no body moves,
 * nothing is left to mirror, and a link turning too fast for the gap rule
 * ends with velocities of its end pose, not its start one. Not carried into
 * the warm start: the next step starts from these velocities already. */
static void settle_velocity(joint_t *joint) {
    take_back_kick(joint);
    vector_t r1, r2, gap;
    double angle;
    joint_current(joint, &r1, &r2, &gap, &angle);
    double k11, k12, k22;
    joint_point_mass(joint, r1, r2, &k11, &k12, &k22);
    const solver_velocity_t *v1 = joint->rows.v1, *v2 = joint->rows.v2;
    vector_t rate = vec_subtract(vec_add(v2->v, vec_cross_scalar(v2->w, r2)),
                                 vec_add(v1->v, vec_cross_scalar(v1->w, r1)));
    vector_t p = vec_negate(joint_solve22(k11, k12, k22, rate));
    joint_apply(joint, p, vec_cross(r1, p), vec_cross(r2, p));
}

/* The tree takes the point of a pin without a motor or limits. */
static int tree_rows(const joint_t *joint, joint_pose_t p1, joint_pose_t p2, double error[],
                     double j1[][3], double j2[][3]) {
    if (joint->def.enable_motor || joint->def.enable_limit) return 0;
    vector_t r1, r2, gap = joint_separation(joint, p1, p2, &r1, &r2);
    error[0] = gap.x, error[1] = gap.y;
    if (j1 != NULL) joint_tree_point(j1, j2, r1, r2);
    return 2;
}

static void tree_add(joint_t *joint, const double impulse[]) {
    joint->point_impulse = vec_add(joint->point_impulse, (vector_t){impulse[0], impulse[1]});
}

const joint_kind_t JOINT_REVOLUTE_KIND = {prepare,         solve_velocity, solve_position,
                                          settle_velocity, tree_rows,      NULL,
                                          tree_add};
