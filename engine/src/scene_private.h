#ifndef SCENE_PRIVATE_H
#define SCENE_PRIVATE_H

/* What the force creators of forces.c need from the scene beyond scene.h. */

#include "contact.h"
#include "scene.h"
#include "world.h"

/* Appends an entry to the record of the tick in progress. */
void scene_record_contact(scene_t *scene, const contact_t *entry);

/* Lets a force creator of `scene` name `body`: stops the program (naming
 * `function` and the parameter `name`) when the body belongs to another
 * scene; a body in no scene yet becomes this scene's, to be added here. */
void scene_claim_body(scene_t *scene, body_t *body, const char *name, const char *function);

/* The scene's world contact pipeline, NULL while contacts are off. Between
 * ticks (and in stage 1) it holds the contacts of the last step. */
world_t *scene_get_world(scene_t *scene);

/* For the message of a tick that fails: the body's index in the scene
 * (SIZE_MAX when it is not in it) and the dt of the tick in progress. */
size_t scene_body_index(const scene_t *scene, const body_t *body);
double scene_step_dt(const scene_t *scene);

#endif // #ifndef SCENE_PRIVATE_H
