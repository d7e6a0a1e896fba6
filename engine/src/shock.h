#ifndef SHOCK_H
#define SHOCK_H

/*
 * Shock propagation (Guendelman, Bridson and Fedkiw 2003), one pass after
 * the velocity iterations. Bodies get levels by their distance from the
 * static bodies through contacts that carry load (an impulse this step);
 * then, level by level from the ground up, each contact between two levels
 * is solved once more with the lower body held still, so whatever still
 * approaches is stopped by moving the upper body alone.
 *
 * Why: a few velocity iterations leave the lowest mode of a tall stack, a
 * slow lean, barely solved, and the column falls like a pendulum on a soft
 * hinge (a column of 20 boxes with 1 cm of jitter fell in 7 s at 8
 * iterations and needed 50 to stand). Holding the lower body still makes
 * every load-bearing contact exact in one pass from the ground up.
 *
 * Allocation: the arrays grow to the largest step seen and are reused.
 */

#include <stddef.h>
#include <stdint.h>
#include "solver.h"
#include "solver_wide.h"

/* One end of a load-bearing contact, in its body's list. */
typedef struct {
    uint32_t next;           /* the body's next side, UINT32_MAX after its last */
    uint32_t other;          /* the body at the other end */
} shock_side_t;

struct shock {
    uint32_t *level;         /* per body; UINT32_MAX when no load path reaches it */
    uint32_t *first;         /* per body: its first side, UINT32_MAX when it has none */
    shock_side_t *sides;     /* 2i and 2i + 1: contact i from its a and its b, if it carries load */
    uint32_t *queue;         /* bodies in the order the levels reached them */
    solver_impulses_t *impulses; size_t impulse_capacity;
    uint32_t *held;          /* scratch: the sides by which one body is held up */
    size_t level_capacity, first_capacity, side_capacity, queue_capacity, held_capacity;
};

void shock_free(shock_t *shock);

/* The pass over contacts[0 .. count) and the velocity rows of body_count
 * bodies. The accumulated impulses so far are read from the colour batches
 * of wide (and from the contacts for the loose ones), not stored back. */
void shock_propagate(shock_t *shock, const solver_wide_t *wide, const solver_contact_t *contacts,
                     size_t count, solver_velocity_t *velocities, size_t body_count);

#endif // #ifndef SHOCK_H
