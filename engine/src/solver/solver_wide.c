#include "solver/solver_wide.h"
#include <string.h>
#include "base/memory.h"

enum { LANES = 4 };

/* Vectors are returned from static functions only (always inlined), so
 * GCC's warning that AVX changes how they are returned between objects does
 * not apply. */
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

/* The kernels below must be inlined into each clone of the exported
 * functions to be compiled for its instruction set; GCC otherwise keeps
 * the larger ones out of line, as baseline code. */
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

struct lane_point {
    lane_lever_t rn, rt;
    lane_t normal_mass, tangent_mass, target;
    lane_t normal_impulse, tangent_impulse;
};

/* What the block solve adds to a batch of two-point contacts: the 2x2
 * normal effective-mass matrix K and its inverse. */
struct lane_block {
    lane_t k11, k12, k22, m11, m12, m22;
};

/*
 * Up to four contacts of one colour and one kind. The batches of a step lie
 * in colour order, and their variable parts follow in arrays of their own,
 * in the same order: a batch's 1 or 2 points in wide->points, a block
 * batch's matrices in wide->blocks. So a sweep reads three arrays straight
 * through, and a one-point contact (half of a pile's) costs one point, not
 * two. A lane without a contact reads body row 0 and holds zero point data:
 * its effective masses are zero, so its impulses are zero, and it is never
 * written back.
 */
typedef enum { BATCH_BLOCK, BATCH_PAIR, BATCH_SINGLE, BATCH_KINDS } batch_kind_t;
_Static_assert((int)BATCH_KINDS == (int)SOLVER_WIDE_KINDS, "solver_wide.h counts the kinds of batch");

struct solver_batch {
    lane_vector_t normal;
    lane_t friction;
    /* The bodies' inverse inertias, lane by lane: loaded with the batch
     * rather than gathered from four rows each time (the rest of a row is
     * one vector load, this was four scalar loads and their shuffles). */
    lane_t ia, ib;
    uint32_t a[LANES], b[LANES];
    uint32_t contact[LANES];
    uint8_t lanes, kind;
    /* Bit l: lane l's body a (b) cannot move. */
    uint8_t fixed_a, fixed_b;
};

/* The same contacts, with what the position pass needs; their points
 * follow in wide->position_points. */
struct solver_position_batch {
    lane_vector_t normal;
    lane_t ma, mb, ia, ib, rate, slop;
    uint32_t a[LANES], b[LANES];
    uint8_t lanes, point_count;
    uint8_t fixed_a, fixed_b; /* as in solver_batch */
};

struct solver_position_point {
    lane_lever_t rn;
    lane_t normal_mass, separation;
};

static int kind_points(batch_kind_t kind) {
    return kind == BATCH_SINGLE ? 1 : 2;
}

/* The two bodies of a batch, lane by lane: velocities, and the inverse
 * masses, which are loaded with them. */
typedef struct {
    lane_t vx, vy, w;
    lane_t inverse_mass, inverse_inertia;
} lane_body_t;

/* yes where condition holds, no elsewhere; and scalar.h's max_of and
 * min_of, lane by lane. Macros, not functions: a vector passed by value
 * goes through memory on the baseline instruction set. Arguments must be
 * free of side effects. */
#define select_lane(condition, yes, no) \
    ((lane_t)(((mask_t)(yes) & (condition)) | ((mask_t)(no) & ~(condition))))
#define max_lane(a, b) select_lane((mask_t)((a) > (b)), (a), (b))
#define min_lane(a, b) select_lane((mask_t)((a) < (b)), (a), (b))

/* Lanes picked from two vectors: indices 0 to 3 name a's lanes, 4 to 7
 * b's (GCC and Clang spell the builtin differently). */
#if defined(__clang__)
#define shuffle_lanes(a, b, i, j, k, l) __builtin_shufflevector((a), (b), i, j, k, l)
#else
#define shuffle_lanes(a, b, i, j, k, l) __builtin_shuffle((a), (b), (mask_t){i, j, k, l})
#endif

/* Four vectors of four doubles, as rows or as columns. */
typedef struct {
    lane_t v0, v1, v2, v3;
} lane_quad_t;

/* Rows to columns and back: out.v<c>[l] = in.v<l>[c]. */
LANE_INLINE lane_quad_t transpose(lane_quad_t in) {
    lane_t low01 = shuffle_lanes(in.v0, in.v1, 0, 4, 2, 6);
    lane_t high01 = shuffle_lanes(in.v0, in.v1, 1, 5, 3, 7);
    lane_t low23 = shuffle_lanes(in.v2, in.v3, 0, 4, 2, 6);
    lane_t high23 = shuffle_lanes(in.v2, in.v3, 1, 5, 3, 7);
    return (lane_quad_t){shuffle_lanes(low01, low23, 0, 1, 4, 5),
                         shuffle_lanes(high01, high23, 0, 1, 4, 5),
                         shuffle_lanes(low01, low23, 2, 3, 6, 7),
                         shuffle_lanes(high01, high23, 2, 3, 6, 7)};
}

LANE_INLINE lane_t load_lane(const void *source) {
    lane_t value;
    memcpy(&value, source, sizeof value);
    return value;
}

/* Rows of `stride` bytes at rows + index[l] * stride begin with four
 * doubles; each row's four are one vector load, and four rows transposed
 * give each double's four lanes. */
LANE_INLINE lane_quad_t load_columns(const void *rows, size_t stride,
                                     const uint32_t index[LANES]) {
    const char *base = rows;
    return transpose((lane_quad_t){load_lane(base + index[0] * stride),
                                   load_lane(base + index[1] * stride),
                                   load_lane(base + index[2] * stride),
                                   load_lane(base + index[3] * stride)});
}

/* The inverse of load_columns, for a full batch: all four rows written
 * back as vectors. (A partial batch writes lane by lane, so that its empty
 * lanes, which read row 0, do not write it.) */
LANE_INLINE void store_columns(void *rows, size_t stride, const uint32_t index[LANES],
                               lane_quad_t columns) {
    char *base = rows;
    lane_quad_t stored = transpose(columns);
    memcpy(base + index[0] * stride, &stored.v0, sizeof(lane_t));
    memcpy(base + index[1] * stride, &stored.v1, sizeof(lane_t));
    memcpy(base + index[2] * stride, &stored.v2, sizeof(lane_t));
    memcpy(base + index[3] * stride, &stored.v3, sizeof(lane_t));
}

/* A velocity row begins with v.x, v.y, w and inverse_mass (solver.h); the
 * inverse inertias come from the batch. */
LANE_INLINE lane_body_t gather(const solver_velocity_t *rows, const uint32_t index[LANES],
                               const lane_t *inverse_inertia) {
    lane_quad_t columns = load_columns(rows, sizeof *rows, index);
    return (lane_body_t){
        .vx = columns.v0,
        .vy = columns.v1,
        .w = columns.v2,
        .inverse_mass = columns.v3,
        .inverse_inertia = *inverse_inertia,
    };
}

/* The inverse mass goes back unchanged. */
LANE_INLINE void scatter(solver_velocity_t *rows, const uint32_t index[LANES], int lanes,
                         const lane_body_t *body) {
    if (lanes == LANES) {
        store_columns(rows, sizeof *rows, index,
                      (lane_quad_t){body->vx, body->vy, body->w, body->inverse_mass});
        return;
    }
    for (int l = 0; l < lanes; l++) {
        solver_velocity_t *row = &rows[index[l]];
        row->v.x = body->vx[l];
        row->v.y = body->vy[l];
        row->w = body->w[l];
    }
}

/* gather and scatter for threads that share a colour (solver_split.h): a
 * partial batch reads its lanes one by one, not row 0 for the empty ones,
 * which another thread may be writing, and the rows of bodies that cannot
 * move (fixed, a lane mask) are not written, since other batches of the
 * colour read them. Those rows would be written unchanged. Both kinds of
 * row begin with the four doubles load_columns reads, the first three
 * of which a sweep changes. */
LANE_INLINE lane_quad_t load_lanes(const void *rows, size_t stride, const uint32_t index[LANES],
                                   int lanes) {
    double columns[4][LANES] = {{0.0}};
    for (int l = 0; l < lanes; l++) {
        double row[4];
        memcpy(row, (const char *)rows + index[l] * stride, sizeof row);
        for (int c = 0; c < 4; c++) columns[c][l] = row[c];
    }
    return (lane_quad_t){load_lane(columns[0]), load_lane(columns[1]), load_lane(columns[2]),
                         load_lane(columns[3])};
}

LANE_INLINE void store_lanes(void *rows, size_t stride, const uint32_t index[LANES], int lanes,
                             unsigned fixed, lane_quad_t columns) {
    for (int l = 0; l < lanes; l++) {
        if (fixed & (1u << l)) continue;
        double row[3] = {columns.v0[l], columns.v1[l], columns.v2[l]};
        memcpy((char *)rows + index[l] * stride, row, sizeof row);
    }
}

LANE_INLINE lane_body_t gather_shared(const solver_velocity_t *rows, const uint32_t index[LANES],
                                      int lanes, const lane_t *inverse_inertia) {
    if (lanes == LANES) return gather(rows, index, inverse_inertia);
    lane_quad_t columns = load_lanes(rows, sizeof *rows, index, lanes);
    return (lane_body_t){.vx = columns.v0, .vy = columns.v1, .w = columns.v2,
                         .inverse_mass = columns.v3, .inverse_inertia = *inverse_inertia};
}

LANE_INLINE void scatter_shared(solver_velocity_t *rows, const uint32_t index[LANES], int lanes,
                                unsigned fixed, const lane_body_t *body) {
    if (lanes == LANES && fixed == 0) {
        scatter(rows, index, lanes, body);
        return;
    }
    store_lanes(rows, sizeof *rows, index, lanes, fixed,
                (lane_quad_t){body->vx, body->vy, body->w, body->inverse_mass});
}

/* The two bodies of batch, gathered for a sweep by one thread or, when
 * shared, by threads that share its colour; and scattered back. */
LANE_INLINE void gather_pair(const solver_velocity_t *rows, const solver_batch_t *batch,
                             bool shared, lane_body_t *a, lane_body_t *b) {
    if (shared) {
        *a = gather_shared(rows, batch->a, batch->lanes, &batch->ia);
        *b = gather_shared(rows, batch->b, batch->lanes, &batch->ib);
        return;
    }
    *a = gather(rows, batch->a, &batch->ia);
    *b = gather(rows, batch->b, &batch->ib);
}

LANE_INLINE void scatter_pair(solver_velocity_t *rows, const solver_batch_t *batch, bool shared,
                              const lane_body_t *a, const lane_body_t *b) {
    if (shared) {
        scatter_shared(rows, batch->a, batch->lanes, batch->fixed_a, a);
        scatter_shared(rows, batch->b, batch->lanes, batch->fixed_b, b);
        return;
    }
    scatter(rows, batch->a, batch->lanes, a);
    scatter(rows, batch->b, batch->lanes, b);
}

/* Relative velocity of b over a along direction d, lever terms r.
 * Directions and lever terms go by pointer: vectors passed by value would
 * go through memory on the baseline instruction set. */
LANE_INLINE lane_t relative_along(const lane_body_t *a, const lane_body_t *b,
                                  const lane_vector_t *d, const lane_lever_t *r) {
    return d->x * (b->vx - a->vx) + d->y * (b->vy - a->vy) + b->w * r->b - a->w * r->a;
}

LANE_INLINE void apply_along(lane_body_t *a, lane_body_t *b, const lane_vector_t *d,
                             const lane_lever_t *r, const lane_t *impulse) {
    lane_t lambda = *impulse;
    a->vx -= a->inverse_mass * lambda * d->x;
    a->vy -= a->inverse_mass * lambda * d->y;
    a->w -= a->inverse_inertia * lambda * r->a;
    b->vx += b->inverse_mass * lambda * d->x;
    b->vy += b->inverse_mass * lambda * d->y;
    b->w += b->inverse_inertia * lambda * r->b;
}

LANE_INLINE void solve_friction(const solver_batch_t *batch, lane_point_t *points, int count,
                                lane_body_t *a, lane_body_t *b) {
    lane_vector_t tangent = {-batch->normal.y, batch->normal.x};
    for (int i = 0; i < count; i++) {
        lane_point_t *p = &points[i];
        lane_t vt = relative_along(a, b, &tangent, &p->rt);
        lane_t limit = batch->friction * p->normal_impulse;
        lane_t wanted = p->tangent_impulse - p->tangent_mass * vt;
        lane_t total = max_lane(-limit, min_lane(wanted, limit));
        lane_t delta = total - p->tangent_impulse;
        p->tangent_impulse = total;
        apply_along(a, b, &tangent, &p->rt, &delta);
    }
}

LANE_INLINE void solve_normal_points(const solver_batch_t *batch, lane_point_t *points, int count,
                                     lane_body_t *a, lane_body_t *b) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < count; i++) {
        lane_point_t *p = &points[i];
        lane_t vn = relative_along(a, b, &batch->normal, &p->rn);
        lane_t wanted = p->normal_impulse - p->normal_mass * (vn - p->target);
        lane_t total = max_lane(wanted, zero);
        lane_t delta = total - p->normal_impulse;
        p->normal_impulse = total;
        apply_along(a, b, &batch->normal, &p->rn, &delta);
    }
}

/* velocity_solve.c's block solve with its four cases evaluated in every lane and
 * the first that holds selected (the case order is the scalar one). */
LANE_INLINE void solve_normal_block(const solver_batch_t *batch, lane_point_t *points,
                                    const lane_block_t *k, lane_body_t *a, lane_body_t *b) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    lane_point_t *p1 = &points[0], *p2 = &points[1];
    lane_t a1 = p1->normal_impulse, a2 = p2->normal_impulse;
    lane_t b1 = relative_along(a, b, &batch->normal, &p1->rn) - p1->target;
    lane_t b2 = relative_along(a, b, &batch->normal, &p2->rn) - p2->target;
    b1 -= k->k11 * a1 + k->k12 * a2;
    b2 -= k->k12 * a1 + k->k22 * a2;

    lane_t both1 = -(k->m11 * b1 + k->m12 * b2);
    lane_t both2 = -(k->m12 * b1 + k->m22 * b2);
    mask_t both = (mask_t)(both1 >= zero) & (mask_t)(both2 >= zero);
    lane_t first = -p1->normal_mass * b1;
    mask_t first_only = (mask_t)(first >= zero) & (mask_t)(k->k12 * first + b2 >= zero);
    lane_t second = -p2->normal_mass * b2;
    mask_t second_only = (mask_t)(second >= zero) & (mask_t)(k->k12 * second + b1 >= zero);
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
    a->vx -= a->inverse_mass * total * batch->normal.x;
    a->vy -= a->inverse_mass * total * batch->normal.y;
    a->w -= a->inverse_inertia * (d1 * p1->rn.a + d2 * p2->rn.a);
    b->vx += b->inverse_mass * total * batch->normal.x;
    b->vy += b->inverse_mass * total * batch->normal.y;
    b->w += b->inverse_inertia * (d1 * p1->rn.b + d2 * p2->rn.b);
    p1->normal_impulse = x1;
    p2->normal_impulse = x2;
}

/* Built twice where the compiler can (GCC on x86-64 with ifunc support):
 * once for AVX2, which does a batch's four lanes in one instruction, and
 * once for the baseline (two SSE2 instructions); the loader picks the one
 * the processor runs. Neither uses fused multiply-add, so both give the
 * same numbers. Clang 14 leaves calls to such functions undefined at link
 * time, so it builds the baseline only; so does ThreadSanitizer (make
 * tsan), whose instrumented resolver runs before it is set up, and crashes. */
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__) && \
    !defined(__SANITIZE_THREAD__)
#define LANE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define LANE_CLONES
#endif

/* Where batch `batch` (in group g) finds its first point and its block. */
static size_t first_point(const solver_wide_t *wide, size_t g, size_t batch) {
    return wide->group_point[g] + (batch - wide->group_batch[g]) * kind_points(g % BATCH_KINDS);
}

static size_t first_block(const solver_wide_t *wide, size_t g, size_t batch) {
    return wide->group_block[g] + (g % BATCH_KINDS == BATCH_BLOCK ? batch - wide->group_batch[g] : 0);
}

/* The group that holds batch `batch`. */
static size_t group_of(const solver_wide_t *wide, size_t batch) {
    size_t g = 0;
    while (wide->group_batch[g + 1] <= batch) g++;
    return g;
}

LANE_INLINE void warm_batches(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                              size_t end, const lane_point_t *points, bool shared) {
    for (size_t i = begin; i < end; i++) {
        const solver_batch_t *batch = &wide->batches[i];
        lane_body_t a, b;
        gather_pair(rows, batch, shared, &a, &b);
        lane_vector_t tangent = {-batch->normal.y, batch->normal.x};
        int count = kind_points((batch_kind_t)batch->kind);
        for (int k = 0; k < count; k++, points++) {
            apply_along(&a, &b, &batch->normal, &points->rn, &points->normal_impulse);
            apply_along(&a, &b, &tangent, &points->rt, &points->tangent_impulse);
        }
        scatter_pair(rows, batch, shared, &a, &b);
    }
}

LANE_CLONES
void solver_wide_warm_start(solver_wide_t *wide, solver_velocity_t *rows) {
    warm_batches(wide, rows, 0, wide->batch_count, wide->points, false);
}

LANE_CLONES
void solver_wide_warm_start_range(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                                  size_t end) {
    if (begin == end) return;
    size_t g = group_of(wide, begin);
    warm_batches(wide, rows, begin, end, wide->points + first_point(wide, g, begin), true);
}

LANE_INLINE void iterate_batches(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                                 size_t end, lane_point_t *points, const lane_block_t *blocks,
                                 bool shared) {
    for (size_t i = begin; i < end; i++) {
        const solver_batch_t *batch = &wide->batches[i];
        lane_body_t a, b;
        gather_pair(rows, batch, shared, &a, &b);
        switch (batch->kind) {
        case BATCH_BLOCK:
            solve_friction(batch, points, 2, &a, &b);
            solve_normal_block(batch, points, blocks++, &a, &b);
            points += 2;
            break;
        case BATCH_PAIR:
            solve_friction(batch, points, 2, &a, &b);
            solve_normal_points(batch, points, 2, &a, &b);
            points += 2;
            break;
        default:
            solve_friction(batch, points, 1, &a, &b);
            solve_normal_points(batch, points, 1, &a, &b);
            points += 1;
            break;
        }
        scatter_pair(rows, batch, shared, &a, &b);
    }
}

LANE_CLONES
void solver_wide_iterate(solver_wide_t *wide, solver_velocity_t *rows) {
    iterate_batches(wide, rows, 0, wide->batch_count, wide->points, wide->blocks, false);
}

LANE_CLONES
void solver_wide_iterate_range(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                               size_t end) {
    if (begin == end) return;
    size_t g = group_of(wide, begin);
    iterate_batches(wide, rows, begin, end, wide->points + first_point(wide, g, begin),
                    wide->blocks + first_block(wide, g, begin), true);
}

/* The bodies' displacements in a batch, lane by lane. */
typedef struct {
    lane_t dx, dy, dtheta, radius; /* radius: carried through unchanged */
} lane_displacement_t;

LANE_INLINE lane_displacement_t gather_displacements(const solver_displacement_t *rows,
                                                     const uint32_t index[LANES]) {
    lane_quad_t columns = load_columns(rows, sizeof *rows, index);
    return (lane_displacement_t){.dx = columns.v0, .dy = columns.v1, .dtheta = columns.v2,
                                 .radius = columns.v3};
}

LANE_INLINE void scatter_displacements(solver_displacement_t *rows, const uint32_t index[LANES],
                                       int lanes, const lane_displacement_t *moved) {
    if (lanes == LANES) {
        store_columns(rows, sizeof *rows, index,
                      (lane_quad_t){moved->dx, moved->dy, moved->dtheta, moved->radius});
        return;
    }
    for (int l = 0; l < lanes; l++) {
        solver_displacement_t *row = &rows[index[l]];
        row->dx.x = moved->dx[l];
        row->dx.y = moved->dy[l];
        row->dtheta = moved->dtheta[l];
    }
}

/* position_pass.c's solver_solve_position, lane by lane. */
LANE_INLINE void correct_batch(const solver_position_batch_t *batch,
                               const solver_position_point_t *points, lane_displacement_t *a,
                               lane_displacement_t *b) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    const lane_t most = zero - SOLVER_MAX_POSITION_CORRECTION;
    const lane_vector_t *n = &batch->normal;
    for (int i = 0; i < batch->point_count; i++) {
        const lane_lever_t *rn = &points[i].rn;
        lane_t separation = points[i].separation +
                            (n->x * (b->dx - a->dx) + n->y * (b->dy - a->dy)) +
                            b->dtheta * rn->b - a->dtheta * rn->a;
        lane_t wanted = batch->rate * (separation + batch->slop);
        lane_t capped = min_lane(wanted, zero);
        lane_t error = max_lane(most, capped);
        lane_t lambda = -error * points[i].normal_mass;
        a->dx -= batch->ma * lambda * n->x;
        a->dy -= batch->ma * lambda * n->y;
        a->dtheta -= batch->ia * lambda * rn->a;
        b->dx += batch->mb * lambda * n->x;
        b->dy += batch->mb * lambda * n->y;
        b->dtheta += batch->ib * lambda * rn->b;
    }
}

/* gather_shared and scatter_shared for the displacements. */
LANE_INLINE lane_displacement_t gather_displacements_shared(const solver_displacement_t *rows,
                                                            const uint32_t index[LANES],
                                                            int lanes) {
    if (lanes == LANES) return gather_displacements(rows, index);
    lane_quad_t columns = load_lanes(rows, sizeof *rows, index, lanes);
    return (lane_displacement_t){.dx = columns.v0, .dy = columns.v1, .dtheta = columns.v2,
                                 .radius = columns.v3};
}

LANE_INLINE void scatter_displacements_shared(solver_displacement_t *rows,
                                              const uint32_t index[LANES], int lanes,
                                              unsigned fixed, const lane_displacement_t *moved) {
    if (lanes == LANES && fixed == 0) {
        scatter_displacements(rows, index, lanes, moved);
        return;
    }
    store_lanes(rows, sizeof *rows, index, lanes, fixed,
                (lane_quad_t){moved->dx, moved->dy, moved->dtheta, moved->radius});
}

LANE_INLINE void correct_one(const solver_position_batch_t *batch,
                             const solver_position_point_t *points,
                             solver_displacement_t *displacements, bool shared) {
    if (shared) {
        lane_displacement_t a = gather_displacements_shared(displacements, batch->a, batch->lanes);
        lane_displacement_t b = gather_displacements_shared(displacements, batch->b, batch->lanes);
        correct_batch(batch, points, &a, &b);
        scatter_displacements_shared(displacements, batch->a, batch->lanes, batch->fixed_a, &a);
        scatter_displacements_shared(displacements, batch->b, batch->lanes, batch->fixed_b, &b);
        return;
    }
    lane_displacement_t a = gather_displacements(displacements, batch->a);
    lane_displacement_t b = gather_displacements(displacements, batch->b);
    correct_batch(batch, points, &a, &b);
    scatter_displacements(displacements, batch->a, batch->lanes, &a);
    scatter_displacements(displacements, batch->b, batch->lanes, &b);
}

LANE_CLONES
void solver_wide_correct_positions(solver_wide_t *wide, solver_displacement_t *displacements,
                                   bool backward) {
    size_t count = wide->batch_count;
    if (!backward) {
        const solver_position_point_t *points = wide->position_points;
        for (size_t i = 0; i < count; i++) {
            const solver_position_batch_t *batch = &wide->position_batches[i];
            correct_one(batch, points, displacements, false);
            points += batch->point_count;
        }
        return;
    }
    const solver_position_point_t *points = wide->position_points + wide->point_count;
    for (size_t i = count; i-- > 0;) {
        const solver_position_batch_t *batch = &wide->position_batches[i];
        points -= batch->point_count;
        correct_one(batch, points, displacements, false);
    }
}

LANE_CLONES
void solver_wide_correct_range(solver_wide_t *wide, solver_displacement_t *displacements,
                               size_t begin, size_t end) {
    if (begin == end) return;
    const solver_position_point_t *points =
        wide->position_points + first_point(wide, group_of(wide, begin), begin);
    for (size_t i = begin; i < end; i++) {
        const solver_position_batch_t *batch = &wide->position_batches[i];
        correct_one(batch, points, displacements, true);
        points += batch->point_count;
    }
}

/* Where a batch is packed: its index, its first point's and its block's. */
typedef struct {
    size_t batch, point, block;
} pack_at_t;

LANE_INLINE void pack_lane(solver_wide_t *wide, pack_at_t at, const solver_contact_t *c, uint32_t index,
                      int l, const solver_velocity_t *rows) {
    solver_batch_t *batch = &wide->batches[at.batch];
    solver_position_batch_t *position = &wide->position_batches[at.batch];
    batch->a[l] = position->a[l] = c->a;
    batch->b[l] = position->b[l] = c->b;
    batch->contact[l] = index;
    batch->normal.x[l] = position->normal.x[l] = c->normal.x;
    batch->normal.y[l] = position->normal.y[l] = c->normal.y;
    batch->friction[l] = c->friction;
    position->ma[l] = rows[c->a].inverse_mass;
    position->mb[l] = rows[c->b].inverse_mass;
    batch->ia[l] = position->ia[l] = rows[c->a].inverse_inertia;
    batch->ib[l] = position->ib[l] = rows[c->b].inverse_inertia;
    position->rate[l] = solver_position_rate(&rows[c->a], &rows[c->b]);
    position->slop[l] = c->slop;
    if (batch->kind == BATCH_BLOCK) {
        lane_block_t *k = &wide->blocks[at.block];
        k->k11[l] = c->k11;
        k->k12[l] = c->k12;
        k->k22[l] = c->k22;
        k->m11[l] = c->m11;
        k->m12[l] = c->m12;
        k->m22[l] = c->m22;
    }
    for (int i = 0; i < c->point_count; i++) {
        const solver_point_t *p = &c->points[i];
        lane_point_t *lp = &wide->points[at.point + (size_t)i];
        lp->rn.a[l] = p->rn_a;
        lp->rn.b[l] = p->rn_b;
        lp->rt.a[l] = p->rt_a;
        lp->rt.b[l] = p->rt_b;
        lp->normal_mass[l] = p->normal_mass;
        lp->tangent_mass[l] = p->tangent_mass;
        lp->target[l] = p->target;
        lp->normal_impulse[l] = p->normal_impulse;
        lp->tangent_impulse[l] = p->tangent_impulse;
        solver_position_point_t *pp = &wide->position_points[at.point + (size_t)i];
        pp->rn.a[l] = p->rn_a;
        pp->rn.b[l] = p->rn_b;
        pp->normal_mass[l] = p->normal_mass;
        pp->separation[l] = p->separation;
    }
}

/* How many contacts ahead of the one being packed are asked for: the
 * colours' order scatters the packing's reads over the contact buffer,
 * which a pile of 4000 bodies holds more of than the cache (measured:
 * 27% of the packing's time waited on each contact's first field). */
enum { PACK_AHEAD = 2 * LANES };

/* Asks for the lines of contacts order[from .. from + LANES), as far as
 * total. A macro: GCC deems a function of prefetches alone const and drops
 * its calls. */
#define PREFETCH_CONTACTS(contacts, order, from, total)                                      \
    do {                                                                                    \
        size_t end_ = (from) + LANES < (total) ? (from) + LANES : (total);                  \
        for (size_t k_ = (from); k_ < end_; k_++) {                                         \
            const char *line_ = (const char *)&(contacts)[(order)[k_]];                     \
            for (size_t at_ = 0; at_ < sizeof(solver_contact_t); at_ += 64) {               \
                __builtin_prefetch(line_ + at_);                                            \
            }                                                                               \
        }                                                                                   \
    } while (0)

/* Packs order[0 .. count) (at most LANES contacts of one kind) into the
 * batch, points and block at `at`. */
LANE_INLINE void load_batch(solver_wide_t *wide, pack_at_t at, const uint32_t *order, int count,
                       batch_kind_t kind, const solver_contact_t *contacts,
                       const solver_velocity_t *rows) {
    int points = kind_points(kind);
    solver_batch_t *batch = &wide->batches[at.batch];
    solver_position_batch_t *position = &wide->position_batches[at.batch];
    if (count < LANES) { /* a full batch has every lane written below */
        memset(batch, 0, sizeof *batch);
        memset(position, 0, sizeof *position);
        memset(&wide->points[at.point], 0, (size_t)points * sizeof(lane_point_t));
        memset(&wide->position_points[at.point], 0,
               (size_t)points * sizeof(solver_position_point_t));
        if (kind == BATCH_BLOCK) memset(&wide->blocks[at.block], 0, sizeof(lane_block_t));
    }
    batch->lanes = position->lanes = (uint8_t)count;
    batch->kind = (uint8_t)kind;
    position->point_count = (uint8_t)points;
    for (int l = 0; l < count; l++) pack_lane(wide, at, &contacts[order[l]], order[l], l, rows);
}

static batch_kind_t kind_of(const solver_contact_t *c) {
    if (c->block) return BATCH_BLOCK;
    return c->point_count == 2 ? BATCH_PAIR : BATCH_SINGLE;
}

enum { GROUPS = BATCH_KINDS * COLORING_MAX_COLORS };

_Static_assert((int)GROUPS < (int)COLORING_NONE, "a group fits where its contact's colour was");

/* Orders the contacts by colour, and within a colour by kind; the
 * uncoloured go to the loose list. Fills start (GROUPS + 1 entries) with
 * the group boundaries in wide->order. The first pass turns each colour
 * into its group, so that the second reads a byte per contact rather than
 * the contact. */
static void sort_by_color(solver_wide_t *wide, const solver_contact_t *contacts, size_t count,
                          uint32_t *start) {
    memset(start, 0, (GROUPS + 1) * sizeof(uint32_t));
    wide->loose_count = 0;
    uint8_t *group = wide->colors;
    for (size_t i = 0; i < count; i++) {
        if (group[i] == COLORING_NONE) {
            wide->loose[wide->loose_count++] = (uint32_t)i;
            continue;
        }
        group[i] = (uint8_t)(BATCH_KINDS * group[i] + kind_of(&contacts[i]));
        start[group[i] + 1]++;
    }
    for (int g = 0; g < GROUPS; g++) start[g + 1] += start[g];
    uint32_t next[GROUPS];
    memcpy(next, start, sizeof next);
    for (size_t i = 0; i < count; i++) {
        if (group[i] == COLORING_NONE) continue;
        wide->order[next[group[i]]++] = (uint32_t)i;
    }
}

static void reserve(solver_wide_t *wide, size_t count) {
    /* At most one partly filled batch per group. */
    size_t batches = count / LANES + GROUPS;
    memory_reserve((void **)&wide->colors, &wide->color_capacity, count, sizeof(uint8_t));
    memory_reserve((void **)&wide->order, &wide->order_capacity, count, sizeof(uint32_t));
    memory_reserve((void **)&wide->loose, &wide->loose_capacity, count, sizeof(uint32_t));
    memory_reserve((void **)&wide->batches, &wide->batch_capacity, batches,
                   sizeof(solver_batch_t));
    memory_reserve((void **)&wide->position_batches, &wide->position_batch_capacity, batches,
                   sizeof(solver_position_batch_t));
    memory_reserve((void **)&wide->points, &wide->point_capacity, 2 * batches,
                   sizeof(lane_point_t));
    memory_reserve((void **)&wide->position_points, &wide->position_point_capacity, 2 * batches,
                   sizeof(solver_position_point_t));
    memory_reserve((void **)&wide->blocks, &wide->block_capacity, batches, sizeof(lane_block_t));
}

/* Where each group's batches, points and blocks begin, from where its
 * contacts begin in wide->order (start, GROUPS + 1 entries). */
static void place_groups(solver_wide_t *wide, const uint32_t *start) {
    wide->group_batch[0] = wide->group_point[0] = wide->group_block[0] = 0;
    for (int g = 0; g < GROUPS; g++) {
        uint32_t batches = (start[g + 1] - start[g] + LANES - 1) / LANES;
        batch_kind_t kind = (batch_kind_t)(g % BATCH_KINDS);
        wide->group_batch[g + 1] = wide->group_batch[g] + batches;
        wide->group_point[g + 1] = wide->group_point[g] + batches * (uint32_t)kind_points(kind);
        wide->group_block[g + 1] = wide->group_block[g] + (kind == BATCH_BLOCK ? batches : 0);
    }
    wide->batch_count = wide->group_batch[GROUPS];
    wide->point_count = wide->group_point[GROUPS];
    wide->block_count = wide->group_block[GROUPS];
}

void solver_wide_pack(solver_wide_t *wide, const solver_contact_t *contacts,
                      const solver_velocity_t *rows, size_t begin, size_t end) {
    size_t g = begin < end ? group_of(wide, begin) : 0;
    for (size_t i = begin; i < end; i++) {
        while (wide->group_batch[g + 1] <= i) g++;
        pack_at_t at = {i, first_point(wide, g, i), first_block(wide, g, i)};
        uint32_t first = wide->group_start[g] + (uint32_t)(i - wide->group_batch[g]) * LANES;
        uint32_t left = wide->group_start[g + 1] - first;
        int n = (int)(left < LANES ? left : LANES);
        PREFETCH_CONTACTS(contacts, wide->order, first + PACK_AHEAD, wide->group_start[GROUPS]);
        load_batch(wide, at, wide->order + first, n, (batch_kind_t)(g % BATCH_KINDS), contacts,
                   rows);
    }
}

void solver_wide_arrange(solver_wide_t *wide, const solver_contact_t *contacts, size_t count,
                         const solver_velocity_t *rows, size_t body_count) {
    reserve(wide, count);
    coloring_assign(&wide->coloring, contacts, count, rows, body_count, wide->colors);
    uint32_t *start = wide->group_start;
    sort_by_color(wide, contacts, count, start);
    place_groups(wide, start);
}

void solver_wide_pack_all(solver_wide_t *wide, const solver_contact_t *contacts,
                          const solver_velocity_t *rows) {
    const uint32_t *start = wide->group_start;
    pack_at_t at = {0, 0, 0};
    for (int g = 0; g < GROUPS; g++) {
        batch_kind_t kind = (batch_kind_t)(g % BATCH_KINDS);
        for (uint32_t i = start[g]; i < start[g + 1]; i += LANES) {
            int n = (int)(start[g + 1] - i < LANES ? start[g + 1] - i : LANES);
            PREFETCH_CONTACTS(contacts, wide->order, i + PACK_AHEAD, start[GROUPS]);
            load_batch(wide, at, wide->order + i, n, kind, contacts, rows);
            at.batch++;
            at.point += (size_t)kind_points(kind);
            at.block += kind == BATCH_BLOCK;
        }
    }
}

void solver_wide_mark_fixed(solver_wide_t *wide, const solver_velocity_t *rows, size_t begin,
                            size_t end) {
    for (size_t i = begin; i < end; i++) {
        solver_batch_t *batch = &wide->batches[i];
        uint8_t fixed_a = 0, fixed_b = 0;
        for (int l = 0; l < batch->lanes; l++) {
            fixed_a |= (uint8_t)(solver_row_is_static(&rows[batch->a[l]]) << l);
            fixed_b |= (uint8_t)(solver_row_is_static(&rows[batch->b[l]]) << l);
        }
        batch->fixed_a = wide->position_batches[i].fixed_a = fixed_a;
        batch->fixed_b = wide->position_batches[i].fixed_b = fixed_b;
    }
}

void solver_wide_store_range(const solver_wide_t *wide, solver_contact_t *contacts, size_t begin,
                             size_t end) {
    if (begin == end) return;
    const lane_point_t *points = wide->points + first_point(wide, group_of(wide, begin), begin);
    for (size_t i = begin; i < end; i++) {
        const solver_batch_t *batch = &wide->batches[i];
        for (int l = 0; l < batch->lanes; l++) {
            solver_contact_t *c = &contacts[batch->contact[l]];
            for (int k = 0; k < c->point_count; k++) {
                c->points[k].normal_impulse = points[k].normal_impulse[l];
                c->points[k].tangent_impulse = points[k].tangent_impulse[l];
            }
        }
        points += kind_points((batch_kind_t)batch->kind);
    }
}

void solver_wide_store(const solver_wide_t *wide, solver_contact_t *contacts) {
    solver_wide_store_range(wide, contacts, 0, wide->batch_count);
}

/* Pushes both ends of contact batch->contact[l] onto its bodies' lists. */
LANE_INLINE void link_lane(const solver_batch_t *batch, int l, uint32_t *first,
                           solver_side_t *sides) {
    uint32_t a = batch->a[l], b = batch->b[l], side = 2 * batch->contact[l];
    sides[side] = (solver_side_t){first[a], b};
    first[a] = side;
    sides[side + 1] = (solver_side_t){first[b], a};
    first[b] = side + 1;
}

bool solver_wide_link_loaded(const solver_wide_t *wide, uint32_t *first, solver_side_t *sides,
                             solver_slot_t *slots) {
    const lane_point_t *points = wide->points;
    solver_slot_t slot = 0; /* LANES times the index of the batch's first point */
    bool any = false;
    for (size_t i = 0; i < wide->batch_count; i++) {
        const solver_batch_t *batch = &wide->batches[i];
        const lane_t *first_impulse = &points[0].normal_impulse;
        if (batch->kind == BATCH_SINGLE) {
            /* No slot: only a two-point contact's impulses are asked for. */
            for (int l = 0; l < batch->lanes; l++) {
                if (!((*first_impulse)[l] > 0.0)) continue;
                link_lane(batch, l, first, sides);
                any = true;
            }
            points += 1;
            slot += LANES;
            continue;
        }
        const lane_t *second_impulse = &points[1].normal_impulse;
        for (int l = 0; l < batch->lanes; l++) {
            if (!((*first_impulse)[l] > 0.0 || (*second_impulse)[l] > 0.0)) continue;
            link_lane(batch, l, first, sides);
            slots[batch->contact[l]] = slot + (solver_slot_t)l;
            any = true;
        }
        points += 2;
        slot += 2 * LANES;
    }
    return any;
}

void solver_wide_impulses(const solver_wide_t *wide, solver_slot_t slot, int point_count,
                          double normal[2], double tangent[2]) {
    const lane_point_t *p = &wide->points[slot / LANES];
    int l = (int)(slot % LANES);
    for (int k = 0; k < point_count; k++) {
        normal[k] = p[k].normal_impulse[l];
        tangent[k] = p[k].tangent_impulse[l];
    }
}

void solver_wide_free(solver_wide_t *wide) {
    coloring_free(&wide->coloring);
    memory_free(wide->colors);
    memory_free(wide->order);
    memory_free(wide->batches);
    memory_free(wide->position_batches);
    memory_free(wide->points);
    memory_free(wide->position_points);
    memory_free(wide->blocks);
    memory_free(wide->loose);
    memset(wide, 0, sizeof *wide);
}
