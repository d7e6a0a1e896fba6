#include "base/memory.h"
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "base/check.h"
#include "jostle/jostle.h"

/* Atomic: the worker threads of scene_set_workers grow their own buffers. */
static atomic_size_t allocation_count = 0;

size_t engine_allocation_count(void) {
    return atomic_load_explicit(&allocation_count, memory_order_relaxed);
}

static void count_allocation(void) {
    atomic_fetch_add_explicit(&allocation_count, 1, memory_order_relaxed);
}

void *memory_alloc(size_t size) {
    void *block = malloc(size == 0 ? 1 : size);
    REQUIRE(block != NULL, "out of memory allocating %zu bytes", size);
    count_allocation();
    return block;
}

void *memory_calloc(size_t count, size_t size) {
    void *block = calloc(count == 0 ? 1 : count, size == 0 ? 1 : size);
    REQUIRE(block != NULL, "out of memory allocating %zu x %zu bytes", count, size);
    count_allocation();
    return block;
}

void *memory_realloc(void *block, size_t size) {
    void *moved = realloc(block, size == 0 ? 1 : size);
    REQUIRE(moved != NULL, "out of memory growing a block to %zu bytes", size);
    if (moved != block) count_allocation();
    return moved;
}

void memory_free(void *block) {
    free(block);
}

static size_t grown_capacity(size_t capacity, size_t needed) {
    size_t grown = capacity < 16 ? 16 : capacity * 2;
    while (grown < needed) grown *= 2;
    return grown;
}

void memory_reserve(void **array, size_t *capacity, size_t needed, size_t element_size) {
    if (needed <= *capacity) return;
    size_t grown = grown_capacity(*capacity, needed);
    *array = memory_realloc(*array, grown * element_size);
    *capacity = grown;
}

enum { CACHE_LINE = 64 };

void memory_reserve_lines(void **array, size_t *capacity, size_t needed, size_t element_size) {
    if (needed <= *capacity) return;
    size_t grown = grown_capacity(*capacity, needed);
    /* aligned_alloc wants a size that is a multiple of the alignment. */
    size_t bytes = (grown * element_size + CACHE_LINE - 1) / CACHE_LINE * CACHE_LINE;
    void *block = aligned_alloc(CACHE_LINE, bytes);
    REQUIRE(block != NULL, "out of memory allocating %zu bytes", bytes);
    count_allocation();
    if (*array != NULL) memcpy(block, *array, *capacity * element_size);
    free(*array);
    *array = block;
    *capacity = grown;
}

void memory_swap(void **a, size_t *a_capacity, void **b, size_t *b_capacity) {
    void *array = *a;
    *a = *b;
    *b = array;
    size_t capacity = *a_capacity;
    *a_capacity = *b_capacity;
    *b_capacity = capacity;
}
