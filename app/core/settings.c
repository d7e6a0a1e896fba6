#include "core/settings.h"
#include <math.h>
#include <stdio.h>
#include "scene/integrator_choice.h"

/* The iterations a click goes through (any count from 1 to 1000 may come
 * from a file: a click goes to the next of these). */
static const size_t ITERATIONS[] = {1, 2, 3, 4, 5, 6, 8, 10, 12, 16, 20, 25, 32, 50, 64, 100};
#define ITERATION_STEPS (sizeof ITERATIONS / sizeof ITERATIONS[0])
/* Steps a second a click goes through (the file's own is always there too). */
static const double RATES[] = {1000, 480, 240, 120, 60, 30};
#define RATE_STEPS (sizeof RATES / sizeof RATES[0])
#define MAX_WORKERS 16

static size_t next_iterations(size_t now, int direction) {
    if (direction > 0) {
        for (size_t i = 0; i < ITERATION_STEPS; i++) {
            if (ITERATIONS[i] > now) return ITERATIONS[i];
        }
        return now;
    }
    for (size_t i = ITERATION_STEPS; i-- > 0;) {
        if (ITERATIONS[i] < now) return ITERATIONS[i];
    }
    return now;
}

static void iterations(const app_t *app, size_t *velocity, size_t *position) {
    scene_get_solver_iterations(app->sandbox.scene, velocity, position);
}

static void velocity_value(const app_t *app, char *out, size_t size) {
    size_t v, p;
    iterations(app, &v, &p);
    snprintf(out, size, "%zu", v);
}

static void position_value(const app_t *app, char *out, size_t size) {
    size_t v, p;
    iterations(app, &v, &p);
    snprintf(out, size, "%zu", p);
}

static void change_velocity(app_t *app, int direction) {
    size_t v, p;
    iterations(app, &v, &p);
    if (sandbox_set_iterations(&app->sandbox, next_iterations(v, direction), p)) {
        iterations(app, &v, &p);
        app_status(app, "velocity iterations %zu", v);
    }
}

static void change_position(app_t *app, int direction) {
    size_t v, p;
    iterations(app, &v, &p);
    if (sandbox_set_iterations(&app->sandbox, v, next_iterations(p, direction))) {
        iterations(app, &v, &p);
        app_status(app, "position iterations %zu", p);
    }
}

static void sleeping_value(const app_t *app, char *out, size_t size) {
    snprintf(out, size, "%s", app->sandbox.sleeping_on ? "on" : "off");
}

static void change_sleeping(app_t *app, int direction) {
    (void)direction;
    sandbox_set_sleeping(&app->sandbox, !app->sandbox.sleeping_on);
    app_status(app, app->sandbox.sleeping_on ? "sleeping on: bodies at rest 0.5 s sleep"
                                             : "sleeping off: every body awake");
}

static void workers_value(const app_t *app, char *out, size_t size) {
    snprintf(out, size, "%zu", scene_get_workers(app->sandbox.scene));
}

static void change_workers(app_t *app, int direction) {
    size_t now = scene_get_workers(app->sandbox.scene);
    size_t next = direction > 0 ? now + 1 : now - 1;
    if (next < 1 || next > MAX_WORKERS) return;
    if (sandbox_set_workers(&app->sandbox, next)) {
        app_status(app, "%zu worker%s (the same motion on any count)", next, next == 1 ? "" : "s");
    } else {
        app_status(app, "at most %d worker%s here", SANDBOX_MAX_WORKERS,
                   SANDBOX_MAX_WORKERS == 1 ? " (a web page runs on one thread)" : "s");
    }
}

static void warm_value(const app_t *app, char *out, size_t size) {
    snprintf(out, size, "%s", scene_get_warm_starting(app->sandbox.scene) ? "on" : "off");
}

static void change_warm(app_t *app, int direction) {
    (void)direction;
    bool on = !scene_get_warm_starting(app->sandbox.scene);
    scene_set_warm_starting(app->sandbox.scene, on);
    app_status(app, on ? "warm starting on: contacts start from their last impulses"
                       : "warm starting off: every contact starts from zero");
}

/* The next value of a list after `now` (+1) or before it (-1); `now` when
 * there is none that way. A value not in the list (from a file) goes to
 * its neighbour. */
static double next_of(const double *values, size_t count, double now, int direction) {
    if (direction > 0) {
        for (size_t i = 0; i < count; i++) {
            if (values[i] > now * (1 + 1e-9)) return values[i];
        }
        return now;
    }
    for (size_t i = count; i-- > 0;) {
        if (values[i] < now * (1 - 1e-9)) return values[i];
    }
    return now;
}

static const double THRESHOLDS[] = {0.0, 0.1, 0.25, 0.5, 1.0, 2.0, 5.0};
static const double SLEEP_SPEEDS[] = {0.001, 0.003, 0.01, 0.03, 0.1, 0.3};
/* INFINITY last: no bound on the turn (the engine's default). */
static const double SLEEP_TURNS[] = {0.01, 0.03, 0.1, 0.3, 1.0, INFINITY};
static const double SLEEP_TIMES[] = {0.1, 0.25, 0.5, 1.0, 2.0, 5.0};
#define COUNT_OF(a) (sizeof(a) / sizeof((a)[0]))

static void threshold_value(const app_t *app, char *out, size_t size) {
    snprintf(out, size, "%.3g m/s", scene_get_restitution_threshold(app->sandbox.scene));
}

static void change_threshold(app_t *app, int direction) {
    scene_t *scene = app->sandbox.scene;
    double v = next_of(THRESHOLDS, COUNT_OF(THRESHOLDS), scene_get_restitution_threshold(scene),
                       direction);
    scene_set_restitution_threshold(scene, v);
    app_status(app, "restitution threshold %.3g m/s: slower approaches do not bounce", v);
}

static void sleep_speed_value(const app_t *app, char *out, size_t size) {
    double linear, angular;
    scene_get_sleep_tolerance(app->sandbox.scene, &linear, &angular);
    snprintf(out, size, "%.3g m/s", linear);
}

static void change_sleep_speed(app_t *app, int direction) {
    double linear, angular;
    scene_get_sleep_tolerance(app->sandbox.scene, &linear, &angular);
    linear = next_of(SLEEP_SPEEDS, COUNT_OF(SLEEP_SPEEDS), linear, direction);
    scene_set_sleep_tolerance(app->sandbox.scene, linear, angular);
    app_status(app, "sleep tolerance: slow under %.3g m/s", linear);
}

static void sleep_turn_value(const app_t *app, char *out, size_t size) {
    double linear, angular;
    scene_get_sleep_tolerance(app->sandbox.scene, &linear, &angular);
    if (isinf(angular)) snprintf(out, size, "no bound");
    else snprintf(out, size, "%.3g rad/s", angular);
}

static void change_sleep_turn(app_t *app, int direction) {
    double linear, angular;
    scene_get_sleep_tolerance(app->sandbox.scene, &linear, &angular);
    angular = isinf(angular) && direction < 0
                  ? SLEEP_TURNS[COUNT_OF(SLEEP_TURNS) - 2]
                  : next_of(SLEEP_TURNS, COUNT_OF(SLEEP_TURNS), angular, direction);
    scene_set_sleep_tolerance(app->sandbox.scene, linear, angular);
    if (isinf(angular)) app_status(app, "sleep tolerance: no bound on the turn");
    else app_status(app, "sleep tolerance: slow under %.3g rad/s", angular);
}

static void sleep_time_value(const app_t *app, char *out, size_t size) {
    snprintf(out, size, "%.3g s", scene_get_sleep_time(app->sandbox.scene));
}

static void change_sleep_time(app_t *app, int direction) {
    scene_t *scene = app->sandbox.scene;
    double v = next_of(SLEEP_TIMES, COUNT_OF(SLEEP_TIMES), scene_get_sleep_time(scene), direction);
    scene_set_sleep_time(scene, v);
    app_status(app, "sleep time %.3g s: an island slow that long sleeps", v);
}

static void integrator_value(const app_t *app, char *out, size_t size) {
    snprintf(out, size, "%s", integrator_get_name(app->sandbox.integrator));
}

static void change_integrator(app_t *app, int direction) {
    app_set_integrator(app, integrator_choice_step(app->sandbox.integrator, direction));
}

static void stepping_value(const app_t *app, char *out, size_t size) {
    snprintf(out, size, "%s", app->sandbox.stepping == SCENE_FILE_STEP_FRAME ? "a frame" : "fixed");
}

static void change_stepping(app_t *app, int direction) {
    (void)direction;
    bool frame = app->sandbox.stepping != SCENE_FILE_STEP_FRAME;
    sandbox_set_stepping(&app->sandbox, frame ? SCENE_FILE_STEP_FRAME : SCENE_FILE_STEP_FIXED);
    app_status(app, frame ? "stepping: one step a frame, as long as the frame"
                          : "stepping: fixed steps of the timestep");
}

/* "1/120 s", or "0.0042 s" for a step that is no whole fraction. */
static void step_words(double step, char *out, size_t size) {
    double rate = round(1.0 / step);
    if (rate >= 1.0 && fabs(1.0 / step - rate) < 1e-9 * rate) {
        snprintf(out, size, "1/%.0f s", rate);
    } else {
        snprintf(out, size, "%.3g s", step);
    }
}

static void timestep_value(const app_t *app, char *out, size_t size) {
    step_words(app->sandbox.step, out, size);
}

/* The next longer (+1) or shorter (-1) step of RATES and the file's own. */
static double next_step(const app_t *app, int direction) {
    double now = app->sandbox.step, best = now;
    double candidates[RATE_STEPS + 1];
    for (size_t i = 0; i < RATE_STEPS; i++) candidates[i] = 1.0 / RATES[i];
    candidates[RATE_STEPS] = app->sandbox.file_step;
    for (size_t i = 0; i <= RATE_STEPS; i++) {
        double c = candidates[i];
        bool beyond = direction > 0 ? c > now * (1 + 1e-9) : c < now * (1 - 1e-9);
        bool nearer = best == now || (direction > 0 ? c < best : c > best);
        if (beyond && nearer) best = c;
    }
    return best;
}

static void change_timestep(app_t *app, int direction) {
    double step = next_step(app, direction);
    if (step == app->sandbox.step || !sandbox_set_timestep(&app->sandbox, step)) return;
    app_step_changed(app);
    char words[32];
    step_words(step, words, sizeof words);
    app_status(app, "timestep %s", words);
}

const setting_t SETTINGS[SETTING_COUNT] = {
    {"velocity iterations", velocity_value, change_velocity, false},
    {"position iterations", position_value, change_position, false},
    {"warm starting", warm_value, change_warm, true},
    {"restitution threshold", threshold_value, change_threshold, false},
    {"sleeping", sleeping_value, change_sleeping, true},
    {"sleep speed", sleep_speed_value, change_sleep_speed, false},
    {"sleep turn", sleep_turn_value, change_sleep_turn, false},
    {"sleep time", sleep_time_value, change_sleep_time, false},
    {"workers", workers_value, change_workers, false},
    {"integrator", integrator_value, change_integrator, false},
    {"stepping", stepping_value, change_stepping, true},
    {"timestep", timestep_value, change_timestep, false},
};

void settings_reset(app_t *app) {
    sandbox_t *sandbox = &app->sandbox;
    scene_reset_solver_settings(sandbox->scene);
    if (!sandbox->sleeping_on) sandbox_set_sleeping(sandbox, true);
    sandbox_set_workers(sandbox, SANDBOX_WORKERS);
    sandbox_set_stepping(sandbox, SCENE_FILE_STEP_FIXED);
    if (sandbox->step != sandbox->file_step) {
        sandbox_set_timestep(sandbox, sandbox->file_step);
        app_step_changed(app);
    }
    if (sandbox->integrator != sandbox->file_integrator) {
        sandbox_set_integrator(sandbox, sandbox->file_integrator);
        energy_drift_rereference(&app->drift);
    }
    char words[32];
    step_words(sandbox->step, words, sizeof words);
    app_status(app, "solver reset: engine defaults, sleeping on, %d worker%s, %s, fixed %s",
               SANDBOX_WORKERS, SANDBOX_WORKERS == 1 ? "" : "s",
               integrator_get_name(sandbox->integrator), words);
}
