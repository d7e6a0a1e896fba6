#include "coloring.h"
#include <string.h>
#include "memory.h"

void coloring_free(coloring_t *coloring) {
    memory_free(coloring->bits);
    coloring->bits = NULL;
    coloring->bit_capacity = 0;
}

static bool can_move(const solver_velocity_t *row) {
    return row->inverse_mass != 0.0 || row->inverse_inertia != 0.0;
}

static bool is_set(const uint64_t *set, uint32_t body) {
    return (set[body >> 6] >> (body & 63)) & 1u;
}

static void set_bit(uint64_t *set, uint32_t body) {
    set[body >> 6] |= (uint64_t)1 << (body & 63);
}

int coloring_assign(coloring_t *coloring, const solver_contact_t *contacts, size_t contact_count,
                    const solver_velocity_t *rows, size_t body_count, uint8_t *colors) {
    size_t words = (body_count + 63) / 64;
    size_t needed = words * COLORING_MAX_COLORS;
    memory_reserve((void **)&coloring->bits, &coloring->bit_capacity, needed, sizeof(uint64_t));
    memset(coloring->bits, 0, needed * sizeof(uint64_t));
    int used = 0;
    for (size_t i = 0; i < contact_count; i++) {
        uint32_t a = contacts[i].a, b = contacts[i].b;
        bool move_a = can_move(&rows[a]), move_b = can_move(&rows[b]);
        colors[i] = COLORING_NONE;
        for (int color = 0; color < COLORING_MAX_COLORS; color++) {
            uint64_t *set = coloring->bits + (size_t)color * words;
            if ((move_a && is_set(set, a)) || (move_b && is_set(set, b))) continue;
            if (move_a) set_bit(set, a);
            if (move_b) set_bit(set, b);
            colors[i] = (uint8_t)color;
            if (color >= used) used = color + 1;
            break;
        }
    }
    return used;
}
