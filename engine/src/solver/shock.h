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
 * shock_lift does the same for the overlaps, after the velocities.
 *
 * Allocation: the arrays grow to the largest step seen and are reused.
 */

#include <stddef.h>
#include <stdint.h>
#include "solver/joint_solver.h"
#include "solver/solver_types.h"
#include "solver/solver_wide.h"

typedef struct shock shock_t;

/* Levels from the static bodies through one kind of contact (shock.c's
 * find_levels). */
typedef struct {
    uint32_t *level;         /* per body; UINT32_MAX when no path reaches it */
    uint32_t *first;         /* per body: its first side, SOLVER_NO_SIDE when it has none */
    solver_side_t *sides;    /* 2i and 2i + 1: contact i from its a and its b, if listed */
    uint32_t *queue;         /* bodies in the order the levels reached them */
    uint32_t *held;          /* the sides by which the bodies are held up, in queue order */
    uint32_t *support_end;   /* per queue place: where its body's supports end in held */
    size_t reached;          /* how many bodies the queue holds; 0 when there is nothing to do */
    size_t level_capacity, first_capacity, side_capacity, queue_capacity, held_capacity,
        support_end_capacity;
} shock_levels_t;

struct shock {
    shock_levels_t load;     /* through the contacts that carry load (shock_propagate) */
    shock_levels_t rest;     /* through the contacts on which a body rests (shock_lift) */
    uint8_t *jointed;        /* the lift: per body, whether a joint holds it */
    solver_slot_t *slots;    /* per two-point contact that carries load: where its impulses are */
    size_t slot_capacity, jointed_capacity;
};

void shock_free(shock_t *shock);

/* The pass over contacts[0 .. count) and the velocity rows of body_count
 * bodies. The accumulated impulses so far are read from the colour batches
 * of wide (and from the contacts for the loose ones), not stored back.
 * A body held by several contacts has them solved in contact order, or in
 * the reverse order when reverse (solver_settings_t).
 *
 * It also finds the levels shock_lift uses, which depend on preparing
 * alone: with workers, the two walks of the levels, each on one thread,
 * run side by side. */
void shock_propagate(shock_t *shock, const solver_wide_t *wide, const solver_contact_t *contacts,
                     size_t count, solver_velocity_t *velocities, size_t body_count,
                     bool reverse);

/*
 * The same for the overlaps (the lift), once a step before the last
 * position iteration, which then spreads its moves over both bodies of
 * each contact. Bodies get levels from the static bodies through the
 * touching contacts on which one body rests: the normal, from the lower
 * body to the upper, within 60 degrees of straight against the upper
 * body's pull (its free acceleration), as preparing marked them in each
 * contact's rests (resting.h). Level by level from the ground up,
 * each body is moved out of the overlap with its supports beyond the slop
 * by SOLVER_STATIC_POSITION_RATE of it, the lower body held still as a
 * static one is. A body pulled by nothing is never lifted, nor one that a
 * joint holds: the joints' own correction follows, and pulled back by its
 * pins every step a lifted ragdoll never came to rest.
 *
 * Why: a landing leaves overlaps of millimetres deep in a heap, and the
 * position iterations, each pushing both bodies of a contact, lift a
 * column of them under 30 m of heap by hundredths of a millimetre a step;
 * their pushes, which know no friction, slid bodies along one another
 * instead until part of the heap slipped, and the heap never rested
 * (docs/design.md, Sleeping). Contacts steeper than 60 degrees hold a
 * body sideways more than up and are left to the position iterations.
 *
 * The levels are those shock_propagate found in the same step.
 */
void shock_lift(shock_t *shock, workers_t *workers, const solver_contact_t *contacts,
                const solver_bodies_t *bodies, const joint_step_t *joints);

#endif // #ifndef SHOCK_H
