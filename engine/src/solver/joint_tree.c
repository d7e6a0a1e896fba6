#include "solver/joint_tree.h"
#include <string.h>
#include "base/check.h"
#include "base/memory.h"

/* A pivot at most this share of its row's scale (ldl_factor) is taken for
 * zero: the row depends on the others before it, and takes no impulse. */
static const double JOINT_TREE_PIVOT = 1e-12;
/* A joint between two moving bodies whose child end cannot move along some
 * of its rows (its subtree is held by the world: the far half of a bridge
 * pinned at both ends) has a singular diagonal; one near that loses digits
 * when eliminated. At a pivot under this share its rows are kept and
 * solved with its parent body's block instead, as the body's world rows
 * are (exact either way; at 1e-8 random trees lost up to all digits). */
static const double JOINT_TREE_MERGE = 1e-3;

/* The rows a body's block holds: its world rows and the merged joints'. */
enum { MAX_BLOCK = 2 * JOINT_TREE_GROUND_ROWS };

/* A symmetric block factored as L D L^T, L unit lower triangular; a
 * dropped pivot has d^-1 = 0. */
typedef struct {
    int n;
    double l[MAX_BLOCK][MAX_BLOCK];
    double dinv[MAX_BLOCK];
} ldl_t;

struct joint_tree_node {
    uint32_t row;
    uint32_t parent_edge; /* toward the root, or JOINT_TREE_NONE for a root */
    uint32_t set;         /* union-find link, while the graph is taken */
    uint32_t adjacency_begin, adjacency_count;
    int ground_rows;   /* its world joints' rows, taken first */
    int held_rows;     /* and the merged joints', after them */
    double w[3];          /* inverse mass, inverse mass, inverse inertia */
    /* Factored: X (what the subtree below adds to M), (M + X)^-1, and the
     * body's inverse mass P under its world rows as well. */
    double x[3][3], wx[3][3], p[3][3];
    double jg[MAX_BLOCK][3], cg[MAX_BLOCK][MAX_BLOCK];
    ldl_t sw; /* the held rows' Jg (M + X)^-1 Jg^T + Cg */
    /* Solving: right-hand side and solution of the velocity and held rows. */
    double bv[3], bg[MAX_BLOCK], xv[3], xg[MAX_BLOCK];
};

struct joint_tree_edge {
    joint_tree_block_t block;
    uint32_t node1, node2;  /* JOINT_TREE_NONE on a ground end */
    /* The body whose block holds its rows (a world joint's, or a merged
     * one's), or JOINT_TREE_NONE; its first row there. */
    uint32_t holder;
    int offset;
    uint32_t parent;        /* between moving bodies: the end nearer the root */
    ldl_t s;                /* C + Jc P Jc^T, Jc the child end's rows */
    double rhs[JOINT_TREE_ROWS], b[JOINT_TREE_ROWS], x[JOINT_TREE_ROWS];
    double impulse[JOINT_TREE_ROWS];
};

/* ---- small dense blocks ---- */

/* Factors a, whose row j is measured by scale[j] (its diagonal before the
 * bodies below took their share: rounding leaves a diagonal that should be
 * zero at 1e-16 of that, not of itself). Returns the smallest pivot as a
 * share of its scale (0 for a dropped one). */
static double ldl_factor(ldl_t *f, int n, const double a[][MAX_BLOCK], const double *scale) {
    double d[MAX_BLOCK], smallest = 1.0;
    f->n = n;
    for (int j = 0; j < n; j++) {
        double dj = a[j][j];
        for (int k = 0; k < j; k++) dj -= f->l[j][k] * f->l[j][k] * d[k];
        bool kept = scale[j] > 0.0 && dj > JOINT_TREE_PIVOT * scale[j];
        d[j] = kept ? dj : 0.0;
        f->dinv[j] = kept ? 1.0 / dj : 0.0;
        double share = kept ? dj / scale[j] : 0.0;
        smallest = share < smallest ? share : smallest;
        f->l[j][j] = 1.0;
        for (int i = j + 1; i < n; i++) {
            double s = a[i][j];
            for (int k = 0; k < j; k++) s -= f->l[i][k] * f->l[j][k] * d[k];
            f->l[i][j] = s * f->dinv[j];
        }
    }
    return smallest;
}

/* x = (L D L^T)^+ b (x may be b). */
static void ldl_solve(const ldl_t *f, const double *b, double *x) {
    double y[MAX_BLOCK];
    int n = f->n;
    for (int i = 0; i < n; i++) {
        double s = b[i];
        for (int k = 0; k < i; k++) s -= f->l[i][k] * y[k];
        y[i] = s;
    }
    for (int i = 0; i < n; i++) y[i] *= f->dinv[i];
    for (int i = n - 1; i >= 0; i--) {
        double s = y[i];
        for (int k = i + 1; k < n; k++) s -= f->l[k][i] * x[k];
        x[i] = s;
    }
}

/* (M + X)^-1 = W (I + X W)^-1, which holds for a W with zeros (a body that
 * cannot turn) where M does not exist. I + X W is invertible: the
 * eigenvalues of X W are >= 0. */
static void inverse_mass_under(joint_tree_node_t *node) {
    double a[3][3], c[3][3];
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) a[r][k] = (r == k ? 1.0 : 0.0) + node->x[r][k] * node->w[k];
    }
    c[0][0] = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    c[0][1] = a[0][2] * a[2][1] - a[0][1] * a[2][2];
    c[0][2] = a[0][1] * a[1][2] - a[0][2] * a[1][1];
    c[1][0] = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    c[1][1] = a[0][0] * a[2][2] - a[0][2] * a[2][0];
    c[1][2] = a[0][2] * a[1][0] - a[0][0] * a[1][2];
    c[2][0] = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    c[2][1] = a[0][1] * a[2][0] - a[0][0] * a[2][1];
    c[2][2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    double inv = 1.0 / (a[0][0] * c[0][0] + a[0][1] * c[1][0] + a[0][2] * c[2][0]);
    double m[3][3];
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) m[r][k] = node->w[r] * c[r][k] * inv;
    }
    for (int r = 0; r < 3; r++) {
        for (int k = 0; k < 3; k++) node->wx[r][k] = 0.5 * (m[r][k] + m[k][r]);
    }
}

static void mul33(const double m[3][3], const double v[3], double out[3]) {
    for (int r = 0; r < 3; r++) out[r] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2];
}

static double dot3(const double a[3], const double b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/* Row j's size on a body of inverse masses w, with compliance c. */
static double row_scale(const double w[3], const double j[3], double c) {
    return w[0] * (j[0] * j[0] + j[1] * j[1]) + w[2] * j[2] * j[2] + c;
}

/* The rows of an edge on one of its nodes' velocities. */
static const double (*rows_on(const joint_tree_edge_t *edge, uint32_t node))[3] {
    return edge->node1 == node ? edge->block.j1 : edge->block.j2;
}

static uint32_t other_end(const joint_tree_edge_t *edge, uint32_t node) {
    return edge->node1 == node ? edge->node2 : edge->node1;
}

/* ---- taking the graph ---- */

void joint_tree_reset(joint_tree_t *tree, size_t row_count) {
    for (size_t i = 0; i < tree->node_count; i++) {
        tree->node_of_row[tree->nodes[i].row] = JOINT_TREE_NONE;
    }
    if (tree->row_capacity < row_count) {
        size_t old = tree->row_capacity;
        memory_reserve((void **)&tree->node_of_row, &tree->row_capacity, row_count,
                       sizeof(uint32_t));
        for (size_t i = old; i < tree->row_capacity; i++) tree->node_of_row[i] = JOINT_TREE_NONE;
    }
    tree->node_count = tree->edge_count = 0;
    tree->ordered = false;
}

static uint32_t find_set(joint_tree_t *tree, uint32_t node) {
    while (tree->nodes[node].set != node) {
        uint32_t up = tree->nodes[node].set;
        tree->nodes[node].set = tree->nodes[up].set;
        node = up;
    }
    return node;
}

static uint32_t node_for(joint_tree_t *tree, uint32_t row) {
    uint32_t index = tree->node_of_row[row];
    if (index != JOINT_TREE_NONE) return index;
    memory_reserve((void **)&tree->nodes, &tree->node_capacity, tree->node_count + 1,
                   sizeof(joint_tree_node_t));
    index = (uint32_t)tree->node_count++;
    joint_tree_node_t *node = &tree->nodes[index];
    node->row = row;
    node->set = index;
    node->ground_rows = 0;
    node->held_rows = MAX_BLOCK; /* its Cg is unknown: cleared whole at the first factor */
    tree->node_of_row[row] = index;
    return index;
}

static int ground_rows_of(const joint_tree_t *tree, uint32_t row) {
    uint32_t index = tree->node_of_row[row];
    return index == JOINT_TREE_NONE ? 0 : tree->nodes[index].ground_rows;
}

uint32_t joint_tree_add(joint_tree_t *tree, const joint_tree_block_t *block) {
    REQUIRE(block->rows >= 1 && block->rows <= JOINT_TREE_ROWS, "a block of %d rows",
            block->rows);
    bool ground1 = block->row1 == JOINT_TREE_GROUND, ground2 = block->row2 == JOINT_TREE_GROUND;
    REQUIRE(!(ground1 && ground2), "both ends of a joint are ground");
    REQUIRE((ground1 || block->row1 < tree->row_capacity) &&
                (ground2 || block->row2 < tree->row_capacity),
            "a row beyond the step's rows");
    uint32_t node1 = JOINT_TREE_NONE, node2 = JOINT_TREE_NONE;
    int offset = 0;
    if (ground1 || ground2) {
        uint32_t row = ground1 ? block->row2 : block->row1;
        offset = ground_rows_of(tree, row);
        if (offset + block->rows > JOINT_TREE_GROUND_ROWS) return JOINT_TREE_NONE;
        uint32_t node = node_for(tree, row);
        tree->nodes[node].ground_rows += block->rows;
        if (ground1) {
            node2 = node;
        } else {
            node1 = node;
        }
    } else {
        uint32_t a = tree->node_of_row[block->row1], b = tree->node_of_row[block->row2];
        if (a != JOINT_TREE_NONE && b != JOINT_TREE_NONE && find_set(tree, a) == find_set(tree, b)) {
            return JOINT_TREE_NONE;
        }
        node1 = node_for(tree, block->row1);
        node2 = node_for(tree, block->row2);
        tree->nodes[find_set(tree, node1)].set = find_set(tree, node2);
    }
    memory_reserve((void **)&tree->edges, &tree->edge_capacity, tree->edge_count + 1,
                   sizeof(joint_tree_edge_t));
    uint32_t index = (uint32_t)tree->edge_count++;
    joint_tree_edge_t *edge = &tree->edges[index];
    edge->block = *block;
    edge->node1 = node1;
    edge->node2 = node2;
    edge->holder = ground1 ? node2 : (ground2 ? node1 : JOINT_TREE_NONE);
    edge->offset = offset;
    edge->parent = JOINT_TREE_NONE;
    tree->ordered = false;
    return index;
}

/* ---- ordering ---- */

static bool between_bodies(const joint_tree_edge_t *edge) {
    return edge->node1 != JOINT_TREE_NONE && edge->node2 != JOINT_TREE_NONE;
}

static void build_adjacency(joint_tree_t *tree) {
    for (size_t i = 0; i < tree->node_count; i++) tree->nodes[i].adjacency_count = 0;
    size_t total = 0;
    for (size_t e = 0; e < tree->edge_count; e++) {
        const joint_tree_edge_t *edge = &tree->edges[e];
        if (!between_bodies(edge)) continue;
        tree->nodes[edge->node1].adjacency_count++;
        tree->nodes[edge->node2].adjacency_count++;
        total += 2;
    }
    memory_reserve((void **)&tree->adjacency, &tree->adjacency_capacity, total,
                   sizeof(uint32_t));
    uint32_t begin = 0;
    for (size_t i = 0; i < tree->node_count; i++) {
        tree->nodes[i].adjacency_begin = begin;
        begin += tree->nodes[i].adjacency_count;
        tree->nodes[i].adjacency_count = 0;
    }
    for (size_t e = 0; e < tree->edge_count; e++) {
        const joint_tree_edge_t *edge = &tree->edges[e];
        if (!between_bodies(edge)) continue;
        uint32_t ends[2] = {edge->node1, edge->node2};
        for (int k = 0; k < 2; k++) {
            joint_tree_node_t *node = &tree->nodes[ends[k]];
            tree->adjacency[node->adjacency_begin + node->adjacency_count++] = (uint32_t)e;
        }
    }
}

/* Breadth first from each tree's first node: parents before children. */
static void order_nodes(joint_tree_t *tree) {
    memory_reserve((void **)&tree->order, &tree->order_capacity, tree->node_count,
                   sizeof(uint32_t));
    for (size_t i = 0; i < tree->node_count; i++) tree->nodes[i].set = JOINT_TREE_NONE;
    size_t count = 0;
    for (size_t root = 0; root < tree->node_count; root++) {
        if (tree->nodes[root].set != JOINT_TREE_NONE) continue;
        tree->nodes[root].set = 0; /* reached */
        tree->nodes[root].parent_edge = JOINT_TREE_NONE;
        tree->order[count++] = (uint32_t)root;
        for (size_t next = count - 1; next < count; next++) {
            uint32_t n = tree->order[next];
            const joint_tree_node_t *node = &tree->nodes[n];
            for (uint32_t k = 0; k < node->adjacency_count; k++) {
                uint32_t e = tree->adjacency[node->adjacency_begin + k];
                if (e == node->parent_edge) continue;
                uint32_t child = other_end(&tree->edges[e], n);
                tree->edges[e].parent = n;
                tree->nodes[child].parent_edge = e;
                tree->nodes[child].set = 0;
                tree->order[count++] = child;
            }
        }
    }
}

/* ---- factoring ---- */

static void hold_rows(joint_tree_node_t *node, int at, int rows, const double (*j)[3],
                      const double (*c)[MAX_BLOCK], const double (*block_c)[JOINT_TREE_ROWS]) {
    for (int i = 0; i < rows; i++) {
        memcpy(node->jg[at + i], j[i], sizeof node->jg[at + i]);
        for (int k = 0; k < rows; k++) {
            node->cg[at + i][at + k] = c != NULL ? c[i][k] : block_c[i][k];
        }
    }
}

/* The world rows of every body: Jg and Cg, in one pass over the edges. */
static void take_ground_rows(joint_tree_t *tree) {
    for (size_t e = 0; e < tree->edge_count; e++) {
        joint_tree_edge_t *edge = &tree->edges[e];
        if (between_bodies(edge)) {
            edge->holder = JOINT_TREE_NONE;
            continue;
        }
        joint_tree_node_t *node = &tree->nodes[edge->holder];
        hold_rows(node, edge->offset, edge->block.rows, rows_on(edge, edge->holder), NULL,
                  edge->block.c);
    }
}

static void factor_node(joint_tree_t *tree, uint32_t n) {
    joint_tree_node_t *node = &tree->nodes[n];
    inverse_mass_under(node);
    memcpy(node->p, node->wx, sizeof node->p);
    int g = node->held_rows;
    if (g == 0) return;
    double s[MAX_BLOCK][MAX_BLOCK], gw[MAX_BLOCK][3];
    for (int i = 0; i < g; i++) mul33(node->wx, node->jg[i], gw[i]); /* rows of Jg Wx */
    double scale[MAX_BLOCK];
    for (int i = 0; i < g; i++) {
        for (int k = 0; k < g; k++) s[i][k] = dot3(gw[i], node->jg[k]) + node->cg[i][k];
        scale[i] = row_scale(node->w, node->jg[i], node->cg[i][i]);
    }
    ldl_factor(&node->sw, g, s, scale);
    /* P = Wx - (Jg Wx)^T Sw^+ (Jg Wx) */
    for (int c = 0; c < 3; c++) {
        double column[MAX_BLOCK], h[MAX_BLOCK];
        for (int i = 0; i < g; i++) column[i] = gw[i][c];
        ldl_solve(&node->sw, column, h);
        for (int r = 0; r < 3; r++) {
            for (int i = 0; i < g; i++) node->p[r][c] -= gw[i][r] * h[i];
        }
    }
}

/* Eliminates the edge above node n into its parent's X. */
static void factor_edge(joint_tree_t *tree, uint32_t n) {
    const joint_tree_node_t *node = &tree->nodes[n];
    joint_tree_edge_t *edge = &tree->edges[node->parent_edge];
    int m = edge->block.rows;
    const double(*jc)[3] = rows_on(edge, n);
    const double(*jp)[3] = rows_on(edge, edge->parent);
    double s[MAX_BLOCK][MAX_BLOCK], scale[JOINT_TREE_ROWS];
    for (int i = 0; i < m; i++) {
        double pj[3];
        mul33(node->p, jc[i], pj);
        for (int k = 0; k < m; k++) s[i][k] = dot3(jc[k], pj) + edge->block.c[i][k];
        scale[i] = row_scale(node->w, jc[i], edge->block.c[i][i]);
    }
    double smallest = ldl_factor(&edge->s, m, s, scale);
    joint_tree_node_t *parent = &tree->nodes[edge->parent];
    if (smallest < JOINT_TREE_MERGE && parent->held_rows + m <= MAX_BLOCK) {
        edge->holder = edge->parent;
        edge->offset = parent->held_rows;
        hold_rows(parent, edge->offset, m, jp, s, NULL);
        parent->held_rows += m;
        return;
    }
    for (int c = 0; c < 3; c++) {
        double column[JOINT_TREE_ROWS], h[JOINT_TREE_ROWS];
        for (int i = 0; i < m; i++) column[i] = jp[i][c];
        ldl_solve(&edge->s, column, h);
        for (int r = 0; r < 3; r++) {
            for (int i = 0; i < m; i++) parent->x[r][c] += jp[i][r] * h[i];
        }
    }
}

void joint_tree_factor(joint_tree_t *tree, const solver_velocity_t *velocities) {
    if (!tree->ordered) {
        build_adjacency(tree);
        order_nodes(tree);
        tree->ordered = true;
    }
    for (size_t i = 0; i < tree->node_count; i++) {
        joint_tree_node_t *node = &tree->nodes[i];
        const solver_velocity_t *row = &velocities[node->row];
        node->w[0] = node->w[1] = row->inverse_mass;
        node->w[2] = row->inverse_inertia;
        /* Only the rows held last time can be nonzero (hold_rows writes no other). */
        memset(node->cg, 0, sizeof node->cg[0] * (size_t)node->held_rows);
        node->held_rows = node->ground_rows;
        memset(node->x, 0, sizeof node->x);
    }
    take_ground_rows(tree);
    for (size_t k = tree->node_count; k-- > 0;) {
        uint32_t n = tree->order[k];
        factor_node(tree, n);
        if (tree->nodes[n].parent_edge != JOINT_TREE_NONE) factor_edge(tree, n);
    }
}

/* ---- solving ---- */

/* (xv, xg) = D^-1 (bv, bg) for the body's block [[M + X, Jg^T], [Jg, -Cg]]. */
static void node_apply_inverse(joint_tree_node_t *node, const double bv[3]) {
    int g = node->held_rows;
    if (g == 0) {
        mul33(node->wx, bv, node->xv);
        return;
    }
    double wb[3], t[MAX_BLOCK], u[3];
    mul33(node->wx, bv, wb);
    for (int i = 0; i < g; i++) t[i] = dot3(node->jg[i], wb) - node->bg[i];
    ldl_solve(&node->sw, t, node->xg);
    for (int r = 0; r < 3; r++) {
        u[r] = bv[r];
        for (int i = 0; i < g; i++) u[r] -= node->jg[i][r] * node->xg[i];
    }
    mul33(node->wx, u, node->xv);
}

const joint_tree_block_t *joint_tree_block(const joint_tree_t *tree, uint32_t edge) {
    return &tree->edges[edge].block;
}

joint_tree_block_t *joint_tree_rows(joint_tree_t *tree, uint32_t edge) {
    return &tree->edges[edge].block;
}

double *joint_tree_rhs(joint_tree_t *tree, uint32_t edge) {
    return tree->edges[edge].rhs;
}

static void load_rhs(joint_tree_t *tree) {
    for (size_t i = 0; i < tree->node_count; i++) {
        memset(tree->nodes[i].bv, 0, sizeof tree->nodes[i].bv);
    }
    for (size_t e = 0; e < tree->edge_count; e++) {
        joint_tree_edge_t *edge = &tree->edges[e];
        if (between_bodies(edge)) {
            memcpy(edge->b, edge->rhs, sizeof edge->b);
            continue;
        }
        joint_tree_node_t *node = &tree->nodes[edge->holder];
        for (int i = 0; i < edge->block.rows; i++) node->bg[edge->offset + i] = edge->rhs[i];
    }
}

/* Leaves first: each node's solution with what is below it, handed up. */
static void eliminate(joint_tree_t *tree) {
    for (size_t k = tree->node_count; k-- > 0;) {
        uint32_t n = tree->order[k];
        joint_tree_node_t *node = &tree->nodes[n];
        if (node->parent_edge == JOINT_TREE_NONE) continue;
        joint_tree_edge_t *edge = &tree->edges[node->parent_edge];
        node_apply_inverse(node, node->bv);
        int m = edge->block.rows;
        const double(*jc)[3] = rows_on(edge, n);
        const double(*jp)[3] = rows_on(edge, edge->parent);
        for (int i = 0; i < m; i++) edge->b[i] -= dot3(jc[i], node->xv);
        joint_tree_node_t *parent = &tree->nodes[edge->parent];
        if (edge->holder != JOINT_TREE_NONE) { /* merged: solved with the parent */
            for (int i = 0; i < m; i++) parent->bg[edge->offset + i] = edge->b[i];
            continue;
        }
        double h[JOINT_TREE_ROWS];
        ldl_solve(&edge->s, edge->b, h);
        for (int r = 0; r < 3; r++) {
            for (int i = 0; i < m; i++) parent->bv[r] += jp[i][r] * h[i];
        }
    }
}

/* Roots first: each node's solution from its parent's. */
static void substitute(joint_tree_t *tree) {
    for (size_t k = 0; k < tree->node_count; k++) {
        uint32_t n = tree->order[k];
        joint_tree_node_t *node = &tree->nodes[n];
        if (node->parent_edge == JOINT_TREE_NONE) {
            node_apply_inverse(node, node->bv);
            continue;
        }
        joint_tree_edge_t *edge = &tree->edges[node->parent_edge];
        int m = edge->block.rows;
        const double(*jc)[3] = rows_on(edge, n);
        const double(*jp)[3] = rows_on(edge, edge->parent);
        const joint_tree_node_t *parent = &tree->nodes[edge->parent];
        if (edge->holder != JOINT_TREE_NONE) {
            memcpy(edge->x, parent->xg + edge->offset, sizeof(double) * (size_t)m);
        } else {
            double t[JOINT_TREE_ROWS];
            for (int i = 0; i < m; i++) t[i] = edge->b[i] - dot3(jp[i], parent->xv);
            ldl_solve(&edge->s, t, edge->x);
            for (int i = 0; i < m; i++) edge->x[i] = -edge->x[i];
        }
        double bv[3];
        for (int r = 0; r < 3; r++) {
            bv[r] = node->bv[r];
            for (int i = 0; i < m; i++) bv[r] -= jc[i][r] * edge->x[i];
        }
        node_apply_inverse(node, bv);
    }
}

void joint_tree_solve(joint_tree_t *tree) {
    load_rhs(tree);
    eliminate(tree);
    substitute(tree);
    for (size_t e = 0; e < tree->edge_count; e++) {
        joint_tree_edge_t *edge = &tree->edges[e];
        const double *x = edge->x;
        if (!between_bodies(edge)) x = tree->nodes[edge->holder].xg + edge->offset;
        for (int i = 0; i < edge->block.rows; i++) edge->impulse[i] = -x[i];
    }
}

const double *joint_tree_impulse(const joint_tree_t *tree, uint32_t edge) {
    return tree->edges[edge].impulse;
}

size_t joint_tree_body_count(const joint_tree_t *tree) {
    return tree->node_count;
}

uint32_t joint_tree_body_row(const joint_tree_t *tree, size_t body) {
    return tree->nodes[body].row;
}

const double *joint_tree_body_change(const joint_tree_t *tree, size_t body) {
    return tree->nodes[body].xv;
}

void joint_tree_free(joint_tree_t *tree) {
    memory_free(tree->nodes);
    memory_free(tree->edges);
    memory_free(tree->node_of_row);
    memory_free(tree->order);
    memory_free(tree->adjacency);
    *tree = (joint_tree_t){0};
}

