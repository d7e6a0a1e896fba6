#include "dynamics/integrator.h"
#include <math.h>
#include <string.h>
#include "dynamics/body_private.h"
#include "base/check.h"
#include "dynamics/implicit_euler.h"
#include "base/memory.h"

double integrator_position_weight(integrator_t integrator) {
    switch (integrator) {
    /* A constant force over the step moves a body by half its velocity
     * change times dt in every scheme that follows constant forces exactly;
     * contacts act as such a force. */
    case INTEGRATOR_SEED:
    case INTEGRATOR_VELOCITY_VERLET:
    case INTEGRATOR_RK4:
    case INTEGRATOR_SYMPLECTIC4: return 0.5;
    case INTEGRATOR_EXPLICIT_EULER: return 0.0;
    case INTEGRATOR_SYMPLECTIC_EULER:
    case INTEGRATOR_IMPLICIT_EULER: return 1.0;
    }
    engine_fail(__func__, "unknown integrator %d", (int)integrator);
}

const char *integrator_get_name(integrator_t integrator) {
    switch (integrator) {
    case INTEGRATOR_SEED: return "seed";
    case INTEGRATOR_EXPLICIT_EULER: return "explicit Euler";
    case INTEGRATOR_SYMPLECTIC_EULER: return "symplectic Euler";
    case INTEGRATOR_VELOCITY_VERLET: return "velocity Verlet";
    case INTEGRATOR_RK4: return "RK4";
    case INTEGRATOR_SYMPLECTIC4: return "symplectic4";
    case INTEGRATOR_IMPLICIT_EULER: return "implicit Euler";
    }
    engine_fail(__func__, "unknown integrator %d", (int)integrator);
}

double integrator_get_stability_limit(integrator_t integrator) {
    switch (integrator) {
    case INTEGRATOR_SEED:
    case INTEGRATOR_EXPLICIT_EULER: return 0.0;
    case INTEGRATOR_SYMPLECTIC_EULER:
    case INTEGRATOR_VELOCITY_VERLET: return 2.0;
    case INTEGRATOR_RK4: return 2.0 * sqrt(2.0);
    /* Where the trace of its oscillator matrix reaches -2 (bisection). */
    case INTEGRATOR_SYMPLECTIC4: return 1.5734019474345387;
    case INTEGRATOR_IMPLICIT_EULER: return INFINITY;
    }
    engine_fail(__func__, "unknown integrator %d", (int)integrator);
}

double integrator_get_drag_limit(integrator_t integrator) {
    switch (integrator) {
    case INTEGRATOR_SEED:
    case INTEGRATOR_EXPLICIT_EULER:
    case INTEGRATOR_SYMPLECTIC_EULER:
    case INTEGRATOR_VELOCITY_VERLET: return 2.0;
    /* Where the quartic Taylor polynomial of e^-z reaches 1 (bisection). */
    case INTEGRATOR_RK4: return 2.785293563405282;
    /* Where three Verlet steps of c z multiply v by -1 (bisection). */
    case INTEGRATOR_SYMPLECTIC4: return 1.3719235554837272;
    case INTEGRATOR_IMPLICIT_EULER: return INFINITY;
    }
    engine_fail(__func__, "unknown integrator %d", (int)integrator);
}

/* A 2x2 matrix acting on (x, v / omega) of an undamped oscillator. */
typedef struct {
    double a, b, c, d;
} matrix2_t;

static matrix2_t matrix2_multiply(matrix2_t m, matrix2_t n) {
    return (matrix2_t){m.a * n.a + m.b * n.c, m.a * n.b + m.b * n.d, m.c * n.a + m.d * n.c,
                       m.c * n.b + m.d * n.d};
}

/* Velocity Verlet over theta = omega h: kick, drift, kick. */
static matrix2_t verlet_matrix(double theta) {
    matrix2_t kick = {1.0, 0.0, -0.5 * theta, 1.0}, drift = {1.0, theta, 0.0, 1.0};
    return matrix2_multiply(kick, matrix2_multiply(drift, kick));
}

/* One step of the scheme on x'' = -omega^2 x with theta = omega h. */
static matrix2_t oscillator_matrix(integrator_t integrator, double theta) {
    double s = theta * theta;
    switch (integrator) {
    case INTEGRATOR_VELOCITY_VERLET: return verlet_matrix(theta);
    case INTEGRATOR_SYMPLECTIC4: {
        double cube_root = cbrt(2.0);
        double outer = 1.0 / (2.0 - cube_root), inner = -cube_root * outer;
        matrix2_t m = verlet_matrix(outer * theta);
        return matrix2_multiply(m, matrix2_multiply(verlet_matrix(inner * theta), m));
    }
    case INTEGRATOR_IMPLICIT_EULER: {
        /* x' = x + theta y', y' = y - theta x', solved for (x', y'). */
        double shrink = 1.0 / (1.0 + s);
        return (matrix2_t){shrink, shrink * theta, -shrink * theta, shrink};
    }
    case INTEGRATOR_RK4: {
        /* exp(theta J) to fourth order, J the rotation generator (J^2 = -1). */
        double cosine = 1.0 - s / 2.0 + s * s / 24.0, sine = theta - s * theta / 6.0;
        return (matrix2_t){cosine, sine, -sine, cosine};
    }
    default: {
        double w = integrator_position_weight(integrator);
        return (matrix2_t){1.0 - w * s, theta, -theta, 1.0};
    }
    }
}

double integrator_oscillator_growth(integrator_t integrator, double theta) {
    matrix2_t m = oscillator_matrix(integrator, theta);
    double trace = m.a + m.d, det = m.a * m.d - m.b * m.c;
    double discriminant = trace * trace - 4.0 * det;
    if (!isfinite(discriminant)) return INFINITY;
    /* Complex eigenvalues have |lambda|^2 = det. */
    if (discriminant < 0.0) return det;
    double radius = (fabs(trace) + sqrt(discriminant)) / 2.0;
    return radius * radius;
}

/* Position and angle, or their rates, of one body: the schemes treat the
 * three degrees of freedom alike. */
typedef struct {
    double x, y, angle;
} dof_t;

static inline dof_t dof_axpy(dof_t y, double a, dof_t x) {
    return (dof_t){y.x + a * x.x, y.y + a * x.y, y.angle + a * x.angle};
}

static inline dof_t dof_subtract(dof_t a, dof_t b) {
    return (dof_t){a.x - b.x, a.y - b.y, a.angle - b.angle};
}

/* A multi-stage scheme's record of one body over the step. */
typedef struct {
    dof_t external;    /* force and torque set before the step, at every stage */
    dof_t first_force; /* force and torque after the first evaluation */
    dof_t impulse;     /* linear and angular impulse of the first evaluation */
    dof_t velocity;    /* the body's own velocities at the start */
    dof_t q0, u0;      /* start pose; start velocities after the impulses */
    dof_t q, u;        /* the pose and velocities the next evaluation is at */
    dof_t a;           /* accelerations at the last evaluation */
    dof_t run;         /* Verlet's and Yoshida's velocities between kicks */
    dof_t sum_u, sum_a; /* RK4's weighted sums */
    /* The last evaluation of the step, for the next one to reuse: where the
     * body was, its mass and id, and the force and torque found there. */
    vector_t last_centroid;
    double last_mass;
    uint32_t last_id;
    dof_t last_force;
} stage_row_t;

struct integrator_stages {
    stage_row_t *rows;
    size_t capacity;
    /* How many bodies integrator_begin saw; later ones had no force set
     * before the step. */
    size_t begun;
    /* The reuse key and body count the rows' last evaluation was recorded
     * with; key 0 when there is none. */
    uint64_t last_key;
    size_t last_count;
    implicit_euler_t *implicit;
};

void integrator_stages_free(integrator_stages_t *stages) {
    if (stages == NULL) return;
    memory_free(stages->rows);
    implicit_euler_free(stages->implicit);
    memory_free(stages);
}

static void make_stages(integrator_stages_t **stages) {
    if (*stages == NULL) *stages = memory_calloc(1, sizeof(integrator_stages_t));
}

static void reserve_rows(integrator_stages_t **stages, size_t count) {
    make_stages(stages);
    memory_reserve((void **)&(*stages)->rows, &(*stages)->capacity, count, sizeof(stage_row_t));
}

/* Whether the schemes's last evaluation is at the pose its step ends at. */
static bool ends_where_it_evaluates(integrator_t integrator) {
    return integrator == INTEGRATOR_VELOCITY_VERLET || integrator == INTEGRATOR_SYMPLECTIC4;
}

static inline bool same_bits(double a, double b) {
    return memcmp(&a, &b, sizeof a) == 0;
}

/* Whether every body is where, and as, the last evaluation found it, with
 * the force and torque set since the same as the last step's. */
static bool unchanged_since_last(const integrator_stages_t *stages, body_t **bodies,
                                 size_t count) {
    for (size_t i = 0; i < count; i++) {
        const body_t *body = bodies[i];
        const stage_row_t *row = &stages->rows[i];
        if (body->id != row->last_id || !same_bits(body->centroid.x, row->last_centroid.x) ||
            !same_bits(body->centroid.y, row->last_centroid.y) ||
            !same_bits(body->mass, row->last_mass) ||
            !same_bits(body->force.x, row->external.x) ||
            !same_bits(body->force.y, row->external.y) ||
            !same_bits(body->torque, row->external.angle)) {
            return false;
        }
    }
    return true;
}

bool integrator_begin(integrator_t integrator, body_t **bodies, size_t count,
                      integrator_stages_t **stages, uint64_t reuse_key) {
    if (integrator_stage_count(integrator) == 1) return false;
    reserve_rows(stages, count);
    integrator_stages_t *s = *stages;
    bool reuse = reuse_key != 0 && s->last_key == reuse_key && s->last_count == count &&
                 ends_where_it_evaluates(integrator) && unchanged_since_last(s, bodies, count);
    s->last_key = 0;
    s->begun = count;
    if (reuse) {
        for (size_t i = 0; i < count; i++) {
            const dof_t *f = &s->rows[i].last_force;
            bodies[i]->force = (vector_t){f->x, f->y};
            bodies[i]->torque = f->angle;
        }
        return true;
    }
    for (size_t i = 0; i < count; i++) {
        const body_t *body = bodies[i];
        s->rows[i].external = (dof_t){body->force.x, body->force.y, body->torque};
    }
    return false;
}

/* After the scheme's last evaluation, with the bodies still where it put
 * them: what the next step's integrator_begin may reuse. */
static void record_last_evaluation(const integrator_step_t *step, integrator_stages_t *stages,
                                   body_t **bodies, size_t count) {
    if (step->reuse_key == 0 || step->evaluate == NULL ||
        !ends_where_it_evaluates(step->integrator)) {
        return;
    }
    for (size_t i = 0; i < count; i++) {
        const body_t *body = bodies[i];
        stage_row_t *row = &stages->rows[i];
        row->last_centroid = body->centroid;
        row->last_mass = body->mass;
        row->last_id = body->id;
        row->last_force = (dof_t){body->force.x, body->force.y, body->torque};
    }
    stages->last_key = step->reuse_key;
    stages->last_count = count;
}

/* The accelerations of a body under a force and torque and gravity; none
 * for a sleeping body, which rests on what holds it. */
static dof_t acceleration_under(const body_t *body, vector_t force, double torque,
                                vector_t gravity) {
    dof_t a = {0.0, 0.0, body->inverse_inertia * torque};
    if (body->asleep) return (dof_t){0.0, 0.0, 0.0};
    if (body->inverse_mass != 0.0) {
        a.x = body->inverse_mass * force.x + gravity.x;
        a.y = body->inverse_mass * force.y + gravity.y;
    }
    return a;
}

static dof_t acceleration_of(const body_t *body, vector_t gravity) {
    return acceleration_under(body, body->force, body->torque, gravity);
}

/* The free motion of the one-stage schemes: the velocity changes by the
 * force over dt and by the impulses, the position by the mean of the two
 * velocities weighted by w. */
static inline void predict_one_stage(const body_t *body, double dt, vector_t gravity, double w,
                              integrator_motion_t *motion) {
    dof_t a = acceleration_of(body, gravity);
    motion->acceleration = (vector_t){a.x, a.y};
    vector_t dv = vec_add(vec_multiply(dt, motion->acceleration),
                          vec_multiply(body->inverse_mass, body->impulse));
    motion->velocity = vec_add(body->velocity, dv);
    motion->angular_velocity = body->angular_velocity +
                               body->inverse_inertia * (dt * body->torque + body->angular_impulse);
    motion->drift = vec_multiply(1.0 - w, body->velocity);
    motion->spin_drift = (1.0 - w) * body->angular_velocity;
    motion->displacement =
        vec_multiply(dt, vec_add(motion->drift, vec_multiply(w, motion->velocity)));
    motion->rotation = dt * (motion->spin_drift + w * motion->angular_velocity);
    motion->inverse_mass = body->inverse_mass;
    motion->still = false;
}

/* Records each body's start and its first evaluation's forces. */
static void start_stages(stage_row_t *rows, size_t begun, body_t **bodies, size_t count,
                         vector_t gravity) {
    for (size_t i = 0; i < count; i++) {
        const body_t *body = bodies[i];
        stage_row_t *row = &rows[i];
        if (i >= begun) row->external = (dof_t){0.0, 0.0, 0.0};
        row->first_force = (dof_t){body->force.x, body->force.y, body->torque};
        row->impulse = (dof_t){body->impulse.x, body->impulse.y, body->angular_impulse};
        row->velocity = (dof_t){body->velocity.x, body->velocity.y, body->angular_velocity};
        row->q0 = (dof_t){body->centroid.x, body->centroid.y, body->angle};
        row->u0 = (dof_t){row->velocity.x + body->inverse_mass * body->impulse.x,
                          row->velocity.y + body->inverse_mass * body->impulse.y,
                          row->velocity.angle + body->inverse_inertia * body->angular_impulse};
        row->q = row->q0;
        row->u = row->u0;
        row->a = acceleration_of(body, gravity);
    }
}

/* Evaluates the forces with every body at its row's trial pose q and
 * velocities u and stores the accelerations in a. Impulses added here are
 * dropped: they act once, at the start of the step. Without force creators
 * the forces are those set before the step, constant over it. */
static void evaluate_stage(const integrator_step_t *step, body_t **bodies, stage_row_t *rows,
                           size_t count) {
    if (step->evaluate == NULL) {
        for (size_t i = 0; i < count; i++) {
            const dof_t *f = &rows[i].external;
            rows[i].a = acceleration_under(bodies[i], (vector_t){f->x, f->y}, f->angle,
                                           step->gravity);
        }
        return;
    }
    for (size_t i = 0; i < count; i++) {
        body_t *body = bodies[i];
        const stage_row_t *row = &rows[i];
        body->centroid = (vector_t){row->q.x, row->q.y};
        body->angle = row->q.angle;
        body->velocity = (vector_t){row->u.x, row->u.y};
        body->angular_velocity = row->u.angle;
        body->world_valid = false;
        body->force = (vector_t){row->external.x, row->external.y};
        body->torque = row->external.angle;
    }
    step->evaluate(step->context);
    for (size_t i = 0; i < count; i++) {
        body_t *body = bodies[i];
        rows[i].a = acceleration_of(body, step->gravity);
        body->impulse = (vector_t){rows[i].impulse.x, rows[i].impulse.y};
        body->angular_impulse = rows[i].impulse.angle;
    }
}

/* Puts every body back at its start with its first evaluation's forces. */
static void restore_start(const integrator_step_t *step, body_t **bodies, const stage_row_t *rows,
                          size_t count) {
    if (step->evaluate == NULL) return;
    for (size_t i = 0; i < count; i++) {
        body_t *body = bodies[i];
        const stage_row_t *row = &rows[i];
        body->centroid = (vector_t){row->q0.x, row->q0.y};
        body->angle = row->q0.angle;
        body->velocity = (vector_t){row->velocity.x, row->velocity.y};
        body->angular_velocity = row->velocity.angle;
        body->world_valid = false;
        body->force = (vector_t){row->first_force.x, row->first_force.y};
        body->torque = row->first_force.angle;
    }
}

/* Kick h/2, drift h, kick h/2 from row->run and row->q; the forces at the
 * end are evaluated at the drifted pose with the velocities predicted by a
 * full kick. */
static void verlet_step(const integrator_step_t *step, body_t **bodies, stage_row_t *rows,
                        size_t count, double h) {
    for (size_t i = 0; i < count; i++) {
        stage_row_t *row = &rows[i];
        row->run = dof_axpy(row->run, 0.5 * h, row->a);
        row->q = dof_axpy(row->q, h, row->run);
        row->u = dof_axpy(row->run, 0.5 * h, row->a);
    }
    evaluate_stage(step, bodies, rows, count);
    for (size_t i = 0; i < count; i++) rows[i].run = dof_axpy(rows[i].run, 0.5 * h, rows[i].a);
}

static void velocity_verlet(const integrator_step_t *step, body_t **bodies, stage_row_t *rows,
                            size_t count) {
    verlet_step(step, bodies, rows, count, step->dt);
}

/* Yoshida's fourth-order composition of three Verlet steps, the forces at
 * the end of one serving the start of the next. */
static void symplectic4(const integrator_step_t *step, body_t **bodies, stage_row_t *rows,
                        size_t count) {
    double cube_root = cbrt(2.0);
    double outer = 1.0 / (2.0 - cube_root), inner = -cube_root * outer;
    verlet_step(step, bodies, rows, count, outer * step->dt);
    verlet_step(step, bodies, rows, count, inner * step->dt);
    verlet_step(step, bodies, rows, count, outer * step->dt);
}

/* Stage k evaluates at q0 + c_k h u_(k-1), u0 + c_k h a_(k-1). */
static void rk4(const integrator_step_t *step, body_t **bodies, stage_row_t *rows,
                size_t count) {
    double h = step->dt;
    const double offsets[3] = {0.5, 0.5, 1.0}, weights[3] = {2.0, 2.0, 1.0};
    for (size_t i = 0; i < count; i++) {
        rows[i].sum_u = rows[i].u0;
        rows[i].sum_a = rows[i].a;
        rows[i].u = rows[i].u0;
    }
    for (int k = 0; k < 3; k++) {
        double c = offsets[k] * h;
        for (size_t i = 0; i < count; i++) {
            stage_row_t *row = &rows[i];
            row->q = dof_axpy(row->q0, c, row->u);
            row->u = dof_axpy(row->u0, c, row->a);
        }
        evaluate_stage(step, bodies, rows, count);
        for (size_t i = 0; i < count; i++) {
            stage_row_t *row = &rows[i];
            row->sum_u = dof_axpy(row->sum_u, weights[k], row->u);
            row->sum_a = dof_axpy(row->sum_a, weights[k], row->a);
        }
    }
    for (size_t i = 0; i < count; i++) {
        stage_row_t *row = &rows[i];
        row->q = dof_axpy(row->q0, h / 6.0, row->sum_u);
        row->run = dof_axpy(row->u0, h / 6.0, row->sum_a);
    }
}

/* The free motion from where a multi-stage scheme ended: pose q, velocity
 * run; w its position weight. */
static void finish_stages(const stage_row_t *row, double dt, double w,
                          integrator_motion_t *motion) {
    dof_t moved = dof_subtract(row->q, row->q0);
    motion->velocity = (vector_t){row->run.x, row->run.y};
    motion->angular_velocity = row->run.angle;
    motion->displacement = (vector_t){moved.x, moved.y};
    motion->rotation = moved.angle;
    motion->drift = (vector_t){moved.x / dt - w * row->run.x, moved.y / dt - w * row->run.y};
    motion->spin_drift = moved.angle / dt - w * row->run.angle;
    motion->acceleration = (vector_t){(row->run.x - row->u0.x) / dt, (row->run.y - row->u0.y) / dt};
}

void integrator_predict_range(const integrator_step_t *step, body_t **bodies,
                              integrator_motion_t *motions, size_t begin, size_t end) {
    double w = integrator_position_weight(step->integrator);
    for (size_t i = begin; i < end; i++) {
        BODY_PREFETCH_AWAKE(bodies, i + BODY_AHEAD, end);
        if (bodies[i]->asleep) {
            motions[i].still = true;
        } else {
            predict_one_stage(bodies[i], step->dt, step->gravity, w, &motions[i]);
        }
    }
}

void integrator_predict(const integrator_step_t *step, body_t **bodies, size_t count,
                        integrator_motion_t *motions, integrator_stages_t **stages) {
    if (integrator_stage_count(step->integrator) == 1) {
        integrator_predict_range(step, bodies, motions, 0, count);
        if (step->integrator == INTEGRATOR_IMPLICIT_EULER && step->jacobian_count > 0) {
            make_stages(stages);
            implicit_euler_correct(step, bodies, count, motions, &(*stages)->implicit);
        }
        return;
    }
    size_t begun = *stages != NULL ? (*stages)->begun : 0;
    reserve_rows(stages, count);
    stage_row_t *rows = (*stages)->rows;
    start_stages(rows, begun, bodies, count, step->gravity);
    for (size_t i = 0; i < count; i++) rows[i].run = rows[i].u0;
    switch (step->integrator) {
    case INTEGRATOR_VELOCITY_VERLET: velocity_verlet(step, bodies, rows, count); break;
    case INTEGRATOR_SYMPLECTIC4: symplectic4(step, bodies, rows, count); break;
    case INTEGRATOR_RK4: rk4(step, bodies, rows, count); break;
    default: engine_fail(__func__, "unknown integrator %d", (int)step->integrator);
    }
    record_last_evaluation(step, *stages, bodies, count);
    restore_start(step, bodies, rows, count);
    double w = integrator_position_weight(step->integrator);
    for (size_t i = 0; i < count; i++) {
        finish_stages(&rows[i], step->dt, w, &motions[i]);
        motions[i].inverse_mass = bodies[i]->inverse_mass;
        motions[i].still = false;
    }
    (*stages)->begun = 0;
}

void integrator_respond(const integrator_step_t *step, body_t **bodies,
                        integrator_motion_t *motions, integrator_stages_t *stages) {
    if (step->integrator != INTEGRATOR_IMPLICIT_EULER || stages == NULL) return;
    implicit_euler_respond(step, bodies, motions, stages->implicit);
}

static inline void apply_motion(body_t *body, const integrator_motion_t *motion) {
    /* A body that did not move keeps its cached world polygon (walls). */
    if (motion->displacement.x != 0.0 || motion->displacement.y != 0.0 || motion->rotation != 0.0) {
        body->centroid = vec_add(body->centroid, motion->displacement);
        body->angle += motion->rotation;
        body->world_valid = false;
    }
    body->velocity = motion->velocity;
    body->angular_velocity = motion->angular_velocity;
}

void integrator_apply(body_t *body, const integrator_motion_t *motion) {
    apply_motion(body, motion);
}

/* Moves body i by motion and clears its accumulators; when the result does
 * not fit a double, writes the outcome and leaves them (they explain it).
 * The result is checked in registers: reading back the fields just written
 * can wait for the stores to retire, which stalls the whole step. */
static inline bool move_body(body_t *body, const integrator_motion_t *motion, size_t i,
                             integrator_outcome_t *outcome) {
    vector_t start = body->centroid;
    bool finite = body_state_is_finite(vec_add(start, motion->displacement),
                                       body->angle + motion->rotation, motion->velocity,
                                       motion->angular_velocity);
    apply_motion(body, motion);
    if (!finite) {
        outcome->failed = i;
        outcome->failed_start = start;
        return false;
    }
    body_clear_accumulators(body);
    return true;
}

integrator_outcome_t integrator_move(const integrator_step_t *step, body_t **bodies,
                                     size_t count, const integrator_motion_t *motions) {
    integrator_outcome_t outcome = {count, VEC_ZERO, false};
    if (motions != NULL) {
        for (size_t i = 0; i < count; i++) {
            BODY_PREFETCH_AWAKE(bodies, i + BODY_AHEAD, count);
            body_t *body = bodies[i];
            if (body->removed) {
                outcome.removed = true;
            } else if (!motions[i].still && !move_body(body, &motions[i], i, &outcome)) {
                break;
            }
        }
        return outcome;
    }
    /* In locals: the stores to the bodies could otherwise alias *step. */
    const double dt = step->dt, w = integrator_position_weight(step->integrator);
    const vector_t gravity = step->gravity;
    for (size_t i = 0; i < count; i++) {
        BODY_PREFETCH(bodies, i + BODY_AHEAD, count, false);
        body_t *body = bodies[i];
        integrator_motion_t motion;
        if (body->removed) {
            outcome.removed = true;
            continue;
        }
        predict_one_stage(body, dt, gravity, w, &motion);
        if (!move_body(body, &motion, i, &outcome)) break;
    }
    return outcome;
}
