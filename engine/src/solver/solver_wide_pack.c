/*
 * The colour batches filled and read back (solver_wide.h): the contacts
 * coloured, sorted by colour and kind and packed lane by lane; their
 * impulses stored back to the contacts, or read for shock propagation.
 */
#include "solver/solver_wide.h"
#include <string.h>
#include "base/memory.h"
#include "base/prefetch.h"
#include "solver/solver_wide_private.h"

/* Where a batch is packed: its index, its first point's and its block's. */
typedef struct {
    size_t batch, point, block;
} pack_at_t;

/* The fields load_batch packs come in groups of four adjacent doubles. */
_Static_assert(offsetof(solver_point_t, rn_b) == offsetof(solver_point_t, normal_impulse) + 24 &&
                   offsetof(solver_point_t, tangent_mass) == offsetof(solver_point_t, rt_a) + 24 &&
                   offsetof(solver_point_t, separation) == offsetof(solver_point_t, target) + 8 &&
                   offsetof(solver_contact_t, friction) == offsetof(solver_contact_t, normal) + 16 &&
                   offsetof(solver_contact_t, m22) == offsetof(solver_contact_t, slop) + 24,
               "solver_point_t and solver_contact_t: load_batch reads four doubles at a time");

/* An empty lane's contact: all zeros, body row 0. */
static const solver_contact_t NO_CONTACT;

/* Packs order[0 .. count) (at most LANES contacts of one kind) into the
 * batch, points and block at `at`; an empty lane holds zeros, masses too.
 * Each group of four adjacent doubles of the contacts is one vector load
 * per contact, transposed into the lanes. */
LANE_INLINE void load_batch(solver_wide_t *wide, pack_at_t at, const uint32_t *order, int count,
                            batch_kind_t kind, const solver_contact_t *contacts,
                            const solver_velocity_t *rows) {
    int points = kind_points(kind);
    solver_batch_t *batch = &wide->batches[at.batch];
    solver_position_batch_t *position = &wide->position_batches[at.batch];
    batch->lanes = position->lanes = (uint8_t)count;
    batch->kind = position->kind = (uint8_t)kind;
    position->point_count = (uint8_t)points;
    const solver_contact_t *c[LANES];
    lane_t ma = {0.0}, mb = {0.0}, ia = {0.0}, ib = {0.0}, rate = {0.0};
    for (int l = 0; l < LANES; l++) {
        c[l] = l < count ? &contacts[order[l]] : &NO_CONTACT;
        batch->a[l] = position->a[l] = c[l]->a;
        batch->b[l] = position->b[l] = c[l]->b;
        batch->contact[l] = l < count ? order[l] : 0;
        if (l >= count) continue;
        const solver_velocity_t *row_a = &rows[c[l]->a], *row_b = &rows[c[l]->b];
        ma[l] = row_a->inverse_mass;
        mb[l] = row_b->inverse_mass;
        ia[l] = row_a->inverse_inertia;
        ib[l] = row_b->inverse_inertia;
        rate[l] = solver_position_rate(row_a, row_b);
    }
    /* normal.x, normal.y, friction, restitution; slop, m11, m12, m22 */
    lane_quad_t n = gather_records(&c[0]->normal, &c[1]->normal, &c[2]->normal, &c[3]->normal);
    lane_quad_t s = gather_records(&c[0]->slop, &c[1]->slop, &c[2]->slop, &c[3]->slop);
    batch->normal.x = position->normal.x = n.v0;
    batch->normal.y = position->normal.y = n.v1;
    batch->friction = n.v2;
    batch->ia = position->ia = ia;
    batch->ib = position->ib = ib;
    position->ma = ma;
    position->mb = mb;
    position->rate = rate;
    position->slop = s.v0;
    lane_t rn_a[2], rn_b[2];
    for (int i = 0; i < points; i++) {
        lane_point_t *lp = &wide->points[at.point + (size_t)i];
        solver_position_point_t *pp = &wide->position_points[at.point + (size_t)i];
        /* normal_impulse, tangent_impulse, rn_a, rn_b; rt_a, rt_b,
         * normal_mass, tangent_mass; target, separation and two more */
        lane_quad_t q1 = gather_records(&c[0]->points[i].normal_impulse, &c[1]->points[i].normal_impulse,
                                        &c[2]->points[i].normal_impulse, &c[3]->points[i].normal_impulse);
        lane_quad_t q2 = gather_records(&c[0]->points[i].rt_a, &c[1]->points[i].rt_a,
                                        &c[2]->points[i].rt_a, &c[3]->points[i].rt_a);
        lane_quad_t q3 = gather_records(&c[0]->points[i].target, &c[1]->points[i].target,
                                        &c[2]->points[i].target, &c[3]->points[i].target);
        lp->normal_impulse = q1.v0;
        lp->tangent_impulse = q1.v1;
        lp->rn.a = pp->rn.a = rn_a[i] = q1.v2;
        lp->rn.b = pp->rn.b = rn_b[i] = q1.v3;
        lp->rt.a = q2.v0;
        lp->rt.b = q2.v1;
        lp->normal_mass = pp->normal_mass = q2.v2;
        lp->tangent_mass = q2.v3;
        lp->target = q3.v0;
        pp->separation = q3.v1;
    }
    if (kind == BATCH_BLOCK) {
        /* solver_contact_k, lane by lane: the same operations in the same
         * order, so the same bits. */
        lane_block_t *k = &wide->blocks[at.block];
        k->k11 = ma + mb + ia * rn_a[0] * rn_a[0] + ib * rn_b[0] * rn_b[0];
        k->k12 = ma + mb + ia * rn_a[0] * rn_a[1] + ib * rn_b[0] * rn_b[1];
        k->k22 = ma + mb + ia * rn_a[1] * rn_a[1] + ib * rn_b[1] * rn_b[1];
        k->m11 = s.v1;
        k->m12 = s.v2;
        k->m22 = s.v3;
    }
}

/* How many contacts ahead of the one being packed are asked for: the
 * colours' order scatters the packing's reads over the contact buffer,
 * which a pile of 4000 bodies holds more of than the cache (measured:
 * 27% of the packing's time waited on each contact's first field). Their
 * bodies' rows are asked for half as far ahead, when the contact's own
 * first line has come. */
enum { PACK_AHEAD = 4 * LANES };

/* Asks for the lines of contacts order[from .. from + LANES), as far as
 * total, and for the rows of contacts order[from - PACK_AHEAD / 2 ..).
 * A macro: GCC deems a function of prefetches alone const and drops its
 * calls. */
#define PREFETCH_CONTACTS(contacts, rows, order, from, total)                               \
    do {                                                                                    \
        size_t end_ = (from) + LANES < (total) ? (from) + LANES : (total);                  \
        for (size_t k_ = (from); k_ < end_; k_++) {                                         \
            PREFETCH_SPAN(&(contacts)[(order)[k_]], sizeof(solver_contact_t), 0);          \
        }                                                                                   \
        size_t near_ = (from) - PACK_AHEAD / 2;                                             \
        end_ = near_ + LANES < (total) ? near_ + LANES : (total);                           \
        for (size_t k_ = near_; k_ < end_; k_++) {                                          \
            const solver_contact_t *c_ = &(contacts)[(order)[k_]];                          \
            __builtin_prefetch(&(rows)[c_->a]);                                             \
            __builtin_prefetch(&(rows)[c_->b]);                                             \
        }                                                                                   \
    } while (0)

static batch_kind_t kind_of(const solver_contact_t *c) {
    if (c->block) return BATCH_BLOCK;
    return c->point_count == 2 ? BATCH_PAIR : BATCH_SINGLE;
}

enum { GROUPS = BATCH_KINDS * COLORING_MAX_COLORS };
/* How many contacts ahead sorting asks for a contact's first line. */
enum { SORT_AHEAD = 16 };

_Static_assert((int)GROUPS < (int)COLORING_NONE, "a group fits where its contact's colour was");

/* Orders the contacts by colour, and within a colour by kind; the
 * uncoloured go to the loose list. Fills start (GROUPS + 1 entries) with
 * the group boundaries in wide->order. The first pass turns each colour
 * into its group, so that the second reads a byte per contact rather than
 * the contact. */
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
    uint32_t next[GROUPS];
    memcpy(next, start, sizeof next);
    for (size_t i = 0; i < count; i++) {
        if (group[i] == COLORING_NONE) continue;
        wide->order[next[group[i]]++] = (uint32_t)i;
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
}

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

LANE_CLONES
void solver_wide_pack(solver_wide_t *wide, const solver_contact_t *contacts,
                      const solver_velocity_t *rows, size_t begin, size_t end) {
    size_t g = begin < end ? group_of(wide, begin) : 0;
    for (size_t i = begin; i < end; i++) {
        while (wide->group_batch[g + 1] <= i) g++;
        pack_at_t at = {i, first_point(wide, g, i), first_block(wide, g, i)};
        uint32_t first = wide->group_start[g] + (uint32_t)(i - wide->group_batch[g]) * LANES;
        uint32_t left = wide->group_start[g + 1] - first;
        int n = (int)(left < LANES ? left : LANES);
        PREFETCH_CONTACTS(contacts, rows, wide->order, first + PACK_AHEAD,
                          wide->group_start[GROUPS]);
        load_batch(wide, at, wide->order + first, n, (batch_kind_t)(g % BATCH_KINDS), contacts,
                   rows);
    }
}

void solver_wide_arrange(solver_wide_t *wide, const solver_contact_t *contacts, size_t count,
                         const solver_velocity_t *rows, size_t body_count) {
    reserve(wide, count);
    coloring_assign(&wide->coloring, contacts, count, rows, body_count, wide->colors);
    uint32_t *start = wide->group_start;
    sort_by_color(wide, contacts, count, start);
    place_groups(wide, start);
}

LANE_CLONES
void solver_wide_pack_all(solver_wide_t *wide, const solver_contact_t *contacts,
                          const solver_velocity_t *rows) {
    const uint32_t *start = wide->group_start;
    pack_at_t at = {0, 0, 0};
    for (int g = 0; g < GROUPS; g++) {
        batch_kind_t kind = (batch_kind_t)(g % BATCH_KINDS);
        for (uint32_t i = start[g]; i < start[g + 1]; i += LANES) {
            int n = (int)(start[g + 1] - i < LANES ? start[g + 1] - i : LANES);
            PREFETCH_CONTACTS(contacts, rows, wide->order, i + PACK_AHEAD, start[GROUPS]);
            load_batch(wide, at, wide->order + i, n, kind, contacts, rows);
            at.batch++;
            at.point += (size_t)kind_points(kind);
            at.block += kind == BATCH_BLOCK;
        }
    }
}

void solver_wide_mark_fixed(solver_wide_t *wide, const solver_velocity_t *rows, size_t begin,
                            size_t end) {
    for (size_t i = begin; i < end; i++) {
        solver_batch_t *batch = &wide->batches[i];
        uint8_t fixed_a = 0, fixed_b = 0;
        for (int l = 0; l < batch->lanes; l++) {
            fixed_a |= (uint8_t)(solver_row_is_static(&rows[batch->a[l]]) << l);
            fixed_b |= (uint8_t)(solver_row_is_static(&rows[batch->b[l]]) << l);
        }
        batch->fixed_a = wide->position_batches[i].fixed_a = fixed_a;
        batch->fixed_b = wide->position_batches[i].fixed_b = fixed_b;
    }
}

void solver_wide_store_range(const solver_wide_t *wide, solver_contact_t *contacts, size_t begin,
                             size_t end) {
    if (begin == end) return;
    const lane_point_t *points = wide->points + first_point(wide, group_of(wide, begin), begin);
    for (size_t i = begin; i < end; i++) {
        const solver_batch_t *batch = &wide->batches[i];
        for (int l = 0; l < batch->lanes; l++) {
            solver_contact_t *c = &contacts[batch->contact[l]];
            for (int k = 0; k < c->point_count; k++) {
                c->points[k].normal_impulse = points[k].normal_impulse[l];
                c->points[k].tangent_impulse = points[k].tangent_impulse[l];
            }
        }
        points += kind_points((batch_kind_t)batch->kind);
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
    memset(wide, 0, sizeof *wide);
}
