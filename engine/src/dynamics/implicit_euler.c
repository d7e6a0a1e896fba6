#include "dynamics/implicit_euler.h"
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include "dynamics/body_private.h"
#include "base/memory.h"
#include "dynamics/spring_system.h"

/* node_of[i] for a body the step holds, and for one no Jacobian reaches yet. */
#define HELD UINT32_MAX
#define UNSEEN (UINT32_MAX - 1)

struct implicit_euler {
    uint32_t *node_of; /* per body: its unknown, or HELD */
    size_t body_capacity;
    uint32_t *body_of; /* per unknown: its body */
    size_t body_of_capacity;
    vector_t *delta;   /* per unknown: v' - v, then the contacts' share */
    size_t delta_capacity;
    vector_t *free_velocity; /* per unknown: v' before the contacts */
    size_t free_capacity;
    sym2_t *inverse_diagonal; /* per unknown: its block of A^-1 (spring_system.h) */
    size_t inverse_capacity;
    size_t nodes; /* of this step; 0 when no Jacobian reached a free body */
    spring_system_t *system;
};

void implicit_euler_free(implicit_euler_t *w) {
    if (w == NULL) return;
    memory_free(w->node_of);
    memory_free(w->body_of);
    memory_free(w->delta);
    memory_free(w->free_velocity);
    memory_free(w->inverse_diagonal);
    spring_system_free(w->system);
    memory_free(w);
}

/* The body's index in bodies; SIZE_MAX for none (NULL: the world) or a
 * body the scene does not hold. */
static size_t index_of(const body_t *body, body_t **bodies, size_t count) {
    if (body == NULL) return SIZE_MAX;
    size_t i = body->solver_index;
    return i < count && bodies[i] == body ? i : SIZE_MAX;
}

static uint32_t node_at(const implicit_euler_t *w, size_t i) {
    return i == SIZE_MAX ? HELD : w->node_of[i];
}

/* Numbers the free bodies the Jacobians reach, in the order they are met;
 * returns how many. */
static size_t number_nodes(implicit_euler_t *w, const integrator_step_t *step, body_t **bodies,
                           size_t count) {
    memory_reserve((void **)&w->node_of, &w->body_capacity, count, sizeof(uint32_t));
    for (size_t i = 0; i < count; i++) {
        body_t *body = bodies[i];
        body->solver_index = (uint32_t)i;
        w->node_of[i] = body->inverse_mass > 0.0 && !body->asleep ? UNSEEN : HELD;
    }
    size_t nodes = 0;
    for (size_t e = 0; e < step->jacobian_count; e++) {
        const force_jacobian_t *j = &step->jacobians[e];
        size_t ends[2] = {index_of(j->body1, bodies, count), index_of(j->body2, bodies, count)};
        for (int k = 0; k < 2; k++) {
            if (ends[k] == SIZE_MAX || w->node_of[ends[k]] != UNSEEN) continue;
            memory_reserve((void **)&w->body_of, &w->body_of_capacity, nodes + 1, sizeof(uint32_t));
            w->node_of[ends[k]] = (uint32_t)nodes;
            w->body_of[nodes++] = (uint32_t)ends[k];
        }
    }
    return nodes;
}

/* The velocity of one end of a Jacobian at the start of the step (the
 * world's: 0). */
static vector_t start_velocity(const body_t *body) {
    return body != NULL ? body->velocity : VEC_ZERO;
}

static sym2_t sym2_combine(double a, sym2_t m, double b, sym2_t n) {
    return (sym2_t){a * m.xx + b * n.xx, a * m.xy + b * n.xy, a * m.yy + b * n.yy};
}

static vector_t sym2_times(sym2_t m, vector_t v) {
    return (vector_t){m.xx * v.x + m.xy * v.y, m.xy * v.x + m.yy * v.y};
}

/* Adds one Jacobian's share of M + h C + h^2 S and of the right side
 * (its -h^2 S v term; the forces at the start are in each body's own). */
static void assemble(implicit_euler_t *w, const force_jacobian_t *j, double h, body_t **bodies,
                     size_t count) {
    if (j->body1 == j->body2) return;
    uint32_t n1 = node_at(w, index_of(j->body1, bodies, count));
    uint32_t n2 = node_at(w, index_of(j->body2, bodies, count));
    if (n1 == HELD && n2 == HELD) return;
    vector_t relative = vec_subtract(start_velocity(j->body2), start_velocity(j->body1));
    vector_t g = sym2_times(j->stiffness, vec_multiply(h * h, relative));
    sym2_t weight = sym2_combine(h, j->damping, h * h, j->stiffness);
    if (n1 != HELD) spring_system_add_rhs(w->system, n1, g);
    if (n2 != HELD) spring_system_add_rhs(w->system, n2, vec_negate(g));
    if (n1 != HELD && n2 != HELD) {
        spring_system_add_edge(w->system, n1, n2, weight);
    } else {
        spring_system_add_diagonal(w->system, n1 != HELD ? n1 : n2, weight);
    }
}

/* The largest eigenvalue: the body's response along its least stiff
 * direction (the contact solver has one mass per body). */
static double sym2_largest(sym2_t m) {
    double half_gap = 0.5 * (m.xx - m.yy);
    return 0.5 * (m.xx + m.yy) + sqrt(half_gap * half_gap + m.xy * m.xy);
}

void implicit_euler_correct(const integrator_step_t *step, body_t **bodies, size_t count,
                            integrator_motion_t *motions, implicit_euler_t **workspace) {
    if (step->jacobian_count == 0) return;
    if (*workspace == NULL) *workspace = memory_calloc(1, sizeof(implicit_euler_t));
    implicit_euler_t *w = *workspace;
    size_t nodes = number_nodes(w, step, bodies, count);
    w->nodes = nodes;
    if (nodes == 0) return;
    memory_reserve((void **)&w->delta, &w->delta_capacity, nodes, sizeof(vector_t));
    memory_reserve((void **)&w->free_velocity, &w->free_capacity, nodes, sizeof(vector_t));
    memory_reserve((void **)&w->inverse_diagonal, &w->inverse_capacity, nodes, sizeof(sym2_t));
    double h = step->dt;
    spring_system_begin(&w->system, nodes, step->jacobian_count);
    /* M and the start's J + h (F + m g) of each body: the velocity change
     * solved for directly, not as a correction to the explicit step's,
     * which a stiff spring makes (omega h)^2 times larger than the answer. */
    for (size_t k = 0; k < nodes; k++) {
        const body_t *body = bodies[w->body_of[k]];
        double m = body->mass;
        spring_system_add_diagonal(w->system, k, (sym2_t){m, 0.0, m});
        vector_t pull = vec_add(body->force, vec_multiply(m, step->gravity));
        spring_system_add_rhs(w->system, k, vec_add(body->impulse, vec_multiply(h, pull)));
    }
    for (size_t e = 0; e < step->jacobian_count; e++) {
        assemble(w, &step->jacobians[e], h, bodies, count);
    }
    spring_system_solve(w->system, w->delta);
    spring_system_inverse_diagonal(w->system, w->inverse_diagonal);
    for (size_t k = 0; k < nodes; k++) {
        const body_t *body = bodies[w->body_of[k]];
        integrator_motion_t *motion = &motions[w->body_of[k]];
        vector_t change = w->delta[k];
        motion->velocity = vec_add(body->velocity, change);
        motion->displacement = vec_multiply(h, motion->velocity);
        motion->acceleration = vec_multiply(
            1.0 / h, vec_subtract(change, vec_multiply(body->inverse_mass, body->impulse)));
        motion->inverse_mass = sym2_largest(w->inverse_diagonal[k]);
        w->free_velocity[k] = motion->velocity;
    }
}

void implicit_euler_respond(const integrator_step_t *step, body_t **bodies,
                            integrator_motion_t *motions, implicit_euler_t *w) {
    if (step->jacobian_count == 0 || w == NULL || w->nodes == 0) return;
    /* The impulse the solver gave each body, as it saw it: its change of
     * velocity times the mass it was told. */
    bool pushed = false;
    spring_system_clear_rhs(w->system);
    for (size_t k = 0; k < w->nodes; k++) {
        const integrator_motion_t *motion = &motions[w->body_of[k]];
        vector_t change = vec_subtract(motion->velocity, w->free_velocity[k]);
        w->delta[k] = change;
        if (bodies[w->body_of[k]]->asleep || (change.x == 0.0 && change.y == 0.0)) continue;
        spring_system_add_rhs(w->system, k, vec_multiply(1.0 / motion->inverse_mass, change));
        pushed = true;
    }
    if (!pushed) return;
    /* delta: the change the solver made; response: what the springs make of
     * those impulses (the same on a body pushed alone in a forest). */
    vector_t *response = w->free_velocity;
    spring_system_solve_again(w->system, response);
    double h = step->dt;
    for (size_t k = 0; k < w->nodes; k++) {
        integrator_motion_t *motion = &motions[w->body_of[k]];
        if (bodies[w->body_of[k]]->asleep) continue;
        vector_t more = vec_subtract(response[k], w->delta[k]);
        motion->velocity = vec_add(motion->velocity, more);
        motion->displacement = vec_add(motion->displacement, vec_multiply(h, more));
    }
}
