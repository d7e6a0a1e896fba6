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
}

static bool spec_in_group(const sf_body_t *spec, size_t group) {
    if (spec->own_group == group) return true;
    for (size_t i = 0; i < spec->group_count; i++) {
        if (spec->groups[i] == group) return true;
    }
    return false;
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

    list_t *shape = list_init(spec->shape.count, free);
    for (size_t i = 0; i < spec->shape.count; i++) {
        vector_t *v = malloc(sizeof *v);
        if (v == NULL) abort();
        *v = spec->shape.centred[i];
        list_add(shape, v);
    }
    body_t *body = body_init_with_info(shape, spec->mass, spec->color, record, record_freed);
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

static void make_force(scene_file_t *file, size_t statement, sf_record_t *a, sf_record_t *b) {
    const sf_statement_t *s = &file->doc.statements[statement];
    scene_t *scene = file->scene;
    switch (s->kind) {
    case STATEMENT_SPRING:
        if (s->has_rest_length) {
            create_spring_with_length(scene, s->constant, s->rest_length, a->body, b->body);
        } else {
            create_spring(scene, s->constant, a->body, b->body);
        }
        break;
    case STATEMENT_NEWTON: create_newtonian_gravity(scene, s->constant, a->body, b->body); break;
    case STATEMENT_DRAG: create_drag(scene, s->constant, a->body); break;
    case STATEMENT_PHYSICS: create_physics_collision(scene, a->body, b->body, s->constant); break;
    case STATEMENT_DESTRUCTIVE: create_destructive_collision(scene, a->body, b->body); break;
    }
    sf_reserve((void **)&file->instances, &file->instance_capacity, file->instance_count + 1,
               sizeof(sf_instance_t));
    file->instances[file->instance_count++] = (sf_instance_t){statement, a, b};
}

/* Whether a live record belongs to the set a reference names. */
static bool in_ref(const scene_file_t *file, const sf_ref_t *ref, const sf_record_t *record) {
    switch (ref->kind) {
    case REF_ALL: return true;
    case REF_BODY: return file->doc.bodies[ref->index].record == record;
    default: return spec_in_group(&file->doc.bodies[record->spec], ref->index);
    }
}

static bool in_refs(const scene_file_t *file, const sf_ref_t *refs, size_t count,
                    const sf_record_t *record) {
    for (size_t i = 0; i < count; i++) {
        if (in_ref(file, &refs[i], record)) return true;
    }
    return false;
}

/* The live records of a set (refs[0..count) together), in record order. */
static size_t members(const scene_file_t *file, const sf_ref_t *refs, size_t count,
                      sf_record_t **out) {
    size_t n = 0;
    for (size_t i = 0; i < file->record_count; i++) {
        sf_record_t *record = file->records[i];
        if (record->body != NULL && in_refs(file, refs, count, record)) out[n++] = record;
    }
    return n;
}

/* The pairs (or single bodies, for drag) a statement joins among the live
 * records: make them when make is true, else only count them. Each unordered
 * pair once; a collide pair is (member of the first side, member of the
 * second), and a pair whose both bodies are on both sides is taken with the
 * earlier body first. */
static size_t statement_pairs(scene_file_t *file, size_t statement, sf_record_t **scratch,
                              bool make) {
    const sf_statement_t *s = &file->doc.statements[statement];
    size_t made = 0;
    if (s->kind == STATEMENT_SPRING) {
        sf_record_t *a = file->doc.bodies[s->refs[0].index].record;
        sf_record_t *b = file->doc.bodies[s->refs[1].index].record;
        if (a == NULL || b == NULL || a->body == NULL || b->body == NULL) return 0;
        if (make) make_force(file, statement, a, b);
        return 1;
    }
    if (s->kind == STATEMENT_NEWTON || s->kind == STATEMENT_DRAG) {
        size_t n = members(file, s->refs, s->ref_count, scratch);
        if (s->kind == STATEMENT_DRAG) {
            for (size_t i = 0; make && i < n; i++) make_force(file, statement, scratch[i], NULL);
            return n;
        }
        for (size_t i = 0; make && i < n; i++) {
            for (size_t j = i + 1; j < n; j++) make_force(file, statement, scratch[i], scratch[j]);
        }
        return n * (n - 1) / 2;
    }
    size_t n = members(file, &s->refs[0], 1, scratch);
    sf_record_t **second = scratch + n;
    size_t m = members(file, &s->refs[1], 1, second);
    if (!make) {
        /* n m ordered pairs, less the bodies paired with themselves and the
         * pairs of two bodies on both sides, which come twice: counted without
         * walking the n m pairs, so that a file asking for far too many is
         * refused at once. */
        size_t both = 0;
        for (size_t i = 0; i < n; i++) both += in_ref(file, &s->refs[1], scratch[i]);
        return n * m - both - both * (both - 1) / 2;
    }
    for (size_t i = 0; i < n; i++) {
        sf_record_t *a = scratch[i];
        bool a_in_second = in_ref(file, &s->refs[1], a);
        for (size_t j = 0; j < m; j++) {
            sf_record_t *b = second[j];
            if (a == b) continue;
            if (a_in_second && in_ref(file, &s->refs[0], b) && a->index > b->index) continue;
            make_force(file, statement, a, b);
            made++;
        }
    }
    return made;
}

static bool make_forces(scene_file_t *file, sf_lexer_t *lexer) {
    sf_doc_t *doc = &file->doc;
    /* Room for both sides of a collide. */
    sf_record_t **scratch = malloc((2 * file->record_count + 1) * sizeof *scratch);
    if (scratch == NULL) abort();
    size_t total = 0;
    for (size_t i = 0; i < doc->statement_count; i++) {
        size_t pairs = statement_pairs(file, i, scratch, false);
        if (pairs > SCENE_FILE_MAX_FORCES - total) {
            free(scratch);
            return sf_fail(lexer, doc->statements[i].where,
                           "expected at most %d force creators from the forces and rules of a "
                           "file, found %zu with this %s",
                           SCENE_FILE_MAX_FORCES, total + pairs,
                           statement_name(doc->statements[i].kind));
        }
        total += pairs;
    }
    for (size_t i = 0; i < doc->statement_count; i++) statement_pairs(file, i, scratch, true);
    free(scratch);
    return true;
}

/* ---- Build ---------------------------------------------------------------- */

static void apply_settings(scene_file_t *file) {
    const sf_settings_t *s = &file->doc.settings;
    scene_set_gravity(file->scene, s->gravity);
    scene_set_contacts_enabled(file->scene, s->contacts);
    scene_set_integrator(file->scene, s->integrator);
    scene_set_solver_iterations(file->scene, s->velocity_iterations, s->position_iterations);
}

bool sf_build(scene_file_t *file, sf_lexer_t *lexer) {
    if (!resolve(&file->doc, lexer)) return false;
    file->scene = scene_init();
    apply_settings(file);
    make_bodies(file);
    return make_forces(file, lexer);
}

/* ---- Live ----------------------------------------------------------------- */

/* Drops the forces whose bodies the scene has freed. */
static void drop_orphan_forces(scene_file_t *file) {
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
    drop_orphan_forces(file);
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

size_t scene_file_force_count(scene_file_t *file) {
    drop_orphan_forces(file);
    return file->instance_count;
}

scene_file_force_t scene_file_get_force(scene_file_t *file, size_t index) {
    static const scene_file_force_kind_t KINDS[] = {
        [STATEMENT_SPRING] = SCENE_FILE_SPRING,
        [STATEMENT_NEWTON] = SCENE_FILE_NEWTON,
        [STATEMENT_DRAG] = SCENE_FILE_DRAG,
        [STATEMENT_PHYSICS] = SCENE_FILE_PHYSICS_COLLISION,
        [STATEMENT_DESTRUCTIVE] = SCENE_FILE_DESTRUCTIVE_COLLISION,
    };
    if (index >= file->instance_count) return (scene_file_force_t){0};
    const sf_instance_t *instance = &file->instances[index];
    const sf_statement_t *s = &file->doc.statements[instance->statement];
    return (scene_file_force_t){
        .kind = KINDS[s->kind],
        .constant = s->constant,
        .rest_length = s->rest_length,
        .body1 = instance->body1->body,
        .body2 = instance->body2 != NULL ? instance->body2->body : NULL,
    };
}

body_t *scene_file_find_body(scene_file_t *file, const char *name) {
    if (file == NULL || name == NULL) return NULL;
    sf_name_entry_t *entry = sf_names_find(&file->doc.names, name);
    if (entry == NULL || entry->is_group) return NULL;
    sf_record_t *record = file->doc.bodies[entry->index].record;
    return record != NULL ? record->body : NULL;
}

/* The force creators a new record of spec would join: counted, or made once
 * the record exists (then `record` is it and is skipped as a partner). */
static size_t spawn_pairs(scene_file_t *file, sf_record_t *record, size_t spec_index) {
    /* A stand-in with the new body's groups, to ask membership before it exists. */
    sf_record_t probe = {.spec = spec_index};
    const sf_record_t *self = record != NULL ? record : &probe;
    size_t count = 0;
    for (size_t s = 0; s < file->doc.statement_count; s++) {
        const sf_statement_t *st = &file->doc.statements[s];
        if (st->kind == STATEMENT_SPRING) continue; /* names single bodies only */
        if (st->kind == STATEMENT_NEWTON || st->kind == STATEMENT_DRAG) {
            if (!in_refs(file, st->refs, st->ref_count, self)) continue;
            if (st->kind == STATEMENT_DRAG) {
                if (record != NULL) make_force(file, s, record, NULL);
                count++;
                continue;
            }
        }
        bool first = st->kind == STATEMENT_NEWTON || in_ref(file, &st->refs[0], self);
        bool second = st->kind == STATEMENT_NEWTON || in_ref(file, &st->refs[1], self);
        if (!first && !second) continue;
        for (size_t i = 0; i < file->record_count; i++) {
            sf_record_t *other = file->records[i];
            if (other == record || other->body == NULL) continue;
            sf_record_t *a = NULL, *b = NULL;
            if (st->kind == STATEMENT_NEWTON) {
                if (!in_refs(file, st->refs, st->ref_count, other)) continue;
                a = other;
            } else if (second && in_ref(file, &st->refs[0], other)) {
                a = other; /* as the pair is taken at load: the earlier body first */
            } else if (first && in_ref(file, &st->refs[1], other)) {
                b = other;
            } else {
                continue;
            }
            if (record != NULL && a != NULL) make_force(file, s, a, record);
            if (record != NULL && b != NULL) make_force(file, s, record, b);
            count++;
        }
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
    size_t forces = scene_file_force_count(file);
    if (spawn_pairs(file, NULL, spec_index) > SCENE_FILE_MAX_FORCES - forces) return NULL;
    sf_record_t *record = make_body(file, spec_index, position, velocity);
    spawn_pairs(file, record, spec_index);
    return record->body;
}
