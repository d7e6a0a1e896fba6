#ifndef CONTACT_POINT_H
#define CONTACT_POINT_H

/*
 * What preparing (velocity_solve.c), the velocity solve, the collision
 * pass (collision_pass.c) and the position pass (position_pass.c) share
 * about one contact point, one contact at a time: velocities at a point,
 * impulses along a direction, a block contact's two points solved
 * together, the bounce threshold, and which of two pending impacts comes
 * later. The batches
 * (solver_wide.c) have their own, four lanes at a time.
 */

#include <math.h>
#include <stdbool.h>
#include "solver/solver_types.h"

static inline vector_t tangent_of(vector_t normal) {
    return vec_perpendicular(normal);
}

static inline vector_t point_velocity(vector_t v, double w, vector_t r) {
    return (vector_t){v.x - w * r.y, v.y + w * r.x};
}

/* Relative velocity of b over a at a point, along direction d whose lever
 * terms are r_a x d and r_b x d. */
static inline double relative_along(const solver_velocity_t *a, const solver_velocity_t *b,
                                    vector_t d, double rd_a, double rd_b) {
    return d.x * (b->v.x - a->v.x) + d.y * (b->v.y - a->v.y) + b->w * rd_b - a->w * rd_a;
}

/* Applies impulse lambda along direction d at a point with lever terms
 * rd_a, rd_b: -lambda d on a, +lambda d on b. */
static inline void apply_along(solver_velocity_t *a, solver_velocity_t *b, vector_t d,
                               double rd_a, double rd_b, double lambda) {
    a->v.x -= a->inverse_mass * lambda * d.x;
    a->v.y -= a->inverse_mass * lambda * d.y;
    a->w -= a->inverse_inertia * lambda * rd_a;
    b->v.x += b->inverse_mass * lambda * d.x;
    b->v.y += b->inverse_mass * lambda * d.y;
    b->w += b->inverse_inertia * lambda * rd_b;
}

/*
 * A block contact's two points at once: x >= 0 with K x + b >= 0 and
 * x (K x + b) = 0, K the contact's 2x2 matrix (k12 its off-diagonal
 * term, solver_contact_k), by enumerating the four cases (both points, the
 * first alone, the second alone, neither), as in Box2D. False when no case
 * holds (rounding), x then unset.
 */
static inline bool solve_block_cases(const solver_contact_t *c, double k12, double b1, double b2,
                                     double *x1, double *x2) {
    *x1 = -(c->m11 * b1 + c->m12 * b2);
    *x2 = -(c->m12 * b1 + c->m22 * b2);
    if (*x1 >= 0.0 && *x2 >= 0.0) return true;
    *x1 = -c->points[0].normal_mass * b1;
    *x2 = 0.0;
    if (*x1 >= 0.0 && k12 * *x1 + b2 >= 0.0) return true;
    *x1 = 0.0;
    *x2 = -c->points[1].normal_mass * b2;
    if (*x2 >= 0.0 && k12 * *x2 + b1 >= 0.0) return true;
    *x2 = 0.0;
    return b1 >= 0.0 && b2 >= 0.0;
}

/* The approach speed (m/s) from which an elastic contact bounces: lower for
 * a pair that nothing accelerates (solver_types.h). Inelastic contacts keep the
 * ordinary threshold, which also decides which of their approaches are
 * timed as impacts; `threshold` is that one (solver_settings_t). */
static inline double bounce_threshold(double restitution, const solver_state_t *sa,
                                      const solver_state_t *sb, double threshold) {
    if (restitution > 0.0 && sa->acceleration.x == 0.0 && sa->acceleration.y == 0.0 &&
        sb->acceleration.x == 0.0 && sb->acceleration.y == 0.0) {
        return SOLVER_FREE_RESTITUTION_THRESHOLD;
    }
    return threshold;
}

/* Two impacts of one contact within this fraction of the step of each
 * other are one: rounding parts the corners of a box that lands flat. */
static const double SAME_MOMENT = 1e-9;

/* Whether pending impact p meets the surface after q, not with it. */
static inline bool later_impact(const solver_point_t *p, const solver_point_t *q, double dt) {
    return !isnan(p->impact_offset) && !isnan(q->impact_offset) &&
           p->impact_time > q->impact_time + SAME_MOMENT * dt;
}

#endif // #ifndef CONTACT_POINT_H
