/*
 * From a checked description to an engine scene: names resolved, the force
 * creator limit checked, bodies made, forces and rules made pair by pair.
 * Also the live side: spawning from templates, and forgetting bodies the
 * engine has freed.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "scene_file_private.h"

/* ---- Names ---------------------------------------------------------------- */

static const char *statement_name(sf_statement_kind_t kind) {
    switch (kind) {
    case STATEMENT_SPRING: return "spring";
    case STATEMENT_NEWTON: return "newton";
    case STATEMENT_DRAG: return "drag";
    default: return "collide";
    }
}

static bool resolve_ref(sf_doc_t *doc, sf_lexer_t *lexer, const sf_statement_t *s, sf_ref_t *ref) {
    if (ref->kind == REF_ALL) return true;
    sf_name_entry_t *entry = sf_names_find(&doc->names, ref->name.text);
    if (entry == NULL) {
        return sf_fail(lexer, ref->where,
                       "expected the name of a body or group, found \"%s\", which names nothing "
                       "in the file",
                       ref->name.text);
    }
    if (s->kind == STATEMENT_SPRING && entry->is_group) {
        return sf_fail(lexer, ref->where,
                       "expected a single body for the spring, found \"%s\", a group (a "
                       "repeated body, a template or a group)",
                       ref->name.text);
    }
    ref->kind = entry->is_group ? REF_GROUP : REF_BODY;
    ref->index = entry->index;
    return true;
}

static bool resolve(sf_doc_t *doc, sf_lexer_t *lexer) {
    for (size_t i = 0; i < doc->statement_count; i++) {
        sf_statement_t *s = &doc->statements[i];
        for (size_t j = 0; j < s->ref_count; j++) {
            if (!resolve_ref(doc, lexer, s, &s->refs[j])) return false;
        }
        if (s->kind == STATEMENT_SPRING && s->refs[0].index == s->refs[1].index) {
            return sf_fail(lexer, s->refs[1].where,
                           "expected two different bodies for the spring, found \"%s\" twice",
                           s->refs[1].name.text);
        }
    }
    return true;
}

/* ---- Records -------------------------------------------------------------- */

/* The body's info freer: the engine frees the body (reaped, or with the
 * scene); the record stays until sf_collect, so that nothing holds a dangling
 * body pointer and a new body at the same address is never mistaken for it. */
static void record_freed(void *info) {
    sf_record_t *record = info;
    record->body = NULL;
    record->file->freed_records++;
    record->file->listing_fresh = false;
}

static bool spec_in_group(const sf_body_t *spec, size_t group) {
    if (spec->own_group == group) return true;
    for (size_t i = 0; i < spec->group_count; i++) {
        if (spec->groups[i] == group) return true;
    }
    return false;
}

/* A body of the spec's shape and mass, wherever the engine puts it: a
 * capsule from its ends as written, so that the same description makes the
 * same body to the bit. */
static body_t *make_shape(const sf_body_t *spec, sf_record_t *record) {
    const sf_shape_t *s = &spec->shape;
    if (s->kind == SHAPE_CIRCLE) {
        return body_init_circle_with_info(VEC_ZERO, s->radius, spec->mass, spec->color, record,
                                          record_freed);
    }
    if (s->kind == SHAPE_CAPSULE) {
        return body_init_capsule_with_info(s->ends[0], s->ends[1], s->radius, spec->mass,
                                           spec->color, record, record_freed);
    }
    if (s->kind == SHAPE_CHAIN || s->kind == SHAPE_LOOP) {
        return body_init_chain_with_info(s->written, s->count, s->kind == SHAPE_LOOP, spec->color,
                                         record, record_freed);
    }
    list_t *shape = list_init(s->count, free);
    for (size_t i = 0; i < s->count; i++) {
        vector_t *v = malloc(sizeof *v);
        if (v == NULL) abort();
        *v = s->centred[i];
        list_add(shape, v);
    }
    return s->as_centred
               ? body_init_centred(shape, spec->mass, spec->color, record, record_freed)
               : body_init_with_info(shape, spec->mass, spec->color, record, record_freed);
}

/* Makes a body of spec with its centroid at position and adds it to the
 * scene; every value was checked by the parser (or by spawn). */
static sf_record_t *make_body(scene_file_t *file, size_t spec_index, vector_t position,
                              vector_t velocity) {
    sf_doc_t *doc = &file->doc;
    const sf_body_t *spec = &doc->bodies[spec_index];
    sf_record_t *record = calloc(1, sizeof *record);
    if (record == NULL) abort();
    memcpy(record->tag, spec->tag.text, sizeof record->tag);
    record->file = file;
    record->spec = spec_index;
    record->index = file->record_count;

    body_t *body = make_shape(spec, record);
    body_set_centroid(body, position);
    body_set_rotation(body, spec->angle);
    body_set_velocity(body, velocity);
    body_set_angular_velocity(body, spec->spin);
    body_set_elasticity(body, spec->elasticity);
    body_set_friction(body, spec->friction);
    if (spec->has_filter) {
        body_set_collision_filter(body, spec->category, spec->mask, spec->filter_group);
    }
    scene_add_body(file->scene, body);
    record->body = body;

    sf_reserve((void **)&file->records, &file->record_capacity, file->record_count + 1,
               sizeof(sf_record_t *));
    file->records[file->record_count++] = record;
    file->listing_fresh = false;
    return record;
}

static void make_bodies(scene_file_t *file) {
    sf_doc_t *doc = &file->doc;
    for (size_t i = 0; i < doc->body_count; i++) {
        sf_body_t *spec = &doc->bodies[i];
        if (spec->is_template) continue;
        for (size_t y = 0; y < spec->repeat_y; y++) {
            for (size_t x = 0; x < spec->repeat_x; x++) {
                vector_t offset = {(double)x * spec->repeat_step.x,
                                   (double)y * spec->repeat_step.y};
                sf_record_t *record =
                    make_body(file, i, vec_add(spec->position, offset), spec->velocity);
                /* A single body is what its name refers to. */
                if (spec->own_group == SIZE_MAX && spec->name.text[0] != '\0')
                    spec->record = record;
            }
        }
    }
}

/* ---- Forces and rules ----------------------------------------------------- */

/* newton and collide: one engine group for all the pairs of the statement. */
static bool is_group_statement(sf_statement_kind_t kind) {
    return kind == STATEMENT_NEWTON || kind == STATEMENT_PHYSICS ||
           kind == STATEMENT_DESTRUCTIVE;
}

/* A spring or a drag: one engine force creator, listed as an instance. */
static void make_force(scene_file_t *file, size_t statement, sf_record_t *a, sf_record_t *b) {
    const sf_statement_t *s = &file->doc.statements[statement];
    if (s->kind == STATEMENT_SPRING && s->has_rest_length) {
        create_spring_with_length(file->scene, s->constant, s->rest_length, a->body, b->body);
    } else if (s->kind == STATEMENT_SPRING) {
        create_spring(file->scene, s->constant, a->body, b->body);
    } else {
        create_drag(file->scene, s->constant, a->body);
    }
    sf_reserve((void **)&file->instances, &file->instance_capacity, file->instance_count + 1,
               sizeof(sf_instance_t));
    /* After the instances of its statement and those before it: a spawned
     * body's drag is listed with its statement. */
    size_t place = file->instance_count;
    while (place > 0 && file->instances[place - 1].statement > statement) place--;
    memmove(&file->instances[place + 1], &file->instances[place],
            (file->instance_count - place) * sizeof(sf_instance_t));
    file->instances[place] = (sf_instance_t){statement, a, b};
    file->instance_count++;
}

/* Whether a live record belongs to the set a reference names. */
bool sf_in_ref(const scene_file_t *file, const sf_ref_t *ref, const sf_record_t *record) {
    switch (ref->kind) {
    case REF_ALL: return true;
    case REF_BODY: return file->doc.bodies[ref->index].record == record;
    default: return spec_in_group(&file->doc.bodies[record->spec], ref->index);
    }
}

static bool in_refs(const scene_file_t *file, const sf_ref_t *refs, size_t count,
                    const sf_record_t *record) {
    for (size_t i = 0; i < count; i++) {
        if (sf_in_ref(file, &refs[i], record)) return true;
    }
    return false;
}

size_t sf_members(const scene_file_t *file, const sf_ref_t *refs, size_t count,
                  sf_record_t **out) {
    size_t n = 0;
    for (size_t i = 0; i < file->record_count; i++) {
        sf_record_t *record = file->records[i];
        if (record->body != NULL && in_refs(file, refs, count, record)) out[n++] = record;
    }
    return n;
}

/* The sets a record of a group statement is on: newton's one set (1), a
 * collide's first side (1) and second (2). */
static int sides_of(const scene_file_t *file, const sf_statement_t *s, const sf_record_t *record) {
    if (s->kind == STATEMENT_NEWTON) return in_refs(file, s->refs, s->ref_count, record);
    return sf_in_ref(file, &s->refs[0], record) | sf_in_ref(file, &s->refs[1], record) << 1;
}

static void join_group(scene_file_t *file, size_t statement, sf_record_t *record) {
    const sf_statement_t *s = &file->doc.statements[statement];
    int sides = sides_of(file, s, record);
    if (sides == 0) return;
    if (s->kind == STATEMENT_NEWTON) {
        gravity_group_add(file->groups[statement].gravity, record->body);
    } else {
        collision_group_add(file->groups[statement].collision, record->body, sides & 1,
                            (sides & 2) != 0);
    }
}

/* The statement's engine group, its members joined in record order: the
 * pairs in the order the pairwise creators would have been made. */
static void make_group(scene_file_t *file, size_t statement) {
    const sf_statement_t *s = &file->doc.statements[statement];
    list_t *none = list_init(0, NULL);
    if (s->kind == STATEMENT_NEWTON) {
        file->groups[statement].gravity =
            create_newtonian_gravity_group(file->scene, s->constant, none);
    } else {
        bool physics = s->kind == STATEMENT_PHYSICS;
        file->groups[statement].collision = create_collision_group(
            file->scene, none, none,
            physics ? physics_collision_handler : destructive_collision_handler, NULL,
            physics ? s->constant : 0.0);
    }
    list_free(none);
    for (size_t i = 0; i < file->record_count; i++) {
        if (file->records[i]->body != NULL) join_group(file, statement, file->records[i]);
    }
}

size_t sf_statement_pairs(const scene_file_t *file, size_t statement, sf_record_t **scratch) {
    const sf_statement_t *s = &file->doc.statements[statement];
    if (s->kind == STATEMENT_SPRING) {
        const sf_record_t *a = file->doc.bodies[s->refs[0].index].record;
        const sf_record_t *b = file->doc.bodies[s->refs[1].index].record;
        return a != NULL && b != NULL && a->body != NULL && b->body != NULL;
    }
    if (s->kind == STATEMENT_NEWTON || s->kind == STATEMENT_DRAG) {
        size_t n = sf_members(file, s->refs, s->ref_count, scratch);
        return s->kind == STATEMENT_DRAG ? n : n * (n - (n > 0)) / 2;
    }
    size_t n = sf_members(file, &s->refs[0], 1, scratch);
    size_t m = sf_members(file, &s->refs[1], 1, scratch + n);
    /* n m ordered pairs, less the bodies paired with themselves and the
     * pairs of two bodies on both sides, which come twice. */
    size_t both = 0;
    for (size_t i = 0; i < n; i++) both += sf_in_ref(file, &s->refs[1], scratch[i]);
    return n * m - both - both * (both - (both > 0)) / 2;
}

/* The force creators a statement makes: one per spring or drag instance,
 * one for the group of a newton or collide. */
static size_t statement_creators(const scene_file_t *file, size_t statement,
                                 sf_record_t **scratch) {
    if (is_group_statement(file->doc.statements[statement].kind)) return 1;
    return sf_statement_pairs(file, statement, scratch);
}

static void make_statement(scene_file_t *file, size_t statement, sf_record_t **scratch) {
    const sf_statement_t *s = &file->doc.statements[statement];
    if (is_group_statement(s->kind)) {
        make_group(file, statement);
    } else if (s->kind == STATEMENT_SPRING) {
        sf_record_t *a = file->doc.bodies[s->refs[0].index].record;
        sf_record_t *b = file->doc.bodies[s->refs[1].index].record;
        if (a != NULL && b != NULL && a->body != NULL && b->body != NULL) {
            make_force(file, statement, a, b);
        }
    } else {
        size_t n = sf_members(file, s->refs, s->ref_count, scratch);
        for (size_t i = 0; i < n; i++) make_force(file, statement, scratch[i], NULL);
    }
}

static bool make_forces(scene_file_t *file, sf_lexer_t *lexer) {
    sf_doc_t *doc = &file->doc;
    /* Room for both sides of a collide. */
    sf_record_t **scratch = malloc((2 * file->record_count + 1) * sizeof *scratch);
    if (scratch == NULL) abort();
    size_t total = 0;
    for (size_t i = 0; i < doc->statement_count; i++) {
        size_t creators = statement_creators(file, i, scratch);
        if (creators > SCENE_FILE_MAX_FORCES - total) {
            free(scratch);
            return sf_fail(lexer, doc->statements[i].where,
                           "expected at most %d force creators from the forces and rules of a "
                           "file, found %zu with this %s",
                           SCENE_FILE_MAX_FORCES, total + creators,
                           statement_name(doc->statements[i].kind));
        }
        total += creators;
    }
    file->groups = calloc(doc->statement_count + 1, sizeof *file->groups);
    if (file->groups == NULL) abort();
    for (size_t i = 0; i < doc->statement_count; i++) make_statement(file, i, scratch);
    free(scratch);
    return true;
}

/* ---- The state a continuation needs (scene_state.h) ------------------------ */

static bool is_unit(vector_t v) {
    return fabs(sqrt(v.x * v.x + v.y * v.y) - 1.0) <= 1e-9;
}

static int compare_contact_pairs(const void *p, const void *q) {
    const sf_contact_t *a = *(const sf_contact_t *const *)p, *b = *(const sf_contact_t *const *)q;
    if (a->body_a != b->body_a) return a->body_a < b->body_a ? -1 : 1;
    if (a->body_b != b->body_b) return a->body_b < b->body_b ? -1 : 1;
    if (a->memory.segment != b->memory.segment) return a->memory.segment < b->memory.segment ? -1 : 1;
    return a->where.line < b->where.line ? -1 : a->where.line > b->where.line;
}

/* The shape of the file's body number `index` (in the order the file
 * makes them); NULL past the last. */
static const sf_shape_t *shape_of(const sf_doc_t *doc, size_t index) {
    for (size_t i = 0; i < doc->body_count; i++) {
        const sf_body_t *spec = &doc->bodies[i];
        if (spec->is_template) continue;
        size_t copies = spec->repeat_x * spec->repeat_y;
        if (index < copies) return &spec->shape;
        index -= copies;
    }
    return NULL;
}

static bool is_chain(const sf_shape_t *shape) {
    return shape != NULL && (shape->kind == SHAPE_CHAIN || shape->kind == SHAPE_LOOP);
}

/* Whether the body is a circle, a capsule or a chain: its manifold is
 * found again each step, and keeps no face. */
static bool is_round(const sf_doc_t *doc, size_t index) {
    const sf_shape_t *shape = shape_of(doc, index);
    return shape != NULL && (shape->kind == SHAPE_CIRCLE || shape->kind == SHAPE_CAPSULE ||
                             is_chain(shape));
}

/* A contact with a chain names one of its segments, the chain second. */
static bool check_segment(const sf_doc_t *doc, const sf_contact_t *c, sf_lexer_t *lexer) {
    if (is_chain(shape_of(doc, c->body_a))) {
        return sf_fail(lexer, c->where, "expected the chain as the contact's second body, found it first");
    }
    const sf_shape_t *b = shape_of(doc, c->body_b);
    size_t segments = !is_chain(b) ? 0 : b->kind == SHAPE_LOOP ? b->count : b->count - 1;
    if (segments > 0 ? c->memory.segment >= segments : c->memory.segment != 0) {
        return sf_fail(lexer, c->where,
                       "expected a segment of body %zu (it has %zu), found segment %zu",
                       c->body_b, segments, c->memory.segment);
    }
    return true;
}

/* The contact blocks name two different bodies the file makes, once per
 * pair, with unit normals (a round pair's face normal may be zero). */
static bool check_contacts(const sf_doc_t *doc, sf_lexer_t *lexer) {
    for (size_t i = 0; i < doc->contact_count; i++) {
        const sf_contact_t *c = &doc->contacts[i];
        size_t last = c->body_a > c->body_b ? c->body_a : c->body_b;
        if (last >= doc->total_bodies) {
            return sf_fail(lexer, c->where,
                           "expected bodies numbered from 0 to %zu (the file makes %zu), found %zu",
                           doc->total_bodies == 0 ? 0 : doc->total_bodies - 1, doc->total_bodies,
                           last);
        }
        if (c->body_a == c->body_b) {
            return sf_fail(lexer, c->where, "expected two different bodies, found %zu twice",
                           c->body_a);
        }
        /* A round pair keeps no face (its manifold is found again each
         * step): its face normal is zero. */
        if (!check_segment(doc, c, lexer)) return false;
        bool round = is_round(doc, c->body_a) || is_round(doc, c->body_b);
        bool face_ok = is_unit(c->memory.face_normal) ||
                       (round && c->memory.face_normal.x == 0.0 && c->memory.face_normal.y == 0.0);
        if (!is_unit(c->memory.normal) || !face_ok) {
            return sf_fail(lexer, c->where,
                           "expected unit vectors for the normal and the face's normal, found "
                           "lengths %g and %g",
                           vec_get_length(c->memory.normal), vec_get_length(c->memory.face_normal));
        }
    }
    const sf_contact_t **sorted = malloc((doc->contact_count + 1) * sizeof *sorted);
    if (sorted == NULL) abort();
    for (size_t i = 0; i < doc->contact_count; i++) sorted[i] = &doc->contacts[i];
    qsort(sorted, doc->contact_count, sizeof *sorted, compare_contact_pairs);
    for (size_t i = 1; i < doc->contact_count; i++) {
        const sf_contact_t *c = sorted[i], *before = sorted[i - 1];
        if (c->body_a == before->body_a && c->body_b == before->body_b &&
            c->memory.segment == before->memory.segment) {
            sf_where_t where = sorted[i]->where, first = sorted[i - 1]->where;
            size_t a = sorted[i]->body_a, b = sorted[i]->body_b;
            free(sorted);
            return sf_fail(lexer, where,
                           "expected one contact per pair, found a second for %zu and %zu (the "
                           "first at line %zu)",
                           a, b, first.line);
        }
    }
    free(sorted);
    return true;
}

/* Sleep state and contact memory are the world's: they need its contacts,
 * and sleep needs sleeping on. */
static bool check_state(const sf_doc_t *doc, sf_lexer_t *lexer) {
    const sf_settings_t *s = &doc->settings;
    sf_where_t needs_contacts = doc->first_island;
    if (needs_contacts.line == 0 && doc->contact_count > 0) needs_contacts = doc->contacts[0].where;
    if (needs_contacts.line == 0) needs_contacts = s->sleep_phase_where;
    if (needs_contacts.line == 0) needs_contacts = s->solver_steps_where;
    if (needs_contacts.line == 0) needs_contacts = s->step_lengths_where;
    if (needs_contacts.line != 0 && !s->contacts) {
        return sf_fail(lexer, needs_contacts,
                       "expected contacts on for the world's state (asleep, contact, sleep_phase, "
                       "solver_steps, step_lengths), found contacts off");
    }
    if (s->step_lengths_where.line != 0 && s->last_step == 0.0 && s->step_before != 0.0) {
        return sf_fail(lexer, s->step_lengths_where,
                       "expected a last step longer than 0 when the step before it has a length, "
                       "found 0 and %g",
                       s->step_before);
    }
    if (doc->first_island.line != 0 && !s->sleeping) {
        return sf_fail(lexer, doc->first_island,
                       "expected sleeping on for a body asleep, found sleeping off");
    }
    return check_contacts(doc, lexer);
}

/* After every body is made and set: the timers (which setting a body's
 * pose restarts), the sleeping islands, the phase, the step lengths, the
 * contact memory. */
static void restore_state(scene_file_t *file) {
    sf_doc_t *doc = &file->doc;
    scene_t *scene = file->scene;
    body_t **sleepers = malloc((file->record_count + 1) * sizeof *sleepers);
    size_t *islands = malloc((file->record_count + 1) * sizeof *islands);
    if (sleepers == NULL || islands == NULL) abort();
    size_t asleep = 0;
    for (size_t i = 0; i < file->record_count; i++) {
        const sf_body_t *spec = &doc->bodies[file->records[i]->spec];
        body_t *body = file->records[i]->body;
        if (spec->has_timer) body_set_sleep_timer(body, spec->timer);
        if (spec->has_island) {
            sleepers[asleep] = body;
            islands[asleep++] = spec->island;
        }
    }
    if (asleep > 0) scene_restore_sleep(scene, sleepers, islands, asleep);
    free(sleepers);
    free(islands);
    if (doc->settings.sleep_phase_where.line != 0) {
        scene_set_sleep_phase(scene, doc->settings.sleep_phase);
    }
    if (doc->settings.solver_steps_where.line != 0) {
        scene_set_solver_steps(scene, doc->settings.solver_steps);
    }
    if (doc->settings.step_lengths_where.line != 0) {
        scene_set_step_lengths(scene, doc->settings.last_step, doc->settings.step_before);
    }
    if (doc->contact_count == 0) return;
    scene_contact_memory_t *memories = malloc(doc->contact_count * sizeof *memories);
    if (memories == NULL) abort();
    for (size_t i = 0; i < doc->contact_count; i++) {
        const sf_contact_t *c = &doc->contacts[i];
        memories[i] = c->memory;
        memories[i].body_a = file->records[c->body_a]->body;
        memories[i].body_b = file->records[c->body_b]->body;
    }
    scene_restore_contact_memory(scene, memories, doc->contact_count);
    free(memories);
}

/* ---- Build ---------------------------------------------------------------- */

static void apply_settings(scene_file_t *file) {
    const sf_settings_t *s = &file->doc.settings;
    scene_set_gravity(file->scene, s->gravity);
    scene_set_contacts_enabled(file->scene, s->contacts);
    scene_set_integrator(file->scene, s->integrator);
    scene_set_solver_iterations(file->scene, s->velocity_iterations, s->position_iterations);
    if (s->warm_starting_where.line != 0) scene_set_warm_starting(file->scene, s->warm_starting);
    if (s->restitution_threshold_where.line != 0) {
        scene_set_restitution_threshold(file->scene, s->restitution_threshold);
    }
    if (s->sleep_tolerance_where.line != 0) {
        scene_set_sleep_tolerance(file->scene, s->sleep_linear, s->sleep_angular);
    }
    if (s->sleep_time_where.line != 0) scene_set_sleep_time(file->scene, s->sleep_time);
    scene_set_sleeping(file->scene, s->sleeping);
    if (s->workers != 0) scene_set_workers(file->scene, s->workers);
}

bool sf_build(scene_file_t *file, sf_lexer_t *lexer) {
    if (!resolve(&file->doc, lexer) || !check_state(&file->doc, lexer) ||
        !sf_check_joints(&file->doc, lexer))
        return false;
    file->scene = scene_init();
    apply_settings(file);
    make_bodies(file);
    if (!make_forces(file, lexer)) return false;
    /* before the sleep state: a new joint wakes its bodies */
    if (!sf_make_joints(file, lexer)) return false;
    restore_state(file);
    return true;
}

/* ---- Live ----------------------------------------------------------------- */

/* Drops the instances whose bodies the scene has freed. */
void sf_drop_orphan_forces(scene_file_t *file) {
    size_t kept = 0;
    for (size_t i = 0; i < file->instance_count; i++) {
        sf_instance_t *instance = &file->instances[i];
        if (instance->body1->body == NULL) continue;
        if (instance->body2 != NULL && instance->body2->body == NULL) continue;
        file->instances[kept++] = *instance;
    }
    file->instance_count = kept;
}

void sf_collect(scene_file_t *file) {
    sf_drop_orphan_forces(file);
    sf_doc_t *doc = &file->doc;
    for (size_t i = 0; i < doc->body_count; i++) {
        if (doc->bodies[i].record != NULL && doc->bodies[i].record->body == NULL)
            doc->bodies[i].record = NULL;
    }
    size_t kept = 0;
    for (size_t i = 0; i < file->record_count; i++) {
        sf_record_t *record = file->records[i];
        if (record->body == NULL) {
            free(record);
            continue;
        }
        record->index = kept;
        file->records[kept++] = record;
    }
    file->record_count = kept;
    file->freed_records = 0;
}

const char *scene_file_body_name(scene_file_t *file, body_t *body) {
    if (file == NULL || body == NULL) return NULL;
    for (size_t i = 0; i < file->record_count; i++) {
        const sf_record_t *record = file->records[i];
        if (record->body == body) return file->doc.bodies[record->spec].name.text;
    }
    return NULL;
}

body_t *scene_file_find_body(scene_file_t *file, const char *name) {
    if (file == NULL || name == NULL) return NULL;
    sf_name_entry_t *entry = sf_names_find(&file->doc.names, name);
    if (entry == NULL || entry->is_group) return NULL;
    sf_record_t *record = file->doc.bodies[entry->index].record;
    return record != NULL ? record->body : NULL;
}

/* The force creators a new record of spec would add: a drag for each drag
 * statement naming one of its groups (newton and collide add it to their
 * group, and springs name single bodies only). */
static size_t spawn_creators(const scene_file_t *file, size_t spec_index) {
    /* A stand-in with the new body's groups, to ask membership before it exists. */
    sf_record_t probe = {.spec = spec_index};
    size_t count = 0;
    for (size_t s = 0; s < file->doc.statement_count; s++) {
        const sf_statement_t *st = &file->doc.statements[s];
        count += st->kind == STATEMENT_DRAG && in_refs(file, st->refs, st->ref_count, &probe);
    }
    return count;
}

/* The new record joins every force and rule that names one of its groups. */
static void spawn_join(scene_file_t *file, sf_record_t *record) {
    for (size_t s = 0; s < file->doc.statement_count; s++) {
        const sf_statement_t *st = &file->doc.statements[s];
        if (is_group_statement(st->kind)) {
            join_group(file, s, record);
        } else if (st->kind == STATEMENT_DRAG && in_refs(file, st->refs, st->ref_count, record)) {
            make_force(file, s, record, NULL);
        }
    }
}

/* Force creators alive: the instances, and a group per newton or collide. */
static size_t creator_count(scene_file_t *file) {
    sf_drop_orphan_forces(file);
    size_t count = file->instance_count;
    for (size_t s = 0; s < file->doc.statement_count; s++) {
        count += is_group_statement(file->doc.statements[s].kind);
    }
    return count;
}

static bool within(vector_t v, double limit) {
    return vec_is_finite(v) && fabs(v.x) <= limit && fabs(v.y) <= limit;
}

/* The index of the template of that name, or SIZE_MAX. */
static size_t find_template(scene_file_t *file, const char *template_name) {
    if (file == NULL || template_name == NULL) return SIZE_MAX;
    sf_name_entry_t *entry = sf_names_find(&file->doc.names, template_name);
    if (entry == NULL || !entry->is_group) return SIZE_MAX;
    return file->doc.groups[entry->index].template_body;
}

bool scene_file_has_template(scene_file_t *file, const char *template_name) {
    return find_template(file, template_name) != SIZE_MAX;
}

body_t *scene_file_spawn(scene_file_t *file, const char *template_name, vector_t position,
                         vector_t velocity) {
    size_t spec_index = find_template(file, template_name);
    if (spec_index == SIZE_MAX) return NULL;
    if (!within(position, SF_MAX_LENGTH) || !within(velocity, SF_MAX_MOTION)) return NULL;
    size_t live = file->record_count - file->freed_records;
    if (file->freed_records > 64 && file->freed_records > live) sf_collect(file);
    if (live + 1 > SCENE_FILE_MAX_BODIES) return NULL;
    size_t forces = creator_count(file);
    if (spawn_creators(file, spec_index) > SCENE_FILE_MAX_FORCES - forces) return NULL;
    sf_record_t *record = make_body(file, spec_index, position, velocity);
    spawn_join(file, record);
    return record->body;
}
