#ifndef SCENE_STATE_H
#define SCENE_STATE_H

/*
 * What a scene carries from one step into the next beyond the values body.h
 * and scene.h report: each body's sleep timer and sleeping island, the
 * phase of the island check, the lengths of the last two steps, and the
 * world's contact memory (last step's contacts, whose impulses warm-start
 * the next step's and whose features it reuses, with what the step before
 * left on the same points), and each joint's accumulated impulses. A program that saves a scene and loads it into a new one
 * (scene_file.h) reads these after a tick and hands them back before the
 * first tick of the new scene, which then continues bit for bit as the
 * saved one would have.
 *
 * The numbers are the engine's own: read them, keep them exactly (a text
 * form must give the same doubles back) and hand them back unchanged; they
 * mean something only to the same version of the engine. Programmer errors
 * stop the program with "engine error in FUNCTION: ..." (docs/api.md).
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "body.h"
#include "joint.h"
#include "scene.h"
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

/* ---- Sleeping -------------------------------------------------------------- */

/* A body's sleep timer (scene_set_sleeping): how long it has been slow (s),
 * and where its drift is measured from: its centroid (m) and angle (rad)
 * `window` seconds ago. A sleeping body's timer is kept but restarts when it
 * wakes. */
typedef struct {
    double slow_time;
    double window;
    vector_t anchor;
    double anchor_angle;
} body_sleep_timer_t;

body_sleep_timer_t body_get_sleep_timer(body_t *body);

/* Sets the timer; every value finite, the two times >= 0 (refused
 * otherwise). */
void body_set_sleep_timer(body_t *body, body_sleep_timer_t timer);

/* The next body of the body's sleeping island: an island's bodies are
 * linked in a circle, so following the link from any of them visits each
 * once and comes back. The body itself when it sleeps alone; NULL when it
 * is awake. */
body_t *body_get_island_next(body_t *body);

/*
 * Puts bodies to sleep as a saved scene had them: bodies[i] sleeps in the
 * island numbered islands[i]; the bodies given the same number form one
 * island, which wakes as one (the numbers only group, any values will do).
 * Their velocities and angular velocities become 0, as a sleeping body's
 * are. The scene's bodies are taken to be where they rest: what was done
 * to them since its last tick (bodies added, poses and materials set),
 * which would otherwise wake the sleeping islands they touch at the next
 * tick, wakes nothing. Call it once, after every body is in the scene.
 *
 * Refused: world contacts or sleeping off; a NULL array with count > 0; a
 * body that is NULL, not in this scene, marked removed, of infinite mass
 * and inertia (it cannot move, so it never sleeps), already asleep, or
 * listed twice.
 */
void scene_restore_sleep(scene_t *scene, body_t *const *bodies, const size_t *islands,
                         size_t count);

/* Islands are joined every 8th step in which some body has been slow long
 * enough to sleep: how many such steps have passed since they last were,
 * 0 to 7 (0 while world contacts are off). Set it to continue a saved
 * scene (refused: 8 or more, or world contacts off). */
unsigned scene_get_sleep_phase(scene_t *scene);
void scene_set_sleep_phase(scene_t *scene, unsigned phase);

/* The steps the contact solver has taken with world contacts on (0 while
 * they are off): their count picks whether the next step sweeps its
 * contacts in one order or in the reverse one (docs/design.md, Sweep
 * order). Set it to continue a saved scene; refused: world contacts off. */
uint64_t scene_get_solver_steps(scene_t *scene);
void scene_set_solver_steps(scene_t *scene, uint64_t steps);

/* ---- Step lengths ------------------------------------------------------------ */

/* The lengths of the last step and of the step before it (s; 0 for a step
 * not taken yet), with world contacts on (both 0 while they are off). A
 * step of another length than the last starts its contacts from their
 * force over both (docs/api.md, Step size), and one longer than the last
 * first wakes what moving bodies may reach in it. Set them to continue a
 * saved scene; refused: world contacts off, a length that is negative or
 * not finite, or a step before the last without a last. */
void scene_get_step_lengths(scene_t *scene, double *last, double *before);
void scene_set_step_lengths(scene_t *scene, double last, double before);

/* ---- Contact memory ---------------------------------------------------------- */

/*
 * One world contact of the last step as the next step reads it. The pair
 * (body_a, body_b) is ordered as the world ordered it. The points are the
 * contact's (world, m) with their feature ids, separations (m) and the
 * impulses the solver accumulated (N s): the velocity pass's normal and
 * tangent impulses, which warm-start the next step's points of the same
 * ids (or at the same place, scene_set_warm_starting), and the collision
 * pass's. The features are what the manifold was
 * found from, in the bodies' own frames: which body holds the reference
 * face (flip: body_b's), its normal and a point on it in that body's
 * frame, and the incident points in the other body's frame with their
 * ids; edge_ends when those points are the incident edge's own ends;
 * face_lead how much the reference face's separation led every other axis
 * that could have taken its place (m; INFINITY for a pair with a round
 * shape, a segment or a chain; 0 or less: reused for no step). pose
 * is body_b's centroid in body_a's frame (m) and pose_angle body_b's angle
 * less body_a's (rad), when the features were found: while the bodies stay
 * close to that, the next steps reuse the features. previous holds the
 * points of the pair's contact in the step before the last (none when it
 * had none), with their ids and velocity-pass impulses: a step of another
 * length reads them with the last step's.
 */
typedef struct {
    uint32_t id;
    vector_t point;
    double separation;
    double normal_impulse, tangent_impulse;
    double restitution_impulse, restitution_tangent_impulse;
} scene_memory_point_t;

typedef struct {
    uint32_t id;
    double normal_impulse, tangent_impulse;
} scene_memory_previous_t;

typedef struct {
    body_t *body_a, *body_b;
    /* When body_b is a chain (body.h): the segment the contact is with
     * (body_get_segment's index); 0 otherwise. A chain is never body_a. */
    size_t segment;
    vector_t normal; /* unit, from body_a toward body_b */
    int point_count; /* 0 to 2 */
    scene_memory_point_t points[2];
    bool flip, edge_ends;
    int feature_count; /* 0 to 2 */
    vector_t face_normal, face_point;
    double face_lead;
    vector_t feature_points[2];
    uint32_t feature_ids[2];
    vector_t pose;
    double pose_angle;
    int previous_count; /* 0 to 2 */
    scene_memory_previous_t previous[2];
} scene_contact_memory_t;

/* The world contacts of the last tick, as scene_contact_count's world
 * entries (0 while world contacts are off). Between ticks. */
size_t scene_contact_memory_count(scene_t *scene);
scene_contact_memory_t scene_get_contact_memory(scene_t *scene, size_t index);

/*
 * Makes memories[0 .. count) the world's contacts of the last step, in any
 * order, replacing what it had: the next tick warm-starts and reuses from
 * them as from the contacts of a step it took. Between ticks, with world
 * contacts on. Refused: a NULL array with count > 0; a body that is NULL,
 * not in this scene or marked removed; body_a == body_b; a pair listed
 * twice; a count (of points, features or previous points) outside 0 to 2;
 * a value that is not finite (but a face_lead of INFINITY); a chain as
 * body_a, a segment beyond body_b's last, a nonzero segment when body_b is
 * not a chain.
 */
void scene_restore_contact_memory(scene_t *scene, const scene_contact_memory_t *memories,
                                  size_t count);

/* ---- Joint impulses ---------------------------------------------------------- */

/* What a joint (joint.h) accumulated over the last step that solved it, and
 * the next step starts from (warm starting, scaled by the ratio of the step
 * lengths): the impulses (N s, N m s) of its point, angle, axial, spring,
 * motor and limit rows (those its type does not use stay 0) and that
 * step's length (s; 0 before any). joint_get_force and _torque read them. */
typedef struct {
    vector_t point_impulse;
    double angle_impulse, axial_impulse, spring_impulse, motor_impulse;
    double lower_impulse, upper_impulse;
    double step_length;
} joint_state_t;

joint_state_t joint_get_state(const joint_t *joint);

/* Sets them, between ticks, to continue a saved scene. Refused: a NULL
 * joint, a value that is not finite, a negative step length. */
void joint_set_state(joint_t *joint, joint_state_t state);

JOSTLE_API_END

#endif // #ifndef SCENE_STATE_H
