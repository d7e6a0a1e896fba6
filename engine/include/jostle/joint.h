#ifndef JOINT_H
#define JOINT_H

/*
 * Joints: constraints between two bodies (or a body and a fixed point of
 * the world), solved by the world contact solver in the same velocity
 * iterations as the contacts, warm-started from the last step's impulses,
 * and, for the rigid ones, corrected in the same position iterations.
 *
 * Units: metres, kilograms, seconds, radians (counter-clockwise positive);
 * forces in newtons, torques in newton metres, frequencies in hertz.
 *
 * Anchors: a joint_def_t holds its anchors and axis in each body's own
 * frame (relative to the body's centroid, unrotated: the frame of
 * body_get_local_polygon), so they ride with the body. The joint_def_*
 * helpers below take world points instead and convert them at the bodies'
 * current poses. body1 may be NULL: the joint then holds body2 to the world,
 * and anchor1 (and the axis) are world coordinates. joint_get_anchor1 and
 * _anchor2 give both anchors in world coordinates as the bodies stand now.
 *
 * Soft joints (a distance joint's spring, a wheel's suspension, the mouse
 * joint, a soft weld) are given by a frequency (Hz, the undamped natural
 * frequency of the constraint with the bodies' effective mass) and a
 * damping ratio (1: critically damped), and solved as implicit springs over
 * the step, so their stiffness does not depend on the step or on the
 * iterations. Frequency 0 means rigid (weld) or no spring (distance, wheel).
 *
 * Ownership and life: the scene owns its joints. joint_create adds one to
 * the scene of its bodies; joint_destroy frees it at once (allowed between
 * ticks and from a force creator or collision handler). A joint is freed at
 * the end of the tick that reaps either of its bodies (scene.h's deferred
 * removal): while a body is marked removed, its joints stop acting, and
 * after that tick a joint_t pointer to them is dangling. scene_free frees
 * every joint.
 *
 * Joints act only while world contacts are on (scene_set_contacts_enabled):
 * creating one in a scene whose contacts are off stops the program; turning
 * contacts off later keeps the joints but suspends them. Two bodies a joint
 * joins make no contact with each other unless its collide_connected is
 * set (a chain: on none of its segments), and a seed collision force
 * creator between them (create_collision, ...) does not fire either; each
 * still collides with everything else its filter allows. Joined bodies sleep and wake as one
 * island.
 *
 * Programmer errors stop with "engine error in FUNCTION: ...": a NULL scene,
 * definition or body2; body1 == body2; a body in no scene, marked removed or
 * of another scene; a non-finite anchor, axis, target, angle or parameter; a
 * zero axis; a non-positive distance length or max length; min above max
 * (lengths, angles, translations); a negative frequency, damping ratio,
 * maximum force or torque.
 */

#include <stdbool.h>
#include <stddef.h>
#include "body.h"
#include "scene.h"
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

typedef struct joint joint_t;

typedef enum {
    /* A pin: anchor2 on body2 is held on anchor1 of body1; body2 turns
     * freely about it, its angle less body1's less reference_angle kept in
     * [lower_angle, upper_angle] when enable_limit, driven at motor_speed
     * (rad/s, body2 relative to body1) by at most max_motor_torque when
     * enable_motor. */
    JOINT_REVOLUTE,
    /* The distance between the anchors: rigid at `length` (a rod), kept in
     * [min_length, max_length] (a rope: min_length 0), and pulled toward
     * `length` by a spring of frequency/damping_ratio when frequency > 0
     * (the limits then bound the spring). */
    JOINT_DISTANCE,
    /* Pulls anchor2 of body2 toward `target` (world) by a soft constraint of
     * frequency/damping_ratio whose force is at most max_force: what a
     * sandbox's grab is. body1 is ignored and may be NULL. */
    JOINT_MOUSE,
    /* Holds the anchors together and the relative angle at reference_angle;
     * rigid when frequency is 0, else soft with frequency/damping_ratio
     * (both the point and the angle). */
    JOINT_WELD,
    /* A slider: anchor2 moves along `axis` (body1's frame) through anchor1,
     * the relative angle held at reference_angle; its translation (along the
     * axis, from anchor1 to anchor2) kept in [lower_translation,
     * upper_translation] when enable_limit, driven at motor_speed (m/s) by at
     * most max_motor_force when enable_motor. */
    JOINT_PRISMATIC,
    /* A wheel on a suspension: anchor2 (the wheel's centre) moves along
     * `axis` through anchor1, held toward translation 0 by a spring of
     * frequency/damping_ratio (free along the axis when frequency is 0),
     * within [lower_translation, upper_translation] when enable_limit; body2
     * turns freely, driven at motor_speed (rad/s) by at most
     * max_motor_torque when enable_motor. */
    JOINT_WHEEL,
    /* Drives body2 toward linear_offset (in body1's frame, from body1's
     * centroid to body2's) and angular_offset (body2's angle less body1's),
     * with at most max_force and max_torque; correction_factor in [0, 1] is
     * the share of the error closed per step. */
    JOINT_MOTOR,
    JOINT_TYPE_COUNT
} joint_type_t;

/* The type's name in lower case, as scene files write it ("revolute",
 * "distance", "mouse", "weld", "prismatic", "wheel", "motor"). */
const char *joint_type_name(joint_type_t type);

/* Everything a joint is made from. Fields a type does not read are
 * ignored (joint_type_t says which each reads). */
typedef struct {
    joint_type_t type;
    body_t *body1, *body2;
    vector_t anchor1, anchor2; /* body frames (body1 NULL: anchor1 in the world) */
    vector_t axis;             /* prismatic, wheel: body1's frame, any length > 0 */
    double reference_angle;    /* revolute (its limits' zero), weld, prismatic (the angle held):
                                  body2's angle less body1's */
    /* distance */
    double length, min_length, max_length;
    /* distance, wheel, mouse, weld: soft constraint (Hz, ratio) */
    double frequency, damping_ratio;
    /* revolute (rad), prismatic and wheel (m) */
    bool enable_limit;
    double lower_angle, upper_angle;
    double lower_translation, upper_translation;
    /* revolute, wheel (rad/s, N m); prismatic (m/s, N) */
    bool enable_motor;
    double motor_speed, max_motor_torque, max_motor_force;
    /* mouse: the world point to pull toward, and the largest force (N) */
    vector_t target;
    double max_force;
    /* motor joint */
    vector_t linear_offset;
    double angular_offset, max_torque, correction_factor;
    /* Whether the two bodies still collide with each other (every type;
     * default false: the world makes no contact between them). */
    bool collide_connected;
} joint_def_t;

/* A definition of the type with the defaults: bodies NULL, anchors at the
 * centroids, axis (1, 0), length 1 with min and max lengths 1 (a rod),
 * frequency 0 but 5 Hz for the mouse joint, damping ratio 0.7, limits and
 * motor off, max forces and torques 0 but the mouse and motor joints' 1000
 * N and 1000 N m, correction factor 0.3, collide_connected false. */
joint_def_t joint_def_default(joint_type_t type);

/* Definitions from world points at the bodies' current poses (body1 may be
 * NULL: the world), the rest at the defaults:
 *   revolute and weld: both anchors at `anchor`, reference angle the
 *     bodies' relative angle now;
 *   distance: a rod between anchor1 and anchor2, its length their distance
 *     now (min and max lengths the same);
 *   prismatic and wheel: both anchors at `anchor`, sliding along `axis`;
 *   mouse: anchor2 at `point` on body2, target `point`;
 *   motor: the offsets that hold the bodies as they stand. */
joint_def_t joint_def_revolute(body_t *body1, body_t *body2, vector_t anchor);
joint_def_t joint_def_weld(body_t *body1, body_t *body2, vector_t anchor);
joint_def_t joint_def_distance(body_t *body1, body_t *body2, vector_t anchor1, vector_t anchor2);
joint_def_t joint_def_prismatic(body_t *body1, body_t *body2, vector_t anchor, vector_t axis);
joint_def_t joint_def_wheel(body_t *body1, body_t *body2, vector_t anchor, vector_t axis);
joint_def_t joint_def_mouse(body_t *body2, vector_t point);
joint_def_t joint_def_motor(body_t *body1, body_t *body2);

/* A body's point between its frame (relative to its centroid, unrotated)
 * and the world, at its current pose; NULL is the world itself. */
vector_t joint_local_point(body_t *body, vector_t world_point);
vector_t joint_world_point(body_t *body, vector_t local_point);

/* Adds a joint of def to the scene of its bodies (both must be the
 * scene's; body1 may be NULL; at least one must move: two static ends,
 * the world counting as static, are refused) and wakes them. The scene
 * owns it. */
joint_t *joint_create(scene_t *scene, const joint_def_t *def);

/* Frees the joint now and wakes its bodies. */
void joint_destroy(joint_t *joint);

/* The scene's joints in the order created (destroyed and reaped ones
 * leave, the others keep their order). */
size_t scene_joints(scene_t *scene);
joint_t *scene_get_joint(scene_t *scene, size_t index);

/* The joint's definition as created, with the changes made by the setters
 * below (anchors in body frames): what a scene file writes. */
joint_def_t joint_get_def(const joint_t *joint);
joint_type_t joint_get_type(const joint_t *joint);
body_t *joint_get_body1(const joint_t *joint);
body_t *joint_get_body2(const joint_t *joint);

/* The anchors in world coordinates at the bodies' current poses. */
vector_t joint_get_anchor1(const joint_t *joint);
vector_t joint_get_anchor2(const joint_t *joint);

/* What the joint did in the last step that solved it (0 before, and
 * while suspended): the force (N, world) and torque (N m) it applied to
 * body2 (body1 got the opposite), springs, limits and motor included. A
 * game breaks a joint whose force passes a bound by destroying it. */
vector_t joint_get_force(const joint_t *joint);
double joint_get_torque(const joint_t *joint);

/* The motor's speed (rad/s, or m/s for a prismatic joint); wakes the
 * bodies. Only for joints with a motor (revolute, prismatic, wheel). */
void joint_set_motor_speed(joint_t *joint, double speed);
double joint_get_motor_speed(const joint_t *joint);
void joint_enable_motor(joint_t *joint, bool enabled);

/* The mouse joint's target (world); wakes body2. */
void joint_set_target(joint_t *joint, vector_t target);

/* body2's angle less body1's less the reference angle, and the
 * prismatic or wheel joint's translation (m, along the axis; for the
 * others, the distance between the anchors) at the bodies' current
 * poses. */
double joint_get_angle(const joint_t *joint);
double joint_get_translation(const joint_t *joint);

JOSTLE_API_END

#endif // #ifndef JOINT_H
