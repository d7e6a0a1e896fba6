#include "solver/collision_pass.h"
#include <math.h>
#include "base/scalar.h"
#include "solver/contact_point.h"

/* A point's approach speed as the collision pass sees it (m/s, negative
 * when approaching), or NAN when the point takes no part: a pending impact
 * measured at its time of impact; a touching point as it is now. */
static double approach_of(const solver_point_t *p, double vn) {
    if (!isnan(p->impact_offset)) return vn - p->impact_offset;
    return p->touched ? vn : NAN;
}

/* Whether an approach calls for a bounce: a pending impact until it has
 * bounced, a touching point while it approaches faster than the threshold. */
static bool needs_bounce(const solver_point_t *p, double approach, double threshold) {
    if (!isnan(p->impact_offset)) return approach < 0.0;
    return approach < -threshold;
}

/*
 * The compression impulses of a contact's taking-part points: the smallest
 * impulses x >= 0 that stop every approach, K x + approach >= 0 with
 * x (K x + approach) = 0, by the same enumeration as solve_normal_block (one
 * point: x = -approach / K; K from the rows a and b). Points that take no
 * part have NAN approach and get 0; a point left for a later pass is set
 * to NAN.
 */
static void compression_impulses(const solver_contact_t *c, const solver_velocity_t *a,
                                 const solver_velocity_t *b, double approach[2], double x[2]) {
    x[0] = x[1] = 0.0;
    bool both = c->point_count == 2 && !isnan(approach[0]) && !isnan(approach[1]);
    if (both && !c->block) {
        /* Too ill-conditioned to solve together: the faster point now, the
         * other in a later pass if it still approaches. */
        approach[approach[0] <= approach[1] ? 1 : 0] = NAN;
        both = false;
    }
    if (!both) {
        for (int i = 0; i < c->point_count; i++) {
            if (!isnan(approach[i])) x[i] = max_of(-approach[i] * c->points[i].normal_mass, 0.0);
        }
        return;
    }
    double b1 = approach[0], b2 = approach[1];
    double k12 = solver_contact_k(c, a, b).k12;
    double x1 = -(c->m11 * b1 + c->m12 * b2), x2 = -(c->m12 * b1 + c->m22 * b2);
    if (x1 >= 0.0 && x2 >= 0.0) {
        x[0] = x1, x[1] = x2;
    } else if ((x1 = -c->points[0].normal_mass * b1) >= 0.0 && k12 * x1 + b2 >= 0.0) {
        x[0] = x1;
    } else if ((x2 = -c->points[1].normal_mass * b2) >= 0.0 && k12 * x2 + b1 >= 0.0) {
        x[1] = x2;
    }
}

/* Friction during the impulse just applied at a point: Coulomb, within
 * friction times the point's collision-pass normal impulse. */
static void impact_friction(solver_contact_t *c, solver_velocity_t *a, solver_velocity_t *b,
                            solver_point_t *p) {
    vector_t tangent = tangent_of(c->normal);
    double vt = relative_along(a, b, tangent, p->rt_a, p->rt_b);
    double limit = c->friction * p->restitution_impulse;
    double total =
        max_of(-limit, min_of(p->restitution_tangent_impulse - p->tangent_mass * vt, limit));
    apply_along(a, b, tangent, p->rt_a, p->rt_b, total - p->restitution_tangent_impulse);
    p->restitution_tangent_impulse = total;
}

/*
 * A point apart at the start of the step that did not meet the surface then
 * (set_target found no impact), but that the pass's impulses now send into
 * it within the step faster than the threshold: a bounce at the other
 * corner of a spinning polygon turns this one into the wall. Its speculative
 * target would stop it at the surface, inelastically: a triangle at e = 1
 * in a closed box without gravity lost 29% of its energy so, and 18% more
 * the next step (2 of its 10^4 steps); 20 such polygons kept 42% after
 * 10^4 steps. Instead it becomes an impact of its own, bounced from the
 * contact's first moment of impact (as same_impact_moment does for points
 * that meet the surface together), or, when no other point of
 * the contact hit, from when the gap closes at this speed. A rebound that
 * would land again within the step is left to the target. Returns whether
 * the point became an impact.
 */
static bool late_impact(const solver_contact_t *c, solver_point_t *p, double vn, double threshold,
                        const solver_state_t *states, double dt) {
    if (p->touched || !isnan(p->impact_offset) || p->separation <= 0.0) return false;
    if (!(vn < p->target && vn < -threshold)) return false;
    double first = -1.0;
    for (int i = 0; i < c->point_count; i++) {
        double t = c->points[i].impact_time;
        if (t >= 0.0 && (first < 0.0 || t < first)) first = t;
    }
    if (first < 0.0) first = min_of(p->separation / -vn, dt);
    double an = vec_dot(c->normal,
                        vec_subtract(states[c->b].acceleration, states[c->a].acceleration));
    double offset = an * (dt - first);
    if (-c->restitution * (vn - offset) + offset < 0.0) return false;
    p->impact_time = first;
    p->impact_offset = offset;
    return true;
}

/*
 * One collision-pass visit of a contact. When a point approaches fast (or a
 * pending impact has not bounced), the contact gets Poisson's impulse: the
 * compression impulse x that stops the approach of its points together,
 * times (1 + e), then friction within the cone of that impulse. Newton's
 * rule (each point leaves at -e times its own approach) gains energy when a
 * polygon lands on a vertex or rotating, because an impulse at one point
 * changes the other's approach (measured: a 16-gon at e = 1 gained 4e5
 * times its energy in 100 bounces). Poisson's impulse changes the kinetic
 * energy by -(1 - e^2) x.K.x / 2: e^2 of the approach energy returns, never
 * more. Sets *impacts when a point became an impact (late_impact). Returns
 * whether it applied an impulse.
 */
static bool bounce_contact(solver_contact_t *c, solver_velocity_t *velocities,
                           const solver_state_t *states, double dt, double restitution_threshold,
                           bool *impacts) {
    solver_velocity_t a = velocities[c->a], b = velocities[c->b];
    double threshold =
        bounce_threshold(c->restitution, &states[c->a], &states[c->b], restitution_threshold);
    double approach[2] = {NAN, NAN};
    bool wanted = false;
    for (int i = 0; i < c->point_count; i++) {
        solver_point_t *p = &c->points[i];
        double vn = relative_along(&a, &b, c->normal, p->rn_a, p->rn_b);
        bool late = late_impact(c, p, vn, threshold, states, dt);
        c->impact |= late;
        *impacts |= late;
        approach[i] = approach_of(p, vn);
    }
    for (int i = 0; i < c->point_count; i++) {
        /* While the first impact still approaches it bounces alone: the
         * velocities it leaves decide whether the later one still hits. */
        int other = 1 - i;
        if (c->point_count == 2 && later_impact(&c->points[i], &c->points[other], dt) &&
            needs_bounce(&c->points[other], approach[other], threshold)) {
            approach[i] = NAN;
        }
        wanted |= !isnan(approach[i]) && needs_bounce(&c->points[i], approach[i], threshold);
    }
    if (!wanted) return false;
    double x[2];
    compression_impulses(c, &a, &b, approach, x);
    bool applied = false;
    for (int i = 0; i < c->point_count; i++) {
        solver_point_t *p = &c->points[i];
        if (isnan(approach[i])) continue;
        p->impact_offset = NAN; /* an impact bounces once; then it is a touching point */
        p->touched = true;
        if (x[i] <= 0.0) continue;
        double lambda = (1.0 + c->restitution) * x[i];
        p->restitution_impulse += lambda;
        apply_along(&a, &b, c->normal, p->rn_a, p->rn_b, lambda);
        applied = true;
    }
    for (int i = 0; i < c->point_count; i++) {
        if (x[i] > 0.0) impact_friction(c, &a, &b, &c->points[i]);
    }
    velocities[c->a] = a;
    velocities[c->b] = b;
    return applied;
}

/*
 * Restitution before the contact solve, pair by pair, as in Guendelman,
 * Bridson and Fedkiw (2003): repeated until no contact approaches faster than
 * the threshold, so an impact travels along a row of touching bodies the way
 * it does in a Newton's cradle (the last one leaves, the others stop). A
 * contact solve that takes restitution from the velocities before it runs
 * cannot do that: the touching pairs have nothing to rebound from, and the
 * momentum smears over the row (measured: 13% of the energy lost, 1.3 m/s
 * off). Contacts without elasticity skip it.
 */
bool solver_collision_pass(solver_contact_t *contacts, size_t count, solver_velocity_t *velocities,
                           const solver_state_t *states, double dt, double threshold,
                           int passes) {
    bool impacts = false;
    for (int pass = 0; pass < passes; pass++) {
        bool applied = false;
        for (size_t i = 0; i < count; i++) {
            if (contacts[i].restitution > 0.0) {
                applied |= bounce_contact(&contacts[i], velocities, states, dt, threshold,
                                          &impacts);
            }
        }
        if (!applied) break;
    }
    return impacts;
}
