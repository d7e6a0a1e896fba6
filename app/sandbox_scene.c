#include "sandbox_scene.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "palette.h"

/* The grab spring: a damped spring from the grab point to the cursor whose
 * stiffness and damping scale with the body's mass, so that every body follows
 * the cursor alike (natural frequency GRAB_HZ, damping ratio GRAB_ZETA), plus
 * the body's weight so it hangs at the cursor rather than below it. The force
 * is capped so a grabbed body cannot be flung through a wall. */
static const double GRAB_HZ = 3.0;
static const double GRAB_ZETA = 0.7;
static const double GRAB_MAX_ACCELERATION = 300.0; /* m/s^2 */

static rgb_color_t color_of(palette_rgb_t c) {
    return (rgb_color_t){c.r / 255.0, c.g / 255.0, c.b / 255.0};
}

/* xorshift64*: a small generator, so a seed replays the same shapes. */
static double random_unit(sandbox_t *sandbox) {
    uint64_t x = sandbox->rng;
    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    sandbox->rng = x;
    return (double)((x * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
}

/* A static box; its info is its name for messages ("inside the floor"). */
static void add_static_box(scene_t *scene, const char *name, double x0, double y0, double x1,
                           double y1) {
    list_t *shape = polygon_make_box((vector_t){0.5 * (x0 + x1), 0.5 * (y0 + y1)},
                                     0.5 * (x1 - x0), 0.5 * (y1 - y0));
    body_t *body =
        body_init_with_info(shape, INFINITY, color_of(PALETTE_STATIC), (void *)name, NULL);
    body_set_elasticity(body, 0.0);
    scene_add_body(scene, body);
}

static vector_t grab_world_point(const grab_t *grab) {
    body_t *body = grab->body;
    return vec_add(body_get_centroid(body), vec_rotate(grab->local_point, body_get_rotation(body)));
}

static void grab_force(void *aux) {
    grab_t *grab = aux;
    if (grab->body == NULL) return;
    body_t *body = grab->body;
    double mass = body_get_mass(body);
    double omega = 2.0 * M_PI * GRAB_HZ;
    vector_t point = grab_world_point(grab);
    vector_t stretch = vec_subtract(grab->target, point);
    vector_t velocity = body_get_point_velocity(body, point);
    vector_t force = vec_subtract(vec_multiply(mass * omega * omega, stretch),
                                  vec_multiply(2.0 * GRAB_ZETA * mass * omega, velocity));
    force = vec_subtract(force, vec_multiply(mass, grab->gravity));
    double limit = mass * GRAB_MAX_ACCELERATION;
    double length = vec_get_length(force);
    if (length > limit) force = vec_multiply(limit / length, force);
    body_add_force_at(body, force, point);
}

static void build(sandbox_t *sandbox) {
    scene_t *scene = scene_init();
    sandbox->scene = scene;
    sandbox->rng = sandbox->seed * 2654435769ULL + 0x9E3779B97F4A7C15ULL;
    if (sandbox->rng == 0) sandbox->rng = 1;
    sandbox->next_color = 0;
    sandbox->grab = (grab_t){0};

    const double w = SANDBOX_WALL_X, thick = 1.0;
    add_static_box(scene, "the floor", -w - thick, -thick, w + thick, 0.0);
    add_static_box(scene, "the left wall", -w - thick, 0.0, -w, SANDBOX_WALL_TOP);
    add_static_box(scene, "the right wall", w, 0.0, w + thick, SANDBOX_WALL_TOP);
    sandbox->container = (aabb_t){{-w, 0.0}, {w, SANDBOX_WALL_TOP}};
    sandbox->extent = (aabb_t){{-w - thick, -thick}, {w + thick, SANDBOX_WALL_TOP}};

    scene_set_contacts_enabled(scene, true);
    scene_set_sleeping(scene, sandbox->sleeping_on);
    scene_set_integrator(scene, sandbox->integrator);
    sandbox_set_gravity(sandbox, true);
    sandbox->changes++;
    /* The grab spring is registered once; it does nothing while grab.body is
     * NULL. It depends on no body: the sandbox clears grab.body itself before
     * it removes the grabbed body. */
    scene_add_bodies_force_creator(scene, grab_force, &sandbox->grab, list_init(0, NULL), NULL);
}

void sandbox_init(sandbox_t *sandbox, uint64_t seed) {
    *sandbox = (sandbox_t){0};
    sandbox->seed = seed;
    sandbox->integrator = INTEGRATOR_SEED;
    sandbox->sleeping_on = true;
    build(sandbox);
}

void sandbox_free(sandbox_t *sandbox) {
    if (sandbox->scene != NULL) scene_free(sandbox->scene);
    sandbox->scene = NULL;
    sandbox->grab.body = NULL;
}

void sandbox_reset(sandbox_t *sandbox) {
    sandbox_free(sandbox);
    build(sandbox);
}

bool sandbox_is_static(body_t *body) {
    return isinf(body_get_mass(body));
}

size_t sandbox_clear(sandbox_t *sandbox) {
    sandbox->grab.body = NULL;
    size_t removed = 0;
    for (size_t i = 0; i < scene_bodies(sandbox->scene); i++) {
        body_t *body = scene_get_body(sandbox->scene, i);
        if (sandbox_is_static(body) || body_is_removed(body)) continue;
        body_remove(body);
        removed++;
    }
    if (removed > 0) sandbox->changes++;
    return removed;
}

/* Points on an ellipse at increasing angles are in convex position; the
 * angle steps are kept apart so no two vertices nearly coincide. */
static list_t *random_polygon(sandbox_t *sandbox, double size) {
    size_t count = 5 + (size_t)(random_unit(sandbox) * 5.0); /* 5 to 9 */
    if (count > 9) count = 9;
    double steps[9], total = 0.0;
    for (size_t i = 0; i < count; i++) {
        steps[i] = 0.5 + random_unit(sandbox);
        total += steps[i];
    }
    double stretch = 0.65 + 0.35 * random_unit(sandbox);
    double turn = 2.0 * M_PI * random_unit(sandbox);
    double angle = 0.0;
    list_t *shape = list_init(count, free);
    for (size_t i = 0; i < count; i++) {
        vector_t *v = malloc(sizeof(vector_t));
        *v = vec_rotate((vector_t){size * cos(angle), size * stretch * sin(angle)}, turn);
        list_add(shape, v);
        angle += 2.0 * M_PI * steps[i] / total;
    }
    return shape;
}

list_t *sandbox_make_shape(sandbox_t *sandbox, shape_choice_t shape, const char **problem) {
    *problem = NULL;
    if (!(shape.size >= SHAPE_MIN_SIZE && shape.size <= SHAPE_MAX_SIZE)) {
        *problem = "size out of range";
        return NULL;
    }
    list_t *vertices = NULL;
    switch (shape.kind) {
    case SHAPE_REGULAR:
        if (shape.sides < 3 || shape.sides > 8) {
            *problem = "a regular polygon has 3 to 8 sides";
            return NULL;
        }
        /* A flat bottom edge: the first vertex half a step right of straight down. */
        vertices = polygon_make_regular((size_t)shape.sides, shape.size, VEC_ZERO,
                                        -M_PI / 2.0 - M_PI / shape.sides);
        break;
    case SHAPE_BOX:
        vertices = polygon_make_box(VEC_ZERO, shape.size, 0.6 * shape.size);
        break;
    case SHAPE_RANDOM:
        vertices = random_polygon(sandbox, shape.size);
        break;
    }
    if (vertices == NULL) {
        *problem = "unknown shape";
        return NULL;
    }
    const char *check = polygon_check(vertices);
    if (check != NULL) {
        list_free(vertices);
        *problem = check;
        return NULL;
    }
    return vertices;
}

/* The static body containing point, or NULL. */
static body_t *static_at(sandbox_t *sandbox, vector_t point) {
    for (size_t i = 0; i < scene_bodies(sandbox->scene); i++) {
        body_t *body = scene_get_body(sandbox->scene, i);
        if (sandbox_is_static(body) && !body_is_removed(body) &&
            body_contains_point(body, point)) {
            return body;
        }
    }
    return NULL;
}

static bool inside(aabb_t box, vector_t point) {
    return point.x > box.min.x && point.x < box.max.x && point.y > box.min.y &&
           point.y < box.max.y;
}

const char *sandbox_place(sandbox_t *sandbox, list_t *vertices, vector_t at, vector_t *placed) {
    *placed = at;
    if (!vec_is_finite(at)) return "not a finite position";
    body_t *wall = static_at(sandbox, at);
    if (wall != NULL) {
        const char *name = body_get_info(wall);
        snprintf(sandbox->refusal, sizeof(sandbox->refusal), "inside %s",
                 name != NULL ? name : "a static body");
        return sandbox->refusal;
    }
    if (!inside(sandbox->container, at)) return "outside the container";
    /* The shape's extent around its centroid, where the drop puts `at`. */
    vector_t centroid = polygon_centroid(vertices);
    vector_t low = {INFINITY, INFINITY}, high = {-INFINITY, -INFINITY};
    for (size_t i = 0; i < list_size(vertices); i++) {
        vector_t v = vec_subtract(*(vector_t *)list_get(vertices, i), centroid);
        low = (vector_t){fmin(low.x, v.x), fmin(low.y, v.y)};
        high = (vector_t){fmax(high.x, v.x), fmax(high.y, v.y)};
    }
    aabb_t box = sandbox->container;
    if (at.y + low.y < box.min.y) placed->y = box.min.y - low.y;
    if (at.x + low.x < box.min.x) placed->x = box.min.x - low.x;
    if (at.x + high.x > box.max.x) placed->x = box.max.x - high.x;
    return NULL;
}

bool sandbox_bodies_bounds(sandbox_t *sandbox, aabb_t *bounds) {
    bool any = false;
    for (size_t i = 0; i < scene_bodies(sandbox->scene); i++) {
        body_t *body = scene_get_body(sandbox->scene, i);
        if (body_is_removed(body) || sandbox_is_static(body)) continue;
        aabb_t box = body_get_bounds(body);
        *bounds = any ? aabb_union(*bounds, box) : box;
        any = true;
    }
    return any;
}

list_t *sandbox_copy_vertices(list_t *vertices) {
    list_t *copy = list_init(list_size(vertices), free);
    for (size_t i = 0; i < list_size(vertices); i++) {
        vector_t *v = malloc(sizeof(vector_t));
        *v = *(vector_t *)list_get(vertices, i);
        list_add(copy, v);
    }
    return copy;
}

body_t *sandbox_drop(sandbox_t *sandbox, list_t *vertices, vector_t at, vector_t velocity,
                     double elasticity, const char **problem) {
    *problem = NULL;
    if (!vec_is_finite(at) || !vec_is_finite(velocity) || !isfinite(elasticity)) {
        *problem = "position, velocity or elasticity is not finite";
    } else {
        *problem = polygon_check(vertices);
    }
    if (*problem != NULL) {
        list_free(vertices);
        return NULL;
    }
    double mass = SANDBOX_DENSITY * fabs(polygon_area(vertices));
    palette_rgb_t color = PALETTE_BODIES[sandbox->next_color++ % PALETTE_BODY_COUNT];
    body_t *body = body_init(vertices, mass, color_of(color));
    body_set_centroid(body, at);
    body_set_velocity(body, velocity);
    body_set_elasticity(body, fmax(0.0, elasticity));
    scene_add_body(sandbox->scene, body);
    sandbox->changes++;
    return body;
}

void sandbox_spawn(sandbox_t *sandbox, size_t count, double size, double elasticity) {
    double spacing = 2.2 * size;
    size_t per_row = (size_t)floor(2.0 * SANDBOX_WALL_X / spacing);
    if (per_row == 0) per_row = 1;
    for (size_t i = 0; i < count; i++) {
        size_t row = i / per_row, column = i % per_row;
        vector_t at = {-SANDBOX_WALL_X + spacing * (column + 0.5) + (row % 2) * 0.25 * size,
                       spacing * (row + 0.5) + 0.1};
        shape_choice_t shape = {SHAPE_REGULAR, 3 + (int)(i % 6), size};
        if (i % 7 == 6) shape.kind = SHAPE_BOX;
        const char *problem;
        list_t *vertices = sandbox_make_shape(sandbox, shape, &problem);
        if (vertices != NULL) sandbox_drop(sandbox, vertices, at, VEC_ZERO, elasticity, &problem);
    }
}

body_t *sandbox_body_at(sandbox_t *sandbox, vector_t point) {
    for (size_t i = scene_bodies(sandbox->scene); i-- > 0;) {
        body_t *body = scene_get_body(sandbox->scene, i);
        if (body_is_removed(body) || sandbox_is_static(body)) continue;
        if (body_contains_point(body, point)) return body;
    }
    return NULL;
}

void sandbox_delete(sandbox_t *sandbox, body_t *body) {
    if (body == NULL || sandbox_is_static(body)) return;
    if (sandbox->grab.body == body) sandbox->grab.body = NULL;
    if (!body_is_removed(body)) sandbox->changes++;
    body_remove(body);
}

void sandbox_grab(sandbox_t *sandbox, body_t *body, vector_t point) {
    if (body == NULL || sandbox_is_static(body) || body_is_removed(body)) return;
    sandbox->grab.body = body;
    sandbox->grab.local_point =
        vec_rotate(vec_subtract(point, body_get_centroid(body)), -body_get_rotation(body));
    sandbox->grab.target = point;
}

void sandbox_grab_move(sandbox_t *sandbox, vector_t target) {
    if (vec_is_finite(target)) sandbox->grab.target = target;
}

void sandbox_release(sandbox_t *sandbox) {
    sandbox->grab.body = NULL;
}

vector_t sandbox_grab_point(sandbox_t *sandbox) {
    return sandbox->grab.body != NULL ? grab_world_point(&sandbox->grab) : sandbox->grab.target;
}

void sandbox_set_gravity(sandbox_t *sandbox, bool on) {
    sandbox->gravity_on = on;
    vector_t gravity = on ? (vector_t){0.0, -SANDBOX_GRAVITY} : VEC_ZERO;
    scene_set_gravity(sandbox->scene, gravity);
    sandbox->grab.gravity = gravity;
}

void sandbox_set_integrator(sandbox_t *sandbox, integrator_t integrator) {
    sandbox->integrator = integrator;
    scene_set_integrator(sandbox->scene, integrator);
}

void sandbox_set_sleeping(sandbox_t *sandbox, bool on) {
    sandbox->sleeping_on = on;
    scene_set_sleeping(sandbox->scene, on);
}

void sandbox_step(sandbox_t *sandbox, double dt) {
    scene_tick(sandbox->scene, dt);
    for (size_t i = 0; i < scene_bodies(sandbox->scene); i++) {
        body_t *body = scene_get_body(sandbox->scene, i);
        if (!body_is_removed(body) && body_get_centroid(body).y < SANDBOX_KILL_Y) {
            sandbox_delete(sandbox, body);
        }
    }
}

sandbox_totals_t sandbox_totals(sandbox_t *sandbox) {
    sandbox_totals_t totals = {0};
    vector_t gravity = scene_get_gravity(sandbox->scene);
    for (size_t i = 0; i < scene_bodies(sandbox->scene); i++) {
        body_t *body = scene_get_body(sandbox->scene, i);
        if (body_is_removed(body) || sandbox_is_static(body)) continue;
        double mass = body_get_mass(body);
        totals.bodies++;
        totals.sleeping += body_is_sleeping(body);
        totals.kinetic += body_get_kinetic_energy(body);
        totals.potential -= mass * vec_dot(gravity, body_get_centroid(body));
        totals.momentum = vec_add(totals.momentum, vec_multiply(mass, body_get_velocity(body)));
    }
    return totals;
}

const char *sandbox_shape_name(shape_choice_t shape) {
    static const char *const names[] = {"triangle", "square",  "pentagon",
                                        "hexagon",  "heptagon", "octagon"};
    switch (shape.kind) {
    case SHAPE_REGULAR:
        if (shape.sides >= 3 && shape.sides <= 8) return names[shape.sides - 3];
        return "polygon";
    case SHAPE_BOX:
        return "box";
    case SHAPE_RANDOM:
        return "random";
    }
    return "?";
}
