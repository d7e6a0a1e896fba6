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

/* The most Newton steps of the tree's projection after the bound on the
 * step's corrections (joint_solver_project), which stop once every row's
 * error is within JOINT_TREE_TOLERANCE (m or rad). The bound reopens what
 * the passes closed in a chain whipping at 1/60 s (links turning 1 rad a
 * step): 7e-5 m are left after two steps, 1e-9 after three, rounding after
 * four. */
static const int JOINT_TREE_FINAL_STEPS = 4;
static const double JOINT_TREE_TOLERANCE = 1e-12;

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
    return body == NULL ? (joint_pose_t){VEC_ZERO, 0.0}
                        : (joint_pose_t){body->centroid, body->angle};
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
        carry_impulses(joint, dt, settings->warm_starting);
        take_geometry(joint);
        joint->closes_gap = joint->weight > 0.0 && slow_turn(joint, joint->rows.v1, joint->spin1) &&
                            slow_turn(joint, joint->rows.v2, joint->spin2);
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

/* Minus what the velocity iterations drive to zero on a joint's tree
 * rows: soft rows' rates with their bias; while a rigid joint closes its
 * gap (closes_gap), the rate that closes within the step the change of
 * the rows' errors the step predicts for the velocities now, as a sweep of
 * the joint does (the error the step starts with is the position pass's);
 * otherwise the rows' rates. */
static void velocity_error(const joint_t *joint, const joint_tree_t *tree, double *rhs) {
    const joint_tree_block_t *block = joint_tree_block(tree, joint->tree_edge);
    double c[JOINT_TREE_ROWS][JOINT_TREE_ROWS], bias[JOINT_TREE_ROWS] = {0.0, 0.0, 0.0};
    bool soft = soft_rows(joint, c, bias);
    if (!soft && joint->closes_gap) {
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
        const joint_t *joint = step->joints[i];
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

/* One Newton step of the tree's rows toward their positions, or none when
 * they are there (returns whether it took one): the rows'
 * errors and derivatives at the poses the position pass has reached,
 * factored there (the step's start is off by the step's turn: a chain
 * whipping at 60 rad/s at 1/60 s turns its links by 1 rad a step, and
 * steps on the start's slope flung it apart), then the displacements that
 * zero the errors, each bounded to JOINT_MAX_LINEAR_CORRECTION (m or rad)
 * so that a joint pulled far apart closes over several steps. */
static bool project_tree(const joint_step_t *step, const solver_bodies_t *bodies) {
    joint_tree_t *tree = step->tree;
    double largest = 0.0;
    for (size_t i = 0; i < step->count; i++) {
        const joint_t *joint = step->joints[i];
        if (!in_tree(joint)) continue;
        joint_tree_block_t *block = joint_tree_rows(tree, joint->tree_edge);
        double *rhs = joint_tree_rhs(tree, joint->tree_edge);
        kind_of(joint)->tree_rows(joint, joint_pose(joint, true), joint_pose(joint, false), rhs,
                                  block->j1, block->j2);
        double c[JOINT_TREE_ROWS][JOINT_TREE_ROWS], bias[JOINT_TREE_ROWS];
        if (soft_rows(joint, c, bias)) { /* a spring: no position correction */
            memset(block->j1, 0, sizeof block->j1);
            memset(block->j2, 0, sizeof block->j2);
            memset(rhs, 0, sizeof(double) * JOINT_TREE_ROWS);
        }
        for (int r = 0; r < block->rows; r++) {
            largest = fmax(largest, fabs(rhs[r]));
            rhs[r] = -joint_clamp(rhs[r], -JOINT_MAX_LINEAR_CORRECTION,
                                  JOINT_MAX_LINEAR_CORRECTION);
        }
    }
    if (largest <= JOINT_TREE_TOLERANCE) return false;
    joint_tree_factor(tree, bodies->velocities);
    joint_tree_solve(tree);
    for (size_t k = 0; k < joint_tree_body_count(tree); k++) {
        solver_displacement_t *row = &bodies->displacements[joint_tree_body_row(tree, k)];
        const double *change = joint_tree_body_change(tree, k);
        row->dx = vec_add(row->dx, (vector_t){change[0], change[1]});
        row->dtheta += change[2];
    }
    return true;
}

void joint_solver_correct(const joint_step_t *step, const solver_bodies_t *bodies) {
    for (int sweep = 0; sweep < JOINT_POSITION_SWEEPS; sweep++) {
        for (size_t i = 0; i < step->count; i++) {
            joint_t *joint = step->joints[i];
            const joint_kind_t *kind = kind_of(joint);
            if (swept(joint) && kind->solve_position != NULL) kind->solve_position(joint);
        }
    }
    if (step->tree->edge_count > 0) project_tree(step, bodies);
}

void joint_solver_project(const joint_step_t *step, const solver_bodies_t *bodies) {
    for (int newton = 0; newton < JOINT_TREE_FINAL_STEPS && step->tree->edge_count > 0; newton++) {
        if (!project_tree(step, bodies)) return;
    }
}
