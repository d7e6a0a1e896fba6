/*
 * The colour batches' sweeps (solver_wide.h): warm starting, the velocity
 * iterations and the position iterations, four contacts at a time, over
 * every batch or over a range of one colour's.
 */
#include "solver/solver_wide.h"
#include <string.h>
#include "solver/solver_wide_private.h"

/* The two bodies of a batch, lane by lane: velocities, and the inverse
 * masses, which are loaded with them. */
typedef struct {
    lane_t vx, vy, w;
    lane_t inverse_mass, inverse_inertia;
} lane_body_t;

/* Rows of `stride` bytes at rows + index[l] * stride begin with four
 * doubles; each row's four are one vector load, and four rows transposed
 * give each double's four lanes. */
LANE_INLINE lane_quad_t load_columns(const void *rows, size_t stride,
                                     const uint32_t index[LANES]) {
    const char *base = rows;
    return gather_records(base + index[0] * stride, base + index[1] * stride,
                          base + index[2] * stride, base + index[3] * stride);
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
        const lane_t zero = {0.0, 0.0, 0.0, 0.0};
        lane_t pressed = p->normal_impulse - p->normal_mass * max_lane(p->target, zero);
        lane_t limit = batch->friction * max_lane(pressed, zero);
        lane_t wanted = p->tangent_impulse - p->tangent_mass * vt;
        lane_t total = max_lane(-limit, min_lane(wanted, limit));
        lane_t delta = total - p->tangent_impulse;
        p->tangent_impulse = total;
        apply_along(a, b, &tangent, &p->rt, &delta);
    }
}

/* relaxed: a raised target counts as 0 (the relaxation, solver.c). */
#define TARGET_OF(p, relaxed) ((relaxed) ? min_lane((p)->target, zero) : (p)->target)

LANE_INLINE void solve_normal_points(const solver_batch_t *batch, lane_point_t *points, int count,
                                     lane_body_t *a, lane_body_t *b, bool relaxed) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < count; i++) {
        lane_point_t *p = &points[i];
        lane_t vn = relative_along(a, b, &batch->normal, &p->rn);
        lane_t wanted = p->normal_impulse - p->normal_mass * (vn - TARGET_OF(p, relaxed));
        lane_t total = max_lane(wanted, zero);
        lane_t delta = total - p->normal_impulse;
        p->normal_impulse = total;
        apply_along(a, b, &batch->normal, &p->rn, &delta);
    }
}

/* contact_point.h's solve_block_cases with its four cases evaluated in
 * every lane and the first that holds selected (the scalar order); where
 * none holds, x1 and x2 keep what they held. nm1, nm2: the points' normal
 * masses. */
LANE_INLINE void solve_block_lanes(const lane_block_t *k, lane_t nm1, lane_t nm2, lane_t b1,
                                   lane_t b2, lane_t *x1, lane_t *x2) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    lane_t both1 = -(k->m11 * b1 + k->m12 * b2);
    lane_t both2 = -(k->m12 * b1 + k->m22 * b2);
    mask_t both = (mask_t)(both1 >= zero) & (mask_t)(both2 >= zero);
    lane_t first = -nm1 * b1;
    mask_t first_only = (mask_t)(first >= zero) & (mask_t)(k->k12 * first + b2 >= zero);
    lane_t second = -nm2 * b2;
    mask_t second_only = (mask_t)(second >= zero) & (mask_t)(k->k12 * second + b1 >= zero);
    mask_t neither = (mask_t)(b1 >= zero) & (mask_t)(b2 >= zero);

    *x1 = select_lane(neither, zero, *x1);
    *x2 = select_lane(neither, zero, *x2);
    *x1 = select_lane(second_only, zero, *x1);
    *x2 = select_lane(second_only, second, *x2);
    *x1 = select_lane(first_only, first, *x1);
    *x2 = select_lane(first_only, zero, *x2);
    *x1 = select_lane(both, both1, *x1);
    *x2 = select_lane(both, both2, *x2);
}

/* velocity_solve.c's block solve, lane by lane. */
LANE_INLINE void solve_normal_block(const solver_batch_t *batch, lane_point_t *points,
                                    const lane_block_t *k, lane_body_t *a, lane_body_t *b,
                                    bool relaxed) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    lane_point_t *p1 = &points[0], *p2 = &points[1];
    lane_t a1 = p1->normal_impulse, a2 = p2->normal_impulse;
    lane_t b1 = relative_along(a, b, &batch->normal, &p1->rn) - TARGET_OF(p1, relaxed);
    lane_t b2 = relative_along(a, b, &batch->normal, &p2->rn) - TARGET_OF(p2, relaxed);
    b1 -= k->k11 * a1 + k->k12 * a2;
    b2 -= k->k12 * a1 + k->k22 * a2;

    lane_t x1 = a1, x2 = a2;
    solve_block_lanes(k, p1->normal_mass, p2->normal_mass, b1, b2, &x1, &x2);

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

/* One batch's friction and normals, its bodies gathered in a and b; points
 * and blocks advanced past it. */
LANE_INLINE void solve_batch(const solver_batch_t *batch, lane_point_t **points,
                             const lane_block_t **blocks, lane_body_t *a, lane_body_t *b,
                             bool friction) {
    /* Each kind spelled out: its point count a constant, the loops over
     * points unrolled (one path with the count read from the batch ran
     * pile(1000) 0.8% more instructions). */
    switch (batch->kind) {
    case BATCH_BLOCK:
        if (friction) solve_friction(batch, *points, 2, a, b);
        solve_normal_block(batch, *points, (*blocks)++, a, b, !friction);
        *points += 2;
        break;
    case BATCH_PAIR:
        if (friction) solve_friction(batch, *points, 2, a, b);
        solve_normal_points(batch, *points, 2, a, b, !friction);
        *points += 2;
        break;
    default:
        if (friction) solve_friction(batch, *points, 1, a, b);
        solve_normal_points(batch, *points, 1, a, b, !friction);
        *points += 1;
        break;
    }
}

/* Two batches of one colour and kind side by side: no movable body in
 * common, so neither reads what the other writes, and the two chains of
 * dependent arithmetic overlap. One batch at a time, the sweeps waited on
 * each chain: pyramid(40)'s step took 10% longer. count: the kind's
 * points. */
LANE_INLINE void solve_two(const solver_batch_t *batch, lane_point_t *points,
                           const lane_block_t *blocks, lane_body_t *a, lane_body_t *b,
                           int count, bool friction) {
    if (friction) {
        solve_friction(&batch[0], points, count, &a[0], &b[0]);
        solve_friction(&batch[1], points + count, count, &a[1], &b[1]);
    }
    if (batch->kind == BATCH_BLOCK) {
        solve_normal_block(&batch[0], points, blocks, &a[0], &b[0], !friction);
        solve_normal_block(&batch[1], points + 2, blocks + 1, &a[1], &b[1], !friction);
        return;
    }
    solve_normal_points(&batch[0], points, count, &a[0], &b[0], !friction);
    solve_normal_points(&batch[1], points + count, count, &a[1], &b[1], !friction);
}

/* solve_two for the two batches at `batch`, each kind spelled out as in
 * solve_batch; points and blocks advanced past them. Apart from solve_batch:
 * one function taking one or two batches, its count a constant at each
 * call, ran pile(1000) 3.5% slower (measured). */
LANE_INLINE void solve_two_of_kind(const solver_batch_t *batch, lane_point_t **points,
                                   const lane_block_t **blocks, lane_body_t *a, lane_body_t *b,
                                   bool friction) {
    switch (batch->kind) {
    case BATCH_BLOCK:
        solve_two(batch, *points, *blocks, a, b, 2, friction);
        *points += 4;
        *blocks += 2;
        break;
    case BATCH_PAIR:
        solve_two(batch, *points, *blocks, a, b, 2, friction);
        *points += 4;
        break;
    default:
        solve_two(batch, *points, *blocks, a, b, 1, friction);
        *points += 2;
        break;
    }
}

/* Batches [begin, end) from their first point and block, two at a time
 * within a group. friction false: the normals only, raised targets
 * counted as 0 (the relaxation, solver.c), a constant at every call, so
 * each sweep is compiled with or without it. */
LANE_INLINE void iterate_batches(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                                 size_t end, lane_point_t *points, const lane_block_t *blocks,
                                 bool shared, bool friction) {
    size_t g = begin < end ? group_of(wide, begin) : 0;
    for (size_t i = begin; i < end;) {
        while (wide->group_batch[g + 1] <= i) g++;
        const solver_batch_t *batch = &wide->batches[i];
        /* Two at once only within a group: one colour and kind. */
        size_t group_end = wide->group_batch[g + 1] < end ? wide->group_batch[g + 1] : end;
        if (i + 1 < group_end) {
            lane_body_t a[2], b[2];
            gather_pair(rows, &batch[0], shared, &a[0], &b[0]);
            gather_pair(rows, &batch[1], shared, &a[1], &b[1]);
            solve_two_of_kind(batch, &points, &blocks, a, b, friction);
            scatter_pair(rows, &batch[0], shared, &a[0], &b[0]);
            scatter_pair(rows, &batch[1], shared, &a[1], &b[1]);
            i += 2;
            continue;
        }
        lane_body_t a, b;
        gather_pair(rows, batch, shared, &a, &b);
        solve_batch(batch, &points, &blocks, &a, &b, friction);
        scatter_pair(rows, batch, shared, &a, &b);
        i++;
    }
}

/* Batches [begin, end) of one colour, from their first point and block;
 * shared: rows shared with other threads. */
LANE_INLINE void iterate_range(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                               size_t end, bool shared, bool friction) {
    if (begin == end) return;
    size_t g = group_of(wide, begin);
    iterate_batches(wide, rows, begin, end, wide->points + first_point(wide, g, begin),
                    wide->blocks + first_block(wide, g, begin), shared, friction);
}

/* Every batch, the colours from the last to the first: within a colour the
 * order changes no number, so each colour is swept as forward. */
LANE_INLINE void iterate_backward(solver_wide_t *wide, solver_velocity_t *rows, bool friction) {
    for (int c = COLORING_MAX_COLORS; c-- > 0;) {
        iterate_range(wide, rows, wide->group_batch[c * BATCH_KINDS],
                      wide->group_batch[(c + 1) * BATCH_KINDS], false, friction);
    }
}

LANE_INLINE void iterate_all(solver_wide_t *wide, solver_velocity_t *rows, bool backward,
                             bool friction) {
    if (backward) {
        iterate_backward(wide, rows, friction);
        return;
    }
    iterate_batches(wide, rows, 0, wide->batch_count, wide->points, wide->blocks, false,
                    friction);
}

LANE_CLONES
void solver_wide_iterate(solver_wide_t *wide, solver_velocity_t *rows, bool backward) {
    iterate_all(wide, rows, backward, true);
}

LANE_CLONES
void solver_wide_iterate_range(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                               size_t end) {
    iterate_range(wide, rows, begin, end, true, true);
}

LANE_CLONES
void solver_wide_relax(solver_wide_t *wide, solver_velocity_t *rows, bool backward) {
    iterate_all(wide, rows, backward, false);
}

LANE_CLONES
void solver_wide_relax_range(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                             size_t end) {
    iterate_range(wide, rows, begin, end, true, false);
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

/* How far a point's overlap is to be pushed back in this pass (<= 0, m):
 * position_pass.c's error, lane by lane. */
LANE_INLINE lane_t position_error(const solver_position_batch_t *batch,
                                  const solver_position_point_t *point,
                                  const lane_displacement_t *a, const lane_displacement_t *b) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    const lane_t most = zero - SOLVER_MAX_POSITION_CORRECTION;
    const lane_vector_t *n = &batch->normal;
    const lane_lever_t *rn = &point->rn;
    lane_t separation = point->separation + (n->x * (b->dx - a->dx) + n->y * (b->dy - a->dy)) +
                        b->dtheta * rn->b - a->dtheta * rn->a;
    lane_t wanted = batch->rate * (separation + batch->slop);
    lane_t capped = min_lane(wanted, zero);
    return max_lane(most, capped);
}

/* Moves the bodies apart by lambda (kg m) at a point. */
LANE_INLINE void push_point(const solver_position_batch_t *batch, const lane_lever_t *rn,
                            lane_t lambda, lane_displacement_t *a, lane_displacement_t *b) {
    const lane_vector_t *n = &batch->normal;
    a->dx -= batch->ma * lambda * n->x;
    a->dy -= batch->ma * lambda * n->y;
    a->dtheta -= batch->ia * lambda * rn->a;
    b->dx += batch->mb * lambda * n->x;
    b->dy += batch->mb * lambda * n->y;
    b->dtheta += batch->ib * lambda * rn->b;
}

/* position_pass.c's block correction, lane by lane. */
LANE_INLINE void correct_block(const solver_position_batch_t *batch,
                               const solver_position_point_t *points, const lane_block_t *k,
                               lane_displacement_t *a, lane_displacement_t *b) {
    const lane_t zero = {0.0, 0.0, 0.0, 0.0};
    const solver_position_point_t *p1 = &points[0], *p2 = &points[1];
    lane_t c1 = position_error(batch, p1, a, b), c2 = position_error(batch, p2, a, b);
    lane_t x1 = zero, x2 = zero;
    solve_block_lanes(k, p1->normal_mass, p2->normal_mass, c1, c2, &x1, &x2);

    const lane_vector_t *n = &batch->normal;
    lane_t total = x1 + x2;
    a->dx -= batch->ma * total * n->x;
    a->dy -= batch->ma * total * n->y;
    a->dtheta -= batch->ia * (x1 * p1->rn.a + x2 * p2->rn.a);
    b->dx += batch->mb * total * n->x;
    b->dy += batch->mb * total * n->y;
    b->dtheta += batch->ib * (x1 * p1->rn.b + x2 * p2->rn.b);
}

/* position_pass.c's solver_solve_position, lane by lane; k: the block
 * batch's matrices (NULL for another kind). */
LANE_INLINE void correct_batch(const solver_position_batch_t *batch,
                               const solver_position_point_t *points, const lane_block_t *k,
                               lane_displacement_t *a, lane_displacement_t *b) {
    if (k != NULL) {
        correct_block(batch, points, k, a, b);
        return;
    }
    for (int i = 0; i < batch->point_count; i++) {
        lane_t lambda = -position_error(batch, &points[i], a, b) * points[i].normal_mass;
        push_point(batch, &points[i].rn, lambda, a, b);
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
                             const solver_position_point_t *points, const lane_block_t *k,
                             solver_displacement_t *displacements, bool shared) {
    if (shared) {
        lane_displacement_t a = gather_displacements_shared(displacements, batch->a, batch->lanes);
        lane_displacement_t b = gather_displacements_shared(displacements, batch->b, batch->lanes);
        correct_batch(batch, points, k, &a, &b);
        scatter_displacements_shared(displacements, batch->a, batch->lanes, batch->fixed_a, &a);
        scatter_displacements_shared(displacements, batch->b, batch->lanes, batch->fixed_b, &b);
        return;
    }
    lane_displacement_t a = gather_displacements(displacements, batch->a);
    lane_displacement_t b = gather_displacements(displacements, batch->b);
    correct_batch(batch, points, k, &a, &b);
    scatter_displacements(displacements, batch->a, batch->lanes, &a);
    scatter_displacements(displacements, batch->b, batch->lanes, &b);
}

LANE_CLONES
void solver_wide_correct_positions(solver_wide_t *wide, solver_displacement_t *displacements,
                                   bool backward) {
    size_t count = wide->batch_count;
    if (!backward) {
        const solver_position_point_t *points = wide->position_points;
        const lane_block_t *blocks = wide->blocks;
        for (size_t i = 0; i < count; i++) {
            const solver_position_batch_t *batch = &wide->position_batches[i];
            bool block = batch->kind == BATCH_BLOCK;
            correct_one(batch, points, block ? blocks++ : NULL, displacements, false);
            points += batch->point_count;
        }
        return;
    }
    const solver_position_point_t *points = wide->position_points + wide->point_count;
    const lane_block_t *blocks = wide->blocks + wide->block_count;
    for (size_t i = count; i-- > 0;) {
        const solver_position_batch_t *batch = &wide->position_batches[i];
        points -= batch->point_count;
        bool block = batch->kind == BATCH_BLOCK;
        correct_one(batch, points, block ? --blocks : NULL, displacements, false);
    }
}

LANE_CLONES
void solver_wide_correct_range(solver_wide_t *wide, solver_displacement_t *displacements,
                               size_t begin, size_t end) {
    if (begin == end) return;
    size_t g = group_of(wide, begin);
    const solver_position_point_t *points = wide->position_points + first_point(wide, g, begin);
    const lane_block_t *blocks = wide->blocks + first_block(wide, g, begin);
    for (size_t i = begin; i < end; i++) {
        const solver_position_batch_t *batch = &wide->position_batches[i];
        bool block = batch->kind == BATCH_BLOCK;
        correct_one(batch, points, block ? blocks++ : NULL, displacements, true);
        points += batch->point_count;
    }
}
