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

/*
 * Queries (jostle/query.h, broadphase_query.c) on a grid of boxes alone:
 * broadphase_build files the proxies' boxes (finding no pairs, ignoring
 * filters; one thread), and the queries read that grid until the next
 * build or broadphase_find_pairs, the proxies staying where they were
 * (the caller's array; a proxy too large for the grid is read from it,
 * the others from the copies filed). broadphase_find_pairs leaves its
 * grid for box queries the same way (not for rays). Each visits a proxy
 * at most once per query; visit returns false to stop a box query, and a
 * ray's visit returns the fraction the ray is clipped to from then on (the
 * nearest hit so far), so cells beyond it are not read.
 */
void broadphase_build(broadphase_t *broadphase, const broadphase_proxy_t *proxies, size_t count);
typedef bool (*broadphase_visit_t)(void *context, uint32_t proxy);
void broadphase_query_box(const broadphase_t *broadphase, aabb_t box, broadphase_visit_t visit,
                          void *context);
typedef double (*broadphase_ray_visit_t)(void *context, uint32_t proxy);
void broadphase_query_ray(broadphase_t *broadphase, vector_t from, vector_t to, double max_fraction,
                          broadphase_ray_visit_t visit, void *context);

/* Whether the filters of two proxies allow them to touch. */
bool broadphase_filters_allow(const broadphase_proxy_t *a, const broadphase_proxy_t *b);

#endif // #ifndef BROADPHASE_H
