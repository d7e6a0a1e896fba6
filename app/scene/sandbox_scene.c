#include "scene/sandbox_scene.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "draw/palette.h"

/* The grab (sandbox_scene.h): both forms follow the cursor at GRAB_HZ with
 * damping ratio GRAB_ZETA, their force capped at GRAB_MAX_ACCELERATION
 * times the body's mass. */
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

static vector_t grab_world_point(const grab_t *grab) {
    body_t *body = grab->body;
    return vec_add(body_get_centroid(body), vec_rotate(grab->local_point, body_get_rotation(body)));
}

/* The grab as a spring, in scenes without world contacts. */
static void grab_force(void *aux) {
    grab_t *grab = aux;
    if (grab->body == NULL || grab->joint != NULL) return;
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

/* The default scene. Its static colour is PALETTE_STATIC (92, 98, 112), which
 * the smoke tests look for; its tags name the bodies in messages ("cannot
 * drop inside the left wall"). */
const char SANDBOX_DEFAULT_SCENE[] =
    "# The sandbox's default scene: an open container, a floor and two walls.\n"
    "category Basics\n"
    "note an empty box: click to drop shapes, Shift-drag to throw them, right-drag to "
    "pull one\n"
    "gravity 0 -10\n"
    "contacts on\n"
    "timestep 1/120\n"
    "view 0 14.5 31 32   # the container with its floor and walls, and 0.5 m around\n"
    "body floor      { box 30 1; static; position 0 -0.5;   elasticity 0; "
    "color 92/255 98/255 112/255; tag floor }\n"
    "body left_wall  { box 1 30; static; position -14.5 15; elasticity 0; "
    "color 92/255 98/255 112/255; tag left_wall }\n"
    "body right_wall { box 1 30; static; position 14.5 15;  elasticity 0; "
    "color 92/255 98/255 112/255; tag right_wall }\n";

void sandbox_scene_name(const char *path, char *name, size_t size) {
    if (size == 0) return;
    const char *base = strrchr(path, '/');
    base = base != NULL ? base + 1 : path;
    size_t length = strlen(base);
    if (length > 6 && strcmp(base + length - 6, ".scene") == 0) length -= 6;
    if (length > size - 1) length = size - 1;
    memcpy(name, base, length);
    name[length] = '\0';
}

bool sandbox_load(const char *path, sandbox_loaded_t *loaded, char *error, size_t error_size) {
    *loaded = (sandbox_loaded_t){0};
    scene_file_error_t problem;
    scene_file_t *file =
        path != NULL ? scene_file_load(path, &problem)
                     : scene_file_parse(SANDBOX_DEFAULT_SCENE, strlen(SANDBOX_DEFAULT_SCENE),
                                        SANDBOX_DEFAULT_NAME, &problem);
    if (file == NULL) {
        snprintf(error, error_size, "%s", problem.message);
        return false;
    }
    char why[256];
    game_t *game = game_start(file, why, sizeof(why));
    if (game == NULL && why[0] != '\0') {
        snprintf(error, error_size, "%s: %s", path != NULL ? path : SANDBOX_DEFAULT_NAME, why);
        scene_file_free(file);
        return false;
    }
    loaded->file = file;
    loaded->game = game;
    loaded->is_default = path == NULL;
    if (path != NULL) snprintf(loaded->path, sizeof(loaded->path), "%s", path);
    return true;
}

void sandbox_loaded_free(sandbox_loaded_t *loaded) {
    game_free(loaded->game); /* the game before its file */
    scene_file_free(loaded->file);
    *loaded = (sandbox_loaded_t){0};
}

/* What the default view shows of a file without a view: every body, with a
 * tenth around them. */
static aabb_t bodies_box(scene_t *scene) {
    aabb_t box = {{-10.0, -10.0}, {10.0, 10.0}};
    bool any = false;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        aabb_t b = body_get_bounds(scene_get_body(scene, i));
        box = any ? aabb_union(box, b) : b;
        any = true;
    }
    vector_t margin = vec_multiply(0.05, vec_subtract(box.max, box.min));
    margin = (vector_t){fmax(margin.x, 0.5), fmax(margin.y, 0.5)};
    return (aabb_t){vec_subtract(box.min, margin), vec_add(box.max, margin)};
}

void sandbox_show(sandbox_t *sandbox, sandbox_loaded_t *loaded, bool keep_integrator) {
    sandbox_free(sandbox);
    sandbox->file = loaded->file;
    sandbox->game = loaded->game;
    sandbox->scene = scene_file_get_scene(loaded->file);
    sandbox->is_default = loaded->is_default;
    snprintf(sandbox->path, sizeof(sandbox->path), "%s", loaded->path);
    if (loaded->is_default) {
        snprintf(sandbox->name, sizeof(sandbox->name), "%s", SANDBOX_DEFAULT_NAME);
    } else {
        sandbox_scene_name(loaded->path, sandbox->name, sizeof(sandbox->name));
    }
    *loaded = (sandbox_loaded_t){0};

    scene_t *scene = sandbox->scene;
    sandbox->step = scene_file_get_timestep(sandbox->file);
    sandbox->file_step = sandbox->step;
    sandbox->tick = sandbox->step;
    sandbox->stepping = scene_file_get_stepping(sandbox->file);
    scene_file_view_t view = scene_file_get_view(sandbox->file);
    if (view.has_view) {
        vector_t half = {0.5 * view.width, 0.5 * view.height};
        sandbox->home = (aabb_t){vec_subtract(view.center, half), vec_add(view.center, half)};
    } else {
        sandbox->home = bodies_box(scene);
    }
    sandbox->container = sandbox->is_default
                             ? (aabb_t){{-SANDBOX_WALL_X, 0.0}, {SANDBOX_WALL_X, SANDBOX_WALL_TOP}}
                             : sandbox->home;
    vector_t gravity = scene_get_gravity(scene);
    bool has_gravity = gravity.x != 0.0 || gravity.y != 0.0;
    sandbox->gravity = has_gravity ? gravity : (vector_t){0.0, -SANDBOX_GRAVITY};
    sandbox->gravity_on = has_gravity;
    sandbox->grab = (grab_t){0};
    sandbox->grab.gravity = gravity;
    sandbox->input = (game_input_t){0};
    sandbox->file_integrator = sandbox->is_default ? sandbox->default_integrator
                                                   : scene_get_integrator(scene);
    if (!keep_integrator) sandbox->integrator = sandbox->file_integrator;
    scene_set_integrator(scene, sandbox->integrator);
    scene_set_sleeping(scene, sandbox->sleeping_on);
    size_t workers = scene_file_get_workers(sandbox->file);
    if (workers == 0) workers = SANDBOX_WORKERS;
    scene_set_workers(scene, workers < SANDBOX_MAX_WORKERS ? workers : SANDBOX_MAX_WORKERS);
    sandbox->rng = sandbox->seed * 2654435769ULL + 0x9E3779B97F4A7C15ULL;
    if (sandbox->rng == 0) sandbox->rng = 1;
    sandbox->next_color = 0;
    sandbox->changes++;
    /* The grab spring is registered once per scene; it does nothing while
     * grab.body is NULL. It depends on no body: the sandbox clears
     * grab.body itself when the grabbed body goes (sandbox_delete, and after
     * each step for bodies a collision or a game removed). */
    scene_add_bodies_force_creator(scene, grab_force, &sandbox->grab, list_init(0, NULL), NULL);
}

bool sandbox_open(sandbox_t *sandbox, const char *path, char *error, size_t error_size) {
    sandbox_loaded_t loaded;
    if (!sandbox_load(path, &loaded, error, error_size)) return false;
    sandbox_show(sandbox, &loaded, false);
    return true;
}

void sandbox_init(sandbox_t *sandbox, uint64_t seed) {
    *sandbox = (sandbox_t){0};
    sandbox->seed = seed;
    sandbox->integrator = INTEGRATOR_SEED;
    sandbox->default_integrator = INTEGRATOR_SEED;
    sandbox->sleeping_on = true;
    char error[512];
    if (!sandbox_open(sandbox, NULL, error, sizeof(error))) {
        /* The built-in text is checked by the tests; this cannot happen. */
        fprintf(stderr, "sandbox: the default scene is refused: %s\n", error);
        abort();
    }
}

void sandbox_free(sandbox_t *sandbox) {
    game_free(sandbox->game); /* the game before its file */
    scene_file_free(sandbox->file);
    sandbox->game = NULL;
    sandbox->file = NULL;
    sandbox->scene = NULL;
    sandbox->grab.body = NULL;
    sandbox->grab.joint = NULL; /* freed with the scene */
    sandbox->inspected = NULL;
}

bool sandbox_reset(sandbox_t *sandbox, char *error, size_t error_size) {
    sandbox_loaded_t loaded;
    char path[SANDBOX_PATH_MAX];
    snprintf(path, sizeof(path), "%s", sandbox->path);
    if (!sandbox_load(sandbox->is_default ? NULL : path, &loaded, error, error_size)) return false;
    sandbox_show(sandbox, &loaded, true);
    return true;
}

bool sandbox_is_static(body_t *body) {
    return isinf(body_get_mass(body));
}

size_t sandbox_clear(sandbox_t *sandbox) {
    sandbox_release(sandbox);
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

bool sandbox_shape_core(shape_choice_t shape, vector_t *p1, vector_t *p2, double *radius) {
    if (shape.kind == SHAPE_CIRCLE) {
        *p1 = *p2 = VEC_ZERO;
        *radius = shape.size;
        return true;
    }
    if (shape.kind == SHAPE_CAPSULE) {
        *p1 = (vector_t){-0.5 * shape.size, 0.0};
        *p2 = (vector_t){0.5 * shape.size, 0.0};
        *radius = 0.5 * shape.size;
        return true;
    }
    return false;
}

/* Points on a round shape's boundary, counter-clockwise: a half circle
 * round each end (one full circle when the ends are equal), quarter turns
 * among them so that the bounding box is exact. */
static list_t *round_shape_outline(vector_t p1, vector_t p2, double radius) {
    enum { HALF = 16 };
    bool circle = p1.x == p2.x && p1.y == p2.y;
    list_t *vertices = list_init(2 * HALF + 2, free);
    for (int end = 0; end < 2; end++) {
        vector_t centre = end == 0 ? p2 : p1;
        int count = circle ? 2 * HALF : HALF + 1;
        for (int k = 0; k < count; k++) {
            double angle = M_PI * (end - 0.5) + M_PI * k / HALF;
            vector_t *v = malloc(sizeof(vector_t));
            *v = vec_add(centre, (vector_t){radius * cos(angle), radius * sin(angle)});
            list_add(vertices, v);
        }
        if (circle) break;
    }
    return vertices;
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
    case SHAPE_CIRCLE:
    case SHAPE_CAPSULE: {
        vector_t p1, p2;
        double radius;
        sandbox_shape_core(shape, &p1, &p2, &radius);
        vertices = round_shape_outline(p1, p2, radius);
        break;
    }
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

static bool inside(aabb_t box, vector_t point) {
    return point.x > box.min.x && point.x < box.max.x && point.y > box.min.y &&
           point.y < box.max.y;
}

void sandbox_body_words(sandbox_t *sandbox, body_t *body, char *out, size_t size) {
    const char *name = scene_file_body_name(sandbox->file, body);
    if (name == NULL || name[0] == '\0') name = body_get_info(body);
    if (name == NULL || name[0] == '\0') {
        snprintf(out, size, "a body");
        return;
    }
    snprintf(out, size, "the %s", name);
    for (char *c = out; *c != '\0'; c++) {
        if (*c == '_') *c = ' ';
    }
}

body_t *sandbox_any_body_at(sandbox_t *sandbox, vector_t point) {
    for (size_t i = scene_bodies(sandbox->scene); i-- > 0;) {
        body_t *body = scene_get_body(sandbox->scene, i);
        if (!body_is_removed(body) && body_contains_point(body, point)) return body;
    }
    return NULL;
}

double sandbox_world_floor(const sandbox_t *sandbox) {
    return sandbox->container.min.y - SANDBOX_KILL_DEPTH;
}

const char *sandbox_place(sandbox_t *sandbox, list_t *vertices, vector_t at, vector_t *placed) {
    *placed = at;
    if (!vec_is_finite(at)) return "not a finite position";
    body_t *body = sandbox_any_body_at(sandbox, at);
    if (body != NULL) {
        char name[SCENE_FILE_NAME_MAX + 8];
        sandbox_body_words(sandbox, body, name, sizeof(name));
        snprintf(sandbox->refusal, sizeof(sandbox->refusal), "inside %s", name);
        return sandbox->refusal;
    }
    if (at.y < sandbox_world_floor(sandbox)) {
        snprintf(sandbox->refusal, sizeof(sandbox->refusal),
                 "outside the world: bodies below y = %.3g m are removed",
                 sandbox_world_floor(sandbox));
        return sandbox->refusal;
    }
    /* The default scene's container has walls: a shape clicked near them
     * or the floor is set against them rather than into them. */
    if (!sandbox->is_default || !inside(sandbox->container, at)) return NULL;
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

/* Puts a new body's centroid at `at`, sets it moving and adds it. */
static body_t *add_dropped(sandbox_t *sandbox, body_t *body, vector_t at, vector_t velocity,
                           double elasticity) {
    body_set_centroid(body, at);
    body_set_velocity(body, velocity);
    body_set_elasticity(body, fmax(0.0, elasticity));
    scene_add_body(sandbox->scene, body);
    sandbox->changes++;
    return body;
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
    return add_dropped(sandbox, body_init(vertices, mass, color_of(color)), at, velocity,
                       elasticity);
}

body_t *sandbox_drop_shape(sandbox_t *sandbox, shape_choice_t shape, list_t *vertices,
                           vector_t at, vector_t velocity, double elasticity,
                           const char **problem) {
    vector_t p1, p2;
    double radius;
    if (!sandbox_shape_core(shape, &p1, &p2, &radius)) {
        return sandbox_drop(sandbox, vertices, at, velocity, elasticity, problem);
    }
    list_free(vertices);
    *problem = NULL;
    if (!vec_is_finite(at) || !vec_is_finite(velocity) || !isfinite(elasticity)) {
        *problem = "position, velocity or elasticity is not finite";
        return NULL;
    }
    if (!(shape.size >= SHAPE_MIN_SIZE && shape.size <= SHAPE_MAX_SIZE)) {
        *problem = "size out of range";
        return NULL;
    }
    /* A disc, or a capsule's two half discs and the rectangle between. */
    double area = M_PI * radius * radius + 2.0 * radius * vec_get_length(vec_subtract(p2, p1));
    rgb_color_t color = color_of(PALETTE_BODIES[sandbox->next_color++ % PALETTE_BODY_COUNT]);
    body_t *body = shape.kind == SHAPE_CIRCLE
                       ? body_init_circle(at, radius, SANDBOX_DENSITY * area, color)
                       : body_init_capsule(vec_add(at, p1), vec_add(at, p2), radius,
                                           SANDBOX_DENSITY * area, color);
    return add_dropped(sandbox, body, at, velocity, elasticity);
}

void sandbox_spawn(sandbox_t *sandbox, size_t count, double size, double elasticity) {
    aabb_t box = sandbox->container;
    double spacing = 2.2 * size;
    size_t per_row = (size_t)floor((box.max.x - box.min.x) / spacing);
    if (per_row == 0) per_row = 1;
    for (size_t i = 0; i < count; i++) {
        size_t row = i / per_row, column = i % per_row;
        vector_t at = {box.min.x + spacing * (column + 0.5) + (row % 2) * 0.25 * size,
                       box.min.y + spacing * (row + 0.5) + 0.1};
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
    if (sandbox->grab.body == body) sandbox_release(sandbox);
    if (sandbox->inspected == body) sandbox->inspected = NULL;
    if (!body_is_removed(body)) sandbox->changes++;
    body_remove(body);
}

void sandbox_grab(sandbox_t *sandbox, body_t *body, vector_t point) {
    if (body == NULL || sandbox_is_static(body) || body_is_removed(body)) return;
    sandbox_release(sandbox);
    sandbox->grab.body = body;
    sandbox->grab.local_point =
        vec_rotate(vec_subtract(point, body_get_centroid(body)), -body_get_rotation(body));
    sandbox->grab.target = point;
    if (!scene_get_contacts_enabled(sandbox->scene)) return;
    joint_def_t def = joint_def_mouse(body, point);
    def.frequency = GRAB_HZ;
    def.damping_ratio = GRAB_ZETA;
    def.max_force = GRAB_MAX_ACCELERATION * body_get_mass(body);
    sandbox->grab.joint = joint_create(sandbox->scene, &def);
}

void sandbox_grab_move(sandbox_t *sandbox, vector_t target) {
    if (!vec_is_finite(target)) return;
    sandbox->grab.target = target;
    if (sandbox->grab.joint != NULL) joint_set_target(sandbox->grab.joint, target);
}

void sandbox_release(sandbox_t *sandbox) {
    if (sandbox->grab.joint != NULL) joint_destroy(sandbox->grab.joint);
    sandbox->grab.joint = NULL;
    sandbox->grab.body = NULL;
}

vector_t sandbox_grab_point(sandbox_t *sandbox) {
    return sandbox->grab.body != NULL ? grab_world_point(&sandbox->grab) : sandbox->grab.target;
}

void sandbox_set_gravity(sandbox_t *sandbox, bool on) {
    sandbox->gravity_on = on;
    vector_t gravity = on ? sandbox->gravity : VEC_ZERO;
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

bool sandbox_set_iterations(sandbox_t *sandbox, size_t velocity, size_t position) {
    if (velocity < 1 || velocity > 1000 || position < 1 || position > 1000) return false;
    scene_set_solver_iterations(sandbox->scene, velocity, position);
    return true;
}

bool sandbox_set_workers(sandbox_t *sandbox, size_t workers) {
    if (workers < 1 || workers > SANDBOX_MAX_WORKERS) return false;
    scene_set_workers(sandbox->scene, workers);
    return true;
}

bool sandbox_set_timestep(sandbox_t *sandbox, double step) {
    if (!scene_file_set_timestep(sandbox->file, step)) return false;
    sandbox->step = step;
    sandbox->tick = step;
    return true;
}

void sandbox_set_stepping(sandbox_t *sandbox, scene_file_stepping_t stepping) {
    scene_file_set_stepping(sandbox->file, stepping);
    sandbox->stepping = scene_file_get_stepping(sandbox->file);
    sandbox->tick = sandbox->step;
}

/* Whether body is still in the scene (not reaped). */
static bool in_scene(scene_t *scene, body_t *body) {
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        if (scene_get_body(scene, i) == body) return true;
    }
    return false;
}

/* Removes the bodies that left the world: below its floor, or farther
 * than SANDBOX_WORLD_RADIUS from the view (on their way to numbers the
 * engine would stop the program over), and says which went last. */
static void remove_escaped(sandbox_t *sandbox) {
    scene_t *scene = sandbox->scene;
    double floor_y = sandbox_world_floor(sandbox);
    vector_t middle = vec_multiply(0.5, vec_add(sandbox->home.min, sandbox->home.max));
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body)) continue;
        vector_t at = body_get_centroid(body);
        const char *why = NULL;
        if (at.y < floor_y) {
            why = "it fell out of the world";
        } else if (vec_get_length(vec_subtract(at, middle)) > SANDBOX_WORLD_RADIUS) {
            why = "it flew out of the world";
        }
        if (why == NULL) continue;
        sandbox_body_words(sandbox, body, sandbox->removed.last, sizeof(sandbox->removed.last));
        sandbox->removed.why = why;
        sandbox->removed.count++;
        sandbox_delete(sandbox, body);
    }
}

void sandbox_step(sandbox_t *sandbox) {
    scene_t *scene = sandbox->scene;
    scene_tick(scene, sandbox->tick);
    /* A collision may have removed the grabbed body in this tick, which then
     * reaped it (a destructive collision): let go of it before anything
     * else can be added where it was. */
    if (sandbox->grab.body != NULL && !in_scene(scene, sandbox->grab.body)) {
        sandbox->grab.body = NULL;
        sandbox->grab.joint = NULL; /* reaped with its body */
    }
    if (sandbox->inspected != NULL && !in_scene(scene, sandbox->inspected)) {
        sandbox->inspected = NULL;
    }
    /* The game reads the step's record, then applies the input for the next
     * step (game.h). */
    game_update(sandbox->game, sandbox->input, sandbox->tick);
    remove_escaped(sandbox);
    if (sandbox->grab.body != NULL && body_is_removed(sandbox->grab.body)) {
        sandbox_release(sandbox); /* the game removed it */
    }
}

/* The potential energy of the file's springs (1/2 k (d - L)^2, d the
 * distance between the centroids, L the rest length) and Newtonian gravity
 * (-G m1 m2 / r between bodies of finite mass, as forces.h applies it). */
static double force_potential(scene_file_t *file) {
    double energy = 0.0;
    size_t count = scene_file_force_count(file);
    for (size_t i = 0; i < count; i++) {
        scene_file_force_t force = scene_file_get_force(file, i);
        if (force.kind != SCENE_FILE_SPRING && force.kind != SCENE_FILE_NEWTON) continue;
        if (force.body1 == NULL || force.body2 == NULL || body_is_removed(force.body1) ||
            body_is_removed(force.body2)) {
            continue;
        }
        vector_t d = vec_subtract(body_get_centroid(force.body2), body_get_centroid(force.body1));
        double r = vec_get_length(d);
        if (force.kind == SCENE_FILE_SPRING) {
            double stretch = r - force.rest_length;
            energy += 0.5 * force.constant * stretch * stretch;
        } else {
            double m1 = body_get_mass(force.body1), m2 = body_get_mass(force.body2);
            if (isinf(m1) || isinf(m2) || r < 1e-9) continue;
            energy -= force.constant * m1 * m2 / r;
        }
    }
    return energy;
}

sandbox_totals_t sandbox_totals(sandbox_t *sandbox) {
    sandbox_totals_t totals = {0};
    vector_t gravity = scene_get_gravity(sandbox->scene);
    for (size_t i = 0; i < scene_bodies(sandbox->scene); i++) {
        body_t *body = scene_get_body(sandbox->scene, i);
        if (body_is_removed(body)) continue;
        if (sandbox_is_static(body)) {
            totals.statics++;
            continue;
        }
        double mass = body_get_mass(body);
        totals.bodies++;
        totals.sleeping += body_is_sleeping(body);
        totals.kinetic += body_get_kinetic_energy(body);
        totals.potential -= mass * vec_dot(gravity, body_get_centroid(body));
        totals.momentum = vec_add(totals.momentum, vec_multiply(mass, body_get_velocity(body)));
    }
    totals.potential += force_potential(sandbox->file);
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
    case SHAPE_CIRCLE:
        return "circle";
    case SHAPE_CAPSULE:
        return "capsule";
    }
    return "?";
}
