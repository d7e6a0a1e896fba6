#include "app.h"
#include <math.h>
#include "integrator_choice.h"
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* Impulses below this (N s) are not kept in the trail: resting contacts
 * carry about m g dt each step, too small to draw, and thousands of them
 * would push the impacts out. */
static const double TRAIL_MIN_IMPULSE = 0.05;

static const char *const OVERLAY_NAMES[OVERLAY_COUNT] = {
    "axes",      "impulses",       "contact points",     "velocities",
    "centroids", "bounding boxes", "dim sleeping bodies"};
static const char *const OVERLAY_KEYS[OVERLAY_COUNT] = {"A", "I", "T", "V", "M", "X", "Z"};

const char *app_overlay_name(overlay_t overlay) {
    return overlay < OVERLAY_COUNT ? OVERLAY_NAMES[overlay] : "?";
}

const char *app_overlay_key(overlay_t overlay) {
    return overlay < OVERLAY_COUNT ? OVERLAY_KEYS[overlay] : "?";
}

static void set_status(app_t *app, bool warning, const char *format, va_list args) {
    vsnprintf(app->status, sizeof(app->status), format, args);
    app->status_time = app->now;
    app->status_warning = warning;
}

void app_status(app_t *app, const char *format, ...) {
    va_list args;
    va_start(args, format);
    set_status(app, false, format, args);
    va_end(args);
}

void app_warn(app_t *app, const char *format, ...) {
    va_list args;
    va_start(args, format);
    set_status(app, true, format, args);
    va_end(args);
}

bool app_status_showing(const app_t *app) {
    return app->status[0] != '\0' && app->now - app->status_time <= APP_STATUS_SECONDS;
}

void app_toggle_overlay(app_t *app, overlay_t overlay) {
    if (overlay >= OVERLAY_COUNT) return;
    app->overlays[overlay] = !app->overlays[overlay];
    app_status(app, "%s %s", app_overlay_name(overlay), app->overlays[overlay] ? "on" : "off");
}

void app_set_elasticity(app_t *app, double elasticity) {
    if (!isfinite(elasticity)) return;
    /* Round to the slider's 0.01 so repeated steps land on round numbers. */
    app->elasticity = round(fmin(APP_ELASTICITY_MAX, fmax(0.0, elasticity)) * 100.0) / 100.0;
}

void app_new_shape(app_t *app) {
    if (app->next_vertices != NULL) list_free(app->next_vertices);
    const char *problem = NULL;
    app->next_vertices = sandbox_make_shape(&app->sandbox, app->shape, &problem);
    if (app->next_vertices == NULL) {
        app_status(app, "cannot make that shape: %s", problem);
        app->shape = (shape_choice_t){SHAPE_REGULAR, 6, 0.5};
        app->next_vertices = sandbox_make_shape(&app->sandbox, app->shape, &problem);
    }
}

void app_init(app_t *app, int width, int height, uint64_t seed) {
    memset(app, 0, sizeof(*app));
    sandbox_init(&app->sandbox, seed);
    app->layout = layout_of(width, height);
    aabb_t home = app->sandbox.extent;
    vector_t margin = {APP_VIEW_MARGIN, APP_VIEW_MARGIN};
    camera_init(&app->camera, app->layout.view.w, app->layout.view.h,
                vec_subtract(home.min, margin), vec_add(home.max, margin));
    app->shape = (shape_choice_t){SHAPE_REGULAR, 6, 0.5};
    app->elasticity = 0.5;
    app->time_scale = 1.0;
    app->impulse_scale = 0.2;
    app->overlays[OVERLAY_AXES] = true;
    app->overlays[OVERLAY_IMPULSES] = true;
    app->overlays[OVERLAY_SLEEPING] = true;
    energy_drift_init(&app->drift);
    app->totals = sandbox_totals(&app->sandbox);
    app->mouse = (vector_t){0.5 * app->layout.view.w, 0.5 * app->layout.view.h};
    app_new_shape(app);
}

void app_resize(app_t *app, int width, int height) {
    app->layout = layout_of(width, height);
    camera_resize(&app->camera, app->layout.view.w, app->layout.view.h);
}

bool app_in_view(const app_t *app, vector_t pixel) {
    return layout_contains(app->layout.view, pixel.x, pixel.y);
}

void app_free(app_t *app) {
    sandbox_free(&app->sandbox);
    if (app->next_vertices != NULL) list_free(app->next_vertices);
    app->next_vertices = NULL;
}

size_t app_collision_count(app_t *app) {
    size_t count = 0;
    scene_t *scene = app->sandbox.scene;
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        count += scene_get_contact(scene, i)->touching;
    }
    return count;
}

/* One step, and the impulses it applied into the trail. */
static void step(app_t *app) {
    sandbox_step(&app->sandbox, APP_STEP);
    if (app->overlays[OVERLAY_IMPULSES]) {
        impulse_trail_record(&app->trail, app->sandbox.scene, TRAIL_MIN_IMPULSE);
    }
}

int app_plan_steps(app_t *app, double frame_dt) {
    int steps = 0;
    if (!app->paused) {
        impulse_trail_age(&app->trail, frame_dt);
        app->requested_time += frame_dt * app->time_scale;
        steps = step_clock_advance(&app->clock, frame_dt * app->time_scale);
    }
    if (app->step_once) {
        app->step_once = false;
        impulse_trail_age(&app->trail, APP_STEP);
        app->clock.simulated += APP_STEP;
        steps++;
    }
    return steps;
}

void app_frame_done(app_t *app, int steps) {
    app->totals = sandbox_totals(&app->sandbox);
    energy_drift_sample(&app->drift, steps, app->totals.kinetic + app->totals.potential,
                        app->totals.bodies, app->sandbox.changes);
}

void app_set_integrator(app_t *app, integrator_t integrator) {
    sandbox_set_integrator(&app->sandbox, integrator);
    energy_drift_rereference(&app->drift);
    char stability[32];
    integrator_choice_stability(integrator, stability, sizeof(stability));
    app_status(app, "integrator: %s (%s)", integrator_get_name(integrator), stability);
}

void app_set_gravity(app_t *app, bool on) {
    sandbox_set_gravity(&app->sandbox, on);
    energy_drift_rereference(&app->drift);
    app_status(app, "gravity %s", on ? "on" : "off");
}

void app_run_steps(app_t *app, int steps) {
    for (int i = 0; i < steps; i++) step(app);
}
