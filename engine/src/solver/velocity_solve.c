#include "solver/velocity_solve.h"
#include <math.h>
#include "base/scalar.h"
#include "solver/contact_point.h"
#include "solver/resting.h"

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

/*
 * Whether a touching point's start approach vn (< 0) is a resting one: no
 * faster than one step of the stronger pull on its bodies (dt times the
 * larger acceleration of their free motions), the load a solve can have
 * left short. The share of it the step's motion carries, (1 - w) dt vn, is
 * then undone within the step (the target is raised to -(1 - w) vn / w)
 * and the relaxation (solver.c) takes that push back out of the end
 * velocity once the bodies have moved. A faster approach is an arrival
 * (and the collision pass bounces one faster than its threshold): raised, a
 * ball landing beside a wall rose along it in the solve, the
 * wall's friction met that rise and the ball rolled away (3 mm).
 * Only the start velocity's share: a spring's pull in the drift, undone
 * too, held a multi-stage scheme to order 2.
 */
static inline bool resting_approach(double vn, const solver_state_t *sa,
                                    const solver_state_t *sb, const solver_settings_t *s) {
    if (vn >= 0.0) return false;
    double pull = vec_get_length(sa->acceleration) + vec_get_length(sb->acceleration);
    return vn >= -min_of(s->dt * pull, s->restitution_threshold);
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
                       const solver_settings_t *settings, bool *raised) {
    double dt = settings->dt, w = settings->position_weight;
    vector_t start = vec_subtract(point_velocity(sb->v_start, sb->w_start, r_b),
                                  point_velocity(sa->v_start, sa->w_start, r_a));
    double vn_start = vec_dot(normal, start);
    p->impact_time = -1.0;
    p->impact_offset = NAN;
    p->lands = false;
    p->restitution_impulse = 0.0;
    p->restitution_tangent_impulse = 0.0;
    p->touched = p->separation <= 0.0;
    if (p->separation <= 0.0) {
        p->target = 0.0;
        if (w > 0.0 && w < 1.0 && resting_approach(vn_start, sa, sb, settings)) {
            p->target = -(1.0 - w) * vn_start / w;
            *raised = true;
        }
        return false;
    }
    vector_t drift = vec_subtract(point_velocity(sb->drift, sb->spin_drift, r_b),
                                  point_velocity(sa->drift, sa->spin_drift, r_a));
    double an = vec_dot(normal, vec_subtract(sb->acceleration, sa->acceleration));
    double tau = time_of_impact(p->separation, vn_start, an, dt);
    double vi = tau >= 0.0 ? vn_start + an * tau : 0.0;
    /* With w = 0 the end velocity does not move the body this step; only an
     * impact, timed, does. */
    double closing =
        w > 0.0 ? min_of((-p->separation / dt - vec_dot(normal, drift)) / w, 0.0) : -INFINITY;
    if (tau >= 0.0 && vi < -bounce_threshold(restitution, sa, sb, settings->restitution_threshold)) {
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
                               const solver_state_t *sb, double threshold) {
    return bounce_threshold(restitution, sa, sb, threshold);
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

bool solver_contact_blocks(const solver_contact_t *c, const solver_anchor_t *anchor,
                          const solver_velocity_t *a, const solver_velocity_t *b) {
    if (c->point_count != 2) return false;
    /* The lever terms preparing finds, so K has solver_contact_k's bits. */
    vector_t n = c->normal;
    double rn_a[2] = {vec_cross(anchor->r_a[0], n), vec_cross(anchor->r_a[1], n)};
    double rn_b[2] = {vec_cross(anchor->r_b[0], n), vec_cross(anchor->r_b[1], n)};
    solver_block_k_t k = solver_block_k(a, b, rn_a, rn_b);
    double det = k.k11 * k.k22 - k.k12 * k.k12;
    double condition = c->edge_ends ? MAX_EDGE_CONDITION_NUMBER : MAX_CONDITION_NUMBER;
    return k.k11 * k.k11 < condition * det;
}

bool solver_prepare_contact(solver_contact_t *c, const solver_anchor_t *anchor,
                            const solver_bodies_t *bodies, const solver_settings_t *s,
                            bool *raised) {
    const solver_state_t *states = bodies->states;
    const solver_velocity_t *a = &bodies->velocities[c->a], *b = &bodies->velocities[c->b];
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
                             &states[c->a], &states[c->b], s, raised);
    }
    if (c->point_count == 2) same_impact_moment(c, s->dt);
    c->impact = impact;
    c->rests = resting_of(c, states[c->a].acceleration, states[c->b].acceleration);
    if (c->block) {
        solver_block_k_t k = solver_contact_k(c, a, b);
        double inv = 1.0 / (k.k11 * k.k22 - k.k12 * k.k12);
        c->m11 = inv * k.k22;
        c->m12 = -inv * k.k12;
        c->m22 = inv * k.k11;
    }
    return impact;
}

void solver_warm_start(const solver_contact_t *c, solver_velocity_t *velocities) {
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
        /* The raised part of the normal impulse (set_target) gives no friction. */
        double pressed = p->normal_impulse - p->normal_mass * max_of(p->target, 0.0);
        double limit = c->friction * max_of(pressed, 0.0);
        double total = max_of(-limit, min_of(p->tangent_impulse - p->tangent_mass * vt, limit));
        double delta = total - p->tangent_impulse;
        p->tangent_impulse = total;
        apply_along(a, b, tangent, p->rt_a, p->rt_b, delta);
    }
}

/* relaxed: a raised target counts as 0 (the relaxation, solver.c). */
static inline double target_of(const solver_point_t *p, bool relaxed) {
    return relaxed ? min_of(p->target, 0.0) : p->target;
}

static inline void solve_normal_point(const solver_contact_t *c, solver_velocity_t *a,
                                      solver_velocity_t *b, solver_point_t *p, bool relaxed) {
    double vn = relative_along(a, b, c->normal, p->rn_a, p->rn_b);
    double total = max_of(p->normal_impulse - p->normal_mass * (vn - target_of(p, relaxed)), 0.0);
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

/* Both normal impulses at once: the complementarity problem
 * vn = K x + b', x >= 0, vn >= target, x (vn - target) = 0
 * (solve_block_cases). */
static inline void solve_normal_block(solver_contact_t *c, solver_velocity_t *a,
                                      solver_velocity_t *b, bool relaxed) {
    solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
    double a1 = p1->normal_impulse, a2 = p2->normal_impulse;
    double b1 = relative_along(a, b, c->normal, p1->rn_a, p1->rn_b) - target_of(p1, relaxed);
    double b2 = relative_along(a, b, c->normal, p2->rn_a, p2->rn_b) - target_of(p2, relaxed);
    solver_block_k_t k = solver_contact_k(c, a, b);
    b1 -= k.k11 * a1 + k.k12 * a2;
    b2 -= k.k12 * a1 + k.k22 * a2;
    double x1, x2;
    if (solve_block_cases(c, k.k12, b1, b2, &x1, &x2)) apply_block(c, a, b, x1, x2);
}

static inline void solve_normals(solver_contact_t *c, solver_velocity_t *a,
                                 solver_velocity_t *b, bool relaxed) {
    if (c->block) {
        solve_normal_block(c, a, b, relaxed);
        return;
    }
    for (int i = 0; i < c->point_count; i++) solve_normal_point(c, a, b, &c->points[i], relaxed);
}

/* Works on copies of the two rows: the compiler then keeps them in
 * registers instead of reloading them after every store (it cannot prove
 * the rows and the contact do not alias). */
void solver_solve_velocity(solver_contact_t *c, solver_velocity_t *velocities) {
    solver_velocity_t a = velocities[c->a], b = velocities[c->b];
    solve_friction(c, &a, &b);
    solve_normals(c, &a, &b, false);
    velocities[c->a] = a;
    velocities[c->b] = b;
}

void solver_relax_velocity(solver_contact_t *c, solver_velocity_t *velocities) {
    solver_velocity_t a = velocities[c->a], b = velocities[c->b];
    solve_normals(c, &a, &b, true);
    velocities[c->a] = a;
    velocities[c->b] = b;
}
