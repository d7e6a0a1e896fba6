#ifndef SPRING_SYSTEM_H
#define SPRING_SYSTEM_H

/*
 * The linear system of bodies joined by springs, as implicit Euler meets it
 * (implicit_euler.h): n unknowns x_i, each a 2-vector (a body's velocity
 * change), and
 *     A = block diag(D_i) + sum over edges e = (a, b) of W_e on (x_a - x_b),
 * i.e. (A x)_a = D_a x_a + sum_e W_e (x_a - x_b), (A x)_b gets the opposite
 * share; D_i symmetric positive definite (a mass, plus what ties the body
 * to the world), W_e symmetric positive semidefinite. A is then symmetric
 * positive definite and A x = b has one solution.
 *
 * The solve is direct along a spanning forest of the edges (the stiffest
 * edges first): eliminating leaves toward the roots fills in nothing, so a
 * chain or any tree of springs is solved exactly in O(n + edges). The edges
 * off the forest (closed loops) are left to conjugate gradients with that
 * forest as preconditioner: A differs from it by a matrix of rank at most
 * twice their number, so it converges in at most 2 (loops) + 1 iterations
 * in exact arithmetic. Memory O(n + edges); the storage is kept from one
 * solve to the next, so a warm system allocates nothing. Results depend
 * only on the order of nodes and edges (one thread, a fixed order).
 */

#include <stddef.h>
#include "dynamics/jacobian.h"
#include "jostle/vector.h"

typedef struct spring_system spring_system_t;

void spring_system_free(spring_system_t *system);

/* Starts a system of `nodes` unknowns, every D_i and b_i 0, with room for
 * `edges` edges; makes or grows *system. */
void spring_system_begin(spring_system_t **system, size_t nodes, size_t edges);

/* D_node += block; b_node += rhs. */
void spring_system_add_diagonal(spring_system_t *system, size_t node, sym2_t block);
void spring_system_add_rhs(spring_system_t *system, size_t node, vector_t rhs);

/* An edge of weight W between distinct nodes a and b. */
void spring_system_add_edge(spring_system_t *system, size_t a, size_t b, sym2_t weight);

/* Solves A x = b into x (one vector per node); returns the number of
 * conjugate-gradient iterations it took (0 for a forest). */
size_t spring_system_solve(spring_system_t *system, vector_t *x);

/* After a solve: A x = b for a new b (every b_i set to 0, then
 * spring_system_add_rhs), with the same A and its factorisation. */
void spring_system_clear_rhs(spring_system_t *system);
size_t spring_system_solve_again(spring_system_t *system, vector_t *x);

/* After a solve: the diagonal blocks of P^-1, P the forest's part of A (D
 * and the forest's edges): those of A^-1 when the edges form a forest,
 * larger (in the order of matrices) where loops close. O(n). */
void spring_system_inverse_diagonal(const spring_system_t *system, sym2_t *diagonal);

#endif // #ifndef SPRING_SYSTEM_H
