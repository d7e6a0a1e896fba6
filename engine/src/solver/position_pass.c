#include "solver/position_pass.h"
#include <math.h>
#include "base/scalar.h"
#include "solver/contact_point.h"

static bool pushes(const solver_contact_t *c) {
    for (int i = 0; i < c->point_count; i++) {
        const solver_point_t *p = &c->points[i];
        if (p->normal_impulse > 0.0 || p->restitution_impulse > 0.0) return true;
    }
    return false;
}

static const uint32_t NO_PARTNER = UINT32_MAX;
enum { MARK_AHEAD = 8 };

/* Marks a body's impact at tau if it is its earliest; toward is the
 * direction in which the body closes the gap (for a landing). */
static void mark_earliest(solver_state_t *state, const solver_point_t *p, uint32_t partner,
                          vector_t toward) {
    if (state->impact_time >= 0.0 && p->impact_time >= state->impact_time) return;
    state->impact_time = p->impact_time;
    state->impact_partner = partner;
    state->landing_gap = p->lands && partner == NO_PARTNER ? p->separation : -1.0;
    state->landing_direction = toward;
}

/* Counts each body's contacts that pushed this step, and marks each movable
 * body of an impact with its earliest impact: the time, the other body when
 * it can move, and for a landing on a static body the gap to close. */
static void mark_impacts(const solver_contact_t *c, const solver_velocity_t *velocities,
                         solver_state_t *states) {
    if (!pushes(c)) return;
    solver_state_t *a = &states[c->a], *b = &states[c->b];
    a->pushing_contacts++;
    b->pushing_contacts++;
    if (!c->impact) return;
    bool static_a = solver_row_is_static(&velocities[c->a]);
    bool static_b = solver_row_is_static(&velocities[c->b]);
    for (int i = 0; i < c->point_count; i++) {
        const solver_point_t *p = &c->points[i];
        if (p->impact_time < 0.0) continue;
        if (!static_a) mark_earliest(a, p, static_b ? NO_PARTNER : c->b, c->normal);
        if (!static_b) mark_earliest(b, p, static_a ? NO_PARTNER : c->a, vec_negate(c->normal));
    }
}

void solver_mark_impacts(const solver_contact_t *contacts, size_t count,
                         const solver_velocity_t *velocities, solver_state_t *states) {
    for (size_t i = 0; i < count; i++) {
        /* Body b's state is anywhere in the rows, and the contacts a record
         * apart: waiting on them was most of this loop's time. */
        if (i + MARK_AHEAD < count) {
            __builtin_prefetch(&states[contacts[i + MARK_AHEAD].b], 1);
            __builtin_prefetch(&contacts[i + 2 * MARK_AHEAD]);
        }
        mark_impacts(&contacts[i], velocities, states);
    }
}

/*
 * A landing on a static body: after the impact the body rests, pressed by
 * the acceleration that brought it, so its velocity changes partly at the
 * impact and partly in a continuous push to the end of the step, and no
 * single time stands for both. Instead the body is moved to touch the
 * surface, along the contact normal, which is where it ends. Timing it all
 * at the impact kept a box dropped at dt >= 0.6 s jumping between two
 * heights (4.9e8 m at dt = 1e4 s); explicit and symplectic Euler floated or
 * fell through the floor.
 */
static void land(const solver_state_t *state, solver_displacement_t *moved) {
    double closed = vec_dot(moved->dx, state->landing_direction);
    moved->dx = vec_add(moved->dx,
                        vec_multiply(state->landing_gap - closed, state->landing_direction));
}

/*
 * The integrator moves a body by w dt of its velocity change, as if the
 * change happened at (1 - w) dt into the step. A body whose only push this
 * step was an impact at time tau, against a static body or a movable one
 * that had no other push either, is moved by (dt - tau - w dt) times its
 * velocity change instead, as if the change happened at tau: the exact
 * motion under constant acceleration, so bounces come out exact at any dt,
 * and the same impulse at another time, so momentum is kept. Without it a
 * scheme that moves a body by its start velocity (w < 1) carries a fast one
 * through a movable wall (the seed scheme from 50 m/s against a 0.1 m wall).
 * Where a body is also pressed by others its change is not that impact's
 * alone; timing it so pushed bodies of the 10000-body pile through its floor
 * and walls, and tilted a settling column (measured), so the integrator's
 * own timing is kept there. A landing is placed instead (land).
 */
static void apply_impact_time(const solver_bodies_t *bodies, size_t i,
                              const solver_settings_t *s) {
    const solver_state_t *state = &bodies->states[i];
    if (state->impact_time < 0.0 || state->pushing_contacts != 1) return;
    if (state->impact_partner != NO_PARTNER &&
        bodies->states[state->impact_partner].pushing_contacts != 1) {
        return;
    }
    const solver_velocity_t *velocity = &bodies->velocities[i];
    solver_displacement_t *moved = &bodies->displacements[i];
    if (state->landing_gap >= 0.0) {
        land(state, moved);
        return;
    }
    double shift = s->dt - state->impact_time - s->position_weight * s->dt;
    moved->dx = vec_add(moved->dx, vec_multiply(shift, vec_subtract(velocity->v, state->v_free)));
    moved->dtheta += shift * (velocity->w - state->w_free);
}

/* Where the integrator will put each body with the solved velocities
 * (with its impact timing, see apply_impact_time), remembered as where the
 * position pass starts from. */
void solver_advance(const solver_bodies_t *bodies, const solver_settings_t *s, size_t begin,
                    size_t end) {
    double w = s->position_weight;
    for (size_t i = begin; i < end; i++) {
        solver_state_t *state = &bodies->states[i];
        const solver_velocity_t *velocity = &bodies->velocities[i];
        solver_displacement_t *moved = &bodies->displacements[i];
        moved->dx = vec_multiply(s->dt, vec_add(state->drift, vec_multiply(w, velocity->v)));
        moved->dtheta = s->dt * (state->spin_drift + w * velocity->w);
        apply_impact_time(bodies, i, s);
        state->dx_advanced = moved->dx;
        state->dtheta_advanced = moved->dtheta;
    }
}

/* The separation re-estimated from the displacements so far, to first
 * order in the rotation (a step turns a body by a small angle). */
double solver_position_error(const solver_contact_t *c, const solver_point_t *p, double rate,
                             const solver_displacement_t *a, const solver_displacement_t *b) {
    double separation = p->separation + vec_dot(c->normal, vec_subtract(b->dx, a->dx)) +
                        b->dtheta * p->rn_b - a->dtheta * p->rn_a;
    return max_of(-SOLVER_MAX_POSITION_CORRECTION, min_of(rate * (separation + c->slop), 0.0));
}

/* Moves the bodies apart by x1 and x2 (kg m) at the contact's points. */
static void push_apart(const solver_contact_t *c, const solver_velocity_t *velocities,
                       solver_displacement_t *a, solver_displacement_t *b, double x1, double x2) {
    const solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
    double ma = velocities[c->a].inverse_mass, ia = velocities[c->a].inverse_inertia;
    double mb = velocities[c->b].inverse_mass, ib = velocities[c->b].inverse_inertia;
    double total = x1 + x2;
    a->dx = vec_subtract(a->dx, vec_multiply(ma * total, c->normal));
    a->dtheta -= ia * (x1 * p1->rn_a + x2 * p2->rn_a);
    b->dx = vec_add(b->dx, vec_multiply(mb * total, c->normal));
    b->dtheta += ib * (x1 * p1->rn_b + x2 * p2->rn_b);
}

/* A block contact's two pushes at once (solve_block_cases on the points'
 * errors). One point after the other, the first push turned the body and
 * the second undid only part of it, so every flat landing left a spin: a
 * box dropped 0.5 m onto another turned at 0.08 rad/s and slid 5 mm. */
static void correct_block(const solver_contact_t *c, const solver_velocity_t *velocities,
                          solver_displacement_t *a, solver_displacement_t *b, double rate) {
    double c1 = solver_position_error(c, &c->points[0], rate, a, b);
    double c2 = solver_position_error(c, &c->points[1], rate, a, b);
    double x1, x2;
    double k12 = solver_contact_k(c, &velocities[c->a], &velocities[c->b]).k12;
    if (solve_block_cases(c, k12, c1, c2, &x1, &x2)) push_apart(c, velocities, a, b, x1, x2);
}

/*
 * One non-linear Gauss-Seidel pass over positions: each point's overlap
 * pushed back toward minus the contact's slop by a fraction of it (both
 * points of a block contact together). Only positions move: no energy is
 * added. solver_wide.c does the same four contacts at a time.
 */
void solver_solve_position(const solver_contact_t *c, const solver_velocity_t *velocities,
                           solver_displacement_t *displacements) {
    solver_displacement_t *a = &displacements[c->a], *b = &displacements[c->b];
    double rate = solver_position_rate(&velocities[c->a], &velocities[c->b]);
    if (c->block) {
        correct_block(c, velocities, a, b, rate);
        return;
    }
    double ma = velocities[c->a].inverse_mass, ia = velocities[c->a].inverse_inertia;
    double mb = velocities[c->b].inverse_mass, ib = velocities[c->b].inverse_inertia;
    for (int i = 0; i < c->point_count; i++) {
        const solver_point_t *p = &c->points[i];
        double lambda = -solver_position_error(c, p, rate, a, b) * p->normal_mass;
        a->dx = vec_subtract(a->dx, vec_multiply(ma * lambda, c->normal));
        a->dtheta -= ia * lambda * p->rn_a;
        b->dx = vec_add(b->dx, vec_multiply(mb * lambda, c->normal));
        b->dtheta += ib * lambda * p->rn_b;
    }
}

/* The most the position pass may turn a body in this step (rad): as far
 * as moves its farthest vertex `most` (m), at most SOLVER_MAX_TURN. */
static double turn_limit(double radius, double most) {
    return radius * SOLVER_MAX_TURN > most ? most / radius : SOLVER_MAX_TURN;
}

/* Caps what the position pass moved each body in this step (solver_types.h:
 * SOLVER_MAX_PUSH_SPEED). */
void solver_limit_corrections(const solver_bodies_t *bodies, double dt, size_t begin, size_t end) {
    double most = min_of(SOLVER_MAX_PUSH_SPEED * dt, SOLVER_MAX_PUSH);
    for (size_t i = begin; i < end; i++) {
        const solver_state_t *state = &bodies->states[i];
        solver_displacement_t *moved = &bodies->displacements[i];
        vector_t corrected = vec_subtract(moved->dx, state->dx_advanced);
        double squared = vec_dot(corrected, corrected);
        if (squared > most * most) { /* rare: no sqrt otherwise */
            double length = sqrt(squared);
            moved->dx = vec_add(state->dx_advanced, vec_multiply(most / length, corrected));
        }
        double turned = moved->dtheta - state->dtheta_advanced, angle = fabs(turned);
        if (angle * moved->radius > most || angle > SOLVER_MAX_TURN) { /* rare: no division */
            moved->dtheta =
                state->dtheta_advanced + copysign(turn_limit(moved->radius, most), turned);
        }
    }
}
