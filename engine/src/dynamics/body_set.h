#ifndef BODY_SET_H
#define BODY_SET_H

/*
 * The members of an all-pairs force or collision (gravity_group.c,
 * collision_group.c): bodies in the order they joined, each with the sides
 * it is on (a bit mask), found by body in constant time. Memory in
 * proportion to the members; a warm set allocates nothing.
 */

#include <stddef.h>
#include <stdint.h>
#include "jostle/body.h"

typedef struct {
    body_t *body;
    uint8_t sides;
} body_set_member_t;

typedef struct {
    body_set_member_t *members;
    size_t count, capacity;
    /* Open addressing by body id: member index + 1, 0 for an empty slot. */
    uint32_t *slots;
    size_t slot_count; /* a power of two, at least twice count; 0 before the first add */
} body_set_t;

/* Adds the body on `sides` (nonzero), after the others; a member already
 * in the set gains the sides instead, keeping its place. */
void body_set_add(body_set_t *set, body_t *body, uint8_t sides);

/* The body's place in the set, SIZE_MAX when it is not a member. */
size_t body_set_find(const body_set_t *set, const body_t *body);

/* Drops the members marked removed (body_is_removed), keeping the order of
 * the rest. When remap is not NULL it receives, for each former place, the
 * new one (SIZE_MAX for a dropped member): room for the former count. */
void body_set_forget_removed(body_set_t *set, size_t *remap);

void body_set_free(body_set_t *set);

#endif // #ifndef BODY_SET_H
