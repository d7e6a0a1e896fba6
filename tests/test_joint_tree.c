/* The joints' tree solve (solver/joint_tree.h) against a dense solve of
 * the same system: random trees of 2 to 50 bodies joined by the row blocks
 * of every joint type the tree takes, some soft, some pinned to the world;
 * and the refusals (a cycle, too many world rows on one body). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "solver/joint_tree.h"
#include "test.h"

static uint32_t lcg_state = 2718281u;

static double uniform(double lo, double hi) {
    lcg_state = (uint32_t)((1103515245ull * lcg_state + 12345ull) % 2147483648ull);
    return lo + (hi - lo) * (lcg_state / 2147483648.0);
}

static uint32_t below(uint32_t n) {
    return (uint32_t)uniform(0.0, (double)n) % n;
}

/* Row i of a block: terms on body1 (negated) and body2 of a relative
 * velocity along direction u with lever arms r1, r2 (a point or line row),
 * or of the relative spin (an angle row). */
static void line_row(joint_tree_block_t *block, int i, double ux, double uy, double a1,
                     double a2) {
    double j1[3] = {-ux, -uy, -a1}, j2[3] = {ux, uy, a2};
    memcpy(block->j1[i], j1, sizeof j1);
    memcpy(block->j2[i], j2, sizeof j2);
}

static void angle_row(joint_tree_block_t *block, int i) {
    line_row(block, i, 0.0, 0.0, 1.0, 1.0);
}

/* A random joint of a random type between rows row1 and row2: revolute
 * (2 point rows), weld (3), prismatic (perpendicular and angle), wheel
 * (perpendicular), rod (1); soft with probability 1/4. */
static joint_tree_block_t random_block(uint32_t row1, uint32_t row2, int max_rows) {
    joint_tree_block_t block;
    memset(&block, 0, sizeof block);
    block.row1 = row1;
    block.row2 = row2;
    double r1x = uniform(-1, 1), r1y = uniform(-1, 1), r2x = uniform(-1, 1), r2y = uniform(-1, 1);
    double angle = uniform(0, 2 * M_PI), ux = cos(angle), uy = sin(angle);
    int type = (int)below(5);
    if (type == 1 && max_rows < 3) type = 0;
    if (type <= 2 && max_rows < 2) type = 3;
    switch (type) {
    case 0: /* revolute: x and y of the point */
    case 1: /* weld: and the angle */
        line_row(&block, 0, 1.0, 0.0, -r1y, -r2y);
        line_row(&block, 1, 0.0, 1.0, r1x, r2x);
        block.rows = 2;
        if (type == 1) angle_row(&block, block.rows++);
        break;
    case 2: /* prismatic: across the axis, and the angle */
        line_row(&block, 0, -uy, ux, r1x * ux + r1y * uy, r2x * ux + r2y * uy);
        angle_row(&block, 1);
        block.rows = 2;
        break;
    default: /* wheel (across an axis) or rod (along the anchors' line) */
        line_row(&block, 0, ux, uy, r1x * uy - r1y * ux, r2x * uy - r2y * ux);
        block.rows = 1;
        break;
    }
    if (below(4) == 0) {
        for (int i = 0; i < block.rows; i++) block.c[i][i] = uniform(0.01, 0.5);
    }
    return block;
}

/* Gaussian elimination with partial pivoting: a x = b, a n x n, in place. */
static void dense_solve(double *a, double *b, int n) {
    for (int col = 0; col < n; col++) {
        int pivot = col;
        for (int r = col + 1; r < n; r++) {
            if (fabs(a[r * n + col]) > fabs(a[pivot * n + col])) pivot = r;
        }
        for (int k = 0; k < n; k++) {
            double t = a[col * n + k];
            a[col * n + k] = a[pivot * n + k];
            a[pivot * n + k] = t;
        }
        double t = b[col];
        b[col] = b[pivot];
        b[pivot] = t;
        for (int r = col + 1; r < n; r++) {
            double f = a[r * n + col] / a[col * n + col];
            for (int k = col; k < n; k++) a[r * n + k] -= f * a[col * n + k];
            b[r] -= f * b[col];
        }
    }
    for (int r = n - 1; r >= 0; r--) {
        double s = b[r];
        for (int k = r + 1; k < n; k++) s -= a[r * n + k] * b[k];
        b[r] = s / a[r * n + r];
    }
}

enum { MOST_BODIES = 50, MOST_JOINTS = 2 * MOST_BODIES, MOST_ROWS = 3 * MOST_JOINTS };

typedef struct {
    size_t body_count, joint_count;
    solver_velocity_t velocities[MOST_BODIES + 3]; /* and some rows no joint uses */
    joint_tree_block_t blocks[MOST_JOINTS];
    uint32_t edges[MOST_JOINTS];
    int first_row[MOST_JOINTS], row_count;
} random_tree_t;

/* One body's terms of row i of a block: (vx, vy, w) on `row`, or none. */
static const double *terms_on(const joint_tree_block_t *block, int i, uint32_t row) {
    if (block->row1 == row) return block->j1[i];
    if (block->row2 == row) return block->j2[i];
    return NULL;
}

/* Row a of joint p times W times row b of joint q, summed over bodies. */
static double coupling(const random_tree_t *t, const joint_tree_block_t *p, int a,
                       const joint_tree_block_t *q, int b) {
    double sum = 0.0;
    uint32_t rows[2] = {p->row1, p->row2};
    for (int k = 0; k < 2; k++) {
        if (rows[k] == JOINT_TREE_GROUND || (k == 1 && rows[1] == rows[0])) continue;
        const double *u = terms_on(p, a, rows[k]), *v = terms_on(q, b, rows[k]);
        if (v == NULL) continue;
        const solver_velocity_t *w = &t->velocities[rows[k]];
        sum += w->inverse_mass * (u[0] * v[0] + u[1] * v[1]) + w->inverse_inertia * u[2] * v[2];
    }
    return sum;
}

/* A random tree (or forest, when a joint would close a cycle) over
 * `bodies` bodies, on rows shuffled among some unused ones. */
static void make_random_tree(random_tree_t *t, joint_tree_t *tree, size_t bodies) {
    t->body_count = bodies;
    uint32_t row_of[MOST_BODIES];
    for (size_t i = 0; i < bodies + 3; i++) {
        t->velocities[i] = (solver_velocity_t){{0, 0}, 0, 1.0 / uniform(0.5, 3.0),
                                               1.0 / uniform(0.05, 1.0)};
    }
    for (size_t i = 0; i < bodies; i++) row_of[i] = (uint32_t)i + 3;
    for (size_t i = bodies; i-- > 1;) {
        size_t j = below((uint32_t)i + 1);
        uint32_t s = row_of[i];
        row_of[i] = row_of[j];
        row_of[j] = s;
    }
    joint_tree_reset(tree, bodies + 3);
    t->joint_count = 0;
    t->row_count = 0;
    /* Body i takes the rows of its joint to an earlier body and of its
     * world joint, 3 at most: the rows are then independent (J has full
     * rank), and the system regular. */
    for (size_t i = 0; i < bodies; i++) {
        int left = 3;
        if (i > 0) {
            uint32_t other = row_of[below((uint32_t)i)];
            bool flip = below(2) == 0;
            joint_tree_block_t block =
                random_block(flip ? row_of[i] : other, flip ? other : row_of[i], 3);
            t->blocks[t->joint_count++] = block;
            left -= block.rows;
        }
        if (below(3) == 0 && left >= 1) {
            bool flip = below(2) == 0;
            joint_tree_block_t block = random_block(flip ? row_of[i] : JOINT_TREE_GROUND,
                                                    flip ? JOINT_TREE_GROUND : row_of[i], left);
            t->blocks[t->joint_count++] = block;
        }
    }
    for (size_t k = 0; k < t->joint_count; k++) {
        t->edges[k] = joint_tree_add(tree, &t->blocks[k]);
        t->first_row[k] = t->row_count;
        t->row_count += t->blocks[k].rows;
    }
}

/* The tree's impulses and body changes match the dense solve of
 * (J W J^T + C) l = rhs to 1e-9 relative, over 60 random trees. */
static void tree_solve_matches_dense_solve(void) {
    static random_tree_t t;
    static double k[MOST_ROWS * MOST_ROWS], rhs[MOST_ROWS];
    joint_tree_t tree = {0};
    double worst = 0.0, worst_change = 0.0;
    for (int trial = 0; trial < 60; trial++) {
        size_t bodies = 2 + below(MOST_BODIES - 1);
        make_random_tree(&t, &tree, bodies);
        for (size_t j = 0; j < t.joint_count; j++) CHECK(t.edges[j] == j);
        joint_tree_factor(&tree, t.velocities);
        int n = t.row_count;
        for (size_t p = 0; p < t.joint_count; p++) {
            for (int a = 0; a < t.blocks[p].rows; a++) {
                int r = t.first_row[p] + a;
                rhs[r] = uniform(-1.0, 1.0);
                joint_tree_rhs(&tree, t.edges[p])[a] = rhs[r];
                for (size_t q = 0; q < t.joint_count; q++) {
                    for (int b = 0; b < t.blocks[q].rows; b++) {
                        double c = p == q ? t.blocks[p].c[a][b] : 0.0;
                        k[r * n + t.first_row[q] + b] =
                            coupling(&t, &t.blocks[p], a, &t.blocks[q], b) + c;
                    }
                }
            }
        }
        joint_tree_solve(&tree);
        dense_solve(k, rhs, n);
        double largest = 0.0;
        for (int r = 0; r < n; r++) largest = fmax(largest, fabs(rhs[r]));
        for (size_t p = 0; p < t.joint_count; p++) {
            const double *l = joint_tree_impulse(&tree, t.edges[p]);
            for (int a = 0; a < t.blocks[p].rows; a++) {
                worst = fmax(worst, fabs(l[a] - rhs[t.first_row[p] + a]) / largest);
            }
        }
        /* Each body's change is W J^T l. */
        for (size_t b = 0; b < joint_tree_body_count(&tree); b++) {
            uint32_t row = joint_tree_body_row(&tree, b);
            double expected[3] = {0, 0, 0};
            for (size_t p = 0; p < t.joint_count; p++) {
                for (int a = 0; a < t.blocks[p].rows; a++) {
                    const double *u = terms_on(&t.blocks[p], a, row);
                    if (u == NULL) continue;
                    for (int c = 0; c < 3; c++) expected[c] += u[c] * rhs[t.first_row[p] + a];
                }
            }
            const solver_velocity_t *w = &t.velocities[row];
            double scale[3] = {w->inverse_mass, w->inverse_mass, w->inverse_inertia};
            const double *change = joint_tree_body_change(&tree, b);
            for (int c = 0; c < 3; c++) {
                worst_change = fmax(worst_change,
                                    fabs(change[c] - scale[c] * expected[c]) / largest);
            }
        }
    }
    printf("    largest error %.2e (impulses), %.2e (body changes), relative\n", worst,
           worst_change);
    CHECK(worst <= 1e-9);
    CHECK(worst_change <= 1e-9);
    joint_tree_free(&tree);
}

/* A joint that closes a cycle among moving bodies, or brings a body's
 * world rows past JOINT_TREE_GROUND_ROWS, is refused; a bridge pinned to
 * the world at both ends is a tree (the world is no node). Two pins of one
 * body at one point are redundant: the solve shares the impulse so that
 * the rows hold (a dropped pivot), rather than dividing by zero. */
static void cycles_and_crowded_bodies_are_refused(void) {
    joint_tree_t tree = {0};
    solver_velocity_t rows[4];
    for (int i = 0; i < 4; i++) rows[i] = (solver_velocity_t){{0, 0}, 0, 1.0, 2.0};
    joint_tree_reset(&tree, 4);
    joint_tree_block_t pin = random_block(JOINT_TREE_GROUND, 0, 2);
    CHECK(joint_tree_add(&tree, &pin) == 0);
    for (uint32_t i = 0; i < 3; i++) {
        joint_tree_block_t link = random_block(i, i + 1, 2);
        CHECK(joint_tree_add(&tree, &link) == i + 1);
    }
    joint_tree_block_t end = random_block(3, JOINT_TREE_GROUND, 2);
    CHECK(joint_tree_add(&tree, &end) == 4);
    joint_tree_block_t closing = random_block(3, 0, 2);
    CHECK(joint_tree_add(&tree, &closing) == JOINT_TREE_NONE);
    joint_tree_block_t weld = random_block(JOINT_TREE_GROUND, 0, 3);
    weld.row2 = 1;
    weld.rows = 3;
    CHECK(joint_tree_add(&tree, &weld) == 5);
    CHECK(joint_tree_add(&tree, &weld) == 6); /* six world rows on body 1 */
    end.row1 = 1;
    CHECK(joint_tree_add(&tree, &end) == JOINT_TREE_NONE);
    joint_tree_free(&tree);

    /* One body pinned twice at the same point, pulled by 1 along x: the
     * pins share the impulse, the body moves by the 1 asked. */
    joint_tree_reset(&tree, 1);
    joint_tree_block_t twice;
    memset(&twice, 0, sizeof twice);
    twice.row1 = JOINT_TREE_GROUND;
    twice.row2 = 0;
    line_row(&twice, 0, 1.0, 0.0, 0.0, -0.5);
    line_row(&twice, 1, 0.0, 1.0, 0.0, 0.25);
    twice.rows = 2;
    CHECK(joint_tree_add(&tree, &twice) == 0);
    CHECK(joint_tree_add(&tree, &twice) == 1);
    joint_tree_factor(&tree, rows);
    double *rhs = joint_tree_rhs(&tree, 0);
    rhs[0] = 1.0, rhs[1] = 0.0;
    rhs = joint_tree_rhs(&tree, 1);
    rhs[0] = 1.0, rhs[1] = 0.0;
    joint_tree_solve(&tree);
    const double *change = joint_tree_body_change(&tree, 0);
    double along_x = change[0] - 0.5 * change[2], along_y = change[1] + 0.25 * change[2];
    CHECK_NEAR(along_x, 1.0, 1e-12);
    CHECK_NEAR(along_y, 0.0, 1e-12);
    CHECK(isfinite(joint_tree_impulse(&tree, 1)[0]));
    joint_tree_free(&tree);
}

TEST_SUITE(joint_tree, TEST_CASE(tree_solve_matches_dense_solve),
           TEST_CASE(cycles_and_crowded_bodies_are_refused));

