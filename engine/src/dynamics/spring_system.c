#include "dynamics/spring_system.h"
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include "base/check.h"
#include "base/memory.h"

#define NO_NODE UINT32_MAX

/* The conjugate gradients stop once the residual, in the norm of the
 * forest's inverse, is this fraction of the right-hand side's. */
static const double TOLERANCE = 1e-10;

typedef struct {
    uint32_t a, b;
    sym2_t weight;
} edge_t;

/* A forest edge seen from one of its ends. */
typedef struct {
    uint32_t node, edge;
} neighbour_t;

struct spring_system {
    size_t nodes, edges;
    size_t forest_edges; /* of the last solve */
    size_t node_capacity, edge_capacity;
    /* Per node. */
    sym2_t *diagonal;
    vector_t *rhs;
    uint32_t *set;       /* union-find while the forest is chosen, then seen marks */
    uint32_t *first;     /* the node's neighbours in the forest: [first[i], first[i + 1]) */
    uint32_t *order;     /* breadth first over each tree: parents before children */
    uint32_t *parent;    /* NO_NODE for a root */
    sym2_t *up;          /* the weight of the edge to the parent */
    sym2_t *rest;        /* D plus what the node's subtree adds to it */
    sym2_t *pivot_inverse;
    vector_t *r, *z, *p, *q;
    /* Per edge. */
    edge_t *edge;
    uint32_t *sorted;    /* edge indices, stiffest first */
    bool *in_forest;
    neighbour_t *neighbours; /* two per edge */
};

static sym2_t sym2_add(sym2_t a, sym2_t b) {
    return (sym2_t){a.xx + b.xx, a.xy + b.xy, a.yy + b.yy};
}

static vector_t sym2_apply(sym2_t m, vector_t v) {
    return (vector_t){m.xx * v.x + m.xy * v.y, m.xy * v.x + m.yy * v.y};
}

/* Of a positive definite block; an overflowed one gives NaN, which the
 * integrate stage then reports with the body. */
static sym2_t sym2_inverse(sym2_t m) {
    double det = m.xx * m.yy - m.xy * m.xy;
    return (sym2_t){m.yy / det, -m.xy / det, m.xx / det};
}

/* W P^-1 R for symmetric W, P, R with P = W + R: the two in series, which
 * is symmetric (rounding aside, hence the mean of the off-diagonal terms)
 * and, unlike W - W P^-1 W, takes no difference of large numbers when W
 * is much stiffer than R. */
static sym2_t sym2_series(sym2_t w, sym2_t pivot_inverse, sym2_t r) {
    sym2_t a = pivot_inverse;
    /* m = P^-1 R (not symmetric) */
    double m11 = a.xx * r.xx + a.xy * r.xy, m12 = a.xx * r.xy + a.xy * r.yy;
    double m21 = a.xy * r.xx + a.yy * r.xy, m22 = a.xy * r.xy + a.yy * r.yy;
    double s11 = w.xx * m11 + w.xy * m21, s12 = w.xx * m12 + w.xy * m22;
    double s21 = w.xy * m11 + w.yy * m21, s22 = w.xy * m12 + w.yy * m22;
    return (sym2_t){s11, 0.5 * (s12 + s21), s22};
}

static void grow(void **array, size_t count, size_t size) {
    *array = memory_realloc(*array, count * size);
}

static void reserve_nodes(spring_system_t *s, size_t nodes) {
    if (nodes <= s->node_capacity) return;
    size_t n = nodes > 2 * s->node_capacity ? nodes : 2 * s->node_capacity;
    grow((void **)&s->diagonal, n, sizeof(sym2_t));
    grow((void **)&s->rhs, n, sizeof(vector_t));
    grow((void **)&s->set, n, sizeof(uint32_t));
    grow((void **)&s->first, n + 1, sizeof(uint32_t));
    grow((void **)&s->order, n, sizeof(uint32_t));
    grow((void **)&s->parent, n, sizeof(uint32_t));
    grow((void **)&s->up, n, sizeof(sym2_t));
    grow((void **)&s->rest, n, sizeof(sym2_t));
    grow((void **)&s->pivot_inverse, n, sizeof(sym2_t));
    grow((void **)&s->r, n, sizeof(vector_t));
    grow((void **)&s->z, n, sizeof(vector_t));
    grow((void **)&s->p, n, sizeof(vector_t));
    grow((void **)&s->q, n, sizeof(vector_t));
    s->node_capacity = n;
}

static void reserve_edges(spring_system_t *s, size_t edges) {
    if (edges <= s->edge_capacity) return;
    size_t n = edges > 2 * s->edge_capacity ? edges : 2 * s->edge_capacity;
    grow((void **)&s->edge, n, sizeof(edge_t));
    grow((void **)&s->sorted, n, sizeof(uint32_t));
    grow((void **)&s->in_forest, n, sizeof(bool));
    grow((void **)&s->neighbours, 2 * n, sizeof(neighbour_t));
    s->edge_capacity = n;
}

void spring_system_free(spring_system_t *s) {
    if (s == NULL) return;
    void *arrays[] = {s->diagonal, s->rhs,  s->set, s->first, s->order,  s->parent,
                      s->up,       s->rest, s->pivot_inverse, s->r, s->z, s->p,
                      s->q,        s->edge, s->sorted, s->in_forest, s->neighbours};
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) memory_free(arrays[i]);
    memory_free(s);
}

void spring_system_begin(spring_system_t **system, size_t nodes, size_t edges) {
    REQUIRE(nodes < NO_NODE && edges < UINT32_MAX / 2, "too many nodes (%zu) or edges (%zu)",
           nodes, edges);
    if (*system == NULL) *system = memory_calloc(1, sizeof(spring_system_t));
    spring_system_t *s = *system;
    reserve_nodes(s, nodes);
    reserve_edges(s, edges);
    s->nodes = nodes;
    s->edges = 0;
    for (size_t i = 0; i < nodes; i++) {
        s->diagonal[i] = (sym2_t){0.0, 0.0, 0.0};
        s->rhs[i] = VEC_ZERO;
    }
}

void spring_system_add_diagonal(spring_system_t *s, size_t node, sym2_t block) {
    s->diagonal[node] = sym2_add(s->diagonal[node], block);
}

void spring_system_add_rhs(spring_system_t *s, size_t node, vector_t rhs) {
    s->rhs[node] = vec_add(s->rhs[node], rhs);
}

void spring_system_add_edge(spring_system_t *s, size_t a, size_t b, sym2_t weight) {
    REQUIRE(a != b && a < s->nodes && b < s->nodes, "bad edge (%zu, %zu) of %zu nodes", a, b,
           s->nodes);
    reserve_edges(s, s->edges + 1);
    s->edge[s->edges++] = (edge_t){(uint32_t)a, (uint32_t)b, weight};
}

/* ---- The forest: Kruskal's, stiffest edges first ---- */

/* Whether edge i comes before edge j: stiffer, or as stiff and added
 * earlier (a total order, so the forest does not depend on the sort). */
static bool comes_before(const edge_t *edges, uint32_t i, uint32_t j) {
    double ki = edges[i].weight.xx + edges[i].weight.yy;
    double kj = edges[j].weight.xx + edges[j].weight.yy;
    return ki > kj || (ki == kj && i < j);
}

static void sift_down(const edge_t *edges, uint32_t *a, size_t root, size_t end) {
    for (size_t child; (child = 2 * root + 1) < end; root = child) {
        if (child + 1 < end && comes_before(edges, a[child], a[child + 1])) child++;
        if (!comes_before(edges, a[root], a[child])) return;
        uint32_t t = a[root];
        a[root] = a[child];
        a[child] = t;
    }
}

/* Heap sort: in place, no allocation. */
static void sort_edges(spring_system_t *s) {
    size_t n = s->edges;
    uint32_t *a = s->sorted;
    for (size_t i = 0; i < n; i++) a[i] = (uint32_t)i;
    for (size_t start = n / 2; start-- > 0;) sift_down(s->edge, a, start, n);
    for (size_t end = n; end-- > 1;) {
        uint32_t t = a[0];
        a[0] = a[end];
        a[end] = t;
        sift_down(s->edge, a, 0, end);
    }
}

static uint32_t find_set(uint32_t *set, uint32_t i) {
    while (set[i] != i) {
        set[i] = set[set[i]];
        i = set[i];
    }
    return i;
}

/* Marks the forest's edges; returns how many. */
static size_t choose_forest(spring_system_t *s) {
    sort_edges(s);
    for (size_t i = 0; i < s->nodes; i++) s->set[i] = (uint32_t)i;
    size_t count = 0;
    for (size_t k = 0; k < s->edges; k++) {
        uint32_t e = s->sorted[k];
        uint32_t ra = find_set(s->set, s->edge[e].a), rb = find_set(s->set, s->edge[e].b);
        s->in_forest[e] = ra != rb;
        if (ra != rb) {
            s->set[ra] = rb;
            count++;
        }
    }
    return count;
}

/* The forest's neighbours of each node, then each tree breadth first from
 * its lowest node: order, parent and up. */
static void root_forest(spring_system_t *s) {
    size_t n = s->nodes;
    for (size_t i = 0; i <= n; i++) s->first[i] = 0;
    for (size_t e = 0; e < s->edges; e++) {
        if (!s->in_forest[e]) continue;
        s->first[s->edge[e].a + 1]++;
        s->first[s->edge[e].b + 1]++;
    }
    for (size_t i = 0; i < n; i++) s->first[i + 1] += s->first[i];
    /* set[i] counts node i's neighbours placed so far, then marks it seen. */
    for (size_t i = 0; i < n; i++) s->set[i] = 0;
    for (size_t e = 0; e < s->edges; e++) {
        if (!s->in_forest[e]) continue;
        uint32_t a = s->edge[e].a, b = s->edge[e].b;
        s->neighbours[s->first[a] + s->set[a]++] = (neighbour_t){b, (uint32_t)e};
        s->neighbours[s->first[b] + s->set[b]++] = (neighbour_t){a, (uint32_t)e};
    }
    for (size_t i = 0; i < n; i++) s->set[i] = 0;
    size_t head = 0, tail = 0;
    for (size_t root = 0; root < n; root++) {
        if (s->set[root]) continue;
        s->set[root] = 1;
        s->parent[root] = NO_NODE;
        s->order[tail++] = (uint32_t)root;
        while (head < tail) {
            uint32_t node = s->order[head++];
            for (uint32_t k = s->first[node]; k < s->first[node + 1]; k++) {
                neighbour_t next = s->neighbours[k];
                if (s->set[next.node]) continue;
                s->set[next.node] = 1;
                s->parent[next.node] = node;
                s->up[next.node] = s->edge[next.edge].weight;
                s->order[tail++] = next.node;
            }
        }
    }
}

/* Eliminates children into parents, leaves first: P = L D L^T with pivots
 * rest + up. */
static void factor_forest(spring_system_t *s) {
    for (size_t i = 0; i < s->nodes; i++) s->rest[i] = s->diagonal[i];
    for (size_t k = s->nodes; k-- > 0;) {
        uint32_t c = s->order[k], p = s->parent[c];
        sym2_t pivot = p == NO_NODE ? s->rest[c] : sym2_add(s->rest[c], s->up[c]);
        s->pivot_inverse[c] = sym2_inverse(pivot);
        if (p != NO_NODE) {
            s->rest[p] = sym2_add(s->rest[p], sym2_series(s->up[c], s->pivot_inverse[c], s->rest[c]));
        }
    }
}

/* z = P^-1 r, P the forest's matrix (D and the forest's edges). */
static void apply_forest_inverse(const spring_system_t *s, const vector_t *r, vector_t *z) {
    for (size_t i = 0; i < s->nodes; i++) z[i] = r[i];
    for (size_t k = s->nodes; k-- > 0;) {
        uint32_t c = s->order[k], p = s->parent[c];
        if (p != NO_NODE) z[p] = vec_add(z[p], sym2_apply(s->up[c], sym2_apply(s->pivot_inverse[c], z[c])));
    }
    for (size_t k = 0; k < s->nodes; k++) {
        uint32_t c = s->order[k], p = s->parent[c];
        vector_t y = z[c];
        if (p != NO_NODE) y = vec_add(y, sym2_apply(s->up[c], z[p]));
        z[c] = sym2_apply(s->pivot_inverse[c], y);
    }
}

/* q = A x. */
static void multiply(const spring_system_t *s, const vector_t *x, vector_t *q) {
    for (size_t i = 0; i < s->nodes; i++) q[i] = sym2_apply(s->diagonal[i], x[i]);
    for (size_t e = 0; e < s->edges; e++) {
        const edge_t *edge = &s->edge[e];
        vector_t t = sym2_apply(edge->weight, vec_subtract(x[edge->a], x[edge->b]));
        q[edge->a] = vec_add(q[edge->a], t);
        q[edge->b] = vec_subtract(q[edge->b], t);
    }
}

static double dot(const vector_t *a, const vector_t *b, size_t n) {
    double sum = 0.0;
    for (size_t i = 0; i < n; i++) sum += a[i].x * b[i].x + a[i].y * b[i].y;
    return sum;
}

/* Conjugate gradients preconditioned by the forest, from x = P^-1 b. */
static size_t refine(spring_system_t *s, vector_t *x, size_t loops) {
    size_t n = s->nodes;
    vector_t *r = s->r, *z = s->z, *p = s->p, *q = s->q;
    double threshold = TOLERANCE * TOLERANCE * dot(s->rhs, x, n);
    multiply(s, x, q);
    for (size_t i = 0; i < n; i++) r[i] = vec_subtract(s->rhs[i], q[i]);
    apply_forest_inverse(s, r, z);
    for (size_t i = 0; i < n; i++) p[i] = z[i];
    double rz = dot(r, z, n);
    /* Twice the exact-arithmetic bound, for rounding. */
    size_t most = 2 * (2 * loops + 1) + 8, done = 0;
    while (done < most && rz > threshold) {
        multiply(s, p, q);
        double pq = dot(p, q, n);
        if (!(pq > 0.0)) break;
        double alpha = rz / pq;
        for (size_t i = 0; i < n; i++) {
            x[i] = vec_add(x[i], vec_multiply(alpha, p[i]));
            r[i] = vec_subtract(r[i], vec_multiply(alpha, q[i]));
        }
        apply_forest_inverse(s, r, z);
        double next = dot(r, z, n), beta = next / rz;
        rz = next;
        for (size_t i = 0; i < n; i++) p[i] = vec_add(z[i], vec_multiply(beta, p[i]));
        done++;
    }
    return done;
}

size_t spring_system_solve(spring_system_t *s, vector_t *x) {
    s->forest_edges = choose_forest(s);
    root_forest(s);
    factor_forest(s);
    return spring_system_solve_again(s, x);
}

void spring_system_clear_rhs(spring_system_t *s) {
    for (size_t i = 0; i < s->nodes; i++) s->rhs[i] = VEC_ZERO;
}

size_t spring_system_solve_again(spring_system_t *s, vector_t *x) {
    apply_forest_inverse(s, s->rhs, x);
    if (s->forest_edges == s->edges) return 0;
    return refine(s, x, s->edges - s->forest_edges);
}

/* B S B^T for symmetric S, symmetrised against rounding. */
static sym2_t sym2_congruent(double b11, double b12, double b21, double b22, sym2_t m) {
    double t11 = b11 * m.xx + b12 * m.xy, t12 = b11 * m.xy + b12 * m.yy;
    double t21 = b21 * m.xx + b22 * m.xy, t22 = b21 * m.xy + b22 * m.yy;
    double xy = 0.5 * ((t11 * b21 + t12 * b22) + (t21 * b11 + t22 * b12));
    return (sym2_t){t11 * b11 + t12 * b12, xy, t21 * b21 + t22 * b22};
}

/* Parents first: Sigma_c = P_c^-1 + (P_c^-1 W) Sigma_p (W P_c^-1)
 * (Takahashi's recurrence on the forest's factors). */
void spring_system_inverse_diagonal(const spring_system_t *s, sym2_t *diagonal) {
    for (size_t k = 0; k < s->nodes; k++) {
        uint32_t c = s->order[k], p = s->parent[c];
        sym2_t a = s->pivot_inverse[c];
        if (p == NO_NODE) {
            diagonal[c] = a;
            continue;
        }
        sym2_t w = s->up[c];
        /* B = P_c^-1 W */
        double b11 = a.xx * w.xx + a.xy * w.xy, b12 = a.xx * w.xy + a.xy * w.yy;
        double b21 = a.xy * w.xx + a.yy * w.xy, b22 = a.xy * w.xy + a.yy * w.yy;
        diagonal[c] = sym2_add(a, sym2_congruent(b11, b12, b21, b22, diagonal[p]));
    }
}
