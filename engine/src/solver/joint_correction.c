/* The position sweeps the rigid joints share (joint_types.h): each moves
 * the bodies' displacements, not their velocities, toward the constraint
 * at the poses the step has reached. */
#include "solver/joint_types.h"

void joint_current(const joint_t *joint, vector_t *r1, vector_t *r2, vector_t *delta,
                   double *angle) {
    joint_pose_t p1 = joint_pose(joint, true), p2 = joint_pose(joint, false);
    *r1 = joint_turned(joint->r1, p1.turn);
    *r2 = joint_turned(joint->r2, p2.turn);
    *delta = vec_subtract(vec_add(p2.centroid, *r2), vec_add(p1.centroid, *r1));
    *angle = p2.angle - p1.angle - joint->def.reference_angle;
}

void joint_correct_point(joint_t *joint) {
    vector_t r1, r2, c;
    double angle;
    joint_current(joint, &r1, &r2, &c, &angle);
    double length = vec_get_length(c);
    if (length > JOINT_MAX_LINEAR_CORRECTION) {
        c = vec_multiply(JOINT_MAX_LINEAR_CORRECTION / length, c);
    }
    double k11, k12, k22;
    joint_point_mass(joint, r1, r2, &k11, &k12, &k22);
    vector_t p = vec_negate(joint_solve22(k11, k12, k22, c));
    joint_displace(joint, p, vec_cross(r1, p), vec_cross(r2, p));
}

void joint_correct_angle(joint_t *joint, double target) {
    vector_t r1, r2, delta;
    double angle;
    joint_current(joint, &r1, &r2, &delta, &angle);
    double c = joint_clamp(angle - target, -JOINT_MAX_ANGULAR_CORRECTION,
                           JOINT_MAX_ANGULAR_CORRECTION);
    double l = -joint_inverse(joint->i1 + joint->i2) * c;
    joint_displace(joint, VEC_ZERO, l, l);
}

void joint_correct_axial(joint_t *joint, double c, vector_t direction, double a1, double a2) {
    if (c >= 0.0) return;
    c = c < -JOINT_MAX_LINEAR_CORRECTION ? -JOINT_MAX_LINEAR_CORRECTION : c;
    double k = joint->m1 + joint->m2 + joint->i1 * a1 * a1 + joint->i2 * a2 * a2;
    double impulse = -joint_inverse(k) * c;
    joint_displace(joint, vec_multiply(impulse, direction), impulse * a1, impulse * a2);
}

/* Solves the 3x3 symmetric K x = b by Cramer's rule; a singular K
 * gives 0. */
void joint_solve33(const double k[3][3], const double b[3], double x[3]) {
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

void joint_block_mass(const joint_t *joint, vector_t r1, vector_t r2, double k[3][3]) {
    double m = joint->m1 + joint->m2, i1 = joint->i1, i2 = joint->i2;
    k[0][0] = m + i1 * r1.y * r1.y + i2 * r2.y * r2.y;
    k[0][1] = k[1][0] = -i1 * r1.x * r1.y - i2 * r2.x * r2.y;
    k[0][2] = k[2][0] = -i1 * r1.y - i2 * r2.y;
    k[1][1] = m + i1 * r1.x * r1.x + i2 * r2.x * r2.x;
    k[1][2] = k[2][1] = i1 * r1.x + i2 * r2.x;
    k[2][2] = i1 + i2;
}

void joint_correct_block(joint_t *joint, vector_t r1, vector_t r2, vector_t gap,
                             double angle_error) {
    double k[3][3];
    joint_block_mass(joint, r1, r2, k);
    double c[3] = {gap.x, gap.y,
                   joint_clamp(angle_error, -JOINT_MAX_ANGULAR_CORRECTION,
                               JOINT_MAX_ANGULAR_CORRECTION)};
    double x[3];
    joint_solve33(k, c, x);
    vector_t p = {-x[0], -x[1]};
    joint_displace(joint, p, vec_cross(r1, p) - x[2], vec_cross(r2, p) - x[2]);
}

