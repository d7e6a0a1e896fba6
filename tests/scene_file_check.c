#include "scene_file_check.h"
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "jostle/jostle.h"

static bool differ(char *why, size_t size, const char *format, ...) {
    va_list args;
    va_start(args, format);
    vsnprintf(why, size, format, args);
    va_end(args);
    return false;
}

static bool same_vector(vector_t a, vector_t b) {
    return a.x == b.x && a.y == b.y;
}

static bool same_settings(scene_file_t *a, scene_file_t *b, char *why, size_t size) {
    scene_t *x = scene_file_get_scene(a), *y = scene_file_get_scene(b);
    if (!same_vector(scene_get_gravity(x), scene_get_gravity(y)))
        return differ(why, size, "gravity differs");
    if (scene_get_contacts_enabled(x) != scene_get_contacts_enabled(y))
        return differ(why, size, "contacts differ");
    if (scene_get_integrator(x) != scene_get_integrator(y))
        return differ(why, size, "integrator differs");
    if (scene_file_get_timestep(a) != scene_file_get_timestep(b))
        return differ(why, size, "timestep differs");
    scene_file_view_t u = scene_file_get_view(a), v = scene_file_get_view(b);
    if (u.has_view != v.has_view || !same_vector(u.center, v.center) || u.width != v.width ||
        u.height != v.height)
        return differ(why, size, "view differs");
    if (strcmp(scene_file_get_game(a), scene_file_get_game(b)) != 0)
        return differ(why, size, "game differs");
    if (scene_file_get_stepping(a) != scene_file_get_stepping(b))
        return differ(why, size, "stepping differs");
    if (scene_get_workers(scene_file_get_scene(a)) != scene_get_workers(scene_file_get_scene(b)))
        return differ(why, size, "workers differ");
    if (strcmp(scene_file_get_category(a), scene_file_get_category(b)) != 0 ||
        strcmp(scene_file_get_note(a), scene_file_get_note(b)) != 0)
        return differ(why, size, "category or note differs");
    if (scene_get_sleeping(x) != scene_get_sleeping(y))
        return differ(why, size, "sleeping differs");
    size_t iterations[2][2];
    scene_get_solver_iterations(x, &iterations[0][0], &iterations[0][1]);
    scene_get_solver_iterations(y, &iterations[1][0], &iterations[1][1]);
    if (iterations[0][0] != iterations[1][0] || iterations[0][1] != iterations[1][1])
        return differ(why, size, "iterations differ");
    if (scene_get_warm_starting(x) != scene_get_warm_starting(y))
        return differ(why, size, "warm starting differs");
    if (scene_get_restitution_threshold(x) != scene_get_restitution_threshold(y))
        return differ(why, size, "restitution threshold differs");
    double tolerance[2][2];
    scene_get_sleep_tolerance(x, &tolerance[0][0], &tolerance[0][1]);
    scene_get_sleep_tolerance(y, &tolerance[1][0], &tolerance[1][1]);
    if (tolerance[0][0] != tolerance[1][0] || tolerance[0][1] != tolerance[1][1])
        return differ(why, size, "sleep tolerance differs");
    if (scene_get_sleep_time(x) != scene_get_sleep_time(y))
        return differ(why, size, "sleep time differs");
    if (scene_get_sleep_phase(x) != scene_get_sleep_phase(y))
        return differ(why, size, "sleep phase differs");
    if (scene_get_solver_steps(x) != scene_get_solver_steps(y))
        return differ(why, size, "solver steps differ");
    double last[2], before[2];
    scene_get_step_lengths(x, &last[0], &before[0]);
    scene_get_step_lengths(y, &last[1], &before[1]);
    if (last[0] != last[1] || before[0] != before[1])
        return differ(why, size, "step lengths differ (%.17g, %.17g against %.17g, %.17g)",
                      last[0], before[0], last[1], before[1]);
    return true;
}

static long index_of(scene_t *scene, body_t *body);

/* The island of a sleeping body named by its member of lowest index; -1
 * when awake. */
static long island_of(scene_t *scene, body_t *body) {
    if (!body_is_sleeping(body)) return -1;
    long lowest = index_of(scene, body);
    for (body_t *m = body_get_island_next(body); m != body; m = body_get_island_next(m)) {
        long k = index_of(scene, m);
        if (k < lowest) lowest = k;
    }
    return lowest;
}

/* What scene_state.h keeps of a body: its filter, timer and island. */
static bool same_body_state(scene_t *x, body_t *a, scene_t *y, body_t *b, size_t i, char *why,
                            size_t size) {
    uint32_t f[3], g[3];
    body_get_collision_filter(a, &f[0], &f[1], &f[2]);
    body_get_collision_filter(b, &g[0], &g[1], &g[2]);
    if (f[0] != g[0] || f[1] != g[1] || f[2] != g[2])
        return differ(why, size, "body %zu: filter differs", i);
    body_sleep_timer_t s = body_get_sleep_timer(a), t = body_get_sleep_timer(b);
    if (s.slow_time != t.slow_time || s.window != t.window || !same_vector(s.anchor, t.anchor) ||
        s.anchor_angle != t.anchor_angle)
        return differ(why, size, "body %zu: sleep timer differs", i);
    if (island_of(x, a) != island_of(y, b))
        return differ(why, size, "body %zu: sleeping island differs (%ld against %ld)", i,
                      island_of(x, a), island_of(y, b));
    return true;
}

static bool same_body(body_t *a, body_t *b, size_t i, char *why, size_t size) {
    if (!same_vector(body_get_centroid(a), body_get_centroid(b)))
        return differ(why, size, "body %zu: centroid (%.17g, %.17g) against (%.17g, %.17g)", i,
                      body_get_centroid(a).x, body_get_centroid(a).y, body_get_centroid(b).x,
                      body_get_centroid(b).y);
    if (body_get_rotation(a) != body_get_rotation(b))
        return differ(why, size, "body %zu: rotation differs", i);
    if (!same_vector(body_get_velocity(a), body_get_velocity(b)))
        return differ(why, size, "body %zu: velocity differs", i);
    if (body_get_angular_velocity(a) != body_get_angular_velocity(b))
        return differ(why, size, "body %zu: angular velocity differs", i);
    if (body_get_mass(a) != body_get_mass(b)) return differ(why, size, "body %zu: mass differs", i);
    if (body_get_inertia(a) != body_get_inertia(b))
        return differ(why, size, "body %zu: inertia differs", i);
    if (body_get_elasticity(a) != body_get_elasticity(b) ||
        body_get_friction(a) != body_get_friction(b))
        return differ(why, size, "body %zu: material differs", i);
    rgb_color_t p = body_get_color(a), q = body_get_color(b);
    if (p.r != q.r || p.g != q.g || p.b != q.b)
        return differ(why, size, "body %zu: colour differs", i);
    const char *s = body_get_info(a), *t = body_get_info(b);
    if ((s == NULL) != (t == NULL) || (s != NULL && strcmp(s, t) != 0))
        return differ(why, size, "body %zu: tag differs", i);
    if (body_get_shape_kind(a) != body_get_shape_kind(b) ||
        body_get_round_radius(a) != body_get_round_radius(b))
        return differ(why, size, "body %zu: shape kind or radius differs", i);
    vector_t a1, a2, b1, b2;
    body_get_core(a, &a1, &a2);
    body_get_core(b, &b1, &b2);
    if (!same_vector(a1, b1) || !same_vector(a2, b2))
        return differ(why, size, "body %zu: core differs", i);
    polygon_t f = body_get_polygon(a), g = body_get_polygon(b);
    if (f.count != g.count) return differ(why, size, "body %zu: vertex count differs", i);
    for (size_t k = 0; k < f.count; k++) {
        if (!same_vector(f.vertices[k], g.vertices[k]))
            return differ(why, size, "body %zu: vertex %zu differs", i, k);
    }
    return true;
}

/* A force with its bodies as indices into its scene, for comparing. */
typedef struct {
    int kind;
    double constant, rest_length;
    long body1, body2;
} indexed_force_t;

/* The scene's bodies sorted by address, to find a body's index in
 * O(log N): a file whose rules pair every body (collide g all) lists
 * N^2 / 2 forces, and a scan per force made checking it quadratic in that. */
typedef struct {
    uintptr_t address;
    long index;
} body_index_t;

static int compare_addresses(const void *p, const void *q) {
    const body_index_t *a = p, *b = q;
    return (a->address > b->address) - (a->address < b->address);
}

static long index_of(scene_t *scene, body_t *body) {
    if (body == NULL) return -1;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        if (scene_get_body(scene, i) == body) return (long)i;
    }
    return -2;
}

static long sorted_index_of(const body_index_t *sorted, size_t count, body_t *body) {
    if (body == NULL) return -1;
    body_index_t key = {(uintptr_t)body, 0};
    const body_index_t *found = bsearch(&key, sorted, count, sizeof key, compare_addresses);
    return found != NULL ? found->index : -2;
}

static indexed_force_t *indexed_forces(scene_file_t *file, size_t *count) {
    *count = scene_file_force_count(file);
    indexed_force_t *forces = malloc((*count + 1) * sizeof *forces);
    scene_t *scene = scene_file_get_scene(file);
    size_t bodies = scene_bodies(scene);
    body_index_t *sorted = malloc((bodies + 1) * sizeof *sorted);
    for (size_t i = 0; i < bodies; i++) {
        sorted[i] = (body_index_t){(uintptr_t)scene_get_body(scene, i), (long)i};
    }
    qsort(sorted, bodies, sizeof *sorted, compare_addresses);
    for (size_t i = 0; i < *count; i++) {
        scene_file_force_t f = scene_file_get_force(file, i);
        forces[i] = (indexed_force_t){(int)f.kind, f.constant, f.rest_length,
                                      sorted_index_of(sorted, bodies, f.body1),
                                      sorted_index_of(sorted, bodies, f.body2)};
    }
    free(sorted);
    return forces;
}

static int compare_forces(const void *p, const void *q) {
    const indexed_force_t *a = p, *b = q;
    if (a->kind != b->kind) return a->kind < b->kind ? -1 : 1;
    if (a->body1 != b->body1) return a->body1 < b->body1 ? -1 : 1;
    if (a->body2 != b->body2) return a->body2 < b->body2 ? -1 : 1;
    if (a->constant != b->constant) return a->constant < b->constant ? -1 : 1;
    return (a->rest_length > b->rest_length) - (a->rest_length < b->rest_length);
}

static bool same_forces(scene_file_t *a, scene_file_t *b, bool sort, char *why, size_t size) {
    size_t n = 0, m = 0;
    indexed_force_t *x = indexed_forces(a, &n), *y = indexed_forces(b, &m);
    bool same = n == m;
    if (!same) differ(why, size, "%zu force creators against %zu", n, m);
    if (same && sort) {
        qsort(x, n, sizeof *x, compare_forces);
        qsort(y, m, sizeof *y, compare_forces);
    }
    for (size_t i = 0; same && i < n; i++) {
        if (compare_forces(&x[i], &y[i]) != 0 || x[i].constant != y[i].constant ||
            x[i].rest_length != y[i].rest_length) {
            same = differ(why, size,
                          "force %zu: kind %d, %.17g, length %.17g, bodies %ld %ld against kind "
                          "%d, %.17g, length %.17g, bodies %ld %ld",
                          i, x[i].kind, x[i].constant, x[i].rest_length, x[i].body1, x[i].body2,
                          y[i].kind, y[i].constant, y[i].rest_length, y[i].body1, y[i].body2);
        }
    }
    free(x);
    free(y);
    return same;
}

static bool same_point(const scene_memory_point_t *p, const scene_memory_point_t *q) {
    return p->id == q->id && same_vector(p->point, q->point) && p->separation == q->separation &&
           p->normal_impulse == q->normal_impulse && p->tangent_impulse == q->tangent_impulse &&
           p->restitution_impulse == q->restitution_impulse &&
           p->restitution_tangent_impulse == q->restitution_tangent_impulse;
}

static bool same_memory(const scene_contact_memory_t *m, const scene_contact_memory_t *n) {
    bool same = same_vector(m->normal, n->normal) && m->point_count == n->point_count &&
                m->flip == n->flip && m->edge_ends == n->edge_ends &&
                m->feature_count == n->feature_count &&
                same_vector(m->face_normal, n->face_normal) &&
                same_vector(m->face_point, n->face_point) && same_vector(m->pose, n->pose) &&
                m->pose_angle == n->pose_angle && m->face_lead == n->face_lead;
    for (int j = 0; same && j < m->point_count; j++) {
        same = same_point(&m->points[j], &n->points[j]);
    }
    for (int j = 0; same && j < m->feature_count; j++) {
        same = same_vector(m->feature_points[j], n->feature_points[j]) &&
               m->feature_ids[j] == n->feature_ids[j];
    }
    same = same && m->previous_count == n->previous_count;
    for (int j = 0; same && j < m->previous_count; j++) {
        same = m->previous[j].id == n->previous[j].id &&
               m->previous[j].normal_impulse == n->previous[j].normal_impulse &&
               m->previous[j].tangent_impulse == n->previous[j].tangent_impulse;
    }
    return same;
}

/* The world's contact memory: the same pairs (by body index) with the same
 * values. A scene written with bodies marked removed has none of their
 * contacts after a reload, so the pairs naming them are left out. */
static bool same_contact_memory(scene_t *x, scene_t *y, char *why, size_t size) {
    size_t n = scene_contact_memory_count(x), m = scene_contact_memory_count(y), kept = 0;
    for (size_t i = 0; i < n; i++) {
        scene_contact_memory_t c = scene_get_contact_memory(x, i);
        if (body_is_removed(c.body_a) || body_is_removed(c.body_b)) continue;
        kept++;
        long a = index_of(x, c.body_a), b = index_of(x, c.body_b);
        bool found = false;
        for (size_t j = 0; j < m && !found; j++) {
            scene_contact_memory_t d = scene_get_contact_memory(y, j);
            if (index_of(y, d.body_a) != a || index_of(y, d.body_b) != b) continue;
            if (d.segment != c.segment) continue; /* a chain's other segment */
            if (!same_memory(&c, &d))
                return differ(why, size, "the contact memory of bodies %ld and %ld differs", a, b);
            found = true;
        }
        if (!found) return differ(why, size, "no contact memory of bodies %ld and %ld", a, b);
    }
    if (kept != m) return differ(why, size, "%zu contacts remembered against %zu", kept, m);
    return true;
}

/* The body's index among the scene's bodies not marked removed; -1 for
 * NULL (the world) and for a body not found. */
static long live_index(scene_t *scene, const body_t *body) {
    long index = 0;
    for (size_t i = 0; body != NULL && i < scene_bodies(scene); i++) {
        body_t *other = scene_get_body(scene, i);
        if (other == body) return index;
        index += !body_is_removed(other);
    }
    return -1;
}

static bool same_def(const joint_def_t *d, const joint_def_t *e) {
    return d->type == e->type && same_vector(d->anchor1, e->anchor1) &&
           same_vector(d->anchor2, e->anchor2) && same_vector(d->axis, e->axis) &&
           d->reference_angle == e->reference_angle && d->length == e->length &&
           d->min_length == e->min_length && d->max_length == e->max_length &&
           d->frequency == e->frequency && d->damping_ratio == e->damping_ratio &&
           d->enable_limit == e->enable_limit && d->lower_angle == e->lower_angle &&
           d->upper_angle == e->upper_angle && d->lower_translation == e->lower_translation &&
           d->upper_translation == e->upper_translation && d->enable_motor == e->enable_motor &&
           d->motor_speed == e->motor_speed && d->max_motor_torque == e->max_motor_torque &&
           d->max_motor_force == e->max_motor_force && same_vector(d->target, e->target) &&
           d->max_force == e->max_force && same_vector(d->linear_offset, e->linear_offset) &&
           d->angular_offset == e->angular_offset && d->max_torque == e->max_torque &&
           d->correction_factor == e->correction_factor &&
           d->collide_connected == e->collide_connected;
}

/* The joints, in order, with the same definitions, bodies by index and
 * impulses to the bit (those naming a body marked removed are not
 * written: left out). */
static bool same_joints(scene_t *x, scene_t *y, char *why, size_t size) {
    size_t j = 0;
    for (size_t i = 0; i < scene_joints(x); i++) {
        joint_def_t d = joint_get_def(scene_get_joint(x, i));
        if (body_is_removed(d.body2) || (d.body1 != NULL && body_is_removed(d.body1))) continue;
        if (j == scene_joints(y)) return differ(why, size, "joint %zu is missing", i);
        joint_state_t s = joint_get_state(scene_get_joint(x, i));
        joint_state_t t = joint_get_state(scene_get_joint(y, j));
        joint_def_t e = joint_get_def(scene_get_joint(y, j++));
        if (!same_def(&d, &e) || memcmp(&s, &t, sizeof s) != 0 || live_index(x, d.body1) != live_index(y, e.body1) ||
            live_index(x, d.body2) != live_index(y, e.body2))
            return differ(why, size, "joint %zu differs", i);
    }
    if (j != scene_joints(y)) return differ(why, size, "the scenes hold different joints");
    return true;
}

bool scene_file_same(scene_file_t *a, scene_file_t *b, char *why, size_t size) {
    if (!same_settings(a, b, why, size)) return false;
    scene_t *x = scene_file_get_scene(a), *y = scene_file_get_scene(b);
    /* Bodies marked removed are not written: compare the others. */
    size_t i = 0, j = 0, compared = 0;
    for (;; i++, j++) {
        while (i < scene_bodies(x) && body_is_removed(scene_get_body(x, i))) i++;
        while (j < scene_bodies(y) && body_is_removed(scene_get_body(y, j))) j++;
        if (i == scene_bodies(x) || j == scene_bodies(y)) break;
        if (!same_body(scene_get_body(x, i), scene_get_body(y, j), compared, why, size) ||
            !same_body_state(x, scene_get_body(x, i), y, scene_get_body(y, j), compared, why,
                             size))
            return false;
        compared++;
    }
    if (i != scene_bodies(x) || j != scene_bodies(y))
        return differ(why, size, "the scenes hold different numbers of bodies");
    return same_contact_memory(x, y, why, size) && same_joints(x, y, why, size) &&
           same_forces(a, b, false, why, size);
}

bool scene_file_same_forces_in_any_order(scene_file_t *a, scene_file_t *b, char *why, size_t size) {
    return same_forces(a, b, true, why, size);
}

bool scene_file_round_trip(const uint8_t *data, size_t size, const char *name, char *why,
                           size_t why_size) {
    scene_file_error_t error;
    scene_file_t *first = scene_file_parse((const char *)data, size, name, &error);
    if (first == NULL) {
        size_t n = strlen(name);
        if (strncmp(error.message, name, n) != 0 || error.message[n] != ':' || error.line == 0)
            return differ(why, why_size, "refused without a FILE:LINE:COLUMN message: \"%s\"",
                          error.message);
        return true;
    }
    size_t length = 0, again_length = 0;
    char *text = scene_file_write(first, &length, &error);
    scene_file_t *second = text != NULL ? scene_file_parse(text, length, "written", &error) : NULL;
    char *again = second != NULL ? scene_file_write(second, &again_length, &error) : NULL;
    bool ok = true;
    if (text == NULL) {
        ok = differ(why, why_size, "could not write: %s", error.message);
    } else if (second == NULL) {
        ok = differ(why, why_size, "the written text does not load: %s", error.message);
    } else if (!scene_file_same(first, second, why, why_size)) {
        ok = false;
    } else if (again == NULL || again_length != length || memcmp(text, again, length) != 0) {
        ok = differ(why, why_size, "writing the reloaded scene gives another text");
    }
    free(text);
    free(again);
    scene_file_free(first);
    scene_file_free(second);
    return ok;
}
