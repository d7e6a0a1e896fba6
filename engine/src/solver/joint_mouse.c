/* The mouse joint: anchor2 pulled toward a world target by an implicit
 * spring on body2 alone, its force bounded. */
#include "solver/joint_types.h"

static void prepare(joint_t *joint) {
    /* body1 takes no part: the target is fixed in the world. */
    joint->m1 = joint->i1 = 0.0;
    joint->r1 = VEC_ZERO;
    joint->rows.v1 = &joint->ground_velocity;
    joint->rows.d1 = &joint->ground_displacement;
    joint->ground_velocity = (solver_velocity_t){VEC_ZERO, 0.0, 0.0, 0.0};
    const body_t *b2 = joint->def.body2;
    joint->delta = vec_subtract(vec_add(b2->centroid, joint->r2), joint->def.target);
    joint_point_mass(joint, joint->r1, joint->r2, &joint->k11, &joint->k12, &joint->k22);
    joint->soft = joint_make_soft(joint->def.frequency, joint->def.damping_ratio, joint->dt);
    vector_t p = joint->point_impulse;
    joint_apply(joint, p, 0.0, vec_cross(joint->r2, p));
}

static void solve_velocity(joint_t *joint) {
    const joint_soft_t *soft = &joint->soft;
    vector_t cdot = vec_add(joint_relative_velocity(joint),
                            vec_multiply(soft->bias_rate, joint->delta));
    vector_t rigid = joint_solve22(joint->k11, joint->k12, joint->k22, cdot);
    vector_t p = vec_subtract(vec_multiply(-soft->mass_scale, rigid),
                              vec_multiply(soft->impulse_scale, joint->point_impulse));
    vector_t old = joint->point_impulse;
    vector_t total = vec_add(old, p);
    double bound = joint->def.max_force * joint->dt, length = vec_get_length(total);
    if (length > bound) total = vec_multiply(bound / length, total);
    joint->point_impulse = total;
    p = vec_subtract(total, old);
    joint_apply(joint, p, 0.0, vec_cross(joint->r2, p));
}

const joint_kind_t JOINT_MOUSE_KIND = {prepare, solve_velocity, NULL, NULL, NULL, NULL, NULL};
