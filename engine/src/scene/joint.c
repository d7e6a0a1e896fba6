/* The public joint API (jostle/joint.h): definitions, the checks of a new
 * joint, the scene's list of them, and what a joint reports. The solving
 * is the solver's (solver/joint_solver.h). */
#include "jostle/joint.h"
#include <math.h>
#include "base/check.h"
#include "base/memory.h"
#include "dynamics/body_private.h"
#include "scene/scene_private.h"
#include "solver/joint_list.h"
#include "solver/joint_types.h"

static const char *const TYPE_NAMES[JOINT_TYPE_COUNT] = {
    "revolute", "distance", "mouse", "weld", "prismatic", "wheel", "motor",
};

const char *joint_type_name(joint_type_t type) {
    REQUIRE((unsigned)type < JOINT_TYPE_COUNT, "unknown joint type %d", (int)type);
    return TYPE_NAMES[type];
}

joint_def_t joint_def_default(joint_type_t type) {
    REQUIRE((unsigned)type < JOINT_TYPE_COUNT, "unknown joint type %d", (int)type);
    bool pulls = type == JOINT_MOUSE || type == JOINT_MOTOR;
    return (joint_def_t){
        .type = type,
        .axis = {1.0, 0.0},
        .length = 1.0,
        .min_length = 1.0,
        .max_length = 1.0,
        .frequency = type == JOINT_MOUSE ? 5.0 : 0.0,
        .damping_ratio = 0.7,
        .max_force = pulls ? 1000.0 : 0.0,
        .max_torque = pulls ? 1000.0 : 0.0,
        .correction_factor = 0.3,
    };
}

vector_t joint_local_point(body_t *body, vector_t world_point) {
    if (body == NULL) return world_point;
    return vec_rotate(vec_subtract(world_point, body->centroid), -body->angle);
}

vector_t joint_world_point(body_t *body, vector_t local_point) {
    if (body == NULL) return local_point;
    return vec_add(body->centroid, vec_rotate(local_point, body->angle));
}

static double angle_of(const body_t *body) {
    return body != NULL ? body->angle : 0.0;
}

static vector_t local_direction(const body_t *body, vector_t direction) {
    return vec_rotate(direction, -angle_of(body));
}

static joint_def_t pinned(joint_type_t type, body_t *body1, body_t *body2, vector_t anchor) {
    joint_def_t def = joint_def_default(type);
    def.body1 = body1;
    def.body2 = body2;
    if (body2 == NULL) return def; /* joint_create says what is wrong */
    def.anchor1 = joint_local_point(body1, anchor);
    def.anchor2 = joint_local_point(body2, anchor);
    def.reference_angle = angle_of(body2) - angle_of(body1);
    return def;
}

joint_def_t joint_def_revolute(body_t *body1, body_t *body2, vector_t anchor) {
    return pinned(JOINT_REVOLUTE, body1, body2, anchor);
}

joint_def_t joint_def_weld(body_t *body1, body_t *body2, vector_t anchor) {
    return pinned(JOINT_WELD, body1, body2, anchor);
}

joint_def_t joint_def_distance(body_t *body1, body_t *body2, vector_t anchor1, vector_t anchor2) {
    joint_def_t def = joint_def_default(JOINT_DISTANCE);
    def.body1 = body1;
    def.body2 = body2;
    if (body2 == NULL) return def;
    def.anchor1 = joint_local_point(body1, anchor1);
    def.anchor2 = joint_local_point(body2, anchor2);
    def.length = def.min_length = def.max_length = vec_get_length(vec_subtract(anchor2, anchor1));
    return def;
}

joint_def_t joint_def_prismatic(body_t *body1, body_t *body2, vector_t anchor, vector_t axis) {
    joint_def_t def = pinned(JOINT_PRISMATIC, body1, body2, anchor);
    def.axis = local_direction(body1, axis);
    return def;
}

joint_def_t joint_def_wheel(body_t *body1, body_t *body2, vector_t anchor, vector_t axis) {
    joint_def_t def = pinned(JOINT_WHEEL, body1, body2, anchor);
    def.axis = local_direction(body1, axis);
    def.reference_angle = 0.0;
    return def;
}

joint_def_t joint_def_mouse(body_t *body2, vector_t point) {
    joint_def_t def = pinned(JOINT_MOUSE, NULL, body2, point);
    def.reference_angle = 0.0;
    def.target = point;
    return def;
}

joint_def_t joint_def_motor(body_t *body1, body_t *body2) {
    joint_def_t def = joint_def_default(JOINT_MOTOR);
    def.body1 = body1;
    def.body2 = body2;
    if (body2 == NULL) return def;
    vector_t c1 = body1 != NULL ? body1->centroid : VEC_ZERO;
    def.linear_offset = local_direction(body1, vec_subtract(body2->centroid, c1));
    def.angular_offset = angle_of(body2) - angle_of(body1);
    return def;
}

/* The checks of joint_create's definition, which name joint_create. */
#define CREATE_REQUIRE(condition, ...)                                                       \
    do {                                                                                     \
        if (!(condition)) engine_fail("joint_create", __VA_ARGS__);                          \
    } while (0)
#define CREATE_FINITE(value)                                                                 \
    CREATE_REQUIRE(isfinite(value), "%s is not finite (%g)", #value, (double)(value))
#define CREATE_FINITE_VECTOR(v)                                                              \
    CREATE_REQUIRE(isfinite((v).x) && isfinite((v).y), "%s is not finite (%g, %g)", #v,     \
                   (v).x, (v).y)

/* A body a joint of scene may name. */
static void check_body(const scene_t *scene, const body_t *body, const char *name) {
    CREATE_REQUIRE(body->in_scene, "%s is in no scene (add it with scene_add_body first)", name);
    CREATE_REQUIRE(body->scene == scene, "%s belongs to another scene", name);
    CREATE_REQUIRE(!body->removed, "%s is marked removed", name);
}

#define REQUIRE_NOT_NEGATIVE(value)                                                         \
    CREATE_REQUIRE(isfinite(value) && (value) >= 0.0, "%s must be finite and >= 0 (got %g)", #value, \
            (double)(value))

#define REQUIRE_ORDERED(low, high)                                                           \
    CREATE_REQUIRE((low) <= (high), "%s %g is above %s %g", #low, (double)(low), #high, (double)(high))

static void check_numbers(const joint_def_t *def) {
    CREATE_FINITE_VECTOR(def->anchor1);
    CREATE_FINITE_VECTOR(def->anchor2);
    CREATE_FINITE(def->reference_angle);
    REQUIRE_NOT_NEGATIVE(def->frequency);
    REQUIRE_NOT_NEGATIVE(def->damping_ratio);
    switch (def->type) {
    case JOINT_DISTANCE:
        CREATE_REQUIRE(isfinite(def->length) && def->length > 0.0,
                "length must be finite and > 0 (got %g)", def->length);
        CREATE_REQUIRE(isfinite(def->max_length) && def->max_length > 0.0,
                "max_length must be finite and > 0 (got %g)", def->max_length);
        REQUIRE_NOT_NEGATIVE(def->min_length);
        REQUIRE_ORDERED(def->min_length, def->max_length);
        break;
    case JOINT_REVOLUTE:
        CREATE_FINITE(def->lower_angle);
        CREATE_FINITE(def->upper_angle);
        REQUIRE_ORDERED(def->lower_angle, def->upper_angle);
        break;
    case JOINT_PRISMATIC:
    case JOINT_WHEEL:
        CREATE_FINITE_VECTOR(def->axis);
        CREATE_REQUIRE(vec_get_length(def->axis) > 0.0, "axis is zero");
        CREATE_FINITE(def->lower_translation);
        CREATE_FINITE(def->upper_translation);
        REQUIRE_ORDERED(def->lower_translation, def->upper_translation);
        break;
    case JOINT_MOUSE:
        CREATE_FINITE_VECTOR(def->target);
        break;
    case JOINT_MOTOR:
        CREATE_FINITE_VECTOR(def->linear_offset);
        CREATE_FINITE(def->angular_offset);
        REQUIRE_NOT_NEGATIVE(def->max_torque);
        CREATE_REQUIRE(isfinite(def->correction_factor) && def->correction_factor >= 0.0 &&
                    def->correction_factor <= 1.0,
                "correction_factor must be in [0, 1] (got %g)", def->correction_factor);
        break;
    default:
        break;
    }
    CREATE_FINITE(def->motor_speed);
    REQUIRE_NOT_NEGATIVE(def->max_motor_torque);
    REQUIRE_NOT_NEGATIVE(def->max_motor_force);
    REQUIRE_NOT_NEGATIVE(def->max_force);
}

static void wake(const joint_t *joint) {
    if (joint->def.body1 != NULL) body_wake(joint->def.body1);
    body_wake(joint->def.body2);
}

joint_t *joint_create(scene_t *scene, const joint_def_t *def) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(def);
    REQUIRE((unsigned)def->type < JOINT_TYPE_COUNT, "unknown joint type %d", (int)def->type);
    REQUIRE(def->body2 != NULL, "body2 is NULL");
    REQUIRE(def->body1 != def->body2, "body1 and body2 are the same body");
    if (def->type != JOINT_MOUSE && def->body1 != NULL) check_body(scene, def->body1, "body1");
    check_body(scene, def->body2, "body2");
    bool fixed1 = def->type == JOINT_MOUSE || def->body1 == NULL || !body_is_movable(def->body1);
    REQUIRE(!fixed1 || body_is_movable(def->body2),
            "body1 and body2 are both static (the world counts as static): one must move");
    check_numbers(def);
    REQUIRE(scene_get_contacts_enabled(scene),
            "world contacts are off: joints are solved with them (call "
            "scene_set_contacts_enabled(scene, true) first)");
    joint_t *joint = memory_calloc(1, sizeof(joint_t));
    joint->def = *def;
    if (def->type == JOINT_MOUSE) joint->def.body1 = NULL;
    joint->scene = scene;
    joint_list_add(scene_joint_list(scene), joint);
    wake(joint);
    return joint;
}

void joint_destroy(joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    wake(joint);
    joint_list_destroy(scene_joint_list(joint->scene), joint);
}

size_t scene_joints(scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    return scene_joint_list(scene)->count;
}

joint_t *scene_get_joint(scene_t *scene, size_t index) {
    REQUIRE_NOT_NULL(scene);
    joint_list_t *list = scene_joint_list(scene);
    REQUIRE(index < list->count, "index %zu out of range (%zu joints)", index, list->count);
    return list->joints[index];
}

joint_def_t joint_get_def(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    return joint->def;
}

joint_type_t joint_get_type(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    return joint->def.type;
}

body_t *joint_get_body1(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    return joint->def.body1;
}

body_t *joint_get_body2(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    return joint->def.body2;
}

vector_t joint_get_anchor1(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    if (joint->def.type == JOINT_MOUSE) return joint->def.target;
    return joint_world_point(joint->def.body1, joint->def.anchor1);
}

vector_t joint_get_anchor2(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    return joint_world_point(joint->def.body2, joint->def.anchor2);
}

/* The impulse along each direction the type pushes (N s): along the
 * axis (or the line between the anchors) and across it. */
static vector_t linear_impulse(const joint_t *joint) {
    double limits = joint->lower_impulse - joint->upper_impulse;
    switch (joint->def.type) {
    case JOINT_DISTANCE:
        return vec_multiply(joint->axial_impulse + joint->spring_impulse + limits, joint->axis);
    case JOINT_PRISMATIC:
        return vec_add(vec_multiply(joint->motor_impulse + limits, joint->axis),
                       vec_multiply(joint->point_impulse.x, joint->perp));
    case JOINT_WHEEL:
        return vec_add(vec_multiply(joint->spring_impulse + limits, joint->axis),
                       vec_multiply(joint->point_impulse.x, joint->perp));
    default:
        return joint->point_impulse;
    }
}

static double angular_impulse(const joint_t *joint) {
    switch (joint->def.type) {
    case JOINT_REVOLUTE:
        return joint->motor_impulse + joint->lower_impulse - joint->upper_impulse;
    case JOINT_WHEEL:
        return joint->motor_impulse;
    case JOINT_WELD:
    case JOINT_PRISMATIC:
    case JOINT_MOTOR:
        return joint->angle_impulse;
    default:
        return 0.0;
    }
}

vector_t joint_get_force(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    if (joint->impulse_dt == 0.0) return VEC_ZERO;
    return vec_multiply(1.0 / joint->impulse_dt, linear_impulse(joint));
}

double joint_get_torque(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    if (joint->impulse_dt == 0.0) return 0.0;
    return angular_impulse(joint) / joint->impulse_dt;
}

static void require_motor(const joint_t *joint) {
    joint_type_t type = joint->def.type;
    REQUIRE(type == JOINT_REVOLUTE || type == JOINT_PRISMATIC || type == JOINT_WHEEL,
            "a %s joint has no motor", TYPE_NAMES[type]);
}

void joint_set_motor_speed(joint_t *joint, double speed) {
    REQUIRE_NOT_NULL(joint);
    require_motor(joint);
    REQUIRE_FINITE(speed);
    joint->def.motor_speed = speed;
    wake(joint);
}

double joint_get_motor_speed(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    return joint->def.motor_speed;
}

void joint_enable_motor(joint_t *joint, bool enabled) {
    REQUIRE_NOT_NULL(joint);
    require_motor(joint);
    joint->def.enable_motor = enabled;
    wake(joint);
}

void joint_set_target(joint_t *joint, vector_t target) {
    REQUIRE_NOT_NULL(joint);
    REQUIRE(joint->def.type == JOINT_MOUSE, "a %s joint has no target",
            TYPE_NAMES[joint->def.type]);
    REQUIRE_FINITE_VECTOR(target);
    joint->def.target = target;
    wake(joint);
}

double joint_get_angle(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    return angle_of(joint->def.body2) - angle_of(joint->def.body1) - joint->def.reference_angle;
}

double joint_get_translation(const joint_t *joint) {
    REQUIRE_NOT_NULL(joint);
    vector_t d = vec_subtract(joint_get_anchor2(joint), joint_get_anchor1(joint));
    if (joint->def.type != JOINT_PRISMATIC && joint->def.type != JOINT_WHEEL) {
        return vec_get_length(d);
    }
    vector_t axis = vec_rotate(vec_normalize(joint->def.axis), angle_of(joint->def.body1));
    return vec_dot(axis, d);
}
