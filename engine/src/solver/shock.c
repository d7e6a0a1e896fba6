#include "solver/shock.h"
#include <math.h>
#include <string.h>
#include "base/memory.h"
#include "base/workers.h"
#include "solver/position_pass.h"
#include "solver/resting.h"

static const uint32_t UNREACHED = UINT32_MAX;
/* The slot of a loose contact: its impulses are in the contact. */
static const solver_slot_t IN_CONTACT = UINT32_MAX;
/* The sign of a side, -1 seen from a and +1 from b: looked up, since
 * which one it is is random and a branch on it mispredicted. */
static const double SIGN[2] = {-1.0, 1.0};

static void free_levels(shock_levels_t *levels) {
    memory_free(levels->level);
    memory_free(levels->first);
    memory_free(levels->sides);
    memory_free(levels->queue);
    memory_free(levels->held);
    memory_free(levels->support_end);
}

void shock_free(shock_t *shock) {
    free_levels(&shock->load);
    free_levels(&shock->rest);
    memory_free(shock->slots);
    memory_free(shock->jointed);
    memset(shock, 0, sizeof *shock);
}

/* Whether the iterations pressed either point of a contact solved on its
 * own (not in a batch). */
static bool carries_load(const solver_contact_t *c) {
    return c->points[0].normal_impulse > 0.0 ||
           (c->point_count == 2 && c->points[1].normal_impulse > 0.0);
}

/*
 * Lists each body's load-bearing contacts: contact i's sides are 2i (seen
 * from a) and 2i + 1 (from b), each pushed on its body's list, the batched
 * contacts' straight from the batches' impulses (solver_wide_link_loaded),
 * then the loose ones'. The lists are in no particular order; hold_up puts
 * a body's supports in contact order. Returns whether any contact carries
 * load.
 */
static bool link_bodies(shock_t *shock, const solver_wide_t *wide,
                        const solver_contact_t *contacts, size_t body_count) {
    uint32_t *first = shock->load.first;
    solver_side_t *sides = shock->load.sides;
    memset(first, 0xff, body_count * sizeof(uint32_t)); /* SOLVER_NO_SIDE */
    bool any = solver_wide_link_loaded(wide, first, sides, shock->slots);
    for (size_t k = 0; k < wide->loose_count; k++) {
        uint32_t i = wide->loose[k];
        const solver_contact_t *c = &contacts[i];
        if (!carries_load(c)) continue;
        solver_link_sides(first, sides, i, c->a, c->b);
        shock->slots[i] = IN_CONTACT;
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
    /* A touching point's target only undoes its start drift (set_target):
     * no load to carry, and lifting each level by it lifted the level above
     * by the sum (pyramid(40)'s top drifted 0.24 m instead of 0.05 m). */
    double target = p->separation <= 0.0 ? 0.0 : p->target;
    return (at_b - at_a) - target;
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

/* The push x >= 0 at one point (lever term rn of the upper body) that
 * brings it to its target, gap short of it where negative, the upper body
 * alone moving; 0 when it cannot move there. */
static double solve_one(const solver_velocity_t *upper, double rn, double gap) {
    double k = upper->inverse_mass + upper->inverse_inertia * rn * rn;
    return gap < 0.0 && k > 0.0 ? -gap / k : 0.0;
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
    push_upper(c, upper, upper_is_b, solve_one(upper, rn, gap), 0.0, rn, 0.0);
}

/* The pushes x1, x2 >= 0 at two points (lever terms rn1, rn2 of the upper
 * body) that bring neither below its target, gap1 and gap2 short of it
 * where negative, the upper body alone moving: the same LCP as the
 * iterations' block solve, from zero. Both 0 when no case holds. */
static void solve_upper(const solver_velocity_t *upper, double rn1, double rn2, double gap1,
                        double gap2, double *x1, double *x2) {
    double m = upper->inverse_mass, ii = upper->inverse_inertia;
    double k11 = m + ii * rn1 * rn1, k22 = m + ii * rn2 * rn2, k12 = m + ii * rn1 * rn2;
    double det = k11 * k22 - k12 * k12;
    *x1 = det > 1e-12 * k11 * k22 ? (k12 * gap2 - k22 * gap1) / det : -1.0;
    *x2 = det > 1e-12 * k11 * k22 ? (k12 * gap1 - k11 * gap2) / det : -1.0;
    if (*x1 >= 0.0 && *x2 >= 0.0) return;
    *x1 = *x2 = 0.0;
    if (gap1 < 0.0 && k11 > 0.0 && gap2 - k12 * gap1 / k11 >= 0.0) {
        *x1 = -gap1 / k11;
    } else if (gap2 < 0.0 && k22 > 0.0 && gap1 - k12 * gap2 / k22 >= 0.0) {
        *x2 = -gap2 / k22;
    }
}

/* The impulses along the normal that stop the upper body's approach at a
 * two-point contact, the lower body held still. */
static void stop_two(const solver_contact_t *c, solver_velocity_t *a, solver_velocity_t *b,
                     bool upper_is_b) {
    const solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
    double gap1 = approach(c, p1, a, b), gap2 = approach(c, p2, a, b);
    if (gap1 >= 0.0 && gap2 >= 0.0) return;
    solver_velocity_t *upper = upper_is_b ? b : a;
    double rn1 = upper_rn(p1, upper_is_b), rn2 = upper_rn(p2, upper_is_b);
    double x1, x2;
    solve_upper(upper, rn1, rn2, gap1, gap2, &x1, &x2);
    push_upper(c, upper, upper_is_b, x1, x2, rn1, rn2);
}

/* Twice the kinetic energy of a body of the row's masses moving at v, w. */
static double doubled_energy(const solver_velocity_t *row, vector_t v, double w) {
    return vec_dot(v, v) / row->inverse_mass + w * w / row->inverse_inertia;
}

/*
 * The upper body moved with the lower one as one rigid body (both points
 * of a two-point contact touching and held, no sliding), when the impulses
 * that takes, added to the iterations' at each point, press (>= 0) and stay
 * within the friction cone, and leave the upper body no more kinetic
 * energy than it had. Returns false, changing nothing, when they would
 * not: the contact is then opening, tipping or sliding, and only its
 * approach is stopped. The lower body gets nothing back, so a weld that
 * sped the upper one up made momentum from nothing: a box at rest on one
 * sliding over ice took its speed at once, and a column in a pile kept
 * swaying for seconds (docs/design.md, Shock propagation).
 */
static bool weld_upper(const solver_contact_t *c, const double normal_impulse[2],
                       const double tangent_impulse[2], solver_velocity_t *upper,
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
    double pressed1 = normal_impulse[0] + n1, pressed2 = normal_impulse[1] + n2;
    if (!(pressed1 >= 0.0 && pressed2 >= 0.0)) return false;
    if (fabs(tangent_impulse[0] + 0.5 * jt) > c->friction * pressed1) return false;
    if (fabs(tangent_impulse[1] + 0.5 * jt) > c->friction * pressed2) return false;
    if (doubled_energy(upper, target_v, lower->w) > doubled_energy(upper, upper->v, upper->w)) {
        return false;
    }
    upper->v = target_v;
    upper->w = lower->w;
    return true;
}

/* The accumulated impulses so far of the two-point contact of side: in the
 * batches, or in the contact for a loose one. */
static void impulses_of(const shock_t *shock, const solver_wide_t *wide,
                        const solver_contact_t *c, uint32_t side, double normal[2],
                        double tangent[2]) {
    solver_slot_t slot = shock->slots[side / 2];
    if (slot != IN_CONTACT) {
        solver_wide_impulses(wide, slot, c->point_count, normal, tangent);
        return;
    }
    for (int k = 0; k < c->point_count; k++) {
        normal[k] = c->points[k].normal_impulse;
        tangent[k] = c->points[k].tangent_impulse;
    }
}

/* Sides in increasing order, which is contact order (a body has one side
 * per contact), or in decreasing order when reverse: insertion sort, as a
 * body has a handful of supports. Flipping every bit of a side flips its
 * order. */
static void sort_sides(uint32_t *held, uint32_t count, bool reverse) {
    uint32_t flip = reverse ? UINT32_MAX : 0;
    for (uint32_t k = 1; k < count; k++) {
        uint32_t side = held[k], j = k;
        for (; j > 0 && (held[j - 1] ^ flip) > (side ^ flip); j--) held[j] = held[j - 1];
        held[j] = side;
    }
}

/* The lines of the contact that hold_up reads. Written out here: GCC
 * deems a function of prefetches alone const and drops its calls. */
#define PREFETCH_CONTACT(c)                                                          \
    do {                                                                             \
        const char *line_ = (const char *)(c);                                       \
        __builtin_prefetch(line_ + offsetof(solver_contact_t, point_count));         \
        __builtin_prefetch(line_ + offsetof(solver_contact_t, points[0].rn_a));      \
        __builtin_prefetch(line_ + offsetof(solver_contact_t, points[0].separation)); \
        __builtin_prefetch(line_ + offsetof(solver_contact_t, points[1].rn_a));      \
        __builtin_prefetch(line_ + offsetof(solver_contact_t, points[1].separation)); \
    } while (0)

/* How many supports ahead hold_up's contacts are fetched: a pile of 4000
 * bodies has more contacts than the cache holds. */
enum { PREFETCH_AHEAD = 8 };

/* body's contacts with the level below (its sides held[0 .. count)), each
 * solved with the lower body held still, in contact order (reversed when
 * reverse); welded when it is the only one (a column), since a body held
 * by two is pulled two ways. */
static void hold_up(const shock_t *shock, const solver_wide_t *wide,
                    const solver_contact_t *contacts, uint32_t body, uint32_t *held,
                    uint32_t count, uint32_t readable, solver_velocity_t *velocities,
                    bool reverse) {
    if (count > 1) sort_sides(held, count, reverse);
    for (uint32_t k = 0; k < count; k++) {
        uint32_t side = held[k];
        if (k + PREFETCH_AHEAD < readable) {
            PREFETCH_CONTACT(&contacts[held[k + PREFETCH_AHEAD] / 2]);
        }
        const solver_contact_t *c = &contacts[side / 2];
        bool upper_is_b = side % 2 == 1; /* the odd side is b's */
        solver_velocity_t *upper = &velocities[body];
        solver_velocity_t *lower = &velocities[shock->load.sides[side].other];
        solver_velocity_t *a = upper_is_b ? lower : upper, *b = upper_is_b ? upper : lower;
        if (c->point_count == 1) {
            stop_one(c, a, b, upper_is_b);
            continue;
        }
        if (count == 1) {
            double normal[2], tangent[2];
            impulses_of(shock, wide, c, side, normal, tangent);
            if (weld_upper(c, normal, tangent, upper, lower, SIGN[upper_is_b])) continue;
        }
        stop_two(c, a, b, upper_is_b);
    }
}

/*
 * Breadth first from every static body: each body's level, and its
 * supports (its sides to the level below) in held, those of queue[q] at
 * held[support_end[q - 1] .. support_end[q]). Returns how many bodies the
 * queue holds.
 *
 * The walk over a body's sides has no branch but the loop's: whether a
 * neighbour is below, level or unreached is random in a pile, and
 * mispredicting it cost more than the stores done regardless.
 */
static size_t find_levels(shock_levels_t *levels, const solver_velocity_t *velocities,
                          size_t body_count) {
    uint32_t *level = levels->level, *queue = levels->queue, *held = levels->held;
    uint32_t *support_end = levels->support_end;
    const uint32_t *first = levels->first;
    const solver_side_t *sides = levels->sides;
    size_t head = 0, tail = 0;
    for (size_t k = 0; k < body_count; k++) {
        level[k] = solver_row_is_static(&velocities[k]) ? 0 : UNREACHED;
        if (level[k] == 0) queue[tail++] = (uint32_t)k;
    }
    uint32_t supports = 0;
    for (; head < tail; head++) {
        uint32_t body = queue[head], here = level[body];
        for (uint32_t side = first[body]; side != SOLVER_NO_SIDE; side = sides[side].next) {
            uint32_t other = sides[side].other, there = level[other];
            held[supports] = side; /* kept when it is a support */
            supports += there < here;
            /* Neighbours differ by a level at most, so this reaches the
             * unreached and leaves the rest. */
            level[other] = there < here + 1 ? there : here + 1;
            queue[tail] = other; /* kept when it was unreached */
            tail += there >> 31; /* only UNREACHED has the top bit: levels < bodies */
        }
        support_end[head] = supports;
    }
    /* What hold_up fetches ahead past the last support: a contact it has. */
    for (uint32_t k = 0; k < PREFETCH_AHEAD; k++) held[supports + k] = supports > 0 ? held[0] : 0;
    return tail;
}

/* The bodies queue[begin .. end) held up, each by its supports: hold_up may
 * read ahead in held as far as the last of these bodies' supports, plus
 * `past` entries beyond. */
static void hold_up_range(shock_t *shock, const solver_wide_t *wide,
                          const solver_contact_t *contacts, solver_velocity_t *velocities,
                          size_t begin, size_t end, uint32_t past, bool reverse) {
    const shock_levels_t *load = &shock->load;
    uint32_t start = begin > 0 ? load->support_end[begin - 1] : 0;
    uint32_t last = end > 0 ? load->support_end[end - 1] + past : 0;
    for (size_t q = begin; q < end; q++) {
        uint32_t stop = load->support_end[q];
        if (stop == start) continue;
        hold_up(shock, wide, contacts, load->queue[q], load->held + start, stop - start,
                last - start, velocities, reverse);
        start = stop;
    }
}

/* A level of this many bodies or more is spread over the workers: below
 * it, the call costs more than the bodies. */
enum { SPLIT_LEVEL = 64 };

/* Does the work of the queue's bodies [begin, end). */
typedef void (*level_range_t)(void *context, size_t begin, size_t end);

typedef struct {
    level_range_t range;
    void *context;
    size_t first; /* the level's first place in the queue */
} level_split_t;

static void level_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const level_split_t *split = context;
    (void)chunk;
    split->range(split->context, split->first + begin, split->first + end);
}

/* range over the queue's bodies [0, reached), level after level, each
 * level of SPLIT_LEVEL bodies or more over the workers: a body's work
 * changes only its own row and reads its supports', all of lower levels,
 * so the bodies of a level may go in any order with the same result. */
static void over_levels(const shock_levels_t *levels, workers_t *workers, level_range_t range,
                        void *context) {
    level_split_t split = {range, context, 0};
    size_t reached = levels->reached;
    for (size_t q = 0; q < reached;) {
        uint32_t level = levels->level[levels->queue[q]];
        size_t end = q + 1;
        while (end < reached && levels->level[levels->queue[end]] == level) end++;
        if (end - q >= SPLIT_LEVEL) {
            split.first = q;
            workers_for(workers, end - q, level_chunk, &split);
        } else {
            range(context, q, end);
        }
        q = end;
    }
}

typedef struct {
    shock_t *shock;
    const solver_wide_t *wide;
    const solver_contact_t *contacts;
    solver_velocity_t *velocities;
    bool reverse;
} hold_t;

/* hold_up reads ahead no further than the range's own supports, which no
 * other thread sorts. */
static void hold_range(void *context, size_t begin, size_t end) {
    const hold_t *hold = context;
    hold_up_range(hold->shock, hold->wide, hold->contacts, hold->velocities, begin, end, 0,
                  hold->reverse);
}

/*
 * Each body held up by its supports, in the order the levels reached the
 * bodies, which is level by level from the ground up: a body's supports
 * are all of the level below, held up before it, so their velocities are
 * final. A body's pass changes its own velocity only (over_levels).
 */
static void propagate(shock_t *shock, const solver_wide_t *wide,
                      const solver_contact_t *contacts, solver_velocity_t *velocities,
                      bool reverse) {
    if (wide->workers == NULL) {
        hold_up_range(shock, wide, contacts, velocities, 0, shock->load.reached, PREFETCH_AHEAD,
                      reverse);
        return;
    }
    hold_t hold = {shock, wide, contacts, velocities, reverse};
    over_levels(&shock->load, wide->workers, hold_range, &hold);
}

/* A set of levels' arrays for count contacts and body_count bodies. */
static void reserve_levels(shock_levels_t *levels, size_t count, size_t body_count) {
    memory_reserve((void **)&levels->level, &levels->level_capacity, body_count,
                   sizeof(uint32_t));
    memory_reserve((void **)&levels->first, &levels->first_capacity, body_count,
                   sizeof(uint32_t));
    memory_reserve((void **)&levels->sides, &levels->side_capacity, 2 * count,
                   sizeof(solver_side_t));
    /* One more than can be kept, for the stores done regardless. */
    memory_reserve((void **)&levels->queue, &levels->queue_capacity, body_count + 1,
                   sizeof(uint32_t));
    memory_reserve((void **)&levels->support_end, &levels->support_end_capacity, body_count,
                   sizeof(uint32_t));
    /* One more than can be kept, for the store done regardless, and what
     * hold_up fetches ahead. */
    memory_reserve((void **)&levels->held, &levels->held_capacity, count + 1 + PREFETCH_AHEAD,
                   sizeof(uint32_t));
}

/* Lists each body's touching contacts on which one of the two rests (the
 * bits preparing set, resting.h), as link_bodies lists the loaded ones.
 * Returns whether one of them started the step deeper than its slop (else
 * the lift has nothing to do). */
static bool link_resting(shock_t *shock, const solver_contact_t *contacts, size_t count,
                         size_t body_count) {
    uint32_t *first = shock->rest.first;
    solver_side_t *sides = shock->rest.sides;
    memset(first, 0xff, body_count * sizeof(uint32_t)); /* SOLVER_NO_SIDE */
    bool deep = false;
    for (size_t i = 0; i < count; i++) {
        const solver_contact_t *c = &contacts[i];
        if (c->rests == 0) continue;
        deep |= (c->rests & RESTS_DEEP) != 0;
        solver_link_sides(first, sides, (uint32_t)i, c->a, c->b);
    }
    return deep;
}

/* What the two walks of the levels read. */
typedef struct {
    shock_t *shock;
    const solver_wide_t *wide;
    const solver_contact_t *contacts;
    size_t count;
    const solver_velocity_t *velocities;
    size_t body_count;
} walk_t;

/* Walk 0 finds the levels through the loaded contacts, walk 1 those
 * through the resting ones when one is deeper than its slop (else the
 * lift has nothing to do). Each writes its own arrays. */
static void walk_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const walk_t *walk = context;
    (void)chunk;
    shock_t *shock = walk->shock;
    for (size_t k = begin; k < end; k++) {
        shock_levels_t *levels = k == 0 ? &shock->load : &shock->rest;
        bool any = k == 0 ? link_bodies(shock, walk->wide, walk->contacts, walk->body_count)
                          : link_resting(shock, walk->contacts, walk->count, walk->body_count);
        levels->reached = any ? find_levels(levels, walk->velocities, walk->body_count) : 0;
    }
}

void shock_propagate(shock_t *shock, const solver_wide_t *wide, const solver_contact_t *contacts,
                     size_t count, solver_velocity_t *velocities, size_t body_count,
                     bool reverse) {
    shock->load.reached = shock->rest.reached = 0;
    if (count == 0) return;
    reserve_levels(&shock->load, count, body_count);
    reserve_levels(&shock->rest, count, body_count);
    memory_reserve((void **)&shock->slots, &shock->slot_capacity, count, sizeof(solver_slot_t));
    walk_t walk = {shock, wide, contacts, count, velocities, body_count};
    workers_each(wide->workers, 2, walk_chunk, &walk);
    propagate(shock, wide, contacts, velocities, reverse);
}

/* The pushes at contact c's points (kg m, >= 0) that move its upper body
 * (row) out of their overlaps beyond the slop by the static position rate,
 * the other body held still; lever terms rn of the upper body. */
static void lift_pushes(const solver_contact_t *c, const solver_velocity_t *row,
                        const solver_displacement_t *a, const solver_displacement_t *b,
                        const double rn[2], double x[2]) {
    double rate = SOLVER_STATIC_POSITION_RATE;
    double e1 = solver_position_error(c, &c->points[0], rate, a, b);
    x[0] = x[1] = 0.0;
    if (c->point_count == 2) {
        double e2 = solver_position_error(c, &c->points[1], rate, a, b);
        if (e1 < 0.0 || e2 < 0.0) solve_upper(row, rn[0], rn[1], e1, e2, &x[0], &x[1]);
        return;
    }
    x[0] = solve_one(row, rn[0], e1);
}

/* The RESTS_ bit of the upper body, b or a, looked up as SIGN is. */
static const uint8_t UPPER_RESTS[2] = {RESTS_A_ON_B, RESTS_B_ON_A};

/* Lifts the upper body (b of contact c, or a) off the other, when it rests
 * on it (the levels may have reached it first through another contact) and
 * no joint holds it (jointed NULL: none holds any). */
static void lift_off(const solver_contact_t *c, const solver_bodies_t *bodies,
                     const uint8_t *jointed, bool upper_is_b) {
    uint32_t body = upper_is_b ? c->b : c->a;
    if ((jointed != NULL && jointed[body]) || !(c->rests & UPPER_RESTS[upper_is_b])) return;
    const solver_velocity_t *row = &bodies->velocities[body];
    solver_displacement_t *displacements = bodies->displacements;
    double rn[2] = {upper_rn(&c->points[0], upper_is_b),
                    c->point_count == 2 ? upper_rn(&c->points[1], upper_is_b) : 0.0};
    double x[2];
    lift_pushes(c, row, &displacements[c->a], &displacements[c->b], rn, x);
    if (x[0] == 0.0 && x[1] == 0.0) return;
    solver_displacement_t *upper = &displacements[body];
    double sign = SIGN[upper_is_b], total = x[0] + x[1];
    upper->dx = vec_add(upper->dx, vec_multiply(sign * row->inverse_mass * total, c->normal));
    upper->dtheta += sign * row->inverse_inertia * (x[0] * rn[0] + x[1] * rn[1]);
}

/* Which bodies a joint holds, or NULL when no joint is solved. */
static const uint8_t *mark_jointed(shock_t *shock, const solver_bodies_t *bodies,
                                   const joint_step_t *joints) {
    if (joints->count == 0) return NULL;
    memory_reserve((void **)&shock->jointed, &shock->jointed_capacity, bodies->body_count,
                   sizeof(uint8_t));
    memset(shock->jointed, 0, bodies->body_count);
    joint_solver_mark_held(joints, bodies, shock->jointed);
    return shock->jointed;
}

typedef struct {
    const shock_t *shock;
    const solver_contact_t *contacts;
    const solver_bodies_t *bodies;
    const uint8_t *jointed;
} lift_t;

/* The queue's bodies [begin, end) lifted off their supports. */
static void lift_range(void *context, size_t begin, size_t end) {
    const lift_t *lift = context;
    const shock_levels_t *rest = &lift->shock->rest;
    const uint32_t *support_end = rest->support_end, *held = rest->held;
    uint32_t stop = support_end[end - 1];
    for (uint32_t k = begin > 0 ? support_end[begin - 1] : 0; k < stop; k++) {
        if (k + PREFETCH_AHEAD < stop) {
            PREFETCH_CONTACT(&lift->contacts[held[k + PREFETCH_AHEAD] / 2]);
        }
        lift_off(&lift->contacts[held[k] / 2], lift->bodies, lift->jointed, held[k] % 2 == 1);
    }
}

void shock_lift(shock_t *shock, workers_t *workers, const solver_contact_t *contacts,
                const solver_bodies_t *bodies, const joint_step_t *joints) {
    size_t reached = shock->rest.reached;
    if (reached == 0) return;
    lift_t lift = {shock, contacts, bodies, mark_jointed(shock, bodies, joints)};
    if (workers == NULL) {
        lift_range(&lift, 0, reached);
        return;
    }
    over_levels(&shock->rest, workers, lift_range, &lift);
}
