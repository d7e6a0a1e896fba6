#ifndef SCENE_FILE_H
#define SCENE_FILE_H

/*
 * Scene files: a plain-text description of a scene (bodies, forces, collision
 * rules, integrator and solver settings, the view, the game to run), read into
 * a new engine scene, and written back out. The format is in docs/scenes.md;
 * the presets are the .scene files in assets/scenes/.
 *
 * This module sits on top of the engine and uses only its public API (it is
 * compiled with engine/include alone, engine/scenefile/). It is archived into
 * libjostle.a, so a program that links the engine has it.
 *
 * User data, not programmer data: a file is checked completely before anything
 * reaches the engine, so a malformed file is refused with a message and never
 * stops the program (the engine itself aborts on bad values, docs/api.md).
 * What is checked: the syntax, every number (finite, within the limits of
 * docs/scenes.md), every shape (polygon_check: at least 3 vertices, strictly
 * convex, no repeated vertex, non-zero area; clockwise vertex lists are
 * reversed, as documented), every mass (its inverse and the moment of inertia
 * of its shape and their inverses finite), every name a force or rule uses,
 * and the size of what the file asks for (bodies, vertices, force creators).
 * A file that loads can still describe a scene that blows up when run (a
 * spring too stiff for the step): scene_tick then stops as docs/api.md says.
 *
 * Ownership: a scene_file_t owns the scene it built and frees it in
 * scene_file_free. Every body the file makes carries, as its info
 * (body_get_info), its tag: a NUL-terminated string, "" when the file gave
 * none, owned by the scene_file_t, valid while the body lives. Game rules tell
 * bodies apart by it (a player, an invader, a shot).
 */

#include <stdbool.h>
#include <stddef.h>
#include "body.h"
#include "scene.h"
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

typedef struct scene_file scene_file_t;

/* Names and tags: a letter or '_', then letters, digits, '_', '.' or '-'. */
#define SCENE_FILE_NAME_MAX 63

/* What the loader accepts at most (docs/scenes.md, "Limits"). */
#define SCENE_FILE_MAX_BODIES 20000
#define SCENE_FILE_MAX_VERTICES 1000          /* per shape */
#define SCENE_FILE_MAX_TOTAL_VERTICES 1000000 /* over every body of a file */
#define SCENE_FILE_MAX_FORCES 1000000         /* force creators made: springs, drags, one per newton or collide */

/* Why a file was refused. `message` is "FILE:LINE:COLUMN: expected WHAT, found
 * WHAT" (lines and columns from 1, columns in bytes), e.g.
 * "pegs.scene:12:14: expected the radius (m), a number > 0 and <= 1e+09, found
 * \"-0.5\"". A file that cannot be read or written gives "FILE: cannot read:
 * REASON" and line = column = 0. */
typedef struct {
    char message[512];
    size_t line;
    size_t column;
} scene_file_error_t;

/*
 * Reads a scene file from memory: `length` bytes of `text` (no terminating NUL
 * needed; a NUL byte inside is refused). `file_name` names it in messages
 * (NULL: "<memory>"). Returns a new scene_file_t holding a new scene, or NULL
 * with *error filled in (error may be NULL). Nothing is allocated on failure
 * and no other scene is touched: a caller keeps its current scene until a new
 * one has loaded.
 */
scene_file_t *scene_file_parse(const char *text, size_t length, const char *file_name,
                               scene_file_error_t *error);

/* scene_file_parse of the file at path (its path names it in messages). */
scene_file_t *scene_file_load(const char *path, scene_file_error_t *error);

/* Frees the scene (its bodies and force creators) and everything else the file
 * holds. NULL is allowed. */
void scene_file_free(scene_file_t *file);

/* The scene, owned by the scene_file_t. Tick it as any scene. */
scene_t *scene_file_get_scene(scene_file_t *file);

/* The step the file asks for (`timestep`, s; default 1/120). */
double scene_file_get_timestep(const scene_file_t *file);

/* The rectangle of the world the file asks to show first (`view`): its centre
 * and size, metres. has_view is false when the file gives none. */
typedef struct {
    bool has_view;
    vector_t center;
    double width;
    double height;
} scene_file_view_t;

scene_file_view_t scene_file_get_view(const scene_file_t *file);

/* The game the file names (`game NAME`), "" when none. The rules themselves
 * live with the caller (the sandbox's app/games/). */
const char *scene_file_get_game(const scene_file_t *file);

/* The solver's settings (iterations, warm starting, restitution threshold,
 * sleep tolerance and time) are the scene's: a program changes them on
 * the scene (jostle/scene.h) and scene_file_write writes them as they are. */

/* A new `timestep` (s), as scene_file_get_timestep then gives it and the
 * writer writes it; the file does not step the scene, its caller does.
 * False, nothing changed, unless 0 < timestep <= 10. */
bool scene_file_set_timestep(scene_file_t *file, double timestep);

/* The workers the file asks for (`workers N`, 1 to SCENE_MAX_WORKERS: the
 * scene is built with scene_set_workers(N)); 0 when it gives none. The
 * writer writes the scene's count (scene_get_workers) when it is not 1 or
 * the file gave one. */
size_t scene_file_get_workers(const scene_file_t *file);

/* How the program running the file is asked to step it (`stepping fixed`,
 * the default: steps of the timestep; `stepping frame`: one step a frame,
 * as long as the frame). The file does not step the scene; the sandbox
 * reads this. */
typedef enum { SCENE_FILE_STEP_FIXED = 0, SCENE_FILE_STEP_FRAME } scene_file_stepping_t;
scene_file_stepping_t scene_file_get_stepping(const scene_file_t *file);
void scene_file_set_stepping(scene_file_t *file, scene_file_stepping_t stepping);

/* What a sample says about itself (`category WORDS`, `note WORDS`): the
 * words up to the end of the statement, joined by one space; "" when the
 * file gives none. The sandbox lists its samples by category with their
 * notes. At most SCENE_FILE_CATEGORY_MAX and SCENE_FILE_NOTE_MAX bytes. */
#define SCENE_FILE_CATEGORY_MAX 40
#define SCENE_FILE_NOTE_MAX 200
const char *scene_file_get_category(const scene_file_t *file);
const char *scene_file_get_note(const scene_file_t *file);

/* The body the file named `name` (a `body NAME { ... }` without repeat), NULL
 * when there is none or the scene has freed it. A body marked removed but not
 * yet freed is returned (body_is_removed tells). */
body_t *scene_file_find_body(scene_file_t *file, const char *name);

/* The name the file gave `body`: its block's (`body NAME { ... }`, repeated
 * or not) or, for a spawned body, its template's; "" for an anonymous body;
 * NULL when the file did not make it (a body the caller added) or an
 * argument is NULL. Valid while the file lives. Looks through the file's
 * bodies: for messages, not for every step. */
const char *scene_file_body_name(scene_file_t *file, body_t *body);

/*
 * Makes a body from the template `template_name` (`template NAME { ... }`)
 * with its centroid at `position` and velocity `velocity`, and adds it to the
 * scene. The body has the template's shape, mass, material, angle, spin, tag
 * and groups, and is in the group NAME; every force and rule of the file that
 * names one of its groups (or `all`) now applies to it, as it would have at
 * load. Returns NULL, adding nothing, when there is no such template, when
 * position or velocity is not finite or beyond the limits of docs/scenes.md,
 * or when the body or force creator limits above would be exceeded.
 */
body_t *scene_file_spawn(scene_file_t *file, const char *template_name, vector_t position,
                         vector_t velocity);

/* Whether the file has a template of that name (scene_file_spawn can use it). */
bool scene_file_has_template(scene_file_t *file, const char *template_name);

/* A force creator the file made (for drawing springs and for tests). body2 is
 * NULL for a drag. */
typedef enum {
    SCENE_FILE_SPRING = 0,
    SCENE_FILE_NEWTON,
    SCENE_FILE_DRAG,
    SCENE_FILE_PHYSICS_COLLISION,
    SCENE_FILE_DESTRUCTIVE_COLLISION,
} scene_file_force_kind_t;

typedef struct {
    scene_file_force_kind_t kind;
    double constant; /* k (N/m), G (N m^2/kg^2), gamma (kg/s), elasticity; 0 for destructive */
    double rest_length; /* m, a spring's (0 for one without `length`); 0 for the others */
    body_t *body1;
    body_t *body2;
} scene_file_force_t;

/* The forces the file made that are still in the scene (none of their bodies
 * freed): each spring, each drag, and each pair of a newton or collide (one
 * engine force creator for all its pairs; the pairs are worked out as they
 * are read). In file order: statement by statement, then by the bodies' order
 * in the file (spawned bodies last). The count is valid, and get takes an
 * index below it, until the next scene_tick or spawn (get counts again
 * when a body was made or freed since); reading the indices in order costs
 * a step each, any other index a walk from the start. */
size_t scene_file_force_count(scene_file_t *file);
scene_file_force_t scene_file_get_force(scene_file_t *file, size_t index);

/*
 * Writes the scene as it is now, in the file format: the settings (sleeping
 * and the sleep phase included), the templates, every body still in the
 * scene and not marked removed (with its current position, angle, velocity,
 * spin, elasticity, friction, colour, collision filter, sleep and sleep
 * timer), the forces and rules among them, and the world's contact memory
 * (scene_state.h). Bodies the file did not make (dropped by the sandbox's
 * user) are written too, as anonymous bodies with their vertices in their
 * own frame (`centred`) and mass; their info is not written. Force creators
 * the file did not make are not written (the engine cannot list them).
 *
 * Loading the text gives the same scene: the same bodies in the same order,
 * equal bit for bit in every value the engine reports and in the state
 * scene_state.h reads, and the same force creators (those a spawned body
 * joined in file order rather than last); ticked, it goes on as this scene
 * would, to the bit, but for what docs/scenes.md ("Saving") lists: chiefly
 * the seed collision rules' memory of which pairs touch. A body that has
 * gone beyond the limits of docs/scenes.md (1e9 m from the origin) makes a
 * text that loading refuses, naming it.
 *
 * Returns a NUL-terminated heap string (the caller frees it with free) and its
 * length in *length (may be NULL), or NULL with *error filled in when the
 * scene's integrator has no name in the file format's table.
 */
char *scene_file_write(scene_file_t *file, size_t *length, scene_file_error_t *error);

/* scene_file_write to a file at path (replaced). False with *error filled in
 * when it cannot be written. */
bool scene_file_save(scene_file_t *file, const char *path, scene_file_error_t *error);

/* The integrator's name in the file format ("seed", "symplectic_euler", ...),
 * NULL for an integrator the table does not list. */
const char *scene_file_integrator_name(integrator_t integrator);

JOSTLE_API_END

#endif // #ifndef SCENE_FILE_H
