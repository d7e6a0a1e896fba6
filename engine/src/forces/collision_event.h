#ifndef COLLISION_EVENT_H
#define COLLISION_EVENT_H

/*
 * When a collision handler fires (forces.h, create_collision): the rule of
 * one pair, read at stage 1 of every tick, shared by the pairwise collision
 * force creator and the collision groups.
 */

#include <stdbool.h>
#include "jostle/forces.h"
#include "jostle/scene.h"

/* The handler of a collision and what it is called with. */
typedef struct {
    scene_t *scene;
    collision_handler_t handler;
    void *aux;
    double force_const;
} collision_rule_t;

/* One pair's state between reads; zero for a pair not yet met. */
typedef struct {
    bool colliding;
    /* With world contacts: the reads in a row that found the colliding
     * pair apart by more than its parting distance. */
    int apart_reads;
} collision_state_t;

/* Reads the pair (body1, body2) at stage 1: calls the handler, with the
 * bodies in that order, when the pair starts colliding, and records the
 * call in the step's record (scene_get_contact); updates *state. By the
 * world's contacts when world contacts resolve the pair, else by
 * find_collision (forces.h says how). */
void collision_event_read(const collision_rule_t *rule, body_t *body1, body_t *body2,
                          collision_state_t *state);

#endif // #ifndef COLLISION_EVENT_H
