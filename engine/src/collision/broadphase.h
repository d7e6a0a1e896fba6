#ifndef BROADPHASE_H
#define BROADPHASE_H

/*
 * Finds the pairs of bodies whose (enlarged) bounding boxes overlap, with a
 * uniform grid rebuilt every step. Why a grid (docs/design.md has the
 * argument): the bodies a person drops and the benchmark piles are of similar
 * size, so a cell of about two body widths holds a handful of bodies and a
 * step costs O(N) with no tree to keep balanced; the grid is rebuilt from
 * scratch by a counting sort, so there is no incremental state to go stale.
 * Bodies much larger than a cell (walls, floors) are inserted in every cell
 * they cover; bodies covering more than BROADPHASE_MAX_CELLS cells are tested
 * against every other body instead.
 *
 * Allocation: arrays grow to the largest scene seen and are reused, so a warm
 * step allocates nothing.
 */

#include <stddef.h>
#include <stdint.h>
#include "jostle/aabb.h"

enum { BROADPHASE_MAX_CELLS = 1024 };

typedef struct {
    aabb_t box;
    /* Bodies that cannot move (infinite mass) never pair with each other. */
    bool fixed;
    uint32_t category, mask, group;
} broadphase_proxy_t;

typedef struct {
    uint32_t a, b; /* proxy indices, a < b */
} broadphase_pair_t;

typedef struct broadphase broadphase_t;

broadphase_t *broadphase_init(void);
void broadphase_free(broadphase_t *broadphase);

/* Fills *pairs (a buffer the broadphase owns, valid until the next call)
 * with every pair of proxies whose boxes overlap and whose filters allow a
 * contact, each pair once, sorted by a (so a pair's first body is visited
 * in order, and its contacts are grouped); returns how many. Adds the number of box
 * comparisons it made to *tests (the work, for tests of its scaling). */
size_t broadphase_find_pairs(broadphase_t *broadphase, const broadphase_proxy_t *proxies,
                             size_t count, const broadphase_pair_t **pairs, size_t *tests);

/* The threads that share the search of the grid's cells (scene_set_workers;
 * NULL, the default: the caller alone). The pairs come out the same, in the
 * same order. */
typedef struct workers workers_t;
void broadphase_set_workers(broadphase_t *broadphase, workers_t *workers);

/* Whether the filters of two proxies allow them to touch. */
bool broadphase_filters_allow(const broadphase_proxy_t *a, const broadphase_proxy_t *b);

#endif // #ifndef BROADPHASE_H
