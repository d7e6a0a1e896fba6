#include "tools/joint_tool.h"
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <SDL.h>

/* Whether body is still one of the scene's and not marked removed. */
static bool still_there(scene_t *scene, body_t *body) {
    if (body == NULL || body_is_removed(body)) return false;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        if (scene_get_body(scene, i) == body) return true;
    }
    return false;
}

bool joint_tool_pick(app_t *app, vector_t *from) {
    if (app->tool != TOOL_JOINT || !still_there(app->sandbox.scene, app->joint_pick.body)) {
        app->joint_pick.body = NULL;
        return false;
    }
    *from = app->joint_pick.point;
    return true;
}

/* The topmost body (static or not) containing point, other than `except`. */
static body_t *body_at_except(scene_t *scene, vector_t point, body_t *except) {
    for (size_t i = scene_bodies(scene); i-- > 0;) {
        body_t *body = scene_get_body(scene, i);
        if (body != except && !body_is_removed(body) && body_contains_point(body, point)) {
            return body;
        }
    }
    return NULL;
}

/* The joint's bodies in the engine's order: body2 must be a body of finite
 * mass when there is one (body1 may be the world, NULL). False when both
 * ends are static or the world. */
static bool order(body_t *first, body_t *second, body_t **body1, body_t **body2,
                  bool *swapped) {
    bool first_moves = first != NULL && !sandbox_is_static(first);
    bool second_moves = second != NULL && !sandbox_is_static(second);
    if (!first_moves && !second_moves) return false;
    *swapped = !first_moves;
    *body1 = *swapped ? first : second;
    *body2 = *swapped ? second : first;
    return true;
}

static void made(app_t *app, const joint_def_t *def, const char *what) {
    joint_create(app->sandbox.scene, def);
    char words[SCENE_FILE_NAME_MAX + 8];
    sandbox_body_words(&app->sandbox, def->body2, words, sizeof words);
    if (def->body1 == NULL) {
        app_status(app, "joint: %s from %s to the world", what, words);
        return;
    }
    char other[SCENE_FILE_NAME_MAX + 8];
    sandbox_body_words(&app->sandbox, def->body1, other, sizeof other);
    app_status(app, "joint: %s from %s to %s", what, words, other);
}

/* The picked body and the body at `at` (or the world), in order (order),
 * the pick cleared; false (said) when both ends are static. */
static bool take_ends(app_t *app, vector_t at, body_t **body1, body_t **body2, bool *swapped) {
    body_t *picked = app->joint_pick.body;
    body_t *other = body_at_except(app->sandbox.scene, at, picked);
    app->joint_pick.body = NULL;
    if (order(picked, other, body1, body2, swapped)) return true;
    app_warn(app, "joint: both ends are static");
    return false;
}

/* The second click of a pin: the picked body pinned at `at` to the body
 * there, or to the world. */
static void pin(app_t *app, vector_t at) {
    body_t *body1, *body2;
    bool swapped;
    if (!take_ends(app, at, &body1, &body2, &swapped)) return;
    joint_def_t def = joint_def_revolute(body1, body2, at);
    made(app, &def, "pin");
}

drag_t joint_tool_press(app_t *app, vector_t at) {
    scene_t *scene = app->sandbox.scene;
    if (!scene_get_contacts_enabled(scene)) {
        app_warn(app, "joint: this scene runs without world contacts, which joints need");
        return DRAG_NONE;
    }
    vector_t from;
    if (app->joint_pick.pending && joint_tool_pick(app, &from)) {
        pin(app, at);
        return DRAG_NONE;
    }
    body_t *body = sandbox_any_body_at(&app->sandbox, at);
    if (body == NULL) {
        app->joint_pick.body = NULL;
        app_status(app, "joint: press on a body (click, or drag to another)");
        return DRAG_NONE;
    }
    app->joint_pick.body = body;
    app->joint_pick.point = at;
    app->joint_pick.press = app->mouse;
    app->joint_pick.pending = false;
    return DRAG_JOINT;
}

/* A drag from the picked body to `at`: a rope, a rod (Shift) or a weld
 * (Alt) to the body there, or to the world. */
static void link(app_t *app, vector_t at) {
    vector_t point = app->joint_pick.point;
    body_t *body1, *body2;
    bool swapped;
    if (!take_ends(app, at, &body1, &body2, &swapped)) return;
    if (app->mods & KMOD_ALT) {
        joint_def_t def = joint_def_weld(body1, body2, vec_multiply(0.5, vec_add(point, at)));
        made(app, &def, "weld");
        return;
    }
    vector_t p1 = swapped ? point : at, p2 = swapped ? at : point;
    joint_def_t def = joint_def_distance(body1, body2, p1, p2);
    if (!(def.length > 1e-6)) {
        app_warn(app, "joint: the two ends are at the same point");
        return;
    }
    bool rod = (app->mods & KMOD_SHIFT) != 0;
    if (!rod) def.min_length = 0.0;
    char what[48];
    snprintf(what, sizeof what, "%s of %.2f m", rod ? "rod" : "rope", def.length);
    made(app, &def, what);
}

void joint_tool_release(app_t *app, vector_t at) {
    vector_t from;
    if (!joint_tool_pick(app, &from)) return;
    vector_t moved = vec_subtract(app->mouse, app->joint_pick.press);
    if (vec_get_length(moved) < JOINT_TOOL_CLICK_PIXELS) {
        app->joint_pick.pending = true;
        char words[SCENE_FILE_NAME_MAX + 8];
        sandbox_body_words(&app->sandbox, app->joint_pick.body, words, sizeof words);
        app_status(app, "pin %s: click a point, or a second body", words);
        return;
    }
    link(app, at);
}

/* Distance (pixels) from p to the segment ab. */
static double to_segment(vector_t p, vector_t a, vector_t b) {
    vector_t ab = vec_subtract(b, a);
    double length2 = vec_dot(ab, ab);
    double t = length2 > 0.0 ? vec_dot(vec_subtract(p, a), ab) / length2 : 0.0;
    t = fmin(1.0, fmax(0.0, t));
    return vec_get_length(vec_subtract(p, vec_add(a, vec_multiply(t, ab))));
}

joint_t *joint_tool_hovered(app_t *app) {
    if (!app->mouse_inside || !app_in_view(app, app->mouse)) return NULL;
    scene_t *scene = app->sandbox.scene;
    joint_t *best = NULL;
    double nearest = JOINT_TOOL_PICK_PIXELS;
    for (size_t i = 0; i < scene_joints(scene); i++) {
        joint_t *joint = scene_get_joint(scene, i);
        if (joint_get_type(joint) == JOINT_MOUSE || joint == app->sandbox.grab.joint) continue;
        body_t *body1 = joint_get_body1(joint), *body2 = joint_get_body2(joint);
        if (body_is_removed(body2) || (body1 != NULL && body_is_removed(body1))) continue;
        vector_t a = joint_get_anchor1(joint), b = joint_get_anchor2(joint);
        if (joint_get_type(joint) == JOINT_MOTOR) {
            a = body1 != NULL ? body_get_centroid(body1) : a;
            b = body_get_centroid(body2);
        }
        double d = to_segment(app->mouse, camera_to_pixel(&app->camera, a),
                              camera_to_pixel(&app->camera, b));
        if (d <= nearest) {
            nearest = d;
            best = joint;
        }
    }
    return best;
}

bool joint_tool_delete_hovered(app_t *app) {
    joint_t *joint = joint_tool_hovered(app);
    if (joint == NULL) return false;
    const char *type = joint_type_name(joint_get_type(joint));
    joint_destroy(joint);
    app_status(app, "deleted a joint (%s)", type);
    return true;
}
