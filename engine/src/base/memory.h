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

#endif // #ifndef MEMORY_H
