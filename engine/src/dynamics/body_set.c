#include "dynamics/body_set.h"
#include <string.h>
#include "dynamics/body_private.h"
#include "base/memory.h"

static size_t slot_of(uint32_t id, size_t slot_count) {
    /* Ids are consecutive: a multiplicative hash spreads them. */
    return (size_t)((id * 2654435761u) & (uint32_t)(slot_count - 1));
}

static void insert_slot(body_set_t *set, size_t index) {
    size_t slot = slot_of(set->members[index].body->id, set->slot_count);
    while (set->slots[slot] != 0) slot = (slot + 1) & (set->slot_count - 1);
    set->slots[slot] = (uint32_t)(index + 1);
}

static void rebuild_slots(body_set_t *set, size_t slot_count) {
    if (slot_count != set->slot_count) {
        memory_free(set->slots);
        set->slots = memory_alloc(slot_count * sizeof(uint32_t));
        set->slot_count = slot_count;
    }
    memset(set->slots, 0, slot_count * sizeof(uint32_t));
    for (size_t i = 0; i < set->count; i++) insert_slot(set, i);
}

size_t body_set_find(const body_set_t *set, const body_t *body) {
    if (set->slot_count == 0) return SIZE_MAX;
    size_t slot = slot_of(body->id, set->slot_count);
    while (set->slots[slot] != 0) {
        size_t index = set->slots[slot] - 1;
        if (set->members[index].body == body) return index;
        slot = (slot + 1) & (set->slot_count - 1);
    }
    return SIZE_MAX;
}

void body_set_add(body_set_t *set, body_t *body, uint8_t sides) {
    size_t found = body_set_find(set, body);
    if (found != SIZE_MAX) {
        set->members[found].sides |= sides;
        return;
    }
    memory_reserve((void **)&set->members, &set->capacity, set->count + 1,
                   sizeof(body_set_member_t));
    set->members[set->count++] = (body_set_member_t){body, sides};
    if (2 * set->count > set->slot_count) {
        size_t slot_count = set->slot_count == 0 ? 32 : set->slot_count;
        while (2 * set->count > slot_count) slot_count *= 2;
        rebuild_slots(set, slot_count);
    } else {
        insert_slot(set, set->count - 1);
    }
}

void body_set_forget_removed(body_set_t *set, size_t *remap) {
    size_t kept = 0;
    for (size_t i = 0; i < set->count; i++) {
        if (set->members[i].body->removed) {
            if (remap != NULL) remap[i] = SIZE_MAX;
            continue;
        }
        if (remap != NULL) remap[i] = kept;
        set->members[kept++] = set->members[i];
    }
    if (kept == set->count) return;
    set->count = kept;
    rebuild_slots(set, set->slot_count);
}

void body_set_free(body_set_t *set) {
    memory_free(set->members);
    memory_free(set->slots);
    *set = (body_set_t){0};
}
