/*
 * Tokens to a description (sf_doc_t). Every value is checked here, where the
 * token that wrote it is at hand for the message; names that forces and rules
 * use are resolved later (scene_file_build.c), since a rule may come before
 * the bodies it names.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_file_private.h"

/* The integrators by name. One line per integrator: the writer and the
 * parser both read this table. */
static const struct {
    const char *name;
    integrator_t integrator;
} INTEGRATORS[] = {
    {"seed", INTEGRATOR_SEED},
    {"explicit_euler", INTEGRATOR_EXPLICIT_EULER},
    {"symplectic_euler", INTEGRATOR_SYMPLECTIC_EULER},
    {"velocity_verlet", INTEGRATOR_VELOCITY_VERLET},
    {"rk4", INTEGRATOR_RK4},
    {"symplectic4", INTEGRATOR_SYMPLECTIC4},
    {"implicit_euler", INTEGRATOR_IMPLICIT_EULER},
};
#define INTEGRATOR_NAMES (sizeof INTEGRATORS / sizeof INTEGRATORS[0])

const char *scene_file_integrator_name(integrator_t integrator) {
    for (size_t i = 0; i < INTEGRATOR_NAMES; i++) {
        if (INTEGRATORS[i].integrator == integrator) return INTEGRATORS[i].name;
    }
    return NULL;
}

static const double DEFAULT_FRICTION = 0.6; /* the engine's default (body.h) */
static const double DEFAULT_DENSITY = 1.0;  /* kg/m^2 */
static const double DEFAULT_TIMESTEP = 1.0 / 120.0;
static const size_t MAX_ITERATIONS = 1000; /* scene_set_solver_iterations */
static const rgb_color_t STATIC_COLOR = {0.5, 0.5, 0.5};
static const rgb_color_t MOVING_COLOR = {0.85, 0.55, 0.25};

typedef struct {
    sf_lexer_t *lexer;
    sf_doc_t *doc;
    sf_token_t token; /* the next token, not yet taken */
} parser_t;

static void next(parser_t *p) {
    p->token = sf_lex_next(p->lexer);
}

/* "expected WHAT, found TOKEN" at the current token. */
static bool expected(parser_t *p, const char *what) {
    char found[128];
    sf_describe(&p->token, found, sizeof found);
    return sf_fail(p->lexer, p->token.where, "expected %s, found %s", what, found);
}

static bool at_separator(const parser_t *p) {
    return p->token.kind == TOKEN_NEWLINE || p->token.kind == TOKEN_SEMICOLON;
}

/* ---- Numbers with their ranges -------------------------------------------- */

/* A quantity: what it is, for the message, and its range. */
typedef struct {
    const char *what;
    double min, max;
    bool min_open; /* min itself excluded (sizes, masses, the step) */
    bool angle;    /* "deg" allowed */
} quantity_t;

static const quantity_t COORDINATE = {"a coordinate (m)", -SF_MAX_LENGTH, SF_MAX_LENGTH, false,
                                      false};
static const quantity_t OFFSET = {"an offset (m)", -SF_MAX_LENGTH, SF_MAX_LENGTH, false, false};
static const quantity_t SIZE = {"a size (m)", 0.0, 2.0 * SF_MAX_LENGTH, true, false};
static const quantity_t RADIUS = {"the radius (m)", 0.0, SF_MAX_LENGTH, true, false};
static const quantity_t MASS = {"the mass (kg)", 0.0, SF_MAX_CONSTANT, true, false};
static const quantity_t DENSITY = {"the density (kg/m^2)", 0.0, SF_MAX_CONSTANT, true, false};
static const quantity_t ELASTICITY = {"the elasticity", 0.0, SF_MAX_MOTION, false, false};
static const quantity_t FRICTION = {"the friction coefficient", 0.0, SF_MAX_MOTION, false, false};
static const quantity_t COLOR = {"a colour component", 0.0, 1.0, false, false};
static const quantity_t ANGLE = {"the angle (rad, or deg with the suffix deg)", -SF_MAX_MOTION,
                                 SF_MAX_MOTION, false, true};
static const quantity_t VELOCITY = {"a velocity component (m/s)", -SF_MAX_MOTION, SF_MAX_MOTION,
                                    false, false};
static const quantity_t SPIN = {"the spin (rad/s, or deg/s with the suffix deg)", -SF_MAX_MOTION,
                                SF_MAX_MOTION, false, true};
static const quantity_t GRAVITY = {"a gravity component (m/s^2)", -SF_MAX_MOTION, SF_MAX_MOTION,
                                   false, false};
static const quantity_t TIMESTEP = {"the timestep (s)", 0.0, 10.0, true, false};
static const quantity_t VIEW_SIZE = {"a view size (m)", 0.0, 2.0 * SF_MAX_LENGTH, true, false};
static const quantity_t SPRING_K = {"the spring constant k (N/m)", 0.0, SF_MAX_CONSTANT, false,
                                    false};
static const quantity_t REST_LENGTH = {"the spring's rest length (m)", 0.0, 2.0 * SF_MAX_LENGTH,
                                       false, false};
static const quantity_t NEWTON_G = {"the constant G (N m^2/kg^2)", 0.0, SF_MAX_CONSTANT, false,
                                    false};
static const quantity_t DRAG_GAMMA = {"the drag gamma (kg/s)", 0.0, SF_MAX_CONSTANT, false, false};
/* The engine's own state (sleep timers, contact memory): any finite value
 * it can hold, read back exactly. */
static const quantity_t DURATION = {"a time (s)", 0.0, SF_MAX_STATE, false, false};
static const quantity_t STATE_VALUE = {"a number", -SF_MAX_STATE, SF_MAX_STATE, false, false};
static const quantity_t UNIT_COMPONENT = {"a component of a unit vector", -2.0, 2.0, false, false};

static bool read_quantity(parser_t *p, const quantity_t *q, double *out) {
    char expectation[256];
    double value = 0.0;
    switch (sf_read_number(&p->token, q->angle, &value)) {
    case SF_NUMBER_OK: break;
    case SF_NUMBER_SYNTAX:
        snprintf(expectation, sizeof expectation, "%s, a number", q->what);
        return expected(p, expectation);
    case SF_NUMBER_NOT_FINITE:
        snprintf(expectation, sizeof expectation, "%s, a finite number", q->what);
        return expected(p, expectation);
    case SF_NUMBER_ZERO_DENOMINATOR:
        snprintf(expectation, sizeof expectation, "%s, a fraction with a denominator other than 0",
                 q->what);
        return expected(p, expectation);
    }
    bool low_ok = q->min_open ? value > q->min : value >= q->min;
    if (!low_ok || value > q->max) {
        snprintf(expectation, sizeof expectation, "%s, a number %s %g and <= %g", q->what,
                 q->min_open ? ">" : ">=", q->min, q->max);
        return expected(p, expectation);
    }
    *out = value;
    next(p);
    return true;
}

static bool read_vector(parser_t *p, const quantity_t *q, vector_t *out) {
    return read_quantity(p, q, &out->x) && read_quantity(p, q, &out->y);
}

static bool read_count(parser_t *p, const char *what, uint64_t min, uint64_t max, uint64_t *out) {
    uint64_t value = 0;
    if (!sf_read_integer(&p->token, UINT64_MAX, false, &value) || value < min || value > max) {
        char expectation[256];
        snprintf(expectation, sizeof expectation, "%s, a whole number from %llu to %llu", what,
                 (unsigned long long)min, (unsigned long long)max);
        return expected(p, expectation);
    }
    *out = value;
    next(p);
    return true;
}

static bool read_bits(parser_t *p, const char *what, uint32_t *out) {
    uint64_t value = 0;
    if (!sf_read_integer(&p->token, UINT32_MAX, true, &value)) {
        char expectation[256];
        snprintf(expectation, sizeof expectation,
                 "%s, a whole number from 0 to 4294967295 (or 0x0 to 0xffffffff)", what);
        return expected(p, expectation);
    }
    *out = (uint32_t)value;
    next(p);
    return true;
}

/* ---- Names ---------------------------------------------------------------- */

static const char NAME_RULE[] =
    "a letter or '_', then letters, digits, '_', '.' or '-', at most 63 characters";

static bool read_name(parser_t *p, const char *what, sf_name_t *out, sf_where_t *where) {
    if (!sf_is_name(&p->token)) {
        char expectation[256];
        snprintf(expectation, sizeof expectation, "%s (%s)", what, NAME_RULE);
        return expected(p, expectation);
    }
    memcpy(out->text, p->token.text, p->token.length);
    out->text[p->token.length] = '\0';
    if (where != NULL) *where = p->token.where;
    next(p);
    return true;
}

/* A name that a body or group is being given: not `all`, which stands for
 * every body. */
static bool read_new_name(parser_t *p, const char *what, sf_name_t *out, sf_where_t *where) {
    if (sf_token_is(&p->token, "all")) {
        char expectation[256];
        snprintf(expectation, sizeof expectation, "%s other than all (all stands for every body)",
                 what);
        return expected(p, expectation);
    }
    return read_name(p, what, out, where);
}

static size_t hash_name(const char *key) {
    size_t h = 14695981039346656037u; /* FNV-1a */
    for (; *key != '\0'; key++) h = (h ^ (unsigned char)*key) * 1099511628211u;
    return h;
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
static sf_where_t entry_where(const sf_doc_t *doc, const sf_name_entry_t *entry) {
    return entry->is_group ? doc->groups[entry->index].where : doc->bodies[entry->index].where;
}

/* The group called name, made when new. False (with the message) when name is
 * a single body's. The body being parsed may not be in doc->bodies yet, so
 * its block's `where` comes from the caller. */
static bool find_or_make_group(parser_t *p, const sf_name_t *name, sf_where_t where,
                               size_t *group) {
    sf_doc_t *doc = p->doc;
    sf_name_entry_t *entry = sf_names_find(&doc->names, name->text);
    if (entry != NULL && !entry->is_group) {
        sf_where_t first = entry_where(doc, entry);
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
static bool read_group_names(parser_t *p, size_t **groups, size_t *count) {
    do {
        sf_name_t name;
        sf_where_t where;
        if (!read_new_name(p, "a group name", &name, &where)) return false;
        size_t group;
        if (!find_or_make_group(p, &name, where, &group)) return false;
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

/* ---- Settings ------------------------------------------------------------- */

/* A setting may be given once: a second one is more likely a mistake than an
 * override. */
static bool first_time(parser_t *p, sf_where_t *seen, const char *keyword, sf_where_t here) {
    if (seen->line != 0) {
        return sf_fail(p->lexer, here,
                       "expected one %s statement per file, found a second (the first at line %zu)",
                       keyword, seen->line);
    }
    *seen = here;
    return true;
}

/* Words up to the end of the statement, joined by one space, at most max
 * bytes: a category or a note. */
static bool read_text(parser_t *p, const char *what, size_t max, char *out) {
    size_t length = 0;
    if (p->token.kind != TOKEN_WORD) return expected(p, what);
    while (p->token.kind == TOKEN_WORD) {
        size_t add = p->token.length + (length > 0);
        if (length + add > max) {
            return sf_fail(p->lexer, p->token.where,
                           "expected %s of at most %zu characters, found more", what, max);
        }
        if (length > 0) out[length++] = ' ';
        memcpy(out + length, p->token.text, p->token.length);
        length += p->token.length;
        next(p);
    }
    out[length] = '\0';
    return true;
}

static bool parse_setting(parser_t *p, const char *keyword, sf_where_t here) {
    sf_settings_t *s = &p->doc->settings;
    if (strcmp(keyword, "workers") == 0) {
        uint64_t workers = 0;
        if (!first_time(p, &s->workers_where, keyword, here) ||
            !read_count(p, "the workers", 1, SCENE_MAX_WORKERS, &workers))
            return false;
        s->workers = (size_t)workers;
        return true;
    }
    if (strcmp(keyword, "stepping") == 0) {
        if (!first_time(p, &s->stepping_where, keyword, here)) return false;
        if (sf_token_is(&p->token, "fixed") || sf_token_is(&p->token, "frame")) {
            s->stepping = sf_token_is(&p->token, "frame") ? SCENE_FILE_STEP_FRAME
                                                          : SCENE_FILE_STEP_FIXED;
            next(p);
            return true;
        }
        return expected(p, "fixed or frame (the stepping)");
    }
    if (strcmp(keyword, "category") == 0) {
        return first_time(p, &s->category_where, keyword, here) &&
               read_text(p, "the category's name", SCENE_FILE_CATEGORY_MAX, s->category);
    }
    if (strcmp(keyword, "note") == 0) {
        return first_time(p, &s->note_where, keyword, here) &&
               read_text(p, "the note's text", SCENE_FILE_NOTE_MAX, s->note);
    }
    if (strcmp(keyword, "gravity") == 0) {
        return first_time(p, &s->gravity_where, keyword, here) &&
               read_vector(p, &GRAVITY, &s->gravity);
    }
    if (strcmp(keyword, "contacts") == 0) {
        if (!first_time(p, &s->contacts_where, keyword, here)) return false;
        if (sf_token_is(&p->token, "on") || sf_token_is(&p->token, "off")) {
            s->contacts = sf_token_is(&p->token, "on");
            next(p);
            return true;
        }
        return expected(p, "on or off (world contacts)");
    }
    if (strcmp(keyword, "integrator") == 0) {
        if (!first_time(p, &s->integrator_where, keyword, here)) return false;
        for (size_t i = 0; i < INTEGRATOR_NAMES; i++) {
            if (sf_token_is(&p->token, INTEGRATORS[i].name)) {
                s->integrator = INTEGRATORS[i].integrator;
                next(p);
                return true;
            }
        }
        char expectation[512] = "an integrator (";
        for (size_t i = 0; i < INTEGRATOR_NAMES; i++) {
            strcat(expectation, INTEGRATORS[i].name);
            strcat(expectation, i + 1 < INTEGRATOR_NAMES ? ", " : ")");
        }
        return expected(p, expectation);
    }
    if (strcmp(keyword, "iterations") == 0) {
        uint64_t velocity = 0, position = 0;
        if (!first_time(p, &s->iterations_where, keyword, here) ||
            !read_count(p, "the velocity iterations", 1, MAX_ITERATIONS, &velocity) ||
            !read_count(p, "the position iterations", 1, MAX_ITERATIONS, &position))
            return false;
        s->velocity_iterations = (size_t)velocity;
        s->position_iterations = (size_t)position;
        return true;
    }
    if (strcmp(keyword, "timestep") == 0) {
        return first_time(p, &s->timestep_where, keyword, here) &&
               read_quantity(p, &TIMESTEP, &s->timestep);
    }
    if (strcmp(keyword, "view") == 0) {
        s->view.has_view = true;
        return first_time(p, &s->view_where, keyword, here) &&
               read_vector(p, &COORDINATE, &s->view.center) &&
               read_quantity(p, &VIEW_SIZE, &s->view.width) &&
               read_quantity(p, &VIEW_SIZE, &s->view.height);
    }
    if (strcmp(keyword, "sleeping") == 0) {
        if (!first_time(p, &s->sleeping_where, keyword, here)) return false;
        if (sf_token_is(&p->token, "on") || sf_token_is(&p->token, "off")) {
            s->sleeping = sf_token_is(&p->token, "on");
            next(p);
            return true;
        }
        return expected(p, "on or off (sleeping)");
    }
    if (strcmp(keyword, "sleep_phase") == 0) {
        uint64_t phase = 0;
        if (!first_time(p, &s->sleep_phase_where, keyword, here) ||
            !read_count(p, "the sleep phase", 0, 7, &phase))
            return false;
        s->sleep_phase = (unsigned)phase;
        return true;
    }
    if (strcmp(keyword, "step_lengths") == 0) {
        quantity_t last = DURATION, before = DURATION;
        last.what = "the last step's length (s)";
        before.what = "the length of the step before it (s)";
        return first_time(p, &s->step_lengths_where, keyword, here) &&
               read_quantity(p, &last, &s->last_step) &&
               read_quantity(p, &before, &s->step_before);
    }
    /* game */
    return first_time(p, &s->game_where, keyword, here) &&
           read_name(p, "the game's name", &s->game, NULL);
}

/* ---- Bodies --------------------------------------------------------------- */

/* Where each property of the block was given (line 0: not given), so that a
 * second one is refused naming the first. */
typedef struct {
    sf_where_t shape, mass, elasticity, friction, color, position, angle, velocity, spin, tag,
        filter, repeat, asleep, sleep_timer;
} seen_t;

static bool once(parser_t *p, sf_where_t *seen, const char *what, sf_where_t here) {
    if (seen->line != 0) {
        return sf_fail(p->lexer, here,
                       "expected one %s per body, found a second (the first at line %zu)", what,
                       seen->line);
    }
    *seen = here;
    return true;
}

/* Vertex coordinates up to the end of the property. A list may go on over
 * several lines: a line that starts with a number continues it. */
static bool read_vertices(parser_t *p, sf_shape_t *shape) {
    size_t capacity = 0;
    for (;;) {
        if (p->token.kind == TOKEN_NEWLINE) {
            /* Look past the line ends without taking them, unless a number
             * follows. */
            sf_lexer_t saved_lexer = *p->lexer;
            sf_token_t saved_token = p->token;
            while (p->token.kind == TOKEN_NEWLINE) next(p);
            double ignored;
            if (sf_read_number(&p->token, false, &ignored) == SF_NUMBER_SYNTAX) {
                *p->lexer = saved_lexer;
                p->token = saved_token;
                break;
            }
        }
        if (p->token.kind != TOKEN_WORD ||
            sf_read_number(&p->token, false, &(double){0}) == SF_NUMBER_SYNTAX) {
            break;
        }
        if (shape->count == SCENE_FILE_MAX_VERTICES) {
            char expectation[128];
            snprintf(expectation, sizeof expectation, "at most %d vertices",
                     SCENE_FILE_MAX_VERTICES);
            return expected(p, expectation);
        }
        vector_t v;
        char what[64];
        snprintf(what, sizeof what, "the x of vertex %zu (m)", shape->count + 1);
        quantity_t x = COORDINATE, y = COORDINATE;
        x.what = what;
        if (!read_quantity(p, &x, &v.x)) return false;
        snprintf(what, sizeof what, "the y of vertex %zu (m)", shape->count + 1);
        y.what = what;
        if (!read_quantity(p, &y, &v.y)) return false;
        sf_reserve((void **)&shape->written, &capacity, shape->count + 1, sizeof(vector_t));
        shape->written[shape->count++] = v;
    }
    if (shape->count < 3) {
        char expectation[128];
        snprintf(expectation, sizeof expectation, "at least 3 vertices (x y pairs), %zu so far",
                 shape->count);
        return expected(p, expectation);
    }
    return true;
}

static bool parse_shape(parser_t *p, const char *keyword, sf_body_t *body, seen_t *seen,
                        sf_where_t here) {
    if (!once(p, &seen->shape, "shape (regular, box or vertices)", here)) return false;
    sf_shape_t *shape = &body->shape;
    shape->where = here;
    if (strcmp(keyword, "regular") == 0) {
        uint64_t sides = 0;
        shape->kind = SHAPE_REGULAR;
        if (!read_count(p, "the number of sides", 3, SCENE_FILE_MAX_VERTICES, &sides)) return false;
        shape->sides = (size_t)sides;
        shape->count = shape->sides;
        return read_quantity(p, &RADIUS, &shape->radius);
    }
    if (strcmp(keyword, "box") == 0) {
        shape->kind = SHAPE_BOX;
        shape->count = 4;
        quantity_t width = SIZE, height = SIZE;
        width.what = "the width (m)";
        height.what = "the height (m)";
        return read_quantity(p, &width, &shape->width) && read_quantity(p, &height, &shape->height);
    }
    shape->kind = SHAPE_VERTICES;
    return read_vertices(p, shape);
}

static bool parse_property(parser_t *p, sf_body_t *body, seen_t *seen) {
    sf_where_t here = p->token.where;
    char keyword[16] = "";
    if (p->token.length < sizeof keyword) memcpy(keyword, p->token.text, p->token.length);
    keyword[p->token.length < sizeof keyword ? p->token.length : 0] = '\0';
    if (strcmp(keyword, "regular") == 0 || strcmp(keyword, "box") == 0 ||
        strcmp(keyword, "vertices") == 0) {
        next(p);
        return parse_shape(p, keyword, body, seen, here);
    }
    if (strcmp(keyword, "mass") == 0 || strcmp(keyword, "density") == 0 ||
        strcmp(keyword, "static") == 0) {
        if (!once(p, &seen->mass, "mass, density or static", here)) return false;
        next(p);
        if (keyword[0] == 's') {
            body->mass_kind = MASS_STATIC;
            return true;
        }
        body->mass_kind = keyword[0] == 'm' ? MASS_TOTAL : MASS_DENSITY;
        return read_quantity(p, keyword[0] == 'm' ? &MASS : &DENSITY, &body->mass_value);
    }
    if (strcmp(keyword, "elasticity") == 0) {
        next(p);
        return once(p, &seen->elasticity, keyword, here) &&
               read_quantity(p, &ELASTICITY, &body->elasticity);
    }
    if (strcmp(keyword, "friction") == 0) {
        next(p);
        return once(p, &seen->friction, keyword, here) &&
               read_quantity(p, &FRICTION, &body->friction);
    }
    if (strcmp(keyword, "color") == 0) {
        next(p);
        body->has_color = true;
        quantity_t r = COLOR, g = COLOR, b = COLOR;
        r.what = "the red component of the colour";
        g.what = "the green component of the colour";
        b.what = "the blue component of the colour";
        return once(p, &seen->color, keyword, here) && read_quantity(p, &r, &body->color.r) &&
               read_quantity(p, &g, &body->color.g) && read_quantity(p, &b, &body->color.b);
    }
    if (strcmp(keyword, "position") == 0) {
        next(p);
        body->has_position = true;
        return once(p, &seen->position, keyword, here) &&
               read_vector(p, &COORDINATE, &body->position);
    }
    if (strcmp(keyword, "angle") == 0) {
        next(p);
        return once(p, &seen->angle, keyword, here) && read_quantity(p, &ANGLE, &body->angle);
    }
    if (strcmp(keyword, "velocity") == 0) {
        next(p);
        return once(p, &seen->velocity, keyword, here) &&
               read_vector(p, &VELOCITY, &body->velocity);
    }
    if (strcmp(keyword, "spin") == 0) {
        next(p);
        return once(p, &seen->spin, keyword, here) && read_quantity(p, &SPIN, &body->spin);
    }
    if (strcmp(keyword, "tag") == 0) {
        next(p);
        return once(p, &seen->tag, keyword, here) && read_name(p, "a tag", &body->tag, NULL);
    }
    if (strcmp(keyword, "group") == 0) {
        next(p);
        return read_group_names(p, &body->groups, &body->group_count);
    }
    if (strcmp(keyword, "filter") == 0) {
        next(p);
        body->has_filter = true;
        return once(p, &seen->filter, keyword, here) &&
               read_bits(p, "the filter's category bits", &body->category) &&
               read_bits(p, "the filter's mask bits", &body->mask) &&
               read_bits(p, "the filter's group", &body->filter_group);
    }
    if (strcmp(keyword, "centred") == 0) {
        next(p);
        if (body->shape.as_centred) {
            return sf_fail(p->lexer, here, "expected one centred per body, found a second");
        }
        body->shape.as_centred = true;
        return true;
    }
    if (strcmp(keyword, "asleep") == 0) {
        next(p);
        uint64_t island = 0;
        if (!once(p, &seen->asleep, keyword, here) ||
            !read_count(p, "the island's number", 0, SCENE_FILE_MAX_BODIES, &island))
            return false;
        body->has_island = true;
        body->island = (size_t)island;
        if (p->doc->first_island.line == 0) p->doc->first_island = here;
        return true;
    }
    if (strcmp(keyword, "sleep_timer") == 0) {
        next(p);
        body->has_timer = true;
        body_sleep_timer_t *t = &body->timer;
        quantity_t slow = DURATION, window = DURATION, angle = STATE_VALUE;
        slow.what = "the time the body has been slow (s)";
        window.what = "the time since the anchor was taken (s)";
        angle.what = "the anchor's angle (rad)";
        return once(p, &seen->sleep_timer, keyword, here) &&
               read_quantity(p, &slow, &t->slow_time) && read_quantity(p, &window, &t->window) &&
               read_vector(p, &COORDINATE, &t->anchor) &&
               read_quantity(p, &angle, &t->anchor_angle);
    }
    if (strcmp(keyword, "repeat") == 0) {
        next(p);
        uint64_t x = 0, y = 0;
        if (!once(p, &seen->repeat, keyword, here) ||
            !read_count(p, "the number of copies along x", 1, SCENE_FILE_MAX_BODIES, &x) ||
            !read_count(p, "the number of copies along y", 1, SCENE_FILE_MAX_BODIES, &y))
            return false;
        body->has_repeat = true;
        body->repeat_x = (size_t)x;
        body->repeat_y = (size_t)y;
        return read_vector(p, &OFFSET, &body->repeat_step);
    }
    return expected(p,
                    "a body property (regular, box, vertices, mass, density, static, elasticity, "
                    "friction, color, position, angle, velocity, spin, tag, group, filter, "
                    "centred, asleep, sleep_timer, repeat) or '}'");
}

static list_t *list_of(const vector_t *vertices, size_t count) {
    list_t *list = list_init(count, free);
    for (size_t i = 0; i < count; i++) {
        vector_t *v = malloc(sizeof *v);
        if (v == NULL) abort();
        *v = vertices[i];
        list_add(list, v);
    }
    return list;
}

/* The shape's vertices as the file describes them, before centring. */
static list_t *shape_list(const sf_shape_t *shape) {
    switch (shape->kind) {
    case SHAPE_REGULAR:
        /* A flat bottom edge: vertices at -90 degrees +- half a side. */
        return polygon_make_regular(shape->sides, shape->radius, VEC_ZERO,
                                    -M_PI / 2.0 - M_PI / (double)shape->sides);
    case SHAPE_BOX: return polygon_make_box(VEC_ZERO, shape->width / 2.0, shape->height / 2.0);
    default: return list_of(shape->written, shape->count);
    }
}

/* Whether the centroid of a centred list lies as near the origin as
 * body_init_centred asks: within a thousandth of the radius. */
static bool centred_enough(list_t *list, vector_t centroid) {
    double radius = 0.0;
    for (size_t i = 0; i < list_size(list); i++) {
        radius = fmax(radius, vec_get_length(*(vector_t *)list_get(list, i)));
    }
    return vec_get_length(centroid) <= 1e-3 * radius;
}

/* Checks the shape as the engine will see it and derives what the body needs.
 * The engine gets the vertices relative to their centroid, so that is the
 * list polygon_check judges (centring rounds, so checking the written list
 * alone would not be enough). */
static bool derive_shape(parser_t *p, sf_shape_t *shape) {
    list_t *list = shape_list(shape);
    const char *problem = polygon_check(list);
    if (problem == NULL && shape->kind == SHAPE_VERTICES && !polygon_is_counterclockwise(list)) {
        /* Documented: a clockwise list is reversed, here rather than by the
         * engine, so that the description (and a saved file) is
         * counter-clockwise. */
        for (size_t i = 0; i < shape->count / 2; i++) {
            vector_t swap = shape->written[i];
            shape->written[i] = shape->written[shape->count - 1 - i];
            shape->written[shape->count - 1 - i] = swap;
        }
        list_free(list);
        list = shape_list(shape);
    }
    if (problem == NULL) {
        shape->centroid = polygon_centroid(list);
        if (!vec_is_finite(shape->centroid)) problem = "its centroid is not finite";
    }
    if (problem == NULL && shape->as_centred) {
        /* Taken as written, as body_init_centred takes them. */
        if (!centred_enough(list, shape->centroid)) {
            vector_t c = shape->centroid;
            list_free(list);
            return sf_fail(p->lexer, shape->where,
                           "expected vertices around their centroid (centred), found it at "
                           "(%g, %g), more than a thousandth of the radius from the origin",
                           c.x, c.y);
        }
        shape->centroid = VEC_ZERO;
    }
    if (problem == NULL && !shape->as_centred) {
        polygon_translate(list, vec_negate(shape->centroid));
        problem = polygon_check(list);
    }
    if (problem != NULL) {
        list_free(list);
        return sf_fail(p->lexer, shape->where,
                       "expected a usable shape (convex, distinct vertices, some area), found "
                       "one that is refused: %s",
                       problem);
    }
    shape->area = polygon_area(list);
    shape->moment_per_kg = polygon_moment_of_inertia(list, 1.0);
    shape->centred = malloc(shape->count * sizeof(vector_t));
    if (shape->centred == NULL) abort();
    for (size_t i = 0; i < shape->count; i++) shape->centred[i] = *(vector_t *)list_get(list, i);
    list_free(list);
    return true;
}

/* The mass from the block, checked as body_init will check it, with a wide
 * margin on the moment of inertia (our product and the engine's sum round
 * differently). */
static bool derive_mass(parser_t *p, sf_body_t *body, sf_where_t where) {
    if (body->mass_kind == MASS_STATIC) {
        body->mass = INFINITY;
        return true;
    }
    double mass =
        body->mass_kind == MASS_TOTAL ? body->mass_value : body->mass_value * body->shape.area;
    double moment = mass * body->shape.moment_per_kg;
    char given[160];
    if (body->mass_kind == MASS_TOTAL) {
        snprintf(given, sizeof given, "mass %g kg", mass);
    } else {
        snprintf(given, sizeof given, "density %g kg/m^2 on %g m^2, %g kg", body->mass_value,
                 body->shape.area, mass);
    }
    if (!(mass > 0.0) || !isfinite(mass) || !isfinite(1.0 / mass)) {
        return sf_fail(p->lexer, where, "expected a mass whose inverse is finite, found %s", given);
    }
    if (!(moment >= SF_MIN_MOMENT && moment <= SF_MAX_MOMENT)) {
        return sf_fail(p->lexer, where,
                       "expected a moment of inertia from %g to %g kg m^2, found %g kg m^2 "
                       "(%s on this shape)",
                       SF_MIN_MOMENT, SF_MAX_MOMENT, moment, given);
    }
    body->mass = mass;
    return true;
}

/* Records the block's name once its properties are known: a repeated body or
 * a template names a group; a single body takes a new name. */
static bool register_name(parser_t *p, sf_body_t *body, size_t index, sf_where_t name_where) {
    sf_doc_t *doc = p->doc;
    if (body->name.text[0] == '\0') return true;
    sf_name_entry_t *entry = sf_names_find(&doc->names, body->name.text);
    bool names_group = body->is_template || body->has_repeat;
    if (!names_group) {
        if (entry != NULL) {
            sf_where_t first = entry_where(doc, entry);
            return sf_fail(p->lexer, name_where,
                           "expected a new name, found \"%s\", already the name of a %s (line %zu)",
                           body->name.text, entry->is_group ? "group" : "body", first.line);
        }
        sf_names_add(&doc->names, body->name.text, false, index);
        return true;
    }
    size_t group;
    if (!find_or_make_group(p, &body->name, name_where, &group)) return false;
    if (body->is_template) {
        sf_group_t *g = &doc->groups[group];
        if (g->template_body != SIZE_MAX) {
            return sf_fail(p->lexer, name_where,
                           "expected a new template name, found \"%s\", already a template's "
                           "(line %zu)",
                           body->name.text, doc->bodies[g->template_body].where.line);
        }
        g->template_body = index;
    }
    body->own_group = group;
    return true;
}

/* After '}': the derived values, the defaults, the limits. */
static bool finish_body(parser_t *p, sf_body_t *body, const seen_t *seen, sf_where_t name_where,
                        sf_where_t close_where) {
    sf_doc_t *doc = p->doc;
    if (body->shape.kind == SHAPE_NONE) {
        return sf_fail(p->lexer, close_where,
                       "expected a shape (regular, box or vertices) in the %s, found '}' without "
                       "one",
                       body->is_template ? "template" : "body");
    }
    if (body->shape.as_centred && body->shape.kind != SHAPE_VERTICES) {
        return sf_fail(p->lexer, body->shape.where,
                       "expected centred with a vertices shape, found it with %s",
                       body->shape.kind == SHAPE_BOX ? "a box" : "a regular polygon");
    }
    if (!derive_shape(p, &body->shape)) return false;
    if (!derive_mass(p, body, seen->mass.line != 0 ? seen->mass : body->shape.where)) return false;
    if (!body->has_color)
        body->color = body->mass_kind == MASS_STATIC ? STATIC_COLOR : MOVING_COLOR;
    if (!body->has_position) body->position = body->shape.centroid;
    if (body->is_template && seen->repeat.line != 0) {
        return sf_fail(p->lexer, seen->repeat,
                       "expected no repeat in a template (a game spawns its copies), found one");
    }
    if (body->is_template && (body->has_island || body->has_timer)) {
        return sf_fail(p->lexer, body->has_island ? seen->asleep : seen->sleep_timer,
                       "expected no sleep state in a template (its copies start awake), found %s",
                       body->has_island ? "asleep" : "sleep_timer");
    }
    if (body->has_island && body->mass_kind == MASS_STATIC) {
        return sf_fail(p->lexer, seen->asleep,
                       "expected asleep on a body that can move, found it on a static body");
    }
    if (body->has_island && (body->velocity.x != 0.0 || body->velocity.y != 0.0 ||
                             body->spin != 0.0)) {
        return sf_fail(p->lexer, seen->asleep,
                       "expected a sleeping body at rest, found a velocity or spin on it");
    }
    size_t copies = body->repeat_x * body->repeat_y;
    if (body->has_repeat) {
        vector_t last =
            vec_add(body->position, (vector_t){(double)(body->repeat_x - 1) * body->repeat_step.x,
                                               (double)(body->repeat_y - 1) * body->repeat_step.y});
        if (!(fabs(last.x) <= SF_MAX_LENGTH && fabs(last.y) <= SF_MAX_LENGTH)) {
            return sf_fail(p->lexer, seen->repeat,
                           "expected copies within %g m of the origin, found the last at "
                           "(%g, %g)",
                           SF_MAX_LENGTH, last.x, last.y);
        }
    }
    if (!body->is_template) {
        if (copies > SCENE_FILE_MAX_BODIES - doc->total_bodies) {
            return sf_fail(p->lexer, body->where,
                           "expected at most %d bodies in a file, found %zu with this block",
                           SCENE_FILE_MAX_BODIES, doc->total_bodies + copies);
        }
        if (copies * body->shape.count > SCENE_FILE_MAX_TOTAL_VERTICES - doc->total_vertices) {
            return sf_fail(p->lexer, body->where,
                           "expected at most %d vertices over all bodies of a file, found %zu "
                           "with this block",
                           SCENE_FILE_MAX_TOTAL_VERTICES,
                           doc->total_vertices + copies * body->shape.count);
        }
        doc->total_bodies += copies;
        doc->total_vertices += copies * body->shape.count;
    }
    return register_name(p, body, doc->body_count - 1, name_where);
}

static bool parse_body(parser_t *p, bool is_template, sf_where_t here) {
    sf_doc_t *doc = p->doc;
    sf_reserve((void **)&doc->bodies, &doc->body_capacity, doc->body_count + 1, sizeof(sf_body_t));
    sf_body_t *body = &doc->bodies[doc->body_count++];
    *body = (sf_body_t){
        .where = here,
        .is_template = is_template,
        .mass_kind = MASS_DENSITY,
        .mass_value = DEFAULT_DENSITY,
        .friction = DEFAULT_FRICTION,
        .mask = UINT32_MAX,
        .category = 1,
        .repeat_x = 1,
        .repeat_y = 1,
        .own_group = SIZE_MAX,
    };
    sf_where_t name_where = here;
    if (p->token.kind == TOKEN_WORD || is_template) {
        if (!read_new_name(p, is_template ? "the template's name" : "the body's name", &body->name,
                           &name_where))
            return false;
    }
    while (p->token.kind == TOKEN_NEWLINE) next(p);
    if (p->token.kind != TOKEN_OPEN) return expected(p, "'{' to open the block");
    next(p);
    seen_t seen = {0};
    for (;;) {
        while (at_separator(p)) next(p);
        if (p->token.kind == TOKEN_CLOSE) break;
        if (p->token.kind == TOKEN_END) {
            char expectation[96];
            snprintf(expectation, sizeof expectation, "'}' to close the block opened at line %zu",
                     here.line);
            return expected(p, expectation);
        }
        if (p->token.kind != TOKEN_WORD) {
            return expected(p, "a body property or '}'");
        }
        if (!parse_property(p, body, &seen)) return false;
        if (!at_separator(p) && p->token.kind != TOKEN_CLOSE) {
            return expected(p, "the end of the property (a new line, ';' or '}')");
        }
    }
    sf_where_t close_where = p->token.where;
    next(p);
    return finish_body(p, body, &seen, name_where, close_where);
}

/* ---- Forces and rules ----------------------------------------------------- */

static bool read_ref(parser_t *p, const char *what, sf_statement_t *statement, bool allow_all) {
    sf_reserve((void **)&statement->refs, &statement->ref_capacity, statement->ref_count + 1,
               sizeof(sf_ref_t));
    sf_ref_t *ref = &statement->refs[statement->ref_count];
    *ref = (sf_ref_t){.where = p->token.where};
    if (allow_all && sf_token_is(&p->token, "all")) {
        ref->kind = REF_ALL;
        strcpy(ref->name.text, "all");
        next(p);
    } else if (!read_name(p, what, &ref->name, NULL)) {
        return false;
    }
    statement->ref_count++;
    return true;
}

static bool parse_statement(parser_t *p, const char *keyword, sf_where_t here) {
    sf_doc_t *doc = p->doc;
    sf_reserve((void **)&doc->statements, &doc->statement_capacity, doc->statement_count + 1,
               sizeof(sf_statement_t));
    sf_statement_t *s = &doc->statements[doc->statement_count++];
    *s = (sf_statement_t){.where = here};
    if (strcmp(keyword, "spring") == 0) {
        s->kind = STATEMENT_SPRING;
        if (!read_quantity(p, &SPRING_K, &s->constant) ||
            !read_ref(p, "the spring's first body", s, false) ||
            !read_ref(p, "the spring's second body", s, false))
            return false;
        if (!sf_token_is(&p->token, "length")) return true;
        next(p);
        s->has_rest_length = true;
        return read_quantity(p, &REST_LENGTH, &s->rest_length);
    }
    if (strcmp(keyword, "newton") == 0 || strcmp(keyword, "drag") == 0) {
        bool newton = keyword[0] == 'n';
        s->kind = newton ? STATEMENT_NEWTON : STATEMENT_DRAG;
        if (!read_quantity(p, newton ? &NEWTON_G : &DRAG_GAMMA, &s->constant)) return false;
        const char *what = newton ? "all or the bodies and groups that attract each other"
                                  : "all or the bodies and groups it acts on";
        if (!read_ref(p, what, s, true)) return false;
        if (s->refs[0].kind == REF_ALL) return true;
        while (p->token.kind == TOKEN_WORD) {
            if (!read_ref(p, "a body or group name", s, false)) return false;
        }
        return true;
    }
    /* collide A B physics E | destructive */
    if (!read_ref(p, "the first body, group or all", s, true) ||
        !read_ref(p, "the second body, group or all", s, true))
        return false;
    if (sf_token_is(&p->token, "physics")) {
        s->kind = STATEMENT_PHYSICS;
        next(p);
        return read_quantity(p, &ELASTICITY, &s->constant);
    }
    if (sf_token_is(&p->token, "destructive")) {
        s->kind = STATEMENT_DESTRUCTIVE;
        next(p);
        return true;
    }
    return expected(p, "the kind of collision (physics ELASTICITY, or destructive)");
}

/* ---- Contact memory ---------------------------------------------------------- */

/* `point ID X Y SEPARATION NORMAL TANGENT RESTITUTION RESTITUTION_TANGENT` */
static bool read_memory_point(parser_t *p, scene_memory_point_t *point) {
    quantity_t coordinate = STATE_VALUE, separation = STATE_VALUE;
    coordinate.what = "a coordinate of the point (m)";
    separation.what = "the separation (m)";
    quantity_t impulses[4] = {STATE_VALUE, STATE_VALUE, STATE_VALUE, STATE_VALUE};
    impulses[0].what = "the normal impulse (N s)";
    impulses[1].what = "the tangent impulse (N s)";
    impulses[2].what = "the collision pass's normal impulse (N s)";
    impulses[3].what = "the collision pass's tangent impulse (N s)";
    return read_bits(p, "the point's feature id", &point->id) &&
           read_vector(p, &coordinate, &point->point) &&
           read_quantity(p, &separation, &point->separation) &&
           read_quantity(p, &impulses[0], &point->normal_impulse) &&
           read_quantity(p, &impulses[1], &point->tangent_impulse) &&
           read_quantity(p, &impulses[2], &point->restitution_impulse) &&
           read_quantity(p, &impulses[3], &point->restitution_tangent_impulse);
}

/* `previous ID NORMAL TANGENT` */
static bool read_previous_point(parser_t *p, scene_memory_previous_t *point) {
    quantity_t normal = STATE_VALUE, tangent = STATE_VALUE;
    normal.what = "the normal impulse of the step before (N s)";
    tangent.what = "the tangent impulse of the step before (N s)";
    return read_bits(p, "the previous point's feature id", &point->id) &&
           read_quantity(p, &normal, &point->normal_impulse) &&
           read_quantity(p, &tangent, &point->tangent_impulse);
}

/* `face a|b NX NY X Y [edge]` */
static bool read_face(parser_t *p, scene_contact_memory_t *m) {
    if (!sf_token_is(&p->token, "a") && !sf_token_is(&p->token, "b")) {
        return expected(p, "a or b (the body holding the reference face)");
    }
    m->flip = sf_token_is(&p->token, "b");
    next(p);
    quantity_t point = STATE_VALUE;
    point.what = "a coordinate of the face's point (m)";
    if (!read_vector(p, &UNIT_COMPONENT, &m->face_normal) ||
        !read_vector(p, &point, &m->face_point))
        return false;
    m->edge_ends = sf_token_is(&p->token, "edge");
    if (m->edge_ends) next(p);
    return true;
}

/* One line of a contact block. */
static bool parse_contact_line(parser_t *p, sf_contact_t *contact, sf_where_t *seen) {
    scene_contact_memory_t *m = &contact->memory;
    sf_where_t here = p->token.where;
    char keyword[16] = "";
    if (p->token.length < sizeof keyword) memcpy(keyword, p->token.text, p->token.length);
    keyword[p->token.length < sizeof keyword ? p->token.length : 0] = '\0';
    static const char *const LINES[] = {"normal", "point", "incident", "face", "pose",
                                        "previous"};
    bool known = false;
    for (size_t i = 0; i < sizeof LINES / sizeof LINES[0]; i++) {
        known = known || strcmp(keyword, LINES[i]) == 0;
    }
    if (!known) {
        return expected(p, "a contact line (normal, point, face, incident, pose, previous) or '}'");
    }
    next(p);
    if (strcmp(keyword, "previous") == 0) {
        if (m->previous_count == 2) {
            return sf_fail(p->lexer, here,
                           "expected at most two previous lines in a contact, found a third");
        }
        return read_previous_point(p, &m->previous[m->previous_count++]);
    }
    if (strcmp(keyword, "normal") == 0) {
        return first_time(p, &seen[0], "normal", here) &&
               read_vector(p, &UNIT_COMPONENT, &m->normal);
    }
    if (strcmp(keyword, "point") == 0 || strcmp(keyword, "incident") == 0) {
        bool incident = keyword[0] == 'i';
        int *count = incident ? &m->feature_count : &m->point_count;
        if (*count == 2) {
            return sf_fail(p->lexer, here,
                           "expected at most two %s lines in a contact, found a third", keyword);
        }
        if (!incident) return read_memory_point(p, &m->points[m->point_count++]);
        quantity_t coordinate = STATE_VALUE;
        coordinate.what = "a coordinate of the incident point (m)";
        int k = m->feature_count++;
        return read_bits(p, "the incident point's feature id", &m->feature_ids[k]) &&
               read_vector(p, &coordinate, &m->feature_points[k]);
    }
    if (strcmp(keyword, "face") == 0) {
        return first_time(p, &seen[1], "face", here) && read_face(p, m);
    }
    /* pose */
    quantity_t coordinate = STATE_VALUE, angle = STATE_VALUE;
    coordinate.what = "a coordinate of the pose (m)";
    angle.what = "the pose's angle (rad)";
    return first_time(p, &seen[2], "pose", here) && read_vector(p, &coordinate, &m->pose) &&
           read_quantity(p, &angle, &m->pose_angle);
}

/* `contact A B { ... }`: the world's memory of one pair. */
static bool parse_contact(parser_t *p, sf_where_t here) {
    sf_doc_t *doc = p->doc;
    sf_reserve((void **)&doc->contacts, &doc->contact_capacity, doc->contact_count + 1,
               sizeof(sf_contact_t));
    sf_contact_t *contact = &doc->contacts[doc->contact_count++];
    *contact = (sf_contact_t){.where = here};
    uint64_t a = 0, b = 0;
    const uint64_t last = SCENE_FILE_MAX_BODIES - 1;
    if (!read_count(p, "the number of the contact's first body", 0, last, &a) ||
        !read_count(p, "the number of the contact's second body", 0, last, &b))
        return false;
    contact->body_a = (size_t)a;
    contact->body_b = (size_t)b;
    while (p->token.kind == TOKEN_NEWLINE) next(p);
    if (p->token.kind != TOKEN_OPEN) return expected(p, "'{' to open the contact");
    next(p);
    sf_where_t seen[3] = {{0, 0}, {0, 0}, {0, 0}};
    for (;;) {
        while (at_separator(p)) next(p);
        if (p->token.kind == TOKEN_CLOSE) break;
        if (p->token.kind != TOKEN_WORD) {
            char expectation[96];
            snprintf(expectation, sizeof expectation, "a contact line or '}' to close the block "
                     "opened at line %zu", here.line);
            return expected(p, expectation);
        }
        if (!parse_contact_line(p, contact, seen)) return false;
        if (!at_separator(p) && p->token.kind != TOKEN_CLOSE) {
            return expected(p, "the end of the line (a new line, ';' or '}')");
        }
    }
    next(p);
    return true;
}

/* ---- The file ------------------------------------------------------------- */

static const char *const SETTINGS[] = {"gravity",  "contacts", "integrator", "iterations",
                                       "timestep", "view",     "game",       "sleeping",
                                       "sleep_phase", "step_lengths", "workers", "stepping",
                                       "category", "note"};
static const char *const FORCES[] = {"spring", "newton", "drag", "collide"};

static bool parse_one(parser_t *p) {
    sf_where_t here = p->token.where;
    char keyword[16] = "";
    if (p->token.kind == TOKEN_WORD && p->token.length < sizeof keyword) {
        memcpy(keyword, p->token.text, p->token.length);
        keyword[p->token.length] = '\0';
    }
    for (size_t i = 0; i < sizeof SETTINGS / sizeof SETTINGS[0]; i++) {
        if (strcmp(keyword, SETTINGS[i]) == 0) {
            next(p);
            return parse_setting(p, keyword, here);
        }
    }
    for (size_t i = 0; i < sizeof FORCES / sizeof FORCES[0]; i++) {
        if (strcmp(keyword, FORCES[i]) == 0) {
            next(p);
            return parse_statement(p, keyword, here);
        }
    }
    if (strcmp(keyword, "body") == 0 || strcmp(keyword, "template") == 0) {
        next(p);
        return parse_body(p, keyword[0] == 't', here);
    }
    if (strcmp(keyword, "contact") == 0) {
        next(p);
        return parse_contact(p, here);
    }
    if (strcmp(keyword, "group") == 0) {
        next(p);
        size_t count = 0;
        size_t *ignored = NULL;
        bool ok = read_group_names(p, &ignored, &count);
        free(ignored);
        return ok;
    }
    if (p->token.kind == TOKEN_BAD_BYTE) return expected(p, "text");
    return expected(p, "a statement (body, template, group, gravity, contacts, integrator, "
                       "iterations, timestep, view, game, sleeping, sleep_phase, step_lengths, "
                       "workers, stepping, category, note, spring, newton, drag, collide, "
                       "contact)");
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
            return expected(&p, "the end of the statement (a new line or ';')");
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
    free(doc->names.slots);
    *doc = (sf_doc_t){0};
}
