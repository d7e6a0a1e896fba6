#ifndef FORCES_PRIVATE_H
#define FORCES_PRIVATE_H

/* What the scene needs from forces.c to explain a tick whose integration
 * overflowed: the springs, which bound the stable dt. */

#include <stdbool.h>
#include <stddef.h>
#include "scene.h"

/* Whether the force creator is an event of the step (a collision of
 * create_collision and its kin) rather than a force: a multi-stage
 * integrator calls it at the first stage only. */
bool forces_is_event(force_creator_t forcer);

/* Whether the force creator's forces depend on its bodies' centroids and
 * masses alone, and it adds nothing else (no impulse, torque or event):
 * the springs and Newtonian gravity. A multi-stage integrator may then
 * reuse the forces it found at the end of a step (integrator_begin). */
bool forces_is_positional(force_creator_t forcer);

/* sqrt(k / m) (rad/s) of a spring made by create_spring or
 * create_spring_with_length, m the reduced mass of its bodies; 0 for any
 * other force creator, or a spring between two INFINITY masses. */
double forces_spring_omega(force_creator_t forcer, const void *aux);

/* Writes into message the spring of this aux (a spring's, as above), its
 * bodies and its stability at the tick's dt with the scene's integrator. */
void forces_explain_spring(const void *aux, char *message, size_t size);

#endif // #ifndef FORCES_PRIVATE_H
