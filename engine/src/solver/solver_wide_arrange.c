/*
 * The colour batches arranged and read back (solver_wide.h): the contacts
 * coloured and sorted by colour and kind, ready to be
 * prepared into the batches (solver_wide_prepare.c); their impulses stored
 * back to the contacts, or read for shock propagation.
 */
#include "solver/solver_wide.h"
#include <string.h>
#include "base/memory.h"
#include "solver/solver_wide_private.h"

static batch_kind_t kind_of(const solver_contact_t *c) {
    if (c->block) return BATCH_BLOCK;
    return c->point_count == 2 ? BATCH_PAIR : BATCH_SINGLE;
}

enum { GROUPS = BATCH_KINDS * COLORING_MAX_COLORS };
/* How many contacts ahead sorting asks for a contact's first line. */
enum { SORT_AHEAD = 16 };

_Static_assert((int)GROUPS < (int)COLORING_NONE, "a group fits where its contact's colour was");

/* Where each group's batches, points and blocks begin, from where its
 * contacts begin in wide->order (start, GROUPS + 1 entries). */
static void place_groups(solver_wide_t *wide, const uint32_t *start) {
    wide->group_batch[0] = wide->group_point[0] = wide->group_block[0] = 0;
    for (int g = 0; g < GROUPS; g++) {
        uint32_t batches = (start[g + 1] - start[g] + LANES - 1) / LANES;
        batch_kind_t kind = (batch_kind_t)(g % BATCH_KINDS);
        wide->group_batch[g + 1] = wide->group_batch[g] + batches;
        wide->group_point[g + 1] = wide->group_point[g] + batches * (uint32_t)kind_points(kind);
        wide->group_block[g + 1] = wide->group_block[g] + (kind == BATCH_BLOCK ? batches : 0);
    }
    wide->batch_count = wide->group_batch[GROUPS];
    wide->point_count = wide->group_point[GROUPS];
    wide->block_count = wide->group_block[GROUPS];
}

/* Orders the contacts by colour, and within a colour by kind; the
 * uncoloured go to the loose list. Fills start (GROUPS + 1 entries) with the group
 * boundaries in wide->order, places the groups' batches, and lists the
 * batches in the order preparing visits them (wide->visits). The first
 * pass turns each colour into its group, so that the second reads a byte
 * per contact rather than the contact. */
static void sort_by_color(solver_wide_t *wide, const solver_contact_t *contacts, size_t count,
                          uint32_t *start) {
    memset(start, 0, (GROUPS + 1) * sizeof(uint32_t));
    wide->loose_count = 0;
    uint8_t *group = wide->colors;
    for (size_t i = 0; i < count; i++) {
        /* A record apart: waiting on them was most of this loop's time. */
        if (i + SORT_AHEAD < count) __builtin_prefetch(&contacts[i + SORT_AHEAD]);
        if (group[i] == COLORING_NONE) {
            wide->loose[wide->loose_count++] = (uint32_t)i;
            continue;
        }
        group[i] = (uint8_t)(BATCH_KINDS * group[i] + kind_of(&contacts[i]));
        start[group[i] + 1]++;
    }
    for (int g = 0; g < GROUPS; g++) start[g + 1] += start[g];
    place_groups(wide, start);
    uint32_t next[GROUPS];
    memcpy(next, start, sizeof next);
    size_t visit = 0;
    for (size_t i = 0; i < count; i++) {
        int g = group[i];
        if (g == COLORING_NONE) continue;
        uint32_t at = next[g]++, in_group = at - start[g];
        wide->order[at] = (uint32_t)i;
        if (in_group % LANES != 0) continue;
        wide->visits[visit] = wide->group_batch[g] + in_group / LANES;
        wide->visit_groups[visit++] = (uint8_t)g;
    }
}

static void reserve(solver_wide_t *wide, size_t count) {
    /* At most one partly filled batch per group. */
    size_t batches = count / LANES + GROUPS;
    memory_reserve((void **)&wide->colors, &wide->color_capacity, count, sizeof(uint8_t));
    memory_reserve((void **)&wide->order, &wide->order_capacity, count, sizeof(uint32_t));
    memory_reserve((void **)&wide->loose, &wide->loose_capacity, count, sizeof(uint32_t));
    memory_reserve((void **)&wide->batches, &wide->batch_capacity, batches,
                   sizeof(solver_batch_t));
    memory_reserve((void **)&wide->position_batches, &wide->position_batch_capacity, batches,
                   sizeof(solver_position_batch_t));
    memory_reserve((void **)&wide->points, &wide->point_capacity, 2 * batches,
                   sizeof(lane_point_t));
    memory_reserve((void **)&wide->position_points, &wide->position_point_capacity, 2 * batches,
                   sizeof(solver_position_point_t));
    memory_reserve((void **)&wide->blocks, &wide->block_capacity, batches, sizeof(lane_block_t));
    memory_reserve((void **)&wide->visits, &wide->visit_capacity, batches, sizeof(uint32_t));
    memory_reserve((void **)&wide->visit_groups, &wide->visit_group_capacity, batches,
                   sizeof(uint8_t));
}

void solver_wide_arrange(solver_wide_t *wide, const solver_contact_t *contacts, size_t count,
                         const solver_velocity_t *rows, size_t body_count) {
    reserve(wide, count);
    coloring_assign(&wide->coloring, contacts, count, rows, body_count, wide->colors);
    sort_by_color(wide, contacts, count, wide->group_start);
}

void solver_wide_store_range(const solver_wide_t *wide, solver_contact_t *contacts, size_t begin,
                             size_t end) {
    for (size_t v = begin; v < end; v++) {
        size_t i = wide->visits[v];
        const solver_batch_t *batch = &wide->batches[i];
        const lane_point_t *points = &wide->points[first_point(wide, wide->visit_groups[v], i)];
        for (int l = 0; l < batch->lanes; l++) {
            solver_contact_t *c = &contacts[batch->contact[l]];
            for (int k = 0; k < c->point_count; k++) {
                c->points[k].normal_impulse = points[k].normal_impulse[l];
                c->points[k].tangent_impulse = points[k].tangent_impulse[l];
            }
        }
    }
}

void solver_wide_store(const solver_wide_t *wide, solver_contact_t *contacts) {
    solver_wide_store_range(wide, contacts, 0, wide->batch_count);
}

bool solver_wide_link_loaded(const solver_wide_t *wide, uint32_t *first, solver_side_t *sides,
                             solver_slot_t *slots) {
    const lane_point_t *points = wide->points;
    solver_slot_t slot = 0; /* LANES times the index of the batch's first point */
    bool any = false;
    for (size_t i = 0; i < wide->batch_count; i++) {
        const solver_batch_t *batch = &wide->batches[i];
        const lane_t *first_impulse = &points[0].normal_impulse;
        if (batch->kind == BATCH_SINGLE) {
            /* No slot: only a two-point contact's impulses are asked for. */
            for (int l = 0; l < batch->lanes; l++) {
                if (!((*first_impulse)[l] > 0.0)) continue;
                solver_link_sides(first, sides, batch->contact[l], batch->a[l], batch->b[l]);
                any = true;
            }
            points += 1;
            slot += LANES;
            continue;
        }
        const lane_t *second_impulse = &points[1].normal_impulse;
        for (int l = 0; l < batch->lanes; l++) {
            if (!((*first_impulse)[l] > 0.0 || (*second_impulse)[l] > 0.0)) continue;
            solver_link_sides(first, sides, batch->contact[l], batch->a[l], batch->b[l]);
            slots[batch->contact[l]] = slot + (solver_slot_t)l;
            any = true;
        }
        points += 2;
        slot += 2 * LANES;
    }
    return any;
}

void solver_wide_impulses(const solver_wide_t *wide, solver_slot_t slot, int point_count,
                          double normal[2], double tangent[2]) {
    const lane_point_t *p = &wide->points[slot / LANES];
    int l = (int)(slot % LANES);
    for (int k = 0; k < point_count; k++) {
        normal[k] = p[k].normal_impulse[l];
        tangent[k] = p[k].tangent_impulse[l];
    }
}

void solver_wide_free(solver_wide_t *wide) {
    coloring_free(&wide->coloring);
    memory_free(wide->colors);
    memory_free(wide->order);
    memory_free(wide->batches);
    memory_free(wide->position_batches);
    memory_free(wide->points);
    memory_free(wide->position_points);
    memory_free(wide->blocks);
    memory_free(wide->loose);
    memory_free(wide->visits);
    memory_free(wide->visit_groups);
    memset(wide, 0, sizeof *wide);
}
