#include "collision/seams.h"
#include <math.h>
#include <stdlib.h>
#include "base/memory.h"
#include "base/scalar.h"

const double SEAM_TOLERANCE = 1e-6;
/* The tolerance of an edge under a millimetre, as a fraction of it. */
static const double SEAM_FRACTION = 1e-3;

/* A stretch [lo, hi] (m from vertex i) of edge `edge` (an index into the
 * search's edges) that an opposite flush edge covers. */
typedef struct seam_cover {
    size_t edge;
    double lo, hi;
} seam_cover_t;

/* A face of a run (non-back edge `edge`, an index into the search's
 * edges): the run's root, its stretch [lo, hi] along the root's line, and
 * whether it is a chain's segment. */
typedef struct seam_member {
    size_t root, edge;
    double lo, hi;
    bool segment;
} seam_member_t;

void seams_free(seams_t *seams) {
    if (seams->broadphase != NULL) broadphase_free(seams->broadphase);
    memory_free(seams->proxies);
    memory_free(seams->statics);
    memory_free(seams->records);
    memory_free(seams->edges);
    memory_free(seams->covers);
    memory_free(seams->run_parent);
    memory_free(seams->run_lo);
    memory_free(seams->run_hi);
    memory_free(seams->members);
}

static double edge_tolerance(double length) {
    return min_of(SEAM_TOLERANCE, SEAM_FRACTION * length);
}

/* One edge of a static body in world coordinates. */
typedef struct {
    vector_t start, along; /* along: unit direction */
    double length;
} edge_line_t;

static edge_line_t edge_line(const body_t *body, size_t i) {
    vector_t p0 = body->world_vertices[i], p1 = body->world_vertices[(i + 1) % body->count];
    double length = vec_get_length(vec_subtract(p1, p0));
    return (edge_line_t){p0, vec_multiply(1.0 / length, vec_subtract(p1, p0)), length};
}

static void add_cover(seams_t *seams, size_t edge, double lo, double hi) {
    memory_reserve((void **)&seams->covers, &seams->cover_capacity, seams->cover_count + 1,
                   sizeof(seam_cover_t));
    seams->covers[seams->cover_count++] = (seam_cover_t){edge, lo, hi};
}

static size_t find_run(size_t *parent, size_t edge) {
    while (parent[edge] != edge) {
        parent[edge] = parent[parent[edge]];
        edge = parent[edge];
    }
    return edge;
}

static void join_runs(size_t *parent, size_t a, size_t b) {
    a = find_run(parent, a);
    b = find_run(parent, b);
    if (a != b) parent[a > b ? a : b] = a < b ? a : b;
}

/* Whether edge i of a static body is a segment's back (seams_is_static). */
static bool is_back(const body_t *body, size_t i) {
    return body->kind == BODY_SHAPE_SEGMENT && i == 0;
}

/* What the edges of neighbour (whose first edge is seams->edges[other])
 * do to the edges of body (first: seams->edges[first]): covers where they
 * lie opposite, runs where they continue each other. */
static void match_edges(seams_t *seams, const body_t *body, size_t first, const body_t *neighbour,
                        size_t other) {
    size_t n = body->count, m = neighbour->count;
    for (size_t i = 0; i < n; i++) {
        if (is_back(body, i)) continue;
        edge_line_t line = edge_line(body, i);
        vector_t normal = body->world_normals[i];
        seam_edge_t *edge = &seams->edges[first + i];
        for (size_t j = 0; j < m; j++) {
            if (is_back(neighbour, j)) continue;
            vector_t q0 = neighbour->world_vertices[j], q1 = neighbour->world_vertices[(j + 1) % m];
            double tolerance =
                edge_tolerance(min_of(line.length, vec_get_length(vec_subtract(q1, q0))));
            if (fabs(vec_dot(normal, vec_subtract(q0, line.start))) > tolerance ||
                fabs(vec_dot(normal, vec_subtract(q1, line.start))) > tolerance) {
                continue;
            }
            double t0 = vec_dot(line.along, vec_subtract(q0, line.start));
            double t1 = vec_dot(line.along, vec_subtract(q1, line.start));
            if (t1 < t0) {
                double lo = max_of(t1, 0.0), hi = min_of(t0, line.length);
                if (hi - lo > tolerance) add_cover(seams, first + i, lo, hi);
                continue;
            }
            if (t0 > line.length + tolerance || t1 < -tolerance) continue; /* apart on the line */
            join_runs(seams->run_parent, first + i, other + j);
            if (t1 > line.length + tolerance) {
                edge->claim_hi = line.length + tolerance;
                edge->chained = true;
                seams->edges[first + (i + 1) % n].smooth = true;
            }
            if (t0 < -tolerance) {
                edge->claim_lo = -tolerance;
                edge->chained = true;
                edge->smooth = true;
            }
        }
    }
}

static int compare_covers(const void *a, const void *b) {
    const seam_cover_t *x = a, *y = b;
    if (x->edge != y->edge) return x->edge < y->edge ? -1 : 1;
    return (x->lo > y->lo) - (x->lo < y->lo);
}

/* Joins the covers of one edge (sorted by lo) into the stretches covered
 * from either end. */
static void join_covers(seam_edge_t *edge, const seam_cover_t *covers, size_t count,
                        double length) {
    double tolerance = edge_tolerance(length);
    double lo = covers[0].lo, hi = covers[0].hi;
    for (size_t k = 1; k <= count; k++) {
        if (k < count && covers[k].lo <= hi + tolerance) {
            hi = max_of(hi, covers[k].hi);
            continue;
        }
        if (lo <= tolerance) edge->start = max_of(edge->start, hi);
        if (hi >= length - tolerance) edge->end = min_of(edge->end, lo);
        if (k < count) {
            lo = covers[k].lo;
            hi = covers[k].hi;
        }
    }
    edge->internal = edge->start >= edge->end - tolerance;
}

/* The first edge of a static body in the search's edges. */
static size_t first_edge(const seams_t *seams, const body_t *body) {
    return (size_t)(body->seam->edges - seams->edges);
}

/* Each edge's covered ends, from the covers sorted by edge. */
static void apply_covers(seams_t *seams, size_t statics) {
    if (seams->cover_count == 0) return;
    qsort(seams->covers, seams->cover_count, sizeof(seam_cover_t), compare_covers);
    const seam_cover_t *covers = seams->covers;
    size_t k = 0;
    for (size_t s = 0; s < statics && k < seams->cover_count; s++) {
        const body_t *body = seams->statics[s];
        size_t first = first_edge(seams, body);
        for (size_t i = 0; i < body->count; i++) {
            size_t end = k;
            while (end < seams->cover_count && covers[end].edge == first + i) end++;
            if (end > k) {
                join_covers(&body->seam->edges[i], covers + k, end - k,
                            edge_line(body, i).length);
            }
            k = end;
        }
    }
}

/* The static body among statics[0 .. upto] whose edges hold `edge`. */
static const body_t *owner_of(const seams_t *seams, size_t upto, size_t edge) {
    size_t lo = 0, hi = upto;
    while (lo < hi) {
        size_t mid = (lo + hi + 1) / 2;
        if (first_edge(seams, seams->statics[mid]) <= edge) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    return seams->statics[lo];
}

static void add_member(seams_t *seams, seam_member_t member) {
    memory_reserve((void **)&seams->members, &seams->member_capacity, seams->member_count + 1,
                   sizeof(seam_member_t));
    seams->members[seams->member_count++] = member;
}

/* Each chained edge's reach: the extent of its run, found along the line
 * of the run's first edge (its root) and measured along the edge; and the
 * faces of the runs, with their stretches along their roots' lines. */
static void apply_runs(seams_t *seams, size_t statics) {
    size_t *parent = seams->run_parent;
    seams->member_count = 0;
    for (size_t pass = 0; pass < 2; pass++) {
        for (size_t s = 0; s < statics; s++) {
            const body_t *body = seams->statics[s];
            size_t first = first_edge(seams, body);
            for (size_t i = 0; i < body->count; i++) {
                size_t root = find_run(parent, first + i);
                /* The root is an edge of this body or of an earlier one. */
                const body_t *owner = root == first + i ? body : owner_of(seams, s, root);
                size_t root_edge = root - first_edge(seams, owner);
                edge_line_t base = edge_line(owner, root_edge);
                edge_line_t line = edge_line(body, i);
                if (pass == 0) {
                    vector_t end = vec_add(line.start, vec_multiply(line.length, line.along));
                    double t0 = vec_dot(base.along, vec_subtract(line.start, base.start));
                    double t1 = vec_dot(base.along, vec_subtract(end, base.start));
                    seams->run_lo[root] = min_of(seams->run_lo[root], min_of(t0, t1));
                    seams->run_hi[root] = max_of(seams->run_hi[root], max_of(t0, t1));
                    if (!is_back(body, i)) {
                        add_member(seams, (seam_member_t){root, first + i, min_of(t0, t1),
                                                          max_of(t0, t1),
                                                          body->kind == BODY_SHAPE_SEGMENT});
                    }
                    continue;
                }
                vector_t lo = vec_add(base.start, vec_multiply(seams->run_lo[root], base.along));
                vector_t hi = vec_add(base.start, vec_multiply(seams->run_hi[root], base.along));
                seam_edge_t *edge = &body->seam->edges[i];
                edge->reach_lo = min_of(0.0, vec_dot(line.along, vec_subtract(lo, line.start)));
                edge->reach_hi =
                    max_of(line.length, vec_dot(line.along, vec_subtract(hi, line.start)));
            }
        }
    }
}

static int compare_members(const void *a, const void *b) {
    const seam_member_t *x = a, *y = b;
    if (x->root != y->root) return x->root < y->root ? -1 : 1;
    if (x->lo != y->lo) return x->lo < y->lo ? -1 : 1;
    return (x->edge > y->edge) - (x->edge < y->edge);
}

/* The tolerance of two faces of a run, as match_edges takes it. */
static double pair_tolerance(const seam_member_t *x, const seam_member_t *y) {
    return edge_tolerance(min_of(x->hi - x->lo, y->hi - y->lo));
}

/* Whether candidate c reaches further along the run than b, both
 * starting before the holder ends: by more than the tolerance, or as far
 * and preferred (a polygon's face before a segment, so that a segment
 * lying exactly on a box's face leaves the box's corners whole; then the
 * earlier edge). */
static bool reaches_further(const seam_member_t *c, const seam_member_t *b) {
    double tolerance = pair_tolerance(c, b);
    if (c->hi > b->hi + tolerance) return true;
    if (c->hi < b->hi - tolerance) return false;
    if (c->segment != b->segment) return !c->segment;
    return c->edge < b->edge;
}

static void set_claim(seams_t *seams, const seam_member_t *member, double lo, double hi) {
    seam_edge_t *edge = &seams->edges[member->edge];
    edge->claim_lo = lo;
    edge->claim_hi = hi;
    edge->chained = true;
}

/*
 * Faces of a run that overlap (a chain's segment lying on a static box's
 * face, or two flush boxes' faces over each other) are one surface, whose
 * every stretch one face holds. Along the run, each face that holds a
 * stretch is followed by the face that reaches furthest among those that
 * start before it ends (the one a contact clipped to the run would meet
 * next); where two such faces overlap, each holds its side of the middle
 * of the overlap (their claims shared there by the tolerance, as at a
 * join); a face that reaches no further than the one holding before it
 * holds nothing. Faces that only meet end to end keep match_edges' claims.
 */
static void claim_group(seams_t *seams, seam_member_t *members, size_t count) {
    const seam_member_t *holder = NULL;
    size_t k = 0;
    while (k < count) {
        /* The faces that start before the holder ends (or, at the start of
         * the run, with its first face): the one that reaches furthest is
         * next, and the others hold nothing. */
        const seam_member_t *from = holder != NULL ? holder : &members[k];
        double limit = holder != NULL ? holder->hi : members[k].lo;
        const seam_member_t *best = NULL;
        for (; k < count && members[k].lo <= limit + pair_tolerance(from, &members[k]); k++) {
            const seam_member_t *candidate = &members[k];
            if (best == NULL || reaches_further(candidate, best)) {
                if (best != NULL) set_claim(seams, best, INFINITY, -INFINITY);
                best = candidate;
            } else {
                set_claim(seams, candidate, INFINITY, -INFINITY);
            }
        }
        if (best == NULL) {
            holder = NULL; /* apart: a new stretch starts at members[k] */
            continue;
        }
        double tolerance = holder != NULL ? pair_tolerance(holder, best) : 0.0;
        if (holder != NULL && !(best->hi > holder->hi + tolerance)) {
            set_claim(seams, best, INFINITY, -INFINITY);
            continue;
        }
        if (holder != NULL && best->lo < holder->hi - tolerance) {
            double middle = 0.5 * (best->lo + holder->hi);
            set_claim(seams, holder, seams->edges[holder->edge].claim_lo,
                      middle - holder->lo + tolerance);
            set_claim(seams, best, middle - best->lo - tolerance,
                      seams->edges[best->edge].claim_hi);
        }
        holder = best;
    }
}

/* The claims of overlapping faces, run by run. */
static void apply_claims(seams_t *seams) {
    seam_member_t *members = seams->members;
    qsort(members, seams->member_count, sizeof(seam_member_t), compare_members);
    for (size_t k = 0; k < seams->member_count;) {
        size_t end = k + 1;
        while (end < seams->member_count && members[end].root == members[k].root) end++;
        if (end - k > 1) claim_group(seams, members + k, end - k);
        k = end;
    }
}

/* Lists the static bodies and gives each its cleared edges; clears the
 * seams of bodies that are no longer static. Returns how many. */
static size_t list_statics(seams_t *seams, body_t **bodies, size_t count) {
    memory_reserve((void **)&seams->statics, &seams->static_capacity, count, sizeof(body_t *));
    size_t statics = 0, edges = 0;
    for (size_t i = 0; i < count; i++) {
        body_t *body = bodies[i];
        if (seams_is_static(body)) {
            body_update_world(body);
            seams->statics[statics++] = body;
            edges += body->count;
        } else if (body->seam_listed) {
            body->seam_listed = false;
            body->has_seams = false;
            body->seam = NULL;
        }
    }
    memory_reserve((void **)&seams->records, &seams->record_capacity, statics,
                   sizeof(seam_record_t));
    memory_reserve((void **)&seams->edges, &seams->edge_capacity, edges, sizeof(seam_edge_t));
    memory_reserve((void **)&seams->run_parent, &seams->run_parent_capacity, edges,
                   sizeof(size_t));
    memory_reserve((void **)&seams->run_lo, &seams->run_lo_capacity, edges, sizeof(double));
    memory_reserve((void **)&seams->run_hi, &seams->run_hi_capacity, edges, sizeof(double));
    size_t first = 0;
    for (size_t k = 0; k < statics; k++) {
        body_t *body = seams->statics[k];
        body->seam_listed = true;
        body->has_seams = false;
        body->seam = &seams->records[k];
        *body->seam = (seam_record_t){body->centroid, body->angle,   body->category,
                                      body->mask,     body->group,   seams->edges + first};
        for (size_t i = 0; i < body->count; i++) {
            double length = edge_line(body, i).length;
            seams->edges[first + i] =
                (seam_edge_t){-INFINITY, INFINITY, 0.0, length, -INFINITY, INFINITY,
                              false,     false,    false};
            seams->run_parent[first + i] = first + i;
            seams->run_lo[first + i] = INFINITY;
            seams->run_hi[first + i] = -INFINITY;
        }
        first += body->count;
    }
    return statics;
}

/* The pairs of static bodies whose boxes touch, through a broadphase of
 * their own (the world's refuses pairs of static bodies). */
static size_t touching_pairs(seams_t *seams, size_t statics, const broadphase_pair_t **pairs) {
    if (seams->broadphase == NULL) seams->broadphase = broadphase_init();
    memory_reserve((void **)&seams->proxies, &seams->proxy_capacity, statics,
                   sizeof(broadphase_proxy_t));
    vector_t grow = {SEAM_TOLERANCE, SEAM_TOLERANCE};
    for (size_t k = 0; k < statics; k++) {
        aabb_t box = seams->statics[k]->bounds;
        box = (aabb_t){vec_subtract(box.min, grow), vec_add(box.max, grow)};
        seams->proxies[k] = (broadphase_proxy_t){box, false, 1, UINT32_MAX, 0};
    }
    size_t tests = 0;
    return broadphase_find_pairs(seams->broadphase, seams->proxies, statics, pairs, &tests);
}

static bool same_filter(const body_t *a, const body_t *b) {
    return a->category == b->category && a->mask == b->mask && a->group == b->group;
}

void seams_find(seams_t *seams, body_t **bodies, size_t count) {
    seams->found = true;
    size_t statics = list_statics(seams, bodies, count);
    if (statics < 2) return;
    const broadphase_pair_t *pairs;
    size_t pair_count = touching_pairs(seams, statics, &pairs);
    seams->cover_count = 0;
    for (size_t k = 0; k < pair_count; k++) {
        body_t *a = seams->statics[pairs[k].a], *b = seams->statics[pairs[k].b];
        if (!same_filter(a, b)) continue;
        size_t first_a = first_edge(seams, a), first_b = first_edge(seams, b);
        match_edges(seams, a, first_a, b, first_b);
        match_edges(seams, b, first_b, a, first_a);
    }
    apply_covers(seams, statics);
    apply_runs(seams, statics);
    apply_claims(seams);
    for (size_t s = 0; s < statics; s++) {
        body_t *body = seams->statics[s];
        for (size_t i = 0; i < body->count; i++) {
            const seam_edge_t *edge = &body->seam->edges[i];
            body->has_seams |= edge->smooth || edge->chained || edge->start > -INFINITY ||
                               edge->end < INFINITY;
        }
    }
}
