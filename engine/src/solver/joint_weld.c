/* The weld joint: the point and the relative angle held, rigidly (with
 * position correction) or as implicit springs of the joint's frequency. */
#include "solver/joint_types.h"

static void prepare(joint_t *joint) {
    joint_point_mass(joint, joint->r1, joint->r2, &joint->k11, &joint->k12, &joint->k22);
    joint->angular_mass = joint_inverse(joint->i1 + joint->i2);
    joint->soft = joint_make_soft(joint->def.frequency, joint->def.damping_ratio, joint->dt);
    vector_t p = joint->point_impulse;
    double l = joint->angle_impulse;
    joint_apply(joint, p, vec_cross(joint->r1, p) + l, vec_cross(joint->r2, p) + l);
}

/* Rigid: the point and the angle as one 3x3 block, which a cantilever of
 * welds needs (solved one after the other, a ten-box beam folded). */
static void solve_rigid(joint_t *joint) {
    double k[3][3], x[3];
    joint_block_mass(joint, joint->r1, joint->r2, k);
    vector_t rate = joint_relative_velocity(joint);
    double b[3] = {rate.x, rate.y, joint->rows.v2->w - joint->rows.v1->w};
    joint_solve33(k, b, x);
    vector_t p = {-x[0], -x[1]};
    joint->point_impulse = vec_add(joint->point_impulse, p);
    joint->angle_impulse -= x[2];
    joint_apply(joint, p, vec_cross(joint->r1, p) - x[2], vec_cross(joint->r2, p) - x[2]);
}

static void solve_velocity(joint_t *joint) {
    if (joint->def.frequency == 0.0) {
        solve_rigid(joint);
        return;
    }
    const joint_soft_t *soft = &joint->soft;
    double spin = joint->rows.v2->w - joint->rows.v1->w;
    double l = -soft->mass_scale * joint->angular_mass * (spin + soft->bias_rate * joint->angle) -
               soft->impulse_scale * joint->angle_impulse;
    joint->angle_impulse += l;
    joint_apply(joint, VEC_ZERO, l, l);

    vector_t cdot = vec_add(joint_relative_velocity(joint),
                            vec_multiply(soft->bias_rate, joint->delta));
    vector_t rigid = joint_solve22(joint->k11, joint->k12, joint->k22, cdot);
    vector_t p = vec_subtract(vec_multiply(-soft->mass_scale, rigid),
                              vec_multiply(soft->impulse_scale, joint->point_impulse));
    joint->point_impulse = vec_add(joint->point_impulse, p);
    joint_apply(joint, p, vec_cross(joint->r1, p), vec_cross(joint->r2, p));
}

static void solve_position(joint_t *joint) {
    if (joint->def.frequency > 0.0) return;
    vector_t r1, r2, gap;
    double angle;
    joint_current(joint, &r1, &r2, &gap, &angle);
    joint_correct_block(joint, r1, r2, gap, angle);
}

/* The tree takes a weld's point and angle, rigid or soft. */
static int tree_rows(const joint_t *joint, joint_pose_t p1, joint_pose_t p2, double error[],
                     double j1[][3], double j2[][3]) {
    vector_t r1, r2, gap = joint_separation(joint, p1, p2, &r1, &r2);
    error[0] = gap.x, error[1] = gap.y;
    error[2] = p2.angle - p1.angle - joint->def.reference_angle;
    if (j1 != NULL) {
        joint_tree_point(j1, j2, r1, r2);
        joint_tree_angle(j1[2], j2[2]);
    }
    return 3;
}

/* A soft weld's rows: with compliance C = K is / ms (K the weld's own
 * blocks, is and ms its soft coefficients), (K + C) dl = -(J v + b + C l)
 * is its sweep's step dl = -ms K^-1 (J v + b) - is l; the tree solves it
 * with the whole tree's K in place of the weld's own. */
static bool tree_soft(const joint_t *joint, double c[][JOINT_TREE_ROWS], double bias[]) {
    if (joint->def.frequency == 0.0) return false;
    const joint_soft_t *soft = &joint->soft;
    double share = soft->impulse_scale / soft->mass_scale;
    double k[3][3] = {{joint->k11, joint->k12, 0.0},
                      {joint->k12, joint->k22, 0.0},
                      {0.0, 0.0, joint->i1 + joint->i2}};
    double impulse[3] = {joint->point_impulse.x, joint->point_impulse.y, joint->angle_impulse};
    double error[3] = {joint->delta.x, joint->delta.y, joint->angle};
    for (int r = 0; r < 3; r++) {
        bias[r] = soft->bias_rate * error[r];
        for (int k2 = 0; k2 < 3; k2++) {
            c[r][k2] = share * k[r][k2];
            bias[r] += c[r][k2] * impulse[k2];
        }
    }
    return true;
}

static void tree_add(joint_t *joint, const double impulse[]) {
    joint->point_impulse = vec_add(joint->point_impulse, (vector_t){impulse[0], impulse[1]});
    joint->angle_impulse += impulse[2];
}

const joint_kind_t JOINT_WELD_KIND = {prepare,   solve_velocity, solve_position,
                                      NULL, tree_rows, tree_soft, tree_add};
