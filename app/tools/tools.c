#include "tools/tools.h"
#include "tools/joint_tool.h"
#include <math.h>
#include <stdio.h>

static const char *const NAMES[TOOL_COUNT] = {"drop", "ray", "box", "explode", "inspect",
                                              "joint"};
static const char *const KEYS[TOOL_COUNT] = {"", "J", "U", "K", "L", "W"};
static const char *const WHAT[TOOL_COUNT] = {"drops a shape", "first hit", "bodies in it",
                                             "a blast", "picks a body", "pin, rope, rod"};

const char *tools_name(tool_t tool) {
    return tool < TOOL_COUNT ? NAMES[tool] : "?";
}

const char *tools_key(tool_t tool) {
    return tool < TOOL_COUNT ? KEYS[tool] : "";
}

const char *tools_what(tool_t tool) {
    return tool < TOOL_COUNT ? WHAT[tool] : "";
}

double tools_explosion_radius(const app_t *app) {
    return TOOLS_BLAST_RADIUS_PIXELS / app->camera.scale;
}

void tools_choose(app_t *app, tool_t tool) {
    if (tool >= TOOL_COUNT) return;
    app->tool = app->tool == tool ? TOOL_DROP : tool;
    app->probe.shown = false;
    app->joint_pick.body = NULL;
    switch (app->tool) {
    case TOOL_DROP:
        app_status(app, "tool: drop (click drops the shape)");
        break;
    case TOOL_RAY:
        app_status(app, "tool: ray (drag: the first body it enters)");
        break;
    case TOOL_BOX:
        app_status(app, "tool: box (drag: the bodies overlapping it)");
        break;
    case TOOL_EXPLODE:
        app_status(app, "tool: explode (click: bodies within %.3g m pushed away)",
                    tools_explosion_radius(app));
        break;
    case TOOL_INSPECT:
        app_status(app, "tool: inspect (click a body; TOOLS page shows it)");
        break;
    case TOOL_JOINT:
        app_status(app, "tool: joint (click a body then a point: pin; drag: rope, "
                        "Shift rod, Alt weld)");
        break;
    case TOOL_COUNT:
        break;
    }
    if (app->tool != TOOL_DROP) app->page = UI_PAGE_TOOLS;
}

/* The mean mass of the bodies of finite mass whose shapes the blast
 * reaches (those overlapping its circle's box, a little more than it
 * reaches); 0 when there are none. */
static double mean_mass_near(scene_t *scene, vector_t centre, double radius) {
    static body_t *near[TOOLS_BOX_MAX];
    vector_t half = {radius, radius};
    size_t n = scene_query_box(scene, vec_subtract(centre, half), vec_add(centre, half), near,
                               TOOLS_BOX_MAX);
    if (n > TOOLS_BOX_MAX) n = TOOLS_BOX_MAX;
    double total = 0.0;
    size_t counted = 0;
    for (size_t i = 0; i < n; i++) {
        double mass = body_get_mass(near[i]);
        if (isinf(mass)) continue;
        total += mass;
        counted++;
    }
    return counted > 0 ? total / (double)counted : 0.0;
}

static void explode(app_t *app, vector_t at) {
    double radius = tools_explosion_radius(app);
    double speed = TOOLS_BLAST_SPEED_PER_METRE * radius;
    double impulse = speed * mean_mass_near(app->sandbox.scene, at, radius);
    app->blast.centre = at;
    app->blast.radius = radius;
    app->blast.age = 0.0;
    app->blast.shown = true;
    if (!(impulse > 0.0)) {
        app_status(app, "explosion: no body within %.3g m", radius);
        return;
    }
    scene_explode(app->sandbox.scene, at, radius, impulse);
    /* Energy came from outside the integrator: the drift starts again. */
    energy_drift_rereference(&app->drift);
    app_status(app, "explosion: %.3g N s at the centre, none at %.3g m", impulse, radius);
}

static void inspect(app_t *app, vector_t at) {
    body_t *body = scene_body_at(app->sandbox.scene, at);
    app->sandbox.inspected = body;
    plot_init(&app->plot, app->plot.quantity);
    if (body == NULL) {
        app_status(app, "inspect: no body there");
        return;
    }
    char words[SCENE_FILE_NAME_MAX + 8];
    sandbox_body_words(&app->sandbox, body, words, sizeof words);
    app_status(app, "inspecting %s", words);
}

drag_t tools_press(app_t *app, vector_t at) {
    switch (app->tool) {
    case TOOL_RAY:
    case TOOL_BOX:
        app->probe.from = app->probe.to = at;
        app->probe.tool = app->tool;
        app->probe.shown = true;
        return DRAG_PROBE;
    case TOOL_EXPLODE:
        explode(app, at);
        break;
    case TOOL_INSPECT:
        inspect(app, at);
        break;
    case TOOL_JOINT:
        return joint_tool_press(app, at);
    case TOOL_DROP:
    case TOOL_COUNT:
        break;
    }
    return DRAG_NONE;
}

void tools_probe_move(app_t *app, vector_t at) {
    if (vec_is_finite(at)) app->probe.to = at;
}

void tools_probe_release(app_t *app, vector_t at) {
    tools_probe_move(app, at);
    char lines[TOOLS_PROBE_LINES][64];
    int n = tools_probe_words(app, lines, 60);
    if (n >= 2) app_status(app, "%s: %s", lines[0], lines[1]);
    else if (n == 1) app_status(app, "%s", lines[0]);
}

bool tools_ray_hit(app_t *app, ray_hit_t *hit) {
    if (!app->probe.shown || app->probe.tool != TOOL_RAY) return false;
    vector_t from = app->probe.from, to = app->probe.to;
    if (from.x == to.x && from.y == to.y) return false;
    return scene_ray_cast(app->sandbox.scene, from, to, hit);
}

size_t tools_box_bodies(app_t *app, body_t **bodies, size_t capacity) {
    if (!app->probe.shown || app->probe.tool != TOOL_BOX) return 0;
    vector_t a = app->probe.from, b = app->probe.to;
    vector_t min = {fmin(a.x, b.x), fmin(a.y, b.y)}, max = {fmax(a.x, b.x), fmax(a.y, b.y)};
    return scene_query_box(app->sandbox.scene, min, max, bodies, capacity);
}

/* A value printed with two decimals: one that rounds to zero as 0.00,
 * never -0.00. */
static double shown(double v) {
    return fabs(v) < 0.005 ? 0.0 : v;
}

int tools_probe_words(app_t *app, char lines[][64], size_t chars) {
    if (!app->probe.shown) return 0;
    int w = (int)(chars < 63 ? chars : 63);
    if (app->probe.tool == TOOL_BOX) {
        vector_t a = app->probe.from, b = app->probe.to;
        size_t n = tools_box_bodies(app, NULL, 0);
        snprintf(lines[0], 64, "box %.3g x %.3g m", fabs(b.x - a.x), fabs(b.y - a.y));
        snprintf(lines[1], 64, "%zu bod%s overlap it", n, n == 1 ? "y" : "ies");
        lines[0][w] = lines[1][w] = '\0';
        return 2;
    }
    ray_hit_t hit;
    if (!tools_ray_hit(app, &hit)) {
        snprintf(lines[0], 64, "ray");
        snprintf(lines[1], 64, "hits nothing");
        return 2;
    }
    char words[SCENE_FILE_NAME_MAX + 8];
    sandbox_body_words(&app->sandbox, hit.body, words, sizeof words);
    snprintf(lines[0], 64, "ray");
    snprintf(lines[1], 64, "hits %.32s at %.3f", words, hit.fraction);
    snprintf(lines[2], 64, "point (%.2f, %.2f) m", shown(hit.point.x), shown(hit.point.y));
    snprintf(lines[3], 64, "normal (%.2f, %.2f)", shown(hit.normal.x), shown(hit.normal.y));
    for (int i = 0; i < 4; i++) lines[i][w] = '\0';
    return 4;
}

void tools_next_plot(app_t *app) {
    plot_init(&app->plot, (plot_quantity_t)((app->plot.quantity + 1) % PLOT_QUANTITY_COUNT));
    app_status(app, "plot: %s", plot_quantity_name(app->plot.quantity));
}

bool tools_plot_value(app_t *app, double *value) {
    body_t *body = app->sandbox.inspected;
    const sandbox_totals_t *t = &app->totals;
    switch (app->plot.quantity) {
    case PLOT_HEIGHT:
        if (body == NULL) return false;
        *value = body_get_centroid(body).y;
        return true;
    case PLOT_SPEED:
        if (body == NULL) return false;
        *value = vec_get_length(body_get_velocity(body));
        return true;
    case PLOT_KINETIC:
        *value = t->kinetic;
        return true;
    case PLOT_ENERGY:
        *value = t->kinetic + t->potential;
        return true;
    case PLOT_MOMENTUM:
        *value = vec_get_length(t->momentum);
        return true;
    case PLOT_QUANTITY_COUNT:
        break;
    }
    return false;
}

void tools_frame(app_t *app, double display, double simulated) {
    double value = 0.0;
    bool has = tools_plot_value(app, &value);
    plot_sample(&app->plot, simulated, has, value);
    if (app->blast.shown) {
        app->blast.age += display;
        if (app->blast.age > TOOLS_BLAST_SECONDS) app->blast.shown = false;
    }
}
