#ifndef SANDBOX_FOCUS_H
#define SANDBOX_FOCUS_H

/*
 * Which contacts get an axis or an impulse arrow, so that a pile of
 * thousands stays readable and cheap to draw: the FOCUS_NEAR nearest the
 * cursor within FOCUS_RADIUS pixels of it, and the FOCUS_STRONG strongest
 * anywhere (axes: the largest normal impulses of the step; impulses: the
 * largest of the trail, faded with their age). A scene with no more than
 * FOCUS_STRONG of them draws them all. Plain C, no SDL; nothing allocated.
 */

#include <stdbool.h>
#include <stddef.h>
#include "jostle/vector.h"

#define FOCUS_RADIUS 100.0 /* pixels around the cursor */
#define FOCUS_NEAR 40
#define FOCUS_STRONG 32
#define FOCUS_MAX 64

/* The k largest weights offered (k <= FOCUS_MAX), with their indices. */
typedef struct {
    size_t index[FOCUS_MAX];
    double weight[FOCUS_MAX];
    size_t count, k;
    size_t next; /* focus_top_has: the next kept index to compare (sorted) */
} focus_top_t;

/* Empty, keeping the k largest (at most FOCUS_MAX). */
void focus_top_init(focus_top_t *top, size_t k);

/* Offers item `index` of weight w (not NaN): kept when among the k largest
 * offered so far (ties: the first offered stays). */
void focus_top_offer(focus_top_t *top, size_t index, double w);

/* Sorts the kept indices, for focus_top_has (the weights no longer match
 * them: offer nothing more). */
void focus_top_sort(focus_top_t *top);

/* Whether index is kept; the indices must be asked in increasing order
 * after focus_top_sort. */
bool focus_top_has(focus_top_t *top, size_t index);

/* Offers item `index` at pixel p to the nearest of the cursor: kept when
 * within FOCUS_RADIUS and among the k nearest (nothing without a cursor
 * over the view). */
void focus_near_offer(focus_top_t *near, size_t index, vector_t p, bool has_cursor,
                      vector_t cursor);

#endif
