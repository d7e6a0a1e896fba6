#include "collision/pair_tracker.h"
#include <string.h>
#include "base/memory.h"
#include "base/scalar.h"
#include "collision/broadphase_private.h"

/* How far a box is grown all round for the search: a tenth of its extent,
 * at most 10 cm (Box2D v3's margin), so that a body resting or creeping
 * stays inside for many steps while its grown box takes in few bodies it
 * does not touch. */
static const double GROW_SHARE = 0.1;
static const double GROW_MAX = 0.1;
/* A search of grown boxes pays only when the next steps keep its pairs.
 * After one whose pairs were not kept even once (a gas, a falling pile:
 * some box leaves its grown box at every step), the boxes themselves are
 * searched for the next `backoff` searches, twice as many after each such
 * failure up to BACKOFF_MAX; grown boxes would only add candidates, and
 * larger pair buffers long after a scene has warmed up (the stability
 * suite's gas of 200 bodies). */
static const unsigned BACKOFF_MAX = 1024;

struct pair_tracker {
    broadphase_t *broadphase;
    /* The proxies of the last search and their count, and whether it
     * searched them grown (else as they were). */
    broadphase_proxy_t *grown;
    size_t grown_capacity, count;
    bool searched_grown;
    /* Calls that kept the last search's pairs, searches of the boxes as
     * they are before grown ones are tried again, and how many the next
     * grown search kept by no call will wait. */
    unsigned since_search, tight_left, backoff;
    /* The pairs the last search found, grouped by a: the grid's own
     * buffer, which stays until this tracker searches it again. */
    const broadphase_pair_t *kept;
    size_t kept_count;
    /* The pairs handed out, and their ranks (pair_rank). */
    broadphase_pair_t *pairs;
    uint64_t *ranks;
    size_t pair_capacity, rank_capacity;
    cell_range_t *ranges;
    size_t range_capacity;
    /* What the last kept call ranked from, so that its pairs are handed
     * out again while nothing a rank reads has changed (a resting scene):
     * each proxy's cells, the bucket mask, and which kept pairs overlapped,
     * a bit each. ranked: pairs holds that call's pair_count pairs. */
    cell_range_t *last_ranges;
    size_t last_range_capacity;
    uint64_t *overlaps, *last_overlaps;
    size_t overlap_capacity, last_overlap_capacity;
    uint32_t last_mask;
    size_t last_count, pair_count;
    bool ranked;
};

pair_tracker_t *pair_tracker_init(void) {
    pair_tracker_t *tracker = memory_calloc(1, sizeof(pair_tracker_t));
    tracker->broadphase = broadphase_init();
    tracker->backoff = 1;
    return tracker;
}

void pair_tracker_free(pair_tracker_t *tracker) {
    broadphase_free(tracker->broadphase);
    memory_free(tracker->grown);
    memory_free(tracker->pairs);
    memory_free(tracker->ranks);
    memory_free(tracker->ranges);
    memory_free(tracker->last_ranges);
    memory_free(tracker->overlaps);
    memory_free(tracker->last_overlaps);
    memory_free(tracker);
}

void pair_tracker_set_workers(pair_tracker_t *tracker, workers_t *workers) {
    broadphase_set_workers(tracker->broadphase, workers);
}

static bool same_filters(const broadphase_proxy_t *a, const broadphase_proxy_t *b) {
    return a->fixed == b->fixed && a->category == b->category && a->mask == b->mask &&
           a->group == b->group;
}

/* Whether inner lies inside outer (false for a NaN in either). */
static bool box_inside(aabb_t inner, aabb_t outer) {
    return inner.min.x >= outer.min.x && inner.min.y >= outer.min.y &&
           inner.max.x <= outer.max.x && inner.max.y <= outer.max.y;
}

/* Whether the pairs of the last search, of grown boxes, still hold every
 * pair of these proxies. */
static bool still_inside(const pair_tracker_t *tracker, const broadphase_proxy_t *proxies,
                         size_t count) {
    if (count != tracker->count) return false;
    for (size_t i = 0; i < count; i++) {
        if (!box_inside(proxies[i].box, tracker->grown[i].box) ||
            !same_filters(&proxies[i], &tracker->grown[i])) {
            return false;
        }
    }
    return true;
}

/* Whether the search about to run grows the boxes (BACKOFF_MAX). */
static bool grow_next(pair_tracker_t *tracker) {
    if (tracker->searched_grown) {
        if (tracker->since_search > 0) {
            tracker->backoff = 1;
        } else {
            tracker->tight_left = tracker->backoff;
            tracker->backoff = tracker->backoff < BACKOFF_MAX ? 2 * tracker->backoff : BACKOFF_MAX;
        }
    }
    if (tracker->tight_left == 0) return true;
    tracker->tight_left--;
    return false;
}

static aabb_t grown_box(aabb_t box) {
    double extent = max_of(box.max.x - box.min.x, box.max.y - box.min.y);
    double grow = min_of(GROW_MAX, GROW_SHARE * extent);
    return (aabb_t){{box.min.x - grow, box.min.y - grow}, {box.max.x + grow, box.max.y + grow}};
}

/* Searches the grid, with every box grown when `grow`, and keeps the
 * pairs. */
static void search(pair_tracker_t *tracker, const broadphase_proxy_t *proxies, size_t count,
                   bool grow, size_t *tests) {
    if (grow) {
        memory_reserve((void **)&tracker->grown, &tracker->grown_capacity, count,
                       sizeof(broadphase_proxy_t));
        for (size_t i = 0; i < count; i++) {
            tracker->grown[i] = proxies[i];
            tracker->grown[i].box = grown_box(proxies[i].box);
        }
    }
    tracker->kept_count = broadphase_find_pairs(tracker->broadphase,
                                                grow ? tracker->grown : proxies, count,
                                                &tracker->kept, tests);
    tracker->count = count;
    tracker->searched_grown = grow;
    tracker->since_search = 0;
    tracker->ranked = false;
}

/* Where the grid would find each pair if it searched the boxes
 * themselves this step: its cells (ranges, each proxy's), their size, and
 * the bucket mask. */
typedef struct {
    const cell_range_t *ranges;
    uint32_t mask;
} grid_place_t;

static grid_place_t grid_place(pair_tracker_t *tracker, const broadphase_proxy_t *proxies,
                               size_t count) {
    memory_reserve((void **)&tracker->ranges, &tracker->range_capacity, count,
                   sizeof(cell_range_t));
    double inverse_size = 1.0 / choose_cell_size(proxies, count);
    size_t entries = 0;
    for (size_t i = 0; i < count; i++) {
        cell_range_t r = cell_range(&proxies[i].box, inverse_size);
        tracker->ranges[i] = r;
        double cells = range_cells(r);
        if (cells <= BROADPHASE_MAX_CELLS) entries += (size_t)cells;
    }
    return (grid_place_t){tracker->ranges, (uint32_t)(bucket_count(entries) - 1)};
}

/*
 * A pair's rank among its first body's pairs, then the other body's index:
 * the order in which a search of the boxes themselves at this step would
 * find them (broadphase.c): by the bucket of the cell holding the lower-left
 * corner of where the boxes overlap, then by that cell's place among the
 * first body's cells; pairs with a body too large for the grid after all
 * others. So the pairs come out as the grid alone would give them, bit
 * for bit, whenever the search last ran. The order matters: it steers the
 * greedy colouring and with it Gauss-Seidel's bias, and ranked otherwise
 * (by the other body's index, or by hashes of the pair or of its place)
 * pyramids drifted the same way at every layout seed, pyramid(40)'s top
 * box 35 to 150 mm (docs/design.md, Broadphase).
 */
static uint64_t pair_rank(grid_place_t place, broadphase_pair_t pair) {
    cell_range_t a = place.ranges[pair.a], b = place.ranges[pair.b];
    if (range_cells(a) > BROADPHASE_MAX_CELLS || range_cells(b) > BROADPHASE_MAX_CELLS) {
        return UINT64_MAX;
    }
    int32_t x = a.x0 > b.x0 ? a.x0 : b.x0, y = a.y0 > b.y0 ? a.y0 : b.y0;
    uint64_t within = (uint64_t)(y - a.y0) * (uint64_t)(a.x1 - a.x0 + 1) + (uint64_t)(x - a.x0);
    return (uint64_t)hash_cell(x, y, place.mask) << 32 | within;
}

/* Appends the pair at its place among the pairs of its first body that
 * came before it (pairs[group .. n)), by insertion: a body has a few. */
static size_t insert_ranked(pair_tracker_t *tracker, size_t group, size_t n,
                            broadphase_pair_t pair, uint64_t rank) {
    size_t j = n;
    for (; j > group && (tracker->ranks[j - 1] > rank ||
                         (tracker->ranks[j - 1] == rank && tracker->pairs[j - 1].b > pair.b));
         j--) {
        tracker->pairs[j] = tracker->pairs[j - 1];
        tracker->ranks[j] = tracker->ranks[j - 1];
    }
    tracker->pairs[j] = pair;
    tracker->ranks[j] = rank;
    return n + 1;
}

/* Room for a bit per kept pair in tracker->overlaps, all clear. */
static void clear_overlaps(pair_tracker_t *tracker) {
    size_t words = (tracker->kept_count + 63) / 64;
    if (words == 0) return; /* memset of a null buffer is undefined even for 0 bytes */
    memory_reserve((void **)&tracker->overlaps, &tracker->overlap_capacity, words,
                   sizeof(uint64_t));
    memset(tracker->overlaps, 0, words * sizeof(uint64_t));
}

static bool kept_overlaps(const pair_tracker_t *tracker, const broadphase_proxy_t *proxies,
                          size_t i) {
    broadphase_pair_t pair = tracker->kept[i];
    return aabb_overlaps(proxies[pair.a].box, proxies[pair.b].box);
}

/* Whether every proxy's cells and the bucket mask, all a rank reads, are
 * those of the last call. */
static bool same_cells(const pair_tracker_t *tracker, grid_place_t place, size_t count) {
    return tracker->ranked && tracker->last_count == count && tracker->last_mask == place.mask &&
           (count == 0 ||
            memcmp(place.ranges, tracker->last_ranges, count * sizeof(cell_range_t)) == 0);
}

/* Whether the same kept pairs overlap as at the last call, marking which
 * do in tracker->overlaps. */
static bool same_overlaps(pair_tracker_t *tracker, const broadphase_proxy_t *proxies) {
    clear_overlaps(tracker);
    for (size_t i = 0; i < tracker->kept_count; i++) {
        tracker->overlaps[i / 64] |= (uint64_t)kept_overlaps(tracker, proxies, i) << (i % 64);
    }
    size_t words = (tracker->kept_count + 63) / 64;
    return words == 0 ||
           memcmp(tracker->overlaps, tracker->last_overlaps, words * sizeof(uint64_t)) == 0;
}

/* The overlapping kept pairs, each at its rank among its first body's;
 * `marked`: tracker->overlaps already says which overlap, else they are
 * found and marked here. */
static void rank_kept(pair_tracker_t *tracker, grid_place_t place,
                      const broadphase_proxy_t *proxies, bool marked) {
    memory_reserve((void **)&tracker->pairs, &tracker->pair_capacity, tracker->kept_count,
                   sizeof(broadphase_pair_t));
    memory_reserve((void **)&tracker->ranks, &tracker->rank_capacity, tracker->kept_count,
                   sizeof(uint64_t));
    if (!marked) clear_overlaps(tracker);
    size_t n = 0, group = 0;
    for (size_t i = 0; i < tracker->kept_count; i++) {
        if (marked) {
            if (!(tracker->overlaps[i / 64] >> (i % 64) & 1u)) continue;
        } else {
            if (!kept_overlaps(tracker, proxies, i)) continue;
            tracker->overlaps[i / 64] |= (uint64_t)1 << (i % 64);
        }
        broadphase_pair_t pair = tracker->kept[i];
        if (n > 0 && tracker->pairs[n - 1].a != pair.a) group = n;
        n = insert_ranked(tracker, group, n, pair, pair_rank(place, pair));
    }
    tracker->pair_count = n;
}

/* Keeps what this call ranked from for the next (same_cells, same_overlaps). */
static void remember(pair_tracker_t *tracker, grid_place_t place, size_t count) {
    memory_swap((void **)&tracker->ranges, &tracker->range_capacity,
                (void **)&tracker->last_ranges, &tracker->last_range_capacity);
    memory_swap((void **)&tracker->overlaps, &tracker->overlap_capacity,
                (void **)&tracker->last_overlaps, &tracker->last_overlap_capacity);
    tracker->last_mask = place.mask;
    tracker->last_count = count;
    tracker->ranked = true;
}

size_t pair_tracker_find(pair_tracker_t *tracker, const broadphase_proxy_t *proxies, size_t count,
                         const broadphase_pair_t **pairs, size_t *tests) {
    if (!tracker->searched_grown || !still_inside(tracker, proxies, count)) {
        bool grow = grow_next(tracker);
        search(tracker, proxies, count, grow, tests);
        if (!grow) { /* the grid's pairs of these very boxes, in its order */
            *pairs = tracker->kept;
            return tracker->kept_count;
        }
    } else {
        tracker->since_search++;
    }
    grid_place_t place = grid_place(tracker, proxies, count);
    if (!same_cells(tracker, place, count)) {
        rank_kept(tracker, place, proxies, false);
    } else if (!same_overlaps(tracker, proxies)) {
        rank_kept(tracker, place, proxies, true);
    }
    remember(tracker, place, count);
    *tests += tracker->kept_count;
    *pairs = tracker->pairs;
    return tracker->pair_count;
}
