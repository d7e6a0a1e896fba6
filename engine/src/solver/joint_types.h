#ifndef JOINT_TYPES_H
#define JOINT_TYPES_H

/*
 * A joint as the solver and the scene see it (jostle/joint.h is the public
 * contract): its definition, the rows of its bodies for the step, what
 * preparing found, and the impulses it accumulates, which the next step
 * starts from (warm starting). Each type's file (joint_revolute.c, ...)
 * prepares and solves its own; joint_solver.c runs them in order.
 */

#include <stdbool.h>
#include "jostle/joint.h"
#include "dynamics/body_private.h"
#include "solver/joint_tree.h"
#include "solver/solver_types.h"

/* A soft constraint's coefficients for a step (an implicit spring of
 * frequency f and damping ratio z on the constraint's effective mass):
 * the velocity bias per metre (or radian) of error, and the shares of the
 * rigid impulse and of the accumulated impulse a sweep applies. */
typedef struct {
    double bias_rate, mass_scale, impulse_scale;
} joint_soft_t;

/* The rows a joint's sweep reads and writes: its two bodies' velocity and
 * displacement rows, or, for the world (body1 NULL) and a static body left
 * out, a row of the joint's own with zero inverse mass. */
typedef struct {
    solver_velocity_t *v1, *v2;
    solver_displacement_t *d1, *d2;
} joint_rows_t;

struct joint {
    joint_def_t def;
    struct scene *scene;
    /* Whether this step solves it (both bodies in the step, none removed). */
    bool active;
    /* Its edge in the step's tree solve (joint_tree.h), or JOINT_TREE_NONE
     * when the sweeps solve it. */
    uint32_t tree_edge;
    joint_rows_t rows;
    solver_velocity_t ground_velocity;
    solver_displacement_t ground_displacement;
    /* Inverse masses and inertias as the rows give them. */
    double m1, m2, i1, i2;
    /* At the start of the step: the lever arms from the centroids to the
     * anchors (world orientation), anchor2 less anchor1, the relative angle
     * less the reference, and the world axis and its perpendicular. */
    vector_t r1, r2, delta;
    double angle;
    vector_t axis, perp;
    /* Where the step takes each body for end velocities v, w: by dt
     * (drift + weight v) and dt (spin + weight w) (integrator.h). */
    vector_t drift1, drift2;
    double spin1, spin2, weight;
    /* Whether this step's rigid sweeps close the gap the step would end
     * with (joint_closing_rate): while neither body turns by more than
     * JOINT_EXACT_TURN over the step. */
    bool closes_gap;
    double translation; /* along the axis (prismatic, wheel) or between the anchors (distance) */
    double dt;
    /* Prepared: effective masses (the point block's K as k11, k12, k22) and
     * the soft coefficients. */
    double k11, k12, k22;
    double axial_mass, angular_mass, motor_mass;
    double a1, a2, s1, s2; /* lever terms along the axis and its perpendicular */
    joint_soft_t soft;
    /* Accumulated impulses (N s, N m s) of the last step solved; their
     * step's length. */
    vector_t point_impulse;
    double angle_impulse, axial_impulse, spring_impulse, motor_impulse;
    double lower_impulse, upper_impulse;
    double impulse_dt;
};

/* A body's pose: where the step has it at some point (its start, its
 * predicted end, the position sweeps' current pose); turn is how far
 * that is turned from the body's angle at the start (angle less it). */
typedef struct {
    vector_t centroid;
    double angle, turn;
} joint_pose_t;

/* v turned by a step's turn (rad). A step turns a body by little, and the
 * anchors are turned again at every sweep (sine and cosine were 45% of a
 * ragdoll pile's instructions), so up to a quarter turn the Taylor series
 * stand in for them, to within an ulp (1.1e-16 measured); beyond, the
 * library's. */
static inline vector_t joint_turned(vector_t v, double turn) {
    if (turn == 0.0) return v;
    if (fabs(turn) > 0.25) return vec_rotate(v, turn);
    double t2 = turn * turn;
    double c = 1.0 + t2 * (-1.0 / 2 + t2 * (1.0 / 24 + t2 * (-1.0 / 720 + t2 * (1.0 / 40320 +
                   t2 * (-1.0 / 3628800 + t2 * (1.0 / 479001600))))));
    double s = turn * (1.0 + t2 * (-1.0 / 6 + t2 * (1.0 / 120 + t2 * (-1.0 / 5040 +
                   t2 * (1.0 / 362880 + t2 * (-1.0 / 39916800 + t2 * (1.0 / 6227020800)))))));
    return vec_rotate_cs(v, c, s);
}

/* Each type's part: prepare (lever arms and rows are set; also applies
 * the warm-start impulses), one velocity sweep, one position sweep (NULL
 * for the soft types, which correct through their bias), and the end
 * velocities made consistent once the step's displacements are fixed
 * (NULL where the velocity sweep already targets the rate).
 *
 * And its part in the tree solve (joint_tree.h; NULL for the mouse and
 * motor joints, which it never takes): tree_rows gives how many equality
 * rows the joint has (0 when it has a spring, a limit, a motor or a force
 * bound, and stays in the sweeps), their errors (m, rad) with body1 and
 * body2 at poses p1 and p2, and, unless j1 is NULL, their derivatives
 * there by each body's displacement (dx, dy, dtheta), which are also the
 * rows' terms on its velocity (vx, vy, w). tree_soft (NULL when the type
 * has no soft rows) says whether the rows are soft this step and then
 * gives their compliance C and velocity bias (with C times the
 * accumulated impulses). tree_add adds a solve's impulses to the
 * accumulated ones. */
typedef struct {
    void (*prepare)(joint_t *joint);
    void (*solve_velocity)(joint_t *joint);
    void (*solve_position)(joint_t *joint);
    void (*settle_velocity)(joint_t *joint);
    int (*tree_rows)(const joint_t *joint, joint_pose_t p1, joint_pose_t p2, double error[],
                     double j1[][3], double j2[][3]);
    bool (*tree_soft)(const joint_t *joint, double c[][JOINT_TREE_ROWS], double bias[]);
    void (*tree_add)(joint_t *joint, const double impulse[]);
} joint_kind_t;

extern const joint_kind_t JOINT_REVOLUTE_KIND, JOINT_DISTANCE_KIND, JOINT_MOUSE_KIND,
    JOINT_WELD_KIND, JOINT_PRISMATIC_KIND, JOINT_WHEEL_KIND, JOINT_MOTOR_KIND;

/* The largest correction (m, rad) one position sweep makes, so a joint
 * pulled far apart closes over several steps instead of flinging its
 * bodies. */
static const double JOINT_MAX_LINEAR_CORRECTION = 0.2;
static const double JOINT_MAX_ANGULAR_CORRECTION = 0.15;

static inline double joint_clamp(double x, double lo, double hi) {
    return x < lo ? lo : (x > hi ? hi : x);
}

/* The soft coefficients of frequency (Hz) and damping ratio for step dt;
 * all zero for frequency 0 (rigid). */
static inline joint_soft_t joint_make_soft(double frequency, double damping_ratio, double dt) {
    if (frequency == 0.0) return (joint_soft_t){0.0, 1.0, 0.0};
    double omega = 2.0 * M_PI * frequency;
    double a1 = 2.0 * damping_ratio + dt * omega;
    double a2 = dt * omega * a1;
    double a3 = 1.0 / (1.0 + a2);
    return (joint_soft_t){omega / a1, a2 * a3, a3};
}

/* Applies impulse p at the anchors (+ to body2, - to body1) with angular
 * parts l1, l2 (the torques' impulses on body1 and body2). */
static inline void joint_apply(joint_t *joint, vector_t p, double l1, double l2) {
    solver_velocity_t *v1 = joint->rows.v1, *v2 = joint->rows.v2;
    v1->v = vec_subtract(v1->v, vec_multiply(joint->m1, p));
    v1->w -= joint->i1 * l1;
    v2->v = vec_add(v2->v, vec_multiply(joint->m2, p));
    v2->w += joint->i2 * l2;
}

/* The same on the displacement rows (position sweeps). */
static inline void joint_displace(joint_t *joint, vector_t p, double l1, double l2) {
    solver_displacement_t *d1 = joint->rows.d1, *d2 = joint->rows.d2;
    d1->dx = vec_subtract(d1->dx, vec_multiply(joint->m1, p));
    d1->dtheta -= joint->i1 * l1;
    d2->dx = vec_add(d2->dx, vec_multiply(joint->m2, p));
    d2->dtheta += joint->i2 * l2;
}

/* The velocity of anchor2 relative to anchor1 (m/s). */
static inline vector_t joint_relative_velocity(const joint_t *joint) {
    const solver_velocity_t *v1 = joint->rows.v1, *v2 = joint->rows.v2;
    return vec_subtract(vec_add(v2->v, vec_cross_scalar(v2->w, joint->r2)),
                        vec_add(v1->v, vec_cross_scalar(v1->w, joint->r1)));
}

/* The pose of the joint's body (body1 when first) within the step; the
 * world's is the origin. */
static inline joint_pose_t joint_pose(const joint_t *joint, bool first) {
    const body_t *body = first ? joint->def.body1 : joint->def.body2;
    const solver_displacement_t *d = first ? joint->rows.d1 : joint->rows.d2;
    if (body == NULL) return (joint_pose_t){VEC_ZERO, 0.0, 0.0};
    return (joint_pose_t){vec_add(body->centroid, d->dx), body->angle + d->dtheta, d->dtheta};
}

/* The pose the step ends at if the rows' velocities are the end ones. */
static inline joint_pose_t joint_predicted(const joint_t *joint, bool first) {
    const body_t *body = first ? joint->def.body1 : joint->def.body2;
    if (body == NULL) return (joint_pose_t){VEC_ZERO, 0.0, 0.0};
    const solver_velocity_t *v = first ? joint->rows.v1 : joint->rows.v2;
    vector_t drift = first ? joint->drift1 : joint->drift2;
    double spin = first ? joint->spin1 : joint->spin2, w = joint->weight, dt = joint->dt;
    double turn = dt * (spin + w * v->w);
    return (joint_pose_t){vec_add(body->centroid, vec_multiply(dt, vec_add(drift,
                                                                          vec_multiply(w, v->v)))),
                          body->angle + turn, turn};
}

/* How far the step moves anchor2 from anchor1 (m) and turns the joint
 * (rad) if the rows' velocities now are the end ones: the change over the
 * step, not the gap it starts with, which the position sweep closes (fed
 * to the velocities, that gap made a 1:100 load on a chain blow up). A
 * rigid joint's velocity sweep drives these to zero, so the step ends on
 * the constraint (to the rotation's second order, which the position
 * sweep takes) rather than drifting off it by the centripetal term every
 * step, which a sweep on the velocities alone would leave to the position
 * sweep and so take out of the kinetic energy. */
static inline vector_t joint_predicted_gap(const joint_t *joint, double *angle) {
    joint_pose_t p1 = joint_predicted(joint, true), p2 = joint_predicted(joint, false);
    if (angle != NULL) *angle = p2.angle - p1.angle - joint->def.reference_angle - joint->angle;
    vector_t end = vec_subtract(vec_add(p2.centroid, joint_turned(joint->r2, p2.turn)),
                                vec_add(p1.centroid, joint_turned(joint->r1, p1.turn)));
    return vec_subtract(end, joint->delta);
}

/* The velocity that closes a predicted gap within the step: gap / (dt
 * weight); or, for a scheme whose positions do not see this step's
 * velocity (weight 0), the rate itself. */
static inline double joint_closing_rate(const joint_t *joint, double gap, double rate) {
    return joint->closes_gap ? gap / (joint->dt * joint->weight) : rate;
}

/* The largest turn of a body over a step (rad) at which the rigid sweeps
 * close the predicted gap; past it they cancel the anchors' relative
 * velocity only, and the position sweep closes the gap (dissipating as the
 * centripetal term goes). The predicted gap is not linear in the angular
 * velocity: at a fast turn (links of a chain spinning at 30 rad/s at 1/60
 * s) the sweeps' linear solve overshoots and feeds the spin until the
 * chain flies apart. */
static const double JOINT_EXACT_TURN = 0.05;

/* A tree row's terms for a rate along direction u with lever terms l1,
 * l2 (u . (v2 - v1) + l2 w2 - l1 w1); the point's x and y rows for lever
 * arms r1, r2; the relative angle's row. */
static inline void joint_tree_line(double j1[3], double j2[3], vector_t u, double l1, double l2) {
    j1[0] = -u.x, j1[1] = -u.y, j1[2] = -l1;
    j2[0] = u.x, j2[1] = u.y, j2[2] = l2;
}

static inline void joint_tree_point(double j1[][3], double j2[][3], vector_t r1, vector_t r2) {
    joint_tree_line(j1[0], j2[0], (vector_t){1.0, 0.0}, -r1.y, -r2.y);
    joint_tree_line(j1[1], j2[1], (vector_t){0.0, 1.0}, r1.x, r2.x);
}

static inline void joint_tree_angle(double j1[3], double j2[3]) {
    joint_tree_line(j1, j2, VEC_ZERO, 1.0, 1.0);
}

/* The lever arms and anchor separation (anchor2 - anchor1) of the joint
 * with its bodies at poses p1, p2. */
static inline vector_t joint_separation(const joint_t *joint, joint_pose_t p1, joint_pose_t p2,
                                        vector_t *r1, vector_t *r2) {
    *r1 = joint_turned(joint->r1, p1.turn);
    *r2 = joint_turned(joint->r2, p2.turn);
    return vec_subtract(vec_add(p2.centroid, *r2), vec_add(p1.centroid, *r1));
}

/* Solves the 2x2 symmetric K x = b. A singular K gives 0. */
static inline vector_t joint_solve22(double k11, double k12, double k22, vector_t b) {
    double det = k11 * k22 - k12 * k12;
    if (det != 0.0) det = 1.0 / det;
    return (vector_t){det * (k22 * b.x - k12 * b.y), det * (k11 * b.y - k12 * b.x)};
}

/* The point block's K for lever arms r1, r2. */
static inline void joint_point_mass(const joint_t *joint, vector_t r1, vector_t r2, double *k11,
                                    double *k12, double *k22) {
    double m = joint->m1 + joint->m2;
    *k11 = m + joint->i1 * r1.y * r1.y + joint->i2 * r2.y * r2.y;
    *k12 = -joint->i1 * r1.x * r1.y - joint->i2 * r2.x * r2.y;
    *k22 = m + joint->i1 * r1.x * r1.x + joint->i2 * r2.x * r2.x;
}

/* 1 / k, or 0 for k 0 (a direction in which neither body can move). */
static inline double joint_inverse(double k) {
    return k > 0.0 ? 1.0 / k : 0.0;
}

/* Position sweep of a rigid point constraint (revolute, weld, prismatic
 * share it): moves the anchors together along the line between them. */
void joint_correct_point(joint_t *joint);
/* Position sweep of the relative angle toward target (rad). */
void joint_correct_angle(joint_t *joint, double target);
/* Position sweep of a one-sided limit along a world direction at the
 * current poses: error c (< 0 violates), lever terms a1, a2. */
void joint_correct_axial(joint_t *joint, double c, vector_t direction, double a1, double a2);
/* The point and angle block (revolute at a limit, weld): its 3x3 K for
 * lever arms r1, r2 (rows: x, y, angle); K x = b solved by Cramer's rule
 * (a singular K gives 0); and its position sweep toward gap 0 and angle
 * error 0 together, since a correction of the angle alone moves the
 * anchors apart, which the point's correction then turns back. */
void joint_block_mass(const joint_t *joint, vector_t r1, vector_t r2, double k[3][3]);
void joint_solve33(const double k[3][3], const double b[3], double x[3]);
void joint_correct_block(joint_t *joint, vector_t r1, vector_t r2, vector_t gap,
                         double angle_error);
/* The current lever arms and anchor separation (anchor2 - anchor1) at the
 * position sweep's poses. */
void joint_current(const joint_t *joint, vector_t *r1, vector_t *r2, vector_t *delta,
                   double *angle);

/* Velocity sweep of a speculative limit along the constraint's axial
 * direction: c the distance to the limit at the step's start (>= 0
 * allowed), cdot its rate; returns the impulse (>= 0 accumulated in
 * *accumulated) to apply along the direction that opens the limit. */
static inline double joint_limit_impulse(double mass, double c, double cdot, double dt,
                                         double *accumulated) {
    double bias = c > 0.0 ? c / dt : 0.0;
    double impulse = -mass * (cdot + bias);
    double old = *accumulated;
    *accumulated = old + impulse > 0.0 ? old + impulse : 0.0;
    return *accumulated - old;
}

/* A line joint's lever terms (prismatic, wheel): for anchor separation d
 * and lever arms r1, r2, the rates of the translation along axis and
 * across it (perp) are axis . (v2 - v1) + a2 w2 - a1 w1 and the same with
 * s1, s2 (body1's frame turns the axis with it). */
static inline void joint_line_terms(vector_t d, vector_t r1, vector_t r2, vector_t axis,
                                    vector_t perp, double *a1, double *a2, double *s1,
                                    double *s2) {
    vector_t arm = vec_add(d, r1);
    *a1 = vec_cross(arm, axis);
    *a2 = vec_cross(r2, axis);
    *s1 = vec_cross(arm, perp);
    *s2 = vec_cross(r2, perp);
}

/* The rate along a line direction with lever terms l1, l2. */
static inline double joint_line_rate(const joint_t *joint, vector_t direction, double l1,
                                     double l2) {
    const solver_velocity_t *v1 = joint->rows.v1, *v2 = joint->rows.v2;
    return vec_dot(direction, vec_subtract(v2->v, v1->v)) + l2 * v2->w - l1 * v1->w;
}

/* An impulse along a line direction with lever terms l1, l2. */
static inline void joint_line_push(joint_t *joint, vector_t direction, double l1, double l2,
                                   double impulse) {
    joint_apply(joint, vec_multiply(impulse, direction), impulse * l1, impulse * l2);
}

/* A line joint's warm start: impulses along the axis and across it, and
 * an angular impulse turning both bodies. */
static inline void joint_line_warm(joint_t *joint, double axial, double across, double turn) {
    vector_t p = vec_add(vec_multiply(axial, joint->axis), vec_multiply(across, joint->perp));
    joint_apply(joint, p, axial * joint->a1 + across * joint->s1 + turn,
                axial * joint->a2 + across * joint->s2 + turn);
}

/* A line joint's tree row across its axis (slider, wheel) at poses p1,
 * p2: its error and, unless j1 is NULL, its terms. */
static inline void joint_tree_across(const joint_t *joint, joint_pose_t p1, joint_pose_t p2,
                                     double *error, double j1[3], double j2[3]) {
    vector_t r1, r2, d = joint_separation(joint, p1, p2, &r1, &r2);
    vector_t axis = joint_turned(joint->axis, p1.turn);
    vector_t perp = vec_perpendicular(axis);
    *error = vec_dot(perp, d);
    if (j1 == NULL) return;
    double a1, a2, s1, s2;
    joint_line_terms(d, r1, r2, axis, perp, &a1, &a2, &s1, &s2);
    joint_tree_line(j1, j2, perp, s1, s2);
}

/* The position sweep's limits along a line (axis, and perp across it),
 * at the pose the sweeps have reached: the translation kept in [lower,
 * upper]. */
static inline void joint_correct_line_limits(joint_t *joint, vector_t axis, vector_t perp) {
    vector_t r1, r2, d;
    double angle, a1, a2, s1, s2;
    joint_current(joint, &r1, &r2, &d, &angle);
    joint_line_terms(d, r1, r2, axis, perp, &a1, &a2, &s1, &s2);
    double t = vec_dot(axis, d);
    joint_correct_axial(joint, t - joint->def.lower_translation, axis, a1, a2);
    joint_correct_axial(joint, joint->def.upper_translation - t, vec_negate(axis), -a1, -a2);
}

/* The velocity sweep's limits along the line (speculative). */
static inline void joint_line_limits(joint_t *joint) {
    double rate = joint_line_rate(joint, joint->axis, joint->a1, joint->a2);
    joint_line_push(joint, joint->axis, joint->a1, joint->a2,
                    joint_limit_impulse(joint->axial_mass,
                                        joint->translation - joint->def.lower_translation, rate,
                                        joint->dt, &joint->lower_impulse));
    rate = joint_line_rate(joint, joint->axis, joint->a1, joint->a2);
    joint_line_push(joint, joint->axis, joint->a1, joint->a2,
                    -joint_limit_impulse(joint->axial_mass,
                                         joint->def.upper_translation - joint->translation, -rate,
                                         joint->dt, &joint->upper_impulse));
}

#endif // #ifndef JOINT_TYPES_H
