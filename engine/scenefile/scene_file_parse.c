/*
 * Tokens to a description (sf_doc_t). Every value is checked here, where the
 * token that wrote it is at hand for the message; names that forces and rules
 * use are resolved later (scene_file_build.c), since a rule may come before
 * the bodies it names. This file reads the file statement by statement, the
 * numbers and the names; each kind of statement has its own
 * (scene_file_parse.h).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_file_parse.h"

static const double DEFAULT_TIMESTEP = 1.0 / 120.0;

/* "expected WHAT, found TOKEN" at the current token. */
bool sf_expected(parser_t *p, const char *what) {
    char found[128];
    sf_describe(&p->token, found, sizeof found);
    return sf_fail(p->lexer, p->token.where, "expected %s, found %s", what, found);
}

/* ---- Numbers with their ranges -------------------------------------------- */

bool sf_read_quantity(parser_t *p, const quantity_t *q, double *out) {
    char expectation[256];
    double value = 0.0;
    switch (sf_read_number(&p->token, q->angle, &value)) {
    case SF_NUMBER_OK: break;
    case SF_NUMBER_SYNTAX:
        snprintf(expectation, sizeof expectation, "%s, a number", q->what);
        return sf_expected(p, expectation);
    case SF_NUMBER_NOT_FINITE:
        snprintf(expectation, sizeof expectation, "%s, a finite number", q->what);
        return sf_expected(p, expectation);
    case SF_NUMBER_ZERO_DENOMINATOR:
        snprintf(expectation, sizeof expectation, "%s, a fraction with a denominator other than 0",
                 q->what);
        return sf_expected(p, expectation);
    }
    bool low_ok = q->min_open ? value > q->min : value >= q->min;
    if (!low_ok || value > q->max) {
        snprintf(expectation, sizeof expectation, "%s, a number %s %g and <= %g", q->what,
                 q->min_open ? ">" : ">=", q->min, q->max);
        return sf_expected(p, expectation);
    }
    *out = value;
    next(p);
    return true;
}

bool sf_read_vector(parser_t *p, const quantity_t *q, vector_t *out) {
    return sf_read_quantity(p, q, &out->x) && sf_read_quantity(p, q, &out->y);
}

bool sf_read_count(parser_t *p, const char *what, uint64_t min, uint64_t max, uint64_t *out) {
    uint64_t value = 0;
    if (!sf_read_integer(&p->token, UINT64_MAX, false, &value) || value < min || value > max) {
        char expectation[256];
        snprintf(expectation, sizeof expectation, "%s, a whole number from %llu to %llu", what,
                 (unsigned long long)min, (unsigned long long)max);
        return sf_expected(p, expectation);
    }
    *out = value;
    next(p);
    return true;
}

bool sf_read_bits(parser_t *p, const char *what, uint32_t *out) {
    uint64_t value = 0;
    if (!sf_read_integer(&p->token, UINT32_MAX, true, &value)) {
        char expectation[256];
        snprintf(expectation, sizeof expectation,
                 "%s, a whole number from 0 to 4294967295 (or 0x0 to 0xffffffff)", what);
        return sf_expected(p, expectation);
    }
    *out = (uint32_t)value;
    next(p);
    return true;
}

/* ---- Names ---------------------------------------------------------------- */

static const char NAME_RULE[] =
    "a letter or '_', then letters, digits, '_', '.' or '-', at most 63 characters";

bool sf_read_name(parser_t *p, const char *what, sf_name_t *out, sf_where_t *where) {
    if (!sf_is_name(&p->token)) {
        char expectation[256];
        snprintf(expectation, sizeof expectation, "%s (%s)", what, NAME_RULE);
        return sf_expected(p, expectation);
    }
    memcpy(out->text, p->token.text, p->token.length);
    out->text[p->token.length] = '\0';
    if (where != NULL) *where = p->token.where;
    next(p);
    return true;
}

/* A name that a body or group is being given: not `all`, which stands for
 * every body. */
bool sf_read_new_name(parser_t *p, const char *what, sf_name_t *out, sf_where_t *where) {
    if (sf_token_is(&p->token, "all")) {
        char expectation[256];
        snprintf(expectation, sizeof expectation, "%s other than all (all stands for every body)",
                 what);
        return sf_expected(p, expectation);
    }
    return sf_read_name(p, what, out, where);
}

static size_t hash_name(const char *key) {
    uint64_t h = 14695981039346656037u; /* FNV-1a, 64-bit also where size_t is not */
    for (; *key != '\0'; key++) h = (h ^ (unsigned char)*key) * 1099511628211u;
    return (size_t)h;
}

sf_name_entry_t *sf_names_find(sf_names_t *names, const char *key) {
    if (names->capacity == 0) return NULL;
    for (size_t i = hash_name(key) & (names->capacity - 1);; i = (i + 1) & (names->capacity - 1)) {
        sf_name_entry_t *slot = &names->slots[i];
        if (!slot->used) return NULL;
        if (strcmp(slot->key.text, key) == 0) return slot;
    }
}

static sf_name_entry_t *insert(sf_names_t *names, const sf_name_entry_t *entry) {
    size_t i = hash_name(entry->key.text) & (names->capacity - 1);
    while (names->slots[i].used) i = (i + 1) & (names->capacity - 1);
    names->slots[i] = *entry;
    names->count++;
    return &names->slots[i];
}

sf_name_entry_t *sf_names_add(sf_names_t *names, const char *key, bool is_group, size_t index) {
    if (2 * (names->count + 1) > names->capacity) {
        size_t capacity = names->capacity < 16 ? 32 : 2 * names->capacity;
        sf_names_t grown = {calloc(capacity, sizeof(sf_name_entry_t)), capacity, 0};
        if (grown.slots == NULL) abort();
        for (size_t i = 0; i < names->capacity; i++) {
            if (names->slots[i].used) insert(&grown, &names->slots[i]);
        }
        free(names->slots);
        *names = grown;
    }
    sf_name_entry_t entry = {.used = true, .is_group = is_group, .index = index};
    snprintf(entry.key.text, sizeof entry.key.text, "%s", key);
    return insert(names, &entry);
}

/* Where a name was first given, for "already the name of ...". */
sf_where_t sf_entry_where(const sf_doc_t *doc, const sf_name_entry_t *entry) {
    return entry->is_group ? doc->groups[entry->index].where : doc->bodies[entry->index].where;
}

/* The group called name, made when new. False (with the message) when name is
 * a single body's. The body being parsed may not be in doc->bodies yet, so
 * its block's `where` comes from the caller. */
bool sf_find_or_make_group(parser_t *p, const sf_name_t *name, sf_where_t where,
                           size_t *group) {
    sf_doc_t *doc = p->doc;
    sf_name_entry_t *entry = sf_names_find(&doc->names, name->text);
    if (entry != NULL && !entry->is_group) {
        sf_where_t first = sf_entry_where(doc, entry);
        return sf_fail(p->lexer, where,
                       "expected a group name, found \"%s\", already the name of a body (line %zu)",
                       name->text, first.line);
    }
    if (entry != NULL) {
        *group = entry->index;
        return true;
    }
    sf_reserve((void **)&doc->groups, &doc->group_capacity, doc->group_count + 1,
               sizeof(sf_group_t));
    sf_group_t *made = &doc->groups[doc->group_count];
    *made = (sf_group_t){.name = *name, .where = where, .template_body = SIZE_MAX};
    *group = doc->group_count++;
    sf_names_add(&doc->names, name->text, true, *group);
    return true;
}

/* One or more group names up to the end of the statement or property, added
 * to *groups (each once). */
bool sf_read_group_names(parser_t *p, size_t **groups, size_t *count) {
    do {
        sf_name_t name;
        sf_where_t where;
        if (!sf_read_new_name(p, "a group name", &name, &where)) return false;
        size_t group;
        if (!sf_find_or_make_group(p, &name, where, &group)) return false;
        bool listed = false;
        for (size_t i = 0; i < *count; i++) listed = listed || (*groups)[i] == group;
        if (listed) continue;
        size_t *grown = realloc(*groups, (*count + 1) * sizeof(size_t));
        if (grown == NULL) abort();
        *groups = grown;
        (*groups)[(*count)++] = group;
    } while (p->token.kind == TOKEN_WORD);
    return true;
}

/* ---- Statements written once ---------------------------------------------- */

/* A setting may be given once: a second one is more likely a mistake than an
 * override. */
bool sf_first_time(parser_t *p, sf_where_t *seen, const char *keyword, sf_where_t here) {
    if (seen->line != 0) {
        return sf_fail(p->lexer, here,
                       "expected one %s statement per file, found a second (the first at line %zu)",
                       keyword, seen->line);
    }
    *seen = here;
    return true;
}

/* ---- The file ------------------------------------------------------------- */

static const char *const SETTINGS[] = {
    "gravity",     "contacts",     "integrator",    "iterations",
    "timestep",    "view",         "game",          "sleeping",
    "sleep_phase", "solver_steps", "step_lengths", "warm_starting", "restitution_threshold",
    "sleep_tolerance", "sleep_time", "workers",     "stepping",
    "category",    "note"};
static const char *const FORCES[] = {"spring", "newton", "drag", "collide"};

static bool parse_one(parser_t *p) {
    sf_where_t here = p->token.where;
    char keyword[32] = "";
    if (p->token.kind == TOKEN_WORD && p->token.length < sizeof keyword) {
        memcpy(keyword, p->token.text, p->token.length);
        keyword[p->token.length] = '\0';
    }
    for (size_t i = 0; i < sizeof SETTINGS / sizeof SETTINGS[0]; i++) {
        if (strcmp(keyword, SETTINGS[i]) == 0) {
            next(p);
            return sf_parse_setting(p, keyword, here);
        }
    }
    for (size_t i = 0; i < sizeof FORCES / sizeof FORCES[0]; i++) {
        if (strcmp(keyword, FORCES[i]) == 0) {
            next(p);
            return sf_parse_statement(p, keyword, here);
        }
    }
    if (strcmp(keyword, "body") == 0 || strcmp(keyword, "template") == 0) {
        next(p);
        return sf_parse_body(p, keyword[0] == 't', here);
    }
    if (strcmp(keyword, "contact") == 0) {
        next(p);
        return sf_parse_contact(p, here);
    }
    if (strcmp(keyword, "joint") == 0) {
        next(p);
        return sf_parse_joint(p, here);
    }
    if (strcmp(keyword, "group") == 0) {
        next(p);
        size_t count = 0;
        size_t *ignored = NULL;
        bool ok = sf_read_group_names(p, &ignored, &count);
        free(ignored);
        return ok;
    }
    if (p->token.kind == TOKEN_BAD_BYTE) return sf_expected(p, "text");
    return sf_expected(p, "a statement (body, template, group, gravity, contacts, integrator, "
                          "iterations, warm_starting, restitution_threshold, sleep_tolerance, "
                          "sleep_time, timestep, view, game, sleeping, sleep_phase, solver_steps, "
                          "step_lengths, workers, stepping, category, note, spring, newton, drag, "
                          "collide, contact, joint)");
}

bool sf_parse(sf_lexer_t *lexer, sf_doc_t *doc) {
    parser_t p = {lexer, doc, {0}};
    doc->settings.integrator = INTEGRATOR_SEED;
    doc->settings.velocity_iterations = 8;
    doc->settings.position_iterations = 4;
    doc->settings.timestep = DEFAULT_TIMESTEP;
    doc->settings.sleeping = true;
    next(&p);
    for (;;) {
        while (at_separator(&p)) next(&p);
        if (p.token.kind == TOKEN_END) return true;
        if (!parse_one(&p)) return false;
        if (!at_separator(&p) && p.token.kind != TOKEN_END) {
            return sf_expected(&p, "the end of the statement (a new line or ';')");
        }
    }
}

void sf_doc_free(sf_doc_t *doc) {
    for (size_t i = 0; i < doc->body_count; i++) {
        free(doc->bodies[i].shape.written);
        free(doc->bodies[i].shape.centred);
        free(doc->bodies[i].groups);
    }
    free(doc->bodies);
    free(doc->groups);
    for (size_t i = 0; i < doc->statement_count; i++) free(doc->statements[i].refs);
    free(doc->statements);
    free(doc->contacts);
    free(doc->joints);
    free(doc->names.slots);
    *doc = (sf_doc_t){0};
}
