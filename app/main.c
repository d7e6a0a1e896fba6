/*
 * The SDL2 sandbox: drop polygons, set their elasticity, and watch the
 * collision axes and impulses the engine computes. This file holds the
 * command line and the frame loop; docs/sandbox.md is the user's guide,
 * docs/sandbox-reference.md the command line.
 */
#define SDL_MAIN_HANDLED
#include <SDL.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "core/app.h"
#include "draw/draw.h"
#include "input/input.h"
#include "scene/integrator_choice.h"
#include "core/layout.h"
#include "draw/render.h"
#include "input/script.h"
#include "core/stepper.h"
#include "panels/ui.h"
#include "tools/tools.h"
#include "draw/video.h"
#ifdef __EMSCRIPTEN__
#include "web/web.h"
#endif

typedef struct {
    bool headless;
    long frames;           /* 0: no limit (headless: until the script ends, or 1) */
    const char *screenshot;
    const char *script;
    int width, height;
    bool gpu;
    bool vsync;
    long spawn;
    double spawn_size;
    uint64_t seed;
    bool stats;
    double elasticity;
    bool overlays_given;
    bool overlays[OVERLAY_COUNT];
    integrator_t integrator;
    bool integrator_given;
    const char *scene;     /* FILE.scene to open, or NULL: the default scene */
    const char *save_dir;  /* where Ctrl+S saves */
} options_t;

static void usage(FILE *out) {
    fprintf(out,
            "Usage: ./sandbox [OPTIONS] [FILE.scene]\n"
            "A 2D rigid-body sandbox: click to drop polygons, change the elasticity,\n"
            "and watch collision axes and impulses live. Press H or F1 in the app for\n"
            "every key.\n"
            "\n"
            "FILE.scene opens a scene file (docs/scenes.md): the view frames its\n"
            "`view`, the physics steps with its timestep and integrator, and its\n"
            "game runs: Breakout and Space Invaders are played with Left/Right or\n"
            "A/D and Space (Enter pauses). Without it the default scene opens: an\n"
            "empty container. PageDown and PageUp go through the default scene and\n"
            "the samples (assets/scenes/*.scene); Ctrl+S saves the scene as it is to\n"
            "a new saved-N.scene. A file that is refused is named with its line and\n"
            "column (FILE:LINE:COLUMN: expected ..., found ...) and the exit status\n"
            "is 2.\n"
            "\n"
            "Options:\n"
            "  --headless          render offscreen (SDL's dummy video driver and a\n"
            "                      software renderer); no window, no clock: every frame\n"
            "                      is 1/60 s of display time\n"
            "  --frames N          stop after N frames (headless default: when the\n"
            "                      script ends, or 1 frame without a script)\n"
            "  --screenshot FILE   save the last frame as FILE: a PNG when FILE ends in\n"
            "                      .png, a BMP when it ends in .bmp\n"
            "  --script FILE       replay timed input from FILE (format below)\n"
            "  --size WxH          window size in pixels (default 1280x720, at least\n"
            "                      800x600)\n"
            "  --software          draw with SDL's software renderer (the default)\n"
            "  --gpu               draw with SDL's accelerated renderer instead\n"
            "  --no-vsync          do not hold the frame rate to the display's\n"
            "                      refresh rate (for measurements)\n"
            "  --spawn N           start with N bodies in a grid (benchmarks)\n"
            "  --spawn-size M      their size in metres (default 0.2)\n"
            "  --elasticity E      elasticity of new bodies, 0 to 1 (default 0.5)\n"
            "  --overlays LIST     overlays on at start: comma-separated from axes,\n"
            "                      impulses, points, velocities, centroids, bounds,\n"
            "                      sleeping (sleeping bodies dimmer), or all or none\n"
            "                      (default axes,impulses,sleeping)\n"
            "  --integrator NAME   the scene's integrator: seed (the default),\n"
            "                      explicit_euler, symplectic_euler, velocity_verlet,\n"
            "                      rk4, symplectic4, implicit_euler (any case; spaces\n"
            "                      or underscores); N and Shift+N switch it while it runs\n"
            "  --seed N            seed of the random polygons (default 1)\n"
            "  --save-dir DIR      where Ctrl+S writes saved-N.scene (default: the\n"
            "                      current directory)\n"
            "  --stats             print frame, physics and render times at exit\n"
            "  -h, --help          this help\n"
            "\n"
            "Exit status: 0 on success, 1 when SDL fails or a screenshot cannot be\n"
            "saved, 2 for a bad option, script or scene file.\n"
            "\n"
            "Example (what make check's smoke tests do):\n"
            "  printf 'click 0 6\\nwait 1s\\n' > drop.txt\n"
            "  ./sandbox --headless --script drop.txt --screenshot out.png\n"
            "\n%s\n",
            SCRIPT_HELP);
    fprintf(out, "Keys and mouse in the app (H or F1 shows them there too):\n");
    for (size_t i = 0; i < INPUT_CONTROL_COUNT; i++) {
        fprintf(out, "  %-36s  %s\n", INPUT_CONTROLS[i].keys, INPUT_CONTROLS[i].action);
    }
}

static int bad_usage(const char *format, const char *a, const char *b) {
    fprintf(stderr, "sandbox: ");
    fprintf(stderr, format, a, b);
    fprintf(stderr, "\nTry './sandbox --help'.\n");
    return 2;
}

static bool parse_long(const char *text, long min, long max, long *out) {
    char *end;
    errno = 0;
    long value = strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno == ERANGE || value < min || value > max) return false;
    *out = value;
    return true;
}

static bool parse_double(const char *text, double min, double max, double *out) {
    char *end;
    errno = 0;
    double value = strtod(text, &end);
    if (end == text || *end != '\0' || errno == ERANGE || !isfinite(value) || value < min ||
        value > max) {
        return false;
    }
    *out = value;
    return true;
}

static bool parse_overlays(const char *text, bool overlays[OVERLAY_COUNT]) {
    static const char *const names[OVERLAY_COUNT] = {
        "axes", "impulses", "points", "velocities", "centroids", "bounds", "sleeping"};
    for (int i = 0; i < OVERLAY_COUNT; i++) overlays[i] = false;
    if (strcmp(text, "none") == 0) return true;
    if (strcmp(text, "all") == 0) {
        for (int i = 0; i < OVERLAY_COUNT; i++) overlays[i] = true;
        return true;
    }
    const char *p = text;
    while (*p != '\0') {
        size_t length = strcspn(p, ",");
        bool found = false;
        for (int i = 0; i < OVERLAY_COUNT; i++) {
            if (strlen(names[i]) == length && strncmp(p, names[i], length) == 0) {
                overlays[i] = true;
                found = true;
            }
        }
        if (!found) return false;
        p += length;
        if (*p == ',') p++;
    }
    return true;
}

/* Returns -1 to go on, else the exit status. */
static int parse_options(int argc, char **argv, options_t *o) {
    *o = (options_t){.width = 1280, .height = 720, .vsync = true, .seed = 1,
                     .elasticity = 0.5, .spawn_size = 0.2};
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        bool takes_value = strcmp(arg, "--frames") == 0 || strcmp(arg, "--screenshot") == 0 ||
                           strcmp(arg, "--script") == 0 || strcmp(arg, "--size") == 0 ||
                           strcmp(arg, "--spawn") == 0 || strcmp(arg, "--spawn-size") == 0 ||
                           strcmp(arg, "--seed") == 0 || strcmp(arg, "--elasticity") == 0 ||
                           strcmp(arg, "--overlays") == 0 || strcmp(arg, "--integrator") == 0 ||
                           strcmp(arg, "--save-dir") == 0;
        const char *value = NULL;
        if (takes_value) {
            if (i + 1 >= argc || argv[i + 1][0] == '\0') {
                return bad_usage("option %s needs a value%s", arg, "");
            }
            value = argv[++i];
        }
        long number;
        if (strcmp(arg, "-h") == 0 || strcmp(arg, "--help") == 0) {
            usage(stdout);
            return 0;
        } else if (strcmp(arg, "--headless") == 0) {
            o->headless = true;
        } else if (strcmp(arg, "--software") == 0) {
            o->gpu = false;
        } else if (strcmp(arg, "--gpu") == 0) {
            o->gpu = true;
        } else if (strcmp(arg, "--no-vsync") == 0) {
            o->vsync = false;
        } else if (strcmp(arg, "--stats") == 0) {
            o->stats = true;
        } else if (strcmp(arg, "--frames") == 0) {
            if (!parse_long(value, 1, 100000000, &o->frames)) {
                return bad_usage("--frames: '%s' is not a whole number from 1 to 100000000%s",
                                 value, "");
            }
        } else if (strcmp(arg, "--screenshot") == 0) {
            if (video_format_of(value) == VIDEO_FORMAT_NONE) {
                return bad_usage("--screenshot: '%s': %s", value, VIDEO_FORMAT_HINT);
            }
            o->screenshot = value;
        } else if (strcmp(arg, "--script") == 0) {
            o->script = value;
        } else if (strcmp(arg, "--size") == 0) {
            int w, h;
            char extra;
            if (sscanf(value, "%dx%d%c", &w, &h, &extra) != 2 || w < LAYOUT_MIN_WIDTH ||
                h < LAYOUT_MIN_HEIGHT || w > 8192 || h > 8192) {
                return bad_usage("--size: '%s' is not WIDTHxHEIGHT between 800x600 and "
                                 "8192x8192%s", value, "");
            }
            o->width = w;
            o->height = h;
        } else if (strcmp(arg, "--spawn") == 0) {
            if (!parse_long(value, 0, 20000, &o->spawn)) {
                return bad_usage("--spawn: '%s' is not a whole number from 0 to 20000%s", value,
                                 "");
            }
        } else if (strcmp(arg, "--spawn-size") == 0) {
            if (!parse_double(value, SHAPE_MIN_SIZE, SHAPE_MAX_SIZE, &o->spawn_size)) {
                return bad_usage("--spawn-size: '%s' is not a size from 0.1 to 3 metres%s",
                                 value, "");
            }
        } else if (strcmp(arg, "--seed") == 0) {
            if (!parse_long(value, 0, 2147483647L, &number)) {
                return bad_usage("--seed: '%s' is not a whole number from 0 to 2147483647%s",
                                 value, "");
            }
            o->seed = (uint64_t)number;
        } else if (strcmp(arg, "--elasticity") == 0) {
            if (!parse_double(value, 0.0, APP_ELASTICITY_MAX, &o->elasticity)) {
                return bad_usage("--elasticity: '%s' is not a number from 0 to 1%s", value, "");
            }
        } else if (strcmp(arg, "--overlays") == 0) {
            if (!parse_overlays(value, o->overlays)) {
                return bad_usage("--overlays: '%s' is not a list of axes, impulses, points, "
                                 "velocities, centroids, bounds, sleeping (or all, none)%s",
                                 value, "");
            }
            o->overlays_given = true;
        } else if (strcmp(arg, "--integrator") == 0) {
            if (!integrator_choice_parse(value, &o->integrator)) {
                char names[160];
                integrator_choice_list(names, sizeof(names));
                return bad_usage("--integrator: '%s' is not an integrator; the integrators "
                                 "are %s", value, names);
            }
            o->integrator_given = true;
        } else if (strcmp(arg, "--save-dir") == 0) {
            o->save_dir = value;
        } else if (arg[0] == '-' && arg[1] != '\0') {
            return bad_usage("unknown option '%s'%s", arg, "");
        } else if (o->scene != NULL) {
            return bad_usage("one scene file at a time: '%s', then '%s'", o->scene, arg);
        } else {
            o->scene = arg;
        }
    }
    return -1;
}

static bool is_dir(const char *path) {
    struct stat info;
    return stat(path, &info) == 0 && S_ISDIR(info.st_mode);
}

/* The samples' directory: assets/scenes here; else beside the program (run
 * from elsewhere, or through a link); else where make install puts them,
 * PREFIX/share/jostle/scenes beside PREFIX/bin. NULL when there is none. */
static char *samples_dir(void) {
    static const char HERE[] = "assets/scenes";
    static const char *const BESIDE[] = {"assets/scenes", "../share/jostle/scenes"};
    if (is_dir(HERE)) return SDL_strdup(HERE);
    char *base = SDL_GetBasePath();
    if (base == NULL) return NULL;
    char *dir = NULL;
    for (size_t i = 0; i < sizeof BESIDE / sizeof BESIDE[0] && dir == NULL; i++) {
        size_t size = strlen(base) + strlen(BESIDE[i]) + 1;
        dir = SDL_malloc(size);
        if (dir == NULL) break;
        snprintf(dir, size, "%s%s", base, BESIDE[i]);
        if (!is_dir(dir)) {
            SDL_free(dir);
            dir = NULL;
        }
    }
    SDL_free(base);
    return dir;
}

static double seconds_since(Uint64 start) {
    return (double)(SDL_GetPerformanceCounter() - start) / (double)SDL_GetPerformanceFrequency();
}

/* Exponential smoothing for the frame budget's drawing time. */
static double smooth(double old, double value) {
    return old == 0.0 ? value : 0.9 * old + 0.1 * value;
}

static void print_stats(app_t *app, double wall_s) {
    const app_timing_t *t = &app->timing;
    double frames = t->frames > 0 ? (double)t->frames : 1.0;
    double steps = t->total_steps > 0 ? (double)t->total_steps : 1.0;
    printf("frames %llu  bodies %zu  steps %llu\n", (unsigned long long)t->frames,
           sandbox_totals(&app->sandbox).bodies, (unsigned long long)t->total_steps);
    printf("frame   %8.3f ms  (%.1f frames per second)\n", 1000.0 * t->total_frame_s / frames,
           t->total_frame_s > 0 ? frames / t->total_frame_s : 0.0);
    printf("physics %8.3f ms per frame  (%.3f ms per step)\n",
           1000.0 * t->total_physics_s / frames, 1000.0 * t->total_physics_s / steps);
    printf("render  %8.3f ms per frame  (overlays %.3f ms)\n", 1000.0 * t->total_render_s / frames,
           1000.0 * t->total_overlays_s / frames);
    printf("present %8.3f ms per frame\n", 1000.0 * t->total_present_s / frames);
    printf("wall    %8.3f ms per frame  (%.1f frames per second shown, waits included)\n",
           1000.0 * wall_s / frames, wall_s > 0 ? frames / wall_s : 0.0);
    /* The simulated clock against the display's: equal while the frame rate
     * holds (step_clock.h). */
    printf("clock   %.3f s simulated for %.3f s of frames (%.2f%%), %.3f s forgiven after "
           "stalls; %lu frames held to the frame budget\n",
           app->clock.simulated, app->requested_time,
           app->requested_time > 0 ? 100.0 * app->clock.simulated / app->requested_time : 0.0,
           app->clock.forgiven, app->clock.held);
}

int main(int argc, char **argv) {
    options_t o;
    int status = parse_options(argc, argv, &o);
    if (status >= 0) return status;

    script_t *script = NULL;
    if (o.script != NULL) {
        char error[512];
        script = script_load(o.script, error, sizeof(error));
        if (script == NULL) {
            fprintf(stderr, "sandbox: %s\n", error);
            return 2;
        }
    }

    /* The scene file too is checked before anything opens: a refused file
     * is named with its line and column, and the status is 2. */
    sandbox_loaded_t scene = {0};
    if (o.scene != NULL) {
        char error[600];
        if (!sandbox_load(o.scene, &scene, error, sizeof(error))) {
            fprintf(stderr, "sandbox: %s\n", error);
            script_free(script);
            return 2;
        }
    }

#ifdef __EMSCRIPTEN__
    /* A page always shows its canvas: --headless keeps the fixed clock. */
    bool windowless = false;
#else
    bool windowless = o.headless;
#endif
    if (windowless) SDL_setenv("SDL_VIDEODRIVER", "dummy", 1);
    SDL_SetMainReady();
    if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0) {
        fprintf(stderr, "sandbox: cannot start SDL: %s%s\n", SDL_GetError(),
                o.headless ? "" : " (no display? try --headless)");
        sandbox_loaded_free(&scene);
        script_free(script);
        return 1;
    }
    const char *driver = SDL_GetCurrentVideoDriver();
    if (!o.headless && driver != NULL &&
        (strcmp(driver, "offscreen") == 0 || strcmp(driver, "dummy") == 0)) {
        /* SDL found no display and fell back to drawing nowhere: a window
         * nobody can see would wait for input forever. */
        fprintf(stderr,
                "sandbox: no display to open a window on (SDL's video driver is '%s'; is "
                "DISPLAY set?). Run it on a desktop, or use --headless (see --help).\n",
                driver);
        SDL_Quit();
        sandbox_loaded_free(&scene);
        script_free(script);
        return 1;
    }
    video_t video;
#ifdef __EMSCRIPTEN__
    web_start();
#endif
    if (!video_open(&video, windowless, o.gpu, o.vsync, o.width, o.height)) {
        video_close(&video);
        SDL_Quit();
        sandbox_loaded_free(&scene);
        script_free(script);
        return 1;
    }
    int width = video.width, height = video.height;

    static app_t app; /* large (the impulse trail): not on the stack */
    char *samples = samples_dir();
    app_init(&app, width, height, o.seed, samples);
    SDL_free(samples);
    if (o.save_dir != NULL) snprintf(app.save_dir, sizeof(app.save_dir), "%s", o.save_dir);
    app.headless = o.headless;
    app_set_elasticity(&app, o.elasticity);
    /* --integrator: the scene opened now, and the default scene whenever it
     * opens again; a file otherwise steps with its own. */
    if (o.integrator_given) app.sandbox.default_integrator = o.integrator;
    if (o.scene != NULL) app_show(&app, &scene);
    if (o.integrator_given) sandbox_set_integrator(&app.sandbox, o.integrator);
    /* --overlays is what the user asked for, in a game too. */
    if (o.overlays_given) memcpy(app.overlays, o.overlays, sizeof(app.overlays));
    if (o.spawn > 0) sandbox_spawn(&app.sandbox, (size_t)o.spawn, o.spawn_size, app.elasticity);

    long frame_limit = o.frames;
    if (o.headless && frame_limit == 0 && script == NULL) frame_limit = 1;

    Uint64 previous = SDL_GetPerformanceCounter();
    Uint64 loop_start = previous;
    bool drawn = false; /* a frame is drawn and not yet shown */
    stepper_t *stepper = stepper_start(&app);
    if (stepper == NULL) {
        fprintf(stderr, "sandbox: out of memory\n");
        app_free(&app);
        video_close(&video);
        SDL_Quit();
        script_free(script);
        return 1;
    }
    status = 0;
    while (!app.quit) {
        Uint64 frame_start = SDL_GetPerformanceCounter();
        double wall_dt = (double)(frame_start - previous) / (double)SDL_GetPerformanceFrequency();
        double frame_dt = o.headless ? APP_HEADLESS_FRAME : wall_dt;
        previous = frame_start;
        if (frame_dt > 0.25) frame_dt = 0.25; /* a stall (a dragged window, a debugger) */
        if (app.timing.frames == 0 && !o.headless) frame_dt = 1.0 / 60.0;
        app.now += frame_dt;

        SDL_Event event;
        while (SDL_PollEvent(&event)) input_handle_event(&app, &event);
        bool resized = false;
        if (app.resize_width > 0) {
            resized = video_request_size(&video, app.resize_width, app.resize_height);
            app.resize_width = app.resize_height = 0;
        }
        resized = video_sync_size(&video) || resized;
        if (resized) app_resize(&app, video.width, video.height);
        SDL_Renderer *renderer = video.renderer;
        const char *shot = NULL;
        if (script != NULL) script_frame(script, &app, &shot);

        /* The physics of this frame runs on the stepper's thread while the
         * previous frame goes to the display; then this frame is drawn. */
        /* In a window, the steps that fit the display's frame beside the
         * drawing, as last measured: at 5000 bodies two steps do not, and
         * running them anyway made every frame late and owe more (a
         * spiral). Headless frames are not timed: every frame runs its
         * steps, so that a script draws the same pixels on every run. */
        app.step_budget = o.headless ? 0
                                     : step_clock_budget(1.0 / video.refresh_hz,
                                                         app.timing.render_ms / 1000.0,
                                                         app.timing.planned_step_s);
        int steps = app_plan_steps(&app, frame_dt);
        /* The stages are timed only while their chart is shown: reading the
         * clock at every stage slows a small scene's step. */
        scene_set_profiling(app.sandbox.scene, app.page == UI_PAGE_SOLVER);
        stepper_begin(stepper, steps);
        double present_s = 0.0;
        if (drawn && !resized) {
            Uint64 present_start = SDL_GetPerformanceCounter();
            video_present(&video);
            present_s = seconds_since(present_start);
        }
        double physics_s = stepper_finish(stepper);
        app_frame_done(&app, steps);
        tools_frame(&app, frame_dt, steps * app.sandbox.tick);
        /* The profile counts islands (O(n log n)): only while it is shown. */
        if (steps > 0 && app.page == UI_PAGE_SOLVER) {
            scene_profile_t profile = scene_get_profile(app.sandbox.scene);
            stage_chart_add(&app.stages, &profile);
        }

        Uint64 render_start = SDL_GetPerformanceCounter();
        body_t *hovered = input_hovered_body(&app);
        draw_set_canvas(renderer, video.canvas);
        double overlays_s = render_world(renderer, video.canvas, &app, hovered);
        ui_draw(renderer, video.canvas, &app, hovered);
        SDL_RenderFlush(renderer);
        double render_s = seconds_since(render_start);
        drawn = true;

        app.timing.frames++;
        bool last = app.quit || (frame_limit > 0 && (long)app.timing.frames >= frame_limit) ||
                    (o.headless && frame_limit == 0 && script != NULL && script_done(script));
        if (shot != NULL && !video_screenshot(&video, shot)) status = 1;
        if (last && o.screenshot != NULL && !video_screenshot(&video, o.screenshot)) status = 1;

        app_timing_t *t = &app.timing;
        double frame_s = seconds_since(frame_start);
        t->steps = steps;
        t->planned_step_s = step_clock_step_cost(t->planned_step_s, physics_s, steps);
        t->render_ms = smooth(t->render_ms, 1000.0 * render_s);
        /* The side bar's figures, from the same window of frames: this
         * frame's wall time is counted at the next one's start. */
        if (t->frames > 1) frame_meter_add(&t->meter, wall_dt, t->last_busy_s, t->last_physics_s,
                                           t->last_steps, t->last_render_s);
        t->last_busy_s = frame_s;
        t->last_physics_s = physics_s;
        t->last_render_s = render_s;
        t->last_steps = steps;
        t->total_steps += (uint64_t)steps;
        t->total_frame_s += frame_s;
        t->total_physics_s += physics_s;
        t->total_render_s += render_s;
        t->total_overlays_s += overlays_s;
        t->total_present_s += present_s;
        if (last || status != 0) break;
#ifdef __EMSCRIPTEN__
        /* A page shows a frame only when it hands it to the browser. */
        drawn = false;
        if (web_frame_due(o.headless)) {
            video_present(&video);
            web_frame_done();
        }
#else
        /* Without a display that paces us, keep to its refresh rate rather
         * than spin (a window drawn in software has none). */
        if (!o.headless && o.vsync && !video.vsync) {
            double rest = 1.0 / video.refresh_hz - seconds_since(frame_start);
            if (rest > 0.001) SDL_Delay((Uint32)(rest * 1000.0));
        }
#endif
    }
    if (o.stats) print_stats(&app, seconds_since(loop_start));
#ifdef __EMSCRIPTEN__
    /* The page keeps the last frame on show: nothing is closed. */
    video_present(&video);
    web_stopped(status);
    return status;
#endif
    stepper_stop(stepper);
    render_free();
    ui_free();
    app_free(&app);
    script_free(script);
    video_close(&video);
    SDL_Quit();
    return status;
}
