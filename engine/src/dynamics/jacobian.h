#ifndef JACOBIAN_H
#define JACOBIAN_H

/*
 * A force's derivatives, as the implicit scheme reads them
 * (implicit_euler.h): the forces.h creators that know theirs hand them over
 * (forces_jacobian), every other force is taken explicitly.
 *
 * A force between two bodies that depends on where and how fast body2 is
 * relative to body1 pushes body1, to first order about the start of the
 * step, by
 *     f1 = f1(start) + S d(x2 - x1) + C d(v2 - v1),
 * and body2 by -f1; with body2 NULL the force ties body1 to the world at rest
 * (x2 and v2 fixed at 0). S (N/m) and C (kg/s) must be symmetric positive
 * semidefinite, which the implicit scheme needs for its system to have one
 * solution: a force whose true derivative is not (a spring compressed below
 * its rest length, sideways) gives the nearest that is, and the difference
 * is taken explicitly.
 */

#include "jostle/body.h"
#include "jostle/vector.h"

/* A symmetric 2x2 matrix. */
typedef struct {
    double xx, xy, yy;
} sym2_t;

typedef struct {
    body_t *body1, *body2; /* body2 NULL: tied to the world */
    sym2_t stiffness;      /* S above, N/m */
    sym2_t damping;        /* C above, kg/s */
} force_jacobian_t;

/* S of a Hooke spring of constant k (N/m) and rest length L (m) whose
 * body2 is `between` (x2 - x1) from body1: k along the spring and k (1 -
 * L / d) across it, d = |between|, the latter clamped at 0 while d < L
 * (compressed: the true value is negative). k I for L = 0; 0 when the ends
 * coincide and L > 0 (the force has no direction there). */
sym2_t jacobian_spring_stiffness(double k, double rest_length, vector_t between);

#endif // #ifndef JACOBIAN_H
