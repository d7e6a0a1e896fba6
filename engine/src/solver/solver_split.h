#ifndef SOLVER_SPLIT_H
#define SOLVER_SPLIT_H

/*
 * The colour batches' sweeps (solver_wide.h) as the solver runs them: on
 * the calling thread alone when wide->workers is NULL, else over the
 * workers' threads: the colours one after another, as one thread sweeps
 * them, and each colour's batches split among the threads, which wait for
 * each other before the next colour. No two batches of a colour share a body
 * that can move, so the order within a colour changes no number: the rows
 * come out with the bytes one thread gives them.
 */

#include <stdbool.h>
#include "solver/solver_wide.h"

/* Prepares the step's contacts (anchors[i] are contact i's):
 * solver_wide_arrange, then every batch prepared, and the loose contacts
 * one at a time (solver_prepare_contact). The contacts' block fields must
 * be decided (solver_contact_blocks). Returns what they hold. */
prepared_t solver_split_prepare(solver_wide_t *wide, solver_contact_t *contacts,
                                const solver_anchor_t *anchors, size_t count,
                                const solver_bodies_t *bodies, const solver_settings_t *settings);
/* solver_wide_store_range over every batch. */
void solver_split_store(const solver_wide_t *wide, solver_contact_t *contacts);

void solver_split_warm_start(solver_wide_t *wide, solver_velocity_t *rows);
/* backward: the colours from the last to the first. */
void solver_split_iterate(solver_wide_t *wide, solver_velocity_t *rows, bool backward);
void solver_split_relax(solver_wide_t *wide, solver_velocity_t *rows, bool backward);
void solver_split_correct_positions(solver_wide_t *wide, solver_displacement_t *displacements,
                                    bool backward);

#endif // #ifndef SOLVER_SPLIT_H
