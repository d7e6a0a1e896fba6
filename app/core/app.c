#include "core/app.h"
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "scene/integrator_choice.h"
#ifdef __EMSCRIPTEN__
#include "web/web.h"
#endif

/* Throws: the cursor's velocity over the last THROW_WINDOW seconds, at most
 * THROW_MAX_SPEED. */
static const double THROW_WINDOW = 0.1;
static const double THROW_MAX_SPEED = 40.0;

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

double app_default_size(double pixels_per_metre) {
    double size = APP_DEFAULT_SIZE_PIXELS / 2.0 / pixels_per_metre;
    if (!(size > 0.0) || !isfinite(size)) return SHAPE_MIN_SIZE;
    /* Two significant digits, so the status line reads "size 1.2 m". */
    double unit = pow(10.0, floor(log10(size)) - 1.0);
    size = round(size / unit) * unit;
    return fmin(SHAPE_MAX_SIZE, fmax(SHAPE_MIN_SIZE, size));
}

/* The camera, clock, drift, trail, drags and keys of a newly shown scene.
 * Another scene starts a new drift chart; the same one again (R) goes on
 * with a mark where it was reset. */
static void scene_shown(app_t *app, bool another) {
    const sandbox_t *sandbox = &app->sandbox;
    camera_init(&app->camera, app->layout.view.w, app->layout.view.h, sandbox->home.min,
                sandbox->home.max);
    step_clock_set_step(&app->clock, sandbox->step);
    if (another) energy_drift_init(&app->drift);
    energy_drift_set_step(&app->drift, sandbox->step);
    energy_drift_rereference(&app->drift);
    impulse_trail_clear(&app->trail);
    if (app->drag == DRAG_GRAB || app->drag == DRAG_PAN || app->drag == DRAG_JOINT) {
        app->drag = DRAG_NONE;
    }
    app->joint_pick.body = NULL;
    app->keys = (game_keys_t){0};
    /* A player wants the game, not the collision axes: the overlays drawn
     * over the bodies are off in a game, and back as they were after it. */
    bool game = sandbox->game != NULL;
    if (game && !app->in_game) {
        memcpy(app->overlays_before_game, app->overlays, sizeof(app->overlays));
        for (int i = 0; i < OVERLAY_COUNT; i++) {
            if (i != OVERLAY_SLEEPING) app->overlays[i] = false;
        }
    } else if (!game && app->in_game) {
        memcpy(app->overlays, app->overlays_before_game, sizeof(app->overlays));
    }
    app->in_game = game;
    app->game_status = sandbox->game != NULL ? game_status(sandbox->game) : (game_status_t){0};
    app->totals = sandbox_totals(&app->sandbox);
    if (game_plots_energy(sandbox->game)) plot_init(&app->plot, PLOT_ENERGY);
    stage_chart_init(&app->stages);
    app->scene_index = samples_find(&app->samples, sandbox->is_default ? NULL : sandbox->path);
    if (app->scene_index >= 0) app->scene_cursor = app->scene_index;
    /* Another scene has another scale: its shapes start at a size that shows. */
    if (another) {
        app->shape.size = app_default_size(app->camera.scale / app->layout.scale);
        if (app->next_vertices != NULL) app_new_shape(app);
    }
}

void app_init(app_t *app, int width, int height, uint64_t seed, const char *samples_dir) {
    memset(app, 0, sizeof(*app));
    sandbox_init(&app->sandbox, seed);
    samples_load(&app->samples, samples_dir, SANDBOX_DEFAULT_NAME, SANDBOX_DEFAULT_SCENE);
    snprintf(app->save_dir, sizeof(app->save_dir), ".");
    app->layout = layout_of(width, height);
    app->shape = (shape_choice_t){SHAPE_REGULAR, 6, 0.5};
    app->elasticity = 0.5;
    app->time_scale = 1.0;
    app->impulse_scale = 0.2;
    app->overlays[OVERLAY_AXES] = true;
    app->overlays[OVERLAY_IMPULSES] = true;
    app->overlays[OVERLAY_SLEEPING] = true;
    scene_shown(app, true);
    app->mouse = (vector_t){0.5 * app->layout.view.w, 0.5 * app->layout.view.h};
    app_new_shape(app);
}

bool app_game_mode(const app_t *app) {
    return game_takes_input(app->sandbox.game);
}

/* "14 bodies, 1 static", "1 body": the bodies that move, as the side bar
 * counts them, and the static ones apart. */
static void count_words(const sandbox_totals_t *totals, char *out, size_t size) {
    int n = snprintf(out, size, "%zu bod%s", totals->bodies, totals->bodies == 1 ? "y" : "ies");
    if (totals->statics > 0 && n > 0 && (size_t)n < size) {
        snprintf(out + n, size - (size_t)n, ", %zu static", totals->statics);
    }
}

/* "breakout: Left/Right or A/D move, Space fires" or "pyramid (55 bodies,
 * 1 static)". */
static void say_opened(app_t *app) {
    const sandbox_t *sandbox = &app->sandbox;
    if (app_game_mode(app) && strcmp(scene_file_get_game(sandbox->file), "car") == 0) {
        app_status(app, "opened %s: Left/Right or A/D drive the wheels", sandbox->name);
    } else if (app_game_mode(app)) {
        app_status(app, "opened %s: Left/Right or A/D move, Space fires", sandbox->name);
    } else if (sandbox->is_default) {
        app_status(app, "opened %s: the empty container", sandbox->name);
    } else {
        char count[48];
        count_words(&app->totals, count, sizeof(count));
        app_status(app, "opened %s (%s)", sandbox->name, count);
    }
}

void app_show(app_t *app, sandbox_loaded_t *loaded) {
    sandbox_show(&app->sandbox, loaded, false);
    scene_shown(app, true);
}

/* A refused file: the message, the file named by its name alone on screen
 * (a line holds 32 characters), the whole of it on stderr. */
static void say_refused(app_t *app, const char *error) {
    fprintf(stderr, "sandbox: %s\n", error);
    const char *shown = error;
    const char *colon = strstr(error, ": ");
    const char *slash = strrchr(error, '/');
    if (slash != NULL && (colon == NULL || slash < colon)) shown = slash + 1;
    app_warn(app, "cannot open %s", shown);
}

bool app_open(app_t *app, const char *path) {
    char error[600];
    sandbox_loaded_t loaded;
    if (!sandbox_load(path, &loaded, error, sizeof(error))) {
        say_refused(app, error);
        return false;
    }
    app_show(app, &loaded);
    say_opened(app);
    return true;
}

void app_open_sample(app_t *app, size_t index) {
    if (index >= samples_count(&app->samples)) return;
    app->scene_cursor = (int)index;
    app_open(app, samples_path(&app->samples, index));
}

void app_cycle_scene(app_t *app, int step) {
    app_open_sample(app, samples_next(&app->samples, app->scene_cursor, step));
}

void app_reset_scene(app_t *app) {
    size_t removed = sandbox_totals(&app->sandbox).bodies;
    char error[600];
    if (!sandbox_reset(&app->sandbox, error, sizeof(error))) {
        say_refused(app, error);
        return;
    }
    scene_shown(app, false);
    if (app->sandbox.game != NULL) {
        app_status(app, "reset: %s from the start", app->sandbox.name);
    } else {
        app_status(app, "reset: new scene, %zu bod%s removed, gravity %s", removed,
                   removed == 1 ? "y" : "ies", app->sandbox.gravity_on ? "on" : "off");
    }
}

/* Writes text to a new file at path; false with errno set when the file
 * exists (EEXIST) or cannot be written. */
static bool write_new_file(const char *path, const char *text, size_t length) {
    int fd = open(path, O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd < 0) return false;
    size_t done = 0;
    while (done < length) {
        ssize_t wrote = write(fd, text + done, length - done);
        if (wrote < 0) {
            if (errno == EINTR) continue;
            int saved = errno;
            close(fd);
            unlink(path);
            errno = saved;
            return false;
        }
        done += (size_t)wrote;
    }
    if (close(fd) != 0) return false;
    return true;
}

void app_save_scene(app_t *app) {
    scene_file_error_t error;
    size_t length = 0;
    char *text = scene_file_write(app->sandbox.file, &length, &error);
    if (text == NULL) {
        fprintf(stderr, "sandbox: cannot save: %s\n", error.message);
        app_warn(app, "cannot save: %s", error.message);
        return;
    }
    char path[SANDBOX_PATH_MAX + 32];
    bool saved = false;
    for (int n = 1; n <= 100000 && !saved; n++) {
        snprintf(path, sizeof(path), "%s/saved-%d.scene", app->save_dir, n);
        if (write_new_file(path, text, length)) {
            saved = true;
        } else if (errno != EEXIST) {
            fprintf(stderr, "sandbox: cannot save %s: %s\n", path, strerror(errno));
            app_warn(app, "cannot save %s: %s", path, strerror(errno));
            free(text);
            return;
        }
    }
    free(text);
    if (!saved) {
        app_warn(app, "cannot save: %s/saved-1 to -100000.scene all exist", app->save_dir);
        return;
    }
#ifdef __EMSCRIPTEN__
    web_offer_file(path); /* a page's files live in memory: the browser downloads it */
#endif
    sandbox_totals_t totals = sandbox_totals(&app->sandbox);
    char count[48];
    count_words(&totals, count, sizeof(count));
    app_status(app, "saved %s (%s)", path, count);
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
    samples_free(&app->samples);
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
    sandbox_step(&app->sandbox);
    if (app->overlays[OVERLAY_IMPULSES]) {
        impulse_trail_record(&app->trail, app->sandbox.scene, TRAIL_MIN_IMPULSE);
    }
}

/* The game's controls for this frame's steps: what the keys hold, and what
 * was pressed and let go since the last steps. */
static void plan_input(app_t *app, int steps) {
    game_keys_t *keys = &app->keys;
    double move = 0.0;
    if (keys->left || keys->left_tapped) move -= 1.0;
    if (keys->right || keys->right_tapped) move += 1.0;
    app->sandbox.input = (game_input_t){move, keys->fire || keys->fire_tapped};
    if (steps > 0 || app->paused) {
        keys->left_tapped = keys->right_tapped = keys->fire_tapped = false;
    }
}

/* Frame stepping: one step as long as the frame's simulated time, within
 * what a frame of fixed steps may run. */
static int plan_frame_step(app_t *app, double simulated) {
    double most = STEP_CLOCK_MAX_STEPS * STEP_CLOCK_STEP;
    double tick = fmin(simulated, most);
    if (!(tick > 0.0)) return 0;
    app->sandbox.tick = tick;
    app->clock.simulated += tick;
    energy_drift_set_step(&app->drift, tick);
    return 1;
}

int app_plan_steps(app_t *app, double frame_dt) {
    int steps = 0;
    double step = app->sandbox.step;
    bool frame = app->sandbox.stepping == SCENE_FILE_STEP_FRAME;
    app->sandbox.tick = step;
    energy_drift_set_step(&app->drift, step);
    if (!app->paused) {
        impulse_trail_age(&app->trail, frame_dt);
        app->requested_time += frame_dt * app->time_scale;
        steps = frame ? plan_frame_step(app, frame_dt * app->time_scale)
                      : step_clock_advance_within(&app->clock, frame_dt * app->time_scale,
                                                  app->step_budget);
    }
    if (app->step_once && steps == 0) {
        impulse_trail_age(&app->trail, step);
        app->clock.simulated += step;
        steps++;
    }
    app->step_once = false;
    plan_input(app, steps);
    return steps;
}

/* Bodies the sandbox removed for leaving the world since the last frame:
 * named on the status line. */
static void announce_removals(app_t *app) {
    unsigned long count = app->sandbox.removed.count, fresh = count - app->removals_said;
    app->removals_said = count;
    if (fresh == 1) {
        const char *who = app->sandbox.removed.last;
        if (strncmp(who, "the ", 4) == 0) who += 4;
        app_warn(app, "removed %s: %s", who, app->sandbox.removed.why);
    } else if (fresh > 1) {
        app_warn(app, "removed %lu bodies that left the world (the last: %s)", fresh,
                 app->sandbox.removed.last);
    }
}

/* A life lost, a game won or lost: on the status line. */
static void announce_game(app_t *app) {
    if (app->sandbox.game == NULL) return;
    game_status_t now = game_status(app->sandbox.game), before = app->game_status;
    app->game_status = now;
    /* The rules moved bodies (a ball served again, dropped again at the
     * top, a brick gone): the energy changed from outside the integrator,
     * and the drift starts again from here. */
    if (now.score != before.score || now.lives != before.lives ||
        now.remaining != before.remaining || now.outcome != before.outcome) {
        app->sandbox.changes++;
    }
    if (now.outcome == GAME_WON && before.outcome != GAME_WON) {
        app_status(app, "you won! score %d (R: play again)", now.score);
    } else if (now.outcome == GAME_LOST && before.outcome != GAME_LOST) {
        app_warn(app, "game over: score %d (R: play again)", now.score);
    } else if (now.outcome == GAME_PLAYING && now.lives < before.lives) {
        app_warn(app, "lost a life: %d left", now.lives);
    }
}

void app_frame_done(app_t *app, int steps) {
    size_t before = app->totals.bodies;
    app->totals = sandbox_totals(&app->sandbox);
    /* Bodies a game spawned or a collision destroyed change the energy from
     * outside the integrator too. */
    if (app->totals.bodies != before) app->sandbox.changes++;
    announce_removals(app);
    announce_game(app);
    energy_drift_sample(&app->drift, steps, app->totals.kinetic + app->totals.potential,
                        app->totals.kinetic, app->totals.bodies, app->sandbox.changes);
}

void app_set_integrator(app_t *app, integrator_t integrator) {
    sandbox_set_integrator(&app->sandbox, integrator);
    energy_drift_rereference(&app->drift);
    char stability[32];
    integrator_choice_stability(integrator, stability, sizeof(stability));
    app_status(app, "integrator: %s (%s)", integrator_get_name(integrator), stability);
}

void app_step_changed(app_t *app) {
    step_clock_set_step(&app->clock, app->sandbox.step);
    energy_drift_set_step(&app->drift, app->sandbox.step);
}

void app_set_gravity(app_t *app, bool on) {
    sandbox_set_gravity(&app->sandbox, on);
    energy_drift_rereference(&app->drift);
    app_status(app, "gravity %s", on ? "on" : "off");
}

void app_run_steps(app_t *app, int steps) {
    for (int i = 0; i < steps; i++) step(app);
}

vector_t app_throw_velocity(const app_t *app) {
    if (app->motion_count < 2) return VEC_ZERO;
    const motion_sample_t *newest = &app->motion[(app->motion_count - 1) % APP_MOTION_SAMPLES];
    if (app->now - newest->time > THROW_WINDOW) return VEC_ZERO; /* held still */
    const motion_sample_t *oldest = newest;
    size_t available = app->motion_count < APP_MOTION_SAMPLES ? app->motion_count
                                                              : APP_MOTION_SAMPLES;
    for (size_t back = 1; back < available; back++) {
        const motion_sample_t *s = &app->motion[(app->motion_count - 1 - back) % APP_MOTION_SAMPLES];
        if (newest->time - s->time > THROW_WINDOW) break;
        oldest = s;
    }
    double dt = newest->time - oldest->time;
    if (dt <= 1e-6) return VEC_ZERO;
    vector_t v = vec_multiply(1.0 / dt, vec_subtract(newest->world, oldest->world));
    double speed = vec_get_length(v);
    if (speed > THROW_MAX_SPEED) v = vec_multiply(THROW_MAX_SPEED / speed, v);
    return v;
}
