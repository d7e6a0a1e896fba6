#ifndef JOINT_SOLVER_H
#define JOINT_SOLVER_H

/*
 * The joints' part of the solver (solver.c calls it at four points):
 * joint_solver_prepare after the contacts are warm-started, prepares every
 * joint of the step and applies its warm-start impulses;
 * joint_solver_iterate after each velocity sweep of the contacts, one
 * velocity sweep of the joints; joint_solver_correct after each position
 * sweep of the contacts, one position sweep of the rigid joints;
 * joint_solver_settle once the displacements are fixed (after the
 * velocity iterations, before the position pass), the end velocities made
 * consistent with the joints at the pose the step ends in. Joints
 * run one after another in the order given, on the calling thread, so the
 * result is the same bits for any worker count.
 *
 * A joint takes part when both its bodies are in the step's rows (body1
 * may be NULL, the world) and neither is asleep or marked removed; its rows
 * are then found by body_t.solver_index, which the world set while loading.
 */

#include <stdbool.h>
#include <stddef.h>
#include "solver/joint_types.h"

/* The joints of a step and what they solve on. */
typedef struct {
    joint_t *const *joints;
    size_t count;
} joint_step_t;

void joint_solver_prepare(const joint_step_t *step, const solver_bodies_t *bodies,
                          const solver_settings_t *settings);
void joint_solver_iterate(const joint_step_t *step);
void joint_solver_correct(const joint_step_t *step);
void joint_solver_settle(const joint_step_t *step);

#endif // #ifndef JOINT_SOLVER_H
