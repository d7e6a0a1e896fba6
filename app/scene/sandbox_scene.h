#ifndef SANDBOX_SCENE_H
#define SANDBOX_SCENE_H

/*
 * The sandbox's world: an engine scene read from a scene file
 * (engine/include/jostle/scene_file.h), the game its file names (app/games/), the
 * bodies the user drops, and the grab spring. The default scene, a static
 * floor and two walls under gravity with world contacts, is a scene file
 * too, built into the app (SANDBOX_DEFAULT_SCENE), so that every scene the
 * sandbox shows can be saved. Pure engine API; no SDL here.
 */

#include <stdbool.h>
#include <stdint.h>
#include "jostle/jostle.h"
#include "jostle/joint.h"
#include "games/game.h"
#include "jostle/scene_file.h"

/* The default scene's layout (metres): the floor's top is y = 0, the walls'
 * inner faces are at x = +-WALL_X and they rise to WALL_TOP. */
#define SANDBOX_WALL_X 14.0
#define SANDBOX_WALL_TOP 30.0
#define SANDBOX_GRAVITY 10.0
/* Threads a step runs on (scene_set_workers): the two cores of the machines
 * it is measured on; the bodies move the same with any count. At most
 * SANDBOX_MAX_WORKERS, whatever a scene file or the SOLVER page asks: a web
 * page runs on one thread (docs/web.md). */
#ifdef __EMSCRIPTEN__
#define SANDBOX_WORKERS 1
#define SANDBOX_MAX_WORKERS 1
#else
#define SANDBOX_WORKERS 2
#define SANDBOX_MAX_WORKERS SCENE_MAX_WORKERS
#endif
/* The world: a body whose centroid falls this far below the bottom of the
 * container (the default scene's floor top, a file's view) is removed (y =
 * -40 in the default scene), and so is one farther than the radius from
 * the middle of the default view; a drop below the world's floor is
 * refused. */
#define SANDBOX_KILL_DEPTH 40.0
#define SANDBOX_WORLD_RADIUS 1e6
/* The default scene, as a scene file (docs/sandbox-reference.md shows it). */
extern const char SANDBOX_DEFAULT_SCENE[];
/* Its name on screen and in messages. */
#define SANDBOX_DEFAULT_NAME "sandbox"

typedef enum {
    SHAPE_REGULAR = 0, /* a regular polygon of `sides` sides (3 to 8) */
    SHAPE_BOX,         /* a rectangle 2 size wide and 1.2 size high */
    SHAPE_RANDOM,      /* a random convex polygon of 5 to 9 vertices */
    SHAPE_CIRCLE,      /* a circle of radius size */
    SHAPE_CAPSULE,     /* a horizontal capsule 2 size long and 1 size high */
} shape_kind_t;

typedef struct {
    shape_kind_t kind;
    int sides;   /* for SHAPE_REGULAR */
    double size; /* circumradius (m) */
} shape_choice_t;

#define SHAPE_MIN_SIZE 0.1
#define SHAPE_MAX_SIZE 3.0

/* The grab: a mouse joint (jostle/joint.h) from the grab point to the
 * cursor, of natural frequency 3 Hz, damping ratio 0.7 and a force of at
 * most 300 m/s^2 times the body's mass, so that every body follows the
 * cursor alike and none is flung through a wall. Joints act only with world
 * contacts: in a scene without them (springs, orbits) the grab is a damped
 * spring of the same frequency, damping and cap (plus the body's weight),
 * applied by a force creator. */
typedef struct {
    body_t *body;         /* NULL when nothing is grabbed */
    joint_t *joint;       /* the mouse joint; NULL without world contacts */
    vector_t local_point; /* grab point in the body's frame (relative to centroid, rotation 0) */
    vector_t target;      /* the cursor (world) */
    vector_t gravity;     /* the scene's gravity, which the spring holds up */
} grab_t;

#define SANDBOX_PATH_MAX 1024
#define SANDBOX_NAME_MAX 64

/* A scene file read and its game started, not yet shown (sandbox_load). */
typedef struct {
    scene_file_t *file;
    game_t *game;              /* NULL when the file names no game */
    bool is_default;           /* the built-in default scene */
    char path[SANDBOX_PATH_MAX]; /* "" for the default scene */
} sandbox_loaded_t;

typedef struct {
    scene_t *scene;      /* scene_file_get_scene(file) */
    scene_file_t *file;  /* the open scene's file (the default scene's too) */
    game_t *game;        /* the file's game, NULL when it names none */
    bool is_default;     /* the built-in default scene is open */
    char path[SANDBOX_PATH_MAX]; /* the file it was read from; "" for the default */
    char name[SANDBOX_NAME_MAX]; /* "sandbox", or the file's name without .scene */
    double step;         /* the file's timestep (s): every fixed step is this long */
    double file_step;    /* the timestep the file was read with (the settings' default) */
    /* The length of the next steps (s): `step`, or with frame stepping the
     * frame's (set by the caller before sandbox_step). */
    double tick;
    scene_file_stepping_t stepping; /* fixed steps, or one step a frame (the file's, changed live) */
    /* The open box the bodies play in: in the default scene between the
     * walls' inner faces, from the floor's top to the walls' top; in a file,
     * its view. The world's floor is SANDBOX_KILL_DEPTH below it; spawned
     * grids fill it. */
    aabb_t container;
    /* What the default view shows: the file's view (the default scene's is
     * its container with the floor and walls, and half a metre around). */
    aabb_t home;
    grab_t grab;
    body_t *inspected; /* the body the inspector shows, NULL for none (let go as the grab is) */
    char refusal[128]; /* sandbox_place's last reason */
    /* The bodies the sandbox removed for leaving the world (sandbox_step):
     * how many since the start, the last one in words ("the weight", "a
     * body") and why ("it fell out of the world"). */
    struct {
        unsigned long count;
        char last[SCENE_FILE_NAME_MAX + 8];
        const char *why;
    } removed;
    bool gravity_on;
    vector_t gravity;    /* what G turns on: the file's gravity, else (0, -10) */
    /* The player's controls for the next steps (a game's only). */
    game_input_t input;
    /* The user's choices. The integrator is the open scene's (a file's own
     * when it opens; kept through sandbox_reset); default_integrator is what
     * the default scene opens with (--integrator, else seed). */
    integrator_t integrator;
    integrator_t default_integrator;
    integrator_t file_integrator; /* the file's own (the default scene's: default_integrator) */
    bool sleeping_on;        /* resting bodies sleep (the engine's default: on) */
    /* Moves whenever a body is added or removed (dropped, deleted, cleared,
     * fallen out, spawned or destroyed by a game, the scene replaced): the
     * energy drift then takes a new reference. */
    unsigned long changes;
    uint64_t rng;
    uint64_t seed;
    unsigned next_color;
} sandbox_t;

/* Kilograms per square metre of the dropped bodies. */
#define SANDBOX_DENSITY 1.0

/* Opens the default scene (the floor and walls, gravity on, contacts on). */
void sandbox_init(sandbox_t *sandbox, uint64_t seed);
void sandbox_free(sandbox_t *sandbox);

/*
 * Reads a scene file (path NULL: the default scene) and starts its game,
 * without touching the open scene. False with a message in error when the
 * file is refused ("FILE:LINE:COLUMN: expected ..., found ..." from
 * scene_file.h, "FILE: cannot read: ...") or its game cannot start
 * ("FILE: breakout: the scene has no body named paddle").
 */
bool sandbox_load(const char *path, sandbox_loaded_t *loaded, char *error, size_t error_size);

/* Frees what sandbox_load made, when it is not shown after all. */
void sandbox_loaded_free(sandbox_loaded_t *loaded);

/*
 * Shows a loaded scene in place of the open one, which is freed (the grab let
 * go). The scene steps with the file's timestep; its integrator is the
 * file's (the default scene: default_integrator), or the current one when
 * keep_integrator; sleeping as the user chose.
 */
void sandbox_show(sandbox_t *sandbox, sandbox_loaded_t *loaded, bool keep_integrator);

/* sandbox_load and sandbox_show; on failure the open scene is kept. */
bool sandbox_open(sandbox_t *sandbox, const char *path, char *error, size_t error_size);

/* Opens the open scene again as it started (the default scene anew, a file
 * read again), keeping the integrator. False, the scene kept, when the file
 * can no longer be read. */
bool sandbox_reset(sandbox_t *sandbox, char *error, size_t error_size);

/* Marks every dynamic body removed (static bodies stay); returns how
 * many there were. */
size_t sandbox_clear(sandbox_t *sandbox);

/* A new list of vertices for the shape centred at the origin (for a circle
 * or capsule, its outline: vertices on its boundary, its bounding box
 * exact); NULL and a message in *problem when the shape is unusable. The random shape draws
 * from the sandbox's generator. */
list_t *sandbox_make_shape(sandbox_t *sandbox, shape_choice_t shape, const char **problem);

/* For a circle or capsule: the centres of its end circles relative to its
 * centroid (equal for a circle; a capsule's lie along x) and its radius
 * (m); false for a polygon. */
bool sandbox_shape_core(shape_choice_t shape, vector_t *p1, vector_t *p2, double *radius);

/* Drops the shape made by sandbox_make_shape (vertices taken over): a
 * polygon by sandbox_drop, a circle or capsule as the round body itself
 * (the vertices, its outline, only place it). */
body_t *sandbox_drop_shape(sandbox_t *sandbox, shape_choice_t shape, list_t *vertices,
                           vector_t at, vector_t velocity, double elasticity,
                           const char **problem);

/* Drops a body of the given vertices (taken over; any position: the body's
 * centroid is moved to `at`), moving at velocity, with the given elasticity.
 * NULL (the vertices freed, nothing added) when the shape is refused; *problem
 * then says why. */
body_t *sandbox_drop(sandbox_t *sandbox, list_t *vertices, vector_t at, vector_t velocity,
                     double elasticity, const char **problem);

/*
 * Where a shape (vertices as sandbox_make_shape gives them) dropped with its
 * centroid at `at` goes. A drop at a point inside a body, static or not, or
 * below the world's floor is refused: the result is why ("inside the
 * floor", "inside the brick", "inside a body", "outside the world: bodies
 * below y = -40 m are removed"). Otherwise the result is NULL and *placed
 * is `at`; in the default scene, a click inside the container is moved just
 * enough that the shape's bounding box clears the container's bottom and
 * sides (a click near the floor sets the shape on it rather than into it).
 */
const char *sandbox_place(sandbox_t *sandbox, list_t *vertices, vector_t at, vector_t *placed);

/* The body in words for messages: "the " and the name the file gave it,
 * else its tag, underscores as spaces ("the left wall"); "a body" when it
 * has neither. */
void sandbox_body_words(sandbox_t *sandbox, body_t *body, char *out, size_t size);

/* The world's floor (y, m): bodies below it are removed, drops refused. */
double sandbox_world_floor(const sandbox_t *sandbox);

/* The bounding box of every dynamic body; false when there is none. */
bool sandbox_bodies_bounds(sandbox_t *sandbox, aabb_t *bounds);

/* A new copy of a list of vertices. */
list_t *sandbox_copy_vertices(list_t *vertices);

/* Adds count bodies of the given size in a grid in the container, from its
 * bottom (for the benchmark), cycling through the shapes. */
void sandbox_spawn(sandbox_t *sandbox, size_t count, double size, double elasticity);

/* The topmost (last added) dynamic body that contains point, or NULL. */
body_t *sandbox_body_at(sandbox_t *sandbox, vector_t point);

/* Removes a dynamic body (letting go of it first if it is grabbed). */
void sandbox_delete(sandbox_t *sandbox, body_t *body);

/* The topmost body (the last added) that contains point, static or not,
 * or NULL. */
body_t *sandbox_any_body_at(sandbox_t *sandbox, vector_t point);

/* Whether body is static (infinite mass: the floor, the walls, bricks). */
bool sandbox_is_static(body_t *body);

void sandbox_grab(sandbox_t *sandbox, body_t *body, vector_t point);
void sandbox_grab_move(sandbox_t *sandbox, vector_t target);
void sandbox_release(sandbox_t *sandbox);
/* The grabbed body's grab point in world coordinates (only when grabbing). */
vector_t sandbox_grab_point(sandbox_t *sandbox);

/* Gravity on (sandbox->gravity) or off. */
void sandbox_set_gravity(sandbox_t *sandbox, bool on);

/* The scene's integrator, now and after a reset. */
void sandbox_set_integrator(sandbox_t *sandbox, integrator_t integrator);

/* Sleeping on or off (scene_set_sleeping), now and in every scene opened
 * later; off wakes every body. */
void sandbox_set_sleeping(sandbox_t *sandbox, bool on);

/* The solver's settings of the open scene, changed live and kept in its
 * file so that saving writes them (scene_file.h): the iterations (each in
 * [1, 1000]), the workers (1 to SANDBOX_MAX_WORKERS), the timestep (0 to 10
 * s) and the stepping. False, nothing changed, when a value is refused. */
bool sandbox_set_iterations(sandbox_t *sandbox, size_t velocity, size_t position);
bool sandbox_set_workers(sandbox_t *sandbox, size_t workers);
bool sandbox_set_timestep(sandbox_t *sandbox, double step);
void sandbox_set_stepping(sandbox_t *sandbox, scene_file_stepping_t stepping);

/* One physics step of sandbox->tick seconds, then the game's rules with
 * sandbox->input; then removes the bodies that left the world (counted in
 * sandbox->removed). */
void sandbox_step(sandbox_t *sandbox);

/* Totals over the bodies of finite mass that are not removed, in one pass
 * (and the static ones counted), and the potential energy of the file's
 * springs and Newtonian gravity. */
typedef struct {
    size_t bodies;      /* dynamic bodies: every count the sandbox shows is of these */
    size_t statics;     /* bodies of infinite mass (floor, walls, bricks), counted apart */
    size_t sleeping;    /* of which asleep (body_is_sleeping) */
    double kinetic;     /* J */
    /* J: m g h with h the centroid's height above y = 0 (the default
     * scene's floor), plus 1/2 k d^2 for each spring of the file and
     * -G m1 m2 / r for each pair under its Newtonian gravity */
    double potential;
    vector_t momentum;  /* N s */
} sandbox_totals_t;

sandbox_totals_t sandbox_totals(sandbox_t *sandbox);

/* A short name for the shape ("hexagon", "box", "random", "circle",
 * "capsule"). */
const char *sandbox_shape_name(shape_choice_t shape);

/* The name a scene file goes by: its file name without the directory and
 * ".scene" ("assets/scenes/pegs.scene" -> "pegs"), at most size - 1 bytes. */
void sandbox_scene_name(const char *path, char *name, size_t size);

#endif
