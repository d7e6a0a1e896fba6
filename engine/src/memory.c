#include "memory.h"
#include <stdio.h>
#include <stdlib.h>
#include "check.h"
#include "engine.h"

static size_t allocation_count = 0;

size_t engine_allocation_count(void) {
    return allocation_count;
}

void *memory_alloc(size_t size) {
    void *block = malloc(size == 0 ? 1 : size);
    REQUIRE(block != NULL, "out of memory allocating %zu bytes", size);
    allocation_count++;
    return block;
}

void *memory_calloc(size_t count, size_t size) {
    void *block = calloc(count == 0 ? 1 : count, size == 0 ? 1 : size);
    REQUIRE(block != NULL, "out of memory allocating %zu x %zu bytes", count, size);
    allocation_count++;
    return block;
}

void *memory_realloc(void *block, size_t size) {
    void *moved = realloc(block, size == 0 ? 1 : size);
    REQUIRE(moved != NULL, "out of memory growing a block to %zu bytes", size);
    if (moved != block) allocation_count++;
    return moved;
}

void memory_free(void *block) {
    free(block);
}

void memory_reserve(void **array, size_t *capacity, size_t needed, size_t element_size) {
    if (needed <= *capacity) return;
    size_t grown = *capacity < 16 ? 16 : *capacity * 2;
    while (grown < needed) grown *= 2;
    *array = memory_realloc(*array, grown * element_size);
    *capacity = grown;
}
