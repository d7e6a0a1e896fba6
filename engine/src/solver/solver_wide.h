#ifndef SOLVER_WIDE_H
#define SOLVER_WIDE_H

/*
 * Warm starting, the velocity iterations and the position iterations, four
 * contacts at a time. Contacts of one colour (coloring.h) share no movable
 * body, so four of them are prepared lane by lane into a batch,
 * structure-of-arrays, and solved with vector arithmetic: the same
 * preparing, friction, two-point block, one-point and position solves as
 * velocity_solve.c and position_pass.c, in the same order within a contact
 * and with the same rounding (no fused multiply-add), so a contact gets the
 * answer they would give it at its place in the order. The order across contacts is by colour.
 *
 * Why: the velocity iterations were half of a step in the 4000-body pile,
 * and one contact's solve is a short chain of dependent arithmetic that
 * leaves most of the processor idle. Four independent chains fill it (the
 * vectors are GCC/Clang vector extensions: four doubles, two SSE2 or one
 * AVX instruction each), and the velocity iterations solve two batches of
 * a colour side by side, which fills it more (solver_wide.c).
 *
 * Contacts no colour could take are listed in loose; the caller solves them
 * one at a time after the batches, in each iteration.
 *
 * Allocation: every array grows to the largest step seen and is reused.
 */

#include <stddef.h>
#include <stdint.h>
#include "solver/coloring.h"
#include "solver/solver_types.h"

typedef struct solver_wide solver_wide_t;
typedef struct solver_batch solver_batch_t;
typedef struct solver_position_batch solver_position_batch_t;
typedef struct solver_position_point solver_position_point_t;
typedef struct lane_point lane_point_t;
typedef struct lane_block lane_block_t;
typedef struct workers workers_t;

/* The batches fall in groups, one per colour and kind of contact (two-point
 * block, two-point, one-point), in this order. */
enum { SOLVER_WIDE_KINDS = 3, SOLVER_WIDE_GROUPS = SOLVER_WIDE_KINDS * COLORING_MAX_COLORS };

struct solver_wide {
    coloring_t coloring;
    uint8_t *colors; /* per contact: its colour, then its group (sort_by_color) */
    size_t color_capacity;
    uint32_t *order;
    size_t order_capacity;
    solver_batch_t *batches;
    size_t batch_count, batch_capacity;
    solver_position_batch_t *position_batches; /* the same contacts, for the position pass */
    size_t position_batch_capacity;
    /* The batches' points (1 or 2 each, in batch order) and the block
     * batches' matrices (in batch order). */
    lane_point_t *points;
    solver_position_point_t *position_points;
    size_t point_count, point_capacity, position_point_capacity;
    lane_block_t *blocks;
    size_t block_count, block_capacity;
    uint32_t *loose;
    size_t loose_count, loose_capacity;
    /* The batches (and their groups) in the order preparing visits them:
     * by their first contact's place in the contact buffer, so that it
     * walks the buffer forward once rather than once per group. */
    uint32_t *visits;
    uint8_t *visit_groups;
    size_t visit_capacity, visit_group_capacity;
    /* Where each group's contacts (in order), batches, points and blocks
     * begin (and the end); a colour's batches are those of its
     * SOLVER_WIDE_KINDS groups. */
    uint32_t group_start[SOLVER_WIDE_GROUPS + 1];
    uint32_t group_batch[SOLVER_WIDE_GROUPS + 1];
    uint32_t group_point[SOLVER_WIDE_GROUPS + 1];
    uint32_t group_block[SOLVER_WIDE_GROUPS + 1];
    /* The threads that share each colour's batches (solver_split.h); NULL:
     * the caller alone. */
    workers_t *workers;
};

void solver_wide_free(solver_wide_t *wide);

/* Colours the contacts and places each colour's groups of each kind (the
 * contacts' block fields decided: solver_contact_blocks), ready to be
 * prepared into batches (solver_wide_prepare). */
void solver_wide_arrange(solver_wide_t *wide, const solver_contact_t *contacts, size_t count,
                         const solver_velocity_t *rows, size_t body_count);

/* Prepares the batches visits[begin .. end) of the contacts
 * solver_wide_arrange placed, as solver_prepare_contact prepares one
 * contact, with their current accumulated impulses, and writes what
 * preparing found back to the contacts too; marks the lanes whose bodies
 * cannot move (solver_batch's fixed_a, fixed_b); returns what they hold.
 * Each batch writes only its own contacts and lanes: ranges may run on
 * several threads. */
prepared_t solver_wide_prepare(solver_wide_t *wide, solver_contact_t *contacts,
                               const solver_anchor_t *anchors, const solver_bodies_t *bodies,
                               const solver_settings_t *settings, size_t begin, size_t end);

/* The sweeps below run on the calling thread; solver_split.h runs them
 * over the workers when there are some. */

/* Applies the batches' accumulated impulses (last step's, warm starting)
 * to the velocities. */
void solver_wide_warm_start(solver_wide_t *wide, solver_velocity_t *rows);

/* One velocity iteration over every batch, colour by colour, from the
 * last colour to the first when backward (solver_settings_t's reverse). */
void solver_wide_iterate(solver_wide_t *wide, solver_velocity_t *rows, bool backward);

/* One velocity iteration of the normals alone (no friction): the
 * relaxation (solver.c); backward as above. */
void solver_wide_relax(solver_wide_t *wide, solver_velocity_t *rows, bool backward);

/* One position iteration (position_pass.h's solver_solve_position) over
 * every batch, colour by colour, from the last batch back when backward.
 * Within a colour the contacts are corrected side by side, so a one-way
 * sweep leaves the colours solved first at a disadvantage; sweeping back
 * and forth in turn restores the quality of solving in contact order
 * (pyramid(40) top box 0.086 m down against 0.093 m one-way and 0.084 m in
 * contact order; the velocity iterations, swept the same way, got worse,
 * 0.18 m). */
void solver_wide_correct_positions(solver_wide_t *wide, solver_displacement_t *displacements,
                                   bool backward);

/* One end of a contact in its body's list of contacts (shock.h): contact
 * i's ends are 2i (seen from a) and 2i + 1 (from b). */
typedef struct {
    uint32_t next;           /* the body's next end, SOLVER_NO_SIDE after its last */
    uint32_t other;          /* the body at the other end */
} solver_side_t;
enum { SOLVER_NO_SIDE = UINT32_MAX };

/* Pushes both ends of contact i (between body rows a and b) onto the front
 * of their bodies' lists (first: each body's first end). */
static inline void solver_link_sides(uint32_t *first, solver_side_t *sides, uint32_t i,
                                     uint32_t a, uint32_t b) {
    uint32_t side = 2 * i; /* fits: 2^31 contacts would not fit in memory */
    sides[side] = (solver_side_t){first[a], b};
    first[a] = side;
    sides[side + 1] = (solver_side_t){first[b], a};
    first[b] = side + 1;
}

/* Where a batched contact's accumulated impulses lie in the batches: for
 * solver_wide_impulses. */
typedef uint32_t solver_slot_t;

/* Pushes both ends of every batched contact that carries load (either
 * point's accumulated normal impulse > 0) onto its bodies' lists: first[body]
 * is a body's first end (the caller sets them all to SOLVER_NO_SIDE before),
 * sides[end] its next and the body at the other end, and for a two-point
 * contact i, slots[i] where its impulses lie. The lists come out in no particular order.
 * Reads the impulses in the batches, so nothing is stored back first.
 * Returns whether any contact carries load. */
bool solver_wide_link_loaded(const solver_wide_t *wide, uint32_t *first, solver_side_t *sides,
                             solver_slot_t *slots);

/* The accumulated impulses of the batched two-point contact at slot:
 * normal and tangent at each of its point_count points. */
void solver_wide_impulses(const solver_wide_t *wide, solver_slot_t slot, int point_count,
                          double normal[2], double tangent[2]);

/* The sweeps above over batches [begin, end) only, which must lie in one
 * colour, for solver_split.c: several threads may sweep ranges of one
 * colour at once, since no two of its batches share a body that can move,
 * and these neither write the rows of bodies that cannot move nor read a
 * row for an empty lane. A range gives its bodies the bytes the whole
 * sweep would (the rows of bodies that cannot move hold no -0.0, which a
 * write of theirs could turn to +0.0: world.c's load_body). */
void solver_wide_warm_start_range(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                                  size_t end);
void solver_wide_iterate_range(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                               size_t end);
void solver_wide_relax_range(solver_wide_t *wide, solver_velocity_t *rows, size_t begin,
                             size_t end);
void solver_wide_correct_range(solver_wide_t *wide, solver_displacement_t *displacements,
                               size_t begin, size_t end);
/* solver_wide_store of the batches visits[begin .. end), in the order
 * preparing visits them, which walks the contacts forward (each batch
 * writes its own contacts: ranges may run on several threads). */
void solver_wide_store_range(const solver_wide_t *wide, solver_contact_t *contacts, size_t begin,
                             size_t end);

/* Writes the batches' accumulated impulses back to their contacts. */
void solver_wide_store(const solver_wide_t *wide, solver_contact_t *contacts);

#endif // #ifndef SOLVER_WIDE_H
