#ifndef JOINT_LIST_H
#define JOINT_LIST_H

/* A scene's joints, in the order created: the scene owns the list and the
 * joints in it (jostle/joint.h), and hands them to the world each step. */

#include <stddef.h>
#include "solver/joint_types.h"

typedef struct {
    joint_t **joints;
    size_t count, capacity;
} joint_list_t;

void joint_list_add(joint_list_t *list, joint_t *joint);
/* Frees the joint and takes it out, keeping the others' order. */
void joint_list_destroy(joint_list_t *list, joint_t *joint);
/* Frees the joints of which a body is marked removed (scene.h's reap). */
void joint_list_reap(joint_list_t *list);
/* Frees every joint and the list's array. */
void joint_list_free(joint_list_t *list);

#endif // #ifndef JOINT_LIST_H
