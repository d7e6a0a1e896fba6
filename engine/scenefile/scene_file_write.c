/*
 * The scene back to text. The shape and mass come from the description
 * (rebuilding a shape from the same description gives the same body to the
 * last bit); the pose, motion, material, filter and sleep come from the live
 * bodies, and the contact memory from the world (scene_state.h), so that
 * the text loads into a scene that goes on as this one does.
 */
#include <math.h>
#include <stdarg.h>
#include <inttypes.h>
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

/* The solver's settings as the scene has them now; all but the iterations
 * only when they differ from a new scene's. */
static void put_solver_settings(out_t *out, const scene_t *scene) {
    size_t velocity, position;
    scene_get_solver_iterations(scene, &velocity, &position);
    put(out, "iterations %zu %zu\n", velocity, position);
    scene_t *defaults = scene_init();
    if (scene_get_warm_starting(scene) != scene_get_warm_starting(defaults)) {
        put(out, "warm_starting %s\n", scene_get_warm_starting(scene) ? "on" : "off");
    }
    double threshold = scene_get_restitution_threshold(scene);
    if (threshold != scene_get_restitution_threshold(defaults)) {
        put(out, "restitution_threshold");
        put_number(out, threshold);
        put(out, "\n");
    }
    double linear, angular, default_linear, default_angular;
    scene_get_sleep_tolerance(scene, &linear, &angular);
    scene_get_sleep_tolerance(defaults, &default_linear, &default_angular);
    if (linear != default_linear || angular != default_angular) {
        put(out, "sleep_tolerance");
        put_number(out, linear);
        if (isfinite(angular)) put_number(out, angular);
        put(out, "\n");
    }
    double time = scene_get_sleep_time(scene);
    if (time != scene_get_sleep_time(defaults)) {
        put(out, "sleep_time");
        put_number(out, time);
        put(out, "\n");
    }
    scene_free(defaults);
}

static void put_settings(out_t *out, scene_file_t *file, const char *integrator) {
    const sf_settings_t *s = &file->doc.settings;
    put(out, "gravity");
    put_vector(out, scene_get_gravity(file->scene));
    put(out, "\ncontacts %s\n", scene_get_contacts_enabled(file->scene) ? "on" : "off");
    put(out, "integrator %s\n", integrator);
    put_solver_settings(out, file->scene);
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
    size_t workers = scene_get_workers(file->scene);
    if (workers != 1 || s->workers != 0) put(out, "workers %zu\n", workers);
    if (s->stepping == SCENE_FILE_STEP_FRAME) put(out, "stepping frame\n");
    if (s->category[0] != '\0') put(out, "category %s\n", s->category);
    if (s->note[0] != '\0') put(out, "note %s\n", s->note);
    put(out, "sleeping %s\n", scene_get_sleeping(file->scene) ? "on" : "off");
    unsigned phase = scene_get_sleep_phase(file->scene);
    if (phase != 0) put(out, "sleep_phase %u\n", phase);
    uint64_t solver_steps = scene_get_solver_steps(file->scene);
    if (solver_steps != 0) put(out, "solver_steps %" PRIu64 "\n", solver_steps);
    double last, before;
    scene_get_step_lengths(file->scene, &last, &before);
    if (last != 0.0) {
        put(out, "step_lengths");
        put_number(out, last);
        put_number(out, before);
        put(out, "\n");
    }
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
    case SHAPE_CIRCLE:
        put(out, "    circle");
        put_number(out, shape->radius);
        break;
    case SHAPE_CAPSULE:
        put(out, "    capsule");
        put_vector(out, shape->ends[0]);
        put_vector(out, shape->ends[1]);
        put_number(out, shape->radius);
        break;
    case SHAPE_CHAIN:
    case SHAPE_LOOP:
        put(out, shape->kind == SHAPE_CHAIN ? "    chain" : "    loop");
        for (size_t i = 0; i < shape->count; i++) put_vector(out, shape->written[i]);
        break;
    default:
        put(out, "    vertices");
        for (size_t i = 0; i < shape->count; i++) put_vector(out, shape->written[i]);
        if (shape->as_centred) put(out, "\n    centred");
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
}

static void put_filter(out_t *out, uint32_t category, uint32_t mask, uint32_t group) {
    if (category == 1 && mask == UINT32_MAX && group == 0) return; /* the default */
    put(out, "    filter 0x%08x 0x%08x 0x%08x\n", (unsigned)category, (unsigned)mask,
        (unsigned)group);
}

static void put_live_filter(out_t *out, body_t *body) {
    uint32_t category, mask, group;
    body_get_collision_filter(body, &category, &mask, &group);
    put_filter(out, category, mask, group);
}

/* The body's sleep: its island's number (SIZE_MAX: awake) and its timer. */
static void put_sleep(out_t *out, body_t *body, size_t island) {
    if (island != SIZE_MAX) put(out, "    asleep %zu\n", island);
    body_sleep_timer_t timer = body_get_sleep_timer(body);
    if (timer.slow_time == 0.0 && timer.window == 0.0 && is_zero(timer.anchor) &&
        timer.anchor_angle == 0.0)
        return;
    put(out, "    sleep_timer");
    put_number(out, timer.slow_time);
    put_number(out, timer.window);
    put_vector(out, timer.anchor);
    put_number(out, timer.anchor_angle);
    put(out, "\n");
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
    if (spec->has_filter) put_filter(out, spec->category, spec->mask, spec->filter_group);
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

static void put_record(out_t *out, const sf_doc_t *doc, const sf_record_t *record,
                       size_t island) {
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
    put_live_filter(out, record->body);
    put_sleep(out, record->body, island);
    put(out, "}\n");
}

/* The shape of a body the file did not make, in its own frame. A circle is
 * exact; a capsule's ends are its world core turned back by its angle, the
 * same to rounding. */
static void put_foreign_shape(out_t *out, body_t *body) {
    body_shape_kind_t kind = body_get_shape_kind(body);
    if (kind == BODY_SHAPE_CIRCLE) {
        put(out, "    circle");
        put_number(out, body_get_round_radius(body));
        put(out, "\n");
        return;
    }
    if (kind == BODY_SHAPE_CAPSULE) {
        vector_t ends[2];
        body_get_core(body, &ends[0], &ends[1]);
        vector_t centroid = body_get_centroid(body);
        double angle = body_get_rotation(body);
        put(out, "    capsule");
        for (size_t i = 0; i < 2; i++) {
            put_vector(out, vec_rotate(vec_subtract(ends[i], centroid), -angle));
        }
        put_number(out, body_get_round_radius(body));
        put(out, "\n");
        return;
    }
    polygon_t polygon = body_get_local_polygon(body);
    if (kind == BODY_SHAPE_CHAIN) {
        /* Its points as made, in its frame: exact. */
        put(out, body_is_loop(body) ? "    loop" : "    chain");
        for (size_t i = 0; i < polygon.count; i++) put_vector(out, polygon.vertices[i]);
        put(out, "\n");
        return;
    }
    put(out, "    vertices");
    for (size_t i = 0; i < polygon.count; i++) put_vector(out, polygon.vertices[i]);
    put(out, "\n    centred\n");
}

/* A body the file did not make: its vertices in its own frame, taken as
 * they are (centred), so that it comes back the same to the bit. */
static void put_foreign(out_t *out, body_t *body, size_t island) {
    put(out, "\nbody {\n");
    put_foreign_shape(out, body);
    double mass = body_get_mass(body);
    put_mass(out, isinf(mass) ? MASS_STATIC : MASS_TOTAL, mass);
    state_t state = live_state(body);
    put_state(out, &state);
    put_live_filter(out, body);
    put_sleep(out, body, island);
    put(out, "}\n");
}

static int compare_by_body(const void *a, const void *b) {
    uintptr_t x = (uintptr_t)(*(sf_record_t *const *)a)->body;
    uintptr_t y = (uintptr_t)(*(sf_record_t *const *)b)->body;
    return x < y ? -1 : x > y;
}

/* A body written, with what the file needs to name it. */
typedef struct {
    body_t *body;
    size_t index;          /* its place among the bodies written */
    sf_record_t *record;   /* NULL for a body the file did not make */
    size_t island;         /* its island's number, SIZE_MAX when awake */
} written_t;

static int compare_written(const void *a, const void *b) {
    uintptr_t x = (uintptr_t)((const written_t *)a)->body;
    uintptr_t y = (uintptr_t)((const written_t *)b)->body;
    return x < y ? -1 : x > y;
}

/* The bodies written: every body in the scene, in scene order, not marked
 * removed. Returns them in that order; *by_body is the same sorted by body
 * address, for finding a body's entry. */
typedef struct {
    written_t *in_order, *by_body;
    size_t count;
} bodies_t;

static written_t *find_written(const bodies_t *bodies, body_t *body) {
    written_t key = {.body = body};
    written_t *found = bsearch(&key, bodies->by_body, bodies->count, sizeof key, compare_written);
    return found != NULL ? &bodies->in_order[found->index] : NULL;
}

/* Islands are numbered 0, 1, ... in the order their first bodies come. */
static void number_islands(bodies_t *bodies) {
    size_t islands = 0;
    for (size_t i = 0; i < bodies->count; i++) {
        written_t *w = &bodies->in_order[i];
        if (w->island != SIZE_MAX || !body_is_sleeping(w->body)) continue;
        body_t *member = w->body;
        do {
            written_t *m = find_written(bodies, member);
            if (m != NULL) m->island = islands;
            member = body_get_island_next(member);
        } while (member != NULL && member != w->body);
        islands++;
    }
}

/* The records sorted by body address tell the file's bodies from the others. */
static bodies_t list_bodies(scene_file_t *file) {
    sf_record_t **sorted = malloc((file->record_count + 1) * sizeof *sorted);
    if (sorted == NULL) abort();
    size_t live = 0;
    for (size_t i = 0; i < file->record_count; i++) {
        if (file->records[i]->body != NULL) sorted[live++] = file->records[i];
    }
    qsort(sorted, live, sizeof *sorted, compare_by_body);
    scene_t *scene = file->scene;
    size_t n = scene_bodies(scene);
    bodies_t bodies = {malloc((n + 1) * sizeof(written_t)), malloc((n + 1) * sizeof(written_t)), 0};
    if (bodies.in_order == NULL || bodies.by_body == NULL) abort();
    for (size_t i = 0; i < n; i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body)) continue;
        sf_record_t key_record = {.body = body};
        sf_record_t *key = &key_record;
        sf_record_t **found = bsearch(&key, sorted, live, sizeof *sorted, compare_by_body);
        bodies.in_order[bodies.count] =
            (written_t){body, bodies.count, found != NULL ? *found : NULL, SIZE_MAX};
        bodies.count++;
    }
    free(sorted);
    memcpy(bodies.by_body, bodies.in_order, bodies.count * sizeof(written_t));
    qsort(bodies.by_body, bodies.count, sizeof(written_t), compare_written);
    number_islands(&bodies);
    return bodies;
}

static void put_bodies(out_t *out, scene_file_t *file, const bodies_t *bodies) {
    for (size_t i = 0; i < bodies->count; i++) {
        const written_t *w = &bodies->in_order[i];
        if (w->record != NULL) {
            put_record(out, &file->doc, w->record, w->island);
        } else {
            put_foreign(out, w->body, w->island);
        }
    }
}

/* ---- The world's contact memory ---------------------------------------------- */

typedef struct {
    size_t a, b;
    scene_contact_memory_t memory;
} numbered_contact_t;

static int compare_numbered(const void *p, const void *q) {
    const numbered_contact_t *x = p, *y = q;
    if (x->a != y->a) return x->a < y->a ? -1 : 1;
    if (x->b != y->b) return x->b < y->b ? -1 : 1;
    return (x->memory.segment > y->memory.segment) - (x->memory.segment < y->memory.segment);
}

static void put_point(out_t *out, const scene_memory_point_t *p) {
    put(out, "    point %u", (unsigned)p->id);
    put_vector(out, p->point);
    put_number(out, p->separation);
    put_number(out, p->normal_impulse);
    put_number(out, p->tangent_impulse);
    put_number(out, p->restitution_impulse);
    put_number(out, p->restitution_tangent_impulse);
    put(out, "\n");
}

static void put_contact(out_t *out, const numbered_contact_t *c) {
    const scene_contact_memory_t *m = &c->memory;
    put(out, "contact %zu %zu {\n", c->a, c->b);
    if (body_get_shape_kind(m->body_b) == BODY_SHAPE_CHAIN) put(out, "    segment %zu\n", m->segment);
    put(out, "    normal");
    put_vector(out, m->normal);
    put(out, "\n");
    for (int j = 0; j < m->point_count; j++) put_point(out, &m->points[j]);
    put(out, "    face %s", m->flip ? "b" : "a");
    put_vector(out, m->face_normal);
    put_vector(out, m->face_point);
    if (isfinite(m->face_lead)) {
        put(out, " lead");
        put_number(out, m->face_lead);
    }
    put(out, "%s\n", m->edge_ends ? " edge" : "");
    for (int j = 0; j < m->feature_count; j++) {
        put(out, "    incident %u", (unsigned)m->feature_ids[j]);
        put_vector(out, m->feature_points[j]);
        put(out, "\n");
    }
    put(out, "    pose");
    put_vector(out, m->pose);
    put_number(out, m->pose_angle);
    put(out, "\n");
    for (int j = 0; j < m->previous_count; j++) {
        put(out, "    previous %u", (unsigned)m->previous[j].id);
        put_number(out, m->previous[j].normal_impulse);
        put_number(out, m->previous[j].tangent_impulse);
        put(out, "\n");
    }
    put(out, "}\n");
}

/* The contacts, by their bodies' places in the file, in that order. */
static void put_contacts(out_t *out, scene_file_t *file, const bodies_t *bodies) {
    size_t count = scene_contact_memory_count(file->scene);
    numbered_contact_t *contacts = malloc((count + 1) * sizeof *contacts);
    if (contacts == NULL) abort();
    size_t kept = 0;
    for (size_t i = 0; i < count; i++) {
        scene_contact_memory_t m = scene_get_contact_memory(file->scene, i);
        const written_t *a = find_written(bodies, m.body_a), *b = find_written(bodies, m.body_b);
        if (a == NULL || b == NULL) continue; /* a body marked removed */
        contacts[kept++] = (numbered_contact_t){a->index, b->index, m};
    }
    qsort(contacts, kept, sizeof *contacts, compare_numbered);
    if (kept > 0) put(out, "\n");
    for (size_t i = 0; i < kept; i++) put_contact(out, &contacts[i]);
    free(contacts);
}

/* The joint's impulses (scene_state.h), unless all are 0 (a joint not
 * solved yet). */
static void put_joint_state(out_t *out, joint_state_t state) {
    const joint_state_t zero = {{0.0, 0.0}, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    if (memcmp(&state, &zero, sizeof state) == 0) return;
    put(out, "    impulses");
    put_vector(out, state.point_impulse);
    put_number(out, state.angle_impulse);
    put_number(out, state.axial_impulse);
    put_number(out, state.spring_impulse);
    put_number(out, state.motor_impulse);
    put_number(out, state.lower_impulse);
    put_number(out, state.upper_impulse);
    put_number(out, state.step_length);
    put(out, "\n");
}

/* The joints of the scene, their bodies by their places in the file, each
 * field that differs from the type's default (to the bit) on a line. */
static void put_joint(out_t *out, const joint_t *joint, const bodies_t *bodies) {
    joint_def_t def = joint_get_def(joint);
    const written_t *b = find_written(bodies, def.body2);
    const written_t *a = def.body1 != NULL ? find_written(bodies, def.body1) : NULL;
    if (b == NULL || (def.body1 != NULL && a == NULL)) return; /* a body marked removed */
    put(out, "joint %s ", joint_type_name(def.type));
    if (a != NULL) {
        put(out, "%zu", a->index);
    } else {
        put(out, "world");
    }
    put(out, " %zu {\n", b->index);
    joint_def_t base = joint_def_default(def.type);
    for (size_t i = 0; i < SF_JOINT_FIELD_COUNT; i++) {
        const sf_joint_field_t *field = &SF_JOINT_FIELDS[i];
        const char *value = (const char *)&def + field->offset;
        const char *standard = (const char *)&base + field->offset;
        size_t size = field->kind == SF_FIELD_VECTOR   ? sizeof(vector_t)
                      : field->kind == SF_FIELD_NUMBER ? sizeof(double)
                                                       : sizeof(bool);
        if (memcmp(value, standard, size) == 0) continue;
        put(out, "    %s", field->name);
        if (field->kind == SF_FIELD_VECTOR) {
            put_vector(out, *(const vector_t *)value);
        } else if (field->kind == SF_FIELD_NUMBER) {
            put_number(out, *(const double *)value);
        } else {
            put(out, *(const bool *)value ? " on" : " off");
        }
        put(out, "\n");
    }
    put_joint_state(out, joint_get_state(joint));
    put(out, "}\n");
}

static void put_joints(out_t *out, scene_file_t *file, const bodies_t *bodies) {
    size_t count = scene_joints(file->scene);
    if (count > 0) put(out, "\n");
    for (size_t i = 0; i < count; i++) put_joint(out, scene_get_joint(file->scene, i), bodies);
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
                     "table (INTEGRATORS in engine/scenefile/scene_file_settings.c)",
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
    bodies_t bodies = list_bodies(file);
    put_bodies(&out, file, &bodies);
    if (doc->statement_count > 0) put(&out, "\n");
    for (size_t i = 0; i < doc->statement_count; i++) put_statement(&out, doc, &doc->statements[i]);
    put_joints(&out, file, &bodies);
    put_contacts(&out, file, &bodies);
    free(bodies.in_order);
    free(bodies.by_body);
    if (length != NULL) *length = out.length;
    return out.text;
}
