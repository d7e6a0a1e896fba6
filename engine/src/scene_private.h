#ifndef SCENE_PRIVATE_H
#define SCENE_PRIVATE_H

/* What the force creators of forces.c need from the scene beyond scene.h. */

#include "contact.h"
#include "scene.h"

/* Appends an entry to the record of the tick in progress. */
void scene_record_contact(scene_t *scene, const contact_t *entry);

/* For the message of a tick that fails: the body's index in the scene
 * (SIZE_MAX when it is not in it) and the dt of the tick in progress. */
size_t scene_body_index(const scene_t *scene, const body_t *body);
double scene_step_dt(const scene_t *scene);

#endif // #ifndef SCENE_PRIVATE_H
