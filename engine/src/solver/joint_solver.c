#include "solver/joint_solver.h"
#include <math.h>
#include <string.h>

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

/* The tree's position projection (joint_solver_project): at most
 * JOINT_TREE_NEWTON_STEPS Newton steps, stopping once every row is within
 * JOINT_TREE_TOLERANCE (m or rad) of its position; a step that makes the
 * largest error worse is halved up to JOINT_TREE_HALVINGS times. On the
 * 20-link chains of the tests one or two steps reach rounding; eight, the
 * halvings and the sweeps after them (see there) kept a 100-link chain
 * swinging from the horizontal at 1/60 s whole. */
static const int JOINT_TREE_NEWTON_STEPS = 8;
static const double JOINT_TREE_TOLERANCE = 1e-12;
static const int JOINT_TREE_HALVINGS = 4;

/* Position sweeps of the joints the tree does not take, per position
 * iteration of the contacts: a chain of them passes its correction one
 * link per sweep, and joints are few beside contacts, so they get more. */
static const int JOINT_POSITION_SWEEPS = 4;

/* The tree's row of a joint's body: the world and static bodies are
 * ground. */
static uint32_t tree_row(const body_t *body, const solver_bodies_t *bodies) {
    if (body == NULL || solver_row_is_static(&bodies->velocities[body->solver_index])) {
        return JOINT_TREE_GROUND;
    }
    return (uint32_t)body->solver_index;
}

/* A body's pose at the start of the step; the world's is the origin. */
static joint_pose_t start_pose(const body_t *body) {
    return body == NULL ? (joint_pose_t){VEC_ZERO, 0.0, 0.0}
                        : (joint_pose_t){body->centroid, body->angle, 0.0};
}

/* Whether the joint's tree rows are soft this step; then their compliance
 * and velocity bias. */
static bool soft_rows(const joint_t *joint, double c[][JOINT_TREE_ROWS], double *bias) {
    const joint_kind_t *kind = kind_of(joint);
    return kind->tree_soft != NULL && kind->tree_soft(joint, c, bias);
}

/* Offers the joint's equality rows at the step's start to the tree; notes
 * its edge. */
static void offer_to_tree(joint_t *joint, joint_tree_t *tree, const solver_bodies_t *bodies) {
    const joint_kind_t *kind = kind_of(joint);
    if (kind->tree_rows == NULL) return;
    joint_tree_block_t block = {0};
    block.row1 = tree_row(joint->def.body1, bodies);
    block.row2 = tree_row(joint->def.body2, bodies);
    if (block.row1 == JOINT_TREE_GROUND && block.row2 == JOINT_TREE_GROUND) return;
    double error[JOINT_TREE_ROWS];
    block.rows = kind->tree_rows(joint, start_pose(joint->def.body1),
                                 start_pose(joint->def.body2), error, block.j1, block.j2);
    soft_rows(joint, block.c, error);
    if (block.rows > 0) joint->tree_edge = joint_tree_add(tree, &block);
}

void joint_solver_prepare(const joint_step_t *step, const solver_bodies_t *bodies,
                          const solver_settings_t *settings) {
    double dt = settings->dt;
    joint_tree_reset(step->tree, bodies->body_count);
    for (size_t i = 0; i < step->count; i++) {
        joint_t *joint = step->joints[i];
        joint->active = in_step(joint->def.body1, bodies) && in_step(joint->def.body2, bodies);
        joint->tree_edge = JOINT_TREE_NONE;
        if (!joint->active) continue;
        take_rows(joint, joint->def.body1, bodies, true);
        take_rows(joint, joint->def.body2, bodies, false);
        joint->dt = dt;
        joint->weight = settings->position_weight;
        joint->closes_gap = joint->weight > 0.0 && slow_turn(joint, joint->rows.v1, joint->spin1) &&
                            slow_turn(joint, joint->rows.v2, joint->spin2);
        carry_impulses(joint, dt, settings->warm_starting);
        take_geometry(joint);
        kind_of(joint)->prepare(joint);
        offer_to_tree(joint, step->tree, bodies);
    }
    if (step->tree->edge_count > 0) joint_tree_factor(step->tree, bodies->velocities);
}

static bool swept(const joint_t *joint) {
    return joint->active && joint->tree_edge == JOINT_TREE_NONE;
}

static bool in_tree(const joint_t *joint) {
    return joint->active && joint->tree_edge != JOINT_TREE_NONE;
}

/* Whether the joint still closes its gap (closes_gap, decided at the
 * step's start): the exact solve can change a link's spin a lot within
 * the step, and past a turn of twice JOINT_EXACT_TURN the predicted gap's
 * linear part fed the spin from one iteration to the next (a 100-link
 * chain swinging at 1/60 s flew apart); the joint then keeps to its rates
 * for the rest of the step, so that it does not flip between the two. */
static bool still_closes_gap(joint_t *joint) {
    if (!joint->closes_gap) return false;
    double most = 2.0 * JOINT_EXACT_TURN;
    joint->closes_gap =
        fabs(joint->dt * (joint->spin1 + joint->weight * joint->rows.v1->w)) <= most &&
        fabs(joint->dt * (joint->spin2 + joint->weight * joint->rows.v2->w)) <= most;
    return joint->closes_gap;
}

/* Minus what the velocity iterations drive to zero on a joint's tree
 * rows: soft rows' rates with their bias; while a rigid joint closes its
 * gap (closes_gap), the rate that closes within the step the change of
 * the rows' errors the step predicts for the velocities now, as a sweep of
 * the joint does (the error the step starts with is the position pass's);
 * otherwise the rows' rates. */
static void velocity_error(joint_t *joint, const joint_tree_t *tree, double *rhs) {
    const joint_tree_block_t *block = joint_tree_block(tree, joint->tree_edge);
    double c[JOINT_TREE_ROWS][JOINT_TREE_ROWS], bias[JOINT_TREE_ROWS] = {0.0, 0.0, 0.0};
    bool soft = soft_rows(joint, c, bias);
    if (!soft && still_closes_gap(joint)) {
        double start[JOINT_TREE_ROWS], end[JOINT_TREE_ROWS];
        const joint_kind_t *kind = kind_of(joint);
        kind->tree_rows(joint, start_pose(joint->def.body1), start_pose(joint->def.body2), start,
                        NULL, NULL);
        kind->tree_rows(joint, joint_predicted(joint, true), joint_predicted(joint, false), end,
                        NULL, NULL);
        for (int r = 0; r < block->rows; r++) {
            rhs[r] = -(end[r] - start[r]) / (joint->dt * joint->weight);
        }
        return;
    }
    const solver_velocity_t *v1 = joint->rows.v1, *v2 = joint->rows.v2;
    for (int r = 0; r < block->rows; r++) {
        const double *a = block->j1[r], *b = block->j2[r];
        rhs[r] = -(a[0] * v1->v.x + a[1] * v1->v.y + a[2] * v1->w + b[0] * v2->v.x +
                   b[1] * v2->v.y + b[2] * v2->w + bias[r]);
    }
}

void joint_solver_iterate(const joint_step_t *step, const solver_bodies_t *bodies) {
    for (size_t i = 0; i < step->count; i++) {
        joint_t *joint = step->joints[i];
        if (swept(joint)) kind_of(joint)->solve_velocity(joint);
    }
    joint_tree_t *tree = step->tree;
    if (tree->edge_count == 0) return;
    for (size_t i = 0; i < step->count; i++) {
        joint_t *joint = step->joints[i];
        if (in_tree(joint)) velocity_error(joint, tree, joint_tree_rhs(tree, joint->tree_edge));
    }
    joint_tree_solve(tree);
    for (size_t i = 0; i < step->count; i++) {
        joint_t *joint = step->joints[i];
        if (in_tree(joint)) kind_of(joint)->tree_add(joint, joint_tree_impulse(tree, joint->tree_edge));
    }
    for (size_t k = 0; k < joint_tree_body_count(tree); k++) {
        solver_velocity_t *row = &bodies->velocities[joint_tree_body_row(tree, k)];
        const double *change = joint_tree_body_change(tree, k);
        row->v = vec_add(row->v, (vector_t){change[0], change[1]});
        row->w += change[2];
    }
}

/* The largest error of the tree's rigid rows at the poses reached (m or
 * rad); with `rows`, their derivatives there and, as right-hand sides,
 * minus the errors, each bounded to JOINT_MAX_LINEAR_CORRECTION so that a
 * joint pulled far apart closes over several steps. A soft weld's rows
 * are a spring's: no position correction (zero rows). */
static double tree_position_errors(const joint_step_t *step, bool rows) {
    joint_tree_t *tree = step->tree;
    double largest = 0.0;
    for (size_t i = 0; i < step->count; i++) {
        const joint_t *joint = step->joints[i];
        if (!in_tree(joint)) continue;
        joint_tree_block_t *block = joint_tree_rows(tree, joint->tree_edge);
        double error[JOINT_TREE_ROWS], j1[JOINT_TREE_ROWS][3], j2[JOINT_TREE_ROWS][3];
        double c[JOINT_TREE_ROWS][JOINT_TREE_ROWS], bias[JOINT_TREE_ROWS];
        kind_of(joint)->tree_rows(joint, joint_pose(joint, true), joint_pose(joint, false), error,
                                  j1, j2);
        bool soft = soft_rows(joint, c, bias);
        double *rhs = joint_tree_rhs(tree, joint->tree_edge);
        for (int r = 0; r < block->rows; r++) {
            if (soft) error[r] = 0.0, memset(j1[r], 0, sizeof j1[r]), memset(j2[r], 0, sizeof j2[r]);
            largest = fmax(largest, fabs(error[r]));
            if (!rows) continue;
            memcpy(block->j1[r], j1[r], sizeof j1[r]);
            memcpy(block->j2[r], j2[r], sizeof j2[r]);
            rhs[r] = -joint_clamp(error[r], -JOINT_MAX_LINEAR_CORRECTION,
                                  JOINT_MAX_LINEAR_CORRECTION);
        }
    }
    return largest;
}

static void displace_tree(const joint_step_t *step, const solver_bodies_t *bodies,
                          double share) {
    joint_tree_t *tree = step->tree;
    for (size_t k = 0; k < joint_tree_body_count(tree); k++) {
        solver_displacement_t *row = &bodies->displacements[joint_tree_body_row(tree, k)];
        const double *change = joint_tree_body_change(tree, k);
        row->dx = vec_add(row->dx, vec_multiply(share, (vector_t){change[0], change[1]}));
        row->dtheta += share * change[2];
    }
}

/* One Newton step of the tree's rigid rows toward their positions, or none
 * when they are there (returns whether it took one): factored at the poses
 * reached (the step's start is off by the step's turn: a chain whipping at
 * 60 rad/s at 1/60 s turns its links by 1 rad a step, and steps on the
 * start's slope flung it apart). So far from the rows' positions that the
 * step makes their largest error worse (the links of a 100-link chain
 * whipping at 1/60 s turning 0.8 rad a step), it is halved, up to
 * JOINT_TREE_HALVINGS times, and the rest is left to the next step. */
static bool project_tree(const joint_step_t *step, const solver_bodies_t *bodies) {
    joint_tree_t *tree = step->tree;
    double largest = tree_position_errors(step, true);
    if (largest <= JOINT_TREE_TOLERANCE) return false;
    joint_tree_factor(tree, bodies->velocities);
    joint_tree_solve(tree);
    displace_tree(step, bodies, 1.0);
    double share = 1.0;
    for (int halving = 0; halving < JOINT_TREE_HALVINGS; halving++) {
        if (tree_position_errors(step, false) <= largest) break;
        share *= 0.5;
        displace_tree(step, bodies, -share);
    }
    return true;
}

void joint_solver_correct(const joint_step_t *step) {
    for (int sweep = 0; sweep < JOINT_POSITION_SWEEPS; sweep++) {
        for (size_t i = 0; i < step->count; i++) {
            joint_t *joint = step->joints[i];
            const joint_kind_t *kind = kind_of(joint);
            if (swept(joint) && kind->solve_position != NULL) kind->solve_position(joint);
        }
    }
}

void joint_solver_project(const joint_step_t *step, const solver_bodies_t *bodies) {
    if (step->tree->edge_count == 0) return;
    for (int newton = 0; newton < JOINT_TREE_NEWTON_STEPS; newton++) {
        if (!project_tree(step, bodies)) return;
    }
    if (tree_position_errors(step, false) <= JOINT_TREE_TOLERANCE) return;
    /* Far from their positions (a 100-link chain whipping at 1/60 s, its
     * links turning 0.8 rad a step), Newton steps on the whole tree come
     * too slowly, and gaps they left grew step by step until the chain
     * fell apart; the sweeps, one joint at a time, shrink every gap. */
    for (int sweep = 0; sweep < JOINT_POSITION_SWEEPS; sweep++) {
        for (size_t i = 0; i < step->count; i++) {
            joint_t *joint = step->joints[i];
            const joint_kind_t *kind = kind_of(joint);
            if (in_tree(joint) && kind->solve_position != NULL) kind->solve_position(joint);
        }
    }
}

/* The tree's rows made to hold at the velocities, with their derivatives
 * at the poses the position pass has reached: not accumulated (the next
 * step starts from these velocities). A soft weld's rows are a spring's
 * (zero rows). */
static void settle_tree(const joint_step_t *step, const solver_bodies_t *bodies) {
    joint_tree_t *tree = step->tree;
    for (size_t i = 0; i < step->count; i++) {
        const joint_t *joint = step->joints[i];
        if (!in_tree(joint)) continue;
        joint_tree_block_t *block = joint_tree_rows(tree, joint->tree_edge);
        double error[JOINT_TREE_ROWS], c[JOINT_TREE_ROWS][JOINT_TREE_ROWS], bias[JOINT_TREE_ROWS];
        kind_of(joint)->tree_rows(joint, joint_pose(joint, true), joint_pose(joint, false), error,
                                  block->j1, block->j2);
        if (soft_rows(joint, c, bias)) {
            memset(block->j1, 0, sizeof block->j1);
            memset(block->j2, 0, sizeof block->j2);
        }
        const solver_velocity_t *v1 = joint->rows.v1, *v2 = joint->rows.v2;
        double *rhs = joint_tree_rhs(tree, joint->tree_edge);
        for (int r = 0; r < block->rows; r++) {
            const double *a = block->j1[r], *b = block->j2[r];
            rhs[r] = -(a[0] * v1->v.x + a[1] * v1->v.y + a[2] * v1->w + b[0] * v2->v.x +
                       b[1] * v2->v.y + b[2] * v2->w);
        }
    }
    joint_tree_factor(tree, bodies->velocities);
    joint_tree_solve(tree);
    for (size_t k = 0; k < joint_tree_body_count(tree); k++) {
        solver_velocity_t *row = &bodies->velocities[joint_tree_body_row(tree, k)];
        const double *change = joint_tree_body_change(tree, k);
        row->v = vec_add(row->v, (vector_t){change[0], change[1]});
        row->w += change[2];
    }
}

/* A rigid joint that closed its gap this step did so with an impulse P
 * that moves its bodies by w dt M^-1 P (w, the scheme's position weight),
 * and so changed their velocities by all of M^-1 P, 1 / w times what the
 * same move takes under RATTLE's half kick (velocity Verlet with
 * constraints: the position constraint's impulse enters the positions
 * through the first half kick only). The rest, (1 - w) M^-1 P, is taken
 * back before the end velocities are settled: left in, it pushes along
 * the anchors' direction at the start, which the settle (along the one at
 * the end) does not fully cancel, and swings gained energy every step (a
 * double pendulum under the seed scheme from 0 to 120 J in 30 s, m g L
 * 9.8 J; now within 1e-3 J). Done here for the tree's rigid rows, whose
 * impulses are then all the joint stores (its warm start applies them);
 * a pin outside the tree, which has limits or a motor beside its point,
 * takes back its point's share in its own settle (joint_revolute.c). */
static void take_back_kick(joint_t *joint) {
    if (!in_tree(joint) || !joint->closes_gap || joint->weight >= 1.0) return;
    double share = -(1.0 - joint->weight);
    double c[JOINT_TREE_ROWS][JOINT_TREE_ROWS], bias[JOINT_TREE_ROWS];
    if (soft_rows(joint, c, bias)) return;
    vector_t point = joint->point_impulse;
    double angle = joint->angle_impulse, axial = joint->axial_impulse;
    joint->point_impulse = vec_multiply(share, point);
    joint->angle_impulse = share * angle;
    joint->axial_impulse = share * axial;
    kind_of(joint)->prepare(joint);
    joint->point_impulse = point;
    joint->angle_impulse = angle;
    joint->axial_impulse = axial;
}

void joint_solver_settle(const joint_step_t *step, const solver_bodies_t *bodies) {
    for (size_t i = 0; i < step->count; i++) {
        if (step->joints[i]->active) take_back_kick(step->joints[i]);
    }
    for (size_t i = 0; i < step->count; i++) {
        joint_t *joint = step->joints[i];
        const joint_kind_t *kind = kind_of(joint);
        if (swept(joint) && kind->settle_velocity != NULL) kind->settle_velocity(joint);
    }
    if (step->tree->edge_count > 0) settle_tree(step, bodies);
}

/* A row of the step's bodies: not the joint's own row for the world. */
static void mark_row(const solver_bodies_t *bodies, const solver_displacement_t *row,
                     uint8_t *held) {
    if (row >= bodies->displacements && row < bodies->displacements + bodies->body_count) {
        held[row - bodies->displacements] = 1;
    }
}

void joint_solver_mark_held(const joint_step_t *step, const solver_bodies_t *bodies,
                            uint8_t *held) {
    for (size_t i = 0; i < step->count; i++) {
        const joint_t *joint = step->joints[i];
        if (!joint->active) continue;
        mark_row(bodies, joint->rows.d1, held);
        mark_row(bodies, joint->rows.d2, held);
    }
}
