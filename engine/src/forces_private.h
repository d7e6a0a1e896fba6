#ifndef FORCES_PRIVATE_H
#define FORCES_PRIVATE_H

/* What the scene needs from forces.c to explain a tick whose integration
 * overflowed (the springs, which bound the stable dt), and the force that
 * the gravity groups share with create_newtonian_gravity. */

#include <stdbool.h>
#include <stddef.h>
#include "body.h"
#include "scene.h"

/* Newtonian gravity between the pair, as create_newtonian_gravity applies
 * it (a force that is not finite stops scene_tick, naming the pair). */
void forces_gravity_between(scene_t *scene, double G, body_t *body1, body_t *body2);

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
