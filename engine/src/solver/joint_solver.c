#include "solver/joint_solver.h"
#include <math.h>

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

/* Whether the body of the row turns by at most `most` (rad) in the step at
 * its angular velocity now. */
static bool slow_turn(const joint_t *joint, const solver_velocity_t *row, double spin,
                      double most) {
    return fabs(joint->dt * (spin + joint->weight * row->w)) <= most;
}

/* Whether the joint's rigid rows close the gap the step would end with
 * (joint_types.h's JOINT_EXACT_TURN; the tree's exact solve converges
 * on the predicted gap at turns up to JOINT_TREE_EXACT_TURN). */
static bool closes_gap(const joint_t *joint, double most) {
    return joint->weight > 0.0 && slow_turn(joint, joint->rows.v1, joint->spin1, most) &&
           slow_turn(joint, joint->rows.v2, joint->spin2, most);
}
static const double JOINT_TREE_EXACT_TURN = 10.0;

/* Position sweeps of the joints per position iteration of the contacts:
 * a chain passes its correction one link per sweep, and joints are few
 * beside contacts, so they get more (a 20-link chain swinging at 1/240 s
 * stretched 0.44% with one, 0.16% with four). */
static const int JOINT_POSITION_SWEEPS = 4;

/* Newton steps of the tree's position projection per position pass. */
static const int JOINT_TREE_NEWTON_STEPS = 4;

/* The tree's row of a joint's body: the world and static bodies are
 * ground. */
static uint32_t tree_row(const body_t *body, const solver_bodies_t *bodies) {
    if (body == NULL || solver_row_is_static(&bodies->velocities[body->solver_index])) {
        return JOINT_TREE_GROUND;
    }
    return (uint32_t)body->solver_index;
}

/* Offers the joint's rigid rows to the tree; notes its edge. */
static void offer_to_tree(joint_t *joint, joint_tree_t *tree, const solver_bodies_t *bodies) {
    const joint_kind_t *kind = kind_of(joint);
    joint_tree_block_t block = {0};
    if (kind->tree_rows == NULL) return;
    block.rows = kind->tree_rows(joint, block.j1, block.j2);
    block.row1 = tree_row(joint->def.body1, bodies);
    block.row2 = tree_row(joint->def.body2, bodies);
    if (block.rows == 0 || (block.row1 == JOINT_TREE_GROUND && block.row2 == JOINT_TREE_GROUND)) {
        return;
    }
    joint->tree_edge = joint_tree_add(tree, &block);
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
        joint->closes_gap = closes_gap(joint, JOINT_EXACT_TURN);
        kind_of(joint)->prepare(joint);
        offer_to_tree(joint, step->tree, bodies);
        if (joint->tree_edge != JOINT_TREE_NONE) {
            joint->closes_gap = closes_gap(joint, JOINT_TREE_EXACT_TURN);
        }
    }
    if (step->tree->edge_count > 0) joint_tree_factor(step->tree, bodies->velocities);
}

static bool swept(const joint_t *joint) {
    return joint->active && joint->tree_edge == JOINT_TREE_NONE;
}

/* One solve of the tree for each joint's rows' errors (error reads them):
 * the impulses that zero them, applied to the joints' accumulated impulses
 * when `accumulate`, and the bodies' changes, returned by the tree. */
static void solve_tree(const joint_step_t *step,
                       void (*error_of)(const joint_kind_t *, const joint_t *, double *),
                       bool accumulate) {
    joint_tree_t *tree = step->tree;
    for (size_t i = 0; i < step->count; i++) {
        const joint_t *joint = step->joints[i];
        if (!joint->active || joint->tree_edge == JOINT_TREE_NONE) continue;
        double error[JOINT_TREE_ROWS];
        error_of(kind_of(joint), joint, error);
        double *rhs = joint_tree_rhs(tree, joint->tree_edge);
        for (int r = 0; r < JOINT_TREE_ROWS; r++) rhs[r] = -error[r];
    }
    joint_tree_solve(tree);
    if (!accumulate) return;
    for (size_t i = 0; i < step->count; i++) {
        joint_t *joint = step->joints[i];
        if (!joint->active || joint->tree_edge == JOINT_TREE_NONE) continue;
        kind_of(joint)->tree_add(joint, joint_tree_impulse(tree, joint->tree_edge));
    }
}

static void velocity_error(const joint_kind_t *kind, const joint_t *joint, double *error) {
    error[0] = error[1] = error[2] = 0.0;
    kind->tree_velocity_error(joint, error);
}

static void position_error(const joint_kind_t *kind, const joint_t *joint, double *error) {
    error[0] = error[1] = error[2] = 0.0;
    kind->tree_position_error(joint, error);
}

void joint_solver_iterate(const joint_step_t *step, const solver_bodies_t *bodies) {
    for (size_t i = 0; i < step->count; i++) {
        joint_t *joint = step->joints[i];
        if (swept(joint)) kind_of(joint)->solve_velocity(joint);
    }
    joint_tree_t *tree = step->tree;
    if (tree->edge_count == 0) return;
    solve_tree(step, velocity_error, true);
    for (size_t k = 0; k < joint_tree_body_count(tree); k++) {
        solver_velocity_t *row = &bodies->velocities[joint_tree_body_row(tree, k)];
        const double *change = joint_tree_body_change(tree, k);
        row->v = vec_add(row->v, (vector_t){change[0], change[1]});
        row->w += change[2];
    }
}

void joint_solver_correct(const joint_step_t *step, const solver_bodies_t *bodies) {
    for (int sweep = 0; sweep < JOINT_POSITION_SWEEPS; sweep++) {
        for (size_t i = 0; i < step->count; i++) {
            joint_t *joint = step->joints[i];
            const joint_kind_t *kind = kind_of(joint);
            if (swept(joint) && kind->solve_position != NULL) kind->solve_position(joint);
        }
    }
    joint_tree_t *tree = step->tree;
    for (int newton = 0; newton < JOINT_TREE_NEWTON_STEPS && tree->edge_count > 0; newton++) {
        solve_tree(step, position_error, false);
        for (size_t k = 0; k < joint_tree_body_count(tree); k++) {
            solver_displacement_t *row = &bodies->displacements[joint_tree_body_row(tree, k)];
            const double *change = joint_tree_body_change(tree, k);
            row->dx = vec_add(row->dx, (vector_t){change[0], change[1]});
            row->dtheta += change[2];
        }
    }
}
