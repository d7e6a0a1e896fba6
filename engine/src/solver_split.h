#ifndef SOLVER_SPLIT_H
#define SOLVER_SPLIT_H

/*
 * The colour batches' sweeps (solver_wide.h) over the threads of
 * wide->workers: the colours one after another, as one thread sweeps them,
 * and each colour's batches split among the threads, which wait for each
 * other before the next colour. No two batches of a colour share a body
 * that can move, so the order within a colour changes no number: the rows
 * come out with the bytes one thread gives them.
 */

#include <stdbool.h>
#include "solver_wide.h"

/* solver_wide_pack and then solver_wide_mark_fixed over every batch. */
void solver_split_pack(solver_wide_t *wide, const solver_contact_t *contacts,
                       const solver_velocity_t *rows);
/* solver_wide_store_range over every batch. */
void solver_split_store(const solver_wide_t *wide, solver_contact_t *contacts);

void solver_split_warm_start(solver_wide_t *wide, solver_velocity_t *rows);
void solver_split_iterate(solver_wide_t *wide, solver_velocity_t *rows);
/* backward: the colours from the last to the first. */
void solver_split_correct_positions(solver_wide_t *wide, solver_displacement_t *displacements,
                                    bool backward);

#endif // #ifndef SOLVER_SPLIT_H
