#ifndef MEMORY_H
#define MEMORY_H

/* Every allocation of the engine goes through these, so that tests can count
 * them (engine_allocation_count). Out of memory is fatal. */

#include <stddef.h>

void *memory_alloc(size_t size);
void *memory_calloc(size_t count, size_t size);
/* Grows or shrinks block to size bytes; counts only when it has to move. */
void *memory_realloc(void *block, size_t size);
void memory_free(void *block);

/* Ensures *array (of element_size elements) holds at least needed elements,
 * growing *capacity geometrically. */
void memory_reserve(void **array, size_t *capacity, size_t needed, size_t element_size);

/* memory_reserve for an array whose first element starts a cache line
 * (64 bytes), so that elements of a multiple of 64 bytes each fill whole
 * lines. The array must come from this function (or be NULL); free it with
 * memory_free. */
void memory_reserve_lines(void **array, size_t *capacity, size_t needed, size_t element_size);

/* Exchanges two reserved arrays with their capacities (double buffering). */
void memory_swap(void **a, size_t *a_capacity, void **b, size_t *b_capacity);

#endif // #ifndef MEMORY_H
