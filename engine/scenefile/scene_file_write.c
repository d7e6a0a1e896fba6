/*
 * The scene back to text. The shape, mass and filter come from the
 * description (the engine cannot give a body's filter back, and rebuilding a
 * shape from the same description gives the same body to the last bit); the
 * pose, motion and material come from the live bodies.
 */
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_file_private.h"

typedef struct {
    char *text;
    size_t length, capacity;
} out_t;

static void put(out_t *out, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void put(out_t *out, const char *format, ...) {
    va_list args;
    va_start(args, format);
    va_list again;
    va_copy(again, args);
    int needed = vsnprintf(NULL, 0, format, args);
    va_end(args);
    if (needed < 0) abort();
    sf_reserve((void **)&out->text, &out->capacity, out->length + (size_t)needed + 1, 1);
    vsnprintf(out->text + out->length, out->capacity - out->length, format, again);
    va_end(again);
    out->length += (size_t)needed;
}

/* The shortest of %.15g, %.16g, %.17g that reads back as the same double, so
 * that 0.1 stays "0.1" and every value still round-trips exactly. */
static void put_number(out_t *out, double value) {
    char text[40];
    for (int digits = 15; digits <= 17; digits++) {
        snprintf(text, sizeof text, "%.*g", digits, value);
        if (strtod(text, NULL) == value) break;
    }
    put(out, " %s", text);
}

static void put_vector(out_t *out, vector_t v) {
    put_number(out, v.x);
    put_number(out, v.y);
}

static bool is_zero(vector_t v) {
    return v.x == 0.0 && v.y == 0.0;
}

static void put_settings(out_t *out, scene_file_t *file, const char *integrator) {
    const sf_settings_t *s = &file->doc.settings;
    put(out, "gravity");
    put_vector(out, scene_get_gravity(file->scene));
    put(out, "\ncontacts %s\n", scene_get_contacts_enabled(file->scene) ? "on" : "off");
    put(out, "integrator %s\n", integrator);
    put(out, "iterations %zu %zu\n", s->velocity_iterations, s->position_iterations);
    put(out, "timestep");
    put_number(out, s->timestep);
    put(out, "\n");
    if (s->view.has_view) {
        put(out, "view");
        put_vector(out, s->view.center);
        put_number(out, s->view.width);
        put_number(out, s->view.height);
        put(out, "\n");
    }
    if (s->game.text[0] != '\0') put(out, "game %s\n", s->game.text);
}

static void put_shape(out_t *out, const sf_shape_t *shape) {
    switch (shape->kind) {
    case SHAPE_REGULAR:
        put(out, "    regular %zu", shape->sides);
        put_number(out, shape->radius);
        break;
    case SHAPE_BOX:
        put(out, "    box");
        put_number(out, shape->width);
        put_number(out, shape->height);
        break;
    default:
        put(out, "    vertices");
        for (size_t i = 0; i < shape->count; i++) put_vector(out, shape->written[i]);
        break;
    }
    put(out, "\n");
}

static void put_mass(out_t *out, sf_mass_kind_t kind, double value) {
    if (kind == MASS_STATIC) {
        put(out, "    static\n");
        return;
    }
    put(out, "    %s", kind == MASS_TOTAL ? "mass" : "density");
    put_number(out, value);
    put(out, "\n");
}

/* What a block says beyond its shape and mass, from wherever it is read. */
typedef struct {
    double elasticity, friction, angle, spin;
    rgb_color_t color;
    bool has_position;
    vector_t position, velocity;
} state_t;

static void put_state(out_t *out, const state_t *state) {
    if (state->elasticity != 0.0) {
        put(out, "    elasticity");
        put_number(out, state->elasticity);
        put(out, "\n");
    }
    put(out, "    friction");
    put_number(out, state->friction);
    put(out, "\n    color");
    put_number(out, state->color.r);
    put_number(out, state->color.g);
    put_number(out, state->color.b);
    put(out, "\n");
    if (state->has_position) {
        put(out, "    position");
        put_vector(out, state->position);
        put(out, "\n");
    }
    if (state->angle != 0.0) {
        put(out, "    angle");
        put_number(out, state->angle);
        put(out, "\n");
    }
    if (!is_zero(state->velocity)) {
        put(out, "    velocity");
        put_vector(out, state->velocity);
        put(out, "\n");
    }
    if (state->spin != 0.0) {
        put(out, "    spin");
        put_number(out, state->spin);
        put(out, "\n");
    }
}

static void put_labels(out_t *out, const sf_doc_t *doc, const sf_body_t *spec, bool own_group) {
    if (spec->tag.text[0] != '\0') put(out, "    tag %s\n", spec->tag.text);
    /* The group a repeated block or template names, unless the block also
     * listed it itself. */
    bool own = own_group && spec->own_group != SIZE_MAX;
    for (size_t i = 0; own && i < spec->group_count; i++) own = spec->groups[i] != spec->own_group;
    if (spec->group_count > 0 || own) {
        put(out, "    group");
        for (size_t i = 0; i < spec->group_count; i++) {
            put(out, " %s", doc->groups[spec->groups[i]].name.text);
        }
        if (own) put(out, " %s", doc->groups[spec->own_group].name.text);
        put(out, "\n");
    }
    if (spec->has_filter) {
        put(out, "    filter 0x%08x 0x%08x 0x%08x\n", (unsigned)spec->category,
            (unsigned)spec->mask, (unsigned)spec->filter_group);
    }
}

static void put_template(out_t *out, const sf_doc_t *doc, const sf_body_t *spec) {
    put(out, "\ntemplate %s {\n", spec->name.text);
    put_shape(out, &spec->shape);
    put_mass(out, spec->mass_kind, spec->mass_value);
    state_t state = {
        .elasticity = spec->elasticity,
        .friction = spec->friction,
        .angle = spec->angle,
        .spin = spec->spin,
        .color = spec->color,
        .has_position = spec->has_position,
        .position = spec->position,
        .velocity = spec->velocity,
    };
    put_state(out, &state);
    put_labels(out, doc, spec, false);
    put(out, "}\n");
}

static state_t live_state(body_t *body) {
    return (state_t){
        .elasticity = body_get_elasticity(body),
        .friction = body_get_friction(body),
        .angle = body_get_rotation(body),
        .spin = body_get_angular_velocity(body),
        .color = body_get_color(body),
        .has_position = true,
        .position = body_get_centroid(body),
        .velocity = body_get_velocity(body),
    };
}

static void put_record(out_t *out, const sf_doc_t *doc, const sf_record_t *record) {
    const sf_body_t *spec = &doc->bodies[record->spec];
    /* Only a single body keeps its name: copies and spawns are anonymous
     * members of the group their block named. */
    bool single = spec->record == record;
    put(out, "\nbody %s%s{\n", single ? spec->name.text : "", single ? " " : "");
    put_shape(out, &spec->shape);
    put_mass(out, spec->mass_kind, spec->mass_value);
    state_t state = live_state(record->body);
    put_state(out, &state);
    put_labels(out, doc, spec, true);
    put(out, "}\n");
}

/* A body the file did not make: its world vertices, at angle 0. */
static void put_foreign(out_t *out, body_t *body) {
    put(out, "\nbody {\n    vertices");
    polygon_t polygon = body_get_polygon(body);
    for (size_t i = 0; i < polygon.count; i++) put_vector(out, polygon.vertices[i]);
    put(out, "\n");
    double mass = body_get_mass(body);
    put_mass(out, isinf(mass) ? MASS_STATIC : MASS_TOTAL, mass);
    state_t state = live_state(body);
    state.angle = 0.0;
    put_state(out, &state);
    put(out, "}\n");
}

static int compare_by_body(const void *a, const void *b) {
    uintptr_t x = (uintptr_t)(*(sf_record_t *const *)a)->body;
    uintptr_t y = (uintptr_t)(*(sf_record_t *const *)b)->body;
    return x < y ? -1 : x > y;
}

/* Every body in the scene, in scene order, not marked removed: the records
 * sorted by body address tell the file's bodies from the others. */
static void put_bodies(out_t *out, scene_file_t *file) {
    sf_record_t **sorted = malloc((file->record_count + 1) * sizeof *sorted);
    if (sorted == NULL) abort();
    size_t live = 0;
    for (size_t i = 0; i < file->record_count; i++) {
        if (file->records[i]->body != NULL) sorted[live++] = file->records[i];
    }
    qsort(sorted, live, sizeof *sorted, compare_by_body);
    scene_t *scene = file->scene;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body)) continue;
        sf_record_t key_record = {.body = body};
        sf_record_t *key = &key_record;
        sf_record_t **found = bsearch(&key, sorted, live, sizeof *sorted, compare_by_body);
        if (found != NULL) {
            put_record(out, &file->doc, *found);
        } else {
            put_foreign(out, body);
        }
    }
    free(sorted);
}

/* A reference is written unless it names a single body that is gone or
 * marked removed (its force creators go with it at the next tick). */
static bool ref_alive(const sf_doc_t *doc, const sf_ref_t *ref) {
    if (ref->kind != REF_BODY) return true;
    const sf_record_t *record = doc->bodies[ref->index].record;
    return record != NULL && record->body != NULL && !body_is_removed(record->body);
}

static void put_statement(out_t *out, const sf_doc_t *doc, const sf_statement_t *s) {
    size_t alive = 0;
    for (size_t i = 0; i < s->ref_count; i++) alive += ref_alive(doc, &s->refs[i]);
    bool pair = s->kind == STATEMENT_SPRING || s->kind == STATEMENT_PHYSICS ||
                s->kind == STATEMENT_DESTRUCTIVE;
    if (alive == 0 || (pair && alive < 2)) return;
    switch (s->kind) {
    case STATEMENT_SPRING: put(out, "spring"); break;
    case STATEMENT_NEWTON: put(out, "newton"); break;
    case STATEMENT_DRAG: put(out, "drag"); break;
    default: put(out, "collide"); break;
    }
    if (s->kind != STATEMENT_PHYSICS && s->kind != STATEMENT_DESTRUCTIVE) {
        put_number(out, s->constant);
    }
    for (size_t i = 0; i < s->ref_count; i++) {
        if (ref_alive(doc, &s->refs[i])) put(out, " %s", s->refs[i].name.text);
    }
    if (s->has_rest_length) {
        put(out, " length");
        put_number(out, s->rest_length);
    }
    if (s->kind == STATEMENT_PHYSICS) {
        put(out, " physics");
        put_number(out, s->constant);
    } else if (s->kind == STATEMENT_DESTRUCTIVE) {
        put(out, " destructive");
    }
    put(out, "\n");
}

char *scene_file_write(scene_file_t *file, size_t *length, scene_file_error_t *error) {
    if (error != NULL) *error = (scene_file_error_t){0};
    integrator_t integrator = scene_get_integrator(file->scene);
    const char *integrator_name = scene_file_integrator_name(integrator);
    if (integrator_name == NULL) {
        if (error != NULL) {
            snprintf(error->message, sizeof error->message,
                     "cannot write the scene: integrator %d has no name in the scene-file "
                     "table (INTEGRATORS in engine/scenefile/scene_file_parse.c)",
                     (int)integrator);
        }
        return NULL;
    }
    const sf_doc_t *doc = &file->doc;
    out_t out = {0};
    put(&out, "# Written by scene_file_write: the scene as it was, one block per body.\n");
    put_settings(&out, file, integrator_name);
    if (doc->group_count > 0) put(&out, "\n");
    for (size_t i = 0; i < doc->group_count; i++) put(&out, "group %s\n", doc->groups[i].name.text);
    for (size_t i = 0; i < doc->body_count; i++) {
        if (doc->bodies[i].is_template) put_template(&out, doc, &doc->bodies[i]);
    }
    put_bodies(&out, file);
    if (doc->statement_count > 0) put(&out, "\n");
    for (size_t i = 0; i < doc->statement_count; i++) put_statement(&out, doc, &doc->statements[i]);
    if (length != NULL) *length = out.length;
    return out.text;
}
