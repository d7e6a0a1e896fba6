#include "tools/tools.h"
#include <math.h>
#include "tools/explosion.h"

static const char *const NAMES[TOOL_COUNT] = {"drop", "explode", "inspect"};
static const char *const KEYS[TOOL_COUNT] = {"", "K", "L"};

const char *tools_name(tool_t tool) {
    return tool < TOOL_COUNT ? NAMES[tool] : "?";
}

const char *tools_key(tool_t tool) {
    return tool < TOOL_COUNT ? KEYS[tool] : "";
}

double tools_explosion_radius(const app_t *app) {
    return EXPLOSION_RADIUS_PIXELS / app->camera.scale;
}

void tools_choose(app_t *app, tool_t tool) {
    if (tool >= TOOL_COUNT) return;
    app->tool = app->tool == tool ? TOOL_DROP : tool;
    switch (app->tool) {
    case TOOL_DROP:
        app_status(app, "tool: drop (click drops the shape)");
        break;
    case TOOL_EXPLODE:
        app_status(app, "tool: explode (click: bodies within %.3g m pushed away)",
                   tools_explosion_radius(app));
        break;
    case TOOL_INSPECT:
        app_status(app, "tool: inspect (click a body; TOOLS page shows it)");
        app->page = UI_PAGE_TOOLS;
        break;
    case TOOL_COUNT:
        break;
    }
}

static void explode(app_t *app, vector_t at) {
    double radius = tools_explosion_radius(app);
    double speed = EXPLOSION_SPEED_PER_METRE * radius;
    size_t pushed = explosion_apply(app->sandbox.scene, at, radius, speed);
    app->blast.centre = at;
    app->blast.radius = radius;
    app->blast.age = 0.0;
    app->blast.shown = true;
    /* Energy came from outside the integrator: the drift starts again. */
    energy_drift_rereference(&app->drift);
    app_status(app, "explosion: %zu bod%s pushed, %.3g m/s at the centre", pushed,
               pushed == 1 ? "y" : "ies", speed);
}

static void inspect(app_t *app, vector_t at) {
    body_t *body = sandbox_any_body_at(&app->sandbox, at);
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

void tools_click(app_t *app, vector_t at) {
    if (app->tool == TOOL_EXPLODE) explode(app, at);
    else if (app->tool == TOOL_INSPECT) inspect(app, at);
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
