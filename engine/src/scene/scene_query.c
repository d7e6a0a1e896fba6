/* The queries of jostle/query.h: a grid of the bodies' boxes (the
 * broadphase's), kept until something moves, and the exact shape tests of
 * geometry/shape_query.h on what it finds. */
#include "jostle/query.h"
#include <math.h>
#include <stdlib.h>
#include "base/check.h"
#include "base/memory.h"
#include "collision/broadphase.h"
#include "dynamics/body_private.h"
#include "geometry/shape_query.h"
#include "scene/scene_private.h"

typedef struct {
    broadphase_t *grid;
    broadphase_proxy_t *proxies;
    size_t proxy_capacity;
    /* scene_moves when the grid was built; built false before the first. */
    uint64_t moves;
    bool built;
    /* The bodies a box query found (scene indices). */
    uint32_t *found;
    size_t found_count, found_capacity;
} queries_t;

static void *queries_init(void) {
    queries_t *queries = memory_calloc(1, sizeof(queries_t));
    queries->grid = broadphase_init();
    return queries;
}

static void queries_free(void *state) {
    queries_t *queries = state;
    broadphase_free(queries->grid);
    memory_free(queries->proxies);
    memory_free(queries->found);
    memory_free(queries);
}

/* The scene's grid, built again when the bodies may have moved. */
static queries_t *ready_queries(scene_t *scene) {
    queries_t *queries = scene_query_state(scene, queries_init, queries_free);
    uint64_t moves = scene_moves(scene);
    if (queries->built && queries->moves == moves) return queries;
    size_t count = scene_bodies(scene);
    body_t **bodies = scene_body_array(scene);
    memory_reserve((void **)&queries->proxies, &queries->proxy_capacity, count,
                   sizeof(broadphase_proxy_t));
    for (size_t i = 0; i < count; i++) {
        body_update_world(bodies[i]);
        /* fixed: the grid's cells are sized by the bodies that move. */
        queries->proxies[i] = (broadphase_proxy_t){bodies[i]->bounds, !body_is_movable(bodies[i]),
                                                   0, 0, 0};
    }
    broadphase_build(queries->grid, queries->proxies, count);
    queries->moves = moves;
    queries->built = true;
    return queries;
}

/* ---- The shape tests by kind ------------------------------------------------ */

/* A round body's world core (body_world_core, after body_update_world). */
static void round_core(const body_t *body, vector_t core[2]) {
    body_world_core(body, core);
}

static bool is_round(const body_t *body) {
    return body->kind == BODY_SHAPE_CIRCLE || body->kind == BODY_SHAPE_CAPSULE;
}

/* A chain's segment i: its world ends and the normal of its free side. */
static void chain_segment(const body_t *chain, size_t i, vector_t *p1, vector_t *p2,
                          vector_t *normal) {
    *p1 = chain->world_vertices[i];
    *p2 = chain->world_vertices[(i + 1) % chain->count];
    vector_t e = vec_normalize(vec_subtract(*p2, *p1));
    *normal = (vector_t){-e.y, e.x};
}

static bool body_ray_cast(const body_t *body, vector_t from, vector_t d, double max_fraction,
                          double *fraction, vector_t *normal) {
    if (is_round(body)) {
        vector_t core[2];
        round_core(body, core);
        return capsule_ray_cast(core[0], core[1], body->round_radius, from, d, max_fraction,
                                fraction, normal);
    }
    if (body->kind == BODY_SHAPE_CHAIN) {
        bool hit = false;
        for (size_t i = 0; i < body->part_count; i++) {
            vector_t p1, p2, n;
            chain_segment(body, i, &p1, &p2, &n);
            if (segment_ray_cast(p1, p2, n, from, d, max_fraction, fraction)) {
                max_fraction = *fraction;
                *normal = n;
                hit = true;
            }
        }
        return hit;
    }
    size_t edge;
    if (!polygon_ray_cast(body->world_vertices, body->world_normals, body->count, from, d,
                          max_fraction, fraction, &edge)) {
        return false;
    }
    *normal = body->world_normals[edge];
    return true;
}

static bool body_overlaps_box(const body_t *body, aabb_t box) {
    if (!aabb_overlaps(body->bounds, box)) return false;
    if (is_round(body)) {
        vector_t core[2];
        round_core(body, core);
        return capsule_overlaps_box(core[0], core[1], body->round_radius, box);
    }
    if (body->kind == BODY_SHAPE_CHAIN) {
        for (size_t i = 0; i < body->part_count; i++) {
            vector_t p1, p2, n;
            chain_segment(body, i, &p1, &p2, &n);
            if (capsule_overlaps_box(p1, p2, 0.0, box)) return true;
        }
        return false;
    }
    return polygon_overlaps_box(body->world_vertices, body->world_normals, body->count,
                                body->bounds, box);
}

static bool body_holds_point(body_t *body, vector_t point) {
    if (body->kind != BODY_SHAPE_POLYGON) return body_contains_point(body, point);
    return polygon_contains_point(body->world_vertices, body->world_normals, body->count, point);
}

static double body_distance(const body_t *body, vector_t point, vector_t *nearest) {
    if (is_round(body)) {
        vector_t core[2];
        round_core(body, core);
        return capsule_distance(core[0], core[1], body->round_radius, point, nearest);
    }
    if (body->kind == BODY_SHAPE_CHAIN) {
        double best = INFINITY;
        for (size_t i = 0; i < body->part_count; i++) {
            vector_t p1, p2, n, q;
            chain_segment(body, i, &p1, &p2, &n);
            double distance = capsule_distance(p1, p2, 0.0, point, &q);
            if (distance < best) {
                best = distance;
                *nearest = q;
            }
        }
        return best;
    }
    return polygon_distance(body->world_vertices, body->world_normals, body->count, point,
                            nearest);
}

/* ---- Ray cast --------------------------------------------------------------- */

typedef struct {
    body_t **bodies;
    vector_t from, d;
    ray_hit_t best;
    size_t best_index; /* SIZE_MAX: none yet */
} ray_search_t;

static double ray_visit(void *context, uint32_t proxy) {
    ray_search_t *search = context;
    body_t *body = search->bodies[proxy];
    double limit = search->best_index == SIZE_MAX ? 1.0 : search->best.fraction;
    double fraction;
    vector_t normal;
    if (body->removed || !body_ray_cast(body, search->from, search->d, limit, &fraction, &normal)) {
        return limit;
    }
    /* Entered at the same fraction: the body added last is on top. */
    if (search->best_index == SIZE_MAX || fraction < limit || proxy > search->best_index) {
        search->best = (ray_hit_t){body, vec_add(search->from, vec_multiply(fraction, search->d)),
                                   normal, fraction};
        search->best_index = proxy;
    }
    return search->best.fraction;
}

bool scene_ray_cast(scene_t *scene, vector_t from, vector_t to, ray_hit_t *hit) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_FINITE_VECTOR(from);
    REQUIRE_FINITE_VECTOR(to);
    REQUIRE_NOT_NULL(hit);
    queries_t *queries = ready_queries(scene);
    ray_search_t search = {scene_body_array(scene), from, vec_subtract(to, from),
                           {NULL, VEC_ZERO, VEC_ZERO, 1.0}, SIZE_MAX};
    REQUIRE(isfinite(search.d.x) && isfinite(search.d.y),
            "to - from is not finite (%g, %g): the ray is too long", search.d.x, search.d.y);
    broadphase_query_ray(queries->grid, from, to, 1.0, ray_visit, &search);
    if (search.best_index == SIZE_MAX) return false;
    *hit = search.best;
    return true;
}

/* ---- Box query and body at a point ------------------------------------------- */

typedef struct {
    queries_t *queries;
    body_t **bodies;
    aabb_t box;
} box_search_t;

static bool box_visit(void *context, uint32_t proxy) {
    box_search_t *search = context;
    queries_t *queries = search->queries;
    const body_t *body = search->bodies[proxy];
    if (body->removed || !body_overlaps_box(body, search->box)) return true;
    memory_reserve((void **)&queries->found, &queries->found_capacity, queries->found_count + 1,
                   sizeof(uint32_t));
    queries->found[queries->found_count++] = proxy;
    return true;
}

static int compare_indices(const void *a, const void *b) {
    uint32_t x = *(const uint32_t *)a, y = *(const uint32_t *)b;
    return (x > y) - (x < y);
}

/* The bodies whose shapes overlap the box, in scene order, in
 * queries->found[0 .. found_count). */
static queries_t *find_in_box(scene_t *scene, aabb_t box) {
    queries_t *queries = ready_queries(scene);
    queries->found_count = 0;
    box_search_t search = {queries, scene_body_array(scene), box};
    broadphase_query_box(queries->grid, box, box_visit, &search);
    if (queries->found_count > 1) {
        qsort(queries->found, queries->found_count, sizeof(uint32_t), compare_indices);
    }
    return queries;
}

size_t scene_query_box(scene_t *scene, vector_t min, vector_t max, body_t **bodies,
                       size_t capacity) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_FINITE_VECTOR(min);
    REQUIRE_FINITE_VECTOR(max);
    REQUIRE(min.x <= max.x && min.y <= max.y, "min (%g, %g) is not below and left of max (%g, %g)",
            min.x, min.y, max.x, max.y);
    REQUIRE(bodies != NULL || capacity == 0, "bodies is NULL with capacity %zu", capacity);
    queries_t *queries = find_in_box(scene, (aabb_t){min, max});
    body_t **all = scene_body_array(scene);
    for (size_t i = 0; i < queries->found_count && i < capacity; i++) {
        bodies[i] = all[queries->found[i]];
    }
    return queries->found_count;
}

body_t *scene_body_at(scene_t *scene, vector_t point) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_FINITE_VECTOR(point);
    /* The point's box finds the shapes holding it (boundary included). */
    queries_t *queries = find_in_box(scene, (aabb_t){point, point});
    if (queries->found_count == 0) return NULL;
    body_t *top = scene_body_array(scene)[queries->found[queries->found_count - 1]];
    return body_holds_point(top, point) ? top : NULL;
}

/* ---- Explosion --------------------------------------------------------------- */

void scene_explode(scene_t *scene, vector_t center, double radius, double impulse) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_FINITE_VECTOR(center);
    REQUIRE(isfinite(radius) && radius > 0.0, "radius must be finite and > 0 (got %g)", radius);
    REQUIRE(isfinite(impulse) && impulse >= 0.0, "impulse must be finite and >= 0 (got %g)",
            impulse);
    aabb_t box = {{center.x - radius, center.y - radius}, {center.x + radius, center.y + radius}};
    queries_t *queries = find_in_box(scene, box);
    body_t **all = scene_body_array(scene);
    for (size_t i = 0; i < queries->found_count; i++) {
        body_t *body = all[queries->found[i]];
        if (body->inverse_mass == 0.0) continue;
        vector_t nearest, direction;
        double distance = body_distance(body, center, &nearest);
        if (distance >= radius) continue;
        if (distance > 0.0) {
            direction = vec_subtract(nearest, center);
        } else {
            nearest = body->centroid;
            direction = vec_subtract(body->centroid, center);
        }
        double length = vec_get_length(direction);
        if (!(length > 0.0)) continue;
        double magnitude = impulse * (1.0 - distance / radius);
        body_add_impulse_at(body, vec_multiply(magnitude / length, direction), nearest);
    }
}
