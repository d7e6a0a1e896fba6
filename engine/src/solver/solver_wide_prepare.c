/*
 * The colour batches prepared (solver_wide.h): four contacts at a time,
 * straight into their batch's lanes, with velocity_solve.c's arithmetic
 * lane by lane in its order (no fused multiply-add), so each contact gets
 * the bits preparing it alone gives. What the rest of the step reads from
 * the contacts (the collision pass, shock propagation and the lift,
 * impacts, the scene's contact queries) is written back to them too. A contact that may have an impact
 * within the step, rare, is then prepared again alone
 * (solver_prepare_contact), which times its impacts; only its targets
 * change in the lanes.
 */
#include <math.h>
#include <stddef.h>
#include "base/prefetch.h"
#include "solver/resting.h"
#include "solver/solver_wide.h"
#include "solver/solver_wide_private.h"
#include "solver/velocity_solve.h"

/* An empty lane's inputs: all zeros, body row 0 (whose row it does not
 * read). */
static const solver_contact_t NO_CONTACT;
static const solver_anchor_t NO_ANCHOR;
static const solver_state_t NO_STATE;
static const solver_velocity_t NO_ROW;

/* The inputs gathered four doubles at a time: a contact's normal,
 * friction, restitution, then slop and the block inverse; a point's
 * impulses and lever terms, then target and separation; an anchor's two
 * points of each body; a state's start velocity, drift and pull. */
_Static_assert(offsetof(solver_contact_t, friction) == offsetof(solver_contact_t, normal) + 16 &&
                   offsetof(solver_contact_t, m22) == offsetof(solver_contact_t, slop) + 24,
               "solver_contact_t: preparing reads and writes four doubles at a time");
_Static_assert(offsetof(solver_point_t, rn_b) == offsetof(solver_point_t, normal_impulse) + 24 &&
                   offsetof(solver_point_t, tangent_mass) == offsetof(solver_point_t, rt_a) + 24 &&
                   offsetof(solver_point_t, impact_offset) ==
                       offsetof(solver_point_t, target) + 24 &&
                   offsetof(solver_point_t, restitution_tangent_impulse) ==
                       offsetof(solver_point_t, restitution_impulse) + 8,
               "solver_point_t: preparing reads and writes four doubles at a time");
_Static_assert(offsetof(solver_state_t, w_start) == offsetof(solver_state_t, v_start) + 16 &&
                   offsetof(solver_state_t, spin_drift) == offsetof(solver_state_t, drift) + 16 &&
                   offsetof(solver_state_t, acceleration) ==
                       offsetof(solver_state_t, spin_drift) + 8 &&
                   offsetof(solver_state_t, acceleration) + 48 <= sizeof(solver_state_t),
               "solver_state_t: preparing reads four doubles at a time");

/* Where a batch is prepared: its index, its first point's and its block's. */
typedef struct {
    size_t batch, point, block;
} batch_at_t;

/* One body of each lane: inverse masses, start velocity, drift, pull. */
typedef struct {
    lane_t mass, inertia;
    lane_t vx, vy, w;
    lane_t drift_x, drift_y, spin_drift;
    lane_t ax, ay;
} lane_motion_t;

/* A body's start velocity, drift and pull in each lane, into m. */
LANE_INLINE void gather_motion(const solver_state_t *const s[LANES], lane_motion_t *m) {
    lane_quad_t start = gather_records(&s[0]->v_start, &s[1]->v_start, &s[2]->v_start,
                                       &s[3]->v_start);
    lane_quad_t drift = gather_records(&s[0]->drift, &s[1]->drift, &s[2]->drift, &s[3]->drift);
    lane_quad_t pull = gather_records(&s[0]->spin_drift, &s[1]->spin_drift, &s[2]->spin_drift,
                                      &s[3]->spin_drift);
    m->vx = start.v0;
    m->vy = start.v1;
    m->w = start.v2;
    m->drift_x = drift.v0;
    m->drift_y = drift.v1;
    m->spin_drift = pull.v0;
    m->ax = pull.v1;
    m->ay = pull.v2;
}

/* The inverse of gather_records for lanes [0, count): column k's lane l to
 * double k of record l. */
LANE_INLINE void scatter_records(void *const r[LANES], int count, lane_quad_t columns) {
    lane_quad_t rows = transpose(columns);
    if (count == LANES) {
        memcpy(r[0], &rows.v0, sizeof(lane_t));
        memcpy(r[1], &rows.v1, sizeof(lane_t));
        memcpy(r[2], &rows.v2, sizeof(lane_t));
        memcpy(r[3], &rows.v3, sizeof(lane_t));
        return;
    }
    const lane_t *row[LANES] = {&rows.v0, &rows.v1, &rows.v2, &rows.v3};
    for (int l = 0; l < count; l++) memcpy(r[l], row[l], sizeof(lane_t));
}

/* sqrt lane by lane: correctly rounded, as the scalar one. Built from the
 * four roots at once: written lane by lane into a vector in memory, then
 * loaded, it waited on the stores (a fifth of preparing's time). */
LANE_INLINE lane_t sqrt_lanes(lane_t x) {
    return (lane_t){sqrt(x[0]), sqrt(x[1]), sqrt(x[2]), sqrt(x[3])};
}

/* A point's velocity of b over a, for motions (vx, vy, w) of each and
 * lever arms r_a, r_b: point_velocity's differences along normal n. */
LANE_INLINE lane_t normal_velocity(lane_vector_t n, lane_t avx, lane_t avy, lane_t aw,
                                   lane_t bvx, lane_t bvy, lane_t bw, lane_vector_t r_a,
                                   lane_vector_t r_b) {
    lane_t x = (bvx - bw * r_b.y) - (avx - aw * r_a.y);
    lane_t y = (bvy + bw * r_b.x) - (avy + aw * r_a.x);
    return n.x * x + n.y * y;
}

/* Whether any lane's mask is set. */
LANE_INLINE bool any_lane(mask_t mask) {
    return (mask[0] | mask[1] | mask[2] | mask[3]) != 0;
}

/* What set_target gives the points that have no impact within the step,
 * lane by lane: 0, or a raised target for a resting approach, when
 * touching; the closing bound when apart. *impact: the lanes whose point
 * may have an impact within the step, whose target this then is not;
 * *raised: the lanes raised. Divisions are most of the cost: each branch
 * is taken only when a lane needs it. */
LANE_INLINE lane_t target_lanes(lane_t separation, lane_vector_t n, lane_vector_t r_a,
                                lane_vector_t r_b, const lane_motion_t *a,
                                const lane_motion_t *b, lane_t pull, lane_t threshold,
                                const solver_settings_t *s, mask_t *impact, mask_t *raised) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    const mask_t none = (mask_t)(zero != zero);
    double dt = s->dt, w = s->position_weight;
    lane_t vn = normal_velocity(n, a->vx, a->vy, a->w, b->vx, b->vy, b->w, r_a, r_b);
    mask_t touched = (mask_t)(separation <= zero);
    lane_t target = zero;
    *raised = none;
    if (w > 0.0 && w < 1.0) {
        lane_t least = -min_lane(dt * pull, zero + s->restitution_threshold);
        *raised = touched & (mask_t)(vn < zero) & (mask_t)(vn >= least);
        if (any_lane(*raised)) target = select_lane(*raised, -(1.0 - w) * vn / w, zero);
    }
    *impact = none;
    if (!any_lane(~touched)) return target;
    lane_t drift = normal_velocity(n, a->drift_x, a->drift_y, a->spin_drift, b->drift_x,
                                   b->drift_y, b->spin_drift, r_a, r_b);
    lane_t closing = zero - INFINITY;
    if (w > 0.0) closing = min_lane((-separation / dt - drift) / w, zero);
    /* An impact needs the gap s + vn t + an t^2 / 2 to close within the
     * step at an approach vn + an t faster than the threshold. Lanes where
     * a bound says neither can happen, with margins of half the gap and
     * half the threshold, far beyond rounding, have none; the rest may,
     * and are timed alone (solver_prepare_contact). */
    lane_t an = n.x * (b->ax - a->ax) + n.y * (b->ay - a->ay);
    lane_t fastest = min_lane(vn, vn + an * dt);
    lane_t nearest = separation + min_lane(vn, zero) * dt + min_lane(an, zero) * (0.5 * dt * dt);
    *impact = ~touched & (mask_t)(fastest < -0.5 * threshold) &
              (mask_t)(nearest <= 0.5 * separation);
    return select_lane(touched, target, closing);
}

/* bounce_threshold lane by lane. */
LANE_INLINE lane_t threshold_lanes(lane_t restitution, const lane_motion_t *a,
                                   const lane_motion_t *b, const solver_settings_t *s) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    mask_t free = (mask_t)(restitution > zero) & (mask_t)(a->ax == zero) &
                  (mask_t)(a->ay == zero) & (mask_t)(b->ax == zero) & (mask_t)(b->ay == zero);
    return select_lane(free, zero + SOLVER_FREE_RESTITUTION_THRESHOLD,
                       zero + s->restitution_threshold);
}

/* resting.h's resting_on, lane by lane, for the body pulled by (ax, ay). */
LANE_INLINE mask_t resting_on_lanes(lane_vector_t n, lane_t ax, lane_t ay, double sign) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    lane_t along = sign * (n.x * ax + n.y * ay);
    return (mask_t)(along < zero) &
           (mask_t)(along * along > RESTING_COSINE * RESTING_COSINE * (ax * ax + ay * ay));
}

/* The lanes' RESTS_ bits (resting_of), from their least separation. */
LANE_INLINE void rests_lanes(solver_contact_t *const c[LANES], int count, lane_vector_t n,
                             lane_t least, lane_t slop, const lane_motion_t *a,
                             const lane_motion_t *b) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    mask_t b_on_a = resting_on_lanes(n, b->ax, b->ay, 1.0);
    mask_t a_on_b = resting_on_lanes(n, a->ax, a->ay, -1.0);
    mask_t deep = (mask_t)(least + slop < zero);
    mask_t touching = ~(mask_t)(least > zero);
    for (int l = 0; l < count; l++) {
        unsigned rests = 0;
        if (touching[l]) {
            rests = (b_on_a[l] ? RESTS_B_ON_A : 0u) | (a_on_b[l] ? RESTS_A_ON_B : 0u);
            if (rests != 0 && deep[l]) rests |= RESTS_DEEP;
        }
        c[l]->rests = (uint8_t)rests;
    }
}

/* How many batches ahead of the one being prepared its contacts and
 * anchors are asked for; their bodies' rows half as far ahead, when the
 * contact's own first line has come. The visits walk the contact buffer
 * forward, but a batch's contacts lie a group's stride apart. */
enum { PREPARE_AHEAD = 4 };

/* Where visit k's batch begins in wide->order, and how many contacts it
 * has. */
static inline uint32_t visit_first(const solver_wide_t *wide, size_t k, int *count) {
    size_t g = wide->visit_groups[k];
    uint32_t first = wide->group_start[g] + (wide->visits[k] - wide->group_batch[g]) * LANES;
    uint32_t left = wide->group_start[g + 1] - first;
    *count = (int)(left < LANES ? left : LANES);
    return first;
}

/* A contact's five lines (the buffer is aligned to a line), its anchor's
 * one; a body's velocity row and the start of its state row, up to its
 * pull. A macro: GCC deems a function of prefetches alone const and drops
 * its calls. */
#define PREFETCH_CONTACT(c, anchor)                                                         \
    do {                                                                                    \
        const char *line_ = (const char *)(c);                                              \
        __builtin_prefetch(line_, 1);                                                       \
        __builtin_prefetch(line_ + PREFETCH_LINE, 1);                                       \
        __builtin_prefetch(line_ + 2 * PREFETCH_LINE, 1);                                   \
        __builtin_prefetch(line_ + 3 * PREFETCH_LINE, 1);                                   \
        __builtin_prefetch(line_ + 4 * PREFETCH_LINE, 1);                                   \
        __builtin_prefetch(anchor);                                                         \
    } while (0)
#define PREFETCH_BODY(bodies, row)                                                          \
    do {                                                                                    \
        __builtin_prefetch(&(bodies)->velocities[row]);                                     \
        const char *state_ = (const char *)&(bodies)->states[row];                          \
        __builtin_prefetch(state_);                                                         \
        __builtin_prefetch(state_ + offsetof(solver_state_t, acceleration) + 8);            \
    } while (0)
_Static_assert(sizeof(solver_contact_t) == 5 * PREFETCH_LINE, "a contact fills five lines");
#define PREFETCH_INPUTS(wide, contacts, anchors, bodies, k, end)                            \
    do {                                                                                    \
        int n_;                                                                             \
        if ((k) + PREPARE_AHEAD < (end)) {                                                  \
            uint32_t first_ = visit_first(wide, (k) + PREPARE_AHEAD, &n_);                  \
            for (int l_ = 0; l_ < n_; l_++) {                                               \
                uint32_t i_ = (wide)->order[first_ + (uint32_t)l_];                         \
                PREFETCH_CONTACT(&(contacts)[i_], &(anchors)[i_]);                          \
            }                                                                               \
        }                                                                                   \
        if ((k) + PREPARE_AHEAD / 2 < (end)) {                                              \
            uint32_t first_ = visit_first(wide, (k) + PREPARE_AHEAD / 2, &n_);              \
            for (int l_ = 0; l_ < n_; l_++) {                                               \
                const solver_contact_t *c_ = &(contacts)[(wide)->order[first_ + (uint32_t)l_]]; \
                PREFETCH_BODY(bodies, c_->a);                                               \
                PREFETCH_BODY(bodies, c_->b);                                               \
            }                                                                               \
        }                                                                                   \
    } while (0)

/* A lane's position rate: 0 when empty. */
static inline double rate_of(const solver_velocity_t *a, const solver_velocity_t *b, bool live) {
    return live ? solver_position_rate(a, b) : 0.0;
}

/* A batch's fixed part: bodies, normal, friction, masses, rate, slop; and
 * the lanes' inverse masses into a and b, their normal, friction and
 * restitution into n, their slop and block inverse into s. */
LANE_INLINE void fill_batch(solver_wide_t *wide, size_t index, solver_contact_t *const c[LANES],
                            const uint32_t *order, int count, batch_kind_t kind,
                            const solver_velocity_t *rows, lane_motion_t *a, lane_motion_t *b,
                            lane_quad_t *n, lane_quad_t *s) {
    solver_batch_t *batch = &wide->batches[index];
    solver_position_batch_t *position = &wide->position_batches[index];
    batch->lanes = position->lanes = (uint8_t)count;
    batch->kind = position->kind = (uint8_t)kind;
    position->point_count = (uint8_t)kind_points(kind);
    const solver_velocity_t *row_a[LANES], *row_b[LANES];
    unsigned fixed_a = 0, fixed_b = 0;
    for (int l = 0; l < LANES; l++) {
        batch->a[l] = position->a[l] = c[l]->a;
        batch->b[l] = position->b[l] = c[l]->b;
        batch->contact[l] = l < count ? order[l] : 0;
        row_a[l] = l < count ? &rows[c[l]->a] : &NO_ROW;
        row_b[l] = l < count ? &rows[c[l]->b] : &NO_ROW;
        fixed_a |= (unsigned)(l < count && solver_row_is_static(row_a[l])) << l;
        fixed_b |= (unsigned)(l < count && solver_row_is_static(row_b[l])) << l;
    }
    batch->fixed_a = position->fixed_a = (uint8_t)fixed_a;
    batch->fixed_b = position->fixed_b = (uint8_t)fixed_b;
    /* Each vector built from its four values at once: written lane by
     * lane into a vector in memory and then loaded, it waited on the
     * stores (a seventh of preparing's time). */
    lane_t ma = {row_a[0]->inverse_mass, row_a[1]->inverse_mass, row_a[2]->inverse_mass,
                 row_a[3]->inverse_mass};
    lane_t mb = {row_b[0]->inverse_mass, row_b[1]->inverse_mass, row_b[2]->inverse_mass,
                 row_b[3]->inverse_mass};
    lane_t ia = {row_a[0]->inverse_inertia, row_a[1]->inverse_inertia,
                 row_a[2]->inverse_inertia, row_a[3]->inverse_inertia};
    lane_t ib = {row_b[0]->inverse_inertia, row_b[1]->inverse_inertia,
                 row_b[2]->inverse_inertia, row_b[3]->inverse_inertia};
    /* normal.x, normal.y, friction, restitution; slop, m11, m12, m22 */
    *n = gather_records(&c[0]->normal, &c[1]->normal, &c[2]->normal, &c[3]->normal);
    *s = gather_records(&c[0]->slop, &c[1]->slop, &c[2]->slop, &c[3]->slop);
    batch->normal.x = position->normal.x = n->v0;
    batch->normal.y = position->normal.y = n->v1;
    batch->friction = n->v2;
    batch->ia = position->ia = ia;
    batch->ib = position->ib = ib;
    position->ma = ma;
    position->mb = mb;
    position->rate = (lane_t){rate_of(row_a[0], row_b[0], 0 < count),
                              rate_of(row_a[1], row_b[1], 1 < count),
                              rate_of(row_a[2], row_b[2], 2 < count),
                              rate_of(row_a[3], row_b[3], 3 < count)};
    position->slop = s->v0;
    a->mass = ma;
    a->inertia = ia;
    b->mass = mb;
    b->inertia = ib;
}

/* The inverse of a block batch's K (solver_contact_k, lane by lane), to
 * the block and back to the contacts; zeros in the empty lanes. */
LANE_INLINE void fill_block(lane_block_t *k, solver_contact_t *const c[LANES], int count,
                            const lane_motion_t *a, const lane_motion_t *b, const lane_t rn_a[2],
                            const lane_t rn_b[2], lane_t slop) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    lane_t ma = a->mass, mb = b->mass, ia = a->inertia, ib = b->inertia;
    k->k11 = ma + mb + ia * rn_a[0] * rn_a[0] + ib * rn_b[0] * rn_b[0];
    k->k12 = ma + mb + ia * rn_a[0] * rn_a[1] + ib * rn_b[0] * rn_b[1];
    k->k22 = ma + mb + ia * rn_a[1] * rn_a[1] + ib * rn_b[1] * rn_b[1];
    lane_t inv = 1.0 / (k->k11 * k->k22 - k->k12 * k->k12);
    mask_t live = (mask_t){0, 1, 2, 3} < count;
    k->m11 = select_lane(live, inv * k->k22, zero);
    k->m12 = select_lane(live, -inv * k->k12, zero);
    k->m22 = select_lane(live, inv * k->k11, zero);
    void *at[LANES] = {&c[0]->slop, &c[1]->slop, &c[2]->slop, &c[3]->slop};
    scatter_records(at, count, (lane_quad_t){slop, k->m11, k->m12, k->m22});
}

/* What a batch's points share, lane by lane. */
typedef struct {
    lane_motion_t a, b;
    lane_vector_t normal, tangent;
    lane_t pull;      /* vec_get_length of each body's pull, summed */
    lane_t threshold; /* bounce_threshold */
} lane_contact_t;

/* Point i of the lanes' contacts c[0 .. count), anchored at r_a, r_b: its
 * lane point and position point at `point`, and back into the contacts.
 * Returns its separation; gives its lever terms along the normal, and
 * adds its lanes that may have an impact and that were raised. */
LANE_INLINE lane_t prepare_point(solver_wide_t *wide, size_t point,
                                 solver_contact_t *const c[LANES], int count, int i,
                                 const lane_contact_t *k, lane_vector_t r_a, lane_vector_t r_b,
                                 const solver_settings_t *settings, lane_t *rn_a, lane_t *rn_b,
                                 mask_t *impact, mask_t *raised) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    solver_point_t *p[LANES] = {&c[0]->points[i], &c[1]->points[i], &c[2]->points[i],
                                &c[3]->points[i]};
    void *front[LANES] = {&p[0]->normal_impulse, &p[1]->normal_impulse, &p[2]->normal_impulse,
                          &p[3]->normal_impulse};
    void *middle[LANES] = {&p[0]->rt_a, &p[1]->rt_a, &p[2]->rt_a, &p[3]->rt_a};
    void *back[LANES] = {&p[0]->target, &p[1]->target, &p[2]->target, &p[3]->target};
    lane_quad_t impulses = gather_records(front[0], front[1], front[2], front[3]);
    lane_t separation = gather_records(back[0], back[1], back[2], back[3]).v1;
    /* vec_cross(r, normal) and vec_cross(r, tangent) */
    *rn_a = r_a.x * k->normal.y - r_a.y * k->normal.x;
    *rn_b = r_b.x * k->normal.y - r_b.y * k->normal.x;
    lane_t rt_a = r_a.x * k->tangent.y - r_a.y * k->tangent.x;
    lane_t rt_b = r_b.x * k->tangent.y - r_b.y * k->tangent.x;
    const lane_motion_t *a = &k->a, *b = &k->b;
    lane_t k_normal = a->mass + b->mass + a->inertia * *rn_a * *rn_a + b->inertia * *rn_b * *rn_b;
    lane_t normal_mass = select_lane((mask_t)(k_normal > zero), 1.0 / k_normal, zero);
    lane_t k_tangent = a->mass + b->mass + a->inertia * rt_a * rt_a + b->inertia * rt_b * rt_b;
    lane_t tangent_mass = select_lane((mask_t)(k_tangent > zero), 1.0 / k_tangent, zero);
    mask_t point_impact, point_raised;
    lane_t target = target_lanes(separation, k->normal, r_a, r_b, a, b, k->pull, k->threshold,
                                 settings, &point_impact, &point_raised);
    *impact |= point_impact;
    *raised |= point_raised;

    lane_point_t *lp = &wide->points[point];
    solver_position_point_t *pp = &wide->position_points[point];
    lp->normal_impulse = impulses.v0;
    lp->tangent_impulse = impulses.v1;
    lp->rn.a = pp->rn.a = *rn_a;
    lp->rn.b = pp->rn.b = *rn_b;
    lp->rt.a = rt_a;
    lp->rt.b = rt_b;
    lp->normal_mass = pp->normal_mass = normal_mass;
    lp->tangent_mass = tangent_mass;
    lp->target = target;
    pp->separation = separation;

    scatter_records(front, count, (lane_quad_t){impulses.v0, impulses.v1, *rn_a, *rn_b});
    scatter_records(middle, count, (lane_quad_t){rt_a, rt_b, normal_mass, tangent_mass});
    /* impact_time -1 and impact_offset NAN: no impact (set_target) */
    scatter_records(back, count, (lane_quad_t){target, separation, zero - 1.0, zero + NAN});
    for (int l = 0; l < count; l++) {
        p[l]->restitution_impulse = 0.0;
        p[l]->restitution_tangent_impulse = 0.0;
        p[l]->touched = separation[l] <= 0.0;
        p[l]->lands = false;
    }
    return separation;
}

/* Prepares contacts order[0 .. count) (at most LANES of one kind) into the
 * batch, points and block at `at`, and back into the contacts. */
LANE_INLINE void prepare_batch(solver_wide_t *wide, batch_at_t at, const uint32_t *order,
                               int count, batch_kind_t kind, solver_contact_t *contacts,
                               const solver_anchor_t *anchors, const solver_bodies_t *bodies,
                               const solver_settings_t *settings, prepared_t *found) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    solver_contact_t *c[LANES];
    const solver_anchor_t *anchor[LANES];
    const solver_state_t *sa[LANES], *sb[LANES];
    for (int l = 0; l < LANES; l++) {
        c[l] = (solver_contact_t *)&NO_CONTACT;
        anchor[l] = &NO_ANCHOR;
        sa[l] = sb[l] = &NO_STATE;
    }
    for (int l = 0; l < count; l++) {
        c[l] = &contacts[order[l]];
        anchor[l] = &anchors[order[l]];
        sa[l] = &bodies->states[c[l]->a];
        sb[l] = &bodies->states[c[l]->b];
    }
    lane_contact_t k;
    lane_quad_t n, s;
    fill_batch(wide, at.batch, c, order, count, kind, bodies->velocities, &k.a, &k.b, &n, &s);
    gather_motion(sa, &k.a);
    gather_motion(sb, &k.b);
    k.normal = (lane_vector_t){n.v0, n.v1};
    k.tangent = (lane_vector_t){-n.v1, n.v0};
    k.pull = sqrt_lanes(k.a.ax * k.a.ax + k.a.ay * k.a.ay) +
             sqrt_lanes(k.b.ax * k.b.ax + k.b.ay * k.b.ay);
    k.threshold = threshold_lanes(n.v3, &k.a, &k.b, settings);
    /* r_a[0].x, r_a[0].y, r_a[1].x, r_a[1].y; the same of r_b */
    lane_quad_t r_a = gather_records(anchor[0]->r_a, anchor[1]->r_a, anchor[2]->r_a,
                                     anchor[3]->r_a);
    lane_quad_t r_b = gather_records(anchor[0]->r_b, anchor[1]->r_b, anchor[2]->r_b,
                                     anchor[3]->r_b);
    mask_t impact = (mask_t)(zero != zero), raised = impact;
    lane_t rn_a[2] = {zero, zero}, rn_b[2] = {zero, zero};
    lane_t least = prepare_point(wide, at.point, c, count, 0, &k, (lane_vector_t){r_a.v0, r_a.v1},
                                 (lane_vector_t){r_b.v0, r_b.v1}, settings, &rn_a[0], &rn_b[0],
                                 &impact, &raised);
    if (kind_points(kind) == 2) {
        lane_t second = prepare_point(wide, at.point + 1, c, count, 1, &k,
                                      (lane_vector_t){r_a.v2, r_a.v3},
                                      (lane_vector_t){r_b.v2, r_b.v3}, settings, &rn_a[1],
                                      &rn_b[1], &impact, &raised);
        least = min_lane(second, least);
    }
    for (int l = 0; l < count; l++) c[l]->impact = false;
    rests_lanes(c, count, k.normal, least, s.v0, &k.a, &k.b);
    if (kind == BATCH_BLOCK) {
        fill_block(&wide->blocks[at.block], c, count, &k.a, &k.b, rn_a, rn_b, s.v0);
    }
    /* Empty lanes hold zeros: no restitution, touching, nothing raised. */
    found->elastic |= any_lane((mask_t)(n.v3 > zero));
    found->raised |= any_lane(raised);
    if (!any_lane(impact)) return;
    for (int l = 0; l < count; l++) {
        if (!impact[l]) continue;
        /* Timed alone; the rest of the contact comes out as it was. */
        found->impact |= solver_prepare_contact(c[l], anchor[l], bodies, settings,
                                                &found->raised);
        for (int i = 0; i < kind_points(kind); i++) {
            wide->points[at.point + (size_t)i].target[l] = c[l]->points[i].target;
        }
    }
}

LANE_CLONES
prepared_t solver_wide_prepare(solver_wide_t *wide, solver_contact_t *contacts,
                               const solver_anchor_t *anchors, const solver_bodies_t *bodies,
                               const solver_settings_t *settings, size_t begin, size_t end) {
    prepared_t found = {false, false, false};
    for (size_t k = begin; k < end; k++) {
        size_t g = wide->visit_groups[k], i = wide->visits[k];
        batch_at_t at = {i, first_point(wide, g, i), first_block(wide, g, i)};
        int n;
        uint32_t first = visit_first(wide, k, &n);
        PREFETCH_INPUTS(wide, contacts, anchors, bodies, k, end);
        prepare_batch(wide, at, wide->order + first, n, (batch_kind_t)(g % BATCH_KINDS), contacts,
                      anchors, bodies, settings, &found);
    }
    return found;
}
