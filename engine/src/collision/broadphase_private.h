#ifndef BROADPHASE_PRIVATE_H
#define BROADPHASE_PRIVATE_H

/* The broadphase's grid, shared by the pair search (broadphase.c) and the
 * queries on it (broadphase_query.c). */

#include <stdint.h>
#include <string.h>
#include "collision/broadphase.h"
#include "base/scalar.h"
#include "base/workers.h"

/* A proxy in one cell, with its box and the cell of its box's lower-left
 * corner: the pair search then reads the entries of a cell straight
 * through instead of looking each box up. */
typedef struct {
    aabb_t box;
    int32_t ix, iy;     /* this cell (adjacent: cell_key reads them as one) */
    int32_t min_x, min_y; /* the cell of box.min */
    uint32_t proxy;
    uint32_t bucket;    /* hash of (ix, iy); in what was padding */
} cell_entry_t;

/* The cells a box covers, corners included. */
typedef struct {
    int32_t x0, y0, x1, y1;
} cell_range_t;

struct broadphase {
    cell_entry_t *sorted;   /* the entries, by bucket */
    size_t sorted_capacity;
    cell_range_t *ranges;   /* each proxy's cells, found once a search */
    size_t range_capacity;
    uint32_t *bucket_start; /* size bucket_count + 1 */
    size_t bucket_capacity;
    uint32_t *large;
    size_t large_capacity;
    broadphase_pair_t *pairs, *pairs_by_a;
    size_t pair_count, pair_capacity, pairs_by_a_capacity;
    uint32_t *pair_start; /* size proxy count + 1 */
    size_t pair_start_capacity;
    size_t tests;
    /* With workers: each chunk of buckets' pairs and tests, joined in chunk
     * order (pairs_in_buckets_split). */
    workers_t *workers;
    broadphase_pair_t *chunk_pairs[WORKERS_MAX_CHUNKS];
    size_t chunk_count[WORKERS_MAX_CHUNKS], chunk_capacity[WORKERS_MAX_CHUNKS];
    size_t chunk_tests[WORKERS_MAX_CHUNKS];
    /* The grid is filled by parts of the proxies (fill_grid), one per worker:
     * each part's entry and large counts, where its large proxies go, and
     * parts x buckets counts that become each part's next place per bucket. */
    size_t part_entries[WORKERS_MAX_CHUNKS], part_large[WORKERS_MAX_CHUNKS];
    uint32_t *part_place;
    size_t part_place_capacity;
    /* The grid of the last broadphase_build, for queries: its cell size,
     * buckets, large proxies and proxies, the box around them all, and a
     * stamp per proxy so a ray visits each once (the query's number). */
    double inverse_size;
    size_t bucket_count, large_count, proxy_count;
    const broadphase_proxy_t *proxies;
    aabb_t bounds;
    uint32_t *stamps;
    size_t stamp_capacity;
    uint32_t query_number;
};

static inline uint32_t hash_cell(int32_t ix, int32_t iy, uint32_t mask) {
    uint32_t h = (uint32_t)ix * 73856093u ^ (uint32_t)iy * 19349663u;
    return (h ^ (h >> 15)) & mask;
}

/* floor(coordinate / size), by truncation: floor() is a library call on
 * baseline x86-64, and this runs for every box corner every step. */
static inline int32_t cell_index(double coordinate, double inverse_size) {
    double cell = coordinate * inverse_size;
    /* Keep far-away bodies (and a NaN, which compares false) from
     * overflowing the cell coordinates. */
    if (cell > 1e9) cell = 1e9;
    if (!(cell >= -1e9)) cell = -1e9;
    int32_t truncated = (int32_t)cell;
    return truncated - (cell < (double)truncated);
}

static inline cell_range_t cell_range(const aabb_t *box, double inverse_size) {
    return (cell_range_t){cell_index(box->min.x, inverse_size), cell_index(box->min.y, inverse_size),
                          cell_index(box->max.x, inverse_size), cell_index(box->max.y, inverse_size)};
}

/* In double: a huge box's count overflows any integer. */
static inline double range_cells(cell_range_t r) {
    return ((double)r.x1 - r.x0 + 1.0) * ((double)r.y1 - r.y0 + 1.0);
}

/* An entry's cell (ix, iy) as one number. */
static inline uint64_t cell_key(const cell_entry_t *entry) {
    uint64_t key;
    memcpy(&key, &entry->ix, sizeof key);
    return key;
}

/* A cell about twice the mean extent of the movable bodies: each such body
 * then covers at most four cells and a cell holds a few bodies. */
static inline double choose_cell_size(const broadphase_proxy_t *proxies, size_t count) {
    double sum = 0.0;
    size_t movable = 0;
    for (size_t i = 0; i < count; i++) {
        if (proxies[i].fixed) continue;
        aabb_t box = proxies[i].box;
        sum += max_of(box.max.x - box.min.x, box.max.y - box.min.y);
        movable++;
    }
    double size = movable > 0 ? 2.0 * sum / (double)movable : 1.0;
    /* An infinite size (a box swept by a dt v that overflows, or extents
     * summing past the largest double) would make every cell index NaN. */
    return size > 1e-6 ? min_of(size, 1e300) : 1e-6;
}

/* Enough buckets that cells, which hold several entries, rarely share one. */
static inline size_t bucket_count(size_t n) {
    size_t buckets = 64;
    while (2 * buckets < n) buckets *= 2;
    return buckets;
}

#endif // #ifndef BROADPHASE_PRIVATE_H
