#include "jostle/body.h"
#include <math.h>
#include <stdio.h>
#include "dynamics/body_private.h"
#include "base/check.h"
#include "base/memory.h"
#include "geometry/polygon_array.h"
#include "base/scalar.h"

static const double DEFAULT_FRICTION = 0.6;

/* body_init and body_init_with_info share this; `function` is the one the
 * caller called, so that a refusal names it. */
void body_check_mass(double mass, const char *function) {
    if (isnan(mass)) engine_fail(function, "mass is NaN");
    if (!(mass > 0.0)) engine_fail(function, "mass must be > 0 or INFINITY (got %g)", mass);
    /* A subnormal mass: the first step would multiply by 1 / m = inf. */
    if (!isfinite(1.0 / mass)) {
        engine_fail(function, "mass %g kg is too small: its inverse is not finite", mass);
    }
}

/* The moment of inertia of the centred shape with this mass; refused when it
 * or its inverse is not finite, as a body could not turn correctly. */
static double shape_moment(const vector_t *vertices, size_t count, double mass,
                           const char *function) {
    if (isinf(mass)) return INFINITY;
    double moment = polygon_array_moment(vertices, count, mass);
    /* That multiplies the mass into a sum of lengths to the fourth before
     * dividing by the area, which can overflow or underflow where the moment
     * itself does not; the per-kilogram moment times the mass cannot. */
    if (!isnormal(moment)) moment = mass * polygon_array_moment(vertices, count, 1.0);
    return body_checked_moment(moment, mass, function);
}

double body_checked_moment(double moment, double mass, const char *function) {
    if (!isfinite(moment)) {
        engine_fail(function,
                    "the moment of inertia of this shape with mass %g kg is not finite; "
                    "give a body that must not move mass INFINITY",
                    mass);
    }
    if (!isfinite(1.0 / moment)) {
        engine_fail(function,
                    "the moment of inertia of this shape with mass %g kg, %g kg m^2, is too "
                    "small: its inverse is not finite",
                    mass, moment);
    }
    return moment;
}

body_t *body_allocate(size_t count) {
    body_t *body = memory_calloc(1, sizeof(body_t) + 4 * count * sizeof(vector_t));
    body->count = count;
    body->world_vertices = body->shape;
    body->world_normals = body->shape + count;
    body->local_vertices = body->shape + 2 * count;
    body->local_normals = body->shape + 3 * count;
    return body;
}

void body_set_defaults(body_t *body, double mass, double inertia, rgb_color_t color, void *info,
                       free_func_t info_freer) {
    body->mass = mass;
    body->inverse_mass = isinf(mass) ? 0.0 : 1.0 / mass;
    body->inertia = inertia;
    body->inverse_inertia = isinf(mass) ? 0.0 : 1.0 / body->inertia;
    body->friction = DEFAULT_FRICTION;
    body->category = 1;
    body->mask = UINT32_MAX;
    body->color = color;
    body->info = info;
    body->info_freer = info_freer;
}

/* Takes the shape list's vertices into a new body, counter-clockwise: one
 * block holds the body and its four vertex arrays (body_private.h). */
static body_t *take_vertices(list_t *shape, const char *function) {
    const char *problem = polygon_check(shape);
    if (problem != NULL) engine_fail(function, "bad shape: %s", problem);
    size_t count = list_size(shape);
    body_t *body = body_allocate(count);
    vector_t *vertices = body->local_vertices;
    for (size_t i = 0; i < count; i++) vertices[i] = *(vector_t *)list_get(shape, i);
    if (polygon_array_signed_area(vertices, count) < 0.0) {
        for (size_t i = 0; i < count / 2; i++) {
            vector_t swap = vertices[i];
            vertices[i] = vertices[count - 1 - i];
            vertices[count - 1 - i] = swap;
        }
    }
    list_free(shape);
    return body;
}

/* A shape given relative to its centroid may be off it by this share of its
 * radius: rounding, but not a shape placed elsewhere. */
static const double CENTRED_TOLERANCE = 1e-3;

/* centred: the vertices are already relative to the centroid and are kept
 * as they are (body_init_centred). */
static body_t *body_create(list_t *shape, double mass, rgb_color_t color, void *info,
                           free_func_t info_freer, bool centred, const char *function) {
    if (shape == NULL) engine_fail(function, "shape is NULL");
    body_check_mass(mass, function);
    body_t *body = take_vertices(shape, function);
    size_t n = body->count;

    body->centroid = polygon_array_centroid(body->local_vertices, n);
    vector_t off = centred ? body->centroid : VEC_ZERO;
    if (centred) body->centroid = VEC_ZERO;
    for (size_t i = 0; i < n; i++) {
        body->local_vertices[i] = vec_subtract(body->local_vertices[i], body->centroid);
        body->radius = fmax(body->radius, vec_get_length(body->local_vertices[i]));
    }
    /* The centroid's sums grow as the cube of the size: a shape polygon_check
     * accepts can still overflow them. */
    if (!vec_is_finite(body->centroid) || !vec_is_finite(off) || !isfinite(body->radius)) {
        engine_fail(function, "bad shape: polygon is too large: its centroid is not finite");
    }
    if (vec_get_length(off) > CENTRED_TOLERANCE * body->radius) {
        engine_fail(function,
                    "bad shape: its centroid (%g, %g) is not at the origin (within %g of its "
                    "radius %g m)",
                    off.x, off.y, CENTRED_TOLERANCE, body->radius);
    }
    for (size_t i = 0; i < n; i++) {
        vector_t edge = vec_subtract(body->local_vertices[(i + 1) % n], body->local_vertices[i]);
        body->local_normals[i] = vec_normalize((vector_t){edge.y, -edge.x});
    }
    double inertia = shape_moment(body->local_vertices, n, mass, function);
    body_set_defaults(body, mass, inertia, color, info, info_freer);
    return body;
}

body_t *body_init_with_info(list_t *shape, double mass, rgb_color_t color, void *info,
                            free_func_t info_freer) {
    return body_create(shape, mass, color, info, info_freer, false, __func__);
}

body_t *body_init(list_t *shape, double mass, rgb_color_t color) {
    return body_create(shape, mass, color, NULL, NULL, false, __func__);
}

body_t *body_init_centred(list_t *shape, double mass, rgb_color_t color, void *info,
                          free_func_t info_freer) {
    return body_create(shape, mass, color, info, info_freer, true, __func__);
}

void body_free(body_t *body) {
    REQUIRE_NOT_NULL(body);
    REQUIRE(!body->in_scene,
            "body belongs to a scene, which frees it: mark it with body_remove instead (the "
            "scene frees it at the end of the next scene_tick)");
    REQUIRE(body->scene == NULL,
            "body is named by a force creator of a scene: add it to that scene (which then "
            "frees it), or free it after scene_free of that scene");
    body_wake(body);
    if (body->info_freer != NULL) body->info_freer(body->info);
    for (size_t k = 0; k < body->part_count; k++) {
        memory_free(body->parts[k]->segment);
        memory_free(body->parts[k]);
    }
    memory_free(body->parts);
    memory_free(body);
}

/* A chain's segments follow its pose (body_private.h): each turned as the
 * chain is, at its offset in the chain's frame. */
static void place_parts(body_t *body) {
    if (body->part_count == 0) return;
    body_update_world(body);
    for (size_t k = 0; k < body->part_count; k++) {
        body_t *part = body->parts[k];
        body_mark_changed(part); /* before: its box there is needed */
        part->angle = body->angle;
        part->centroid = body_to_world(body, part->segment->offset);
        part->world_valid = WORLD_STALE;
    }
}

/* A chain's segments take its material, filter and colour. */
static void copy_to_parts(body_t *body) {
    for (size_t k = 0; k < body->part_count; k++) {
        body_t *part = body->parts[k];
        if (part->friction != body->friction || part->elasticity != body->elasticity ||
            part->category != body->category || part->mask != body->mask ||
            part->group != body->group) {
            body_mark_changed(part);
        }
        part->friction = body->friction;
        part->elasticity = body->elasticity;
        part->category = body->category;
        part->mask = body->mask;
        part->group = body->group;
        part->color = body->color;
    }
}

/* A chain does not move (body.h); `function` is the setter called. */
static void require_still(const body_t *body, bool moving, const char *what,
                          const char *function) {
    if (body->kind == BODY_SHAPE_CHAIN && moving) {
        engine_fail(function, "a chain is static: it cannot be given %s", what);
    }
}

void body_update_pose(body_t *body) {
    if (body->world_valid != WORLD_STALE) return;
    if (body->kind != BODY_SHAPE_CIRCLE && body->kind != BODY_SHAPE_CAPSULE) {
        body_update_world(body);
        return;
    }
    body->rotation_cos = cos(body->angle);
    body->rotation_sin = sin(body->angle);
    body->bounds = body_round_bounds(body);
    body->world_valid = WORLD_POSE;
}

void body_update_world(body_t *body) {
    if (body->world_valid == WORLD_FULL) return;
    body->rotation_cos = cos(body->angle);
    body->rotation_sin = sin(body->angle);
    aabb_t bounds = {{INFINITY, INFINITY}, {-INFINITY, -INFINITY}};
    for (size_t i = 0; i < body->count; i++) {
        vector_t p = body_to_world(body, body->local_vertices[i]);
        body->world_vertices[i] = p;
        body->world_normals[i] = body_rotate_vector(body, body->local_normals[i]);
        bounds.min.x = min_of(bounds.min.x, p.x);
        bounds.min.y = min_of(bounds.min.y, p.y);
        bounds.max.x = max_of(bounds.max.x, p.x);
        bounds.max.y = max_of(bounds.max.y, p.y);
    }
    bool round = body->kind == BODY_SHAPE_CIRCLE || body->kind == BODY_SHAPE_CAPSULE;
    body->bounds = round ? body_round_bounds(body) : bounds;
    body->world_valid = WORLD_FULL;
}

list_t *body_get_shape(body_t *body) {
    REQUIRE_NOT_NULL(body);
    body_update_world(body);
    list_t *shape = list_init(body->count, memory_free);
    for (size_t i = 0; i < body->count; i++) {
        vector_t *vertex = memory_alloc(sizeof(vector_t));
        *vertex = body->world_vertices[i];
        list_add(shape, vertex);
    }
    return shape;
}

polygon_t body_get_polygon(body_t *body) {
    REQUIRE_NOT_NULL(body);
    body_update_world(body);
    return (polygon_t){body->count, body->world_vertices, body->world_normals};
}

polygon_t body_get_local_polygon(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return (polygon_t){body->count, body->local_vertices, body->local_normals};
}

aabb_t body_get_bounds(body_t *body) {
    REQUIRE_NOT_NULL(body);
    body_update_world(body);
    return body->bounds;
}

vector_t body_get_centroid(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->centroid;
}

vector_t body_get_velocity(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->velocity;
}

double body_get_mass(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->mass;
}

rgb_color_t body_get_color(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->color;
}

double body_get_rotation(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->angle;
}

void *body_get_info(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->info;
}

void body_wake(body_t *body) {
    if (body->asleep && body->sleep_changes != NULL) (*body->sleep_changes)++;
    body_t *member = body;
    do {
        body_t *next = member->sleep_next;
        member->asleep = false;
        member->sleep_time = 0.0;
        member->sleep_next = NULL;
        member = next;
    } while (member != NULL && member != body);
}

void body_mark_changed(body_t *body) {
    if (!body->changed) {
        body_update_world(body);
        body->changed_bounds = body->bounds;
        body->changed = true;
    }
    body_wake(body);
}

bool body_is_sleeping(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->asleep;
}

void body_set_centroid(body_t *body, vector_t x) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_FINITE_VECTOR(x);
    body_mark_changed(body); /* before: its box there is needed */
    body->centroid = x;
    body->world_valid = false;
    body_note_move(body);
    place_parts(body);
}

void body_set_velocity(body_t *body, vector_t v) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_FINITE_VECTOR(v);
    require_still(body, v.x != 0.0 || v.y != 0.0, "a velocity", __func__);
    body->velocity = v;
    body_mark_changed(body);
}

void body_set_rotation(body_t *body, double angle) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_FINITE(angle);
    body_mark_changed(body);
    body->angle = angle;
    body->world_valid = false;
    body_note_move(body);
    place_parts(body);
}

void body_set_color(body_t *body, rgb_color_t color) {
    REQUIRE_NOT_NULL(body);
    body->color = color;
    copy_to_parts(body);
}

void body_add_force(body_t *body, vector_t force) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_FINITE_VECTOR(force);
    body_push(body, force);
}

void body_add_impulse(body_t *body, vector_t impulse) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_FINITE_VECTOR(impulse);
    body->impulse = vec_add(body->impulse, impulse);
    if (impulse.x != 0.0 || impulse.y != 0.0) body_wake(body);
}

void body_add_torque(body_t *body, double torque) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_FINITE(torque);
    body->torque += torque;
    if (torque != 0.0) body_wake(body);
}

void body_add_force_at(body_t *body, vector_t force, vector_t point) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_FINITE_VECTOR(force);
    REQUIRE_FINITE_VECTOR(point);
    body->torque += vec_cross(vec_subtract(point, body->centroid), force);
    body_push(body, force);
}

void body_add_impulse_at(body_t *body, vector_t impulse, vector_t point) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_FINITE_VECTOR(impulse);
    REQUIRE_FINITE_VECTOR(point);
    body->impulse = vec_add(body->impulse, impulse);
    body->angular_impulse += vec_cross(vec_subtract(point, body->centroid), impulse);
    if (impulse.x != 0.0 || impulse.y != 0.0) body_wake(body);
}

vector_t body_get_point_velocity(body_t *body, vector_t point) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_FINITE_VECTOR(point);
    return vec_add(body->velocity,
                   vec_cross_scalar(body->angular_velocity, vec_subtract(point, body->centroid)));
}

void body_explain_non_finite(const body_t *body, const body_motion_t *before, double dt,
                             char *message, size_t size) {
    /* A velocity that overflowed makes the pose overflow too: it is the cause. */
    if (!vec_is_finite(body->velocity)) {
        snprintf(message, size,
                 "velocity is not finite after integrating with dt = %g s; likely cause: the "
                 "step's velocity change (F / m + g) dt + J / m overflows, with force (%g, %g) N "
                 "and impulse (%g, %g) N s (contact impulses included) on mass %g kg",
                 dt, before->force.x, before->force.y, before->impulse.x, before->impulse.y,
                 body->mass);
    } else if (!isfinite(body->angular_velocity)) {
        snprintf(message, size,
                 "angular velocity is not finite after integrating with dt = %g s; likely cause: "
                 "the step's change T dt / I + L / I overflows, with torque %g N m and angular "
                 "impulse %g N m s (contact impulses included) on moment of inertia %g kg m^2",
                 dt, before->torque, before->angular_impulse, body->inertia);
    } else if (!vec_is_finite(body->centroid)) {
        snprintf(message, size,
                 "position is not finite after integrating with dt = %g s; likely cause: dt is "
                 "too large for its velocity (%g, %g) m/s: the step's displacement overflows",
                 dt, body->velocity.x, body->velocity.y);
    } else {
        snprintf(message, size,
                 "angle is not finite after integrating with dt = %g s; likely cause: dt is too "
                 "large for its angular velocity %g rad/s: the step's turn overflows",
                 dt, body->angular_velocity);
    }
}

void body_reset(body_t *body) {
    REQUIRE_NOT_NULL(body);
    body_clear_accumulators(body);
}

void body_remove(body_t *body) {
    REQUIRE_NOT_NULL(body);
    body->removed = true;
    body_mark_changed(body);
    for (size_t k = 0; k < body->part_count; k++) {
        body->parts[k]->removed = true;
        body_mark_changed(body->parts[k]);
    }
}

bool body_is_removed(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->removed;
}

double body_get_angular_velocity(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->angular_velocity;
}

void body_set_angular_velocity(body_t *body, double omega) {
    REQUIRE_NOT_NULL(body);
    REQUIRE_FINITE(omega);
    require_still(body, omega != 0.0, "an angular velocity", __func__);
    body->angular_velocity = omega;
    body_mark_changed(body);
}

double body_get_inertia(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->inertia;
}

void body_set_inertia(body_t *body, double inertia) {
    REQUIRE_NOT_NULL(body);
    REQUIRE(inertia > 0.0, "inertia must be > 0 or INFINITY (got %g)", inertia);
    REQUIRE(isfinite(1.0 / inertia), "inertia %g kg m^2 is too small: its inverse is not finite",
            inertia);
    require_still(body, !isinf(inertia), "a finite moment of inertia", __func__);
    body->inertia = inertia;
    body->inverse_inertia = isinf(inertia) ? 0.0 : 1.0 / inertia;
    body_mark_changed(body);
}

double body_get_elasticity(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->elasticity;
}

void body_set_elasticity(body_t *body, double elasticity) {
    REQUIRE_NOT_NULL(body);
    REQUIRE(isfinite(elasticity) && elasticity >= 0.0,
            "elasticity must be finite and >= 0 (got %g)", elasticity);
    if (elasticity != body->elasticity) body_mark_changed(body);
    body->elasticity = elasticity;
    copy_to_parts(body);
}

double body_get_friction(body_t *body) {
    REQUIRE_NOT_NULL(body);
    return body->friction;
}

void body_set_friction(body_t *body, double friction) {
    REQUIRE_NOT_NULL(body);
    REQUIRE(isfinite(friction) && friction >= 0.0, "friction must be finite and >= 0 (got %g)",
            friction);
    if (friction != body->friction) body_mark_changed(body);
    body->friction = friction;
    copy_to_parts(body);
}

void body_set_collision_filter(body_t *body, uint32_t category, uint32_t mask, uint32_t group) {
    REQUIRE_NOT_NULL(body);
    body->category = category;
    body->mask = mask;
    body->group = group;
    body_mark_changed(body);
    copy_to_parts(body);
}

void body_get_collision_filter(body_t *body, uint32_t *category, uint32_t *mask,
                               uint32_t *group) {
    REQUIRE_NOT_NULL(body);
    if (category != NULL) *category = body->category;
    if (mask != NULL) *mask = body->mask;
    if (group != NULL) *group = body->group;
}

/* Whether the point lies on one of the chain's segments: its distance from
 * the segment's line is 0 and it lies between the ends. */
static bool chain_contains(const body_t *body, vector_t point) {
    for (size_t i = 0; i < body->part_count; i++) {
        vector_t p1 = body->world_vertices[i], p2 = body->world_vertices[(i + 1) % body->count];
        vector_t d = vec_subtract(p2, p1), r = vec_subtract(point, p1);
        double t = vec_dot(r, d);
        if (vec_cross(d, r) == 0.0 && t >= 0.0 && t <= vec_dot(d, d)) return true;
    }
    return false;
}

bool body_contains_point(body_t *body, vector_t point) {
    REQUIRE_NOT_NULL(body);
    /* A NaN point would compare false against every edge and so be "inside". */
    REQUIRE_FINITE_VECTOR(point);
    body_update_world(body);
    if (body->kind == BODY_SHAPE_CHAIN) return chain_contains(body, point);
    if (body->kind != BODY_SHAPE_POLYGON) return body_round_contains(body, point);
    for (size_t i = 0; i < body->count; i++) {
        if (vec_dot(body->world_normals[i], vec_subtract(point, body->world_vertices[i])) > 0.0) {
            return false;
        }
    }
    return true;
}

double body_get_kinetic_energy(body_t *body) {
    REQUIRE_NOT_NULL(body);
    double energy = 0.0;
    if (body->inverse_mass > 0.0) energy += 0.5 * body->mass * vec_get_length_squared(body->velocity);
    if (body->inverse_inertia > 0.0) {
        energy += 0.5 * body->inertia * body->angular_velocity * body->angular_velocity;
    }
    return energy;
}
