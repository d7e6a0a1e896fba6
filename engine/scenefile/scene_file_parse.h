#ifndef SCENE_FILE_PARSE_H
#define SCENE_FILE_PARSE_H

/*
 * The parser's parts (tokens to a description, scene_file_private.h), one
 * file per kind of statement:
 *   scene_file_parse.c           the file, numbers with their ranges, names
 *   scene_file_settings.c        gravity, contacts, integrator, ... (each once)
 *   scene_file_bodies.c          body and template blocks, checked and derived
 *   scene_file_forces.c          spring, newton, drag and collide
 *   scene_file_contact_memory.c  contact blocks: the world's contact memory
 *   scene_file_joints.c          joint blocks: the joints (jostle/joint.h)
 * Each reads from the current token to the end of what it reads, and
 * returns false with the error set (sf_fail) at the first problem.
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "scene_file_private.h"

typedef struct {
    sf_lexer_t *lexer;
    sf_doc_t *doc;
    sf_token_t token; /* the next token, not yet taken */
} parser_t;

static inline void next(parser_t *p) {
    p->token = sf_lex_next(p->lexer);
}

static inline bool at_separator(const parser_t *p) {
    return p->token.kind == TOKEN_NEWLINE || p->token.kind == TOKEN_SEMICOLON;
}

/* "expected WHAT, found TOKEN" at the current token; returns false. */
bool sf_expected(parser_t *p, const char *what);

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
/* The ranges of scene_set_restitution_threshold, _sleep_tolerance and
 * _sleep_time. */
static const quantity_t RESTITUTION_THRESHOLD = {"the restitution threshold (m/s)", 0.0, 100.0,
                                                 false, false};
static const quantity_t SLEEP_LINEAR = {"the linear sleep tolerance (m/s)", 0.0, 10.0, true, false};
static const quantity_t SLEEP_ANGULAR = {"the angular sleep tolerance (rad/s)", 0.0, 100.0, true,
                                         false};
static const quantity_t SLEEP_TIME = {"the sleep time (s)", 0.0, 1000.0, true, false};
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

/* A number of quantity q (two for a vector), taken; false with the
 * message when it is not one or lies outside q's range. */
bool sf_read_quantity(parser_t *p, const quantity_t *q, double *out);
bool sf_read_vector(parser_t *p, const quantity_t *q, vector_t *out);
/* A whole number from min to max. */
bool sf_read_count(parser_t *p, const char *what, uint64_t min, uint64_t max, uint64_t *out);
/* 32 bits, decimal or 0x hexadecimal. */
bool sf_read_bits(parser_t *p, const char *what, uint32_t *out);

/* ---- Names ---------------------------------------------------------------- */

/* A name, and where it was written when where is not NULL; a new name may
 * not be `all`. */
bool sf_read_name(parser_t *p, const char *what, sf_name_t *out, sf_where_t *where);
bool sf_read_new_name(parser_t *p, const char *what, sf_name_t *out, sf_where_t *where);
/* Where a name was first given. */
sf_where_t sf_entry_where(const sf_doc_t *doc, const sf_name_entry_t *entry);
/* The group called name, made when new; false when a body has the name. */
bool sf_find_or_make_group(parser_t *p, const sf_name_t *name, sf_where_t where, size_t *group);
/* Group names up to the end of the statement or property, each added once. */
bool sf_read_group_names(parser_t *p, size_t **groups, size_t *count);
/* Whether a statement that may be written once (seen: where it was, line 0
 * when not yet) is written here the first time; false with the message. */
bool sf_first_time(parser_t *p, sf_where_t *seen, const char *keyword, sf_where_t here);

/* ---- Statements ----------------------------------------------------------- */

/* Each after its keyword, which is taken; here is where the keyword was. */
bool sf_parse_setting(parser_t *p, const char *keyword, sf_where_t here);
bool sf_parse_body(parser_t *p, bool is_template, sf_where_t here);
bool sf_parse_statement(parser_t *p, const char *keyword, sf_where_t here);
bool sf_parse_contact(parser_t *p, sf_where_t here);
bool sf_parse_joint(parser_t *p, sf_where_t here);

#endif // #ifndef SCENE_FILE_PARSE_H
