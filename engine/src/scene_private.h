#ifndef SCENE_PRIVATE_H
#define SCENE_PRIVATE_H

/* What the force creators of forces.c need from the scene beyond scene.h. */

#include "contact.h"
#include "scene.h"

/* Appends an entry to the record of the tick in progress. */
void scene_record_contact(scene_t *scene, const contact_t *entry);

#endif // #ifndef SCENE_PRIVATE_H
