#ifndef SANDBOX_APP_H
#define SANDBOX_APP_H

/*
 * The sandbox's state, shared by its parts: main.c runs the loop, input.c
 * turns events into changes here, render.c and ui.c draw it, script.c feeds
 * recorded events to input.c.
 */

#include <stdbool.h>
#include <stdint.h>
#include "core/camera.h"
#include "core/energy_drift.h"
#include "core/frame_meter.h"
#include "core/plot.h"
#include "core/stage_chart.h"
#include "core/impulse_trail.h"
#include "core/layout.h"
#include "scene/samples.h"
#include "scene/sandbox_scene.h"
#include "core/step_clock.h"

/* Physics runs in fixed steps of the open scene's timestep (1/120 s in the
 * default scene); step_clock.h says how frames pay for steps. */
/* The frame time in --headless mode, where no clock is read (s). */
#define APP_HEADLESS_FRAME (1.0 / 60.0)

typedef enum {
    OVERLAY_AXES = 0,
    OVERLAY_IMPULSES,
    OVERLAY_POINTS,
    OVERLAY_VELOCITIES,
    OVERLAY_CENTROIDS,
    OVERLAY_BOUNDS,
    OVERLAY_SLEEPING, /* not drawn over the bodies: sleeping bodies drawn dimmer */
    OVERLAY_COUNT
} overlay_t;

/* The pages of the side bar (F2 to F5, or a click on a tab). */
typedef enum {
    UI_PAGE_PLAY = 0, /* the simulation, the shape, overlays, integrator, scene */
    UI_PAGE_SAMPLES,  /* the samples by category, with their notes */
    UI_PAGE_SOLVER,   /* the solver's settings, live */
    UI_PAGE_TOOLS,    /* the tools, the body inspector, a plot */
    UI_PAGE_COUNT
} ui_page_t;

/* What a left click in the view does (J, U, K, L, W, or a click in the TOOLS
 * page; tools/tools.h). */
typedef enum {
    TOOL_DROP = 0, /* drop the shape (Shift: throw it) */
    TOOL_RAY,      /* drag a ray: its first hit (scene_ray_cast) */
    TOOL_BOX,      /* drag a box: the bodies overlapping it (scene_query_box) */
    TOOL_EXPLODE,  /* an explosion at the cursor (scene_explode) */
    TOOL_INSPECT,  /* choose the body the inspector shows (scene_body_at) */
    TOOL_JOINT,    /* join bodies: pins, ropes, rods, welds (tools/joint_tool.h) */
    TOOL_COUNT
} tool_t;

typedef enum {
    DRAG_NONE = 0,
    DRAG_THROW,  /* shift + left: the shape follows the cursor; release throws it */
    DRAG_GRAB,   /* right on a body: the grab spring pulls it to the cursor */
    DRAG_PAN,    /* middle anywhere, or right on empty space: moves the view */
    DRAG_SLIDER, /* left on the elasticity slider */
    DRAG_PROBE,  /* left with the ray or box tool: drawing the ray or the box */
    DRAG_JOINT,  /* left with the joint tool: from the body pressed to the cursor */
} drag_t;

#define APP_MOTION_SAMPLES 16

/* A game's keys: held now, and pressed since the last steps (a press and
 * release within one frame still moves or fires for that frame's steps). */
typedef struct {
    bool left, right, fire;
    bool left_tapped, right_tapped, fire_tapped;
} game_keys_t;

typedef struct {
    double time;     /* app clock (s) */
    vector_t world;  /* cursor (m) */
} motion_sample_t;

/* Timings for the side bar (core/frame_meter.h), for the frame budget and
 * for --stats (totals). */
typedef struct {
    frame_meter_t meter;     /* the SIMULATION panel's: one window of frames */
    double planned_step_s;   /* per step, as the frame budget plans (step_clock_step_cost) */
    double render_ms;        /* drawing the frame, smoothed, for the frame budget */
    int steps;               /* physics steps in the last frame */
    /* The last frame's, for the meter once its wall time is known. */
    double last_busy_s, last_physics_s, last_render_s;
    int last_steps;
    /* Totals since the start (for --stats). */
    uint64_t frames;
    uint64_t total_steps;
    double total_frame_s, total_physics_s, total_render_s, total_present_s;
    double total_overlays_s; /* of total_render_s: the overlays (render_world) */
} app_timing_t;

typedef struct {
    sandbox_t sandbox;
    /* The samples (the SAMPLES panel; PageDown and PageUp go through them),
     * the open scene's place in that list (-1: a file from elsewhere) and
     * the place they go on from (the last one tried, even when it was
     * refused). */
    samples_t samples;
    int scene_index;
    int scene_cursor;
    char save_dir[SANDBOX_PATH_MAX]; /* where Ctrl+S writes saved-N.scene */
    game_keys_t keys;                /* the game's controls (a game's scene only) */
    game_status_t game_status;       /* as of the last frame, to announce changes */
    unsigned long removals_said;     /* sandbox.removed.count as last announced */
    layout_t layout;  /* the view area and the side bar */
    camera_t camera;  /* the world in the view area */
    bool headless;    /* no clock: the side bar shows no wall-clock timings */

    /* What a click drops, and the elasticity of new bodies. */
    shape_choice_t shape;
    list_t *next_vertices; /* the next body's shape, centred at the origin (previewed) */
    double elasticity;

    bool overlays[OVERLAY_COUNT];
    /* The axes and impulse arrows the last frame drew, of how many there
     * were (near the cursor and the strongest or newest: draw/focus.h). */
    size_t overlay_shown[OVERLAY_COUNT], overlay_total[OVERLAY_COUNT];
    /* A game's scene opens with the overlays drawn over the bodies off; they
     * are kept here to come back when a scene without a game opens. */
    bool overlays_before_game[OVERLAY_COUNT];
    bool in_game;
    bool paused;
    bool step_once;  /* run one step at the next frame (while paused) */
    bool show_help;
    ui_page_t page;  /* the side bar's page */
    tool_t tool;     /* what a left click in the view does */
    /* The last explosion, drawn as a ring for a moment: its centre and
     * radius (m) and its age (s of display time). */
    struct {
        vector_t centre;
        double radius, age;
        bool shown;
    } blast;
    /* The ray or box drawn with the ray or box tool (world points), asked
     * again every frame while shown: the bodies move under it. */
    struct {
        vector_t from, to;
        tool_t tool; /* TOOL_RAY or TOOL_BOX */
        bool shown;
    } probe;
    /* The joint tool's first end (tools/joint_tool.h): the body pressed
     * and the world point pressed on it; after a click (no drag) it waits
     * for the second click. Let go when the scene changes. */
    struct {
        body_t *body;    /* NULL: none */
        vector_t point;  /* world (m) */
        vector_t press;  /* pixels, to tell a click from a drag */
        bool pending;    /* a click chose it: the next click pins it */
    } joint_pick;
    plot_t plot;     /* the TOOLS page's plot of one quantity */
    stage_chart_t stages; /* the SOLVER page's chart of the step's stages */
    bool quit;
    int resize_width, resize_height; /* a size the script asked for; 0: none */
    double time_scale; /* simulated seconds per displayed second, 0.1 to 1 */
    double impulse_scale; /* impulse arrow length (m) per N s, 0.2 to start */

    /* Input state. */
    double now;          /* app clock (s): real time, or frames / 60 headless */
    vector_t mouse;      /* cursor (pixels) */
    bool mouse_inside;
    uint16_t mods;       /* keyboard modifiers (SDL KMOD_*) as of the last key event */
    drag_t drag;
    vector_t drag_last;  /* pixels, for panning */
    motion_sample_t motion[APP_MOTION_SAMPLES];
    size_t motion_count; /* ring: the newest is motion[(motion_count - 1) % N] */

    impulse_trail_t trail;
    /* The bodies' totals as of the last frame's steps (app_frame_done), read
     * by the side bar, and the energy drift they feed. */
    sandbox_totals_t totals;
    energy_drift_t drift;
    app_timing_t timing;
    step_clock_t clock;
    int step_budget;       /* the most steps this frame may run; 0: no budget */
    double requested_time; /* simulated seconds the frames asked for (for --stats) */

    /* A short status line ("elasticity of body set to 0.80"), shown a while;
     * a warning (a refused drop) stands out. */
    char status[160];
    double status_time;
    bool status_warning;
} app_t;

/* How long a status line shows (s). */
#define APP_STATUS_SECONDS 2.5

/* The default scene and settings for a window of width x height pixels;
 * the samples are the default scene and the *.scene files of samples_dir
 * (NULL: none). */
void app_init(app_t *app, int width, int height, uint64_t seed, const char *samples_dir);
void app_free(app_t *app);

/* The window is now width x height pixels: the layout and the view follow. */
void app_resize(app_t *app, int width, int height);

/* Whether a window pixel is in the view area (the world), not the side bar. */
bool app_in_view(const app_t *app, vector_t pixel);

/* The physics for a frame of frame_dt seconds of display time: the step
 * clock is owed frame_dt times the time scale and gives the steps to run now
 * (step_clock.h; none while paused, but a requested single step), at most
 * step_budget of them; ages the impulse trail. Returns how many steps to
 * run. */
int app_plan_steps(app_t *app, double frame_dt);

/* Runs that many steps, recording their impulses into the trail. Touches
 * only the sandbox's scene and the trail, so it may run on another thread
 * while the main thread does anything else but those. */
void app_run_steps(app_t *app, int steps);

/* After a frame's steps (and before drawing it): the totals of the bodies,
 * measured once, and the energy drift's sample. */
void app_frame_done(app_t *app, int steps);

/* Switches the scene's integrator, says so, and has the energy drift take a
 * new reference. */
void app_set_integrator(app_t *app, integrator_t integrator);

/* The open scene's timestep changed: the clock and the drift chart follow. */
void app_step_changed(app_t *app);

/* Gravity on or off, said on the status line; the energy drift takes a new
 * reference (the potential energy changes meaning). */
void app_set_gravity(app_t *app, bool on);

/* Shows a scene sandbox_load read (in place of the open one): the view
 * frames its `view`, the clock and the energy drift take its timestep, the
 * drags, the impulse trail and the game's keys start afresh. */
void app_show(app_t *app, sandbox_loaded_t *loaded);

/* Opens a scene file (NULL: the default scene) and says so; when it is
 * refused, says why as a warning (also on stderr) and keeps the open scene.
 * Returns whether it opened. */
bool app_open(app_t *app, const char *path);

/* PageDown (+1) and PageUp (-1): the next or previous sample. */
void app_cycle_scene(app_t *app, int step);

/* Opens sample `index` of the list (a click in the SAMPLES panel). */
void app_open_sample(app_t *app, size_t index);

/* R: the open scene as it started (its file read again). */
void app_reset_scene(app_t *app);

/* Ctrl+S: writes the scene as it is now to a new file save_dir/saved-N.scene
 * (the first N free; an existing file is never replaced) and says where. */
void app_save_scene(app_t *app);

/* Whether the open scene runs a game that takes input (Breakout, Space
 * Invaders; not the pegs board): its keys then come first. */
bool app_game_mode(const app_t *app);

/* Shows a status line for a few seconds (printf-style). */
void app_status(app_t *app, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* The same, as a warning: something asked for was refused. */
void app_warn(app_t *app, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* Whether the status line is still showing. */
bool app_status_showing(const app_t *app);

/* The overlay's display name and its toggle key's label. */
const char *app_overlay_name(overlay_t overlay);
const char *app_overlay_key(overlay_t overlay);

/* Turns an overlay on or off, and says so on the status line. */
void app_toggle_overlay(app_t *app, overlay_t overlay);

/* Clamps and sets the global elasticity (new bodies). */
void app_set_elasticity(app_t *app, double elasticity);

#define APP_ELASTICITY_MAX 1.0

/* The collisions (touching contacts) of the last step. */
size_t app_collision_count(app_t *app);

/* A throw's velocity (m/s): the cursor's over the last 0.1 s of motion
 * samples (zero when it was held still), at most 40 m/s. */
vector_t app_throw_velocity(const app_t *app);

/* A new shape is about this many pixels across at the scene's default view
 * (times the UI's scale, layout.h). */
#define APP_DEFAULT_SIZE_PIXELS 40.0

/* The size (circumradius, m) of a shape APP_DEFAULT_SIZE_PIXELS across at
 * that scale (UI pixels a metre), to two significant digits, within
 * SHAPE_MIN_SIZE .. SHAPE_MAX_SIZE: each scene opens with it. */
double app_default_size(double pixels_per_metre);

/* Makes the next body's vertices for the current shape and size (a new random
 * polygon for the random shape). */
void app_new_shape(app_t *app);

#endif
