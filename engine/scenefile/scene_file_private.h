#ifndef SCENE_FILE_PRIVATE_H
#define SCENE_FILE_PRIVATE_H

/*
 * The scene-file module's insides, shared by its four parts:
 *   scene_file_lex.c    bytes to tokens, numbers, messages with FILE:LINE:COLUMN
 *   scene_file_parse.c  tokens to a description (sf_doc_t), every value checked
 *                       (with a file per kind of statement: scene_file_parse.h)
 *   scene_file_build.c  names resolved, limits checked, the scene made; spawn
 *   scene_file_write.c  the description and the live scene back to text
 *
 * A file is read in two passes: the parser fills an sf_doc_t (pure data, no
 * engine object), then the builder resolves the names that forces and rules
 * use (they may come before the bodies they name) and only then makes engine
 * objects, which by then cannot be refused.
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "jostle/jostle.h"
#include "jostle/scene_file.h"

/* Where in the text something was written (1-based; column in bytes). */
typedef struct {
    size_t line;
    size_t column;
} sf_where_t;

typedef struct {
    char text[SCENE_FILE_NAME_MAX + 1];
} sf_name_t;

/* ---- Lexer ---------------------------------------------------------------- */

typedef enum {
    TOKEN_WORD = 0, /* a run of bytes up to a space, newline, ';', '{', '}' or '#' */
    TOKEN_NEWLINE,
    TOKEN_SEMICOLON,
    TOKEN_OPEN,  /* '{' */
    TOKEN_CLOSE, /* '}' */
    TOKEN_END,
    TOKEN_BAD_BYTE, /* a control byte (NUL included) outside a comment */
} sf_token_kind_t;

typedef struct {
    sf_token_kind_t kind;
    const char *text; /* into the buffer; not NUL-terminated */
    size_t length;
    sf_where_t where;
} sf_token_t;

typedef struct {
    const char *text;
    size_t length;
    size_t offset;
    sf_where_t where; /* of text[offset] */
    const char *file_name;
    scene_file_error_t *error; /* may be NULL */
    bool failed;
} sf_lexer_t;

void sf_lexer_init(sf_lexer_t *lexer, const char *text, size_t length, const char *file_name,
                   scene_file_error_t *error);
sf_token_t sf_lex_next(sf_lexer_t *lexer);

/* Fills the error (the first one wins) with "FILE:LINE:COLUMN: " and the
 * formatted text; returns false so that callers can `return sf_fail(...)`. */
bool sf_fail(sf_lexer_t *lexer, sf_where_t where, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* How a token reads in "found ...": "\"abc\"" (escaped, shortened), "the end
 * of the line", "';'", "the end of the file", ... Writes into buffer. */
const char *sf_describe(const sf_token_t *token, char *buffer, size_t size);

/* A decimal number, optionally a fraction "1/60", optionally with the suffix
 * "deg" when allow_degrees (converted to radians). False when the token is
 * not one (nothing is reported: the caller knows what it expected). */
typedef enum {
    SF_NUMBER_OK = 0,
    SF_NUMBER_SYNTAX,
    SF_NUMBER_NOT_FINITE,
    SF_NUMBER_ZERO_DENOMINATOR
} sf_number_status_t;
sf_number_status_t sf_read_number(const sf_token_t *token, bool allow_degrees, double *value);

/* A decimal integer (or "0x" hexadecimal when allow_hex) no larger than max. */
bool sf_read_integer(const sf_token_t *token, uint64_t max, bool allow_hex, uint64_t *value);

bool sf_token_is(const sf_token_t *token, const char *word);
bool sf_is_name(const sf_token_t *token);

/* ---- Description ---------------------------------------------------------- */

typedef enum {
    SHAPE_NONE = 0,
    SHAPE_REGULAR,
    SHAPE_BOX,
    SHAPE_VERTICES,
    SHAPE_CIRCLE,
    SHAPE_CAPSULE,
    SHAPE_CHAIN, /* `chain`: an open chain through the written points */
    SHAPE_LOOP   /* `loop`: a closed one */
} sf_shape_kind_t;

typedef struct {
    sf_shape_kind_t kind;
    sf_where_t where;
    size_t sides;         /* SHAPE_REGULAR */
    double radius;        /* SHAPE_REGULAR: circumradius; SHAPE_CIRCLE, SHAPE_CAPSULE: radius */
    vector_t ends[2];     /* SHAPE_CAPSULE: the end centres as written */
    double width, height; /* SHAPE_BOX: full sizes */
    vector_t *written;    /* SHAPE_VERTICES: as written, made counter-clockwise; SHAPE_CHAIN,
                             SHAPE_LOOP: the points as written, in the chain's frame */
    bool as_centred;      /* SHAPE_VERTICES: written relative to the centroid, kept exactly */
    size_t count;         /* vertices (of the engine's outline for a round shape) */
    /* Derived once the shape is checked: */
    vector_t *centred;    /* the vertices relative to the area centroid, counter-clockwise
                             (NULL for a round shape) */
    vector_t centroid;    /* where that centroid lies as written (origin for regular, box,
                             circle; the ends' midpoint for a capsule) */
    double area;          /* m^2, > 0 */
    double moment_per_kg; /* moment of inertia of 1 kg of it, kg m^2 / kg */
} sf_shape_t;

typedef enum { MASS_DENSITY = 0, MASS_TOTAL, MASS_STATIC } sf_mass_kind_t;

/* A `body` or `template` block. */
typedef struct {
    sf_where_t where;
    bool is_template;
    sf_name_t name; /* "" for an anonymous body */
    sf_name_t tag;
    sf_shape_t shape;
    sf_mass_kind_t mass_kind;
    double mass_value; /* density (kg/m^2) or mass (kg) as written */
    double mass;       /* kg; INFINITY when static */
    double elasticity;
    double friction;
    rgb_color_t color;
    bool has_color;
    bool has_position;
    vector_t position; /* of the centroid */
    double angle;
    vector_t velocity;
    double spin;
    bool has_filter;
    uint32_t category, mask, filter_group;
    bool has_island;           /* `asleep ISLAND`: the body sleeps in that island */
    size_t island;
    bool has_timer;            /* `sleep_timer`: its sleep timer (scene_state.h) */
    body_sleep_timer_t timer;
    bool has_repeat;           /* a repeated block names a group, whatever its counts */
    size_t repeat_x, repeat_y; /* 1 and 1 without repeat */
    vector_t repeat_step;
    size_t *groups; /* group indices named by `group` */
    size_t group_count;
    size_t own_group;         /* the group named after a repeated body or a template, or SIZE_MAX */
    struct sf_record *record; /* a single named body's record once built, NULL when freed */
} sf_body_t;

/* A group. Its members are the records made from blocks that list it (or
 * that it is named after): membership is read from the blocks, so bodies
 * spawned later belong as they appear. */
typedef struct {
    sf_name_t name;
    sf_where_t where;
    size_t template_body; /* index of the template named like it, or SIZE_MAX */
} sf_group_t;

typedef enum { REF_BODY = 0, REF_GROUP, REF_ALL } sf_ref_kind_t;

typedef struct {
    sf_where_t where;
    sf_name_t name;
    sf_ref_kind_t kind; /* set by the resolve pass */
    size_t index;       /* body (single) or group index */
} sf_ref_t;

typedef enum {
    STATEMENT_SPRING = 0,
    STATEMENT_NEWTON,
    STATEMENT_DRAG,
    STATEMENT_PHYSICS,
    STATEMENT_DESTRUCTIVE,
} sf_statement_kind_t;

/* A force or a collision rule. collide: refs[0] and refs[1] are its two sides;
 * spring: its two bodies, and its rest length when it gives one (`length L`);
 * newton: the sets whose union pulls pairwise (none: `all`); drag: the sets
 * it acts on. */
typedef struct {
    sf_statement_kind_t kind;
    sf_where_t where;
    double constant;
    bool has_rest_length; /* a spring with `length`: create_spring_with_length */
    double rest_length;
    sf_ref_t *refs;
    size_t ref_count, ref_capacity;
} sf_statement_t;

/* A setting written at most once: where, or line 0 when absent. */
typedef struct {
    vector_t gravity;
    sf_where_t gravity_where;
    bool contacts;
    sf_where_t contacts_where;
    integrator_t integrator;
    sf_where_t integrator_where;
    size_t velocity_iterations, position_iterations;
    sf_where_t iterations_where;
    /* The solver's settings below are applied only when written (the
     * scene's defaults stand otherwise). */
    bool warm_starting;
    sf_where_t warm_starting_where;
    double restitution_threshold;
    sf_where_t restitution_threshold_where;
    double sleep_linear, sleep_angular; /* sleep_tolerance; angular INFINITY when absent */
    sf_where_t sleep_tolerance_where;
    double sleep_time;
    sf_where_t sleep_time_where;
    double timestep;
    sf_where_t timestep_where;
    scene_file_view_t view;
    sf_where_t view_where;
    sf_name_t game;
    sf_where_t game_where;
    bool sleeping;
    sf_where_t sleeping_where;
    unsigned sleep_phase;
    sf_where_t sleep_phase_where;
    uint64_t solver_steps;
    sf_where_t solver_steps_where;
    double last_step, step_before; /* scene_set_step_lengths */
    sf_where_t step_lengths_where;
    size_t workers; /* 0: the file gives none */
    sf_where_t workers_where;
    scene_file_stepping_t stepping;
    sf_where_t stepping_where;
    char category[SCENE_FILE_CATEGORY_MAX + 1]; /* words joined by one space, "" when none */
    sf_where_t category_where;
    char note[SCENE_FILE_NOTE_MAX + 1];
    sf_where_t note_where;
} sf_settings_t;

/* A `contact A B { ... }` block: the world's contact memory of one pair
 * (scene_state.h), its bodies by the order the file makes them. */
typedef struct {
    sf_where_t where;
    size_t body_a, body_b;
    scene_contact_memory_t memory; /* bodies NULL until built */
} sf_contact_t;

/* A `joint TYPE A B { ... }` block: a joint (jostle/joint.h) between the
 * bodies the file makes A-th and B-th (A SF_WORLD: the world), its
 * definition with the bodies left NULL until built, and its impulses
 * (scene_state.h) when the block gives them. */
#define SF_WORLD SIZE_MAX
typedef struct {
    sf_where_t where;
    size_t body1, body2;
    joint_def_t def;
    bool has_state;
    joint_state_t state;
} sf_joint_t;

/* The lines of a joint block, one per field of joint_def_t a file may
 * give (scene_file_joints.c reads them, scene_file_write.c writes them). */
typedef enum { SF_FIELD_NUMBER, SF_FIELD_VECTOR, SF_FIELD_FLAG } sf_field_kind_t;
typedef struct {
    const char *name;
    sf_field_kind_t kind;
    size_t offset;
} sf_joint_field_t;
extern const sf_joint_field_t SF_JOINT_FIELDS[];
extern const size_t SF_JOINT_FIELD_COUNT;

/* One name: a single body or a group. */
typedef struct {
    sf_name_t key; /* a copy: the bodies and groups arrays move as they grow */
    bool used;
    bool is_group;
    size_t index;
} sf_name_entry_t;

typedef struct {
    sf_name_entry_t *slots; /* open addressing, a power-of-two capacity, at most half full */
    size_t capacity, count;
} sf_names_t;

typedef struct {
    sf_settings_t settings;
    sf_body_t *bodies;
    size_t body_count, body_capacity;
    sf_group_t *groups;
    size_t group_count, group_capacity;
    sf_statement_t *statements;
    size_t statement_count, statement_capacity;
    sf_names_t names;
    sf_contact_t *contacts;
    size_t contact_count, contact_capacity;
    sf_joint_t *joints;
    size_t joint_count, joint_capacity;
    sf_where_t first_island; /* the first `asleep`, for the message when sleeping is off */
    size_t total_bodies; /* bodies the blocks make, repeats counted */
    size_t total_vertices;
} sf_doc_t;

void sf_doc_free(sf_doc_t *doc);
sf_name_entry_t *sf_names_find(sf_names_t *names, const char *key);
/* Adds key (not yet there) and returns its entry. */
sf_name_entry_t *sf_names_add(sf_names_t *names, const char *key, bool is_group, size_t index);

/* Parses the whole text into doc (zeroed by the caller). False on the first
 * error, which lexer->error holds; doc must still be freed. */
bool sf_parse(sf_lexer_t *lexer, sf_doc_t *doc);

/* ---- The live file -------------------------------------------------------- */

/* One body the file made. The body's info points at this record, whose first
 * member is the tag: a pointer to a structure, converted, points to its first
 * member (C11 6.7.2.1), so body_get_info reads as the tag string. */
typedef struct sf_record {
    char tag[SCENE_FILE_NAME_MAX + 1];
    body_t *body; /* NULL once the engine freed the body */
    struct scene_file *file;
    size_t spec;  /* the sf_body_t it was made from */
    size_t index; /* its place in file->records */
} sf_record_t;

/* A force creator made by a spring or drag statement, with the records it
 * joins. */
typedef struct {
    size_t statement;
    sf_record_t *body1;
    sf_record_t *body2; /* NULL for a drag */
} sf_instance_t;

/* The engine group of a newton (gravity) or collide (collision) statement:
 * one force creator for all its pairs. */
typedef struct {
    gravity_group_t *gravity;
    collision_group_t *collision;
} sf_engine_group_t;

/* Where scene_file_get_force is in the listing (scene_file_list.c): the
 * force at index, of statement; for a spring or drag the instance at i, for
 * a pair the members i and j of the statement's sides (side1, side2), with
 * the next instance to list kept in instance. */
typedef struct {
    bool valid;
    size_t index, statement, i, j;
    size_t n, m; /* the sides' sizes */
    size_t instance;
} sf_cursor_t;

struct scene_file {
    sf_doc_t doc;
    scene_t *scene;
    sf_record_t **records; /* in the order made */
    size_t record_count, record_capacity;
    size_t freed_records; /* records whose body the engine freed */
    sf_instance_t *instances; /* in statement order */
    size_t instance_count, instance_capacity;
    sf_engine_group_t *groups; /* one per statement */
    /* The listing: its length at the last scene_file_force_count (while
     * listing_fresh: no body made or freed since), the cursor and the
     * members of the statement it is in. */
    size_t listed;
    bool listing_fresh;
    sf_cursor_t cursor;
    sf_record_t **side1, **side2;
    size_t side1_capacity, side2_capacity;
};

/* Resolves names, checks the limits, and builds file->scene. False with the
 * error set when a name or a limit is refused; nothing is built then. */
bool sf_build(scene_file_t *file, sf_lexer_t *lexer);

/* The joint blocks (scene_file_joints.c): checked before anything is made
 * (what joint_create would refuse, with the block's place), made after the
 * bodies and forces. */
bool sf_check_joints(const sf_doc_t *doc, sf_lexer_t *lexer);
bool sf_make_joints(scene_file_t *file, sf_lexer_t *lexer);

/* Whether a live record belongs to the set a reference names. */
bool sf_in_ref(const scene_file_t *file, const sf_ref_t *ref, const sf_record_t *record);

/* The live records of a set (refs[0 .. count) together), in record order,
 * into out (room for record_count); returns how many. */
size_t sf_members(const scene_file_t *file, const sf_ref_t *refs, size_t count,
                  sf_record_t **out);

/* The forces a statement lists among the live records: 1 or 0 for a spring,
 * a drag per member, newton's and collide's pairs (each unordered pair
 * once; a collide pair is (member of the first side, member of the second),
 * the earlier body first when both are on both sides). scratch has room
 * for twice record_count. */
size_t sf_statement_pairs(const scene_file_t *file, size_t statement, sf_record_t **scratch);

/* Drops the instances whose bodies the engine freed. */
void sf_drop_orphan_forces(scene_file_t *file);

/* Drops instances whose bodies were freed, forgets those bodies, and frees their
 * records (keeps memory flat while a game spawns and destroys bodies). */
void sf_collect(scene_file_t *file);

/* Grows *array (of element_size bytes each) to hold at least needed. */
void sf_reserve(void **array, size_t *capacity, size_t needed, size_t element_size);

/* The checked quantities, shared by the parser and spawn. */
#define SF_MAX_LENGTH 1e9    /* coordinates, sizes, positions (m) */
#define SF_MAX_MOTION 1e9    /* velocities (m/s), angles (rad), spins (rad/s), gravity */
#define SF_MAX_CONSTANT 1e40 /* masses, densities, G, k, gamma */
#define SF_MIN_MOMENT 1e-290 /* kg m^2: far inside what a double inverts */
#define SF_MAX_MOMENT 1e290
#define SF_MAX_STATE 1e300   /* the engine's state: timers, impulses, separations */

#endif // #ifndef SCENE_FILE_PRIVATE_H
