#ifndef SOLVER_TYPES_H
#define SOLVER_TYPES_H

/*
 * What every part of the contact solver shares: the rows of the bodies and
 * the contacts it works on, and the constants that tune it (defined in
 * solver_types.c). The bottom of solver/: the colouring, the colour
 * batches, the sweeps over threads, shock propagation and the entry point
 * (solver.h) include it; it includes none of them.
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "jostle/vector.h"
#include "base/stage_clock.h"

/* What the velocity iterations touch, kept small so that thousands of
 * bodies stay in cache: one row per body. */
typedef struct {
    vector_t v;              /* velocity being solved: ends as the step's new velocity */
    double w;
    double inverse_mass, inverse_inertia;
} solver_velocity_t;
/* Whether a row's body cannot move: no contact changes its velocity, so it
 * takes no part in the colouring and gets the firmer static correction. */
static inline bool solver_row_is_static(const solver_velocity_t *row) {
    return row->inverse_mass == 0.0 && row->inverse_inertia == 0.0;
}

/* solver_wide.c loads and stores v, w and inverse_mass as one vector of
 * four doubles. */
_Static_assert(offsetof(solver_velocity_t, inverse_mass) == 3 * sizeof(double),
               "solver_velocity_t: v, w, inverse_mass must be the first four doubles");

/* What the rest of the solve needs, one row per body. */
typedef struct {
    vector_t v_start;        /* at the start of the step */
    double w_start;
    vector_t v_free;         /* at the end of the step if no contact acted */
    double w_free;
    /* The step moves the body by dt (drift + position_weight v) for end
     * velocity v (integrator.h). */
    vector_t drift;
    double spin_drift;
    vector_t acceleration;   /* of the free motion: for times of impact */
    vector_t dx_advanced;    /* dx before the position correction */
    double dtheta_advanced;
    double impact_time;      /* of the body's earliest impact this step (s), < 0 for none */
    uint32_t impact_partner; /* the other body's row when it can move, else UINT32_MAX */
    /* When that impact lands the body on a static one: the gap to close (m)
     * along landing_direction; < 0 otherwise. */
    double landing_gap;
    vector_t landing_direction;
    int pushing_contacts;    /* contacts with a normal impulse this step */
} solver_state_t;

/* What the position iterations touch, one row per body: the displacement
 * of this step, advanced by the integrator's rule, then corrected. */
typedef struct {
    vector_t dx;
    double dtheta;
    /* Centroid to farthest vertex (m): how far a turn moves the body, for
     * the cap on the correction (SOLVER_MAX_PUSH_SPEED). Here because the
     * row is padded to the four doubles solver_wide.c loads at once anyway,
     * and the cap reads the row; a field in solver_state_t made that row
     * 112 bytes and every access to it by index dearer (0.15% more
     * instructions in pile(1000), measured). */
    double radius;
} solver_displacement_t;

/* One contact point, as the iterations see it. The lever arms r (from each
 * centroid to the point) enter only through r x n and r x t, computed once,
 * so the loops touch nothing else. What the next step's warm start reads
 * (the id and the accumulated impulses) comes first. */
typedef struct {
    uint32_t id;
    bool touched;            /* touching, or an impact that has bounced this step */
    bool lands;              /* an impact after which the point rests on the surface */
    double normal_impulse;   /* accumulated (N s), >= 0 */
    double tangent_impulse;  /* accumulated (N s), |.| <= friction * normal */
    double rn_a, rn_b;       /* r_a x normal, r_b x normal */
    double rt_a, rt_b;       /* r_a x tangent, r_b x tangent */
    double normal_mass, tangent_mass;
    double target;           /* lower bound on the end relative normal velocity */
    double separation;       /* at the start of the step (m) */
    double impact_time;      /* when the gap closes within the step (s), or < 0 */
    /* What the accelerations add to the relative normal velocity between a
     * pending impact and the end of the step (m/s); NAN when no impact is
     * pending. */
    double impact_offset;
    double restitution_impulse; /* normal impulse of the collision pass (N s), >= 0 */
    double restitution_tangent_impulse; /* friction of the collision pass (N s) */
} solver_point_t;

/* The lever arms of a contact's points (world, m), used only to prepare. */
typedef struct {
    vector_t r_a[2], r_b[2];
} solver_anchor_t;

/* The fields the next step's warm start reads (point_count, then each
 * point's id and impulses) come first, in two runs of a few words: the
 * narrowphase reads them from last step's contacts for every pair, and
 * spread over the contact they cost five cache lines instead of two. */
typedef struct {
    uint32_t a, b;           /* body rows */
    int point_count;
    bool block; /* decided with the geometry: solver_contact_blocks */
    /* The two points are an incident edge's own ends (manifold_features_t),
     * so the block solve may take a worse condition (velocity_solve.c). */
    bool edge_ends;
    /* A point has an impact within the step (impact_time >= 0): set where
     * impact times are, so passes over every contact read no further. */
    bool impact;
    uint8_t rests;           /* which body rests on the other: resting.h's bits, set by prepare */
    solver_point_t points[2];
    vector_t normal;         /* unit, from a toward b; the tangent is perp(normal) */
    double friction, restitution;
    double slop;             /* overlap the position pass leaves alone (m): solver_contact_slop */
    /* The inverse of the 2x2 normal effective-mass matrix K (block solve);
     * K itself is recomputed where it is needed (solver_contact_k). */
    double m11, m12, m22;
} solver_contact_t;

/* Five cache lines: the contact buffers are aligned to a line
 * (memory_reserve_lines), so each contact is read and written in five,
 * where at 344 bytes, with K kept, it spanned six or seven. */
_Static_assert(sizeof(solver_contact_t) == 5 * 64, "solver_contact_t fills five cache lines");

/* A two-point contact's normal effective-mass matrix K, from its points'
 * lever terms and its bodies' rows a and b: the expression preparing
 * decides the block solve with, so every user gets the same bits. */
typedef struct {
    double k11, k12, k22;
} solver_block_k_t;

/* K from the bodies' rows and the two points' lever terms along the
 * normal (rn_a[i] = r_a[i] x n, rn_b[i] = r_b[i] x n). */
static inline solver_block_k_t solver_block_k(const solver_velocity_t *a,
                                              const solver_velocity_t *b, const double rn_a[2],
                                              const double rn_b[2]) {
    double ma = a->inverse_mass, mb = b->inverse_mass;
    double ia = a->inverse_inertia, ib = b->inverse_inertia;
    return (solver_block_k_t){
        ma + mb + ia * rn_a[0] * rn_a[0] + ib * rn_b[0] * rn_b[0],
        ma + mb + ia * rn_a[0] * rn_a[1] + ib * rn_b[0] * rn_b[1],
        ma + mb + ia * rn_a[1] * rn_a[1] + ib * rn_b[1] * rn_b[1],
    };
}

static inline solver_block_k_t solver_contact_k(const solver_contact_t *c,
                                                const solver_velocity_t *a,
                                                const solver_velocity_t *b) {
    const solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
    return solver_block_k(a, b, (const double[2]){p1->rn_a, p2->rn_a},
                          (const double[2]){p1->rn_b, p2->rn_b});
}

/* The rows of every body, body_count of each. */
typedef struct {
    solver_velocity_t *velocities;
    solver_displacement_t *displacements;
    solver_state_t *states;
    size_t body_count;
} solver_bodies_t;

typedef struct {
    double dt;
    double position_weight;
    int velocity_iterations;
    int position_iterations;
    /* scene_set_warm_starting, scene_set_restitution_threshold (m/s) */
    bool warm_starting;
    double restitution_threshold;
    /* Whether this step's sweeps take their contacts in the reverse order:
     * the velocity iterations but the last, and the relaxation, the colours
     * from the last to the first and the loose contacts from the last;
     * shock propagation a body's supports from the last; the position
     * iterations each the other way than otherwise. A Gauss-Seidel sweep
     * leaves a bias along its order, and swept one way step after step a
     * pyramid leaned with it and kept swaying (docs/design.md, Sweep
     * order). */
    bool reverse;
    /* The step's stage times (NULL: not timed). */
    stage_clock_t *clock;
} solver_settings_t;

/* What preparing contacts found: an impact within the step, an elastic
 * contact, a touching point whose target was raised above 0 (a resting
 * approach, velocity_solve.c). */
typedef struct {
    bool impact, elastic, raised;
} prepared_t;

/* Below solver_settings_t's restitution_threshold (m/s) contacts are
 * inelastic (scene_set_restitution_threshold). This one replaces it for an
 * elastic pair of bodies that nothing accelerates (no gravity, no force on
 * either): nothing presses them together, so no contact of theirs rests,
 * and a slow meeting is an impact like a fast one.
 * With the ordinary threshold a gas of 20 elastic polygons in a closed box
 * without gravity kept 0.05% of its energy after 10^4 steps (every impact
 * slower than 1 m/s stopped dead); this one only keeps the collision pass
 * from re-bouncing rounding. */
extern const double SOLVER_FREE_RESTITUTION_THRESHOLD;
/*
 * Overlap the position correction leaves alone (m), so resting contacts
 * persist from step to step instead of flickering: SOLVER_LINEAR_SLOP
 * between bodies of ordinary size, SOLVER_SLOP_FRACTION of the smaller
 * body's radius (centroid to farthest vertex) when that is less. Bodies of
 * 10 cm radius or more get the full 1 mm, so piles and pyramids of 1 m
 * bodies are unchanged; a 1 cm box gets 0.07 mm where the fixed 1 mm let it
 * rest a tenth of its size deep in the floor (measured). See
 * solver_contact_slop.
 */
extern const double SOLVER_LINEAR_SLOP;
extern const double SOLVER_SLOP_FRACTION;
/* Fraction of an overlap beyond the slop that one position iteration
 * removes: between two movable bodies, and against a body that cannot move
 * (only one side moves, so a larger share does not overshoot); see
 * solver_position_rate. And the most one point's correction removes at
 * once (m). */
extern const double SOLVER_POSITION_RATE;
extern const double SOLVER_STATIC_POSITION_RATE;
extern const double SOLVER_MAX_POSITION_CORRECTION;
/*
 * The fastest the position correction moves a body (m/s): in a step of dt
 * it moves a body's centroid at most SOLVER_MAX_PUSH_SPEED dt beyond what
 * the body's velocity does, and turns it at most as far as moves its
 * farthest vertex (the radius) SOLVER_MAX_PUSH_SPEED dt, however many
 * contacts push it; and never more than SOLVER_MAX_PUSH (m) and
 * SOLVER_MAX_TURN (rad) in one step, however long the step. The rest of an
 * overlap is removed in the following steps.
 *
 * Why a speed: bodies created overlapping were pushed apart in one jump
 * (the overlap scene: 0.19 m in the first step, 11.4 m/s of position change
 * while the reported velocity stayed under 0.01 m/s); Chipmunk2D moves them
 * at 4.2 m/s at most, Box2D at 9.0 m/s. At 4 m/s that scene's overlaps are
 * under 1 cm after 20 steps instead of 17, with the same end state; 3 m/s
 * takes 22, 2 m/s 28. The turn is bounded through the radius so that one
 * speed rules both at any size: a flat figure in rad/s would swing the rim
 * of a 100 m box at hundreds of m/s. At 60 Hz it lets a 1 m box turn at
 * 5.7 rad/s, more than the overlap scene needed before (4.75); a flat
 * 2 rad/s left pile(1000) deeper (docs/design.md has the measurements). Why
 * a bound per step as well: a speed times a long step is a long way (4 m
 * in a 1 s step), and a body squeezed by many deep contacts was shoved
 * through a 1 m wall in the 10000-body pile before any cap; 0.2 m and
 * 0.2 rad were the cap then, and the first binds now only for steps longer
 * than 1/20 s.
 */
extern const double SOLVER_MAX_PUSH_SPEED;
extern const double SOLVER_MAX_PUSH;
extern const double SOLVER_MAX_TURN;

/* The position rate of a contact between bodies with these rows. Derived
 * where it is used rather than kept in solver_contact_t beside the slop:
 * the field would take the contact past its five lines, and kept it cost
 * pile(1000) 0.7% more instructions than this (measured): address
 * arithmetic in every loop over the contacts, and prepare setting it. */
static inline double solver_position_rate(const solver_velocity_t *a, const solver_velocity_t *b) {
    bool against_static = solver_row_is_static(a) || solver_row_is_static(b);
    return against_static ? SOLVER_STATIC_POSITION_RATE : SOLVER_POSITION_RATE;
}

/* The slop of a contact between bodies of these radii (m): the smaller
 * body sets it, so a small body on a large floor rests as shallow as on
 * another small body. */
static inline double solver_contact_slop(double radius_a, double radius_b) {
    double scaled = SOLVER_SLOP_FRACTION * (radius_a < radius_b ? radius_a : radius_b);
    return scaled < SOLVER_LINEAR_SLOP ? scaled : SOLVER_LINEAR_SLOP;
}

#endif // #ifndef SOLVER_TYPES_H
