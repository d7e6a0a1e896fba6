#ifndef COLORING_H
#define COLORING_H

/*
 * Greedy colouring of the contact graph (bodies are nodes, contacts are
 * edges): no two contacts of one colour share a body that can move, so the
 * contacts of a colour can be solved at the same time without one
 * overwriting another's result (solver_wide.h solves four at once).
 * Bodies that cannot move (both inverse mass and inverse inertia zero) do
 * not count: every contact may touch the floor.
 *
 * A pile's contact graph has degree about 6, so a handful of colours holds
 * nearly every contact; a contact that fits none of COLORING_MAX_COLORS gets
 * COLORING_NONE and is solved on its own.
 *
 * Finding a contact's colour is one OR of its two bodies' colour sets and
 * a lowest-zero-bit: O(1), so colouring costs less than a pass that reads
 * the contacts.
 *
 * Allocation: the colour sets grow to the largest scene seen and are reused.
 */

#include <stddef.h>
#include <stdint.h>
#include "solver/solver_types.h"

enum { COLORING_MAX_COLORS = 24, COLORING_NONE = 255 };

typedef struct {
    uint32_t *used; /* per body, a bit for each colour its contacts have */
    size_t used_capacity;
} coloring_t;

void coloring_free(coloring_t *coloring);

/* Gives each contact the lowest colour whose contacts share no movable
 * body with it, in contact order, writing it to colors[i] (COLORING_NONE
 * when none is free). rows are the solver's body rows, body_count of them.
 * Returns the number of colours used. */
int coloring_assign(coloring_t *coloring, const solver_contact_t *contacts, size_t contact_count,
                    const solver_velocity_t *rows, size_t body_count, uint8_t *colors);

#endif // #ifndef COLORING_H
