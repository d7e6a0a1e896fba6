#include "solver/coloring.h"
#include <string.h>
#include "base/memory.h"

/* How far ahead colouring asks for a contact's first line, and for its
 * body b's row: the contacts lie a record apart and b anywhere in the
 * rows, and waiting on the two was most of colouring's time (pile(10000)).
 * A macro: GCC deems a function of prefetches alone const and drops its
 * calls. */
enum { CONTACT_AHEAD = 16, ROW_AHEAD = 8 };
#define COLORING_PREFETCH(contacts, rows, i, count)                        \
    do {                                                                   \
        if ((i) + CONTACT_AHEAD < (count)) {                               \
            __builtin_prefetch(&(contacts)[(i) + CONTACT_AHEAD]);          \
        }                                                                  \
        if ((i) + ROW_AHEAD < (count)) {                                   \
            __builtin_prefetch(&(rows)[(contacts)[(i) + ROW_AHEAD].b]);    \
        }                                                                  \
    } while (0)

/* Every colour taken. */
static const uint32_t FULL = ((uint32_t)1 << COLORING_MAX_COLORS) - 1;

void coloring_free(coloring_t *coloring) {
    memory_free(coloring->used);
    coloring->used = NULL;
    coloring->used_capacity = 0;
}

int coloring_assign(coloring_t *coloring, const solver_contact_t *contacts, size_t contact_count,
                    const solver_velocity_t *rows, size_t body_count, uint8_t *colors) {
    memory_reserve((void **)&coloring->used, &coloring->used_capacity, body_count,
                   sizeof(uint32_t));
    uint32_t *used = coloring->used;
    memset(used, 0, body_count * sizeof(uint32_t));
    uint32_t all = 0;
    for (size_t i = 0; i < contact_count; i++) {
        COLORING_PREFETCH(contacts, rows, i, contact_count);
        uint32_t a = contacts[i].a, b = contacts[i].b;
        bool move_a = !solver_row_is_static(&rows[a]);
        bool move_b = !solver_row_is_static(&rows[b]);
        uint32_t taken = (move_a ? used[a] : 0) | (move_b ? used[b] : 0);
        if (taken == FULL) {
            colors[i] = COLORING_NONE;
            continue;
        }
        uint32_t color_bit = ~taken & (taken + 1); /* the lowest free colour */
        if (move_a) used[a] |= color_bit;
        if (move_b) used[b] |= color_bit;
        all |= color_bit;
        colors[i] = (uint8_t)__builtin_ctz(color_bit);
    }
    return all == 0 ? 0 : 32 - __builtin_clz(all);
}
