#ifndef SOLVER_WIDE_PRIVATE_H
#define SOLVER_WIDE_PRIVATE_H

/*
 * The colour batches' layout (solver_wide.h), shared by their arranging
 * (solver_wide_arrange.c), preparing (solver_wide_prepare.c) and sweeps
 * (solver_wide.c): up to four contacts of one colour and kind lane by
 * lane, their points and block matrices in arrays of their own, and where
 * each group's batches, points and blocks begin; and the lane vectors they
 * build on (rows of four doubles loaded as one vector and transposed into
 * columns).
 */

#include <stddef.h>
#include <stdint.h>
#include <string.h>
#include "solver/solver_wide.h"

enum { LANES = 4 };

/* The kernels of the sweeps and of preparing must be inlined into each
 * clone of the exported functions to be compiled for its instruction set;
 * GCC otherwise keeps the larger ones out of line, as baseline code. */
#define LANE_INLINE static inline __attribute__((always_inline))

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

/* Four doubles, and four 64-bit lane masks (all ones where a comparison
 * held). aligned(8): the batches come from malloc, which promises less
 * than the 32 bytes a vector would otherwise demand. */
typedef double lane_t __attribute__((vector_size(LANES * sizeof(double)), aligned(8)));
typedef int64_t mask_t __attribute__((vector_size(LANES * sizeof(int64_t)), aligned(8)));

/* Vectors are returned from static functions only (always inlined), so
 * GCC's warning that AVX changes how they are returned between objects does
 * not apply. */
#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

/* Lanes picked from two vectors: indices 0 to 3 name a's lanes, 4 to 7
 * b's (GCC and Clang spell the builtin differently). */
#if defined(__clang__)
#define shuffle_lanes(a, b, i, j, k, l) __builtin_shufflevector((a), (b), i, j, k, l)
#else
#define shuffle_lanes(a, b, i, j, k, l) __builtin_shuffle((a), (b), (mask_t){i, j, k, l})
#endif

/* yes where condition holds, no elsewhere; and scalar.h's max_of and
 * min_of, lane by lane. Macros, not functions: a vector passed by value
 * goes through memory on the baseline instruction set. Arguments must be
 * free of side effects. */
#define select_lane(condition, yes, no) \
    ((lane_t)(((mask_t)(yes) & (condition)) | ((mask_t)(no) & ~(condition))))
#define max_lane(a, b) select_lane((mask_t)((a) > (b)), (a), (b))
#define min_lane(a, b) select_lane((mask_t)((a) < (b)), (a), (b))

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

/* Double k of a group of four adjacent doubles of each of four records
 * (at r0 .. r3) into lane l of column k: each group one vector load. */
LANE_INLINE lane_quad_t gather_records(const void *r0, const void *r1, const void *r2,
                                       const void *r3) {
    return transpose((lane_quad_t){load_lane(r0), load_lane(r1), load_lane(r2), load_lane(r3)});
}

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
    uint8_t lanes, point_count, kind;
    uint8_t fixed_a, fixed_b; /* as in solver_batch */
};

struct solver_position_point {
    lane_lever_t rn;
    lane_t normal_mass, separation;
};

static inline int kind_points(batch_kind_t kind) {
    return kind == BATCH_SINGLE ? 1 : 2;
}

/* Where batch `batch` (in group g) finds its first point and its block. */
static inline size_t first_point(const solver_wide_t *wide, size_t g, size_t batch) {
    return wide->group_point[g] + (batch - wide->group_batch[g]) * kind_points(g % BATCH_KINDS);
}

static inline size_t first_block(const solver_wide_t *wide, size_t g, size_t batch) {
    return wide->group_block[g] +
           (g % BATCH_KINDS == BATCH_BLOCK ? batch - wide->group_batch[g] : 0);
}

/* The group that holds batch `batch`. */
static inline size_t group_of(const solver_wide_t *wide, size_t batch) {
    size_t g = 0;
    while (wide->group_batch[g + 1] <= batch) g++;
    return g;
}

#endif // #ifndef SOLVER_WIDE_PRIVATE_H
