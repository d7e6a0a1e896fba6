#ifndef SANDBOX_SCENE_H
#define SANDBOX_SCENE_H

/*
 * The sandbox's world: an engine scene with a static floor and two walls,
 * gravity, world contacts, the bodies the user drops, and the grab spring.
 * Pure engine API; no SDL here.
 */

#include <stdbool.h>
#include <stdint.h>
#include "engine.h"

/* World layout (metres): the floor's top is y = 0, the walls' inner faces are
 * at x = +-WALL_X and they rise to WALL_TOP. */
#define SANDBOX_WALL_X 14.0
#define SANDBOX_WALL_TOP 30.0
#define SANDBOX_GRAVITY 10.0
/* A body whose centroid falls below this height is removed. */
#define SANDBOX_KILL_Y (-40.0)

typedef enum {
    SHAPE_REGULAR = 0, /* a regular polygon of `sides` sides (3 to 8) */
    SHAPE_BOX,         /* a rectangle 2 size wide and 1.2 size high */
    SHAPE_RANDOM,      /* a random convex polygon of 5 to 9 vertices */
} shape_kind_t;

typedef struct {
    shape_kind_t kind;
    int sides;   /* for SHAPE_REGULAR */
    double size; /* circumradius (m) */
} shape_choice_t;

#define SHAPE_MIN_SIZE 0.1
#define SHAPE_MAX_SIZE 3.0

/* The grab spring's state, read by its force creator every tick. */
typedef struct {
    body_t *body;         /* NULL when nothing is grabbed */
    vector_t local_point; /* grab point in the body's frame (relative to centroid, rotation 0) */
    vector_t target;      /* the cursor (world) */
    vector_t gravity;     /* the scene's gravity, which the spring holds up */
} grab_t;

typedef struct {
    scene_t *scene;
    /* The open box the bodies play in: between the walls' inner faces, from
     * the floor's top to the walls' top. Drops outside it are refused. */
    aabb_t container;
    /* The container with its floor and walls: what the default view shows. */
    aabb_t extent;
    grab_t grab;
    char refusal[64]; /* sandbox_place's last reason */
    bool gravity_on;
    /* Kept through sandbox_reset: the user's choices. */
    integrator_t integrator; /* the scene's integrator (the engine's default: seed) */
    bool sleeping_on;        /* resting bodies sleep (the engine's default: on) */
    /* Moves whenever a body is added or removed (dropped, deleted, cleared,
     * fallen out, the scene reset): the energy drift then takes a new
     * reference. */
    unsigned long changes;
    uint64_t rng;
    uint64_t seed;
    unsigned next_color;
} sandbox_t;

/* Kilograms per square metre of the dropped bodies. */
#define SANDBOX_DENSITY 1.0

/* Builds the default scene (the floor and walls, gravity on, contacts on). */
void sandbox_init(sandbox_t *sandbox, uint64_t seed);
void sandbox_free(sandbox_t *sandbox);

/* Frees everything and builds the default scene again (same seed). */
void sandbox_reset(sandbox_t *sandbox);

/* Marks every dynamic body removed (the floor and walls stay); returns how
 * many there were. */
size_t sandbox_clear(sandbox_t *sandbox);

/* A new list of vertices for the shape centred at the origin; NULL and a
 * message in *problem when the shape is unusable. The random shape draws
 * from the sandbox's generator. */
list_t *sandbox_make_shape(sandbox_t *sandbox, shape_choice_t shape, const char **problem);

/* Drops a body of the given vertices (taken over; any position: the body's
 * centroid is moved to `at`), moving at velocity, with the given elasticity.
 * NULL (the vertices freed, nothing added) when the shape is refused; *problem
 * then says why. */
body_t *sandbox_drop(sandbox_t *sandbox, list_t *vertices, vector_t at, vector_t velocity,
                     double elasticity, const char **problem);

/*
 * Where a shape (vertices as sandbox_make_shape gives them) dropped with its
 * centroid at `at` goes. A drop at a point inside a static body or outside
 * the container is refused: the result is why ("inside the floor", "outside
 * the container"). Otherwise the result is NULL and *placed is `at`, moved
 * just enough that the shape's bounding box clears the floor and the walls
 * (a click near the floor sets the shape on it rather than into it).
 */
const char *sandbox_place(sandbox_t *sandbox, list_t *vertices, vector_t at, vector_t *placed);

/* The bounding box of every dynamic body; false when there is none. */
bool sandbox_bodies_bounds(sandbox_t *sandbox, aabb_t *bounds);

/* A new copy of a list of vertices. */
list_t *sandbox_copy_vertices(list_t *vertices);

/* Adds count bodies of the given size in a grid above the floor (for the
 * benchmark), cycling through the shapes. */
void sandbox_spawn(sandbox_t *sandbox, size_t count, double size, double elasticity);

/* The topmost (last added) dynamic body that contains point, or NULL. */
body_t *sandbox_body_at(sandbox_t *sandbox, vector_t point);

/* Removes a dynamic body (letting go of it first if it is grabbed). */
void sandbox_delete(sandbox_t *sandbox, body_t *body);

/* Whether body is one of the scene's static bodies (the floor, the walls). */
bool sandbox_is_static(body_t *body);

void sandbox_grab(sandbox_t *sandbox, body_t *body, vector_t point);
void sandbox_grab_move(sandbox_t *sandbox, vector_t target);
void sandbox_release(sandbox_t *sandbox);
/* The grabbed body's grab point in world coordinates (only when grabbing). */
vector_t sandbox_grab_point(sandbox_t *sandbox);

void sandbox_set_gravity(sandbox_t *sandbox, bool on);

/* The scene's integrator, now and after a reset. */
void sandbox_set_integrator(sandbox_t *sandbox, integrator_t integrator);

/* Sleeping on or off (scene_set_sleeping), now and after a reset; off wakes
 * every body. */
void sandbox_set_sleeping(sandbox_t *sandbox, bool on);

/* One physics step of dt seconds; then removes the bodies that fell out. */
void sandbox_step(sandbox_t *sandbox, double dt);

/* Totals over the bodies of finite mass that are not removed, in one pass. */
typedef struct {
    size_t bodies;      /* dynamic bodies */
    size_t sleeping;    /* of which asleep (body_is_sleeping) */
    double kinetic;     /* J */
    double potential;   /* J, m g h with h the centroid's height above the floor */
    vector_t momentum;  /* N s */
} sandbox_totals_t;

sandbox_totals_t sandbox_totals(sandbox_t *sandbox);

/* A short name for the shape ("hexagon", "box", "random"). */
const char *sandbox_shape_name(shape_choice_t shape);

#endif
