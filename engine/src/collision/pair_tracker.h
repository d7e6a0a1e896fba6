#ifndef PAIR_TRACKER_H
#define PAIR_TRACKER_H

/*
 * A world's broadphase pairs kept from step to step. The grid
 * (broadphase.h) searches boxes grown by a margin (a tenth of a box's
 * extent, at most 10 cm); while every box stays inside its grown box, with
 * the same filters, the pairs of grown boxes still include every pair whose
 * boxes overlap, so the search is skipped and only the kept pairs' boxes
 * are compared. A box that leaves its grown box is grown again and its
 * pairs found by a query of the last search's grid, until so many have
 * left that a search pays. A resting pile or pyramid then searches its
 * grid once in many steps (Box2D keeps its tree's boxes enlarged for the
 * same reason); where boxes keep leaving their grown boxes, the grid
 * searches the boxes as they are (pair_tracker.c has the rules).
 *
 * What comes out is what broadphase_find_pairs gives for these proxies,
 * bit for bit and in its order, whenever the grid was last searched: the
 * order of contacts steers the solve (docs/design.md, Broadphase). Which
 * body a proxy stands for may change between calls (bodies falling asleep
 * or waking renumber them): the kept pairs are pairs of indices whose
 * grown boxes overlap, and a box outside its index's grown box starts a new
 * search.
 *
 * Allocation: arrays grow to the largest scene seen and are reused.
 */

#include <stddef.h>
#include "collision/broadphase.h"

typedef struct pair_tracker pair_tracker_t;

pair_tracker_t *pair_tracker_init(void);
void pair_tracker_free(pair_tracker_t *tracker);

/* The threads the grid's search runs on (broadphase_set_workers). */
void pair_tracker_set_workers(pair_tracker_t *tracker, workers_t *workers);

/* Fills *pairs (owned by the tracker, valid until the next call) as above
 * and returns how many; adds to *tests the box comparisons made (the
 * grid's when it searched, one per kept pair). */
size_t pair_tracker_find(pair_tracker_t *tracker, const broadphase_proxy_t *proxies, size_t count,
                         const broadphase_pair_t **pairs, size_t *tests);

#endif // #ifndef PAIR_TRACKER_H
