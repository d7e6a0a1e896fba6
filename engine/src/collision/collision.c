#include "jostle/collision.h"
#include <math.h>
#include "dynamics/body_private.h"
#include "base/check.h"
#include "collision/collision_private.h"
#include "collision/round_manifold.h"
#include "collision/segment_manifold.h"

typedef struct {
    double min;
    double max;
} projection_t;

static projection_t project(const body_t *body, vector_t axis) {
    projection_t p = {INFINITY, -INFINITY};
    for (size_t i = 0; i < body->count; i++) {
        double d = vec_dot(body->world_vertices[i], axis);
        p.min = fmin(p.min, d);
        p.max = fmax(p.max, d);
    }
    return p;
}

/*
 * Tests the edge normals of `owner` as candidate separating axes. Returns
 * false at the first axis that separates. Otherwise lowers *least_overlap to
 * the smallest push-out distance seen and sets *axis to point the way body2
 * must move, from body1 toward body2.
 */
static bool overlaps_on_normals_of(const body_t *owner, const body_t *body1,
                                   const body_t *body2, double *least_overlap, vector_t *axis) {
    for (size_t i = 0; i < owner->count; i++) {
        vector_t normal = owner->world_normals[i];
        projection_t p1 = project(body1, normal);
        projection_t p2 = project(body2, normal);
        if (p1.max < p2.min || p2.max < p1.min) return false;
        /* Pushing body2 along +normal takes p1.max - p2.min; along -normal,
         * p2.max - p1.min. The smaller is the overlap on this axis, and it
         * handles containment, where centroid directions mislead. */
        double forward = p1.max - p2.min;
        double backward = p2.max - p1.min;
        double overlap = fmin(forward, backward);
        if (overlap < *least_overlap) {
            *least_overlap = overlap;
            *axis = forward <= backward ? normal : vec_negate(normal);
        }
    }
    return true;
}

/* The separation of a manifold's deepest point (INFINITY: no points). */
static double deepest(const manifold_t *m) {
    double least = INFINITY;
    for (int i = 0; i < m->point_count; i++) least = fmin(least, m->points[i].separation);
    return least;
}

/* A pair with a round body: the contact the world builds, its points
 * found at any distance (the world's margin only drops points, and the
 * shapes' separation is a lower bound on theirs, so apart shapes are
 * apart): collided when its deepest point touches, the axis its normal,
 * the depth that point's overlap along it. */
static collision_info_t round_collision(const body_t *body1, const body_t *body2) {
    collision_info_t info = {false, VEC_ZERO, 0.0};
    manifold_features_t features;
    double separation;
    manifold_t manifold = round_manifold_collide(body1, body2, 0.0, &features, &separation);
    if (separation > 0.0) return info;
    manifold = round_manifold_collide(body1, body2, INFINITY, &features, &separation);
    double least = manifold.point_count > 0 ? deepest(&manifold) : separation;
    if (least > 0.0) return info;
    info.collided = true;
    info.axis = manifold.normal;
    info.depth = -least;
    return info;
}

/* The bodies that stand for body in a pair: a chain's segments (brought up
 * to date), or the body itself. */
static size_t parts_of(body_t *body, body_t ***parts) {
    if (body->kind != BODY_SHAPE_CHAIN) {
        *parts = NULL;
        return 1;
    }
    for (size_t k = 0; k < body->part_count; k++) body_update_world(body->parts[k]);
    *parts = body->parts;
    return body->part_count;
}

/* A pair with a chain: each segment against the other body (or each
 * segment of it) by the chain's rules (segment_manifold.h), as the world
 * builds their contacts (round_collision), the deepest touch kept; *least
 * receives the least separation found. */
static collision_info_t chain_collision(body_t *body1, body_t *body2, double *least) {
    body_t **parts1, **parts2;
    size_t n1 = parts_of(body1, &parts1), n2 = parts_of(body2, &parts2);
    collision_info_t info = {false, VEC_ZERO, 0.0};
    *least = INFINITY;
    for (size_t i = 0; i < n1; i++) {
        for (size_t j = 0; j < n2; j++) {
            body_t *a = parts1 != NULL ? parts1[i] : body1;
            body_t *b = parts2 != NULL ? parts2[j] : body2;
            manifold_features_t features;
            double separation;
            /* Not manifold_collide: a program of seed collisions links
             * none of the world's narrowphase. */
            manifold_t m = segment_manifold_collide(a, b, 0.0, &features, &separation);
            *least = fmin(*least, fmin(separation, deepest(&m)));
            if (m.point_count == 0) continue;
            m = segment_manifold_collide(a, b, INFINITY, &features, &separation);
            double depth = -deepest(&m);
            if (depth >= 0.0 && (!info.collided || depth > info.depth)) {
                info = (collision_info_t){true, m.normal, depth};
            }
        }
    }
    return info;
}

collision_info_t find_collision(body_t *body1, body_t *body2) {
    REQUIRE_NOT_NULL(body1);
    REQUIRE_NOT_NULL(body2);
    body_update_world(body1);
    body_update_world(body2);
    if (body1->kind == BODY_SHAPE_CHAIN || body2->kind == BODY_SHAPE_CHAIN) {
        double least;
        return chain_collision(body1, body2, &least);
    }
    if ((body1->kind | body2->kind) != BODY_SHAPE_POLYGON) return round_collision(body1, body2);
    collision_info_t info = {false, VEC_ZERO, 0.0};
    /* Bounds apart by a gap: some edge normal separates them too, so the
     * answer is the same; most pairs of a scene are far apart. */
    const aabb_t a = body1->bounds, b = body2->bounds;
    if (a.max.x < b.min.x || b.max.x < a.min.x || a.max.y < b.min.y || b.max.y < a.min.y)
        return info;
    double least_overlap = INFINITY;
    if (!overlaps_on_normals_of(body1, body1, body2, &least_overlap, &info.axis)) return info;
    if (!overlaps_on_normals_of(body2, body1, body2, &least_overlap, &info.axis)) return info;
    info.collided = true;
    info.depth = least_overlap;
    return info;
}

/* The largest gap between the projections on the normals of owner. */
static double gap_on_normals_of(const body_t *owner, const body_t *body1, const body_t *body2) {
    double gap = -INFINITY;
    for (size_t i = 0; i < owner->count; i++) {
        vector_t normal = owner->world_normals[i];
        projection_t p1 = project(body1, normal);
        projection_t p2 = project(body2, normal);
        gap = fmax(gap, fmax(p2.min - p1.max, p1.min - p2.max));
    }
    return gap;
}

double collision_separation(body_t *body1, body_t *body2) {
    body_update_world(body1);
    body_update_world(body2);
    if (body1->kind == BODY_SHAPE_CHAIN || body2->kind == BODY_SHAPE_CHAIN) {
        double least;
        chain_collision(body1, body2, &least);
        return least;
    }
    if ((body1->kind | body2->kind) != BODY_SHAPE_POLYGON) {
        manifold_features_t features;
        double separation;
        round_manifold_collide(body1, body2, -INFINITY, &features, &separation);
        return separation;
    }
    return fmax(gap_on_normals_of(body1, body1, body2), gap_on_normals_of(body2, body1, body2));
}
