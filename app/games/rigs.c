/*
 * The joint presets' games: their scene files make every joint; a game adds
 * only what a file cannot say. A rig has nothing to win or lose; its status
 * reports lives -1 and the scene's joints as `remaining` (the SCENE panel
 * shows "joints N").
 *
 *   car: the player's move sets the speed of every wheel joint's motor,
 *     CAR_SPEED times the move (clockwise for a move to the right); the
 *     file gives the motors their torque. Looked up each step, so a joint
 *     deleted in the sandbox leaves nothing dangling.
 *   double_pendulum: nothing but the energy plot the sandbox opens with.
 */
#include <stdlib.h>
#include "game.h"
#include "jostle/joint.h"

static const double CAR_SPEED = 8.0; /* rad/s of the wheels at full move */

typedef struct {
    scene_t *scene;
} rig_t;

static void *rig_start(scene_file_t *file, char *error, size_t size) {
    if (size > 0) error[0] = '\0';
    rig_t *rig = malloc(sizeof *rig);
    if (rig == NULL) abort();
    rig->scene = scene_file_get_scene(file);
    return rig;
}

static void rig_update(void *state, game_input_t input, double dt) {
    (void)state;
    (void)input;
    (void)dt;
}

/* The input's move to the right turns the wheels clockwise (negative). */
static void car_update(void *state, game_input_t input, double dt) {
    (void)dt;
    rig_t *rig = state;
    double speed = -CAR_SPEED * input.move;
    for (size_t i = 0; i < scene_joints(rig->scene); i++) {
        joint_t *joint = scene_get_joint(rig->scene, i);
        if (joint_get_type(joint) != JOINT_WHEEL || !joint_get_def(joint).enable_motor) continue;
        if (joint_get_motor_speed(joint) != speed) joint_set_motor_speed(joint, speed);
    }
}

static game_status_t rig_status(const void *state) {
    const rig_t *rig = state;
    return (game_status_t){GAME_PLAYING, -1, 0, (int)scene_joints(rig->scene)};
}

static void rig_free(void *state) {
    free(state); /* the joints are the scene's */
}

const game_rules_t DOUBLE_PENDULUM_RULES = {"double_pendulum", rig_start, rig_update,
                                            rig_status,        rig_free,  false, true};
const game_rules_t CAR_RULES = {"car", rig_start, car_update, rig_status, rig_free, true, false};
