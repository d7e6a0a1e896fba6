/*
 * The joint presets' rigs: the joints a sample's bodies are joined by,
 * made at the start from the bodies the scene file names (scene files do
 * not hold joints yet), the anchors at points the bodies' placement gives.
 * A rig has nothing to win or lose; its status reports lives -1 and its
 * joints as `remaining` (the SCENE panel shows "joints N"). Only the car
 * reads the player's input: Left / Right drive its motors.
 *
 *   cradle: ball1..ball5 each hung from the static pivot1..5 by a rod (a
 *     distance joint) from the pivot's centroid to the ball's.
 *   bridge: left_post, plank1..plankN, right_post pinned end to end: plank i
 *     and plank i + 1 at the vertex they share (each plank's ends are its
 *     centroid plus or minus half its length along its angle).
 *   double_pendulum: arm1 pinned to the static pivot at the pivot's
 *     centroid, arm2 pinned to arm1 at arm1's far end.
 *   ragdoll: each limb pinned to its parent at the limb's near end, within
 *     the limits of RAGDOLL_LIMBS (radians, relative to the pose in the
 *     file).
 *   crank: the crank pinned to the static frame at its centroid, driven at
 *     CRANK_SPEED by at most CRANK_TORQUE; the rod pinned to the crank at
 *     the rod's left end and to the slider at its right end; the slider on
 *     a prismatic joint along x through its centroid.
 *   car: rear_wheel and front_wheel on wheel joints to the chassis along
 *     its vertical axis (CAR_HZ, CAR_DAMPING), both driven at CAR_SPEED
 *     times the input's move (clockwise for a move to the right) by at most
 *     CAR_TORQUE.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "game.h"
#include "jostle/joint.h"

#define RIG_MAX_JOINTS 32

static const double CRANK_SPEED = 2.0;     /* rad/s, counter-clockwise */
static const double CRANK_TORQUE = 5000.0; /* N m */
static const double CAR_SPEED = 8.0;       /* rad/s of the wheels at full move */
static const double CAR_TORQUE = 40.0;     /* N m per wheel */
static const double CAR_HZ = 4.0;
static const double CAR_DAMPING = 0.7;

typedef struct {
    scene_file_t *file;
    scene_t *scene;
    joint_t *joints[RIG_MAX_JOINTS];
    int count;
    joint_t *motors[2]; /* the car's wheels */
} rig_t;

/* The body the file calls name; NULL with a message when there is none. */
static body_t *need(rig_t *rig, const char *name, char *error, size_t size) {
    body_t *body = scene_file_find_body(rig->file, name);
    if (body == NULL && size > 0 && error[0] == '\0') {
        snprintf(error, size, "%s: the scene has no body named %s",
                 scene_file_get_game(rig->file), name);
    }
    return body;
}

/* A static body1 becomes the world itself (NULL), at the same anchor and
 * axis in world coordinates. */
static joint_t *add(rig_t *rig, const joint_def_t *given) {
    joint_def_t world = *given, *def = &world;
    body_t *ground = given->body1;
    if (ground != NULL && isinf(body_get_mass(ground))) {
        world.body1 = NULL;
        world.anchor1 = joint_world_point(ground, given->anchor1);
        world.axis = vec_rotate(given->axis, body_get_rotation(ground));
        world.reference_angle = given->reference_angle + body_get_rotation(ground);
    }
    joint_t *joint = joint_create(rig->scene, def);
    if (rig->count < RIG_MAX_JOINTS) rig->joints[rig->count++] = joint;
    return joint;
}

/* A point of a body along its own x axis, `along` metres from its centroid. */
static vector_t along_body(body_t *body, double along) {
    double angle = body_get_rotation(body);
    return vec_add(body_get_centroid(body), (vector_t){along * cos(angle), along * sin(angle)});
}

/* Half the length of a bar-like body along its own x axis: its extent in
 * its own frame. */
static double half_length(body_t *body) {
    polygon_t local = body_get_local_polygon(body);
    double high = 0.0;
    for (size_t i = 0; i < local.count; i++) high = fmax(high, fabs(local.vertices[i].x));
    return high;
}

/* Pins two bodies at a world point; a static one goes first (body2 must
 * move). */
static bool pin(rig_t *rig, body_t *body1, body_t *body2, vector_t at) {
    if (body2 == NULL) return false;
    if (isinf(body_get_mass(body2))) {
        body_t *swap = body1;
        body1 = body2;
        body2 = swap;
    }
    joint_def_t def = joint_def_revolute(body1, body2, at);
    add(rig, &def);
    return true;
}

static bool build_cradle(rig_t *rig, char *error, size_t size) {
    for (int i = 1; i <= 5; i++) {
        char pivot[24], ball[24];
        snprintf(pivot, sizeof pivot, "pivot%d", i);
        snprintf(ball, sizeof ball, "ball%d", i);
        body_t *p = need(rig, pivot, error, size), *b = need(rig, ball, error, size);
        if (p == NULL || b == NULL) return false;
        /* A rod, not a pin: a pinned ball turns with its arm, which adds
         * r^2 / 2 L^2 to its mass at the centre (3% here), and the row then
         * keeps 3% of each blow. On a rod the ball turns freely. */
        joint_def_t def =
            joint_def_distance(NULL, b, body_get_centroid(p), body_get_centroid(b));
        add(rig, &def);
    }
    return true;
}

static bool build_bridge(rig_t *rig, char *error, size_t size) {
    body_t *previous = need(rig, "left_post", error, size);
    body_t *right = need(rig, "right_post", error, size);
    body_t *first = need(rig, "plank1", error, size);
    if (previous == NULL || right == NULL || first == NULL) return false;
    vector_t end = along_body(first, -half_length(first));
    for (int i = 1;; i++) {
        char name[24];
        snprintf(name, sizeof name, "plank%d", i);
        body_t *plank = scene_file_find_body(rig->file, name);
        if (plank == NULL) break;
        pin(rig, previous, plank, end);
        end = along_body(plank, half_length(plank));
        previous = plank;
    }
    pin(rig, previous, right, end);
    return true;
}

static bool build_double_pendulum(rig_t *rig, char *error, size_t size) {
    body_t *pivot = need(rig, "pivot", error, size), *arm1 = need(rig, "arm1", error, size);
    body_t *arm2 = need(rig, "arm2", error, size);
    if (pivot == NULL || arm1 == NULL || arm2 == NULL) return false;
    pin(rig, pivot, arm1, body_get_centroid(pivot));
    pin(rig, arm1, arm2, along_body(arm1, half_length(arm1)));
    return true;
}

/* A limb pinned to its parent at the limb's end nearer the joint point
 * `end` (-1: the limb's own -x end, +1: its +x end), within [low, high]. */
typedef struct {
    const char *limb, *parent;
    int end;
    double low, high;
} limb_t;

static const limb_t RAGDOLL_LIMBS[] = {
    {"head", "torso", -1, -0.5, 0.5},
    {"upper_arm_left", "torso", -1, -2.5, 0.5},
    {"upper_arm_right", "torso", -1, -0.5, 2.5},
    {"lower_arm_left", "upper_arm_left", -1, -2.5, 0.0},
    {"lower_arm_right", "upper_arm_right", -1, 0.0, 2.5},
    {"thigh_left", "torso", -1, -1.5, 0.5},
    {"thigh_right", "torso", -1, -0.5, 1.5},
    {"shin_left", "thigh_left", -1, 0.0, 2.0},
    {"shin_right", "thigh_right", -1, -2.0, 0.0},
};

static bool build_ragdoll(rig_t *rig, char *error, size_t size) {
    for (size_t i = 0; i < sizeof RAGDOLL_LIMBS / sizeof RAGDOLL_LIMBS[0]; i++) {
        const limb_t *l = &RAGDOLL_LIMBS[i];
        body_t *limb = need(rig, l->limb, error, size), *parent = need(rig, l->parent, error, size);
        if (limb == NULL || parent == NULL) return false;
        joint_def_t def =
            joint_def_revolute(parent, limb, along_body(limb, l->end * half_length(limb)));
        def.enable_limit = true;
        def.lower_angle = l->low; /* of the angle less the reference: the pose */
        def.upper_angle = l->high;
        add(rig, &def);
    }
    return true;
}

static bool build_crank(rig_t *rig, char *error, size_t size) {
    body_t *frame = need(rig, "frame", error, size), *crank = need(rig, "crank", error, size);
    body_t *rod = need(rig, "rod", error, size), *slider = need(rig, "slider", error, size);
    if (frame == NULL || crank == NULL || rod == NULL || slider == NULL) return false;
    joint_def_t drive = joint_def_revolute(frame, crank, body_get_centroid(crank));
    drive.enable_motor = true;
    drive.motor_speed = CRANK_SPEED;
    drive.max_motor_torque = CRANK_TORQUE;
    add(rig, &drive);
    pin(rig, crank, rod, along_body(rod, -half_length(rod)));
    pin(rig, rod, slider, along_body(rod, half_length(rod)));
    joint_def_t rail =
        joint_def_prismatic(frame, slider, body_get_centroid(slider), (vector_t){1.0, 0.0});
    add(rig, &rail);
    return true;
}

static bool build_car(rig_t *rig, char *error, size_t size) {
    body_t *chassis = need(rig, "chassis", error, size);
    const char *names[2] = {"rear_wheel", "front_wheel"};
    for (int i = 0; i < 2; i++) {
        body_t *wheel = need(rig, names[i], error, size);
        if (chassis == NULL || wheel == NULL) return false;
        joint_def_t def =
            joint_def_wheel(chassis, wheel, body_get_centroid(wheel), (vector_t){0.0, 1.0});
        def.frequency = CAR_HZ;
        def.damping_ratio = CAR_DAMPING;
        def.enable_motor = true;
        def.motor_speed = 0.0;
        def.max_motor_torque = CAR_TORQUE;
        rig->motors[i] = add(rig, &def);
    }
    return true;
}

typedef bool (*build_t)(rig_t *rig, char *error, size_t size);

static void *start(scene_file_t *file, build_t build, char *error, size_t size) {
    scene_t *scene = scene_file_get_scene(file);
    if (!scene_get_contacts_enabled(scene)) {
        snprintf(error, size, "%s: joints need world contacts (contacts on)",
                 scene_file_get_game(file));
        return NULL;
    }
    rig_t *rig = calloc(1, sizeof *rig);
    if (rig == NULL) abort();
    rig->file = file;
    rig->scene = scene;
    if (size > 0) error[0] = '\0';
    if (!build(rig, error, size)) {
        /* Nothing half made stays in the scene. */
        for (int i = 0; i < rig->count; i++) joint_destroy(rig->joints[i]);
        free(rig);
        return NULL;
    }
    return rig;
}

static void *cradle_start(scene_file_t *f, char *e, size_t n) { return start(f, build_cradle, e, n); }
static void *bridge_start(scene_file_t *f, char *e, size_t n) { return start(f, build_bridge, e, n); }
static void *double_pendulum_start(scene_file_t *f, char *e, size_t n) {
    return start(f, build_double_pendulum, e, n);
}
static void *ragdoll_start(scene_file_t *f, char *e, size_t n) { return start(f, build_ragdoll, e, n); }
static void *crank_start(scene_file_t *f, char *e, size_t n) { return start(f, build_crank, e, n); }
static void *car_start(scene_file_t *f, char *e, size_t n) { return start(f, build_car, e, n); }

static void rig_update(void *state, game_input_t input, double dt) {
    (void)state;
    (void)input;
    (void)dt;
}

/* The input's move to the right turns the wheels clockwise (negative). */
static void car_update(void *state, game_input_t input, double dt) {
    (void)dt;
    rig_t *rig = state;
    for (int i = 0; i < 2; i++) {
        double speed = -CAR_SPEED * input.move;
        if (joint_get_motor_speed(rig->motors[i]) != speed) {
            joint_set_motor_speed(rig->motors[i], speed);
        }
    }
}

static game_status_t rig_status(const void *state) {
    const rig_t *rig = state;
    return (game_status_t){GAME_PLAYING, -1, 0, (int)scene_joints(rig->scene)};
}

static void rig_free(void *state) {
    free(state); /* the joints are the scene's */
}

const game_rules_t CRADLE_RULES = {"cradle", cradle_start, rig_update, rig_status, rig_free, false, false};
const game_rules_t BRIDGE_RULES = {"bridge", bridge_start, rig_update, rig_status, rig_free, false, false};
const game_rules_t DOUBLE_PENDULUM_RULES = {"double_pendulum", double_pendulum_start, rig_update,
                                            rig_status, rig_free, false, true};
const game_rules_t RAGDOLL_RULES = {"ragdoll", ragdoll_start, rig_update, rig_status, rig_free,
                                    false, false};
const game_rules_t CRANK_RULES = {"crank", crank_start, rig_update, rig_status, rig_free, false, false};
const game_rules_t CAR_RULES = {"car", car_start, car_update, rig_status, rig_free, true, false};
