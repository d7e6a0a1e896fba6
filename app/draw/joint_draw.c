#include "draw/joint_draw.h"
#include <SDL2_gfxPrimitives.h>
#include <math.h>
#include "draw/draw.h"

#define ANCHOR_PIXELS 4    /* an anchor's ring */
#define PIN_PIXELS 6       /* a revolute joint's pin */
#define LIMIT_PIXELS 22.0  /* a revolute limit's rays */
#define MOTOR_PIXELS 13.0  /* a motor's curved arrow */
#define DASH_PIXELS 6.0    /* a slack rope's dashes */
#define TICK_PIXELS 6.0    /* a slider's limit ticks, either side of the axis */

typedef struct {
    SDL_Renderer *renderer;
    const camera_t *camera;
} pen_t;

static vector_t pixel(const pen_t *pen, vector_t world) {
    return camera_to_pixel(pen->camera, world);
}

static void line(const pen_t *pen, vector_t a, vector_t b, int width, palette_rgb_t c) {
    if (!vec_is_finite(a) || !vec_is_finite(b)) return;
    if (width <= 1) {
        aalineRGBA(pen->renderer, draw_coord(a.x), draw_coord(a.y), draw_coord(b.x),
                   draw_coord(b.y), c.r, c.g, c.b, 255);
    } else {
        thickLineRGBA(pen->renderer, draw_coord(a.x), draw_coord(a.y), draw_coord(b.x),
                      draw_coord(b.y), (Uint8)width, c.r, c.g, c.b, 255);
    }
}

static void ring(const pen_t *pen, vector_t at, int radius, palette_rgb_t c) {
    if (!vec_is_finite(at)) return;
    filledCircleRGBA(pen->renderer, draw_coord(at.x), draw_coord(at.y), (Sint16)radius,
                     PALETTE_BACKGROUND.r, PALETTE_BACKGROUND.g, PALETTE_BACKGROUND.b, 255);
    aacircleRGBA(pen->renderer, draw_coord(at.x), draw_coord(at.y), (Sint16)radius, c.r, c.g,
                 c.b, 255);
}

/* Dashes from a to b (pixels). */
static void dashed(const pen_t *pen, vector_t a, vector_t b, palette_rgb_t c) {
    vector_t d = vec_subtract(b, a);
    double length = vec_get_length(d);
    if (!(length < 1e5)) return;
    for (double t = 0.0; t < length; t += 2.0 * DASH_PIXELS) {
        double end = fmin(length, t + DASH_PIXELS);
        line(pen, vec_add(a, vec_multiply(t / length, d)), vec_add(a, vec_multiply(end / length, d)),
             2, c);
    }
}

/* A world angle (rad, counter-clockwise) as a direction on screen. */
static vector_t screen_direction(double angle) {
    return (vector_t){cos(angle), -sin(angle)};
}

/* A curved arrow round `at` turning the way `speed` (rad/s, counter-
 * clockwise positive) drives: three quarters of a circle and a head. */
static void motor_arrow(const pen_t *pen, vector_t at, double speed, palette_rgb_t c) {
    if (!vec_is_finite(at) || speed == 0.0) return;
    /* SDL2_gfx's arcs go clockwise on screen, in degrees from +x. */
    arcRGBA(pen->renderer, draw_coord(at.x), draw_coord(at.y), (Sint16)MOTOR_PIXELS, 45, 315,
            c.r, c.g, c.b, 255);
    double end = (speed > 0.0 ? 45.0 : 315.0) * M_PI / 180.0;
    vector_t tip = {at.x + MOTOR_PIXELS * cos(end), at.y + MOTOR_PIXELS * sin(end)};
    /* Counter-clockwise on screen is toward smaller arc angles. */
    vector_t along = speed > 0.0 ? (vector_t){sin(end), -cos(end)} : (vector_t){-sin(end), cos(end)};
    vector_t side = vec_perpendicular(along);
    vector_t head = vec_add(tip, vec_multiply(6.0, along));
    vector_t back1 = vec_add(tip, vec_multiply(4.0, side));
    vector_t back2 = vec_subtract(tip, vec_multiply(4.0, side));
    filledTrigonRGBA(pen->renderer, draw_coord(head.x), draw_coord(head.y), draw_coord(back1.x),
                     draw_coord(back1.y), draw_coord(back2.x), draw_coord(back2.y), c.r, c.g, c.b,
                     255);
}

static double body_angle(body_t *body) {
    return body != NULL ? body_get_rotation(body) : 0.0;
}

/* The limit's two rays and the arc between them (body1's frame), and a
 * ray along body2's angle, from the pin. */
static void revolute_limit(const pen_t *pen, joint_t *joint, const joint_def_t *def,
                           vector_t pin) {
    double base = body_angle(def->body1) + def->reference_angle;
    double low = base + def->lower_angle, high = base + def->upper_angle;
    palette_rgb_t c = PALETTE_JOINT_LIMIT;
    line(pen, pin, vec_add(pin, vec_multiply(LIMIT_PIXELS, screen_direction(low))), 2, c);
    line(pen, pin, vec_add(pin, vec_multiply(LIMIT_PIXELS, screen_direction(high))), 2, c);
    if (high - low < 2.0 * M_PI) {
        double from = -high * 180.0 / M_PI, to = -low * 180.0 / M_PI;
        arcRGBA(pen->renderer, draw_coord(pin.x), draw_coord(pin.y),
                (Sint16)(0.7 * LIMIT_PIXELS), (Sint16)lround(from), (Sint16)lround(to), c.r, c.g,
                c.b, 255);
    }
    double now = base + joint_get_angle(joint);
    line(pen, pin, vec_add(pin, vec_multiply(0.8 * LIMIT_PIXELS, screen_direction(now))), 1,
         PALETTE_TEXT);
}

/* The slider's axis through anchor1: between the limits with ticks, else
 * `pad` metres past the anchors either way. */
static void slider_axis(const pen_t *pen, joint_t *joint, const joint_def_t *def,
                        palette_rgb_t c, double pad) {
    vector_t axis = vec_rotate(def->axis, body_angle(def->body1));
    double length = vec_get_length(axis);
    if (!(length > 0.0)) return;
    axis = vec_multiply(1.0 / length, axis);
    vector_t origin = joint_get_anchor1(joint);
    double low, high;
    if (def->enable_limit) {
        low = def->lower_translation;
        high = def->upper_translation;
    } else {
        double t = joint_get_translation(joint);
        low = fmin(0.0, t) - pad;
        high = fmax(0.0, t) + pad;
    }
    vector_t a = pixel(pen, vec_add(origin, vec_multiply(low, axis)));
    vector_t b = pixel(pen, vec_add(origin, vec_multiply(high, axis)));
    line(pen, a, b, 1, c);
    if (!def->enable_limit) return;
    vector_t across = vec_multiply(TICK_PIXELS, (vector_t){axis.y, axis.x});
    for (int k = 0; k < 2; k++) {
        vector_t end = k == 0 ? a : b;
        line(pen, vec_add(end, across), vec_subtract(end, across), 2, PALETTE_JOINT_LIMIT);
    }
}

static void draw_one(const pen_t *pen, joint_t *joint, bool selected) {
    joint_def_t def = joint_get_def(joint);
    palette_rgb_t c = selected ? PALETTE_ACCENT : PALETTE_JOINT;
    int width = selected ? 3 : 2;
    vector_t a1 = pixel(pen, joint_get_anchor1(joint));
    vector_t a2 = pixel(pen, joint_get_anchor2(joint));
    if (def.type == JOINT_MOUSE) {
        palette_rgb_t g = PALETTE_GRAB;
        vector_t target = pixel(pen, def.target);
        line(pen, a2, target, 1, g);
        filledCircleRGBA(pen->renderer, draw_coord(a2.x), draw_coord(a2.y), 3, g.r, g.g, g.b, 255);
        aacircleRGBA(pen->renderer, draw_coord(target.x), draw_coord(target.y), 5, g.r, g.g, g.b,
                     255);
        return;
    }
    if (def.type == JOINT_MOTOR) {
        vector_t c1 = def.body1 != NULL ? pixel(pen, body_get_centroid(def.body1)) : a1;
        line(pen, c1, pixel(pen, body_get_centroid(def.body2)), width, c);
        return;
    }
    /* What holds what: each body's centroid to its anchor. */
    if (def.body1 != NULL) line(pen, pixel(pen, body_get_centroid(def.body1)), a1, 1, c);
    line(pen, pixel(pen, body_get_centroid(def.body2)), a2, 1, c);
    switch (def.type) {
    case JOINT_REVOLUTE:
        if (def.enable_limit) revolute_limit(pen, joint, &def, a2);
        ring(pen, a2, PIN_PIXELS, c);
        if (def.enable_motor) motor_arrow(pen, a2, def.motor_speed, PALETTE_JOINT_MOTOR);
        break;
    case JOINT_DISTANCE: {
        double now = vec_get_length(vec_subtract(joint_get_anchor2(joint), joint_get_anchor1(joint)));
        bool slack = def.min_length < def.max_length && now < def.max_length - 1e-3;
        if (slack) dashed(pen, a1, a2, c);
        else line(pen, a1, a2, width, c);
        ring(pen, a1, ANCHOR_PIXELS, c);
        ring(pen, a2, ANCHOR_PIXELS, c);
        break;
    }
    case JOINT_WELD:
        line(pen, a1, a2, width, c);
        rectangleRGBA(pen->renderer, draw_coord(a2.x - 5), draw_coord(a2.y - 5),
                      draw_coord(a2.x + 5), draw_coord(a2.y + 5), c.r, c.g, c.b, 255);
        break;
    case JOINT_PRISMATIC:
        slider_axis(pen, joint, &def, c, 1.0);
        line(pen, a1, a2, width, c);
        ring(pen, a2, ANCHOR_PIXELS, c);
        if (def.enable_motor && def.motor_speed != 0.0) {
            vector_t axis = vec_rotate(def.axis, body_angle(def.body1));
            vector_t dir = {axis.x, -axis.y};
            double length = vec_get_length(dir);
            if (length > 0.0) {
                double sign = def.motor_speed > 0.0 ? 1.0 : -1.0;
                vector_t head = vec_add(a2, vec_multiply(sign * 24.0 / length, dir));
                line(pen, a2, head, 2, PALETTE_JOINT_MOTOR);
                ring(pen, head, 2, PALETTE_JOINT_MOTOR);
            }
        }
        break;
    case JOINT_WHEEL:
        /* A suspension's travel is short: a short tick either side. */
        slider_axis(pen, joint, &def, c, 0.15);
        line(pen, a1, a2, width, c);
        ring(pen, a2, ANCHOR_PIXELS, c);
        if (def.enable_motor) motor_arrow(pen, a2, def.motor_speed, PALETTE_JOINT_MOTOR);
        break;
    case JOINT_MOUSE:
    case JOINT_MOTOR:
    case JOINT_TYPE_COUNT:
        break;
    }
}

void joint_draw_all(SDL_Renderer *renderer, app_t *app, joint_t *selected) {
    pen_t pen = {renderer, &app->camera};
    scene_t *scene = app->sandbox.scene;
    for (size_t i = 0; i < scene_joints(scene); i++) {
        joint_t *joint = scene_get_joint(scene, i);
        body_t *body1 = joint_get_body1(joint);
        /* A joint of a body marked removed no longer acts (and goes with it). */
        if (body_is_removed(joint_get_body2(joint)) || (body1 != NULL && body_is_removed(body1))) {
            continue;
        }
        draw_one(&pen, joint, joint == selected);
    }
}
