/* The solver's internals that the scene tests cannot see directly: the
 * colouring of the contact graph, and the four-lane preparing and
 * iterations. Contacts are built by hand here and prepared into the
 * batches as the solver does; the effective masses are checked against
 * their definitions, so a mistake in preparing cannot hide one in the
 * iterations. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "solver/coloring.h"
#include "solver/solver.h"
#include "solver/solver_split.h"
#include "solver/solver_wide.h"
#include "solver/velocity_solve.h"
#include "test.h"

/* The SCENES.md generator, for reproducible random graphs. */
static uint32_t lcg_state = 12345;

static double lcg_uniform(void) {
    lcg_state = (uint32_t)((1103515245ull * lcg_state + 12345ull) % 2147483648ull);
    return lcg_state / 2147483648.0;
}

static uint32_t lcg_below(uint32_t n) {
    return (uint32_t)(lcg_uniform() * n);
}

static solver_velocity_t movable_row(void) {
    return (solver_velocity_t){{0.0, 0.0}, 0.0, 1.0, 1.0};
}

static bool moves(const solver_velocity_t *row) {
    return row->inverse_mass != 0.0 || row->inverse_inertia != 0.0;
}

static bool share_movable(const solver_contact_t *c, const solver_contact_t *d,
                          const solver_velocity_t *rows) {
    uint32_t mine[2] = {c->a, c->b}, theirs[2] = {d->a, d->b};
    for (int i = 0; i < 2; i++) {
        for (int j = 0; j < 2; j++) {
            if (mine[i] == theirs[j] && moves(&rows[mine[i]])) return true;
        }
    }
    return false;
}

static void coloring_separates_movable_bodies(void) {
    enum { BODIES = 300, STATIC = 5, CONTACTS = 1200 };
    solver_velocity_t rows[BODIES];
    for (int i = 0; i < BODIES; i++) rows[i] = movable_row();
    for (int i = 0; i < STATIC; i++) rows[i] = (solver_velocity_t){{0.0, 0.0}, 0.0, 0.0, 0.0};
    static solver_contact_t contacts[CONTACTS];
    for (int i = 0; i < CONTACTS; i++) {
        uint32_t a = lcg_below(BODIES), b;
        do b = lcg_below(BODIES); while (b == a || (a < STATIC && b < STATIC));
        contacts[i] = (solver_contact_t){.a = a, .b = b};
    }
    uint8_t colors[CONTACTS];
    coloring_t coloring = {0};
    int used = coloring_assign(&coloring, contacts, CONTACTS, rows, BODIES, colors);
    int highest = -1, statics_shared = 0;
    for (int i = 0; i < CONTACTS; i++) {
        CHECK(colors[i] != COLORING_NONE); /* degree about 8: 24 colours suffice */
        if (colors[i] != COLORING_NONE && colors[i] > highest) highest = colors[i];
        for (int j = 0; j < i; j++) {
            if (colors[j] != colors[i]) continue;
            CHECK(!share_movable(&contacts[i], &contacts[j], rows));
            statics_shared += contacts[i].a < STATIC && contacts[j].a == contacts[i].a;
        }
        /* Greedy: every lower colour was taken by an earlier neighbour. */
        for (int lower = 0; lower < colors[i] && colors[i] != COLORING_NONE; lower++) {
            bool blocked = false;
            for (int j = 0; j < i && !blocked; j++) {
                blocked = colors[j] == lower && share_movable(&contacts[i], &contacts[j], rows);
            }
            CHECK(blocked);
        }
    }
    CHECK(used == highest + 1);
    CHECK(statics_shared > 0); /* a static body is no conflict */
    coloring_free(&coloring);
}

/* A body with more contacts than there are colours: the rest are left
 * uncoloured, to be solved one by one. */
static void coloring_leaves_the_excess_uncoloured(void) {
    enum { SPOKES = COLORING_MAX_COLORS + 6 };
    solver_velocity_t rows[SPOKES + 1];
    solver_contact_t contacts[SPOKES];
    for (int i = 0; i <= SPOKES; i++) rows[i] = movable_row();
    for (int i = 0; i < SPOKES; i++) contacts[i] = (solver_contact_t){.a = 0, .b = (uint32_t)i + 1};
    uint8_t colors[SPOKES];
    coloring_t coloring = {0};
    CHECK(coloring_assign(&coloring, contacts, SPOKES, rows, SPOKES + 1, colors) ==
          COLORING_MAX_COLORS);
    for (int i = 0; i < SPOKES; i++) {
        CHECK(colors[i] == (i < COLORING_MAX_COLORS ? i : COLORING_NONE));
    }
    coloring_free(&coloring);
}

/* Each contact's kind, as the narrowphase decides it. */
static void decide_blocks(solver_contact_t *contacts, const solver_anchor_t *anchors,
                          size_t count, const solver_velocity_t *rows) {
    for (size_t i = 0; i < count; i++) {
        solver_contact_t *c = &contacts[i];
        c->block = solver_contact_blocks(c, &anchors[i], &rows[c->a], &rows[c->b]);
    }
}

/* The step length of the tests' preparing. */
static const double DT = 1.0 / 60.0;

/* Prepares contacts [0, count) (anchors[i] are contact i's) into wide's
 * batches as the solver does, from bodies at rest at the start of the
 * step (no start velocity, drift or pull) and a position weight of 1,
 * each contact's kind decided as the narrowphase decides it: a
 * touching point's target is then 0, and that of a point apart by s,
 * -s / DT. The rows' velocities are where the iterations start. */
static prepared_t prepare_contacts(solver_wide_t *wide, solver_contact_t *contacts,
                                   const solver_anchor_t *anchors, size_t count,
                                   solver_velocity_t *rows, size_t body_count) {
    enum { MOST = 32 };
    static solver_state_t states[MOST];
    static solver_displacement_t displacements[MOST];
    CHECK(body_count <= MOST);
    memset(states, 0, sizeof states);
    decide_blocks(contacts, anchors, count, rows);
    solver_bodies_t bodies = {rows, displacements, states, body_count};
    solver_settings_t settings = {.dt = DT,
                                  .position_weight = 1.0,
                                  .velocity_iterations = 8,
                                  .position_iterations = 3,
                                  .warm_starting = true,
                                  .restitution_threshold = 1.0};
    return solver_split_prepare(wide, contacts, anchors, count, &bodies, &settings);
}

/* The separation that gives a point apart target `target` < 0 in
 * prepare_contacts, or a touching one for target 0. */
static double separation_for(double target) {
    return target < 0.0 ? -target * DT : -0.001;
}

/* Checks point p of a prepared contact against its definitions, from its
 * lever arms: r x d, and effective masses
 * 1 / (ma + mb + ia (r_a x d)^2 + ib (r_b x d)^2). */
static void check_point(const solver_point_t *p, vector_t r_a, vector_t r_b, vector_t normal,
                        const solver_velocity_t *a, const solver_velocity_t *b, double target) {
    vector_t tangent = {-normal.y, normal.x};
    double rn_a = vec_cross(r_a, normal), rn_b = vec_cross(r_b, normal);
    double rt_a = vec_cross(r_a, tangent), rt_b = vec_cross(r_b, tangent);
    CHECK_NEAR(p->rn_a, rn_a, 1e-15);
    CHECK_NEAR(p->rn_b, rn_b, 1e-15);
    CHECK_NEAR(p->rt_a, rt_a, 1e-15);
    CHECK_NEAR(p->rt_b, rt_b, 1e-15);
    double m = a->inverse_mass + b->inverse_mass;
    double ia = a->inverse_inertia, ib = b->inverse_inertia;
    CHECK_NEAR(p->normal_mass, 1.0 / (m + ia * rn_a * rn_a + ib * rn_b * rn_b), 1e-14);
    CHECK_NEAR(p->tangent_mass, 1.0 / (m + ia * rt_a * rt_a + ib * rt_b * rt_b), 1e-14);
    CHECK_NEAR(p->target, target, 1e-12);
}

/* Checks a prepared block contact's inverse matrix against K's definition. */
static void check_block(const solver_contact_t *c, const solver_velocity_t *a,
                        const solver_velocity_t *b) {
    const solver_point_t *p = c->points, *q = c->points + 1;
    double m = a->inverse_mass + b->inverse_mass;
    double ia = a->inverse_inertia, ib = b->inverse_inertia;
    double k11 = m + ia * p->rn_a * p->rn_a + ib * p->rn_b * p->rn_b;
    double k22 = m + ia * q->rn_a * q->rn_a + ib * q->rn_b * q->rn_b;
    double k12 = m + ia * p->rn_a * q->rn_a + ib * p->rn_b * q->rn_b;
    double det = k11 * k22 - k12 * k12;
    CHECK(c->block);
    CHECK_NEAR(c->m11, k22 / det, 1e-12);
    CHECK_NEAR(c->m12, -k12 / det, 1e-12);
    CHECK_NEAR(c->m22, k11 / det, 1e-12);
}

static double normal_velocity(const solver_contact_t *c, const solver_point_t *p,
                              const solver_velocity_t *rows) {
    const solver_velocity_t *a = &rows[c->a], *b = &rows[c->b];
    return vec_dot(c->normal, vec_subtract(b->v, a->v)) + b->w * p->rn_b - a->w * p->rn_a;
}

/*
 * Eleven contacts on distinct pairs of bodies (three share the static
 * floor, row 0), of three kinds: two-point block solves, two points one at
 * a time (their points nearly coincide, too ill-conditioned to solve
 * together), and one point. They fill three batches, the last partly.
 * Each approaches at its own velocity. Because no two share a movable
 * body, a block or one-point contact must be solved exactly in one
 * iteration (the complementarity conditions hold to rounding), and every
 * body's velocity must have changed by exactly the impulses its contacts
 * report.
 */
static void batches_solve_isolated_contacts(void) {
    enum { CONTACTS = 11, BODIES = 2 * CONTACTS + 1 };
    solver_velocity_t rows[BODIES], before[BODIES];
    rows[0] = (solver_velocity_t){{0.0, 0.0}, 0.0, 0.0, 0.0};
    for (int i = 1; i < BODIES; i++) {
        rows[i] = (solver_velocity_t){{lcg_uniform() - 0.5, lcg_uniform() - 0.5},
                                      lcg_uniform() - 0.5, 0.5 + lcg_uniform(),
                                      2.0 + lcg_uniform()};
    }
    solver_contact_t contacts[CONTACTS];
    solver_anchor_t anchors[CONTACTS];
    double targets[CONTACTS][2];
    for (int i = 0; i < CONTACTS; i++) {
        solver_contact_t *c = &contacts[i];
        memset(c, 0, sizeof *c);
        c->a = i < 3 ? 0 : (uint32_t)(2 * i + 1);
        c->b = (uint32_t)(2 * i + 2);
        double angle = 2.0 * M_PI * lcg_uniform();
        c->normal = (vector_t){cos(angle), sin(angle)};
        c->friction = 0.6;
        /* Approaching: b moves against the normal. */
        rows[c->b].v = vec_add(rows[c->b].v, vec_multiply(-2.0, c->normal));
        vector_t tangent = {-c->normal.y, c->normal.x};
        int kind = i % 3; /* 0 block, 1 two points one by one, 2 one point */
        c->point_count = kind == 2 ? 1 : 2;
        for (int k = 0; k < c->point_count; k++) {
            double offset = k == 0 ? 0.4 : kind == 1 ? 0.3999 : -0.4;
            vector_t along = vec_multiply(offset, tangent);
            anchors[i].r_a[k] = vec_add(vec_multiply(0.5, c->normal), along);
            anchors[i].r_b[k] = vec_add(vec_multiply(-0.5, c->normal), along);
            /* Block contacts 3, 6 and 9 leave the second point, the first,
             * and both free to separate: each case of the block solve. */
            bool free = (k == 0 && (i == 6 || i == 9)) || (k == 1 && (i == 3 || i == 9));
            targets[i][k] = free ? -5.0 : k == 0 ? 0.0 : -0.3;
            c->points[k].separation = separation_for(targets[i][k]);
            c->points[k].id = (uint32_t)k;
            c->points[k].normal_impulse = 0.1 * k; /* a warm start */
        }
    }
    solver_wide_t wide = {0};
    prepared_t found = prepare_contacts(&wide, contacts, anchors, CONTACTS, rows, BODIES);
    CHECK(!found.impact && !found.elastic && !found.raised);
    CHECK(wide.loose_count == 0);
    for (int i = 0; i < CONTACTS; i++) {
        const solver_contact_t *c = &contacts[i];
        for (int k = 0; k < c->point_count; k++) {
            check_point(&c->points[k], anchors[i].r_a[k], anchors[i].r_b[k], c->normal,
                        &rows[c->a], &rows[c->b], targets[i][k]);
        }
        if (i % 3 == 0) check_block(c, &rows[c->a], &rows[c->b]);
        CHECK(c->block == (i % 3 == 0));
    }
    solver_wide_warm_start(&wide, rows);
    memcpy(before, rows, sizeof rows);
    solver_wide_iterate(&wide, rows, false);
    solver_wide_store(&wide, contacts);

    CHECK_VEC(rows[0].v, 0.0, 0.0, 0.0);
    CHECK(rows[0].w == 0.0);
    for (int i = 0; i < CONTACTS; i++) {
        const solver_contact_t *c = &contacts[i];
        vector_t tangent = {-c->normal.y, c->normal.x};
        vector_t impulse = {0.0, 0.0};
        double angular_a = 0.0, angular_b = 0.0;
        for (int k = 0; k < c->point_count; k++) {
            const solver_point_t *p = &c->points[k];
            /* Warm-start impulses are already in the velocities. */
            double applied = p->normal_impulse - 0.1 * k;
            impulse = vec_add(impulse, vec_add(vec_multiply(applied, c->normal),
                                               vec_multiply(p->tangent_impulse, tangent)));
            angular_a += applied * p->rn_a + p->tangent_impulse * p->rt_a;
            angular_b += applied * p->rn_b + p->tangent_impulse * p->rt_b;
            CHECK(p->normal_impulse >= 0.0);
            /* Friction saw the normal impulse before this iteration's. */
            CHECK(fabs(p->tangent_impulse) <= 0.6 * 0.1 * k + 1e-15);
            if (i % 3 != 1) {
                double gap = normal_velocity(c, p, rows) - p->target;
                CHECK(gap >= -1e-12);
                CHECK(fabs(p->normal_impulse * gap) < 1e-12);
            }
        }
        const solver_velocity_t *a = &rows[c->a], *b = &rows[c->b];
        const solver_velocity_t *a0 = &before[c->a], *b0 = &before[c->b];
        vector_t expect_b = vec_add(b0->v, vec_multiply(b0->inverse_mass, impulse));
        CHECK_VEC(b->v, expect_b.x, expect_b.y, 1e-12);
        CHECK_NEAR(b->w, b0->w + b0->inverse_inertia * angular_b, 1e-12);
        if (c->a != 0) {
            vector_t expect_a = vec_subtract(a0->v, vec_multiply(a0->inverse_mass, impulse));
            CHECK_VEC(a->v, expect_a.x, expect_a.y, 1e-12);
            CHECK_NEAR(a->w, a0->w - a0->inverse_inertia * angular_a, 1e-12);
        }
    }
    solver_wide_free(&wide);
}

/* Two-point contacts on a floor, one solved as a block and one a point
 * at a time (its points 3 cm apart, too ill-conditioned to solve
 * together), converge to the complementarity conditions when iterated. */
static void batches_converge_when_iterated(void) {
    solver_velocity_t rows[3] = {{{0.0, 0.0}, 0.0, 0.0, 0.0},
                                 {{0.3, -2.0}, 0.7, 1.0, 3.0},
                                 {{-0.2, -1.0}, -0.4, 0.5, 1.5}};
    solver_contact_t contacts[2];
    solver_anchor_t anchors[2];
    vector_t up = {0.0, 1.0}, tangent = {-1.0, 0.0};
    for (int i = 0; i < 2; i++) {
        solver_contact_t *c = &contacts[i];
        memset(c, 0, sizeof *c);
        c->a = 0;
        c->b = (uint32_t)i + 1;
        c->normal = up;
        c->friction = 0.6;
        c->point_count = 2;
        for (int k = 0; k < 2; k++) {
            double offset = k == 0 ? 0.5 : i == 0 ? -0.3 : 0.47;
            vector_t along = vec_multiply(offset, tangent);
            anchors[i].r_a[k] = along;
            anchors[i].r_b[k] = vec_add(along, (vector_t){0.0, -0.5});
            c->points[k].separation = separation_for(0.0);
            c->points[k].id = (uint32_t)k;
        }
    }
    solver_wide_t wide = {0};
    prepare_contacts(&wide, contacts, anchors, 2, rows, 3);
    CHECK(contacts[0].block && !contacts[1].block);
    /* The pair's rows differ by 3%: one by one, a slow sweep. */
    for (int iteration = 0; iteration < 20000; iteration++) {
        solver_wide_iterate(&wide, rows, false);
    }
    solver_wide_store(&wide, contacts);
    for (int i = 0; i < 2; i++) {
        for (int k = 0; k < 2; k++) {
            const solver_point_t *p = &contacts[i].points[k];
            double gap = normal_velocity(&contacts[i], p, rows) - p->target;
            CHECK(gap >= -1e-9);
            CHECK(fabs(p->normal_impulse * gap) < 1e-9);
            CHECK(fabs(p->tangent_impulse) <= 0.6 * p->normal_impulse + 1e-9);
        }
    }
    solver_wide_free(&wide);
}

/* The linearised separation of a point after the position pass moved the
 * bodies by displacements. */
static double moved_separation(const solver_contact_t *c, const solver_point_t *p,
                               const solver_displacement_t *moved) {
    const solver_displacement_t *a = &moved[c->a], *b = &moved[c->b];
    return p->separation + vec_dot(c->normal, vec_subtract(b->dx, a->dx)) +
           b->dtheta * p->rn_b - a->dtheta * p->rn_a;
}

/*
 * Five one-point contacts on distinct bodies, overlapping by different
 * amounts, one of them apart, with slops of their own, every other one
 * against a body that cannot move. One position iteration takes each
 * overlap beyond the contact's slop down by the contact's rate (the static
 * one against the immovable body), at most SOLVER_MAX_POSITION_CORRECTION,
 * and leaves the one apart alone, whichever way the batches are swept.
 */
static void batches_correct_overlaps_by_their_rate(void) {
    enum { CONTACTS = 5, BODIES = 2 * CONTACTS };
    const double overlaps[CONTACTS] = {0.01, 0.05, 0.5, 2.0, -0.1};
    for (int backward = 0; backward < 2; backward++) {
        solver_velocity_t rows[BODIES];
        solver_displacement_t moved[BODIES];
        solver_contact_t contacts[CONTACTS];
        solver_anchor_t anchors[CONTACTS];
        for (int i = 0; i < BODIES; i++) {
            rows[i] = (solver_velocity_t){{0.0, 0.0}, 0.0, 1.0 / (1.0 + i), 0.5 / (1.0 + i)};
            moved[i] = (solver_displacement_t){{0.01 * i, -0.02 * i}, 0.001 * i, 0.0};
        }
        /* Every other contact against a body that cannot move: the static rate. */
        for (int i = 1; i < CONTACTS; i += 2) {
            rows[2 * i] = (solver_velocity_t){{0.0, 0.0}, 0.0, 0.0, 0.0};
            moved[2 * i] = (solver_displacement_t){{0.0, 0.0}, 0.0, 0.0};
        }
        for (int i = 0; i < CONTACTS; i++) {
            solver_contact_t *c = &contacts[i];
            memset(c, 0, sizeof *c);
            c->a = (uint32_t)(2 * i);
            c->b = (uint32_t)(2 * i + 1);
            double angle = 1.0 + i;
            c->normal = (vector_t){cos(angle), sin(angle)};
            c->point_count = 1;
            c->slop = i < 2 ? SOLVER_LINEAR_SLOP : 0.0001 * i;
            anchors[i].r_a[0] = (vector_t){0.3, 0.1};
            anchors[i].r_b[0] = (vector_t){-0.2, 0.4};
            /* The separation at the start of the step, chosen so that the
             * pass sees the overlap the test names: the lever terms are
             * the ones preparing finds. */
            c->points[0].rn_a = vec_cross(anchors[i].r_a[0], c->normal);
            c->points[0].rn_b = vec_cross(anchors[i].r_b[0], c->normal);
            c->points[0].separation = -overlaps[i] - moved_separation(c, &c->points[0], moved);
        }
        solver_wide_t wide = {0};
        prepare_contacts(&wide, contacts, anchors, CONTACTS, rows, BODIES);
        solver_wide_correct_positions(&wide, moved, backward);
        for (int i = 0; i < CONTACTS; i++) {
            double before = -overlaps[i];
            double rate = i % 2 == 0 ? SOLVER_POSITION_RATE : SOLVER_STATIC_POSITION_RATE;
            CHECK(solver_position_rate(&rows[2 * i], &rows[2 * i + 1]) == rate);
            double wanted = rate * (before + contacts[i].slop);
            double removed = fmax(-SOLVER_MAX_POSITION_CORRECTION, fmin(wanted, 0.0));
            double after = moved_separation(&contacts[i], &contacts[i].points[0], moved);
            CHECK_NEAR(after, before - removed, 1e-12);
        }
        solver_wide_free(&wide);
    }
}

/* The steps' sweep orders follow the Thue-Morse sequence, so that steps
 * of a periodic pattern share both orders: over steps 0 .. 1023 each
 * residue class modulo 2 and 4 has as many reversed steps as not, and
 * modulo 3 (which evens out slowly) each has at least a quarter of each. */
static void sweeps_reverse_in_thue_morse_order(void) {
    static const bool first[16] = {0, 1, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1, 1, 0};
    for (uint64_t n = 0; n < 16; n++) CHECK(solver_sweeps_reversed(n) == first[n]);
    CHECK(solver_sweeps_reversed(UINT64_C(1) << 63));
    CHECK(!solver_sweeps_reversed(UINT64_MAX));
    for (int period = 2; period <= 4; period++) {
        for (int residue = 0; residue < period; residue++) {
            int reversed = 0, total = 0;
            for (uint64_t n = (uint64_t)residue; n < 1024; n += (uint64_t)period) {
                reversed += solver_sweeps_reversed(n);
                total++;
            }
            if (period == 3) {
                CHECK(4 * reversed >= total && 4 * (total - reversed) >= total);
            } else {
                CHECK(2 * reversed == total);
            }
        }
    }
}

/* Whether two doubles have the same bits (NAN included). */
static bool same_bits(double x, double y) {
    return memcmp(&x, &y, sizeof x) == 0;
}

/* Checks that preparing in the batches gave contact c what preparing it
 * alone gave `alone`, bit for bit. */
static void check_same_preparing(const solver_contact_t *c, const solver_contact_t *alone) {
    CHECK(c->block == alone->block && c->impact == alone->impact && c->rests == alone->rests);
    if (c->block) {
        CHECK(same_bits(c->m11, alone->m11) && same_bits(c->m12, alone->m12) &&
              same_bits(c->m22, alone->m22));
    }
    for (int k = 0; k < c->point_count; k++) {
        const solver_point_t *p = &c->points[k], *q = &alone->points[k];
        CHECK(same_bits(p->rn_a, q->rn_a) && same_bits(p->rn_b, q->rn_b));
        CHECK(same_bits(p->rt_a, q->rt_a) && same_bits(p->rt_b, q->rt_b));
        CHECK(same_bits(p->normal_mass, q->normal_mass));
        CHECK(same_bits(p->tangent_mass, q->tangent_mass));
        CHECK(same_bits(p->target, q->target));
        CHECK(same_bits(p->impact_time, q->impact_time));
        CHECK(same_bits(p->impact_offset, q->impact_offset));
        CHECK(p->touched == q->touched && p->lands == q->lands);
        CHECK(p->restitution_impulse == 0.0 && p->restitution_tangent_impulse == 0.0);
    }
}

/*
 * Random contacts of every kind, touching, apart, closing within the step
 * or not, elastic or not, between bodies in free motion (start velocity,
 * drift, pull): preparing them four at a time into the batches gives each
 * the bits preparing it alone gives (solver_prepare_contact), impacts,
 * raised targets and which body rests on which included, and the same
 * findings; and each lane holds its own contact's impulses.
 */
static void batches_prepare_as_one_contact_alone(void) {
    enum { CONTACTS = 400, BODIES = 31 };
    solver_velocity_t rows[BODIES];
    solver_state_t states[BODIES];
    solver_displacement_t displacements[BODIES];
    memset(states, 0, sizeof states);
    rows[0] = (solver_velocity_t){{0.0, 0.0}, 0.0, 0.0, 0.0};
    for (int i = 1; i < BODIES; i++) {
        rows[i] = (solver_velocity_t){{0.0, 0.0}, 0.0, 0.5 + lcg_uniform(), 1.0 + lcg_uniform()};
        solver_state_t *st = &states[i];
        st->v_start = (vector_t){4.0 * lcg_uniform() - 2.0, 4.0 * lcg_uniform() - 2.0};
        st->w_start = lcg_uniform() - 0.5;
        st->drift = (vector_t){0.1 * lcg_uniform(), -0.1 * lcg_uniform()};
        st->spin_drift = 0.01 * lcg_uniform();
        /* A few bodies in free fall, the rest pulled by gravity. */
        st->acceleration = i % 7 == 0 ? (vector_t){0.0, 0.0} : (vector_t){0.0, -9.81};
    }
    static solver_contact_t contacts[CONTACTS], alone[CONTACTS];
    static solver_anchor_t anchors[CONTACTS];
    for (int i = 0; i < CONTACTS; i++) {
        solver_contact_t *c = &contacts[i];
        memset(c, 0, sizeof *c);
        c->a = lcg_below(BODIES);
        do c->b = lcg_below(BODIES); while (c->b == c->a);
        double angle = 2.0 * M_PI * lcg_uniform();
        c->normal = (vector_t){cos(angle), sin(angle)};
        c->friction = 0.5;
        c->restitution = i % 5 == 0 ? 0.5 : 0.0;
        c->slop = 0.001;
        c->point_count = i % 3 == 2 ? 1 : 2;
        c->edge_ends = i % 11 == 0;
        vector_t tangent = {-c->normal.y, c->normal.x};
        for (int k = 0; k < c->point_count; k++) {
            /* Every fourth contact's points nearly coincide: no block. */
            double offset = k == 0 ? 0.4 : i % 4 == 0 ? 0.4 + 1e-5 : -0.3;
            vector_t along = vec_multiply(offset, tangent);
            anchors[i].r_a[k] = vec_add(vec_multiply(0.5, c->normal), along);
            anchors[i].r_b[k] = vec_add(vec_multiply(-0.5, c->normal), along);
            c->points[k].separation = 0.06 * lcg_uniform() - 0.02;
            c->points[k].normal_impulse = lcg_uniform();
            c->points[k].tangent_impulse = 0.2 * lcg_uniform() - 0.1;
        }
    }
    decide_blocks(contacts, anchors, CONTACTS, rows);
    memcpy(alone, contacts, sizeof contacts);
    solver_bodies_t bodies = {rows, displacements, states, BODIES};
    solver_settings_t settings = {.dt = DT, .position_weight = 0.5, .velocity_iterations = 8,
                                  .position_iterations = 3, .warm_starting = true,
                                  .restitution_threshold = 1.0};
    solver_wide_t wide = {0};
    prepared_t found =
        solver_split_prepare(&wide, contacts, anchors, CONTACTS, &bodies, &settings);
    prepared_t expected = {false, false, false};
    int impacts = 0, raised = 0, blocks = 0;
    for (int i = 0; i < CONTACTS; i++) {
        solver_contact_t *c = &alone[i];
        bool point_raised = false;
        expected.impact |=
            solver_prepare_contact(c, &anchors[i], &bodies, &settings, &point_raised);
        expected.raised |= point_raised;
        expected.elastic |= c->restitution > 0.0;
        impacts += c->impact;
        raised += point_raised;
        blocks += c->block;
        check_same_preparing(&contacts[i], c);
    }
    CHECK(found.impact == expected.impact && found.elastic == expected.elastic &&
          found.raised == expected.raised);
    /* Each case came up. */
    CHECK(impacts > 0 && raised > 0 && blocks > 0 && blocks < 2 * CONTACTS / 3);
    /* Stored back before any sweep, the lanes' impulses are the contacts' own. */
    solver_wide_store(&wide, contacts);
    for (int i = 0; i < CONTACTS; i++) {
        for (int k = 0; k < contacts[i].point_count; k++) {
            const solver_point_t *p = &contacts[i].points[k], *q = &alone[i].points[k];
            CHECK(same_bits(p->normal_impulse, q->normal_impulse));
            CHECK(same_bits(p->tangent_impulse, q->tangent_impulse));
        }
    }
    solver_wide_free(&wide);
}

TEST_SUITE(solver, TEST_CASE(coloring_separates_movable_bodies),
           TEST_CASE(sweeps_reverse_in_thue_morse_order),
           TEST_CASE(coloring_leaves_the_excess_uncoloured),
           TEST_CASE(batches_solve_isolated_contacts), TEST_CASE(batches_converge_when_iterated),
           TEST_CASE(batches_correct_overlaps_by_their_rate),
           TEST_CASE(batches_prepare_as_one_contact_alone));
