#ifndef FORCES_PRIVATE_H
#define FORCES_PRIVATE_H

/* What the scene needs from forces.c to explain a tick whose integration
 * overflowed (the springs, which bound the stable dt), and the force that
 * the gravity groups share with create_newtonian_gravity. */

#include <stdbool.h>
#include <stddef.h>
#include "body.h"
#include "jacobian.h"
#include "scene.h"

/* Newtonian gravity between the pair, as create_newtonian_gravity applies
 * it (a force that is not finite stops scene_tick, naming the pair). */
void forces_gravity_between(scene_t *scene, double G, body_t *body1, body_t *body2);

/* sqrt(k / m) (rad/s) of a spring made by create_spring or
 * create_spring_with_length, m the reduced mass of its bodies; 0 for any
 * other force creator, or a spring between two INFINITY masses. */
double forces_spring_omega(force_creator_t forcer, const void *aux);

/* The Jacobian of a force creator of forces.h that has one (create_spring,
 * create_spring_with_length, create_drag) at the bodies' poses now, for the
 * implicit scheme; false for any other creator, whose force that scheme
 * takes explicitly. */
bool forces_jacobian(force_creator_t forcer, const void *aux, force_jacobian_t *jacobian);

/* Writes into message the spring of this aux (a spring's, as above), its
 * bodies and its stability at the tick's dt with the scene's integrator. */
void forces_explain_spring(const void *aux, char *message, size_t size);

#endif // #ifndef FORCES_PRIVATE_H
