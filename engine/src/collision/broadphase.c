#include "collision/broadphase.h"
#include "collision/broadphase_private.h"
#include <math.h>
#include <string.h>
#include "base/memory.h"
#include "base/scalar.h"
#include "base/workers.h"

broadphase_t *broadphase_init(void) {
    return memory_calloc(1, sizeof(broadphase_t));
}

void broadphase_free(broadphase_t *broadphase) {
    memory_free(broadphase->ranges);
    memory_free(broadphase->sorted);
    memory_free(broadphase->bucket_start);
    memory_free(broadphase->large);
    memory_free(broadphase->pairs);
    memory_free(broadphase->pairs_by_a);
    memory_free(broadphase->pair_start);
    memory_free(broadphase->part_place);
    memory_free(broadphase->stamps);
    for (size_t k = 0; k < WORKERS_MAX_CHUNKS; k++) memory_free(broadphase->chunk_pairs[k]);
    memory_free(broadphase);
}

void broadphase_set_workers(broadphase_t *broadphase, workers_t *workers) {
    broadphase->workers = workers;
}

bool broadphase_filters_allow(const broadphase_proxy_t *a, const broadphase_proxy_t *b) {
    if (a->fixed && b->fixed) return false;
    if ((a->category & b->mask) == 0 || (b->category & a->mask) == 0) return false;
    return a->group == 0 || a->group != b->group;
}

/* Appends the pair (a, b) to pairs[0 .. *count), growing it. */
static inline void append_pair(broadphase_pair_t **pairs, size_t *count, size_t *capacity,
                               uint32_t a, uint32_t b) {
    if (*count == *capacity) {
        memory_reserve((void **)pairs, capacity, *count + 1, sizeof(broadphase_pair_t));
    }
    (*pairs)[(*count)++] = a < b ? (broadphase_pair_t){a, b} : (broadphase_pair_t){b, a};
}

static inline void add_pair(broadphase_t *broadphase, uint32_t a, uint32_t b) {
    append_pair(&broadphase->pairs, &broadphase->pair_count, &broadphase->pair_capacity, a, b);
}

/*
 * The grid's entries sorted by bucket, written in place: the proxies are
 * cut into parts (one per worker, one without workers); a first pass finds
 * each proxy's cells and counts each part's entries (the bucket count hangs
 * on their total), a second each part's entries per bucket, and a third
 * writes each part's entries from its places, its share of each bucket
 * after the earlier parts'. A counting sort is stable, so the entries come
 * out in proxy order within a bucket, for any number of parts, and the
 * large list in proxy order too.
 */
typedef struct {
    broadphase_t *broadphase;
    const broadphase_proxy_t *proxies;
    size_t count, parts, buckets;
    double inverse_size;
} fill_split_t;

/* Parts per worker: few, as the places cost parts x buckets to count
 * (pile(10000) on 2 workers, in alternation: 4 parts each 2% slower). */
static const size_t PARTS_PER_WORKER = 1;

static inline void part_proxies(const fill_split_t *split, size_t part, size_t *first,
                                size_t *last) {
    *first = part * split->count / split->parts;
    *last = (part + 1) * split->count / split->parts;
}

static void count_part(void *context, size_t chunk, size_t begin, size_t end) {
    (void)chunk;
    const fill_split_t *split = context;
    for (size_t part = begin; part < end; part++) {
        size_t first, last, entries = 0, large = 0;
        part_proxies(split, part, &first, &last);
        for (size_t i = first; i < last; i++) {
            cell_range_t r = cell_range(&split->proxies[i].box, split->inverse_size);
            split->broadphase->ranges[i] = r;
            double cells = range_cells(r);
            if (cells > BROADPHASE_MAX_CELLS) {
                large++;
            } else {
                entries += (size_t)cells;
            }
        }
        split->broadphase->part_entries[part] = entries;
        split->broadphase->part_large[part] = large;
    }
}

/* Counts a part's entries per bucket, and writes its large proxies from
 * part_large, by then where they start. */
static void histogram_part(void *context, size_t chunk, size_t begin, size_t end) {
    (void)chunk;
    const fill_split_t *split = context;
    broadphase_t *broadphase = split->broadphase;
    uint32_t mask = (uint32_t)(split->buckets - 1);
    for (size_t part = begin; part < end; part++) {
        uint32_t *counts = broadphase->part_place + part * split->buckets;
        memset(counts, 0, split->buckets * sizeof(uint32_t));
        size_t first, last, large = broadphase->part_large[part];
        part_proxies(split, part, &first, &last);
        for (size_t i = first; i < last; i++) {
            cell_range_t r = broadphase->ranges[i];
            if (range_cells(r) > BROADPHASE_MAX_CELLS) {
                broadphase->large[large++] = (uint32_t)i;
                continue;
            }
            for (int32_t iy = r.y0; iy <= r.y1; iy++) {
                for (int32_t ix = r.x0; ix <= r.x1; ix++) counts[hash_cell(ix, iy, mask)]++;
            }
        }
    }
}

static void place_part(void *context, size_t chunk, size_t begin, size_t end) {
    (void)chunk;
    const fill_split_t *split = context;
    broadphase_t *broadphase = split->broadphase;
    uint32_t mask = (uint32_t)(split->buckets - 1);
    for (size_t part = begin; part < end; part++) {
        uint32_t *place = broadphase->part_place + part * split->buckets;
        size_t first, last;
        part_proxies(split, part, &first, &last);
        for (size_t i = first; i < last; i++) {
            aabb_t box = split->proxies[i].box;
            cell_range_t r = broadphase->ranges[i];
            if (range_cells(r) > BROADPHASE_MAX_CELLS) continue;
            for (int32_t iy = r.y0; iy <= r.y1; iy++) {
                for (int32_t ix = r.x0; ix <= r.x1; ix++) {
                    uint32_t bucket = hash_cell(ix, iy, mask);
                    broadphase->sorted[place[bucket]++] =
                        (cell_entry_t){box, ix, iy, r.x0, r.y0, (uint32_t)i, bucket};
                }
            }
        }
    }
}

/* Totals the parts' counts; part_large becomes where each part's large
 * proxies start. Returns the number of entries. */
static size_t total_parts(broadphase_t *broadphase, size_t parts, size_t *large_count) {
    size_t n = 0;
    *large_count = 0;
    for (size_t k = 0; k < parts; k++) {
        n += broadphase->part_entries[k];
        size_t large = broadphase->part_large[k];
        broadphase->part_large[k] = *large_count;
        *large_count += large;
    }
    return n;
}

/* Turns the parts' counts into places, ordered by (bucket, part), and
 * sets where each bucket starts. */
static void places_from_counts(broadphase_t *broadphase, size_t parts, size_t buckets) {
    uint32_t running = 0;
    for (size_t b = 0; b < buckets; b++) {
        broadphase->bucket_start[b] = running;
        for (size_t k = 0; k < parts; k++) {
            uint32_t *place = &broadphase->part_place[k * buckets + b];
            uint32_t here = *place;
            *place = running;
            running += here;
        }
    }
    broadphase->bucket_start[buckets] = running;
}

/* Fills the grid (sorted, bucket_start, large) on the workers given
 * (NULL: this thread); returns the bucket count, and the numbers of
 * entries and of large proxies (covering more than BROADPHASE_MAX_CELLS
 * cells, paired with everything instead). */
static size_t fill_grid(broadphase_t *broadphase, workers_t *workers,
                        const broadphase_proxy_t *proxies, size_t count, double inverse_size,
                        size_t *n, size_t *large_count) {
    memory_reserve((void **)&broadphase->ranges, &broadphase->range_capacity, count,
                   sizeof(cell_range_t));
    size_t parts = workers != NULL ? workers_count(workers) * PARTS_PER_WORKER : 1;
    if (parts > WORKERS_MAX_CHUNKS) parts = WORKERS_MAX_CHUNKS;
    fill_split_t split = {broadphase, proxies, count, parts, 0, inverse_size};
    workers_each(workers, parts, count_part, &split);
    *n = total_parts(broadphase, parts, large_count);
    split.buckets = bucket_count(*n);
    memory_reserve((void **)&broadphase->large, &broadphase->large_capacity, *large_count,
                   sizeof(uint32_t));
    memory_reserve((void **)&broadphase->bucket_start, &broadphase->bucket_capacity,
                   split.buckets + 1, sizeof(uint32_t));
    memory_reserve((void **)&broadphase->sorted, &broadphase->sorted_capacity, *n,
                   sizeof(cell_entry_t));
    memory_reserve((void **)&broadphase->part_place, &broadphase->part_place_capacity,
                   parts * split.buckets, sizeof(uint32_t));
    workers_each(workers, parts, histogram_part, &split);
    places_from_counts(broadphase, parts, split.buckets);
    workers_each(workers, parts, place_part, &split);
    return split.buckets;
}

#if defined(__SSE2__)
#include <emmintrin.h>
/* A box as two pairs of doubles, x and y side by side. */
typedef struct {
    __m128d min, max;
} box_lanes_t;
static inline box_lanes_t box_lanes(const aabb_t *box) {
    return (box_lanes_t){_mm_loadu_pd(&box->min.x), _mm_loadu_pd(&box->max.x)};
}
/* aabb_overlaps, its four comparisons two at a time and one answer. */
static inline bool boxes_overlap(box_lanes_t a, const aabb_t *b) {
    box_lanes_t c = box_lanes(b);
    __m128d both = _mm_and_pd(_mm_cmple_pd(a.min, c.max), _mm_cmple_pd(c.min, a.max));
    return _mm_movemask_pd(both) == 3;
}
#else
typedef aabb_t box_lanes_t;
static inline box_lanes_t box_lanes(const aabb_t *box) {
    return *box;
}
static inline bool boxes_overlap(box_lanes_t a, const aabb_t *b) {
    return aabb_overlaps(a, *b);
}
#endif

/*
 * Pairs that share a cell; a pair sharing several cells is reported only in
 * the cell holding the lower-left corner of the boxes' intersection.
 *
 * Whether the next entry of a bucket is in the same cell, and whether its
 * box overlaps, is random: the two are tested with a branch each, the box
 * test's four comparisons two at a time with no short cut (a branch per
 * comparison mispredicted: 19.0 million of pile(1000)'s branches against
 * 16.7 million now, cachegrind's model; one branch for both tests, 15.7
 * million, cost 0.8% more instructions), and what the tests read of the
 * first entry is read once. Inlined into the one-thread search and the
 * workers' chunks alike (called, pile(1000) ran 0.3% more instructions).
 */
static inline __attribute__((always_inline)) size_t pairs_in_bucket_range(
    const broadphase_t *broadphase, const broadphase_proxy_t *proxies, size_t first, size_t last,
    broadphase_pair_t **pairs, size_t *count, size_t *capacity) {
    const cell_entry_t *sorted = broadphase->sorted;
    size_t tests = 0;
    for (size_t b = first; b < last; b++) {
        uint32_t begin = broadphase->bucket_start[b], end = broadphase->bucket_start[b + 1];
        for (uint32_t p = begin; p + 1 < end; p++) {
            const cell_entry_t *a = &sorted[p];
            tests += end - p - 1;
            uint64_t cell = cell_key(a);
            box_lanes_t box = box_lanes(&a->box);
            for (uint32_t q = p + 1; q < end; q++) {
                const cell_entry_t *c = &sorted[q];
                if (cell_key(c) != cell || !boxes_overlap(box, &c->box)) continue;
                /* cell_index is monotonic: the corner's cell is the larger
                 * of the two boxes' lower-left cells. */
                int32_t corner_x = a->min_x > c->min_x ? a->min_x : c->min_x;
                int32_t corner_y = a->min_y > c->min_y ? a->min_y : c->min_y;
                if (corner_x != a->ix || corner_y != a->iy) continue;
                if (!broadphase_filters_allow(&proxies[a->proxy], &proxies[c->proxy])) continue;
                append_pair(pairs, count, capacity, a->proxy, c->proxy);
            }
        }
    }
    return tests;
}

static void pairs_in_buckets(broadphase_t *broadphase, const broadphase_proxy_t *proxies,
                             size_t buckets) {
    broadphase->tests += pairs_in_bucket_range(broadphase, proxies, 0, buckets, &broadphase->pairs,
                                               &broadphase->pair_count,
                                               &broadphase->pair_capacity);
}

/* pairs_in_buckets over the workers: each chunk of buckets finds its pairs
 * into its own list, and the lists are joined in chunk order, so the pairs
 * come out in the order one thread finds them. */
typedef struct {
    broadphase_t *broadphase;
    const broadphase_proxy_t *proxies;
} bucket_split_t;

static void bucket_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const bucket_split_t *split = context;
    broadphase_t *broadphase = split->broadphase;
    broadphase->chunk_count[chunk] = 0;
    broadphase->chunk_tests[chunk] = pairs_in_bucket_range(
        broadphase, split->proxies, begin, end, &broadphase->chunk_pairs[chunk],
        &broadphase->chunk_count[chunk], &broadphase->chunk_capacity[chunk]);
}

static void pairs_in_buckets_split(broadphase_t *broadphase, const broadphase_proxy_t *proxies,
                                   size_t buckets) {
    bucket_split_t split = {broadphase, proxies};
    size_t chunks = workers_chunks(broadphase->workers, buckets);
    /* A chunk finds at most all the pairs: each list holds as many as the
     * most any step has had, so a warm step allocates nothing. */
    for (size_t k = 0; k < chunks; k++) {
        memory_reserve((void **)&broadphase->chunk_pairs[k], &broadphase->chunk_capacity[k],
                       broadphase->pair_capacity, sizeof(broadphase_pair_t));
    }
    workers_for(broadphase->workers, buckets, bucket_chunk, &split);
    for (size_t k = 0; k < chunks; k++) {
        size_t n = broadphase->chunk_count[k];
        memory_reserve((void **)&broadphase->pairs, &broadphase->pair_capacity,
                       broadphase->pair_count + n, sizeof(broadphase_pair_t));
        if (n > 0) {
            memcpy(broadphase->pairs + broadphase->pair_count, broadphase->chunk_pairs[k],
                   n * sizeof(broadphase_pair_t));
        }
        broadphase->pair_count += n;
        broadphase->tests += broadphase->chunk_tests[k];
    }
}

/* Large proxies against everything; a pair of two large ones once. */
static void pairs_with_large(broadphase_t *broadphase, const broadphase_proxy_t *proxies,
                             size_t count, size_t large_count) {
    for (size_t l = 0; l < large_count; l++) {
        uint32_t big = broadphase->large[l];
        for (size_t i = 0; i < count; i++) {
            if (i == big) continue;
            bool other_large_seen = false;
            for (size_t m = 0; m < l; m++) other_large_seen |= broadphase->large[m] == i;
            if (other_large_seen) continue;
            broadphase->tests++;
            if (!aabb_overlaps(proxies[big].box, proxies[i].box)) continue;
            if (!broadphase_filters_allow(&proxies[big], &proxies[i])) continue;
            add_pair(broadphase, big, (uint32_t)i);
        }
    }
}

/* Counting sort of the pairs by their first proxy. */
static const broadphase_pair_t *sort_pairs(broadphase_t *broadphase, size_t count) {
    size_t n = broadphase->pair_count;
    memory_reserve((void **)&broadphase->pairs_by_a, &broadphase->pairs_by_a_capacity, n,
                   sizeof(broadphase_pair_t));
    memory_reserve((void **)&broadphase->pair_start, &broadphase->pair_start_capacity, count + 1,
                   sizeof(uint32_t));
    uint32_t *start = broadphase->pair_start;
    memset(start, 0, (count + 1) * sizeof(uint32_t));
    for (size_t i = 0; i < n; i++) start[broadphase->pairs[i].a + 1]++;
    for (size_t i = 0; i < count; i++) start[i + 1] += start[i];
    for (size_t i = 0; i < n; i++) {
        broadphase->pairs_by_a[start[broadphase->pairs[i].a]++] = broadphase->pairs[i];
    }
    return broadphase->pairs_by_a;
}

/* The pair buffers start at this many pairs per proxy: a scene's pair
 * count wanders from step to step (a gas), and one a little above a
 * doubled capacity late in a run is an allocation in a warm step. */
static const size_t PAIRS_PER_PROXY = 2;

size_t broadphase_find_pairs(broadphase_t *broadphase, const broadphase_proxy_t *proxies,
                             size_t count, const broadphase_pair_t **pairs, size_t *tests) {
    memory_reserve((void **)&broadphase->pairs, &broadphase->pair_capacity,
                   PAIRS_PER_PROXY * count, sizeof(broadphase_pair_t));
    memory_reserve((void **)&broadphase->pairs_by_a, &broadphase->pairs_by_a_capacity,
                   PAIRS_PER_PROXY * count, sizeof(broadphase_pair_t));
    broadphase->pair_count = 0;
    broadphase->tests = 0;
    double inverse_size = 1.0 / choose_cell_size(proxies, count);
    size_t large_count, n, buckets;
    buckets = fill_grid(broadphase, broadphase->workers, proxies, count, inverse_size, &n,
                        &large_count);
    if (broadphase->workers != NULL) {
        pairs_in_buckets_split(broadphase, proxies, buckets);
    } else {
        pairs_in_buckets(broadphase, proxies, buckets);
    }
    if (large_count > 0) pairs_with_large(broadphase, proxies, count, large_count);
    *pairs = sort_pairs(broadphase, count);
    /* The grid stays for box queries; bounds all round, as finding them
     * is a pass the search does not need. */
    broadphase->inverse_size = inverse_size;
    broadphase->bucket_count = buckets;
    broadphase->large_count = large_count;
    broadphase->proxy_count = count;
    broadphase->proxies = proxies;
    broadphase->bounds = (aabb_t){{-INFINITY, -INFINITY}, {INFINITY, INFINITY}};
    *tests += broadphase->tests + n;
    return broadphase->pair_count;
}

void broadphase_build(broadphase_t *broadphase, const broadphase_proxy_t *proxies, size_t count) {
    broadphase->inverse_size = 1.0 / choose_cell_size(proxies, count);
    size_t n;
    broadphase->bucket_count = fill_grid(broadphase, NULL, proxies, count,
                                         broadphase->inverse_size, &n, &broadphase->large_count);
    broadphase->proxy_count = count;
    broadphase->proxies = proxies;
    aabb_t bounds = {{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
    for (size_t i = 0; i < count; i++) bounds = aabb_union(bounds, proxies[i].box);
    broadphase->bounds = bounds;
    memory_reserve((void **)&broadphase->stamps, &broadphase->stamp_capacity, count,
                   sizeof(uint32_t));
    if (count > 0) memset(broadphase->stamps, 0, count * sizeof(uint32_t));
    broadphase->query_number = 0;
}
