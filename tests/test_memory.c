/* base/memory.h: counted allocation, and arrays that grow in place. */
#include <stdint.h>
#include <string.h>
#include "base/memory.h"
#include "jostle/jostle.h"
#include "test.h"

typedef struct {
    double values[8]; /* one cache line */
} line_t;

static bool starts_a_line(const void *p) {
    return (uintptr_t)p % 64 == 0;
}

/* Grows from nothing past several doublings: every block starts a line,
 * keeps what was written, and counts as one allocation per growth. */
static void reserve_lines_aligns_and_keeps_contents(void) {
    line_t *array = NULL;
    size_t capacity = 0;
    size_t written = 0;
    for (size_t needed = 1; needed <= 1000; needed = needed * 3 + 1) {
        size_t before = engine_allocation_count(), old_capacity = capacity;
        memory_reserve_lines((void **)&array, &capacity, needed, sizeof(line_t));
        CHECK(capacity >= needed);
        CHECK(starts_a_line(array));
        CHECK(engine_allocation_count() == before + (capacity != old_capacity));
        for (size_t i = 0; i < written; i++) CHECK(array[i].values[i % 8] == (double)i);
        for (; written < needed; written++) array[written].values[written % 8] = (double)written;
    }
    memory_free(array);
}

/* Enough room already: nothing moves and nothing is allocated. */
static void reserve_lines_with_room_is_a_no_op(void) {
    line_t *array = NULL;
    size_t capacity = 0;
    memory_reserve_lines((void **)&array, &capacity, 40, sizeof(line_t));
    line_t *block = array;
    size_t before = engine_allocation_count();
    memory_reserve_lines((void **)&array, &capacity, capacity, sizeof(line_t));
    memory_reserve_lines((void **)&array, &capacity, 0, sizeof(line_t));
    CHECK(array == block);
    CHECK(engine_allocation_count() == before);
    memory_free(array);
}

/* An element smaller than a line: the block is still aligned and its size
 * rounded up to whole lines (aligned_alloc's rule), so the last element
 * can be written. */
static void reserve_lines_of_small_elements(void) {
    char *array = NULL;
    size_t capacity = 0;
    memory_reserve_lines((void **)&array, &capacity, 17, 3);
    CHECK(starts_a_line(array));
    CHECK(capacity >= 17);
    memset(array, 7, capacity * 3);
    CHECK(array[capacity * 3 - 1] == 7);
    memory_free(array);
}

TEST_SUITE(memory, TEST_CASE(reserve_lines_aligns_and_keeps_contents),
           TEST_CASE(reserve_lines_with_room_is_a_no_op),
           TEST_CASE(reserve_lines_of_small_elements));
