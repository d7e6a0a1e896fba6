#ifndef BODY_PRIVATE_H
#define BODY_PRIVATE_H

/* The body's fields, shared with the scene, the integrator and the contact
 * pipeline (which read and write them in bulk); everyone else uses body.h. */

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include "jostle/body.h"
#include "base/prefetch.h"

struct body {
    /* The fields every step reads for each pair and each body (the
     * narrowphase, the solver's loading, integration) come first, so that a
     * pair touches two cache lines of each body rather than five. */

    /* World polygon, recomputed lazily after the pose changes, with cos and
     * sin of angle; the arrays lie in this body's own block (shape below). */
    size_t count;
    vector_t *world_vertices;
    vector_t *world_normals;
    /* Pose. */
    vector_t centroid;
    double angle;
    double rotation_cos, rotation_sin;

    /* Set by the scene: a number no other body of the scene has had, so
     * contact caches can match pairs across steps even as indices shift. */
    uint32_t id;
    /* Set by the scene each step: the body's row in the solver's arrays. */
    uint32_t solver_index;
    /* Set by the contact pipeline: the contacts this body had as body a in
     * the step of its world numbered contact_step (modulo 2^32), at
     * [contact_first, contact_first + contact_count) of that step's contact
     * buffer, and its pairs that were apart at [gap_first, gap_first +
     * gap_count) of the step's gap buffer (narrowphase.c). */
    uint32_t contact_first, contact_count;
    uint32_t gap_first, gap_count;
    uint32_t contact_step;
    /* Seams (seams.h), in what was padding: whether the world's last
     * search for seams counted this body as static (the world checks such
     * bodies, and static ones, for change while it loads them), and whether
     * a flush static neighbour covers or continues a part of its boundary
     * (read for every pair the narrowphase searches). */
    bool seam_listed;
    bool has_seams;
    /* body_shape_kind_t: a polygon, or a round shape (below), in what was
     * padding too; a pair of polygons reads it once to keep its path. */
    uint8_t kind;
    /* Largest distance from the centroid to a vertex (m). */
    double radius;
    double friction;
    double elasticity;
    double inverse_mass, inverse_inertia;

    /* Motion. */
    vector_t velocity;
    double angular_velocity;
    aabb_t bounds;
    /* How much of the world shape is up to date with the pose: WORLD_STALE
     * (a pose change sets it false), WORLD_POSE or WORLD_FULL (below). */
    uint8_t world_valid;
    bool removed;
    /* Sleeping (sleep.c): asleep bodies are left out of the step; the
     * bodies of one sleeping island are linked in a circle by sleep_next
     * (NULL when awake); sleep_time is how long the body has been slow (s),
     * sleep_anchor and sleep_anchor_angle where it was sleep_window (s) ago. */
    bool asleep;
    /* Changed since the world last stepped it (body_mark_changed): the world
     * wakes, at the start of its next step, the sleeping islands that
     * changed_bounds (its box before the first such change) or its box now
     * touches. */
    bool changed;
    /* Whether a scene owns the body (a body belongs to one scene, once). */
    bool in_scene;
    uint32_t category, mask, group;

    /* Accumulated since the last tick. */
    vector_t force;
    double torque;
    vector_t impulse;
    double angular_impulse;

    double sleep_time, sleep_window;
    vector_t sleep_anchor;
    double sleep_anchor_angle;
    struct body *sleep_next;
    aabb_t changed_bounds;

    double mass, inertia;
    rgb_color_t color;
    void *info;
    free_func_t info_freer;
    /* The scene that owns the body or whose force creators name it (before
     * it is added); NULL for neither. A force creator of one scene must not
     * read a body that another scene frees. */
    struct scene *scene;
    /* The owning scene's count of moves (scene_private.h, scene_moves),
     * which a pose set here advances; NULL outside a scene. */
    uint64_t *moves;
    /* The owning scene's count of changes to which of its bodies sleep
     * (body_wake, body_fall_asleep), by which it keeps its list of awake
     * bodies; NULL outside a scene. */
    uint64_t *sleep_changes;

    /* What the last search for seams found of a listed body (seams.h; the
     * world owns it). */
    struct seam_record *seam;

    /* A round shape (body_round.c): the centres of its core, a point for a
     * circle (both the same) or a capsule's segment, in the body frame,
     * and the radius around them (m). The polygon below is then its
     * outline, with vertices on the boundary. */
    vector_t core[2];
    double round_radius;

    /* A chain (body_chain.c): its segments, static bodies of their own
     * (kind BODY_SHAPE_SEGMENT) that the world collides in its place, each
     * at the midpoint of its ends, turned as the chain is. A segment names
     * its chain and what it knows of its neighbours (segment). */
    struct body **parts;
    size_t part_count;
    bool loop;
    struct body *chain;
    struct body_segment *segment;

    /* Shape in the body frame, relative to the centroid, counter-clockwise. */
    vector_t *local_vertices;
    vector_t *local_normals;
    /* The four arrays of count vectors: world vertices and normals, then
     * local ones. */
    vector_t shape[];
};

/* A chain's segment as the world sees it: a static body whose core (core[0]
 * to core[1], body frame) collides on the side of `normal` only. */
enum { BODY_SHAPE_SEGMENT = 4 };

/* What a segment knows of its chain (body frame, which turns as the chain
 * turns): the points before its start and after its end (ghost vertices,
 * where has_ghost says there is one: not at an open chain's ends), the
 * normal of its free side, and, lengths along it from core[0] (m), the
 * straight run of segments it belongs to, [run_lo, run_hi] (itself when
 * its joins bend), and the stretch [claim_lo, claim_hi] of that run where
 * the middle of a contact's points makes the contact this segment's. */
typedef struct body_segment {
    vector_t normal;
    vector_t ghost[2];
    bool has_ghost[2];
    double run_lo, run_hi;
    double claim_lo, claim_hi;
    /* Its place in the chain, and its offset (chain frame) from the
     * chain's origin. */
    size_t index;
    vector_t offset;
} body_segment_t;

/* The body that stands for a world body in what the scene reports: a
 * segment's chain, otherwise the body itself. */
static inline struct body *body_public(struct body *body) {
    return body->chain != NULL ? body->chain : body;
}

/* BODY_PREFETCH (without shape) for a loop that does nothing for a sleeping
 * body but read its sleep flags: the line of those flags twice as far
 * ahead, and the rest of the body BODY_AHEAD ahead only when it is awake,
 * so that a sleeping pile's step does not fetch the bodies it leaves out. */
#define BODY_PREFETCH_AWAKE(bodies, at, count)                                            \
    do {                                                                                  \
        if ((at) + BODY_AHEAD < (count)) {                                                \
            __builtin_prefetch(&(bodies)[(at) + BODY_AHEAD]->asleep);                     \
        }                                                                                 \
        if ((at) < (count) && !(bodies)[at]->asleep) {                                    \
            PREFETCH_SPAN((bodies)[at], offsetof(struct body, sleep_time), 0);            \
        }                                                                                 \
    } while (0)

/* How many bodies ahead a loop over the step's bodies asks for the next
 * ones: each body is a block of its own, and the loops that walk them all
 * (predicting, loading, moving) waited on each body's first field. */
enum { BODY_AHEAD = 8 };
/* The round core and its radius, which lie together. */
#define BODY_CORE_BYTES                                                                   \
    (offsetof(struct body, round_radius) + sizeof(double) - offsetof(struct body, core))
/* Asks for the lines of bodies[at] (when at < count) that a step reads:
 * its fields through the accumulated impulses and, with_shape, what
 * placing it in the world reads: a round shape's core, or a box's vertex
 * arrays (256 bytes) and the pointer to its local ones. */
#define BODY_PREFETCH(bodies, at, count, with_shape)                                      \
    do {                                                                                  \
        if ((at) < (count)) {                                                             \
            const struct body *body_ = (bodies)[at];                                      \
            PREFETCH_SPAN(body_, offsetof(struct body, sleep_time), 0);                   \
            if (with_shape) {                                                             \
                PREFETCH_SPAN(body_->core, BODY_CORE_BYTES, 0);                           \
                PREFETCH_SPAN(&body_->local_vertices, 2 * sizeof(vector_t *), 0);         \
                PREFETCH_SPAN(body_->shape, 16 * sizeof(vector_t), 0);                    \
            }                                                                             \
        }                                                                                 \
    } while (0)

/* Allocates a body (zeroed) with room for a polygon of count vertices in
 * its four arrays. */
body_t *body_allocate(size_t count);

/* moment (kg m^2) of a body of finite mass, returned when it and its
 * inverse are finite; otherwise stops the program, naming function. */
double body_checked_moment(double moment, double mass, const char *function);

/* Stops the program, naming function, when mass cannot be a body's. */
void body_check_mass(double mass, const char *function);

/* Sets what every new body starts with: mass and moment of inertia (and
 * their inverses, 0 for mass INFINITY), the default material and filter,
 * colour and info. */
void body_set_defaults(body_t *body, double mass, double inertia, rgb_color_t color, void *info,
                       free_func_t info_freer);

/* A round body's core centres in the world (its pose as cached with the
 * world polygon: call body_update_world after the pose changes). */
static inline void body_world_core(const body_t *body, vector_t core[2]) {
    core[0] = vec_add(body->centroid, vec_rotate_cs(body->core[0], body->rotation_cos,
                                                    body->rotation_sin));
    core[1] = vec_add(body->centroid, vec_rotate_cs(body->core[1], body->rotation_cos,
                                                    body->rotation_sin));
}

/* The box of a round body's world core grown by its radius. */
static inline aabb_t body_round_bounds(const body_t *body) {
    vector_t core[2];
    body_world_core(body, core);
    double r = body->round_radius;
    return (aabb_t){{fmin(core[0].x, core[1].x) - r, fmin(core[0].y, core[1].y) - r},
                    {fmax(core[0].x, core[1].x) + r, fmax(core[0].y, core[1].y) + r}};
}

/* Whether the world point lies within the radius of a round body's core. */
static inline bool body_round_contains(const body_t *body, vector_t point) {
    vector_t core[2];
    body_world_core(body, core);
    vector_t d = vec_subtract(core[1], core[0]);
    double length_squared = vec_dot(d, d);
    double t = length_squared > 0.0 ? vec_dot(vec_subtract(point, core[0]), d) / length_squared
                                    : 0.0;
    t = fmin(1.0, fmax(0.0, t));
    vector_t nearest = vec_add(core[0], vec_multiply(t, d));
    double r = body->round_radius;
    return vec_get_length_squared(vec_subtract(point, nearest)) <= r * r;
}

/* Tells the body's scene that it moved (its queries' grid is stale). */
static inline void body_note_move(body_t *body) {
    if (body->moves != NULL) (*body->moves)++;
}

/* Wakes the body and every body of its sleeping island. */
void body_wake(body_t *body);

/* Marks the body asleep (its island's circle is sleep.c's to link). */
static inline void body_fall_asleep(body_t *body) {
    body->asleep = true;
    if (body->sleep_changes != NULL) (*body->sleep_changes)++;
}

/* A change that sleeping bodies around the body must see (its pose,
 * velocity, mass, material or filter set, its removal, its arrival in a
 * scene): wakes its island now, and marks it changed so that the world
 * wakes the islands its box touched before the change or touches after it
 * (a static body has no island of its own, but holds others up). */
void body_mark_changed(body_t *body);

/* Adds a force already checked (body_add_force checks the caller's;
 * forces.c checks its own): a nonzero push keeps the body awake. */
static inline void body_push(body_t *body, vector_t force) {
    body->force.x += force.x;
    body->force.y += force.y;
    if (force.x != 0.0 || force.y != 0.0) {
        if (body->asleep) {
            body_wake(body);
        } else {
            body->sleep_time = 0.0;
        }
    }
}

/* The velocity with the impulses accumulated for the step applied. */
static inline vector_t body_velocity_after_impulses(const body_t *body) {
    return vec_add(body->velocity, vec_multiply(body->inverse_mass, body->impulse));
}

/* Clears the force, torque and impulses accumulated for the step. */
static inline void body_clear_accumulators(body_t *body) {
    body->force = VEC_ZERO;
    body->torque = 0.0;
    body->impulse = VEC_ZERO;
    body->angular_impulse = 0.0;
}

/* Whether the body can be moved by contacts (finite mass or inertia). */
static inline bool body_is_movable(const body_t *body) {
    return body->inverse_mass > 0.0 || body->inverse_inertia > 0.0;
}

/* The levels of body->world_valid: nothing; the rotation's cosine and sine
 * and the bounds (a polygon's world vertices and normals with them); those
 * and a round body's world outline. */
enum { WORLD_STALE = 0, WORLD_POSE = 1, WORLD_FULL = 2 };

/* Recomputes the world vertices, normals and bounds if the pose changed. */
void body_update_world(body_t *body);

/* Recomputes what a step reads if the pose changed: the rotation, the
 * bounds, a polygon's world vertices and normals. A round body's outline
 * (its world vertices and normals) waits for body_update_world: contacts
 * use its core and radius. */
void body_update_pose(body_t *body);

/* What a step starts from and the integrator clears, kept by whoever
 * integrates so that a step whose result does not fit a double can be
 * explained (body_explain_non_finite). The fields the message needs only:
 * this is copied for every body at every step. */
typedef struct {
    vector_t centroid;
    vector_t force;
    double torque;
    vector_t impulse;
    double angular_impulse;
} body_motion_t;

static inline body_motion_t body_motion(const body_t *body) {
    return (body_motion_t){body->centroid, body->force, body->torque, body->impulse,
                           body->angular_impulse};
}

/* Whether a pose and velocities are finite. 0 x is 0 for finite x and NaN
 * otherwise, and a sum of zeros cannot overflow: one test for six values in
 * the per-body path of every step (paired to shorten the chain of adds). */
static inline bool body_state_is_finite(vector_t centroid, double angle, vector_t velocity,
                                        double angular_velocity) {
    double zero = (0.0 * centroid.x + 0.0 * centroid.y) + (0.0 * velocity.x + 0.0 * velocity.y) +
                  (0.0 * angle + 0.0 * angular_velocity);
    return zero == 0.0;
}

static inline bool body_motion_is_finite(const body_t *body) {
    return body_state_is_finite(body->centroid, body->angle, body->velocity,
                                body->angular_velocity);
}

/* Writes into message which of the body's pose and velocities is not finite
 * after a step of dt from `before`, and the likely cause. */
void body_explain_non_finite(const body_t *body, const body_motion_t *before, double dt,
                             char *message, size_t size);

/* Frame changes between the body's own frame (relative to its centroid,
 * unrotated) and the world. They use the rotation cached with the world
 * polygon: call body_update_world after the pose changes. */
static inline vector_t body_rotate_vector(const body_t *body, vector_t v) {
    return vec_rotate_cs(v, body->rotation_cos, body->rotation_sin);
}

static inline vector_t body_to_world(const body_t *body, vector_t local) {
    return vec_add(body->centroid, body_rotate_vector(body, local));
}

static inline vector_t body_to_local(const body_t *body, vector_t world) {
    vector_t d = vec_subtract(world, body->centroid);
    return (vector_t){body->rotation_cos * d.x + body->rotation_sin * d.y,
                      -body->rotation_sin * d.x + body->rotation_cos * d.y};
}

#endif // #ifndef BODY_PRIVATE_H
