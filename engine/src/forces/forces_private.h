#ifndef FORCES_PRIVATE_H
#define FORCES_PRIVATE_H

/* The force that the gravity groups share with create_newtonian_gravity. */

#include <stdbool.h>
#include <stddef.h>
#include "jostle/body.h"
#include "jostle/scene.h"

/* Newtonian gravity between the pair, as create_newtonian_gravity applies
 * it (a force that is not finite stops scene_tick, naming the pair). */
void forces_gravity_between(scene_t *scene, double G, body_t *body1, body_t *body2);

#endif // #ifndef FORCES_PRIVATE_H
