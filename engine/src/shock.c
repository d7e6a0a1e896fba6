#include "shock.h"
#include <math.h>
#include <string.h>
#include "memory.h"

static const uint32_t UNREACHED = UINT32_MAX;
static const uint32_t NO_SIDE = UINT32_MAX;
/* The sign of a side, -1 seen from a and +1 from b: looked up, since
 * which one it is is random and a branch on it mispredicted. */
static const double SIGN[2] = {-1.0, 1.0};

void shock_free(shock_t *shock) {
    memory_free(shock->level);
    memory_free(shock->first);
    memory_free(shock->sides);
    memory_free(shock->queue);
    memory_free(shock->held);
    memory_free(shock->impulses);
    memset(shock, 0, sizeof *shock);
}

/* Whether the iterations pressed either point (a one-point contact's
 * second impulse is 0 in the compact array). */
static bool carries_load(const solver_impulses_t *c) {
    return (c->normal_impulse[0] > 0.0) | (c->normal_impulse[1] > 0.0);
}

/*
 * Lists each body's load-bearing contacts, one pass over the contacts:
 * contact i's sides are 2i (seen from a) and 2i + 1 (from b), each pushed
 * on its body's list. Walking the contacts from the last makes every list
 * come out in contact order, the order the supports are solved in. Returns
 * whether any contact carries load.
 */
static bool link_bodies(shock_t *shock, const solver_impulses_t *contacts, size_t count,
                        size_t body_count) {
    uint32_t *first = shock->first;
    shock_side_t *sides = shock->sides;
    memset(first, 0xff, body_count * sizeof(uint32_t)); /* NO_SIDE */
    bool any = false;
    for (size_t i = count; i-- > 0;) {
        const solver_impulses_t *c = &contacts[i];
        if (!carries_load(c)) continue;
        uint32_t side = 2 * (uint32_t)i; /* fits: 2^31 contacts would not fit in memory */
        sides[side] = (shock_side_t){first[c->a], c->b};
        first[c->a] = side;
        sides[side + 1] = (shock_side_t){first[c->b], c->a};
        first[c->b] = side + 1;
        any = true;
    }
    return any;
}

/* The relative normal velocity of b over a at point p, less its target:
 * below zero, the point approaches. Measured from a and b, not from the
 * upper body and the sign: negating a difference is exact (but for the
 * sign of a zero, which no test or sum below tells apart), and a choice
 * of lever terms by the sign was a branch that mispredicted. */
static double approach(const solver_contact_t *c, const solver_point_t *p,
                       const solver_velocity_t *a, const solver_velocity_t *b) {
    double at_b = vec_dot(c->normal, b->v) + b->w * p->rn_b;
    double at_a = vec_dot(c->normal, a->v) + a->w * p->rn_a;
    return (at_b - at_a) - p->target;
}

/* The upper body's lever term along the normal at p, picked by address:
 * a pick of the value was a branch. */
static double upper_rn(const solver_point_t *p, bool upper_is_b) {
    const double *rn = upper_is_b ? &p->rn_b : &p->rn_a;
    return *rn;
}

/* Normal impulses x1, x2 at the points, lever terms rn1, rn2 of the upper
 * body, applied to it. */
static void push_upper(const solver_contact_t *c, solver_velocity_t *upper, bool upper_is_b,
                       double x1, double x2, double rn1, double rn2) {
    double sign = SIGN[upper_is_b], total = x1 + x2;
    upper->v = vec_add(upper->v, vec_multiply(sign * upper->inverse_mass * total, c->normal));
    upper->w += sign * upper->inverse_inertia * (x1 * rn1 + x2 * rn2);
}

/* The impulse along the normal that stops the upper body's approach at a
 * one-point contact, the lower body (the other of a, b) held still. */
static void stop_one(const solver_contact_t *c, solver_velocity_t *a, solver_velocity_t *b,
                     bool upper_is_b) {
    const solver_point_t *p = &c->points[0];
    double gap = approach(c, p, a, b);
    if (gap >= 0.0) return;
    solver_velocity_t *upper = upper_is_b ? b : a;
    double rn = upper_rn(p, upper_is_b);
    double k = upper->inverse_mass + upper->inverse_inertia * rn * rn;
    double x = k > 0.0 ? -gap / k : 0.0;
    push_upper(c, upper, upper_is_b, x, 0.0, rn, 0.0);
}

/* The impulses along the normal that stop the upper body's approach at a
 * two-point contact, the lower body held still: the same LCP as the
 * iterations' block solve, from zero. */
static void stop_two(const solver_contact_t *c, solver_velocity_t *a, solver_velocity_t *b,
                     bool upper_is_b) {
    const solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
    double gap1 = approach(c, p1, a, b), gap2 = approach(c, p2, a, b);
    if (gap1 >= 0.0 && gap2 >= 0.0) return;
    solver_velocity_t *upper = upper_is_b ? b : a;
    double m = upper->inverse_mass, ii = upper->inverse_inertia;
    double rn1 = upper_rn(p1, upper_is_b), rn2 = upper_rn(p2, upper_is_b);
    double k11 = m + ii * rn1 * rn1, k22 = m + ii * rn2 * rn2, k12 = m + ii * rn1 * rn2;
    double det = k11 * k22 - k12 * k12;
    double x1 = det > 1e-12 * k11 * k22 ? (k12 * gap2 - k22 * gap1) / det : -1.0;
    double x2 = det > 1e-12 * k11 * k22 ? (k12 * gap1 - k11 * gap2) / det : -1.0;
    if (x1 >= 0.0 && x2 >= 0.0) {
        push_upper(c, upper, upper_is_b, x1, x2, rn1, rn2);
    } else if (gap1 < 0.0 && k11 > 0.0 && gap2 - k12 * gap1 / k11 >= 0.0) {
        push_upper(c, upper, upper_is_b, -gap1 / k11, 0.0, rn1, rn2);
    } else if (gap2 < 0.0 && k22 > 0.0 && gap1 - k12 * gap2 / k22 >= 0.0) {
        push_upper(c, upper, upper_is_b, 0.0, -gap2 / k22, rn1, rn2);
    } else {
        push_upper(c, upper, upper_is_b, 0.0, 0.0, rn1, rn2);
    }
}

/*
 * The upper body moved with the lower one as one rigid body (both points
 * of a two-point contact touching and held, no sliding), when the impulses
 * that takes, added to the iterations' at each point, press (>= 0) and stay
 * within the friction cone. Returns false, changing nothing, when they would not: the contact
 * is then opening, tipping or sliding, and only its approach is stopped.
 */
static bool weld_upper(const solver_contact_t *c, const solver_impulses_t *imp,
                       solver_velocity_t *upper,
                       const solver_velocity_t *lower, double sign) {
    if (upper->inverse_mass <= 0.0 || upper->inverse_inertia <= 0.0) return false;
    const solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
    /* Only faces in touch: a gap the step may close is no support yet,
     * and welding across it left a landed box hovering (measured). */
    if (p1->separation > 0.0 || p2->separation > 0.0) return false;
    bool b_upper = sign > 0.0;
    double rn1 = b_upper ? p1->rn_b : p1->rn_a, rn2 = b_upper ? p2->rn_b : p2->rn_a;
    double rt1 = b_upper ? p1->rt_b : p1->rt_a, rt2 = b_upper ? p2->rt_b : p2->rt_a;
    if (fabs(rn1 - rn2) < 1e-9) return false;
    vector_t n = c->normal, t = vec_perpendicular(n);
    /* From the lower centroid to the upper one, through point 1's lever
     * arms (r = (r x t) n - (r x n) t in the contact frame). */
    double lower_rn1 = b_upper ? p1->rn_a : p1->rn_b, lower_rt1 = b_upper ? p1->rt_a : p1->rt_b;
    vector_t r_lower = vec_subtract(vec_multiply(lower_rt1, n), vec_multiply(lower_rn1, t));
    vector_t r_upper = vec_subtract(vec_multiply(rt1, n), vec_multiply(rn1, t));
    vector_t offset = vec_subtract(r_lower, r_upper);
    vector_t target_v = vec_add(lower->v, (vector_t){-lower->w * offset.y, lower->w * offset.x});
    vector_t impulse = vec_multiply(1.0 / upper->inverse_mass, vec_subtract(target_v, upper->v));
    double moment = (lower->w - upper->w) / upper->inverse_inertia;
    /* Per point: the tangential impulse shared equally, the normal ones
     * from the total and the moment. */
    double jn = sign * vec_dot(impulse, n), jt = sign * vec_dot(impulse, t);
    double turn = sign * moment - 0.5 * jt * (rt1 + rt2);
    double n1 = (turn - rn2 * jn) / (rn1 - rn2), n2 = jn - n1;
    double pressed1 = imp->normal_impulse[0] + n1, pressed2 = imp->normal_impulse[1] + n2;
    if (!(pressed1 >= 0.0 && pressed2 >= 0.0)) return false;
    if (fabs(imp->tangent_impulse[0] + 0.5 * jt) > c->friction * pressed1) return false;
    if (fabs(imp->tangent_impulse[1] + 0.5 * jt) > c->friction * pressed2) return false;
    upper->v = target_v;
    upper->w = lower->w;
    return true;
}

/* body's contacts with the level below (its sides held[0 .. count)), each
 * solved with the lower body held still; welded when it is the only one
 * (a column), since a body held by two is pulled two ways. */
static void hold_up(const shock_t *shock, const solver_contact_t *contacts, uint32_t body,
                    const uint32_t *held, uint32_t count, solver_velocity_t *velocities) {
    for (uint32_t k = 0; k < count; k++) {
        uint32_t side = held[k];
        const solver_contact_t *c = &contacts[side / 2];
        bool upper_is_b = side % 2 == 1; /* the odd side is b's */
        solver_velocity_t *upper = &velocities[body];
        solver_velocity_t *lower = &velocities[shock->sides[side].other];
        solver_velocity_t *a = upper_is_b ? lower : upper, *b = upper_is_b ? upper : lower;
        if (c->point_count == 1) {
            stop_one(c, a, b, upper_is_b);
        } else if (count != 1 ||
                   !weld_upper(c, &shock->impulses[side / 2], upper, lower, SIGN[upper_is_b])) {
            stop_two(c, a, b, upper_is_b);
        }
    }
}

/*
 * Breadth first from every static body; each body is held up by its
 * supports as it leaves the queue. That is level by level from the ground
 * up: the bodies of the level below all left the queue before it, so their
 * velocities are final, and they were all reached (given their levels)
 * while the level below them left it, so the supports are known too.
 *
 * The walk over a body's sides has no branch but the loop's: whether a
 * neighbour is below, level or unreached is random in a pile, and
 * mispredicting it cost more than the stores done regardless.
 */
static void propagate(shock_t *shock, const solver_contact_t *contacts,
                      solver_velocity_t *velocities, size_t body_count) {
    uint32_t *level = shock->level, *queue = shock->queue, *held = shock->held;
    const shock_side_t *sides = shock->sides;
    size_t head = 0, tail = 0;
    for (size_t k = 0; k < body_count; k++) {
        level[k] = solver_row_is_static(&velocities[k]) ? 0 : UNREACHED;
        if (level[k] == 0) queue[tail++] = (uint32_t)k;
    }
    while (head < tail) {
        uint32_t body = queue[head++], here = level[body];
        uint32_t supports = 0;
        for (uint32_t side = shock->first[body]; side != NO_SIDE; side = sides[side].next) {
            uint32_t other = sides[side].other, there = level[other];
            /* The lines of the contact hold_up reads. A body's supports
             * are seen a level before it is held up, as the bodies below
             * leave the queue; a pile of 4000 bodies has more contacts
             * than the cache holds, and fetching them now took a tenth
             * off the pass (measured). Written out here: GCC deems a
             * function of prefetches alone const and drops its calls. */
            const char *c = (const char *)&contacts[side / 2];
            __builtin_prefetch(c + offsetof(solver_contact_t, point_count));
            __builtin_prefetch(c + offsetof(solver_contact_t, points[0].rn_a));
            __builtin_prefetch(c + offsetof(solver_contact_t, points[0].separation));
            __builtin_prefetch(c + offsetof(solver_contact_t, points[1].rn_a));
            __builtin_prefetch(c + offsetof(solver_contact_t, points[1].separation));
            held[supports] = side; /* kept when it is a support */
            supports += there < here;
            /* Neighbours differ by a level at most, so this reaches the
             * unreached and leaves the rest. */
            level[other] = there < here + 1 ? there : here + 1;
            queue[tail] = other; /* kept when it was unreached */
            tail += there >> 31; /* only UNREACHED has the top bit: levels < bodies */
        }
        if (supports > 0) hold_up(shock, contacts, body, held, supports, velocities);
    }
}

/* Every contact's bodies and impulses so far in one compact array: the
 * batches' from their lanes, the loose contacts' from the contacts. */
static void gather_impulses(shock_t *shock, const solver_wide_t *wide,
                            const solver_contact_t *contacts, size_t count) {
    memory_reserve((void **)&shock->impulses, &shock->impulse_capacity, count,
                   sizeof(solver_impulses_t));
    solver_wide_gather_impulses(wide, shock->impulses);
    for (size_t k = 0; k < wide->loose_count; k++) {
        const solver_contact_t *c = &contacts[wide->loose[k]];
        solver_impulses_t *out = &shock->impulses[wide->loose[k]];
        out->a = c->a;
        out->b = c->b;
        out->normal_impulse[0] = c->points[0].normal_impulse;
        out->tangent_impulse[0] = c->points[0].tangent_impulse;
        out->normal_impulse[1] = c->point_count == 2 ? c->points[1].normal_impulse : 0.0;
        out->tangent_impulse[1] = c->point_count == 2 ? c->points[1].tangent_impulse : 0.0;
    }
}

void shock_propagate(shock_t *shock, const solver_wide_t *wide, const solver_contact_t *contacts,
                     size_t count, solver_velocity_t *velocities, size_t body_count) {
    if (count == 0) return;
    gather_impulses(shock, wide, contacts, count);
    memory_reserve((void **)&shock->level, &shock->level_capacity, body_count, sizeof(uint32_t));
    memory_reserve((void **)&shock->first, &shock->first_capacity, body_count, sizeof(uint32_t));
    memory_reserve((void **)&shock->sides, &shock->side_capacity, 2 * count,
                   sizeof(shock_side_t));
    /* One more than can be kept, for the stores done regardless. */
    memory_reserve((void **)&shock->queue, &shock->queue_capacity, body_count + 1,
                   sizeof(uint32_t));
    memory_reserve((void **)&shock->held, &shock->held_capacity, count + 1, sizeof(uint32_t));
    if (!link_bodies(shock, shock->impulses, count, body_count)) return;
    propagate(shock, contacts, velocities, body_count);
}
