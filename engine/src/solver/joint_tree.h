#ifndef JOINT_TREE_H
#define JOINT_TREE_H

/*
 * An exact solve of the joints' rigid equality rows over the joint graph,
 * in time linear in the bodies and joints (after Baraff, "Linear-Time
 * Dynamics using Lagrange Multipliers", 1996).
 *
 * The nodes are the step's bodies that move (inverse masses from their
 * solver rows) and the joints (blocks of 1 to 3 rows). A body's world or
 * static joints hang off it: the world and static bodies are no nodes, so
 * a bridge pinned at both ends is a tree. For each tree, rooted at a body,
 * the sparse symmetric matrix [[M, J^T], [J, -C]] is factored leaves first
 * without fill-in: a joint between two moving bodies is eliminated as its
 * own node, and a body together with its world joints as one block (a
 * world joint has a zero diagonal, so it cannot be a leaf of its own).
 * A solve then gives the impulses dl of
 *
 *     (J M^-1 J^T + C) dl = rhs,
 *
 * for every row of every joint at once, and the bodies' velocity (or
 * displacement) changes M^-1 J^T dl. Rows that depend on others (two pins
 * of one body at one point, a weld between bodies that cannot turn) get
 * a least-norm share: a pivot under JOINT_TREE_PIVOT of its diagonal is
 * dropped, and its row takes no impulse.
 *
 * A joint that would close a cycle among the moving bodies, or add more
 * than JOINT_TREE_GROUND_ROWS world rows to one body, is refused
 * (joint_tree_add gives JOINT_TREE_NONE): the caller solves it otherwise.
 * The tree owns its arrays and reuses them: once warm, a step of the same
 * joints allocates nothing. Everything runs on the calling thread in a
 * fixed order (the joints' order of joint_tree_add), so results are the
 * same bits each run.
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "solver/solver_types.h"

#define JOINT_TREE_NONE UINT32_MAX
/* The row of a joint's end that is the world or a static body. */
#define JOINT_TREE_GROUND UINT32_MAX
enum { JOINT_TREE_ROWS = 3, JOINT_TREE_GROUND_ROWS = 6 };

/* A joint's rows: for row i, its terms on body1's and body2's velocity
 * (vx, vy, w), and the rows' compliance C (symmetric, >= 0; all zero for
 * rigid rows). row1, row2 are the bodies' solver rows, or
 * JOINT_TREE_GROUND; at most one end is ground. */
typedef struct {
    uint32_t row1, row2;
    int rows;
    double j1[JOINT_TREE_ROWS][3], j2[JOINT_TREE_ROWS][3];
    double c[JOINT_TREE_ROWS][JOINT_TREE_ROWS];
} joint_tree_block_t;

typedef struct joint_tree_node joint_tree_node_t;
typedef struct joint_tree_edge joint_tree_edge_t;

typedef struct {
    joint_tree_node_t *nodes;
    joint_tree_edge_t *edges;
    uint32_t *node_of_row; /* per solver row: its node, or JOINT_TREE_NONE */
    uint32_t *order;       /* nodes, every parent before its children */
    uint32_t *adjacency;   /* per node, its edges between moving bodies */
    size_t node_count, edge_count;
    bool ordered; /* the order is the graph's */
    size_t node_capacity, edge_capacity, row_capacity, order_capacity, adjacency_capacity;
} joint_tree_t;

/* Starts a step's graph over solver rows [0, row_count). */
void joint_tree_reset(joint_tree_t *tree, size_t row_count);
/* Takes a joint's rows: gives its edge (0, 1, ... in the order taken) or
 * JOINT_TREE_NONE when it would close a cycle or overload a body's world
 * rows. Asserts 1 <= rows <= JOINT_TREE_ROWS and rows below row_count. */
uint32_t joint_tree_add(joint_tree_t *tree, const joint_tree_block_t *block);
/* Factors the matrix for the blocks' rows and the inverse masses of the
 * solver rows (velocities[row].inverse_mass, inverse_inertia); orders the
 * trees first when the graph has changed since the last call. */
void joint_tree_factor(joint_tree_t *tree, const solver_velocity_t *velocities);
/* An edge's block as taken; and its rows, to change them before factoring
 * again (the graph stays). */
const joint_tree_block_t *joint_tree_block(const joint_tree_t *tree, uint32_t edge);
joint_tree_block_t *joint_tree_rows(joint_tree_t *tree, uint32_t edge);
/* The right-hand side of an edge's rows (set before joint_tree_solve). */
double *joint_tree_rhs(joint_tree_t *tree, uint32_t edge);
/* Solves for the right-hand sides; then the impulses of an edge's rows and
 * each body's change (vx, vy, w) are read below. */
void joint_tree_solve(joint_tree_t *tree);
const double *joint_tree_impulse(const joint_tree_t *tree, uint32_t edge);
size_t joint_tree_body_count(const joint_tree_t *tree);
uint32_t joint_tree_body_row(const joint_tree_t *tree, size_t body);
const double *joint_tree_body_change(const joint_tree_t *tree, size_t body);
void joint_tree_free(joint_tree_t *tree);

#endif // #ifndef JOINT_TREE_H
