/* The broadphase against the definition: every pair of proxies whose boxes
 * overlap and whose filters allow it, each once, sorted by a, on random
 * scenes with bodies of mixed sizes (some covering more cells than the
 * grid takes, so the large-proxy path runs too). */
#include <stdlib.h>
#include <string.h>
#include "collision/broadphase.h"
#include "test.h"
#include "base/workers.h"

static uint32_t lcg_state = 12345;

static double lcg_uniform(void) {
    lcg_state = (uint32_t)((1103515245ull * lcg_state + 12345ull) % 2147483648ull);
    return lcg_state / 2147483648.0;
}

static broadphase_proxy_t random_proxy(double size) {
    double x = 100.0 * lcg_uniform(), y = 100.0 * lcg_uniform();
    double w = size * (0.2 + lcg_uniform()), h = size * (0.2 + lcg_uniform());
    broadphase_proxy_t proxy = {{{x, y}, {x + w, y + h}}, false, 1, UINT32_MAX, 0};
    return proxy;
}

static int compare_pairs(const void *p, const void *q) {
    const broadphase_pair_t *a = p, *b = q;
    if (a->a != b->a) return a->a < b->a ? -1 : 1;
    return a->b < b->b ? -1 : a->b > b->b;
}

enum { COUNT = 600 };

/* Bodies of three sizes, the largest covering more cells than the grid
 * takes, with all the filters. */
static void mixed_proxies(broadphase_proxy_t *proxies) {
    for (int i = 0; i < COUNT; i++) {
        double size = i % 50 == 0 ? 60.0 : i % 7 == 0 ? 6.0 : 1.5;
        proxies[i] = random_proxy(size);
        proxies[i].fixed = i % 11 == 0;
        proxies[i].group = i % 13 == 0 ? 1 : 0;
        if (i % 17 == 0) proxies[i].mask = 2;
    }
}

static void finds_exactly_the_overlapping_pairs(void) {
    static broadphase_proxy_t proxies[COUNT];
    mixed_proxies(proxies);
    static broadphase_pair_t expected[COUNT * COUNT / 2];
    size_t expected_count = 0;
    for (uint32_t a = 0; a < COUNT; a++) {
        for (uint32_t b = a + 1; b < COUNT; b++) {
            if (!aabb_overlaps(proxies[a].box, proxies[b].box)) continue;
            if (!broadphase_filters_allow(&proxies[a], &proxies[b])) continue;
            expected[expected_count++] = (broadphase_pair_t){a, b};
        }
    }
    broadphase_t *broadphase = broadphase_init();
    for (int round = 0; round < 2; round++) { /* the second reuses the arrays */
        const broadphase_pair_t *pairs;
        size_t tests = 0;
        size_t count = broadphase_find_pairs(broadphase, proxies, COUNT, &pairs, &tests);
        CHECK(count == expected_count);
        for (size_t i = 1; i < count; i++) CHECK(pairs[i - 1].a <= pairs[i].a);
        static broadphase_pair_t found[COUNT * COUNT / 2];
        memcpy(found, pairs, count * sizeof *pairs);
        qsort(found, count, sizeof *found, compare_pairs);
        CHECK(count == expected_count && memcmp(found, expected, count * sizeof *found) == 0);
        CHECK(tests < (size_t)COUNT * (COUNT - 1) / 2); /* less than all pairs */
    }
    CHECK(expected_count > 100);
    broadphase_free(broadphase);
}

/* Boxes that only touch (shared edge or corner) overlap, as aabb_overlaps
 * says; boxes a hair apart do not. */
static void touching_boxes_pair_and_separate_ones_do_not(void) {
    broadphase_proxy_t proxies[4] = {
        {{{0.0, 0.0}, {1.0, 1.0}}, false, 1, UINT32_MAX, 0},
        {{{1.0, 0.0}, {2.0, 1.0}}, false, 1, UINT32_MAX, 0},    /* shares an edge with 0 */
        {{{2.0, 1.0}, {3.0, 2.0}}, false, 1, UINT32_MAX, 0},    /* shares a corner with 1 */
        {{{3.0 + 1e-9, 0.0}, {4.0, 0.5}}, false, 1, UINT32_MAX, 0}, /* apart from 2 */
    };
    broadphase_t *broadphase = broadphase_init();
    const broadphase_pair_t *pairs;
    size_t tests = 0;
    size_t count = broadphase_find_pairs(broadphase, proxies, 4, &pairs, &tests);
    CHECK(count == 2);
    CHECK(count == 2 && pairs[0].a == 0 && pairs[0].b == 1);
    CHECK(count == 2 && pairs[1].a == 1 && pairs[1].b == 2);
    broadphase_free(broadphase);
}

/* A box swept by a step whose dt v overflows reaches infinity: it still
 * pairs with what it overlaps (the grid's mean cell size once became
 * infinite, every cell index NaN, and the fill never ended). */
static void an_infinite_box_pairs_with_what_it_overlaps(void) {
    broadphase_proxy_t proxies[4] = {
        {{{0.0, 0.0}, {1.0, 1.0}}, false, 1, UINT32_MAX, 0},
        {{{2.0, 0.0}, {INFINITY, 1.0}}, false, 1, UINT32_MAX, 0},
        {{{5.0, 5.0}, {6.0, 6.0}}, false, 1, UINT32_MAX, 0},  /* above 1 */
        {{{1e300, 0.5}, {1e301, 0.7}}, false, 1, UINT32_MAX, 0}, /* inside 1 */
    };
    broadphase_t *broadphase = broadphase_init();
    const broadphase_pair_t *pairs;
    size_t tests = 0;
    size_t count = broadphase_find_pairs(broadphase, proxies, 4, &pairs, &tests);
    CHECK(count == 1);
    CHECK(count == 1 && pairs[0].a == 1 && pairs[0].b == 3);
    broadphase_free(broadphase);
}

/* With workers the grid is filled and searched in parts: the pairs, their
 * order and the test count are still one thread's, large proxies and all. */
static void workers_find_the_same_pairs_in_the_same_order(void) {
    static broadphase_proxy_t proxies[COUNT];
    mixed_proxies(proxies);
    broadphase_t *alone = broadphase_init();
    const broadphase_pair_t *expected;
    size_t expected_tests = 0;
    size_t expected_count = broadphase_find_pairs(alone, proxies, COUNT, &expected, &expected_tests);
    for (size_t threads = 2; threads <= 3; threads++) {
        workers_t *workers = workers_init(threads);
        broadphase_t *broadphase = broadphase_init();
        broadphase_set_workers(broadphase, workers);
        for (int round = 0; round < 2; round++) { /* the second reuses the arrays */
            const broadphase_pair_t *pairs;
            size_t tests = 0;
            size_t count = broadphase_find_pairs(broadphase, proxies, COUNT, &pairs, &tests);
            CHECK(count == expected_count && tests == expected_tests);
            CHECK(count == expected_count && memcmp(pairs, expected, count * sizeof *pairs) == 0);
        }
        broadphase_free(broadphase);
        workers_free(workers);
    }
    broadphase_free(alone);
}

TEST_SUITE(broadphase, TEST_CASE(finds_exactly_the_overlapping_pairs),
           TEST_CASE(touching_boxes_pair_and_separate_ones_do_not),
           TEST_CASE(an_infinite_box_pairs_with_what_it_overlaps),
           TEST_CASE(workers_find_the_same_pairs_in_the_same_order));
