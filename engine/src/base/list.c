#include "jostle/list.h"
#include <stdint.h>
#include <string.h>
#include "base/check.h"
#include "base/memory.h"

struct list {
    void **items;
    size_t size;
    size_t capacity;
    free_func_t freer;
};

list_t *list_init(size_t initial_capacity, free_func_t freer) {
    /* Otherwise the byte count below wraps around to a small block that the
     * list then believes holds initial_capacity elements. */
    REQUIRE(initial_capacity <= SIZE_MAX / sizeof(void *),
            "initial capacity %zu is too large", initial_capacity);
    list_t *list = memory_alloc(sizeof(list_t));
    list->capacity = initial_capacity;
    list->items = memory_alloc((initial_capacity == 0 ? 1 : initial_capacity) * sizeof(void *));
    list->size = 0;
    list->freer = freer;
    return list;
}

void list_free(list_t *list) {
    REQUIRE_NOT_NULL(list);
    if (list->freer != NULL) {
        for (size_t i = 0; i < list->size; i++) list->freer(list->items[i]);
    }
    memory_free(list->items);
    memory_free(list);
}

size_t list_size(list_t *list) {
    REQUIRE_NOT_NULL(list);
    return list->size;
}

void *list_get(list_t *list, size_t index) {
    REQUIRE_NOT_NULL(list);
    REQUIRE(index < list->size, "index %zu out of range (size %zu)", index, list->size);
    return list->items[index];
}

void *list_set(list_t *list, size_t index, void *value) {
    REQUIRE_NOT_NULL(list);
    REQUIRE(index < list->size, "index %zu out of range (size %zu)", index, list->size);
    void *old = list->items[index];
    list->items[index] = value;
    return old;
}

void *list_remove(list_t *list, size_t index) {
    REQUIRE_NOT_NULL(list);
    REQUIRE(index < list->size, "index %zu out of range (size %zu)", index, list->size);
    void *removed = list->items[index];
    memmove(&list->items[index], &list->items[index + 1],
            (list->size - index - 1) * sizeof(void *));
    list->size--;
    return removed;
}

void list_add(list_t *list, void *value) {
    REQUIRE_NOT_NULL(list);
    /* The course's contract: a NULL added is a bug, caught here rather than
     * where a reader of the list dereferences it. */
    REQUIRE(value != NULL, "element is NULL");
    if (list->size == list->capacity) {
        list->capacity = list->capacity < 4 ? 4 : list->capacity * 2;
        list->items = memory_realloc(list->items, list->capacity * sizeof(void *));
    }
    list->items[list->size++] = value;
}
