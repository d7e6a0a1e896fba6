/* The pairs kept from step to step (collision/pair_tracker.h) against the
 * definition, call after call while boxes move, filters change and proxies
 * come and go: every pair whose boxes overlap and whose filters allow it,
 * each once, in the order the grid finds them searching the boxes at that
 * call (broadphase.h), whenever it last searched; and it is searched again
 * only when a box has left its grown box. */
#include <stdlib.h>
#include <string.h>
#include "base/workers.h"
#include "collision/pair_tracker.h"
#include "test.h"

static uint32_t lcg_state = 777;

static double lcg_uniform(void) {
    lcg_state = (uint32_t)((1103515245ull * lcg_state + 12345ull) % 2147483648ull);
    return lcg_state / 2147483648.0;
}

enum { COUNT = 400 };

static broadphase_proxy_t proxies[COUNT];
static broadphase_pair_t expected[COUNT * COUNT / 2], found[COUNT * COUNT / 2];

static int compare_pairs(const void *p, const void *q) {
    const broadphase_pair_t *a = p, *b = q;
    if (a->a != b->a) return a->a < b->a ? -1 : 1;
    return a->b < b->b ? -1 : a->b > b->b;
}

/* Boxes of 1 to 2 m on a 40 m square, a wide floor, a box over more cells
 * than the grid takes, some fixed, grouped or masked. */
static void scatter(size_t count) {
    for (size_t i = 0; i < count; i++) {
        double x = 40.0 * lcg_uniform(), y = 40.0 * lcg_uniform();
        double w = 1.0 + lcg_uniform(), h = 1.0 + lcg_uniform();
        proxies[i] = (broadphase_proxy_t){{{x, y}, {x + w, y + h}}, i % 11 == 0, 1, UINT32_MAX, 0};
        proxies[i].group = i % 13 == 0 ? 1 : 0;
        if (i % 17 == 0) proxies[i].mask = 2;
    }
    proxies[0].box = (aabb_t){{-5.0, -1.0}, {45.0, 0.5}};
    if (count > 2) proxies[2].box = (aabb_t){{-100.0, 10.0}, {200.0, 300.0}}; /* too large for the grid */
}

static size_t brute_force(size_t count) {
    size_t n = 0;
    for (uint32_t a = 0; a < count; a++) {
        for (uint32_t b = a + 1; b < count; b++) {
            if (!aabb_overlaps(proxies[a].box, proxies[b].box)) continue;
            if (!broadphase_filters_allow(&proxies[a], &proxies[b])) continue;
            expected[n++] = (broadphase_pair_t){a, b};
        }
    }
    return n;
}

/* The tracker's pairs are the expected ones, grouped by a; returns the box
 * comparisons the call made. */
static size_t check_call(pair_tracker_t *tracker, size_t count) {
    const broadphase_pair_t *pairs;
    size_t tests = 0;
    size_t n = pair_tracker_find(tracker, proxies, count, &pairs, &tests);
    size_t want = brute_force(count);
    CHECK(n == want);
    for (size_t i = 1; i < n; i++) CHECK(pairs[i - 1].a <= pairs[i].a);
    if (n > 0) memcpy(found, pairs, n * sizeof *pairs);
    qsort(found, n, sizeof *found, compare_pairs);
    CHECK(n == want && (n == 0 || memcmp(found, expected, n * sizeof *found) == 0));
    return tests;
}

static void moves_by(size_t count, double reach) {
    for (size_t i = 1; i < count; i++) {
        double dx = reach * (2.0 * lcg_uniform() - 1.0), dy = reach * (2.0 * lcg_uniform() - 1.0);
        proxies[i].box.min.x += dx;
        proxies[i].box.max.x += dx;
        proxies[i].box.min.y += dy;
        proxies[i].box.max.y += dy;
    }
}

/* The tracker's pairs, in their order, are those the grid finds searching
 * the boxes themselves now. */
static void check_same_as_grid(pair_tracker_t *tracker, size_t count) {
    const broadphase_pair_t *pairs, *grid_pairs;
    size_t tests = 0;
    size_t n = pair_tracker_find(tracker, proxies, count, &pairs, &tests);
    broadphase_t *grid = broadphase_init();
    size_t m = broadphase_find_pairs(grid, proxies, count, &grid_pairs, &tests);
    CHECK(n == m && (n == 0 || memcmp(pairs, grid_pairs, n * sizeof *pairs) == 0));
    broadphase_free(grid);
}

/* The box comparisons of a search of the proxies as they are now (a
 * tracker's first call). */
static size_t search_tests(void) {
    const broadphase_pair_t *pairs;
    size_t tests = 0;
    pair_tracker_t *fresh = pair_tracker_init();
    pair_tracker_find(fresh, proxies, COUNT, &pairs, &tests);
    pair_tracker_free(fresh);
    return tests;
}

static void pairs_are_the_overlapping_ones_call_after_call(void) {
    scatter(COUNT);
    pair_tracker_t *tracker = pair_tracker_init();
    check_call(tracker, COUNT);
    for (int call = 0; call < 60; call++) {
        /* Creeping by up to 2 mm, jumping by up to 30 cm (out of grown
         * boxes), a filter changed, the proxies renumbered or cut short. */
        moves_by(COUNT, call % 10 == 9 ? 0.3 : 0.002);
        if (call % 15 == 7) proxies[5].mask ^= 1;
        if (call % 20 == 11) {
            broadphase_proxy_t first = proxies[1];
            memmove(proxies + 1, proxies + 2, (COUNT - 2) * sizeof *proxies);
            proxies[COUNT - 1] = first;
        }
        size_t count = call % 25 == 24 ? COUNT / 2 : COUNT;
        check_call(tracker, count);
        check_same_as_grid(tracker, count);
    }
    pair_tracker_free(tracker);
}

/* Boxes that stay inside their grown boxes cost one comparison per kept
 * pair, not a search of the grid; a box that leaves its grown box (by
 * 11 cm: more than the margin of a 1 to 2 m box) makes the next call
 * search again. */
static void resting_boxes_skip_the_search(void) {
    scatter(COUNT);
    pair_tracker_t *tracker = pair_tracker_init();
    size_t searched = check_call(tracker, COUNT);
    moves_by(COUNT, 0.001);
    size_t kept = check_call(tracker, COUNT);
    CHECK(kept < searched);
    CHECK(check_call(tracker, COUNT) == kept); /* nothing moved: the same pairs compared */
    proxies[COUNT / 2].box.max.x += 0.11;
    CHECK(check_call(tracker, COUNT) > kept);
    pair_tracker_free(tracker);
}

/* Boxes that keep leaving their grown boxes (a gas) are searched as they
 * are, grown boxes tried again after 1, 2, 4, 8 ... searches: of 40
 * calls, the 2nd, 5th, 10th, 19th and 36th search grown boxes, which
 * cost as many tests as a first call's search. */
static void moving_boxes_are_searched_as_they_are(void) {
    scatter(COUNT);
    pair_tracker_t *tracker = pair_tracker_init();
    check_call(tracker, COUNT);
    int grown = 0;
    for (int call = 0; call < 40; call++) {
        moves_by(COUNT, 0.3);
        size_t tests = check_call(tracker, COUNT);
        size_t fresh_tests = search_tests();
        grown += tests == fresh_tests;
    }
    CHECK(grown == 5);
    pair_tracker_free(tracker);
}

/* A few boxes leaving their grown boxes at each call (a settling pile)
 * are grown again and their pairs found by queries, not by a search of
 * every box: the pairs stay exact, and most calls compare far fewer boxes
 * than a search does; a search runs again only once enough boxes have
 * left (pair_tracker.c). The same boxes leave again and again, one of
 * them back and forth across the grid. */
static void a_few_boxes_leaving_are_grown_again(void) {
    scatter(COUNT);
    pair_tracker_t *tracker = pair_tracker_init();
    check_call(tracker, COUNT);
    int cheap = 0;
    for (int call = 0; call < 40; call++) {
        moves_by(COUNT, 0.001);
        for (int k = 0; k < 3; k++) {
            size_t i = 1 + (size_t)(call * 7 + k * 131) % (COUNT - 1);
            double dx = k == 0 ? (call % 2 == 0 ? 20.0 : -20.0) : 0.3;
            proxies[i].box.min.x += dx;
            proxies[i].box.max.x += dx;
        }
        size_t tests = check_call(tracker, COUNT);
        check_same_as_grid(tracker, COUNT);
        size_t fresh_tests = search_tests();
        cheap += 2 * tests < fresh_tests;
    }
    CHECK(cheap >= 36);
    pair_tracker_free(tracker);
}

/* Trackers on 2 and 3 threads hand out the pairs of one on the caller
 * alone, in its order, call after call: the overlaps are marked and the
 * pairs ranked in chunks of whole first-body groups. */
static void workers_hand_out_the_same_pairs(void) {
    scatter(COUNT);
    pair_tracker_t *alone = pair_tracker_init(), *shared[2];
    workers_t *workers[2] = {workers_init(2), workers_init(3)};
    for (int k = 0; k < 2; k++) {
        shared[k] = pair_tracker_init();
        pair_tracker_set_workers(shared[k], workers[k]);
    }
    for (int call = 0; call < 30; call++) {
        moves_by(COUNT, call % 10 == 9 ? 0.3 : 0.002);
        proxies[1 + (size_t)call * 13 % (COUNT - 1)].box.max.y += 0.2;
        const broadphase_pair_t *want, *got;
        size_t tests = 0;
        size_t n = pair_tracker_find(alone, proxies, COUNT, &want, &tests);
        for (int k = 0; k < 2; k++) {
            CHECK(pair_tracker_find(shared[k], proxies, COUNT, &got, &tests) == n);
            CHECK(n == 0 || memcmp(got, want, n * sizeof *got) == 0);
        }
    }
    for (int k = 0; k < 2; k++) {
        pair_tracker_free(shared[k]);
        workers_free(workers[k]);
    }
    pair_tracker_free(alone);
}

/* A resting scene is handed last call's pairs again while no box changes
 * cells and the same pairs overlap; a box that starts or stops touching
 * another within the cells it had still changes the pairs. Two 1 m boxes
 * 1 cm apart in a 2 m grid, the second nudged 2 cm across and back. */
static void touching_within_the_same_cells(void) {
    const broadphase_pair_t *pairs;
    size_t tests = 0;
    proxies[0] = (broadphase_proxy_t){{{0.19, 0.2}, {1.19, 1.2}}, false, 1, UINT32_MAX, 0};
    proxies[1] = (broadphase_proxy_t){{{1.2, 0.2}, {2.2, 1.2}}, false, 1, UINT32_MAX, 0};
    proxies[2] = (broadphase_proxy_t){{{5.2, 0.2}, {6.2, 1.2}}, false, 1, UINT32_MAX, 0};
    pair_tracker_t *tracker = pair_tracker_init();
    CHECK(pair_tracker_find(tracker, proxies, 3, &pairs, &tests) == 0);
    CHECK(pair_tracker_find(tracker, proxies, 3, &pairs, &tests) == 0);
    double nudges[] = {-0.02, 0.0, 0.02, 0.0};
    for (int k = 0; k < 4; k++) {
        proxies[1].box.min.x += nudges[k];
        proxies[1].box.max.x += nudges[k];
        size_t n = pair_tracker_find(tracker, proxies, 3, &pairs, &tests);
        bool touching = proxies[1].box.min.x <= proxies[0].box.max.x;
        CHECK(n == (touching ? 1u : 0u));
        CHECK(!touching || (pairs[0].a == 0 && pairs[0].b == 1));
        check_same_as_grid(tracker, 3);
    }
    pair_tracker_free(tracker);
}

/* A box that is NaN or infinite: NaN never pairs and always searches, an
 * infinite box pairs with what it overlaps, as the grid's own rule. */
static void nan_and_infinite_boxes(void) {
    scatter(8);
    pair_tracker_t *tracker = pair_tracker_init();
    proxies[3].box.max.x = INFINITY;
    check_call(tracker, 8);
    proxies[4].box.min.y = NAN;
    check_call(tracker, 8);
    check_call(tracker, 8);
    pair_tracker_free(tracker);
}

TEST_SUITE(pair_tracker, TEST_CASE(pairs_are_the_overlapping_ones_call_after_call),
           TEST_CASE(resting_boxes_skip_the_search),
           TEST_CASE(a_few_boxes_leaving_are_grown_again),
           TEST_CASE(workers_hand_out_the_same_pairs),
           TEST_CASE(moving_boxes_are_searched_as_they_are),
           TEST_CASE(touching_within_the_same_cells), TEST_CASE(nan_and_infinite_boxes));
