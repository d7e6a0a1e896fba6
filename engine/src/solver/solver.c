#include "solver/solver.h"
#include <math.h>
#include "base/scalar.h"
#include "solver/shock.h"
#include "solver/solver_split.h"
#include "solver/solver_wide.h"
#include "base/workers.h"

/* The block solve needs a well-conditioned 2x2 matrix; beyond this
 * condition number the two points are solved one at a time. */
static const double MAX_CONDITION_NUMBER = 1000.0;
/*
 * The same for two points that are an incident edge's own ends: a short
 * edge of a fine polygon resting on a face, whose rows differ only by the
 * edge's length. Solved one at a time, the first point took the whole load
 * every step, 1.5 mm off centre on a regular 1000-gon of 1 m, a steady
 * torque (0.12 rad/s^2): set down on a floor it rolled away ever faster
 * (0.6 m/s after 10 s). In doubles the 2x2 solve is good to about the
 * condition number times 1e-16, so up to 1e8 it keeps every digit that
 * matters; Box2D's 1000 is for floats. Polygons of up to 50000 sides of
 * 1 m now rest. A pair cut by clipping near a corner keeps the one-by-one
 * solve: piles meet those, and the bound raised for them too left the
 * benchmark's pile(10000) 0.339 m deep instead of 0.274 (better over other
 * seeds, 0.295 against 0.315 m on average over 3, but not that one).
 */
static const double MAX_EDGE_CONDITION_NUMBER = 1e8;

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

/* The earliest time in [0, dt] at which s + v t + a t^2 / 2 reaches 0, or a
 * negative number when it does not. */
static inline __attribute__((always_inline)) double time_of_impact(double s, double v, double a,
                                                                   double dt) {
    double best = INFINITY;
    if (fabs(a) < 1e-12) {
        if (v < 0.0) best = -s / v;
    } else {
        double discriminant = v * v - 2.0 * a * s;
        if (discriminant < 0.0) return -1.0;
        double root = sqrt(discriminant);
        /* Both roots without cancellation: q = -(v + sign(v) root) / 2. */
        double q = -0.5 * (v + (v >= 0.0 ? root : -root));
        double t1 = q / (0.5 * a), t2 = q != 0.0 ? s / q : -1.0;
        if (t1 >= 0.0) best = min_of(best, t1);
        if (t2 >= 0.0) best = min_of(best, t2);
    }
    /* Only an impact within this step counts (a later one is next step's). */
    return best <= dt ? best : -1.0;
}

/* The approach speed (m/s) from which an elastic contact bounces: lower for
 * a pair that nothing accelerates (solver.h). Inelastic contacts keep the
 * ordinary threshold, which also decides which of their approaches are
 * timed as impacts. */
static inline double bounce_threshold(double restitution, const solver_state_t *sa,
                                      const solver_state_t *sb) {
    if (restitution > 0.0 && sa->acceleration.x == 0.0 && sa->acceleration.y == 0.0 &&
        sb->acceleration.x == 0.0 && sb->acceleration.y == 0.0) {
        return SOLVER_FREE_RESTITUTION_THRESHOLD;
    }
    return SOLVER_RESTITUTION_THRESHOLD;
}

/*
 * The lower bound on a point's end-of-step relative normal velocity.
 *
 * Touching or overlapping: no approach (0); a fast approach bounces in the
 * collision pass. Apart by s > 0: the approach may close at most s by the
 * end of the step; the step moves the point by dt (drift + w v_end), w the
 * integrator's position weight, which bounds the end velocity by
 * (-s / dt - drift_n) / w, never above 0 (a slow
 * approach is not turned into a rebound; the position pass removes the
 * little overlap left).
 *
 * When the gap closes within the step at restitution speed, the exact answer
 * for constant accelerations is known: the point hits at time tau with
 * speed vi and leaves at -e vi, and ends the step at -e vi + a (dt - tau).
 * The collision pass bounces it from vi (impact_offset is a (dt - tau));
 * an inelastic impact targets the end velocity a (dt - tau), or 0. For a
 * body whose only push was such an impact on a static body,
 * apply_impact_time then moves it as if the impulse had acted at tau.
 * Bounce heights come out exact to rounding at any dt
 * (tests/test_contacts.c). Returns whether the point has such an impact
 * (impact_time >= 0).
 */
static bool set_target(solver_point_t *p, vector_t r_a, vector_t r_b, vector_t normal,
                       double restitution, const solver_state_t *sa, const solver_state_t *sb,
                       const solver_settings_t *settings) {
    double dt = settings->dt, w = settings->position_weight;
    vector_t start = vec_subtract(point_velocity(sb->v_start, sb->w_start, r_b),
                                  point_velocity(sa->v_start, sa->w_start, r_a));
    vector_t drift = vec_subtract(point_velocity(sb->drift, sb->spin_drift, r_b),
                                  point_velocity(sa->drift, sa->spin_drift, r_a));
    double vn_start = vec_dot(normal, start);
    p->impact_time = -1.0;
    p->impact_offset = NAN;
    p->lands = false;
    p->restitution_impulse = 0.0;
    p->restitution_tangent_impulse = 0.0;
    p->touched = p->separation <= 0.0;
    if (p->separation <= 0.0) {
        p->target = 0.0;
        return false;
    }
    double an = vec_dot(normal, vec_subtract(sb->acceleration, sa->acceleration));
    double tau = time_of_impact(p->separation, vn_start, an, dt);
    double vi = tau >= 0.0 ? vn_start + an * tau : 0.0;
    /* With w = 0 the end velocity does not move the body this step; only an
     * impact, timed, does. */
    double closing =
        w > 0.0 ? min_of((-p->separation / dt - vec_dot(normal, drift)) / w, 0.0) : -INFINITY;
    if (tau >= 0.0 && vi < -bounce_threshold(restitution, sa, sb)) {
        p->impact_time = tau;
        double after = an * (dt - tau);
        if (restitution > 0.0 && -restitution * vi + after >= 0.0) {
            p->impact_offset = after;
            p->target = closing;
        } else {
            /* Inelastic, or a step so long that the rebound lands again
             * within it: the point ends the step at rest on the surface. */
            p->target = max_of(after, 0.0);
            p->lands = after < 0.0;
        }
        return true;
    }
    p->target = closing;
    return false;
}

double solver_time_of_impact(double s, double v, double a, double dt) {
    return time_of_impact(s, v, a, dt);
}

double solver_bounce_threshold(double restitution, const solver_state_t *sa,
                               const solver_state_t *sb) {
    return bounce_threshold(restitution, sa, sb);
}

/* Two impacts of one contact within this fraction of the step of each
 * other are one: rounding parts the corners of a box that lands flat. */
static const double SAME_MOMENT = 1e-9;

/* Whether pending impact p meets the surface after q, not with it. */
static bool later_impact(const solver_point_t *p, const solver_point_t *q, double dt) {
    return !isnan(p->impact_offset) && !isnan(q->impact_offset) &&
           p->impact_time > q->impact_time + SAME_MOMENT * dt;
}

/* Two points of one manifold that hit at the same moment bounce together
 * from it: approaches measured at two moments are not one rigid motion, and
 * the impulse built from them gains energy (a tilted pentagon at e = 1
 * gained 0.1% a bounce). A point that hits later waits for the first one's
 * bounce (bounce_contact). */
static void same_impact_moment(solver_contact_t *c, double dt) {
    solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
    if (isnan(p1->impact_offset) || isnan(p2->impact_offset)) return;
    if (later_impact(p1, p2, dt) || later_impact(p2, p1, dt)) return;
    double first = p1->impact_time <= p2->impact_time ? p1->impact_offset : p2->impact_offset;
    p1->impact_offset = p2->impact_offset = first;
}

/* Returns whether a point of c has an impact within the step. Inlined into
 * its loop, as it was before the loop could run on workers too (called,
 * pile(1000) ran 2% more instructions). */
static inline __attribute__((always_inline)) bool prepare(solver_contact_t *c, const solver_anchor_t *anchor,
                    const solver_velocity_t *velocities, const solver_state_t *states,
                    const solver_settings_t *s) {
    const solver_velocity_t *a = &velocities[c->a], *b = &velocities[c->b];
    vector_t tangent = tangent_of(c->normal);
    double ma = a->inverse_mass, mb = b->inverse_mass;
    double ia = a->inverse_inertia, ib = b->inverse_inertia;
    bool impact = false;
    for (int i = 0; i < c->point_count; i++) {
        solver_point_t *p = &c->points[i];
        p->rn_a = vec_cross(anchor->r_a[i], c->normal);
        p->rn_b = vec_cross(anchor->r_b[i], c->normal);
        p->rt_a = vec_cross(anchor->r_a[i], tangent);
        p->rt_b = vec_cross(anchor->r_b[i], tangent);
        double k_normal = ma + mb + ia * p->rn_a * p->rn_a + ib * p->rn_b * p->rn_b;
        p->normal_mass = k_normal > 0.0 ? 1.0 / k_normal : 0.0;
        double k_tangent = ma + mb + ia * p->rt_a * p->rt_a + ib * p->rt_b * p->rt_b;
        p->tangent_mass = k_tangent > 0.0 ? 1.0 / k_tangent : 0.0;
        impact |= set_target(p, anchor->r_a[i], anchor->r_b[i], c->normal, c->restitution,
                             &states[c->a], &states[c->b], s);
    }
    if (c->point_count == 2) same_impact_moment(c, s->dt);
    c->block = false;
    if (c->point_count == 2) {
        const solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
        c->k11 = ma + mb + ia * p1->rn_a * p1->rn_a + ib * p1->rn_b * p1->rn_b;
        c->k22 = ma + mb + ia * p2->rn_a * p2->rn_a + ib * p2->rn_b * p2->rn_b;
        c->k12 = ma + mb + ia * p1->rn_a * p2->rn_a + ib * p1->rn_b * p2->rn_b;
        double det = c->k11 * c->k22 - c->k12 * c->k12;
        double condition = c->edge_ends ? MAX_EDGE_CONDITION_NUMBER : MAX_CONDITION_NUMBER;
        if (c->k11 * c->k11 < condition * det) {
            c->block = true;
            double inv = 1.0 / det;
            c->m11 = inv * c->k22;
            c->m12 = -inv * c->k12;
            c->m22 = inv * c->k11;
        }
    }
    return impact;
}

static void warm_start(const solver_contact_t *c, solver_velocity_t *velocities) {
    solver_velocity_t *a = &velocities[c->a], *b = &velocities[c->b];
    vector_t tangent = tangent_of(c->normal);
    for (int i = 0; i < c->point_count; i++) {
        const solver_point_t *p = &c->points[i];
        apply_along(a, b, c->normal, p->rn_a, p->rn_b, p->normal_impulse);
        apply_along(a, b, tangent, p->rt_a, p->rt_b, p->tangent_impulse);
    }
}

static inline void solve_friction(solver_contact_t *c, solver_velocity_t *a,
                                  solver_velocity_t *b) {
    vector_t tangent = tangent_of(c->normal);
    for (int i = 0; i < c->point_count; i++) {
        solver_point_t *p = &c->points[i];
        double vt = relative_along(a, b, tangent, p->rt_a, p->rt_b);
        double limit = c->friction * p->normal_impulse;
        double total = max_of(-limit, min_of(p->tangent_impulse - p->tangent_mass * vt, limit));
        double delta = total - p->tangent_impulse;
        p->tangent_impulse = total;
        apply_along(a, b, tangent, p->rt_a, p->rt_b, delta);
    }
}

static inline void solve_normal_point(const solver_contact_t *c, solver_velocity_t *a,
                                      solver_velocity_t *b, solver_point_t *p) {
    double vn = relative_along(a, b, c->normal, p->rn_a, p->rn_b);
    double total = max_of(p->normal_impulse - p->normal_mass * (vn - p->target), 0.0);
    double delta = total - p->normal_impulse;
    p->normal_impulse = total;
    apply_along(a, b, c->normal, p->rn_a, p->rn_b, delta);
}

/* Applies new accumulated normal impulses x1, x2 to both points. */
static inline void apply_block(solver_contact_t *c, solver_velocity_t *a, solver_velocity_t *b,
                               double x1, double x2) {
    solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
    double d1 = x1 - p1->normal_impulse, d2 = x2 - p2->normal_impulse;
    vector_t n = c->normal;
    double total = d1 + d2;
    a->v.x -= a->inverse_mass * total * n.x;
    a->v.y -= a->inverse_mass * total * n.y;
    a->w -= a->inverse_inertia * (d1 * p1->rn_a + d2 * p2->rn_a);
    b->v.x += b->inverse_mass * total * n.x;
    b->v.y += b->inverse_mass * total * n.y;
    b->w += b->inverse_inertia * (d1 * p1->rn_b + d2 * p2->rn_b);
    p1->normal_impulse = x1;
    p2->normal_impulse = x2;
}

/*
 * Both normal impulses at once: the linear complementarity problem
 * vn = K x + b', x >= 0, vn >= target, x (vn - target) = 0, solved by
 * enumerating its four cases (both active, either alone, none), as in Box2D.
 */
static inline void solve_normal_block(solver_contact_t *c, solver_velocity_t *a,
                                      solver_velocity_t *b) {
    solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
    double a1 = p1->normal_impulse, a2 = p2->normal_impulse;
    double b1 = relative_along(a, b, c->normal, p1->rn_a, p1->rn_b) - p1->target;
    double b2 = relative_along(a, b, c->normal, p2->rn_a, p2->rn_b) - p2->target;
    b1 -= c->k11 * a1 + c->k12 * a2;
    b2 -= c->k12 * a1 + c->k22 * a2;

    double x1 = -(c->m11 * b1 + c->m12 * b2), x2 = -(c->m12 * b1 + c->m22 * b2);
    if (x1 >= 0.0 && x2 >= 0.0) {
        apply_block(c, a, b, x1, x2);
        return;
    }
    x1 = -p1->normal_mass * b1;
    if (x1 >= 0.0 && c->k12 * x1 + b2 >= 0.0) {
        apply_block(c, a, b, x1, 0.0);
        return;
    }
    x2 = -p2->normal_mass * b2;
    if (x2 >= 0.0 && c->k12 * x2 + b1 >= 0.0) {
        apply_block(c, a, b, 0.0, x2);
        return;
    }
    if (b1 >= 0.0 && b2 >= 0.0) apply_block(c, a, b, 0.0, 0.0);
}

/* Works on copies of the two rows: the compiler then keeps them in
 * registers instead of reloading them after every store (it cannot prove
 * the rows and the contact do not alias). */
static void solve_velocity(solver_contact_t *c, solver_velocity_t *velocities) {
    solver_velocity_t a = velocities[c->a], b = velocities[c->b];
    solve_friction(c, &a, &b);
    if (c->block) {
        solve_normal_block(c, &a, &b);
    } else {
        for (int i = 0; i < c->point_count; i++) solve_normal_point(c, &a, &b, &c->points[i]);
    }
    velocities[c->a] = a;
    velocities[c->b] = b;
}

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
 * point: x = -approach / K). Points that take no part have NAN approach and
 * get 0; a point left for a later pass is set to NAN.
 */
static void compression_impulses(const solver_contact_t *c, double approach[2], double x[2]) {
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
    double x1 = -(c->m11 * b1 + c->m12 * b2), x2 = -(c->m12 * b1 + c->m22 * b2);
    if (x1 >= 0.0 && x2 >= 0.0) {
        x[0] = x1, x[1] = x2;
    } else if ((x1 = -c->points[0].normal_mass * b1) >= 0.0 && c->k12 * x1 + b2 >= 0.0) {
        x[0] = x1;
    } else if ((x2 = -c->points[1].normal_mass * b2) >= 0.0 && c->k12 * x2 + b1 >= 0.0) {
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
                           const solver_state_t *states, double dt, bool *impacts) {
    solver_velocity_t a = velocities[c->a], b = velocities[c->b];
    double threshold = bounce_threshold(c->restitution, &states[c->a], &states[c->b]);
    double approach[2] = {NAN, NAN};
    bool wanted = false;
    for (int i = 0; i < c->point_count; i++) {
        solver_point_t *p = &c->points[i];
        double vn = relative_along(&a, &b, c->normal, p->rn_a, p->rn_b);
        *impacts |= late_impact(c, p, vn, threshold, states, dt);
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
    compression_impulses(c, approach, x);
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
static bool collision_pass(solver_contact_t *contacts, size_t count, solver_velocity_t *velocities,
                           const solver_state_t *states, double dt, int passes) {
    bool impacts = false;
    for (int pass = 0; pass < passes; pass++) {
        bool applied = false;
        for (size_t i = 0; i < count; i++) {
            if (contacts[i].restitution > 0.0) {
                applied |= bounce_contact(&contacts[i], velocities, states, dt, &impacts);
            }
        }
        if (!applied) break;
    }
    return impacts;
}

static bool pushes(const solver_contact_t *c) {
    for (int i = 0; i < c->point_count; i++) {
        const solver_point_t *p = &c->points[i];
        if (p->normal_impulse > 0.0 || p->restitution_impulse > 0.0) return true;
    }
    return false;
}

static const uint32_t NO_PARTNER = UINT32_MAX;

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
    bool static_a = solver_row_is_static(&velocities[c->a]);
    bool static_b = solver_row_is_static(&velocities[c->b]);
    for (int i = 0; i < c->point_count; i++) {
        const solver_point_t *p = &c->points[i];
        if (p->impact_time < 0.0) continue;
        if (!static_a) mark_earliest(a, p, static_b ? NO_PARTNER : c->b, c->normal);
        if (!static_b) mark_earliest(b, p, static_a ? NO_PARTNER : c->a, vec_negate(c->normal));
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
static void advance(const solver_bodies_t *bodies, const solver_settings_t *s, size_t begin,
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

/*
 * One non-linear Gauss-Seidel pass over positions. The separation is
 * re-estimated from the displacements so far, to first order in the
 * rotation (a step turns a body by a small angle), and pushed back toward
 * minus the contact's slop by a fraction of the overlap. Only positions
 * move: no energy is added. solver_wide.c does the same four contacts at a
 * time.
 */
static void solve_position(const solver_contact_t *c, const solver_velocity_t *velocities,
                           solver_displacement_t *displacements) {
    solver_displacement_t *a = &displacements[c->a], *b = &displacements[c->b];
    double ma = velocities[c->a].inverse_mass, ia = velocities[c->a].inverse_inertia;
    double mb = velocities[c->b].inverse_mass, ib = velocities[c->b].inverse_inertia;
    double rate = solver_position_rate(&velocities[c->a], &velocities[c->b]);
    for (int i = 0; i < c->point_count; i++) {
        const solver_point_t *p = &c->points[i];
        double separation = p->separation + vec_dot(c->normal, vec_subtract(b->dx, a->dx)) +
                            b->dtheta * p->rn_b - a->dtheta * p->rn_a;
        double error = max_of(-SOLVER_MAX_POSITION_CORRECTION,
                              min_of(rate * (separation + c->slop), 0.0));
        double lambda = -error * p->normal_mass;
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

/* Caps what the position pass moved each body in this step (solver.h:
 * SOLVER_MAX_PUSH_SPEED). */
static void limit_corrections(const solver_bodies_t *bodies, double dt, size_t begin, size_t end) {
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

/* What preparing contacts found: an impact within the step, an elastic
 * contact. */
typedef struct {
    bool impact, elastic;
} prepared_t;

/* How many contacts ahead preparing asks for body b's rows: the contacts
 * come grouped by body a, so b is anywhere in the rows. */
enum { PREPARE_AHEAD = 4 };

static prepared_t prepare_range(solver_contact_t *contacts, const solver_anchor_t *anchors,
                                const solver_bodies_t *bodies, const solver_settings_t *settings,
                                size_t begin, size_t end) {
    prepared_t found = {false, false};
    for (size_t i = begin; i < end; i++) {
        if (i + PREPARE_AHEAD < end) {
            const solver_contact_t *ahead = &contacts[i + PREPARE_AHEAD];
            __builtin_prefetch(&bodies->states[ahead->b]);
            __builtin_prefetch((const char *)&bodies->states[ahead->b] + 64);
            __builtin_prefetch(&bodies->velocities[ahead->b]);
        }
        solver_contact_t *c = &contacts[i];
        found.impact |= prepare(c, &anchors[i], bodies->velocities, bodies->states, settings);
        found.elastic |= c->restitution > 0.0;
    }
    return found;
}

/* The loops over contacts and over bodies of solver_solve that the workers
 * share (scene_set_workers): each contact or body writes only its own, and
 * what preparing found is gathered per chunk and joined in chunk order. */
typedef struct {
    solver_contact_t *contacts;
    const solver_anchor_t *anchors;
    const solver_bodies_t *bodies;
    const solver_settings_t *settings;
    prepared_t found[WORKERS_MAX_CHUNKS];
} solve_split_t;

static void prepare_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    solve_split_t *split = context;
    split->found[chunk] =
        prepare_range(split->contacts, split->anchors, split->bodies, split->settings, begin, end);
}

static void advance_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const solve_split_t *split = context;
    (void)chunk;
    advance(split->bodies, split->settings, begin, end);
}

static void limit_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const solve_split_t *split = context;
    (void)chunk;
    limit_corrections(split->bodies, split->settings->dt, begin, end);
}

static prepared_t prepare_all(workers_t *workers, solve_split_t *split, size_t contact_count) {
    if (workers == NULL) {
        return prepare_range(split->contacts, split->anchors, split->bodies, split->settings, 0,
                             contact_count);
    }
    workers_for(workers, contact_count, prepare_chunk, split);
    prepared_t found = {false, false};
    for (size_t k = 0; k < workers_chunks(workers, contact_count); k++) {
        found.impact |= split->found[k].impact;
        found.elastic |= split->found[k].elastic;
    }
    return found;
}

/* fn over every body: on the workers when there are. */
static void for_bodies(workers_t *workers, solve_split_t *split, workers_fn_t fn) {
    size_t count = split->bodies->body_count;
    if (workers == NULL) {
        fn(split, 0, 0, count);
        return;
    }
    workers_for(workers, count, fn, split);
}

void solver_solve(solver_wide_t *wide, shock_t *shock, solver_contact_t *contacts,
                  const solver_anchor_t *anchors, size_t contact_count,
                  const solver_bodies_t *bodies, const solver_settings_t *settings) {
    solver_velocity_t *velocities = bodies->velocities;
    solve_split_t split = {contacts, anchors, bodies, settings, {{false, false}}};
    /* A step pays for the collision pass only with an elastic contact, and
     * for timing impacts only with an impact. */
    prepared_t found = prepare_all(wide->workers, &split, contact_count);
    bool any_elastic = found.elastic, any_impact = found.impact;
    /* Bounces before warm starting: last step's impulses, applied one by
     * one inside a deep pile, leave approaches above the threshold that no
     * impact made, and bouncing those kept a pile at e = 0.5 boiling. */
    if (any_elastic) {
        any_impact |= collision_pass(contacts, contact_count, velocities, bodies->states,
                                     settings->dt, settings->velocity_iterations);
    }
    solver_split_load(wide, contacts, contact_count, velocities, bodies->body_count);
    solver_split_warm_start(wide, velocities);
    for (size_t i = 0; i < wide->loose_count; i++) {
        warm_start(&contacts[wide->loose[i]], velocities);
    }
    /* Shock propagation before the last iteration, which then spreads its
     * pushes back over both bodies of each contact (shock.h). */
    int shock_after = settings->velocity_iterations > 1 ? settings->velocity_iterations - 1 : 1;
    for (int iteration = 1; iteration <= settings->velocity_iterations; iteration++) {
        solver_split_iterate(wide, velocities);
        for (size_t i = 0; i < wide->loose_count; i++) {
            solve_velocity(&contacts[wide->loose[i]], velocities);
        }
        if (iteration == shock_after) {
            shock_propagate(shock, wide, contacts, contact_count, velocities, bodies->body_count);
        }
    }
    solver_split_store(wide, contacts);
    for (size_t i = 0; any_impact && i < contact_count; i++) {
        mark_impacts(&contacts[i], velocities, bodies->states);
    }
    for_bodies(wide->workers, &split, advance_chunk);
    for (int iteration = 0; iteration < settings->position_iterations; iteration++) {
        solver_split_correct_positions(wide, bodies->displacements, iteration % 2 == 1);
        for (size_t i = 0; i < wide->loose_count; i++) {
            solve_position(&contacts[wide->loose[i]], velocities, bodies->displacements);
        }
    }
    for_bodies(wide->workers, &split, limit_chunk);
}
