/*
 * Chains (body.h): static bodies made of line segments, and their
 * segments, the static bodies the world collides in their place, each
 * knowing its neighbours (body_private.h, body_segment_t).
 */
#include <math.h>
#include "jostle/body.h"
#include "dynamics/body_private.h"
#include "base/check.h"
#include "base/memory.h"
#include "base/scalar.h"

/* Two segments whose directions differ by less than this sine continue
 * each other into one straight run. */
static const double FLAT_SINE = 1e-9;

/* The tolerance (m) by which the claims of two segments of a run overlap
 * at the join, so that no contact there falls between them. */
static const double CLAIM_OVERLAP = 1e-9;

static void check_points(const vector_t *points, size_t count, bool loop, const char *function) {
    if (points == NULL) engine_fail(function, "points is NULL");
    size_t least = loop ? 3 : 2;
    if (count < least) {
        engine_fail(function, "a%s chain needs at least %zu points (got %zu)", loop ? " loop" : "n open",
                    least, count);
    }
    for (size_t i = 0; i < count; i++) {
        if (!vec_is_finite(points[i])) {
            engine_fail(function, "point %zu is not finite (%g, %g)", i, points[i].x, points[i].y);
        }
    }
    size_t segments = loop ? count : count - 1;
    for (size_t i = 0; i < segments; i++) {
        vector_t p = points[i], q = points[(i + 1) % count];
        if (!(vec_get_length(vec_subtract(q, p)) > 0.0)) {
            engine_fail(function, "segment %zu from (%g, %g) to (%g, %g) has zero length", i, p.x,
                        p.y, q.x, q.y);
        }
        if (!isfinite(vec_get_length(vec_subtract(q, p)))) {
            engine_fail(function, "segment %zu from (%g, %g) to (%g, %g) is too long: its length is "
                        "not finite", i, p.x, p.y, q.x, q.y);
        }
    }
}

/* The unit direction of the chain's segment i. */
static vector_t direction(const body_t *chain, size_t i) {
    const vector_t *v = chain->local_vertices;
    vector_t d = vec_subtract(v[(i + 1) % chain->count], v[i]);
    return vec_multiply(1.0 / vec_get_length(d), d);
}

static double length(const body_t *chain, size_t i) {
    const vector_t *v = chain->local_vertices;
    return vec_get_length(vec_subtract(v[(i + 1) % chain->count], v[i]));
}

/* Whether segment j continues segment i straight on (j follows i). */
static bool flat_join(const body_t *chain, size_t i, size_t j) {
    vector_t u = direction(chain, i), w = direction(chain, j);
    return fabs(vec_cross(u, w)) <= FLAT_SINE && vec_dot(u, w) > 0.0;
}

/* Segment k's straight run: how far it reaches before its start and after
 * its end through segments that continue it, and its claim. */
static void find_run(const body_t *chain, size_t segments, size_t k, body_segment_t *segment) {
    double own = length(chain, k), before = 0.0, after = 0.0;
    bool loop = chain->loop;
    size_t i = k, steps = 0;
    while ((loop || i > 0) && steps + 1 < segments) {
        size_t previous = (i + segments - 1) % segments;
        if (!flat_join(chain, previous, i)) break;
        before += length(chain, previous);
        i = previous;
        steps++;
    }
    i = k;
    while ((loop || i + 1 < segments) && steps + 1 < segments) {
        size_t next = (i + 1) % segments;
        if (!flat_join(chain, i, next)) break;
        after += length(chain, next);
        i = next;
        steps++;
    }
    segment->run_lo = -before;
    segment->run_hi = own + after;
    segment->claim_lo = before > 0.0 ? -CLAIM_OVERLAP : -INFINITY;
    segment->claim_hi = after > 0.0 ? own + CLAIM_OVERLAP : INFINITY;
}

/* Segment k of the chain as a static body of its own. */
static body_t *make_segment(body_t *chain, size_t segments, size_t k) {
    const vector_t *v = chain->local_vertices;
    size_t n = chain->count;
    vector_t p1 = v[k], p2 = v[(k + 1) % n];
    vector_t mid = vec_multiply(0.5, vec_add(p1, p2));
    vector_t u = direction(chain, k);
    body_t *part = body_allocate(2);
    part->kind = BODY_SHAPE_SEGMENT;
    part->chain = chain;
    part->core[0] = part->local_vertices[0] = vec_subtract(p1, mid);
    part->core[1] = part->local_vertices[1] = vec_subtract(p2, mid);
    /* Outward normals as a polygon's: each edge's right side. */
    part->local_normals[0] = (vector_t){u.y, -u.x};
    part->local_normals[1] = (vector_t){-u.y, u.x};
    part->radius = 0.5 * vec_get_length(vec_subtract(p2, p1));
    part->centroid = mid;
    body_segment_t *segment = memory_calloc(1, sizeof(body_segment_t));
    segment->normal = (vector_t){-u.y, u.x};
    segment->has_ghost[0] = chain->loop || k > 0;
    segment->has_ghost[1] = chain->loop || k + 1 < segments;
    if (segment->has_ghost[0]) segment->ghost[0] = vec_subtract(v[(k + n - 1) % n], mid);
    if (segment->has_ghost[1]) segment->ghost[1] = vec_subtract(v[(k + 2) % n], mid);
    segment->index = k;
    segment->offset = mid;
    find_run(chain, segments, k, segment);
    part->segment = segment;
    body_set_defaults(part, INFINITY, INFINITY, chain->color, NULL, NULL);
    return part;
}

static body_t *chain_create(const vector_t *points, size_t count, bool loop, rgb_color_t color,
                            void *info, free_func_t info_freer, const char *function) {
    check_points(points, count, loop, function);
    body_t *chain = body_allocate(count);
    chain->kind = BODY_SHAPE_CHAIN;
    chain->loop = loop;
    for (size_t i = 0; i < count; i++) {
        chain->local_vertices[i] = points[i];
        chain->radius = fmax(chain->radius, vec_get_length(points[i]));
    }
    if (!isfinite(chain->radius)) {
        engine_fail(function, "bad shape: chain is too large: its reach from the origin is not finite");
    }
    for (size_t i = 0; i < count; i++) {
        vector_t edge = vec_subtract(points[(i + 1) % count], points[i]);
        double l = vec_get_length(edge);
        chain->local_normals[i] = l > 0.0 ? vec_multiply(1.0 / l, (vector_t){edge.y, -edge.x})
                                          : VEC_ZERO;
    }
    body_set_defaults(chain, INFINITY, INFINITY, color, info, info_freer);
    size_t segments = loop ? count : count - 1;
    chain->parts = memory_alloc(segments * sizeof(body_t *));
    chain->part_count = segments;
    for (size_t k = 0; k < segments; k++) chain->parts[k] = make_segment(chain, segments, k);
    return chain;
}

body_t *body_init_chain(const vector_t *points, size_t count, bool loop, rgb_color_t color) {
    return chain_create(points, count, loop, color, NULL, NULL, __func__);
}

body_t *body_init_chain_with_info(const vector_t *points, size_t count, bool loop,
                                  rgb_color_t color, void *info, free_func_t info_freer) {
    return chain_create(points, count, loop, color, info, info_freer, __func__);
}

size_t body_get_segment_count(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->part_count;
}

void body_get_segment(body_t *body, size_t index, vector_t *p1, vector_t *p2) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_NOT_NULL(p1);
    REQUIRE_NOT_NULL(p2);
    REQUIRE(index < body->part_count, "segment %zu out of range (%zu segments)", index,
            body->part_count);
    body_update_world(body);
    *p1 = body->world_vertices[index];
    *p2 = body->world_vertices[(index + 1) % body->count];
}

bool body_is_loop(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->loop;
}
