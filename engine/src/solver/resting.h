#ifndef RESTING_H
#define RESTING_H

/*
 * Which body of a touching contact rests on the other: decided once a step
 * by preparing (velocity_solve.c), where the contact and its bodies' rows
 * are at hand, and read by the lift (shock_lift, shock.h), which would
 * otherwise fetch every body's pull again. The upper body rests on the
 * lower when the normal from the lower to it points against its pull (its
 * free acceleration) within 60 degrees: a contact steeper than that holds
 * it sideways more than up. A body of infinite mass has no pull
 * (integrator.c), so it rests on nothing.
 */

#include <stdbool.h>
#include <stdint.h>
#include "solver/solver_types.h"

enum {
    RESTS_B_ON_A = 1, /* b rests on a */
    RESTS_A_ON_B = 2, /* a rests on b */
    RESTS_DEEP = 4    /* one of them rests, and a point overlaps past the contact's slop */
};

/* cos 60 degrees. */
static const double RESTING_COSINE = 0.5;

/* Whether the body pulled by `pull` rests on a contact whose normal, times
 * sign, points from the other body to it. */
static inline bool resting_on(vector_t normal, vector_t pull, double sign) {
    double along = sign * vec_dot(normal, pull);
    return along < 0.0 && along * along > RESTING_COSINE * RESTING_COSINE * vec_dot(pull, pull);
}

/* Contact c's RESTS_ bits (0 when no point touches), its bodies pulled by
 * pull_a and pull_b. */
static inline uint8_t resting_of(const solver_contact_t *c, vector_t pull_a, vector_t pull_b) {
    double least = c->points[0].separation;
    if (c->point_count == 2 && c->points[1].separation < least) least = c->points[1].separation;
    if (least > 0.0) return 0;
    unsigned rests = (resting_on(c->normal, pull_b, 1.0) ? RESTS_B_ON_A : 0u) |
                     (resting_on(c->normal, pull_a, -1.0) ? RESTS_A_ON_B : 0u);
    if (rests != 0 && least + c->slop < 0.0) rests |= RESTS_DEEP;
    return (uint8_t)rests;
}

#endif // #ifndef RESTING_H
