/*
 * Unit tests of the sandbox's plain-C parts (no SDL): the numbers and lines
 * of the side bar (app/text.c, app/stats_text.c), the step clock
 * (app/step_clock.c), the layout (app/layout.c), the energy drift of the
 * INTEGRATOR panel (app/energy_drift.c), the integrators by name
 * (app/integrator_choice.c, against the engine), the list of scenes
 * PageDown and PageUp go through (app/scene/samples.c), the SCENE panel's words
 * (app/scene_text.c), and the sandbox's scenes from scene files
 * (app/sandbox_scene.c with the game rules, against the sanitized engine),
 * the geometry batch the renderer draws in one call (app/batch.c), the
 * outline of a round body in pixels (app/draw/round_outline.c), and the
 * state a script's `log` prints (app/scene/state_log.c).
 * Ends with "N passed, N failed" like every test program make check runs.
 * Run from the repository root (it reads assets/scenes/).
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "draw/batch.h"
#include "core/energy_drift.h"
#include "core/frame_meter.h"
#include "draw/focus.h"
#include "draw/round_outline.h"
#include "scene/integrator_choice.h"
#include "core/layout.h"
#include "draw/palette.h"
#include "scene/samples.h"
#include "scene/sample_categories.h"
#include "core/stage_chart.h"
#include "core/plot.h"
#include "scene/sandbox_scene.h"
#include "scene/state_log.h"
#include "panels/scene_text.h"
#include "panels/stats_text.h"
#include "core/step_clock.h"
#include "panels/text.h"

#include "app_expect.h"

static void expect_number(double value, int decimals, size_t width, const char *expected) {
    char out[32];
    text_number(out, sizeof(out), value, decimals, width);
    EXPECT(strcmp(out, expected) == 0, "text_number(%g, %d, %zu) gave \"%s\", expected \"%s\"",
           value, decimals, width, out, expected);
}

static void test_numbers_never_show_negative_zero(void) {
    expect_number(-0.0, 2, 9, "0.00");
    expect_number(-0.004, 2, 9, "0.00");
    expect_number(-1e-12, 1, 9, "0.0");
    expect_number(-0.006, 2, 9, "-0.01");
    expect_number(12.345, 2, 9, "12.35");
    expect_number(-3.0, 0, 9, "-3");
}

static void test_large_numbers_shorten_to_fit(void) {
    expect_number(123456.78, 2, 7, "123.46k");
    expect_number(-123456.78, 2, 7, "-123.5k");
    expect_number(98765432.1, 1, 6, "98.8M");
    expect_number(98765432.1, 2, 6, "98.77M");
    expect_number(1e30, 2, 7, "1e+30");
    char out[32];
    for (double v = 1.0; v < 1e18; v *= 7.3) {
        text_number(out, sizeof(out), -v, 2, 7);
        EXPECT(strlen(out) <= 7, "text_number(%g) gave \"%s\", over 7 characters", -v, out);
    }
}

static void test_fit_and_wrap(void) {
    char text[64] = "collisions this step 3613 (1144 near)";
    text_fit(text, 20);
    EXPECT(strlen(text) == 20 && strcmp(text + 18, "..") == 0, "text_fit gave \"%s\"", text);
    char lines[2][40];
    int n = text_wrap("elasticity of all 2000 bodies set to 0.55", 31, &lines[0][0], 40, 2);
    EXPECT(n == 2 && strcmp(lines[0], "elasticity of all 2000 bodies") == 0 &&
               strcmp(lines[1], "set to 0.55") == 0,
           "text_wrap gave %d lines: \"%s\" / \"%s\"", n, lines[0], n > 1 ? lines[1] : "");
    n = text_wrap("short", 31, &lines[0][0], 40, 2);
    EXPECT(n == 1 && strcmp(lines[0], "short") == 0, "text_wrap of one word: %d lines", n);
    /* A message longer than the lines: the last one ends in "..", also when
     * the line's buffer is exactly one line long (it used to be cut
     * without a mark). */
    char three[3][LAYOUT_LINE_CHARS + 1];
    n = text_wrap("cannot open bad.scene:2:20: expected the radius (m), a number > 0 and <= "
                  "1e+09, found \"-1\"",
                  LAYOUT_LINE_CHARS, &three[0][0], sizeof(three[0]), 3);
    EXPECT(n == 3 && strlen(three[2]) == LAYOUT_LINE_CHARS &&
               strcmp(three[2] + LAYOUT_LINE_CHARS - 2, "..") == 0,
           "a message cut after 3 lines ends \"%s\"", n == 3 ? three[2] : "");
}

/* Every line of the SIMULATION panel fits the side bar, shows its numbers
 * whole, and no "-0.00", for small and huge values alike. */
static void check_stats(const stats_values_t *values, const char *what) {
    char lines[STATS_LINES][STATS_LINE_SIZE];
    stats_text(values, lines);
    for (int i = 0; i < STATS_LINES; i++) {
        EXPECT(strlen(lines[i]) <= LAYOUT_LINE_CHARS, "%s: line %d is %zu characters: \"%s\"",
               what, i, strlen(lines[i]), lines[i]);
        EXPECT(strstr(lines[i], "..") == NULL, "%s: line %d was cut: \"%s\"", what, i,
               lines[i]);
        char *minus_zero = strstr(lines[i], "-0.00");
        EXPECT(minus_zero == NULL, "%s: line %d shows -0.00: \"%s\"", what, i, lines[i]);
    }
}

static void test_stats_lines_fit_the_side_bar(void) {
    stats_values_t resting = {.fps = 60.0, .frame_ms = 12.2, .physics_ms = 3.1,
                              .render_ms = 4.3, .steps = 2, .bodies = 3, .sleeping = 2,
                              .sleeping_on = true, .collisions = 3,
                              .near = 0, .energy = 22.2, .kinetic = 1e-9,
                              .momentum_x = -1e-9, .momentum_y = -0.004, .gravity_on = true,
                              .time_scale = 1.0};
    check_stats(&resting, "three resting bodies");
    char lines[STATS_LINES][STATS_LINE_SIZE];
    stats_text(&resting, lines);
    EXPECT(strcmp(lines[7], "momentum (0.00, 0.00) N s") == 0, "momentum line: \"%s\"",
           lines[7]);
    EXPECT(strcmp(lines[3], "bodies 3  sleeping 2") == 0, "bodies line: \"%s\"", lines[3]);
    resting.sleeping_on = false;
    stats_text(&resting, lines);
    EXPECT(strcmp(lines[3], "bodies 3  sleeping off") == 0, "bodies line with sleeping off: "
           "\"%s\"", lines[3]);
    stats_values_t pile = {.fps = 1149.6, .frame_ms = 249.99, .busy_ms = 999.99,
                           .physics_ms = 123.456,
                           .render_ms = 999.99, .steps = 4, .bodies = 20000,
                           .sleeping = 19999, .sleeping_on = true,
                           .collisions = 36130, .near = 11440, .energy = -123456789.0,
                           .kinetic = 98765432.1, .momentum_x = -123456.78,
                           .momentum_y = -98765.43, .paused = true, .time_scale = 0.1};
    check_stats(&pile, "20000 bodies");
    pile.headless = true;
    check_stats(&pile, "20000 bodies, headless");
    stats_text(&pile, lines);
    EXPECT(strstr(lines[4], "36130") && strstr(lines[4], "11440"), "collisions line: \"%s\"",
           lines[4]);
}

/* The frame rate and the frame time come from the same window of frames:
 * FPS x ms a frame = 1000 in every window, whatever the frames' busy times
 * (the panel used to show a half-second frame rate beside an exponentially
 * smoothed busy time: "51.1 FPS, frame 27.29 ms"). */
static void test_frame_times_from_one_window(void) {
    frame_meter_t meter = {0};
    /* 20 ms frames, 12 ms of them busy, a late one of 70 ms each 0.5 s. */
    for (int i = 0; i < 300; i++) {
        bool late = i % 25 == 24;
        frame_meter_add(&meter, late ? 0.070 : 0.020, late ? 0.062 : 0.012, 0.006, 2, 0.004);
        const frame_times_t *t = &meter.shown;
        EXPECT(fabs(t->fps * t->frame_ms - 1000.0) < 1e-9,
               "frame %d: %.3f FPS and %.3f ms a frame", i, t->fps, t->frame_ms);
    }
    /* The windows of 25 frames: 24 x 20 ms + 70 ms = 0.55 s. */
    EXPECT(fabs(meter.shown.fps - 25.0 / 0.55) < 1e-9, "%.4f FPS over a window", meter.shown.fps);
    EXPECT(fabs(meter.shown.busy_ms - (24 * 12.0 + 62.0) / 25.0) < 1e-9, "busy %.4f ms",
           meter.shown.busy_ms);
    EXPECT(fabs(meter.shown.physics_ms - 3.0) < 1e-9 && fabs(meter.shown.render_ms - 4.0) < 1e-9,
           "physics %.4f ms a step, drawing %.4f ms", meter.shown.physics_ms,
           meter.shown.render_ms);
    /* Before the first window is full, the frames so far. */
    frame_meter_t fresh = {0};
    frame_meter_add(&fresh, 0.010, 0.005, 0.0, 0, 0.002);
    EXPECT(fabs(fresh.shown.fps - 100.0) < 1e-9 && fabs(fresh.shown.frame_ms - 10.0) < 1e-9,
           "one frame: %.3f FPS, %.3f ms", fresh.shown.fps, fresh.shown.frame_ms);
}

/* The focus keeps the k strongest of any number offered, and the nearest
 * to the cursor within its radius; asked in increasing index order. */
static void test_overlays_focus_on_the_strongest_and_nearest(void) {
    focus_top_t top;
    focus_top_init(&top, FOCUS_STRONG);
    uint64_t x = 12345;
    double weights[5000];
    for (size_t i = 0; i < 5000; i++) {
        x = x * 6364136223846793005ULL + 1442695040888963407ULL;
        weights[i] = (double)(x >> 11) / 9007199254740992.0;
        focus_top_offer(&top, i, weights[i]);
    }
    /* The FOCUS_STRONG-th largest weight: every kept one is at least it. */
    double sorted[5000];
    memcpy(sorted, weights, sizeof sorted);
    for (size_t i = 0; i < FOCUS_STRONG; i++) {
        for (size_t j = i + 1; j < 5000; j++) {
            if (sorted[j] > sorted[i]) {
                double t = sorted[i];
                sorted[i] = sorted[j];
                sorted[j] = t;
            }
        }
    }
    double threshold = sorted[FOCUS_STRONG - 1];
    focus_top_sort(&top);
    size_t kept = 0;
    for (size_t i = 0; i < 5000; i++) {
        bool has = focus_top_has(&top, i);
        kept += has;
        EXPECT(has == (weights[i] >= threshold), "item %zu (weight %.6f) kept: %d", i,
               weights[i], has);
    }
    EXPECT(kept == FOCUS_STRONG, "%zu kept of 5000", kept);
    /* Near: within the radius only, the nearest first. */
    focus_top_t near;
    focus_top_init(&near, 3);
    vector_t cursor = {100, 100};
    const vector_t points[] = {{100, 150}, {100, 210}, {100, 101}, {300, 100}, {130, 100},
                               {100, 60}};
    for (size_t i = 0; i < 6; i++) focus_near_offer(&near, i, points[i], true, cursor);
    focus_top_sort(&near);
    bool expected[6] = {false, false, true, false, true, true};
    for (size_t i = 0; i < 6; i++) {
        EXPECT(focus_top_has(&near, i) == expected[i], "point %zu near: %d", i, !expected[i]);
    }
    focus_top_init(&near, 3);
    focus_near_offer(&near, 0, cursor, false, cursor);
    EXPECT(near.count == 0, "kept a point with no cursor over the view");
}

/* 11 minutes at 60 frames per second where one frame a second is late
 * (50 ms) and the others make up for it: the frame rate holds, and the
 * simulated clock must keep real time (the old rule dropped the owed steps
 * at each late frame: 1.7% slow). */
static void test_clock_keeps_real_time_through_late_frames(void) {
    step_clock_t clock = {0};
    double requested = 0.0;
    const double late = 0.050, usual = (1.0 - late) / 59.0;
    for (int frame = 0; frame < 60 * 660; frame++) {
        double dt = frame % 60 == 59 ? late : usual;
        requested += dt;
        int steps = step_clock_advance(&clock, dt);
        EXPECT(steps <= STEP_CLOCK_MAX_STEPS, "frame %d ran %d steps", frame, steps);
        if (app_failures > 0) return;
    }
    /* Behind by at most the steps the last late frame still owes. */
    EXPECT(requested - clock.simulated <= STEP_CLOCK_MAX_STEPS * STEP_CLOCK_STEP,
           "simulated %.4f s for %.4f s of frames (%.3f%%)", clock.simulated, requested,
           100.0 * clock.simulated / requested);
    EXPECT(clock.forgiven == 0.0, "%.4f s forgiven while the frame rate held", clock.forgiven);
}

/* A stall of 2 s: a few steps now, then the debt is forgiven (the
 * simulation slows down instead of running 240 steps in a burst). */
static void test_clock_forgives_a_stall(void) {
    step_clock_t clock = {0};
    int steps = step_clock_advance(&clock, 2.0);
    EXPECT(steps == STEP_CLOCK_MAX_STEPS, "%d steps after a stall", steps);
    EXPECT(clock.owed <= STEP_CLOCK_MAX_DEBT, "%.3f s still owed after a stall", clock.owed);
    int later = 0;
    for (int i = 0; i < 60; i++) later += step_clock_advance(&clock, 1.0 / 60.0);
    double expected = (1.0 + STEP_CLOCK_MAX_DEBT) / STEP_CLOCK_STEP;
    EXPECT(fabs(later - expected) <= 1.0, "%d steps in the second after a stall, expected %.0f",
           later, expected);
    EXPECT(fabs(clock.forgiven - (2.0 - STEP_CLOCK_MAX_DEBT - 4 * STEP_CLOCK_STEP)) < 1e-9,
           "forgave %.4f s", clock.forgiven);
}

/* A frame held to one step pays the frame's start-up alone; planning with
 * that cost kept a 5000-body pile held to one step a frame for good. Only
 * frames of two steps or more raise the cost; a cheaper frame lowers it. */
static void test_step_cost_is_planned_from_frames_of_two_steps(void) {
    double cost = step_clock_step_cost(0.0, 0.0049, 1);
    EXPECT(cost == 0.0049, "the first frame's cost is taken: %g", cost);
    cost = step_clock_step_cost(0.0040, 0.0080, 2);
    EXPECT(cost == 0.0040, "two steps of 4 ms keep 4 ms: %g", cost);
    for (int frame = 0; frame < 100; frame++) cost = step_clock_step_cost(cost, 0.0060, 1);
    EXPECT(cost == 0.0040, "single steps of 6 ms raised the cost to %g", cost);
    EXPECT(step_clock_budget(1.0 / 60.0, 0.006, cost) == 2, "two steps no longer fit");
    for (int frame = 0; frame < 100; frame++) cost = step_clock_step_cost(cost, 0.0120, 2);
    EXPECT(fabs(cost - 0.006) < 1e-6, "two steps of 6 ms each: the cost is %g", cost);
    for (int frame = 0; frame < 100; frame++) cost = step_clock_step_cost(cost, 0.0010, 1);
    EXPECT(fabs(cost - 0.001) < 1e-6, "single steps of 1 ms: the cost is %g", cost);
    EXPECT(step_clock_step_cost(cost, NAN, 2) == cost, "a NaN time changed the cost");
    EXPECT(step_clock_step_cost(cost, 0.01, 0) == cost, "a frame of no steps changed the cost");
}

/* A machine whose step takes 10 ms while drawing takes 8 ms (5000 bodies on
 * two shared cores): one step fits a 60 Hz frame. Held to it, every frame
 * runs one step, however late the frames come, and the debt never builds:
 * no spiral. A budget that fits the frame's two steps changes nothing. */
static void test_clock_held_to_the_frame_budget(void) {
    EXPECT(step_clock_budget(1.0 / 60.0, 0.008, 0.010) == 1, "budget at 10 ms a step: %d",
           step_clock_budget(1.0 / 60.0, 0.008, 0.010));
    EXPECT(step_clock_budget(1.0 / 60.0, 0.003, 0.003) == 4, "budget at 3 ms a step: %d",
           step_clock_budget(1.0 / 60.0, 0.003, 0.003));
    EXPECT(step_clock_budget(1.0 / 60.0, 0.050, 0.010) == 1, "a frame over budget stops it");
    EXPECT(step_clock_budget(1.0 / 60.0, 0.008, 0.0) == 0, "no step measured: a budget");
    step_clock_t clock = {0};
    for (int frame = 0; frame < 600; frame++) {
        double dt = frame % 2 ? 1.0 / 60.0 : 0.040; /* frames late too */
        int steps = step_clock_advance_within(&clock, dt, 1);
        EXPECT(steps == 1, "frame %d ran %d steps on a budget of 1", frame, steps);
        EXPECT(clock.owed <= STEP_CLOCK_STEP, "frame %d: %.4f s owed", frame, clock.owed);
        if (app_failures > 0) return;
    }
    EXPECT(clock.held == 600, "%lu of 600 frames counted as held", clock.held);
    EXPECT(fabs(clock.simulated - 600 * STEP_CLOCK_STEP) < 1e-9, "simulated %.4f s",
           clock.simulated);
    step_clock_t fits = {0};
    double requested = 0.0;
    for (int frame = 0; frame < 600; frame++) {
        requested += 1.0 / 60.0;
        step_clock_advance_within(&fits, 1.0 / 60.0, 2);
    }
    EXPECT(fits.held == 0 && fits.forgiven == 0.0, "a budget of 2 held %lu frames, forgave %g s",
           fits.held, fits.forgiven);
    EXPECT(fabs(requested - fits.simulated) <= STEP_CLOCK_STEP, "simulated %.4f s for %.4f s",
           fits.simulated, requested);
}

/* A scene file's own timestep: the clock keeps real time at 60 frames per
 * second for steps of 1/1000 s to 1/30 s, runs up to 1/30 s of steps a frame
 * (never fewer than 4 steps), and a step longer than the debt limit still
 * comes round. */
static void test_clock_follows_the_scene_timestep(void) {
    const double steps[] = {1.0 / 1000.0, 1.0 / 240.0, 1.0 / 120.0, 1.0 / 60.0, 1.0 / 30.0};
    const int max_steps[] = {34, 8, 4, 4, 4};
    for (size_t i = 0; i < sizeof steps / sizeof steps[0]; i++) {
        step_clock_t clock = {0};
        step_clock_set_step(&clock, steps[i]);
        EXPECT(step_clock_max_steps(&clock) == max_steps[i], "dt = %g s: at most %d steps a "
               "frame, expected %d", steps[i], step_clock_max_steps(&clock), max_steps[i]);
        long total = 0;
        for (int frame = 0; frame < 600; frame++) total += step_clock_advance(&clock, 1.0 / 60.0);
        EXPECT(fabs(total * steps[i] - 10.0) <= steps[i] + 1e-9 && clock.forgiven == 0.0,
               "dt = %g s: %ld steps (%.4f s) in 10 s of frames, %.4f s forgiven", steps[i],
               total, total * steps[i], clock.forgiven);
    }
    step_clock_t slow = {0};
    step_clock_set_step(&slow, 2.0);
    long total = 0;
    for (int frame = 0; frame < 630; frame++) total += step_clock_advance(&slow, 1.0 / 60.0);
    EXPECT(total == 5 && slow.forgiven == 0.0, "steps of 2 s: %ld in 10.5 s, %.3f s forgiven",
           total, slow.forgiven);
    step_clock_set_step(&slow, 0.0);
    EXPECT(step_clock_step(&slow) == STEP_CLOCK_STEP && slow.owed == 0.0,
           "step 0 is not the default step");
}

static void test_layout_leaves_the_view_free(void) {
    const int sizes[2][2] = {{800, 600}, {1280, 720}};
    for (int i = 0; i < 2; i++) {
        layout_t l = layout_of(sizes[i][0], sizes[i][1]);
        EXPECT(l.view.x == 0 && l.view.y == 0 && l.view.h == sizes[i][1],
               "%dx%d: view at (%d, %d) %d high", sizes[i][0], sizes[i][1], l.view.x, l.view.y,
               l.view.h);
        EXPECT(l.view.w + l.sidebar.w == sizes[i][0] && l.sidebar.x == l.view.w,
               "%dx%d: view %d wide, side bar at %d, %d wide", sizes[i][0], sizes[i][1],
               l.view.w, l.sidebar.x, l.sidebar.w);
        EXPECT(!layout_contains(l.view, l.sidebar.x, 10) && layout_contains(l.view, 0, 0),
               "%dx%d: the view and the side bar overlap", sizes[i][0], sizes[i][1]);
    }
}

/* The UI grows with the window past 1280x720, in quarters: the side bar's
 * panels keep their size in UI units and a window pixel maps into them. */
static void test_layout_scales_the_ui_with_the_window(void) {
    const struct {
        int w, h;
        double scale;
    } cases[] = {{800, 600, 1.0},   {1280, 720, 1.0},  {1279, 2000, 1.0}, {1920, 1080, 1.5},
                 {2560, 1440, 2.0}, {2560, 1000, 1.25}, {8192, 8192, 6.25}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        layout_t l = layout_of(cases[i].w, cases[i].h);
        EXPECT(l.scale == cases[i].scale, "%dx%d: scale %g, not %g", cases[i].w, cases[i].h,
               l.scale, cases[i].scale);
        EXPECT(l.sidebar.w == (int)lround(LAYOUT_SIDEBAR_W * l.scale) &&
                   l.panels.w == LAYOUT_SIDEBAR_W && l.view.w + l.sidebar.w == cases[i].w,
               "%dx%d: side bar %d wide (%d in UI units), view %d", cases[i].w, cases[i].h,
               l.sidebar.w, l.panels.w, l.view.w);
        double ux, uy;
        layout_to_panels(&l, l.sidebar.x + l.sidebar.w - 1, cases[i].h - 1, &ux, &uy);
        EXPECT(ux >= l.panels.x + l.panels.w - 1 && ux < l.panels.x + l.panels.w &&
                   uy < l.panels.y + l.panels.h + 1,
               "%dx%d: the side bar's last pixel maps to (%g, %g) of %dx%d", cases[i].w,
               cases[i].h, ux, uy, l.panels.w, l.panels.h);
    }
}

/* Frames of 2 steps (1/60 s) at a constant energy of `energy` J. */
static void drift_frames(energy_drift_t *drift, int frames, double energy, unsigned long changes) {
    for (int i = 0; i < frames; i++) energy_drift_sample(drift, 2, energy, 0.0, 3, changes);
}

/* The drift is measured from the first energy after each change: a body added
 * or removed (the change counter), a rereference (integrator, gravity, grab);
 * a paused frame records nothing but may take the new reference. */
static void test_energy_drift_from_its_reference(void) {
    static energy_drift_t drift;
    energy_drift_init(&drift);
    energy_drift_sample(&drift, 2, 0.0, 0.0, 0, 1);
    EXPECT(!drift.valid, "a drift with no bodies");
    drift_frames(&drift, 1, 200.0, 2);
    EXPECT(drift.valid && drift.drift == 0.0, "the first energy is not the reference (%g)",
           drift.drift);
    EXPECT(!energy_drift_column(&drift, 0)->rereferenced,
           "a mark where the chart had nothing to break off from");
    drift_frames(&drift, 1, 201.0, 2);
    EXPECT(fabs(drift.drift - 0.005) < 1e-12, "E 201 J from 200 J: drift %g", drift.drift);
    drift_frames(&drift, 1, 190.0, 2);
    EXPECT(fabs(drift.drift + 0.05) < 1e-12, "E 190 J from 200 J: drift %g", drift.drift);
    const drift_column_t *newest = energy_drift_column(&drift, 0);
    EXPECT(newest->filled && newest->low < -0.049f, "the newest column: %g to %g",
           newest->low, newest->high);
    EXPECT(fabs(energy_drift_scale(&drift) - 0.05) < 1e-12, "scale %g for a drift of -5%%",
           energy_drift_scale(&drift));
    /* A body dropped: a new reference, marked. */
    drift_frames(&drift, 1, 500.0, 3);
    EXPECT(drift.drift == 0.0 && drift.reference == 500.0, "after a drop: drift %g from %g J",
           drift.drift, drift.reference);
    newest = energy_drift_column(&drift, 0);
    EXPECT(newest->rereferenced && newest->filled && newest->low == 0.0f,
           "the drop's column: mark %d, %g to %g", newest->rereferenced, newest->low,
           newest->high);
    /* The integrator switched. */
    drift_frames(&drift, 1, 510.0, 3);
    energy_drift_rereference(&drift);
    drift_frames(&drift, 1, 520.0, 3);
    EXPECT(drift.drift == 0.0 && drift.reference == 520.0, "after a rereference: %g from %g J",
           drift.drift, drift.reference);
    /* Paused: no column moves, but a body deleted meanwhile is a new reference. */
    size_t head = drift.head;
    double elapsed = drift.elapsed;
    energy_drift_sample(&drift, 0, 400.0, 0.0, 2, 4);
    EXPECT(drift.head == head && drift.elapsed == elapsed, "a paused frame moved the chart");
    EXPECT(drift.reference == 400.0 && drift.drift == 0.0, "paused deletion: reference %g J",
           drift.reference);
    /* No energy to compare with (gravity off, all at rest). */
    energy_drift_rereference(&drift);
    energy_drift_sample(&drift, 2, 0.0, 0.0, 3, 4);
    EXPECT(!drift.valid, "a drift relative to 0 J");
}

/* A pendulum released at the height of its pivot has E_ref near 0 J (here
 * 1e-5 J, rounding): its drift is measured against the kinetic energy the
 * swing reaches (10 J), so a 0.1 J error reads 1%, not 10000%. Before any
 * motion the scale is |E_ref|. */
static void test_energy_drift_scale_is_the_motion_when_e_ref_is_near_zero(void) {
    static energy_drift_t drift;
    energy_drift_init(&drift);
    energy_drift_sample(&drift, 2, 1e-5, 0.0, 2, 1);
    energy_drift_sample(&drift, 2, 2e-5, 0.0, 2, 1);
    EXPECT(drift.valid && fabs(drift.drift - 1.0) < 1e-9, "before motion: drift %g of |E_ref|",
           drift.drift);
    energy_drift_sample(&drift, 2, 0.05, 10.0, 2, 1);
    EXPECT(fabs(drift.drift - (0.05 - 1e-5) / 10.0) < 1e-12, "swinging: drift %g", drift.drift);
    energy_drift_sample(&drift, 2, -0.1, 4.0, 2, 1);
    EXPECT(fabs(drift.drift - (-0.1 - 1e-5) / 10.0) < 1e-12,
           "the peak is kept as the swing slows: drift %g", drift.drift);
    /* A new reference forgets the peak. */
    energy_drift_rereference(&drift);
    energy_drift_sample(&drift, 2, 100.0, 1.0, 2, 1);
    energy_drift_sample(&drift, 2, 99.0, 1.0, 2, 1);
    EXPECT(fabs(drift.drift + 0.01) < 1e-12, "|E_ref| 100 J over a peak of 1 J: drift %g",
           drift.drift);
}

/* The chart holds the last 5 s: 200 columns of 3 steps; frames of 4 steps
 * (catching up) leave no gap; the scale follows what is on the chart. */
static void test_energy_drift_chart_window_and_scale(void) {
    static energy_drift_t drift;
    energy_drift_init(&drift);
    /* 10 s of a drift rising 0.1% a second. */
    for (int frame = 0; frame <= 600; frame++) {
        energy_drift_sample(&drift, 2, 1000.0 * (1.0 + 0.001 * frame / 60.0), 0.0, 3, 1);
    }
    const drift_column_t *oldest = energy_drift_column(&drift, DRIFT_COLUMNS - 1);
    const drift_column_t *newest = energy_drift_column(&drift, 0);
    EXPECT(oldest->filled && fabs(oldest->low - 0.005) < 0.0001,
           "5 s ago the chart shows %g, expected 0.005", oldest->low);
    EXPECT(newest->filled && fabs(newest->high - 0.01) < 1e-6, "now the chart shows %g",
           newest->high);
    EXPECT(fabs(energy_drift_scale(&drift) - 0.01) < 1e-12, "scale %g for 1%%",
           energy_drift_scale(&drift));
    for (int frame = 0; frame < 200; frame++) energy_drift_sample(&drift, 4, 1000.0, 0.0, 3, 2);
    size_t gaps = 0;
    for (size_t age = 0; age < DRIFT_COLUMNS; age++) gaps += !energy_drift_column(&drift, age)->filled;
    EXPECT(gaps == 0, "%zu empty columns after frames of 4 steps", gaps);
    EXPECT(energy_drift_scale(&drift) == DRIFT_MIN_SCALE, "scale %g for no drift at all",
           energy_drift_scale(&drift));
    drift_frames(&drift, 1, 1e9, 2);
    EXPECT(energy_drift_scale(&drift) == DRIFT_MAX_SCALE, "scale %g beyond 1000%%",
           energy_drift_scale(&drift));
    const double drifts[] = {0.0003, 0.0007, 0.0015, 0.003, 0.04, 0.3, 0.7};
    const double scales[] = {0.0005, 0.001, 0.002, 0.005, 0.05, 0.5, 1.0};
    for (size_t i = 0; i < sizeof drifts / sizeof drifts[0]; i++) {
        energy_drift_init(&drift);
        drift_frames(&drift, 1, 100.0, 1);
        drift_frames(&drift, 1, 100.0 * (1.0 - drifts[i]), 1);
        EXPECT(fabs(energy_drift_scale(&drift) - scales[i]) < 1e-12,
               "scale %g for a drift of -%g, expected %g", energy_drift_scale(&drift),
               drifts[i], scales[i]);
    }
}

/* With a scene's step of 1/60 s (two a column... and a half) or 1/240 s the
 * chart still holds the last 5 s: its columns are time, not steps. */
static void test_energy_drift_columns_follow_the_step(void) {
    static energy_drift_t drift;
    const double steps[] = {1.0 / 60.0, 1.0 / 240.0, 1.0 / 30.0};
    for (size_t i = 0; i < sizeof steps / sizeof steps[0]; i++) {
        energy_drift_init(&drift);
        energy_drift_set_step(&drift, steps[i]);
        int per_frame = (int)lround(1.0 / 60.0 / steps[i]);
        if (per_frame < 1) per_frame = 1;
        double frame_time = per_frame * steps[i];
        /* 10 s of a drift rising 0.1% a second. */
        for (double t = 0.0; t <= 10.0 + 1e-9; t += frame_time) {
            energy_drift_sample(&drift, per_frame, 1000.0 * (1.0 + 0.001 * t), 0.0, 3, 1);
        }
        const drift_column_t *oldest = energy_drift_column(&drift, DRIFT_COLUMNS - 1);
        EXPECT(oldest->filled && fabs(oldest->low - 0.005) < 0.0002,
               "dt = %g s: 5 s ago the chart shows %g, expected 0.005", steps[i], oldest->low);
    }
}

static void expect_drift_text(double fraction, const char *expected) {
    char out[32];
    energy_drift_format(fraction, out, sizeof(out));
    EXPECT(strcmp(out, expected) == 0 && strlen(out) <= 7,
           "energy_drift_format(%g) gave \"%s\", expected \"%s\"", fraction, out, expected);
}

static void test_energy_drift_text_fits(void) {
    expect_drift_text(0.00367, "+0.367%");
    expect_drift_text(-0.0000001, "0.000%");
    expect_drift_text(-0.0135, "-1.35%");
    expect_drift_text(0.123, "+12.3%");
    expect_drift_text(-0.99996, "-100.0%");
    expect_drift_text(2.5, "+250%");
    expect_drift_text(20.0, ">+999%");
    expect_drift_text(-1e300, "<-999%");
    char out[32];
    for (double v = 1e-6; v < 1e6; v *= 1.37) {
        energy_drift_format(-v, out, sizeof(out));
        EXPECT(strlen(out) <= 7, "energy_drift_format(%g) gave \"%s\"", -v, out);
    }
    const struct {
        double scale;
        char sign;
        const char *text;
    } labels[] = {{1e-4, '+', "+0.01%"}, {5e-3, '-', "-0.5%"}, {1.0, '+', "+100%"},
                  {10.0, '-', "-1000%"}, {2e-4, '+', "+0.02%"}};
    for (size_t i = 0; i < sizeof labels / sizeof labels[0]; i++) {
        energy_drift_format_scale(labels[i].scale, labels[i].sign, out, sizeof(out));
        EXPECT(strcmp(out, labels[i].text) == 0, "scale label %g: \"%s\", expected \"%s\"",
               labels[i].scale, out, labels[i].text);
    }
}

/* --integrator's names: the engine's, any case, spaces, underscores or
 * hyphens; N and Shift+N wrap around; the words for springs. */
static void test_integrators_by_name(void) {
    const struct {
        const char *text;
        integrator_t expected;
    } names[] = {
        {"seed", INTEGRATOR_SEED},
        {"SEED", INTEGRATOR_SEED},
        {"explicit euler", INTEGRATOR_EXPLICIT_EULER},
        {"symplectic_euler", INTEGRATOR_SYMPLECTIC_EULER},
        {"Symplectic Euler", INTEGRATOR_SYMPLECTIC_EULER},
        {"velocity-Verlet", INTEGRATOR_VELOCITY_VERLET},
        {"rk4", INTEGRATOR_RK4},
        {"Symplectic4", INTEGRATOR_SYMPLECTIC4},
        {"implicit_euler", INTEGRATOR_IMPLICIT_EULER},
        {"Implicit Euler", INTEGRATOR_IMPLICIT_EULER},
    };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        integrator_t got = INTEGRATOR_COUNT;
        EXPECT(integrator_choice_parse(names[i].text, &got) && got == names[i].expected,
               "'%s' gave integrator %d, expected %d", names[i].text, (int)got,
               (int)names[i].expected);
    }
    const char *unknown[] = {"leapfrog", "", "symplectic", "rk", "euler"};
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; i++) {
        integrator_t got;
        EXPECT(!integrator_choice_parse(unknown[i], &got), "'%s' was taken as an integrator",
               unknown[i]);
    }
    char list[256];
    integrator_choice_list(list, sizeof(list));
    EXPECT(strcmp(list, "seed, explicit_euler, symplectic_euler, velocity_verlet, rk4, "
                        "symplectic4, implicit_euler") == 0,
           "the list of integrators: \"%s\"", list);
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        integrator_t got;
        EXPECT(integrator_choice_parse(integrator_get_name((integrator_t)i), &got) &&
                   got == (integrator_t)i,
               "the engine's own name '%s' is refused", integrator_get_name((integrator_t)i));
    }
    EXPECT(integrator_choice_step(INTEGRATOR_SYMPLECTIC4, 1) == INTEGRATOR_IMPLICIT_EULER &&
               integrator_choice_step(INTEGRATOR_IMPLICIT_EULER, 1) == INTEGRATOR_SEED &&
               integrator_choice_step(INTEGRATOR_SEED, -1) == INTEGRATOR_IMPLICIT_EULER &&
               integrator_choice_step(INTEGRATOR_EXPLICIT_EULER, 1) ==
                   INTEGRATOR_SYMPLECTIC_EULER,
           "N and Shift+N do not go round the integrators");
    const char *expected[INTEGRATOR_COUNT] = {
        "unstable with springs",  "unstable with springs",  "stable for w dt < 2.00",
        "stable for w dt < 2.00", "stable for w dt < 2.83", "stable for w dt < 1.57",
        "stable for any w dt"};
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        char words[64];
        integrator_choice_stability((integrator_t)i, words, sizeof(words));
        EXPECT(strcmp(words, expected[i]) == 0 && strlen(words) <= 22,
               "%s with springs: \"%s\", expected \"%s\"", integrator_get_name((integrator_t)i),
               words, expected[i]);
    }
}

/* ---- scenes ---- */

/* The samples: the default scene first, then the *.scene files ordered
 * by category (sample_categories.h) and by name within one, each with a
 * known category and a one-line note; a scene is found by its path however
 * it is written; PageDown and PageUp go round. */
static void test_samples_list_by_category(void) {
    static samples_t samples;
    samples_load(&samples, "assets/scenes", SANDBOX_DEFAULT_NAME, SANDBOX_DEFAULT_SCENE);
    EXPECT(samples.count >= 12, "%zu samples with assets/scenes", samples.count);
    EXPECT(samples_count(&samples) == samples.count && samples_path(&samples, 0) == NULL &&
               strcmp(samples.items[0].name, SANDBOX_DEFAULT_NAME) == 0,
           "the default scene is not first");
    for (size_t i = 0; i < samples.count; i++) {
        const sample_t *s = &samples.items[i];
        EXPECT(s->category >= 0 && s->category < SAMPLE_CATEGORY_COUNT,
               "%s: category %d is none of the browser's", s->name, s->category);
        EXPECT(s->note[0] != '\0' && strlen(s->note) <= SCENE_FILE_NOTE_MAX, "%s: no note",
               s->name);
        if (i < 2) continue;
        const sample_t *before = &samples.items[i - 1];
        EXPECT(before->category < s->category ||
                   (before->category == s->category && strcmp(before->name, s->name) < 0),
               "%s before %s", before->name, s->name);
    }
    EXPECT(strcmp(samples_category_name(&samples, 0), "Basics") == 0, "the default scene in %s",
           samples_category_name(&samples, 0));
    int pegs = samples_find(&samples, "./assets/scenes/../scenes/pegs.scene");
    EXPECT(pegs > 0 && strstr(samples_path(&samples, (size_t)pegs), "pegs.scene") != NULL,
           "pegs.scene found at %d", pegs);
    EXPECT(pegs > 0 && strcmp(samples_category_name(&samples, (size_t)pegs), "Games") == 0,
           "pegs is not in Games");
    EXPECT(samples_find(&samples, NULL) == 0, "the default scene is not at 0");
    EXPECT(samples_find(&samples, "app/app.c") == -1 && samples_find(&samples, "no/such") == -1,
           "a file that is not a sample is found in the list");
    size_t last = samples_count(&samples) - 1;
    EXPECT(samples_next(&samples, (int)last, 1) == 0 && samples_next(&samples, 0, -1) == last &&
               samples_next(&samples, 2, 1) == 3 && samples_next(&samples, -1, 1) == 0 &&
               samples_next(&samples, -1, -1) == last,
           "PageDown and PageUp do not go round the list");
    samples_free(&samples);
    samples_load(&samples, "no/such/directory", SANDBOX_DEFAULT_NAME, NULL);
    EXPECT(samples.count == 1 && samples_count(&samples) == 1 && samples.items[0].category == 0,
           "a missing directory lists %zu samples", samples.count);
    samples_free(&samples);
}

/* The stage chart keeps a column per frame in a ring, each stage's time
 * only when the stage ran; its peak is the longest column. */
static void test_stage_chart_keeps_the_frames(void) {
    static stage_chart_t chart;
    stage_chart_init(&chart);
    EXPECT(stage_chart_peak(&chart) == 0.0 && !stage_chart_column(&chart, 0)->filled,
           "a new chart is not empty");
    scene_profile_t p = {{0}, {false}, 0, 0, 0, 0};
    p.seconds[SCENE_STAGE_FORCES] = 1e-3;
    p.ran[SCENE_STAGE_FORCES] = true;
    p.seconds[SCENE_STAGE_SOLVER] = 5e-3; /* not run: not drawn */
    p.awake_bodies = 7;
    stage_chart_add(&chart, &p);
    p.ran[SCENE_STAGE_SOLVER] = true;
    stage_chart_add(&chart, &p);
    const stage_column_t *newest = stage_chart_column(&chart, 0), *older = stage_chart_column(&chart, 1);
    EXPECT(newest->filled && older->filled && older->seconds[SCENE_STAGE_SOLVER] == 0.0f &&
               newest->seconds[SCENE_STAGE_SOLVER] == 5e-3f && chart.last.awake_bodies == 7 &&
               chart.has_last,
           "columns: %g then %g s of solver", older->seconds[SCENE_STAGE_SOLVER],
           newest->seconds[SCENE_STAGE_SOLVER]);
    EXPECT(fabs(stage_chart_peak(&chart) - 6e-3) < 1e-9, "peak %g s", stage_chart_peak(&chart));
    for (int i = 0; i < STAGE_CHART_COLUMNS; i++) {
        p.seconds[SCENE_STAGE_SOLVER] = 1e-4;
        stage_chart_add(&chart, &p);
    }
    EXPECT(fabs(stage_chart_peak(&chart) - 1.1e-3) < 1e-9, "after a full turn, peak %g s",
           stage_chart_peak(&chart));
    EXPECT(fabs(stage_chart_scale(&chart) - 1.1e-3) < 1e-9, "scale %g s", stage_chart_scale(&chart));
    p.seconds[SCENE_STAGE_SOLVER] = 0.1; /* one slow step: the scale stays at 4 medians */
    stage_chart_add(&chart, &p);
    EXPECT(fabs(stage_chart_peak(&chart) - 0.101) < 1e-6 &&
               fabs(stage_chart_scale(&chart) - 4.4e-3) < 1e-9,
           "one slow step: peak %g s, scale %g s", stage_chart_peak(&chart),
           stage_chart_scale(&chart));
}

/* The plot keeps the lowest and highest value of each column of simulated
 * time; a frame without a value (no body inspected) leaves columns empty;
 * a constant is widened to show. */
static void test_plot_columns_hold_low_and_high(void) {
    static plot_t plot;
    plot_init(&plot, PLOT_HEIGHT);
    double low = 0, high = 0;
    EXPECT(!plot_range(&plot, &low, &high), "an empty plot has a range");
    double column = PLOT_SECONDS / PLOT_COLUMNS;
    plot_sample(&plot, 0.25 * column, true, 2.0);
    plot_sample(&plot, 0.25 * column, true, -1.0);
    plot_sample(&plot, 0.0, true, 9.0); /* paused: nothing added */
    const plot_column_t *c = plot_column(&plot, 0);
    EXPECT(c->filled && c->low == -1.0f && c->high == 2.0f && plot.latest == 9.0,
           "column %g to %g, latest %g", c->low, c->high, plot.latest);
    plot_sample(&plot, 3.0 * column, false, 0.0);
    EXPECT(!plot_column(&plot, 0)->filled && plot_column(&plot, 3)->filled && !plot.has_latest,
           "a frame without a value filled a column");
    EXPECT(plot_range(&plot, &low, &high) && low == -1.0 && high == 2.0, "range %g to %g", low,
           high);
    plot_init(&plot, PLOT_ENERGY);
    plot_sample(&plot, column, true, 5.0);
    EXPECT(plot_range(&plot, &low, &high) && low < 5.0 && high > 5.0 && high - low < 0.2,
           "a constant's range %g to %g", low, high);
    EXPECT(plot_needs_body(PLOT_SPEED) && !plot_needs_body(PLOT_MOMENTUM) &&
               strcmp(plot_quantity_name(PLOT_KINETIC), "kinetic energy (J)") == 0,
           "quantities");
}

/* The SCENE panel's lines fit the side bar and say what they should. */
static void test_scene_panel_words(void) {
    char line[SCENE_TEXT_SIZE];
    scene_text_position(1, 12, line);
    EXPECT(strcmp(line, "2 of 12") == 0, "position: \"%s\"", line);
    scene_text_position(-1, 12, line);
    EXPECT(strcmp(line, "file") == 0, "position of a file: \"%s\"", line);
    scene_text_timestep(1.0 / 120.0, line);
    EXPECT(strcmp(line, "timestep 1/120 s") == 0, "timestep: \"%s\"", line);
    scene_text_timestep(0.003, line);
    EXPECT(strcmp(line, "timestep 0.003 s") == 0, "timestep: \"%s\"", line);
    scene_text_game("breakout", SCENE_TEXT_PLAYING, 3, 2, 47, line);
    EXPECT(strcmp(line, "score 3  lives 2  bricks 47") == 0, "breakout: \"%s\"", line);
    scene_text_game("space_invaders", SCENE_TEXT_PLAYING, 31, 1, 1, line);
    EXPECT(strcmp(line, "score 31  lives 1  invaders 1") == 0, "invaders: \"%s\"", line);
    scene_text_game("pegs", SCENE_TEXT_PLAYING, 12, 1, 24, line);
    EXPECT(strcmp(line, "balls 24  landed 12") == 0, "pegs: \"%s\"", line);
    scene_text_game("breakout", SCENE_TEXT_WON, 50, 3, 0, line);
    EXPECT(strcmp(line, "WON  score 50  R: again") == 0, "won: \"%s\"", line);
    scene_text_game("space_invaders", SCENE_TEXT_LOST, 12, 0, 20, line);
    EXPECT(strcmp(line, "LOST  score 12  R: again") == 0, "lost: \"%s\"", line);
    scene_text_game("some_game", SCENE_TEXT_PLAYING, 2000000000, 2000000000, 2000000000, line);
    EXPECT(strlen(line) <= LAYOUT_LINE_CHARS, "huge numbers: \"%s\"", line);
}

static bool same_rgb(rgb_color_t c, palette_rgb_t p) {
    return lround(c.r * 255.0) == p.r && lround(c.g * 255.0) == p.g && lround(c.b * 255.0) == p.b;
}

/* The default scene is a scene file built into the app: the same container
 * as before (the floor and walls in the static colour the smoke tests look
 * for, gravity 10, contacts on, 1/120 s), and drops into it are refused or
 * placed as before. */
static void test_default_scene_is_a_scene_file(void) {
    static sandbox_t sandbox;
    sandbox_init(&sandbox, 1);
    scene_t *scene = sandbox.scene;
    EXPECT(sandbox.is_default && strcmp(sandbox.name, "sandbox") == 0 && sandbox.game == NULL,
           "the default scene is \"%s\"", sandbox.name);
    EXPECT(scene_bodies(scene) == 3, "%zu bodies in the default scene", scene_bodies(scene));
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        EXPECT(isinf(body_get_mass(body)) && same_rgb(body_get_color(body), PALETTE_STATIC) &&
                   body_get_elasticity(body) == 0.0,
               "static body %zu: mass %g, not in PALETTE_STATIC or elastic", i,
               body_get_mass(body));
    }
    aabb_t floor = body_get_bounds(scene_get_body(scene, 0));
    EXPECT(floor.min.x == -15.0 && floor.max.x == 15.0 && floor.min.y == -1.0 && floor.max.y == 0.0,
           "the floor spans (%g, %g) to (%g, %g)", floor.min.x, floor.min.y, floor.max.x,
           floor.max.y);
    EXPECT(sandbox.home.min.x == -15.5 && sandbox.home.max.x == 15.5 &&
               sandbox.home.min.y == -1.5 && sandbox.home.max.y == 30.5,
           "the default view is (%g, %g) to (%g, %g)", sandbox.home.min.x, sandbox.home.min.y,
           sandbox.home.max.x, sandbox.home.max.y);
    EXPECT(sandbox.step == 1.0 / 120.0 && sandbox.gravity_on &&
               scene_get_gravity(scene).y == -SANDBOX_GRAVITY,
           "step %g, gravity %g", sandbox.step, scene_get_gravity(scene).y);
    EXPECT(scene_get_workers(scene) == SANDBOX_WORKERS && SANDBOX_WORKERS == 2,
           "the sandbox steps on %zu workers", scene_get_workers(scene));
    const char *problem = NULL;
    list_t *shape = sandbox_make_shape(&sandbox, (shape_choice_t){SHAPE_BOX, 0, 0.5}, &problem);
    vector_t placed;
    const char *why = sandbox_place(&sandbox, shape, (vector_t){-14.5, 10.0}, &placed);
    EXPECT(why != NULL && strcmp(why, "inside the left wall") == 0, "a drop in the left wall: %s",
           why != NULL ? why : "accepted");
    why = sandbox_place(&sandbox, shape, (vector_t){0.0, -1.4}, &placed);
    EXPECT(why == NULL && placed.y == -1.4, "a drop just below the floor: %s at y = %g",
           why != NULL ? why : "accepted", placed.y);
    why = sandbox_place(&sandbox, shape, (vector_t){0.0, -40.01}, &placed);
    EXPECT(why != NULL &&
               strcmp(why, "outside the world: bodies below y = -40 m are removed") == 0,
           "a drop below the world's floor: %s", why != NULL ? why : "accepted");
    list_t *box = sandbox_make_shape(&sandbox, (shape_choice_t){SHAPE_BOX, 0, 0.5}, &problem);
    sandbox_drop(&sandbox, box, (vector_t){5.0, 5.0}, VEC_ZERO, 0.5, &problem);
    why = sandbox_place(&sandbox, shape, (vector_t){5.1, 5.1}, &placed);
    EXPECT(why != NULL && strcmp(why, "inside a body") == 0, "a drop inside a dropped box: %s",
           why != NULL ? why : "accepted");
    why = sandbox_place(&sandbox, shape, (vector_t){0.0, 0.1}, &placed);
    EXPECT(why == NULL && fabs(placed.y - 0.3) < 1e-12, "a drop on the floor goes to y = %g",
           placed.y);
    list_free(shape);
    sandbox_free(&sandbox);
    /* docs/sandbox-reference.md shows the default scene: the very text. */
    FILE *doc = fopen("docs/sandbox-reference.md", "rb");
    static char text[200000];
    size_t length = doc != NULL ? fread(text, 1, sizeof(text) - 1, doc) : 0;
    if (doc != NULL) fclose(doc);
    text[length] = '\0';
    const char *start = strstr(text, "```scene\n# The sandbox's default scene");
    const char *end = start != NULL ? strstr(start + 9, "```") : NULL;
    EXPECT(start != NULL && end != NULL &&
               (size_t)(end - start - 9) == strlen(SANDBOX_DEFAULT_SCENE) &&
               strncmp(start + 9, SANDBOX_DEFAULT_SCENE, strlen(SANDBOX_DEFAULT_SCENE)) == 0,
           "docs/sandbox-reference.md does not show SANDBOX_DEFAULT_SCENE word for word");
}

/* The SHAPE panel's round shapes drop as round bodies: a circle of radius
 * size and a flat capsule 2 sizes long and 1 high, of density 1 kg/m^2,
 * their centroid where placed; placed on the floor by their exact extent. */
static void test_round_shapes_drop_round(void) {
    static sandbox_t sandbox;
    sandbox_init(&sandbox, 1);
    const char *problem = NULL;
    shape_choice_t circle = {SHAPE_CIRCLE, 0, 0.5};
    EXPECT(strcmp(sandbox_shape_name(circle), "circle") == 0, "the circle is named \"%s\"",
           sandbox_shape_name(circle));
    list_t *outline = sandbox_make_shape(&sandbox, circle, &problem);
    EXPECT(outline != NULL, "no circle: %s", problem != NULL ? problem : "?");
    vector_t placed = VEC_ZERO;
    const char *why = outline != NULL
                          ? sandbox_place(&sandbox, outline, (vector_t){0.0, 0.1}, &placed)
                          : "no outline";
    EXPECT(why == NULL && fabs(placed.y - 0.5) < 1e-12, "a circle on the floor goes to y = %g",
           placed.y);
    body_t *ball = outline != NULL ? sandbox_drop_shape(&sandbox, circle, outline, placed,
                                                        (vector_t){1.0, 0.0}, 0.5, &problem)
                                   : NULL;
    EXPECT(ball != NULL && body_get_shape_kind(ball) == BODY_SHAPE_CIRCLE &&
               body_get_round_radius(ball) == 0.5 &&
               fabs(body_get_mass(ball) - M_PI * 0.25) < 1e-12 &&
               body_get_centroid(ball).x == placed.x && body_get_centroid(ball).y == placed.y &&
               body_get_velocity(ball).x == 1.0 && body_get_elasticity(ball) == 0.5,
           "the dropped circle: %s", problem != NULL ? problem : "wrong kind, size or pose");
    shape_choice_t capsule = {SHAPE_CAPSULE, 0, 1.0};
    EXPECT(strcmp(sandbox_shape_name(capsule), "capsule") == 0, "the capsule is named \"%s\"",
           sandbox_shape_name(capsule));
    outline = sandbox_make_shape(&sandbox, capsule, &problem);
    body_t *pill = outline != NULL ? sandbox_drop_shape(&sandbox, capsule, outline,
                                                        (vector_t){5.0, 5.0}, VEC_ZERO, 0.0,
                                                        &problem)
                                   : NULL;
    EXPECT(pill != NULL && body_get_shape_kind(pill) == BODY_SHAPE_CAPSULE &&
               body_get_round_radius(pill) == 0.5 &&
               fabs(body_get_mass(pill) - (M_PI * 0.25 + 1.0)) < 1e-12,
           "the dropped capsule: %s", problem != NULL ? problem : "wrong kind, size or mass");
    if (pill != NULL) {
        aabb_t box = body_get_bounds(pill);
        EXPECT(fabs(box.min.x - 4.0) < 1e-9 && fabs(box.max.x - 6.0) < 1e-9 &&
                   fabs(box.min.y - 4.5) < 1e-9 && fabs(box.max.y - 5.5) < 1e-9,
               "the capsule spans (%g, %g) to (%g, %g)", box.min.x, box.min.y, box.max.x,
               box.max.y);
    }
    sandbox_free(&sandbox);
}

/* Every sample opens: its view, timestep and integrator are the file's, its
 * game starts; a refused file leaves the open scene as it was; R reads the
 * file again, keeping the integrator the user chose. */
static void test_scene_files_open_and_refusals_keep_the_scene(void) {
    static sandbox_t sandbox;
    static samples_t samples;
    char error[600];
    sandbox_init(&sandbox, 1);
    samples_load(&samples, "assets/scenes", SANDBOX_DEFAULT_NAME, NULL);
    for (size_t i = 1; i < samples.count; i++) {
        const char *path = samples.items[i].path;
        if (!sandbox_open(&sandbox, path, error, sizeof(error))) {
            app_fail("%s is refused: %s", path, error);
            continue;
        }
        scene_file_view_t view = scene_file_get_view(sandbox.file);
        EXPECT(!sandbox.is_default && strstr(path, sandbox.name) != NULL &&
                   sandbox.step == scene_file_get_timestep(sandbox.file) && view.has_view &&
                   fabs(sandbox.home.max.x - sandbox.home.min.x - view.width) < 1e-9,
               "%s: opened as \"%s\", step %g", path, sandbox.name, sandbox.step);
        EXPECT((sandbox.game != NULL) == (scene_file_get_game(sandbox.file)[0] != '\0'),
               "%s: the game %s started", path, sandbox.game != NULL ? "" : "not");
        EXPECT(scene_get_workers(sandbox.scene) == SANDBOX_WORKERS, "%s: %zu workers", path,
               scene_get_workers(sandbox.scene));
        for (int step = 0; step < 30; step++) sandbox_step(&sandbox);
    }
    EXPECT(sandbox_open(&sandbox, "assets/scenes/orbits.scene", error, sizeof(error)) &&
               sandbox.integrator == INTEGRATOR_SYMPLECTIC_EULER,
           "orbits.scene does not step with its own integrator");
    scene_t *kept = sandbox.scene;
    size_t bodies = scene_bodies(kept);
    const char *bad = "build/tests/app_units_bad.scene";
    FILE *file = fopen(bad, "w");
    if (file != NULL) {
        fputs("body a { box 1 1 }\nbody b { regular 3 -1 }\n", file);
        fclose(file);
    }
    EXPECT(!sandbox_open(&sandbox, bad, error, sizeof(error)) &&
               strstr(error, "app_units_bad.scene:2:20: expected the radius") != NULL,
           "a bad file: \"%s\"", error);
    EXPECT(sandbox.scene == kept && scene_bodies(kept) == bodies &&
               strcmp(sandbox.name, "orbits") == 0,
           "a refused file changed the open scene");
    EXPECT(!sandbox_open(&sandbox, "no/such.scene", error, sizeof(error)) &&
               strstr(error, "no/such.scene: cannot read") != NULL,
           "a missing file: \"%s\"", error);
    /* A file whose game lacks what it needs. */
    file = fopen(bad, "w");
    if (file != NULL) {
        fputs("game breakout\nbody ball { regular 8 0.2; velocity 1 1 }\n", file);
        fclose(file);
    }
    EXPECT(!sandbox_open(&sandbox, bad, error, sizeof(error)) &&
               strstr(error, "breakout: the scene has no body named paddle") != NULL &&
               sandbox.scene == kept,
           "a game that cannot start: \"%s\"", error);
    remove(bad);
    sandbox_set_integrator(&sandbox, INTEGRATOR_RK4);
    for (int step = 0; step < 30; step++) sandbox_step(&sandbox);
    EXPECT(sandbox_reset(&sandbox, error, sizeof(error)) &&
               sandbox.integrator == INTEGRATOR_RK4 &&
               scene_get_integrator(sandbox.scene) == INTEGRATOR_RK4,
           "R forgot the integrator");
    EXPECT(sandbox_open(&sandbox, NULL, error, sizeof(error)) && sandbox.is_default &&
               sandbox.integrator == INTEGRATOR_SEED && scene_bodies(sandbox.scene) == 3,
           "the default scene does not open again");
    samples_free(&samples);
    sandbox_free(&sandbox);
}

/* A grabbed shot that a destructive collision removes (and the engine frees
 * in the same tick) is let go: the grab spring never touches it again (the
 * sanitizer would tell). The game's keys move the gun and fire. */
static void test_grabbed_body_destroyed_is_let_go(void) {
    static sandbox_t sandbox;
    char error[600];
    sandbox_init(&sandbox, 1);
    if (!sandbox_open(&sandbox, "assets/scenes/space_invaders.scene", error, sizeof(error))) {
        app_fail("space_invaders.scene: %s", error);
        sandbox_free(&sandbox);
        return;
    }
    body_t *gun = scene_file_find_body(sandbox.file, "player");
    double x0 = body_get_centroid(gun).x;
    sandbox.input = (game_input_t){-1.0, true};
    sandbox_step(&sandbox);
    sandbox_step(&sandbox);
    sandbox.input = (game_input_t){0.0, false};
    body_t *shot = NULL;
    for (size_t i = 0; i < scene_bodies(sandbox.scene); i++) {
        if (game_body_has_tag(scene_get_body(sandbox.scene, i), "shot")) {
            shot = scene_get_body(sandbox.scene, i);
        }
    }
    EXPECT(body_get_centroid(gun).x < x0 - 0.05, "the gun did not move left (x %g from %g)",
           body_get_centroid(gun).x, x0);
    EXPECT(shot != NULL, "Space fired no shot");
    if (shot == NULL) {
        sandbox_free(&sandbox);
        return;
    }
    /* Held by the grab spring just under the middle shield: it flies into it. */
    sandbox_grab(&sandbox, shot, body_get_centroid(shot));
    sandbox_grab_move(&sandbox, (vector_t){-0.5, 3.0});
    int steps = 0;
    while (sandbox.grab.body != NULL && steps < 240) {
        sandbox_step(&sandbox);
        steps++;
    }
    EXPECT(sandbox.grab.body == NULL, "the shot is still held after %d steps", steps);
    for (int i = 0; i < 60; i++) sandbox_step(&sandbox);
    sandbox_free(&sandbox);
}

/* The energy the side bar shows counts the file's springs and Newtonian
 * gravity: on the orbits, kinetic energy alone swings by tens of percent,
 * the whole stays within 0.1% (symplectic Euler). */
static void test_energy_counts_springs_and_newton(void) {
    static sandbox_t sandbox;
    char error[600];
    sandbox_init(&sandbox, 1);
    if (!sandbox_open(&sandbox, "assets/scenes/orbits.scene", error, sizeof(error))) {
        app_fail("orbits.scene: %s", error);
        sandbox_free(&sandbox);
        return;
    }
    sandbox_totals_t start = sandbox_totals(&sandbox);
    double e0 = start.kinetic + start.potential, worst = 0.0;
    for (int step = 0; step < 1200; step++) {
        sandbox_step(&sandbox);
        sandbox_totals_t now = sandbox_totals(&sandbox);
        worst = fmax(worst, fabs((now.kinetic + now.potential - e0) / e0));
    }
    EXPECT(start.potential < 0.0 && worst < 0.001,
           "orbits: potential %g J, energy drifts %.4f%% in 10 s", start.potential, 100 * worst);
    /* One spring, to a static anchor: 1/2 k d^2 with d the distance between
     * the centroids. */
    if (sandbox_open(&sandbox, "assets/scenes/stiff_spring.scene", error, sizeof(error))) {
        scene_file_force_t spring = scene_file_get_force(sandbox.file, 0);
        double d = vec_get_length(vec_subtract(body_get_centroid(spring.body1),
                                               body_get_centroid(spring.body2)));
        sandbox_set_gravity(&sandbox, false);
        sandbox_totals_t totals = sandbox_totals(&sandbox);
        EXPECT(spring.kind == SCENE_FILE_SPRING &&
                   fabs(totals.potential - 0.5 * spring.constant * d * d) < 1e-9 * spring.constant,
               "stiff_spring: potential %g J, expected %g J", totals.potential,
               0.5 * spring.constant * d * d);
    } else {
        app_fail("stiff_spring.scene: %s", error);
    }
    sandbox_free(&sandbox);
}

/* k vertices of a regular polygon of radius r about c (pixels). */
static void regular(vector_t *out, int k, vector_t c, double r) {
    for (int i = 0; i < k; i++) {
        double a = 2.0 * M_PI * i / k;
        out[i] = (vector_t){c.x + r * cos(a), c.y + r * sin(a)};
    }
}

static void test_batch_counts_triangles_of_polygons(void) {
    batch_t batch = {0};
    const palette_rgb_t color = {1, 2, 3};
    vector_t p[BATCH_MAX_POLYGON];
    for (int k = 3; k <= 8; k++) {
        batch_clear(&batch);
        const int n = 1000;
        for (int i = 0; i < n; i++) {
            regular(p, k, (vector_t){10.0 + i, 20.0}, 4.0);
            EXPECT(batch_outlined(&batch, p, k, color, color), "polygon %d of %d refused", i, k);
        }
        EXPECT(batch.vertex_count == (size_t)(n * k), "%d %d-gons: %zu vertices, expected %d", n,
               k, batch.vertex_count, n * k);
        EXPECT(batch.index_count == (size_t)(n * 3 * (k - 2)),
               "%d %d-gons: %zu indices, expected %d", n, k, batch.index_count, n * 3 * (k - 2));
        EXPECT(batch.run_count == (size_t)n, "%zu runs, expected %d", batch.run_count, n);
        /* Each polygon's fan: (first, first + j, first + j + 1). */
        bool fans = true;
        for (int i = 0; i < n && fans; i++) {
            for (int j = 1; j + 1 < k; j++) {
                const int *t = &batch.indices[(size_t)(i * (k - 2) + j - 1) * 3];
                fans = fans && t[0] == i * k && t[1] == i * k + j && t[2] == i * k + j + 1;
            }
        }
        EXPECT(fans, "%d-gons: the indices are not each polygon's fan", k);
        EXPECT(!batch.translucent && !batch.failed, "opaque polygons made the batch translucent");
    }
    EXPECT(!batch_polygon(&batch, p, 2, color, 255), "a polygon of 2 vertices was accepted");
    EXPECT(!batch_polygon(&batch, p, BATCH_MAX_POLYGON + 1, color, 255),
           "a polygon over BATCH_MAX_POLYGON vertices was accepted");
    batch_free(&batch);
}

static void test_batch_allocates_nothing_once_warm(void) {
    batch_t batch = {0};
    vector_t p[6];
    batch_vertex_t *vertices = NULL;
    int *indices = NULL;
    batch_run_t *runs = NULL;
    for (int frame = 0; frame < 3; frame++) {
        batch_clear(&batch);
        for (int i = 0; i < 5000; i++) {
            regular(p, 6, (vector_t){i % 100, i / 100}, 2.0);
            batch_outlined(&batch, p, 6, (palette_rgb_t){9, 9, 9}, (palette_rgb_t){0, 0, 0});
        }
        if (frame > 0) {
            EXPECT(batch.vertices == vertices && batch.indices == indices && batch.runs == runs,
                   "frame %d: the same 5000 hexagons moved the batch's buffers", frame);
        }
        vertices = batch.vertices;
        indices = batch.indices;
        runs = batch.runs;
    }
    batch_free(&batch);
    EXPECT(batch.vertices == NULL && batch.vertex_capacity == 0, "batch_free kept a buffer");
}

static void test_batch_arrows_and_alpha(void) {
    batch_t batch = {0};
    const palette_rgb_t c = {255, 0, 255};
    EXPECT(batch_arrow(&batch, (vector_t){0, 0}, (vector_t){100, 0}, c, 255, 3),
           "a long arrow was refused");
    EXPECT(batch.run_count == 2 && batch.vertex_count == 7 && batch.index_count == 9,
           "a long arrow: %zu runs, %zu vertices, %zu indices; expected a quad and a triangle",
           batch.run_count, batch.vertex_count, batch.index_count);
    batch_clear(&batch);
    batch_arrow(&batch, (vector_t){0, 0}, (vector_t){1.5, 0}, c, 255, 3);
    EXPECT(batch.run_count == 1 && batch.vertex_count == 3, "a 1.5 px arrow: only its head");
    batch_clear(&batch);
    EXPECT(!batch_arrow(&batch, (vector_t){0, 0}, (vector_t){0.5, 0}, c, 255, 3) &&
               !batch_arrow(&batch, (vector_t){0, 0}, (vector_t){50, 0}, c, 0, 3) &&
               !batch_arrow(&batch, (vector_t){0, 0}, (vector_t){NAN, 0}, c, 255, 3),
           "an arrow under a pixel, invisible or not finite was drawn");
    EXPECT(batch.vertex_count == 0, "refused arrows left %zu vertices", batch.vertex_count);
    batch_arrow(&batch, (vector_t){0, 0}, (vector_t){50, 0}, c, 128, 3);
    EXPECT(batch.translucent && batch.vertices[0].a == 128, "alpha 128 is not translucent");
    batch_clear(&batch);
    EXPECT(!batch.translucent, "batch_clear kept the batch translucent");
    batch_free(&batch);
}

/* Distance from p to the segment a b. */
static double segment_distance(vector_t p, vector_t a, vector_t b) {
    vector_t d = vec_subtract(b, a);
    double t = vec_dot(vec_subtract(p, a), d) / vec_dot(d, d);
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    return vec_get_length(vec_subtract(p, vec_add(a, vec_multiply(t, d))));
}

/* Whether the outline is strictly convex, either winding. */
static bool outline_is_convex(const vector_t *p, int n) {
    int sign = 0;
    for (int k = 0; k < n; k++) {
        vector_t e = vec_subtract(p[(k + 1) % n], p[k]);
        vector_t f = vec_subtract(p[(k + 2) % n], p[(k + 1) % n]);
        double cross = vec_cross(e, f);
        int s = cross > 1e-12 ? 1 : cross < -1e-12 ? -1 : 0;
        if (s == 0 || (sign != 0 && s != sign)) return false;
        sign = s;
    }
    return true;
}

static void test_round_outlines_lie_on_the_boundary(void) {
    vector_t out[ROUND_OUTLINE_MAX];
    /* A circle: every vertex on the rim, chords within a quarter pixel of
     * it (the sagitta r (1 - cos(pi / n))), more vertices when larger. */
    const double radii[] = {2.0, 10.0, 50.0, 150.0};
    int last = 0;
    for (size_t i = 0; i < sizeof radii / sizeof radii[0]; i++) {
        double r = radii[i];
        vector_t c = {300.5, 200.25};
        int n = round_outline(c, c, r, out);
        EXPECT(n >= 8 && n <= ROUND_OUTLINE_MAX && n >= last, "circle r %g: %d vertices", r, n);
        last = n;
        for (int k = 0; k < n; k++) {
            double d = vec_get_length(vec_subtract(out[k], c));
            EXPECT(fabs(d - r) <= 1e-9 * r, "circle r %g: vertex %d at %g", r, k, d);
        }
        EXPECT(outline_is_convex(out, n), "circle r %g: not convex", r);
        if (n < ROUND_OUTLINE_MAX) {
            double sagitta = r * (1.0 - cos(M_PI / n));
            EXPECT(sagitta <= 0.25, "circle r %g: chords %g px inside the rim", r, sagitta);
        }
    }
    /* A capsule: every vertex at r from its core, the two caps' extreme
     * points reached, convex, within the batch's limit. */
    vector_t a = {100, 100}, b = {260, 220};
    double r = 40.0;
    int n = round_outline(a, b, r, out);
    EXPECT(n >= 8 && n <= ROUND_OUTLINE_MAX, "capsule: %d vertices", n);
    double far_a = 0.0, far_b = 0.0;
    for (int k = 0; k < n; k++) {
        double d = segment_distance(out[k], a, b);
        EXPECT(fabs(d - r) <= 1e-9 * r, "capsule: vertex %d at %g from the core", k, d);
        far_a = fmax(far_a, vec_get_length(vec_subtract(out[k], b)));
        far_b = fmax(far_b, vec_get_length(vec_subtract(out[k], a)));
    }
    double core = vec_get_length(vec_subtract(b, a));
    EXPECT(fabs(far_a - (core + r)) <= 1e-9 && fabs(far_b - (core + r)) <= 1e-9,
           "capsule: ends reach %g and %g, expected %g", far_a, far_b, core + r);
    EXPECT(outline_is_convex(out, n), "capsule: not convex");
    /* Refused sizes and centres give nothing. */
    EXPECT(round_outline(a, a, 0.0, out) == 0, "radius 0 drawn");
    EXPECT(round_outline(a, a, NAN, out) == 0, "radius NaN drawn");
    EXPECT(round_outline((vector_t){INFINITY, 0}, a, 1.0, out) == 0, "infinite centre drawn");
    /* The radius line: the world's counter-clockwise is clockwise on a
     * screen whose y grows downward. */
    vector_t rim = round_rim_point((vector_t){10, 10}, 5.0, M_PI / 2.0);
    EXPECT(fabs(rim.x - 10.0) < 1e-12 && fabs(rim.y - 5.0) < 1e-12, "rim at (%g, %g)", rim.x,
           rim.y);
}

static void test_batch_culls_what_is_out_of_view(void) {
    vector_t p[4];
    const int w = 800, h = 600;
    regular(p, 4, (vector_t){400, 300}, 5.0);
    EXPECT(batch_polygon_visible(p, 4, w, h), "a polygon in the middle was culled");
    regular(p, 4, (vector_t){-3, 300}, 5.0);
    EXPECT(batch_polygon_visible(p, 4, w, h), "a polygon across the left edge was culled");
    const vector_t outside[4] = {{-10, 300}, {810, 300}, {400, -10}, {400, 610}};
    for (int i = 0; i < 4; i++) {
        regular(p, 4, outside[i], 5.0);
        EXPECT(!batch_polygon_visible(p, 4, w, h), "a polygon at (%g, %g) was not culled",
               outside[i].x, outside[i].y);
    }
    regular(p, 4, (vector_t){400, 300}, 5.0);
    p[2].x = NAN;
    EXPECT(!batch_polygon_visible(p, 4, w, h), "a polygon with a NaN vertex was not culled");
}

/* FNV-1a over the bytes of the doubles as they lie in memory (this machine
 * is little-endian, as the web page's is): the hash state_log_hash
 * promises, worked out byte by byte. */
static uint64_t fnv_of_doubles(const double *values, size_t count) {
    uint64_t h = 14695981039346656037u;
    const unsigned char *bytes = (const unsigned char *)values;
    for (size_t i = 0; i < count * sizeof(double); i++) h = (h ^ bytes[i]) * 1099511628211u;
    return h;
}

/* The log line and the hash: exactly the bodies' positions and angles, one
 * ulp apart telling apart, removed bodies left out, a game's score added. */
static void test_state_log_hash_and_lines(void) {
    static sandbox_t sandbox;
    sandbox_init(&sandbox, 1);
    scene_t *scene = sandbox.scene;
    /* The default scene: the floor at (0, -0.5), the walls at (-14.5, 15)
     * and (14.5, 15), none turned. */
    const double poses[] = {0, -0.5, 0, -14.5, 15, 0, 14.5, 15, 0};
    uint64_t expected = fnv_of_doubles(poses, 9);
    EXPECT(state_log_hash(scene) == expected, "hash %016llx, expected %016llx",
           (unsigned long long)state_log_hash(scene), (unsigned long long)expected);

    char *text = NULL;
    size_t size = 0;
    FILE *out = open_memstream(&text, &size);
    state_log_print(out, &sandbox, 7, true);
    fclose(out);
    char want[256];
    snprintf(want, sizeof want,
             "state: frame 7  bodies 3  hash %016llx\nbody 0  0 -0.5 0\nbody 1  -14.5 15 0\n"
             "body 2  14.5 15 0\n",
             (unsigned long long)expected);
    EXPECT(text != NULL && strcmp(text, want) == 0, "logged\n%s\nexpected\n%s", text, want);
    free(text);

    /* One ulp of one wall's x is another hash; the wall removed is left
     * out of it. */
    body_t *wall = scene_get_body(scene, 2);
    body_set_centroid(wall, (vector_t){nextafter(14.5, 15.0), 15.0});
    EXPECT(state_log_hash(scene) != expected, "a wall moved by one ulp keeps the hash");
    body_remove(wall);
    EXPECT(state_log_hash(scene) == fnv_of_doubles(poses, 6),
           "a removed body counts in the hash");
    sandbox_free(&sandbox);

    /* In a game the line ends with its score, lives and what is left. */
    char error[600];
    sandbox_init(&sandbox, 1);
    EXPECT(sandbox_open(&sandbox, "assets/scenes/breakout.scene", error, sizeof error),
           "%s", error);
    text = NULL;
    out = open_memstream(&text, &size);
    state_log_print(out, &sandbox, 0, false);
    fclose(out);
    game_status_t status = game_status(sandbox.game);
    snprintf(want, sizeof want, "  score 0  lives %d  remaining %d\n", status.lives,
             status.remaining);
    EXPECT(text != NULL && strncmp(text, "state: frame 0  bodies ", 23) == 0 &&
               strlen(text) > strlen(want) && strcmp(text + strlen(text) - strlen(want), want) == 0,
           "logged \"%s\", expected it to end \"%s\"", text, want);
    free(text);
    sandbox_free(&sandbox);
}

static const app_test_t TESTS[] = {
    {"app_units.numbers_never_show_negative_zero", test_numbers_never_show_negative_zero},
    {"app_units.large_numbers_shorten_to_fit", test_large_numbers_shorten_to_fit},
    {"app_units.fit_and_wrap", test_fit_and_wrap},
    {"app_units.stats_lines_fit_the_side_bar", test_stats_lines_fit_the_side_bar},
    {"app_units.frame_times_from_one_window", test_frame_times_from_one_window},
    {"app_units.overlays_focus_on_the_strongest_and_nearest",
     test_overlays_focus_on_the_strongest_and_nearest},
    {"app_units.clock_keeps_real_time_through_late_frames",
     test_clock_keeps_real_time_through_late_frames},
    {"app_units.clock_forgives_a_stall", test_clock_forgives_a_stall},
    {"app_units.clock_held_to_the_frame_budget", test_clock_held_to_the_frame_budget},
    {"app_units.step_cost_is_planned_from_frames_of_two_steps",
     test_step_cost_is_planned_from_frames_of_two_steps},
    {"app_units.layout_leaves_the_view_free", test_layout_leaves_the_view_free},
    {"app_units.layout_scales_the_ui_with_the_window", test_layout_scales_the_ui_with_the_window},
    {"app_units.energy_drift_from_its_reference", test_energy_drift_from_its_reference},
    {"app_units.energy_drift_chart_window_and_scale", test_energy_drift_chart_window_and_scale},
    {"app_units.energy_drift_scale_is_the_motion_when_e_ref_is_near_zero",
     test_energy_drift_scale_is_the_motion_when_e_ref_is_near_zero},
    {"app_units.energy_drift_text_fits", test_energy_drift_text_fits},
    {"app_units.integrators_by_name", test_integrators_by_name},
    {"app_units.clock_follows_the_scene_timestep", test_clock_follows_the_scene_timestep},
    {"app_units.energy_drift_columns_follow_the_step", test_energy_drift_columns_follow_the_step},
    {"app_units.samples_list_by_category", test_samples_list_by_category},
    {"app_units.stage_chart_keeps_the_frames", test_stage_chart_keeps_the_frames},
    {"app_units.plot_columns_hold_low_and_high", test_plot_columns_hold_low_and_high},
    {"app_units.scene_panel_words", test_scene_panel_words},
    {"app_units.default_scene_is_a_scene_file", test_default_scene_is_a_scene_file},
    {"app_units.round_shapes_drop_round", test_round_shapes_drop_round},
    {"app_units.scene_files_open_and_refusals_keep_the_scene",
     test_scene_files_open_and_refusals_keep_the_scene},
    {"app_units.grabbed_body_destroyed_is_let_go", test_grabbed_body_destroyed_is_let_go},
    {"app_units.energy_counts_springs_and_newton", test_energy_counts_springs_and_newton},
    {"app_units.batch_counts_triangles_of_polygons", test_batch_counts_triangles_of_polygons},
    {"app_units.batch_allocates_nothing_once_warm", test_batch_allocates_nothing_once_warm},
    {"app_units.batch_arrows_and_alpha", test_batch_arrows_and_alpha},
    {"app_units.batch_culls_what_is_out_of_view", test_batch_culls_what_is_out_of_view},
    {"app_units.round_outlines_lie_on_the_boundary", test_round_outlines_lie_on_the_boundary},
    {"app_units.state_log_hash_and_lines", test_state_log_hash_and_lines},
};

int main(void) {
    return app_run_tests(TESTS, sizeof(TESTS) / sizeof(TESTS[0]), NULL);
}
