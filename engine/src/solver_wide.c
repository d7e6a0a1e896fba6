#include "solver_wide.h"
#include <string.h>
#include "memory.h"

enum { LANES = 4 };

/* Vectors are returned from static functions only (always inlined), so
 * GCC's warning that AVX changes how they are returned between objects does
 * not apply. */
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

/* The kernels below must be inlined into each clone of
 * solver_wide_iterate to be compiled for its instruction set; GCC
 * otherwise keeps the larger ones out of line, as baseline code. */
#define LANE_INLINE static inline __attribute__((always_inline))

/* Four doubles, and four 64-bit lane masks (all ones where a comparison
 * held). aligned(8): the batches come from malloc, which promises less
 * than the 32 bytes a vector would otherwise demand. */
typedef double lane_t __attribute__((vector_size(LANES * sizeof(double)), aligned(8)));
typedef int64_t mask_t __attribute__((vector_size(LANES * sizeof(int64_t)), aligned(8)));

/* A direction, lane by lane. */
typedef struct {
    lane_t x, y;
} lane_vector_t;

/* A point's lever terms along a direction d: r_a x d and r_b x d. */
typedef struct {
    lane_t a, b;
} lane_lever_t;

typedef struct {
    lane_lever_t rn, rt;
    lane_t normal_mass, tangent_mass, target;
    lane_t normal_impulse, tangent_impulse;
} lane_point_t;

/* Up to four contacts of one colour, all solved by the block solve or all
 * point by point. A missing second point, and a lane without a contact,
 * hold zeros: zero masses give zero impulses. */
struct solver_batch {
    lane_vector_t normal;
    lane_t friction;
    lane_t ma, mb, ia, ib;
    lane_t k11, k12, k22, m11, m12, m22; /* block batches only */
    lane_point_t points[2];
    uint32_t a[LANES], b[LANES]; /* body rows; empty lanes read row 0 */
    uint32_t contact[LANES];
    int lanes;
    bool block;
};

/* The same contacts, with what the position pass needs. */
struct solver_position_batch {
    lane_vector_t normal;
    lane_t ma, mb, ia, ib, rate;
    struct {
        lane_lever_t rn;
        lane_t normal_mass, separation;
    } points[2];
    uint32_t a[LANES], b[LANES];
    int lanes;
};

/* The two bodies' velocities in a batch, lane by lane. */
typedef struct {
    lane_t vx, vy, w;
} lane_body_t;

/* yes where condition holds, no elsewhere; and scalar.h's max_of and
 * min_of, lane by lane. Macros, not functions: a vector passed by value
 * goes through memory on the baseline instruction set. Arguments must be
 * free of side effects. */
#define select_lane(condition, yes, no) \
    ((lane_t)(((mask_t)(yes) & (condition)) | ((mask_t)(no) & ~(condition))))
#define max_lane(a, b) select_lane((mask_t)((a) > (b)), (a), (b))
#define min_lane(a, b) select_lane((mask_t)((a) < (b)), (a), (b))

LANE_INLINE lane_body_t gather(const solver_velocity_t *rows, const uint32_t index[LANES]) {
    const solver_velocity_t *r0 = &rows[index[0]], *r1 = &rows[index[1]];
    const solver_velocity_t *r2 = &rows[index[2]], *r3 = &rows[index[3]];
    return (lane_body_t){
        .vx = {r0->v.x, r1->v.x, r2->v.x, r3->v.x},
        .vy = {r0->v.y, r1->v.y, r2->v.y, r3->v.y},
        .w = {r0->w, r1->w, r2->w, r3->w},
    };
}

LANE_INLINE void scatter(solver_velocity_t *rows, const uint32_t index[LANES], int lanes,
                           const lane_body_t *body) {
    for (int l = 0; l < lanes; l++) {
        solver_velocity_t *row = &rows[index[l]];
        row->v.x = body->vx[l];
        row->v.y = body->vy[l];
        row->w = body->w[l];
    }
}

/* Relative velocity of b over a along (dx, dy), lever terms rd_a, rd_b. */
/* Directions and lever terms go by pointer: vectors passed by value would
 * go through memory on the baseline instruction set. */
LANE_INLINE lane_t relative_along(const lane_body_t *a, const lane_body_t *b,
                                  const lane_vector_t *d, const lane_lever_t *r) {
    return d->x * (b->vx - a->vx) + d->y * (b->vy - a->vy) + b->w * r->b - a->w * r->a;
}

LANE_INLINE void apply_along(const solver_batch_t *batch, lane_body_t *a, lane_body_t *b,
                             const lane_vector_t *d, const lane_lever_t *r,
                             const lane_t *impulse) {
    lane_t lambda = *impulse;
    a->vx -= batch->ma * lambda * d->x;
    a->vy -= batch->ma * lambda * d->y;
    a->w -= batch->ia * lambda * r->a;
    b->vx += batch->mb * lambda * d->x;
    b->vy += batch->mb * lambda * d->y;
    b->w += batch->ib * lambda * r->b;
}

LANE_INLINE void solve_friction(solver_batch_t *batch, lane_body_t *a, lane_body_t *b) {
    lane_vector_t tangent = {-batch->normal.y, batch->normal.x};
    for (int i = 0; i < 2; i++) {
        lane_point_t *p = &batch->points[i];
        lane_t vt = relative_along(a, b, &tangent, &p->rt);
        lane_t limit = batch->friction * p->normal_impulse;
        lane_t wanted = p->tangent_impulse - p->tangent_mass * vt;
        lane_t total = max_lane(-limit, min_lane(wanted, limit));
        lane_t delta = total - p->tangent_impulse;
        p->tangent_impulse = total;
        apply_along(batch, a, b, &tangent, &p->rt, &delta);
    }
}

LANE_INLINE void solve_normal_points(solver_batch_t *batch, lane_body_t *a, lane_body_t *b) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < 2; i++) {
        lane_point_t *p = &batch->points[i];
        lane_t vn = relative_along(a, b, &batch->normal, &p->rn);
        lane_t wanted = p->normal_impulse - p->normal_mass * (vn - p->target);
        lane_t total = max_lane(wanted, zero);
        lane_t delta = total - p->normal_impulse;
        p->normal_impulse = total;
        apply_along(batch, a, b, &batch->normal, &p->rn, &delta);
    }
}

/* solver.c's block solve with its four cases evaluated in every lane and
 * the first that holds selected (the case order is the scalar one). */
LANE_INLINE void solve_normal_block(solver_batch_t *batch, lane_body_t *a, lane_body_t *b) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    lane_point_t *p1 = &batch->points[0], *p2 = &batch->points[1];
    lane_t a1 = p1->normal_impulse, a2 = p2->normal_impulse;
    lane_t b1 = relative_along(a, b, &batch->normal, &p1->rn) - p1->target;
    lane_t b2 = relative_along(a, b, &batch->normal, &p2->rn) - p2->target;
    b1 -= batch->k11 * a1 + batch->k12 * a2;
    b2 -= batch->k12 * a1 + batch->k22 * a2;

    lane_t both1 = -(batch->m11 * b1 + batch->m12 * b2);
    lane_t both2 = -(batch->m12 * b1 + batch->m22 * b2);
    mask_t both = (mask_t)(both1 >= zero) & (mask_t)(both2 >= zero);
    lane_t first = -p1->normal_mass * b1;
    mask_t first_only = (mask_t)(first >= zero) & (mask_t)(batch->k12 * first + b2 >= zero);
    lane_t second = -p2->normal_mass * b2;
    mask_t second_only = (mask_t)(second >= zero) & (mask_t)(batch->k12 * second + b1 >= zero);
    mask_t neither = (mask_t)(b1 >= zero) & (mask_t)(b2 >= zero);

    lane_t x1 = select_lane(neither, zero, a1), x2 = select_lane(neither, zero, a2);
    x1 = select_lane(second_only, zero, x1);
    x2 = select_lane(second_only, second, x2);
    x1 = select_lane(first_only, first, x1);
    x2 = select_lane(first_only, zero, x2);
    x1 = select_lane(both, both1, x1);
    x2 = select_lane(both, both2, x2);

    lane_t d1 = x1 - a1, d2 = x2 - a2;
    lane_t total = d1 + d2;
    a->vx -= batch->ma * total * batch->normal.x;
    a->vy -= batch->ma * total * batch->normal.y;
    a->w -= batch->ia * (d1 * p1->rn.a + d2 * p2->rn.a);
    b->vx += batch->mb * total * batch->normal.x;
    b->vy += batch->mb * total * batch->normal.y;
    b->w += batch->ib * (d1 * p1->rn.b + d2 * p2->rn.b);
    p1->normal_impulse = x1;
    p2->normal_impulse = x2;
}

/* Built twice where the compiler can (GCC and Clang on x86-64 with ifunc
 * support): once for AVX2, which does a batch's four lanes in one
 * instruction, and once for the baseline (two SSE2 instructions); the
 * loader picks the one the processor runs. Neither uses fused
 * multiply-add, so both give the same numbers. */
#if defined(__x86_64__) && defined(__GNUC__) && defined(__ELF__)
__attribute__((target_clones("avx2", "default")))
#endif
void solver_wide_iterate(solver_wide_t *wide, solver_velocity_t *rows) {
    for (size_t i = 0; i < wide->batch_count; i++) {
        solver_batch_t *batch = &wide->batches[i];
        lane_body_t a = gather(rows, batch->a), b = gather(rows, batch->b);
        solve_friction(batch, &a, &b);
        if (batch->block) {
            solve_normal_block(batch, &a, &b);
        } else {
            solve_normal_points(batch, &a, &b);
        }
        scatter(rows, batch->a, batch->lanes, &a);
        scatter(rows, batch->b, batch->lanes, &b);
    }
}

/* The bodies' displacements in a batch, lane by lane. */
typedef struct {
    lane_t dx, dy, dtheta;
} lane_displacement_t;

LANE_INLINE lane_displacement_t gather_displacements(const solver_displacement_t *rows,
                                                     const uint32_t index[LANES]) {
    const solver_displacement_t *r0 = &rows[index[0]], *r1 = &rows[index[1]];
    const solver_displacement_t *r2 = &rows[index[2]], *r3 = &rows[index[3]];
    return (lane_displacement_t){
        .dx = {r0->dx.x, r1->dx.x, r2->dx.x, r3->dx.x},
        .dy = {r0->dx.y, r1->dx.y, r2->dx.y, r3->dx.y},
        .dtheta = {r0->dtheta, r1->dtheta, r2->dtheta, r3->dtheta},
    };
}

LANE_INLINE void scatter_displacements(solver_displacement_t *rows, const uint32_t index[LANES],
                                       int lanes, const lane_displacement_t *moved) {
    for (int l = 0; l < lanes; l++) {
        solver_displacement_t *row = &rows[index[l]];
        row->dx.x = moved->dx[l];
        row->dx.y = moved->dy[l];
        row->dtheta = moved->dtheta[l];
    }
}

/* solver.c's solve_position, lane by lane. */
LANE_INLINE void correct_batch(const solver_position_batch_t *batch, lane_displacement_t *a,
                               lane_displacement_t *b) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    const lane_t slop = zero + SOLVER_LINEAR_SLOP;
    const lane_t most = zero - SOLVER_MAX_POSITION_CORRECTION;
    const lane_vector_t *n = &batch->normal;
    for (int i = 0; i < 2; i++) {
        const lane_lever_t *rn = &batch->points[i].rn;
        lane_t separation = batch->points[i].separation +
                            (n->x * (b->dx - a->dx) + n->y * (b->dy - a->dy)) +
                            b->dtheta * rn->b - a->dtheta * rn->a;
        lane_t wanted = batch->rate * (separation + slop);
        lane_t capped = min_lane(wanted, zero);
        lane_t error = max_lane(most, capped);
        lane_t lambda = -error * batch->points[i].normal_mass;
        a->dx -= batch->ma * lambda * n->x;
        a->dy -= batch->ma * lambda * n->y;
        a->dtheta -= batch->ia * lambda * rn->a;
        b->dx += batch->mb * lambda * n->x;
        b->dy += batch->mb * lambda * n->y;
        b->dtheta += batch->ib * lambda * rn->b;
    }
}

#if defined(__x86_64__) && defined(__GNUC__) && defined(__ELF__)
__attribute__((target_clones("avx2", "default")))
#endif
void solver_wide_correct_positions(solver_wide_t *wide, solver_displacement_t *displacements,
                                   bool backward) {
    size_t count = wide->batch_count;
    for (size_t k = 0; k < count; k++) {
        const solver_position_batch_t *batch = &wide->position_batches[backward ? count - 1 - k : k];
        lane_displacement_t a = gather_displacements(displacements, batch->a);
        lane_displacement_t b = gather_displacements(displacements, batch->b);
        correct_batch(batch, &a, &b);
        scatter_displacements(displacements, batch->a, batch->lanes, &a);
        scatter_displacements(displacements, batch->b, batch->lanes, &b);
    }
}

static void load_position_lane(solver_position_batch_t *batch, int l, const solver_contact_t *c,
                               const solver_velocity_t *rows) {
    batch->a[l] = c->a;
    batch->b[l] = c->b;
    batch->normal.x[l] = c->normal.x;
    batch->normal.y[l] = c->normal.y;
    batch->ma[l] = rows[c->a].inverse_mass;
    batch->mb[l] = rows[c->b].inverse_mass;
    batch->ia[l] = rows[c->a].inverse_inertia;
    batch->ib[l] = rows[c->b].inverse_inertia;
    batch->rate[l] = c->position_rate;
    for (int i = 0; i < c->point_count; i++) {
        batch->points[i].rn.a[l] = c->points[i].rn_a;
        batch->points[i].rn.b[l] = c->points[i].rn_b;
        batch->points[i].normal_mass[l] = c->points[i].normal_mass;
        batch->points[i].separation[l] = c->points[i].separation;
    }
}

static void load_lane(solver_batch_t *batch, int l, const solver_contact_t *c, uint32_t index,
                      const solver_velocity_t *rows) {
    batch->a[l] = c->a;
    batch->b[l] = c->b;
    batch->contact[l] = index;
    batch->normal.x[l] = c->normal.x;
    batch->normal.y[l] = c->normal.y;
    batch->friction[l] = c->friction;
    batch->ma[l] = rows[c->a].inverse_mass;
    batch->mb[l] = rows[c->b].inverse_mass;
    batch->ia[l] = rows[c->a].inverse_inertia;
    batch->ib[l] = rows[c->b].inverse_inertia;
    batch->k11[l] = c->k11;
    batch->k12[l] = c->k12;
    batch->k22[l] = c->k22;
    batch->m11[l] = c->m11;
    batch->m12[l] = c->m12;
    batch->m22[l] = c->m22;
    for (int i = 0; i < c->point_count; i++) {
        const solver_point_t *p = &c->points[i];
        lane_point_t *lp = &batch->points[i];
        lp->rn.a[l] = p->rn_a;
        lp->rn.b[l] = p->rn_b;
        lp->rt.a[l] = p->rt_a;
        lp->rt.b[l] = p->rt_b;
        lp->normal_mass[l] = p->normal_mass;
        lp->tangent_mass[l] = p->tangent_mass;
        lp->target[l] = p->target;
        lp->normal_impulse[l] = p->normal_impulse;
        lp->tangent_impulse[l] = p->tangent_impulse;
    }
}

/* Packs order[0 .. count) (at most LANES contacts) into batch number i. */
static void load_batch(solver_wide_t *wide, size_t i, const uint32_t *order, int count,
                       bool block, const solver_contact_t *contacts,
                       const solver_velocity_t *rows) {
    solver_batch_t *batch = &wide->batches[i];
    solver_position_batch_t *position = &wide->position_batches[i];
    memset(batch, 0, sizeof *batch);
    memset(position, 0, sizeof *position);
    batch->lanes = position->lanes = count;
    batch->block = block;
    for (int l = 0; l < count; l++) {
        load_lane(batch, l, &contacts[order[l]], order[l], rows);
        load_position_lane(position, l, &contacts[order[l]], rows);
    }
}

/* Orders the contacts by colour, and within a colour block solves first;
 * the uncoloured go to the loose list. Returns the group boundaries in
 * start (2 * COLORING_MAX_COLORS + 1 entries). */
static void sort_by_color(solver_wide_t *wide, const solver_contact_t *contacts, size_t count,
                          uint32_t *start) {
    enum { GROUPS = 2 * COLORING_MAX_COLORS };
    memset(start, 0, (GROUPS + 1) * sizeof(uint32_t));
    wide->loose_count = 0;
    for (size_t i = 0; i < count; i++) {
        if (wide->colors[i] == COLORING_NONE) {
            wide->loose[wide->loose_count++] = (uint32_t)i;
            continue;
        }
        start[2 * wide->colors[i] + !contacts[i].block + 1]++;
    }
    for (int g = 0; g < GROUPS; g++) start[g + 1] += start[g];
    uint32_t next[GROUPS];
    memcpy(next, start, sizeof next);
    for (size_t i = 0; i < count; i++) {
        if (wide->colors[i] == COLORING_NONE) continue;
        wide->order[next[2 * wide->colors[i] + !contacts[i].block]++] = (uint32_t)i;
    }
}

void solver_wide_load(solver_wide_t *wide, const solver_contact_t *contacts, size_t count,
                      const solver_velocity_t *rows, size_t body_count) {
    enum { GROUPS = 2 * COLORING_MAX_COLORS };
    memory_reserve((void **)&wide->colors, &wide->color_capacity, count, sizeof(uint8_t));
    memory_reserve((void **)&wide->order, &wide->order_capacity, count, sizeof(uint32_t));
    memory_reserve((void **)&wide->loose, &wide->loose_capacity, count, sizeof(uint32_t));
    /* At most one partly filled batch per group. */
    memory_reserve((void **)&wide->batches, &wide->batch_capacity, count / LANES + GROUPS,
                   sizeof(solver_batch_t));
    memory_reserve((void **)&wide->position_batches, &wide->position_batch_capacity,
                   count / LANES + GROUPS, sizeof(solver_position_batch_t));
    coloring_assign(&wide->coloring, contacts, count, rows, body_count, wide->colors);
    uint32_t start[GROUPS + 1];
    sort_by_color(wide, contacts, count, start);
    wide->batch_count = 0;
    for (int g = 0; g < GROUPS; g++) {
        for (uint32_t i = start[g]; i < start[g + 1]; i += LANES) {
            int n = (int)(start[g + 1] - i < LANES ? start[g + 1] - i : LANES);
            load_batch(wide, wide->batch_count++, wide->order + i, n, g % 2 == 0, contacts,
                       rows);
        }
    }
}

void solver_wide_store(const solver_wide_t *wide, solver_contact_t *contacts) {
    for (size_t i = 0; i < wide->batch_count; i++) {
        const solver_batch_t *batch = &wide->batches[i];
        for (int l = 0; l < batch->lanes; l++) {
            solver_contact_t *c = &contacts[batch->contact[l]];
            for (int k = 0; k < c->point_count; k++) {
                c->points[k].normal_impulse = batch->points[k].normal_impulse[l];
                c->points[k].tangent_impulse = batch->points[k].tangent_impulse[l];
            }
        }
    }
}

void solver_wide_free(solver_wide_t *wide) {
    coloring_free(&wide->coloring);
    memory_free(wide->colors);
    memory_free(wide->order);
    memory_free(wide->batches);
    memory_free(wide->position_batches);
    memory_free(wide->loose);
    memset(wide, 0, sizeof *wide);
}
