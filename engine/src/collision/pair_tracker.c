#include "collision/pair_tracker.h"
#include <stdlib.h>
#include <string.h>
#include "base/memory.h"
#include "base/scalar.h"
#include "base/workers.h"
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
/* Boxes that left their grown boxes since the last search (the stale ones)
 * are grown again and their pairs found by queries (regrow) while they
 * are at most this many, or a share of the proxies; beyond, the grid is
 * searched anew. Each query also compares its box with every stale box,
 * whose entries in the grid are out of date. */
static const size_t STALE_MIN = 8;
static const size_t STALE_SHARE = 16;
/* The pairs a box grown again is given room for when a grown search
 * reserves what the calls after it write (reserve_after_search). */
static const size_t FOUND_PER_BOX = 16;

struct pair_tracker {
    broadphase_t *broadphase;
    workers_t *workers;
    /* The proxies of the last search and their count, and whether it
     * searched them grown (else as they were). */
    broadphase_proxy_t *grown;
    size_t grown_capacity, count;
    bool searched_grown;
    /* Calls that kept the last search's pairs, searches of the boxes as
     * they are before grown ones are tried again, and how many the next
     * grown search kept by no call will wait. */
    unsigned since_search, tight_left, backoff;
    /* The pairs of grown boxes, grouped by a: the grid's own buffer after
     * a search, which stays until this tracker searches it again, or one of
     * `candidates` after regrow. */
    const broadphase_pair_t *kept;
    size_t kept_count;
    broadphase_pair_t *candidates[2];
    size_t candidate_capacity[2];
    unsigned candidate_side;
    /* The proxies grown again since the last search, whose grid entries
     * are out of date: a flag each (STALE, or GROWN_NOW during a regrow)
     * and their list; the proxies that left their grown boxes at this call;
     * the pairs a regrow found. */
    uint8_t *stale;
    uint32_t *stale_list, *escaped;
    size_t stale_capacity, stale_list_capacity, escaped_capacity, stale_count, escaped_count;
    broadphase_pair_t *found;
    size_t found_capacity, found_count;
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
    memory_free(tracker->candidates[0]);
    memory_free(tracker->candidates[1]);
    memory_free(tracker->stale);
    memory_free(tracker->stale_list);
    memory_free(tracker->escaped);
    memory_free(tracker->found);
    memory_free(tracker);
}

void pair_tracker_set_workers(pair_tracker_t *tracker, workers_t *workers) {
    tracker->workers = workers;
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

/* The most stale proxies a regrow may leave before a search pays. */
static size_t stale_limit(size_t count) {
    return max_of(STALE_MIN, count / STALE_SHARE);
}

/* Whether the pairs of grown boxes still hold every pair of these proxies
 * once the boxes that left theirs are grown again (regrow): the same
 * proxies and filters, and with those that left no more than stale_limit
 * stale. Lists those that left in escaped, their count in escaped_count. */
static bool still_inside(pair_tracker_t *tracker, const broadphase_proxy_t *proxies,
                         size_t count) {
    if (count != tracker->count) return false;
    size_t room = stale_limit(count) - tracker->stale_count, n = 0;
    for (size_t i = 0; i < count; i++) {
        if (!same_filters(&proxies[i], &tracker->grown[i])) return false;
        if (box_inside(proxies[i].box, tracker->grown[i].box)) continue;
        if (n == room) return false;
        tracker->escaped[n++] = (uint32_t)i;
    }
    tracker->escaped_count = n;
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

/* Room, reserved with a grown search, for what the calls until the next
 * search write (regrow's pairs and merge, the ranked pairs, the overlap
 * bits), as many pairs as it found and those of the most boxes that may
 * go stale at FOUND_PER_BOX each: a warm step then allocates nothing,
 * unless a box grown again takes in more pairs than that. */
static void reserve_after_search(pair_tracker_t *tracker, size_t count) {
    size_t found = stale_limit(count) * FOUND_PER_BOX, room = tracker->kept_count + found;
    size_t size = sizeof(broadphase_pair_t);
    memory_reserve((void **)&tracker->found, &tracker->found_capacity, found, size);
    memory_reserve((void **)&tracker->candidates[0], &tracker->candidate_capacity[0], room, size);
    memory_reserve((void **)&tracker->candidates[1], &tracker->candidate_capacity[1], room, size);
    memory_reserve((void **)&tracker->pairs, &tracker->pair_capacity, room, size);
    memory_reserve((void **)&tracker->ranks, &tracker->rank_capacity, room, sizeof(uint64_t));
    /* Both: remember swaps them at every ranked call. */
    memory_reserve((void **)&tracker->overlaps, &tracker->overlap_capacity, (room + 63) / 64,
                   sizeof(uint64_t));
    memory_reserve((void **)&tracker->last_overlaps, &tracker->last_overlap_capacity,
                   (room + 63) / 64, sizeof(uint64_t));
}

/* Searches the grid, with every box grown when `grow`, and keeps the
 * pairs. */
static void search(pair_tracker_t *tracker, const broadphase_proxy_t *proxies, size_t count,
                   bool grow, size_t *tests) {
    tracker->stale_count = 0;
    if (grow) {
        memory_reserve((void **)&tracker->stale, &tracker->stale_capacity, count, sizeof(uint8_t));
        if (count > 0) memset(tracker->stale, 0, count);
        memory_reserve((void **)&tracker->stale_list, &tracker->stale_list_capacity,
                       stale_limit(count), sizeof(uint32_t));
        memory_reserve((void **)&tracker->escaped, &tracker->escaped_capacity, stale_limit(count),
                       sizeof(uint32_t));
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
    if (grow) reserve_after_search(tracker, count);
}

enum { STALE = 1, GROWN_NOW = 2 };

/* Appends (i, j), a < b, to the pairs found when their filters allow it. */
static void add_found(pair_tracker_t *tracker, uint32_t i, uint32_t j) {
    if (!broadphase_filters_allow(&tracker->grown[i], &tracker->grown[j])) return;
    memory_reserve((void **)&tracker->found, &tracker->found_capacity, tracker->found_count + 1,
                   sizeof(broadphase_pair_t));
    tracker->found[tracker->found_count++] = i < j ? (broadphase_pair_t){i, j}
                                                   : (broadphase_pair_t){j, i};
}

typedef struct {
    pair_tracker_t *tracker;
    uint32_t proxy;
    size_t visits;
} regrow_query_t;

/* A proxy whose grid entry overlaps the query's grown box: its entry is
 * its grown box unless it is stale (those are compared in regrow_one). */
static bool visit_grown(void *context, uint32_t other) {
    regrow_query_t *query = context;
    query->visits++;
    if (other != query->proxy && !query->tracker->stale[other]) {
        add_found(query->tracker, query->proxy, other);
    }
    return true;
}

/* The pairs of proxy i, grown now, with the grid's up-to-date entries and
 * with the stale proxies; a pair of two grown now is found once, from the
 * lower index. Returns the comparisons made. */
static size_t regrow_one(pair_tracker_t *tracker, uint32_t i) {
    regrow_query_t query = {tracker, i, 0};
    aabb_t box = tracker->grown[i].box;
    broadphase_query_box(tracker->broadphase, box, visit_grown, &query);
    for (size_t k = 0; k < tracker->stale_count; k++) {
        uint32_t j = tracker->stale_list[k];
        if (j == i || (tracker->stale[j] == GROWN_NOW && j < i)) continue;
        if (aabb_overlaps(box, tracker->grown[j].box)) add_found(tracker, i, j);
    }
    return query.visits + tracker->stale_count;
}

static int compare_pairs(const void *p, const void *q) {
    const broadphase_pair_t *x = p, *y = q;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    return x->b < y->b ? -1 : x->b > y->b;
}

/* The kept pairs without those of proxies grown now, and the pairs found,
 * grouped by a, into the other candidate buffer, which becomes the kept. */
static void merge_found(pair_tracker_t *tracker) {
    const uint8_t *stale = tracker->stale;
    unsigned side = tracker->candidate_side ^ 1u;
    memory_reserve((void **)&tracker->candidates[side], &tracker->candidate_capacity[side],
                   tracker->kept_count + tracker->found_count, sizeof(broadphase_pair_t));
    broadphase_pair_t *out = tracker->candidates[side];
    const broadphase_pair_t *found = tracker->found;
    size_t n = 0, f = 0, found_count = tracker->found_count;
    for (size_t k = 0; k < tracker->kept_count; k++) {
        broadphase_pair_t pair = tracker->kept[k];
        if ((stale[pair.a] | stale[pair.b]) & GROWN_NOW) continue;
        while (f < found_count && found[f].a < pair.a) out[n++] = found[f++];
        out[n++] = pair;
    }
    while (f < found_count) out[n++] = found[f++];
    tracker->kept = out;
    tracker->kept_count = n;
    tracker->candidate_side = side;
}

/*
 * The proxies that left their grown boxes (escaped) grown again around
 * their boxes, their pairs with every grown box found by queries on the
 * grid of the last search, whose other entries are still right: the kept
 * pairs are then the pairs of grown boxes, as a search would find them,
 * at the cost of the few that moved.
 */
static void regrow(pair_tracker_t *tracker, const broadphase_proxy_t *proxies, size_t *tests) {
    for (size_t k = 0; k < tracker->escaped_count; k++) {
        uint32_t i = tracker->escaped[k];
        tracker->grown[i].box = grown_box(proxies[i].box);
        if (tracker->stale[i] == 0) tracker->stale_list[tracker->stale_count++] = i;
        tracker->stale[i] = GROWN_NOW;
    }
    tracker->found_count = 0;
    for (size_t k = 0; k < tracker->escaped_count; k++) {
        *tests += regrow_one(tracker, tracker->escaped[k]);
    }
    if (tracker->found_count > 1) {
        qsort(tracker->found, tracker->found_count, sizeof(broadphase_pair_t), compare_pairs);
    }
    merge_found(tracker);
    for (size_t k = 0; k < tracker->escaped_count; k++) tracker->stale[tracker->escaped[k]] = STALE;
    tracker->ranked = false;
}

/* Where the grid would find each pair if it searched the boxes
 * themselves this step: its cells (ranges, each proxy's; TOO_LARGE for a
 * proxy over more than BROADPHASE_MAX_CELLS, which the grid leaves out),
 * and the bucket mask. */
typedef struct {
    const cell_range_t *ranges;
    uint32_t mask;
} grid_place_t;

/* No box's range: its first column past its last. */
static const cell_range_t TOO_LARGE = {1, 0, 0, 0};

static bool too_large(cell_range_t r) {
    return r.x0 > r.x1;
}

static grid_place_t grid_place(pair_tracker_t *tracker, const broadphase_proxy_t *proxies,
                               size_t count) {
    memory_reserve((void **)&tracker->ranges, &tracker->range_capacity, count,
                   sizeof(cell_range_t));
    double inverse_size = 1.0 / choose_cell_size(proxies, count);
    size_t entries = 0;
    for (size_t i = 0; i < count; i++) {
        cell_range_t r = cell_range(&proxies[i].box, inverse_size);
        double cells = range_cells(r);
        if (cells <= BROADPHASE_MAX_CELLS) entries += (size_t)cells;
        tracker->ranges[i] = cells <= BROADPHASE_MAX_CELLS ? r : TOO_LARGE;
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
    if (too_large(a) || too_large(b)) return UINT64_MAX;
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

static bool kept_overlaps(const pair_tracker_t *tracker, const broadphase_proxy_t *proxies,
                          size_t i) {
    broadphase_pair_t pair = tracker->kept[i];
    return aabb_overlaps(proxies[pair.a].box, proxies[pair.b].box);
}

typedef struct {
    pair_tracker_t *tracker;
    const broadphase_proxy_t *proxies;
} mark_split_t;

/* Words [begin, end) of tracker->overlaps: a bit per kept pair, set when
 * its boxes overlap. A chunk writes whole words of its own. */
static void mark_words(void *context, size_t chunk, size_t begin, size_t end) {
    (void)chunk;
    const mark_split_t *split = context;
    pair_tracker_t *tracker = split->tracker;
    for (size_t w = begin; w < end; w++) {
        size_t last = min_of(64 * w + 64, tracker->kept_count);
        uint64_t bits = 0;
        for (size_t i = 64 * w; i < last; i++) {
            bits |= (uint64_t)kept_overlaps(tracker, split->proxies, i) << (i % 64);
        }
        tracker->overlaps[w] = bits;
    }
}

/* Marks which kept pairs overlap in tracker->overlaps, over the workers;
 * returns its length in words. */
static size_t mark_overlaps(pair_tracker_t *tracker, const broadphase_proxy_t *proxies) {
    size_t words = (tracker->kept_count + 63) / 64;
    memory_reserve((void **)&tracker->overlaps, &tracker->overlap_capacity, words,
                   sizeof(uint64_t));
    mark_split_t split = {tracker, proxies};
    workers_for(tracker->workers, words, mark_words, &split);
    return words;
}

/* Whether every proxy's cells and the bucket mask, all a rank reads, are
 * those of the last call. */
static bool same_cells(const pair_tracker_t *tracker, grid_place_t place, size_t count) {
    return tracker->ranked && tracker->last_count == count && tracker->last_mask == place.mask &&
           (count == 0 ||
            memcmp(place.ranges, tracker->last_ranges, count * sizeof(cell_range_t)) == 0);
}

/* Whether the same kept pairs overlap as at the last call (words of
 * tracker->overlaps marked). */
static bool same_overlaps(const pair_tracker_t *tracker, size_t words) {
    return words == 0 ||
           memcmp(tracker->overlaps, tracker->last_overlaps, words * sizeof(uint64_t)) == 0;
}

/* The marks (tracker->overlaps) of kept pairs [64 w, 64 w + 64) that lie
 * in [begin, end). */
static uint64_t marks_within(const pair_tracker_t *tracker, size_t w, size_t begin, size_t end) {
    uint64_t bits = tracker->overlaps[w];
    if (begin > 64 * w) bits &= ~(uint64_t)0 << (begin - 64 * w);
    if (end < 64 * w + 64) bits &= ((uint64_t)1 << (end - 64 * w)) - 1;
    return bits;
}

/* The kept pairs of a chunk [begin, end): the groups (pairs of one first
 * body) that start in it, moved to whole groups. */
static void whole_groups(const pair_tracker_t *tracker, size_t *begin, size_t *end) {
    const broadphase_pair_t *kept = tracker->kept;
    size_t count = tracker->kept_count;
    while (*begin > 0 && *begin < count && kept[*begin].a == kept[*begin - 1].a) (*begin)++;
    while (*end > 0 && *end < count && kept[*end].a == kept[*end - 1].a) (*end)++;
}

typedef struct {
    pair_tracker_t *tracker;
    grid_place_t place;
    size_t starts[WORKERS_MAX_CHUNKS + 1]; /* per chunk: its overlapping pairs, then where they go */
} rank_split_t;

static void count_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    rank_split_t *split = context;
    whole_groups(split->tracker, &begin, &end);
    size_t n = 0;
    for (size_t w = begin / 64; 64 * w < end; w++) {
        n += (size_t)__builtin_popcountll(marks_within(split->tracker, w, begin, end));
    }
    split->starts[chunk + 1] = n;
}

/* The chunk's overlapping pairs from its place on, each at its rank among
 * its first body's, by insertion: a body has a few. They are found a mark
 * word at a time: a branch on each pair's mark mispredicted. */
static void rank_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    rank_split_t *split = context;
    pair_tracker_t *tracker = split->tracker;
    whole_groups(tracker, &begin, &end);
    size_t n = split->starts[chunk], group = n;
    for (size_t w = begin / 64; 64 * w < end; w++) {
        for (uint64_t bits = marks_within(tracker, w, begin, end); bits != 0; bits &= bits - 1) {
            broadphase_pair_t pair = tracker->kept[64 * w + (size_t)__builtin_ctzll(bits)];
            if (n > group && tracker->pairs[n - 1].a != pair.a) group = n;
            n = insert_ranked(tracker, group, n, pair, pair_rank(split->place, pair));
        }
    }
}

/* The overlapping kept pairs (tracker->overlaps marked), each at its rank
 * among its first body's: counted, then ranked, chunk by chunk over the
 * workers, each chunk's groups whole. */
static void rank_kept(pair_tracker_t *tracker, grid_place_t place) {
    memory_reserve((void **)&tracker->pairs, &tracker->pair_capacity, tracker->kept_count,
                   sizeof(broadphase_pair_t));
    memory_reserve((void **)&tracker->ranks, &tracker->rank_capacity, tracker->kept_count,
                   sizeof(uint64_t));
    rank_split_t split = {tracker, place, {0}};
    size_t chunks = workers_chunks(tracker->workers, tracker->kept_count);
    workers_for(tracker->workers, tracker->kept_count, count_chunk, &split);
    for (size_t k = 0; k < chunks; k++) split.starts[k + 1] += split.starts[k];
    workers_for(tracker->workers, tracker->kept_count, rank_chunk, &split);
    tracker->pair_count = split.starts[chunks];
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
        if (tracker->escaped_count > 0) regrow(tracker, proxies, tests);
        tracker->since_search++;
    }
    grid_place_t place = grid_place(tracker, proxies, count);
    size_t words = mark_overlaps(tracker, proxies);
    if (!same_cells(tracker, place, count) || !same_overlaps(tracker, words)) {
        rank_kept(tracker, place);
    }
    remember(tracker, place, count);
    *tests += tracker->kept_count;
    *pairs = tracker->pairs;
    return tracker->pair_count;
}
