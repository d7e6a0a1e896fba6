#ifndef JOINT_SOLVER_H
#define JOINT_SOLVER_H

/*
 * The joints' part of the solver (solver.c calls it at five points):
 * joint_solver_prepare after the contacts are warm-started, prepares every
 * joint of the step, applies its warm-start impulses, and factors the tree
 * solve (joint_tree.h) of the joints' equality rows at the step's start;
 * joint_solver_iterate after each velocity sweep of the contacts, one
 * velocity sweep of the joints the tree does not take, then the tree's
 * exact solve of its rows (the impulses added to the accumulated ones);
 * joint_solver_settle once the displacements are fixed (after the
 * velocity iterations, before the position pass), the rigid rows that
 * closed their gap (the tree's, and the points of the pins outside it)
 * give back the kick their positions did not see (RATTLE's half kick) and
 * every joint's end velocities are made consistent with it at the pose the
 * step ends in; joint_solver_correct after each position sweep of the
 * contacts, the position sweeps of the rigid joints the tree does not take;
 * joint_solver_project after the bound on the step's corrections
 * (solver_limit_corrections, the contacts'), Newton steps of the tree's
 * rigid rows onto their positions, each factored at the poses reached,
 * until they are within 1e-12 (m, rad), at most 8 (then position sweeps
 * of those joints too).
 *
 * The tree takes, in the joints' order, each joint without a spring,
 * limit, motor or force bound (revolute: its point; weld, rigid or soft:
 * point and angle; prismatic: across and angle; wheel: across; a distance
 * rod) unless it would close a cycle among moving bodies; that one, and
 * the rest, are swept one at a time. A soft weld's rows take no position
 * step (a spring corrects through its bias). Everything runs on the
 * calling thread in the order given, so the result is the same bits for
 * any worker count.
 *
 * A joint takes part when both its bodies are in the step's rows (body1
 * may be NULL, the world) and neither is asleep or marked removed; its rows
 * are then found by body_t.solver_index, which the world set while loading.
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "solver/joint_types.h"

/* The joints of a step, and the tree solve's arrays (the world's, reused
 * from step to step; NULL where no step is solved). */
typedef struct {
    joint_t *const *joints;
    size_t count;
    joint_tree_t *tree;
} joint_step_t;

void joint_solver_prepare(const joint_step_t *step, const solver_bodies_t *bodies,
                          const solver_settings_t *settings);
void joint_solver_iterate(const joint_step_t *step, const solver_bodies_t *bodies);
void joint_solver_correct(const joint_step_t *step);
void joint_solver_settle(const joint_step_t *step, const solver_bodies_t *bodies);
void joint_solver_project(const joint_step_t *step, const solver_bodies_t *bodies);

/* Sets held[i] for each body row i that a joint solved this step holds
 * (after joint_solver_prepare); leaves the other entries as they are. */
void joint_solver_mark_held(const joint_step_t *step, const solver_bodies_t *bodies,
                            uint8_t *held);

#endif // #ifndef JOINT_SOLVER_H
