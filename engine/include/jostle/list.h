#ifndef LIST_H
#define LIST_H

#include <stddef.h>
#include "export.h"

JOSTLE_API_BEGIN

/*
 * A growable array of void pointers.
 *
 * Ownership: a list owns its elements when it was given a freer; list_free
 * then calls the freer on every element still in it. list_remove hands the
 * removed element back to the caller, who then owns it.
 *
 * Programmer errors (a NULL list, an index out of range, an initial capacity
 * whose size in bytes overflows a size_t, a NULL element given to list_add)
 * stop the program with a message on stderr naming the function and the bad
 * value ("engine error in list_add: element is NULL").
 */

typedef struct list list_t;

/* A function that frees one element. */
typedef void (*free_func_t)(void *);

/* A new empty list with room for initial_capacity elements before it grows
 * (0 is allowed). freer may be NULL: the elements are then not freed. */
list_t *list_init(size_t initial_capacity, free_func_t freer);

/* Frees the list and, when it has a freer, every element in it. */
void list_free(list_t *list);

size_t list_size(list_t *list);

/* The element at index (0 <= index < list_size). */
void *list_get(list_t *list, size_t index);

/* Removes the element at index, shifting the later ones down by one, and
 * returns it (the caller now owns it). */
void *list_remove(list_t *list, size_t index);

/* Appends value (not NULL) at the end, growing the list as needed
 * (amortised O(1)). */
void list_add(list_t *list, void *value);

/* Additions beyond the seed API. */

/* Replaces the element at index and returns the old one (not freed).
 * value may be NULL, which blanks the slot; a freer must then accept NULL. */
void *list_set(list_t *list, size_t index, void *value);

JOSTLE_API_END

#endif // #ifndef LIST_H
