/*
 * Smoke tests of the real sandbox (./sandbox), driven from outside through
 * its --headless, --script and --screenshot flags: drop bodies, click the
 * panels, press keys, and read the screenshots: body and overlay colours,
 * the container's place, and the side bar's words (found glyph by glyph in
 * the app's own 8x8 font, tests/app_image.c). Also: bad flags and scripts
 * are refused with a message, the README's keys are all in the help, and
 * the documented commands of docs/sandbox-reference.md draw the committed pictures.
 * When the sandbox could not be built (SDL2, SDL2_gfx or SDL2_image missing)
 * every test is reported as skipped with the reason.
 *
 * Run from the repository root (make check does). SANDBOX=path overrides
 * ./sandbox; files go to build/tests/app_smoke.tmp/.
 */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "app_run.h"
#include "scene/samples.h"
#include "jostle/joint.h"
#include "jostle/scene_file.h"

#ifndef APP_SMOKE_HAVE_SDL
#define APP_SMOKE_HAVE_SDL 0
#endif

int app_failures;

/* ---- the tests ---- */

/* Three bodies dropped at x = -8, 0 and 8 m come to rest on the floor: their
 * colours are there, just above the floor, and no longer where they were
 * dropped. */
static void test_dropped_bodies_rest_on_floor(void) {
    run_t run;
    const char *script = "# three bodies, no bounce, 3 s to settle\n"
                         "click -8 8\n"
                         "key b\n"
                         "click 0 8\n"
                         "key p\n"
                         "click 8 8\n"
                         "wait 3s\n"
                         "move px 5 5\n";
    const char *flags[] = {"--elasticity", "0", "--overlays", "none", NULL};
    image_t image;
    world_map_t map;
    if (!run_script("rest", script, flags, &run) || !load_shot("rest", &image)) return;
    EXPECT(image.width == WIDTH && image.height == HEIGHT, "screenshot is %dx%d, not %dx%d",
           image.width, image.height, WIDTH, HEIGHT);
    if (map_world(&image, &map)) {
        int floor_y = px_y(&map, 0.0), drop_y = px_y(&map, 8.0);
        const double columns[3] = {-8.0, 0.0, 8.0};
        for (int i = 0; i < 3; i++) {
            int x = px_x(&map, columns[i]);
            long resting = image_count(&image, is_body_color, x - 25, floor_y - 30, x + 25, floor_y);
            long above = image_count(&image, is_body_color, x - 25, drop_y - 15, x + 25, drop_y + 15);
            EXPECT(resting > 60, "x = %g m: %ld body pixels just above the floor (row %d)",
                   columns[i], resting, floor_y);
            EXPECT(above == 0, "x = %g m: %ld body pixels where it was dropped", columns[i],
                   above);
        }
    }
    image_free(&image);
}

/* A large body dropped near the floor (no bounce), screenshot just after it
 * lands, while it rests there: the axis arrows (yellow) and the fading
 * impulse arrows (magenta) are drawn at the contact. */
static void test_overlays_on_while_colliding(void) {
    run_t run;
    const char *script = "wheel -4\n"       /* size 1.2 -> 0.82 m */
                         "click 0 4\n"      /* lands at 8 m/s after about 49 frames */
                         "wait 56\n"
                         "move px 5 5\n";
    const char *flags[] = {"--elasticity", "0", NULL};
    image_t image;
    world_map_t map;
    if (!run_script("overlays_on", script, flags, &run) || !load_shot("overlays_on", &image)) {
        return;
    }
    if (map_world(&image, &map)) {
        int x0 = px_x(&map, -3), x1 = px_x(&map, 3), y0 = px_y(&map, 3), y1 = px_y(&map, -0.5);
        long bodies = image_count(&image, is_body_color, x0, y0, x1, px_y(&map, 0));
        long axes = image_count(&image, is_axis_color, x0, y0, x1, y1);
        long impulses = image_count(&image, is_impulse_color, x0, y0, x1, y1);
        EXPECT(bodies > 150, "the dropped body is not on the floor (%ld body pixels)", bodies);
        EXPECT(axes > 20, "only %ld axis-coloured pixels at the collision", axes);
        EXPECT(impulses > 20, "only %ld impulse-coloured pixels at the collision", impulses);
    }
    image_free(&image);
}

/* The same drop with the axes and impulses toggled off by their keys: none of
 * their colours anywhere in the view. */
static void test_overlays_off_draw_nothing(void) {
    run_t run;
    const char *script = "key a\n"
                         "key i\n"
                         "wheel -4\n"
                         "click 0 1.5\n"
                         "wait 40\n"
                         "move px 5 5\n";
    const char *flags[] = {"--elasticity", "0", NULL};
    image_t image;
    if (!run_script("overlays_off", script, flags, &run) || !load_shot("overlays_off", &image)) {
        return;
    }
    int view_w = layout_800().view.w;
    long bodies = bodies_in_view(&image);
    long axes = image_count(&image, is_axis_color, 0, 0, view_w, image.height);
    long impulses = image_count(&image, is_impulse_color, 0, 0, view_w, image.height);
    EXPECT(bodies > 150, "the dropped body is not there (%ld body pixels)", bodies);
    EXPECT(axes == 0, "%ld axis-coloured pixels with the axes overlay off", axes);
    EXPECT(impulses == 0, "%ld impulse-coloured pixels with the impulses overlay off", impulses);
    image_free(&image);
}

/* Shift + drag to the right throws the body: it lands in the right half. */
static void test_throw_carries_the_drag_velocity(void) {
    run_t run;
    const char *script = "throw -10 4 -8.5 4 5\n" /* 18 m/s to the right */
                         "wait 2s\n"
                         "move px 5 5\n";
    const char *flags[] = {"--elasticity", "0", "--overlays", "none", NULL};
    image_t image;
    world_map_t map;
    if (!run_script("throw", script, flags, &run) || !load_shot("throw", &image)) return;
    if (map_world(&image, &map)) {
        int middle = px_x(&map, 0.0);
        long left = image_count(&image, is_body_color, 0, 0, px_x(&map, -4), image.height);
        long right = image_count(&image, is_body_color, middle, 0, map.right, image.height);
        EXPECT(right > 60 && left == 0,
               "thrown body: %ld body pixels right of x = 0, %ld left of x = -4 m", right, left);
    }
    image_free(&image);
}

/* Near PALETTE_JOINT (the joints' lines are anti-aliased). */
static bool is_joint_color(const unsigned char *p) {
    palette_rgb_t c = PALETTE_JOINT;
    return abs(p[0] - c.r) < 40 && abs(p[1] - c.g) < 40 && abs(p[2] - c.b) < 40 &&
           p[1] > 160;
}

/* The box of the joint tool's tests, pinned at (2, 8) 2.83 m from its
 * centre: its pixels where it swings (x 0 to 4 m, its centre no lower than
 * 8 - 2.83 = 5.17 m), near the floor, and the joint's pixels. */
static void count_pinned_box(const image_t *image, const world_map_t *map, long *hanging,
                             long *low, long *joint) {
    *hanging = image_count(image, is_body_color, px_x(map, -1), px_y(map, 7), px_x(map, 5),
                           px_y(map, 4.3));
    *low = image_count(image, is_body_color, map->left, px_y(map, 2), map->right, px_y(map, 0));
    *joint = image_count(image, is_joint_color, px_x(map, -1), px_y(map, 8.5), px_x(map, 5),
                         px_y(map, 4.3));
}

/* The joint tool: a box clicked, then a point above it, hangs from that point
 * on a pin and swings below it, the pin drawn; D on the pin deletes the
 * joint and the box falls to the floor. */
static void test_joint_tool_pins_and_deletes(void) {
    const char *pin = "key b\n"
                      "click 4 6\n"
                      "key space\n" /* paused: the box stays where it was dropped */
                      "key w\n"
                      "click 4 6\n"
                      "click 2 8\n"
                      "key space\n"
                      "wait 3s\n";
    const char *flags[] = {"--overlays", "none", "--elasticity", "0", NULL};
    char script[512];
    for (int deleted = 0; deleted < 2; deleted++) {
        snprintf(script, sizeof script, "%s%s", pin,
                 deleted ? "key space\nmove 2 8\nkey d\nkey space\nwait 3s\nmove px 5 5\n"
                         : "move px 5 5\n");
        const char *name = deleted ? "joint_deleted" : "joint_pinned";
        run_t run;
        image_t image;
        world_map_t map;
        if (!run_script(name, script, flags, &run) || !load_shot(name, &image)) return;
        if (map_world(&image, &map)) {
            long hanging, low, joint;
            count_pinned_box(&image, &map, &hanging, &low, &joint);
            if (!deleted) {
                EXPECT(hanging > 60 && low == 0 && joint > 10,
                       "pinned: %ld body pixels where it hangs, %ld near the floor, %ld of the "
                       "joint",
                       hanging, low, joint);
            } else {
                EXPECT(hanging == 0 && low > 60 && joint == 0,
                       "deleted: %ld body pixels where it hung, %ld near the floor, %ld of the "
                       "joint",
                       hanging, low, joint);
            }
        }
        image_free(&image);
    }
}

/* D with the cursor on a body deletes it, and says so. */
static void test_delete_key_removes_body(void) {
    run_t run;
    const char *script = "click 0 2\n"
                         "wait 2s\n"
                         "move 0 0.3\n"
                         "key d\n"
                         "wait 2\n"
                         "move px 5 5\n";
    const char *flags[] = {"--overlays", "none", "--elasticity", "0", NULL};
    image_t image;
    if (!run_script("delete", script, flags, &run) || !load_shot("delete", &image)) return;
    long bodies = bodies_in_view(&image);
    EXPECT(bodies == 0, "%ld body pixels after deleting the only body", bodies);
    EXPECT(shows(&image, "deleted a body", false), "no status line 'deleted a body'");
    image_free(&image);
}

/* At the default and the smallest window size, the default view shows the
 * whole container (floor, both walls to their top) inside the view, clear of
 * the side bar, which shows every panel, all of it within the window. */
static void check_layout(const char *size, int width, int height) {
    run_t run;
    char name[64];
    snprintf(name, sizeof name, "layout_%s", size);
    const char *flags[] = {"--frames", "2", NULL};
    image_t image;
    world_map_t map;
    if (!run_script_at(name, size, "move px 5 5\n", flags, &run) || !load_shot(name, &image)) {
        return;
    }
    layout_t layout = layout_of(width, height);
    EXPECT(image.width == width && image.height == height, "%s: screenshot is %dx%d", size,
           image.width, image.height);
    if (map_world(&image, &map)) {
        EXPECT(map.left >= 2 && map.top >= 2 && map.right < layout.view.w - 2 &&
                   map.bottom < height - 2,
               "%s: the container spans (%d, %d) to (%d, %d): not all inside the %dx%d view",
               size, map.left, map.top, map.right, map.bottom, layout.view.w, height);
        double aspect = (map.right - map.left + 1.0) / (map.bottom - map.top + 1.0);
        EXPECT(fabs(aspect - 30.0 / 31.0) < 0.03,
               "%s: the container is %dx%d pixels, not 30 m x 31 m", size,
               map.right - map.left + 1, map.bottom - map.top + 1);
    }
    const char *panels[] = {"H or F1: every key", "SIMULATION", "SHAPE", "ELASTICITY",
                            "OVERLAYS", "dim sleeping bodies", "INTEGRATOR", "energy drift",
                            "-5 s", "now", "SCENE (PgDn, PgUp; Ctrl+S saves)", "sandbox",
                            "timestep 1/120 s"};
    for (size_t i = 0; i < sizeof panels / sizeof panels[0]; i++) {
        int x, y;
        bool found = image_find_text(&image, panels[i], 0, 0, width, height, &x, &y, NULL);
        EXPECT(found, "%s: no '%s' on screen", size, panels[i]);
        EXPECT(!found || (x >= layout.sidebar.x && y + 8 < height),
               "%s: '%s' at (%d, %d), not in the side bar", size, panels[i], x, y);
    }
    expect_text_inside(&image, size);
    image_free(&image);
}

static void test_default_view_shows_the_container_and_every_panel(void) {
    check_layout("800x600", 800, 600);
    check_layout("1280x720", 1280, 720);
}

/* Clicks all over the side bar (its PLAY page) act on its panels only,
 * even with the container panned behind it; clicks inside the floor and the walls are
 * refused with a message: no body anywhere, the side bar counts none. */
static void test_panel_and_wall_clicks_drop_nothing(void) {
    layout_t layout = layout_800();
    /* Five presses of Left pan the world 300 px right: the container's right
     * half is then behind the side bar, where a click must not reach. */
    char script[16384] = "key left\nkey left\nkey left\nkey left\nkey left\n";
    size_t used = strlen(script);
    const int columns[3] = {layout.sidebar.x + 3, layout.sidebar.x + 130, WIDTH - 4};
    for (int y = 3; y < HEIGHT; y += 12) {
        for (int c = 0; c < 3; c++) {
            /* A click on a tab shows its page: back to PLAY's panels. */
            used += (size_t)snprintf(script + used, sizeof script - used,
                                     "click px %d %d\nkey f2\n", columns[c], y);
        }
    }
    used += (size_t)snprintf(script + used, sizeof script - used,
                             "throw px %d 300 %d 300 5\n" /* a throw inside the side bar */
                             "key 0\nclick 0 -0.5\nscreenshot " TMP_DIR "/refused_floor.bmp\n"
                             "click -14.5 10\nscreenshot " TMP_DIR "/refused_wall.bmp\n"
                             "click -10 -0.9\nclick 14.5 25\nclick 14.9 3\n"
                             "wait 5\nmove px 5 5\n",
                             layout.sidebar.x + 20, WIDTH - 20);
    run_t run;
    image_t image;
    if (!run_script("clicks", script, NULL, &run) || !load_shot("clicks", &image)) return;
    long bodies = bodies_in_view(&image);
    EXPECT(bodies == 0, "%ld body pixels in the view after clicks that drop nothing", bodies);
    char count[40];
    EXPECT(read_line_after(&image, "bodies ", count, 30) && strcmp(count, "0  sleeping 0") == 0,
           "the side bar counts '%s' bodies, not '0  sleeping 0'", count);
    image_free(&image);
    const struct {
        const char *shot, *first, *second;
    } refusals[] = {
        {"refused_floor", "cannot drop inside the floor", NULL},
        {"refused_wall", "cannot drop inside the left wall", NULL},
    };
    for (size_t i = 0; i < sizeof refusals / sizeof refusals[0]; i++) {
        if (!load_shot(refusals[i].shot, &image)) continue;
        int x, y;
        unsigned char color[3];
        bool found = image_find_text(&image, refusals[i].first, layout.sidebar.x, 0, WIDTH,
                                     HEIGHT, &x, &y, color);
        EXPECT(found, "%s: no message '%s'", refusals[i].shot, refusals[i].first);
        EXPECT(!found || same_color(color, PALETTE_WARNING), "%s: the message is not a warning",
               refusals[i].shot);
        if (found && refusals[i].second != NULL) {
            char next[40];
            image_read_text(&image, x, y + LAYOUT_LINE_H, color, next, 30);
            EXPECT(strcmp(next, refusals[i].second) == 0, "%s: second line '%s', not '%s'",
                   refusals[i].shot, next, refusals[i].second);
        }
        image_free(&image);
    }
}

/* The legend says "on" in the overlay's colour and "off" in grey, at the
 * end of each line; a key or a click on the line toggles it. */
static void test_legend_shows_on_and_off(void) {
    run_t run;
    image_t image;
    char state[8];
    unsigned char color[3];
    const char *flags[] = {"--frames", "2", NULL};
    if (!run_script("legend", "move px 5 5\n", flags, &run) || !load_shot("legend", &image)) {
        return;
    }
    if (legend_state(&image, "bounding boxes", state, color)) {
        EXPECT(strcmp(state, "off") == 0 && same_color(color, PALETTE_OFF),
               "bounding boxes at start: '%s' in (%d, %d, %d)", state, color[0], color[1],
               color[2]);
    }
    if (legend_state(&image, "axes", state, color)) {
        EXPECT(strcmp(state, "on") == 0 && same_color(color, PALETTE_AXIS),
               "axes at start: '%s' in (%d, %d, %d)", state, color[0], color[1], color[2]);
    }
    int x, y;
    bool found = image_find_text(&image, "bounding boxes", layout_800().sidebar.x, 0, WIDTH,
                                 HEIGHT, &x, &y, NULL); /* no status line yet */
    image_free(&image);
    if (!found) return;
    char script[256];
    snprintf(script, sizeof script,
             "click px %d %d\nscreenshot " TMP_DIR "/legend_clicked.bmp\nkey x\nkey t\n"
             "move px 5 5\n", x + 20, y + 4);
    if (!run_script("legend_keys", script, NULL, &run)) return;
    if (load_shot("legend_clicked", &image)) {
        if (legend_state(&image, "bounding boxes", state, color)) {
            EXPECT(strcmp(state, "on") == 0 && same_color(color, PALETTE_BOUNDS),
                   "bounding boxes after a click on its line: '%s'", state);
        }
        EXPECT(shows(&image, "bounding boxes on", false), "no status 'bounding boxes on'");
        image_free(&image);
    }
    if (load_shot("legend_keys", &image)) {
        if (legend_state(&image, "bounding boxes", state, color)) {
            EXPECT(strcmp(state, "off") == 0, "bounding boxes after X: '%s'", state);
        }
        if (legend_state(&image, "contact points", state, color)) {
            EXPECT(strcmp(state, "on") == 0 && same_color(color, PALETTE_POINT),
                   "contact points after T: '%s'", state);
        }
        image_free(&image);
    }
}

/* Every change by a key shows what it did on the status line. */
static void test_status_lines_confirm_changes(void) {
    static const struct {
        const char *actions, *expected;
    } steps[] = {
        {"key up", "elasticity of new bodies 0.55"},
        {"wheel 1", "size 1.32 m"},
        {"click -3 2\nclick 3 2\nkey c", "cleared: 2 bodies removed"},
        {"click 0 2\nkey r", "reset: new scene, 1 body"},
        {"key g", "gravity off"},
        {"move 0 5\nkey +", "zoom x1.15"},
        {"key f", "no bodies: the whole container"},
        {"key +\nkey 0", "view: the whole container"},
        {"key s", "one step of 0.008333 s (paused)"},
        {"key ]", "time x1.0"},
        {"key b", "shape: box"},
        {"key 1", "shape: circle"},
        {"key tab", "shape: capsule"},
        {"key e", "E: no body under the cursor"},
    };
    const size_t count = sizeof steps / sizeof steps[0];
    char script[4096] = "";
    size_t used = 0;
    for (size_t i = 0; i < count; i++) {
        used += (size_t)snprintf(script + used, sizeof script - used,
                                 "%s\nscreenshot " TMP_DIR "/status_%zu.bmp\n", steps[i].actions,
                                 i);
    }
    run_t run;
    if (!run_script("status", script, NULL, &run)) return;
    for (size_t i = 0; i < count; i++) {
        char name[32];
        image_t image;
        snprintf(name, sizeof name, "status_%zu", i);
        if (!load_shot(name, &image)) continue;
        EXPECT(shows(&image, steps[i].expected, false), "after '%s': no status line '%s'",
               steps[i].actions, steps[i].expected);
        image_free(&image);
    }
}

/* + zooms about the cursor: a body under the cursor stays under it, larger
 * (it used to zoom about the middle: three presses left an empty grid).
 * The cursor moves away before each screenshot: the shape it would drop is
 * drawn over the body. */
static void test_zoom_keys_zoom_about_the_cursor(void) {
    const char *script = "click 9 1\nwait 2s\nmove px 5 5\n"
                         "screenshot " TMP_DIR "/zoom_before.bmp\nmove 9 0.4\n"
                         "key +\nkey +\nkey +\nkey +\nkey +\nkey +\nmove px 5 5\n";
    const char *flags[] = {"--elasticity", "0", "--overlays", "none", NULL};
    run_t run;
    image_t before, after;
    world_map_t map;
    if (!run_script("zoom", script, flags, &run)) return;
    if (!load_shot("zoom_before", &before)) return;
    if (!load_shot("zoom", &after)) {
        image_free(&before);
        return;
    }
    if (map_world(&before, &map)) {
        int cx = px_x(&map, 9), cy = px_y(&map, 0.4);
        long near_before = image_count(&before, is_body_color, cx - 8, cy - 8, cx + 8, cy + 8);
        long near_after = image_count(&after, is_body_color, cx - 8, cy - 8, cx + 8, cy + 8);
        long all_before = bodies_in_view(&before), all_after = bodies_in_view(&after);
        EXPECT(near_before > 20 && near_after > 100,
               "the body under the cursor: %ld pixels around it before, %ld after", near_before,
               near_after);
        EXPECT(all_after > 3 * all_before, "zoomed x2.3: %ld body pixels, before %ld", all_after,
               all_before);
    }
    image_free(&before);
    image_free(&after);
}

/* Zoomed in far from the bodies: each gets a marker at the view's edge,
 * pointing at it. F then frames them all. */
static void test_edge_markers_and_frame_key(void) {
    const char *script = "click -12 1\nclick 12 1\nwait 2s\nmove 0 20\n"
                         "key +\nkey +\nkey +\nkey +\nkey +\nkey +\nkey +\nkey +\nkey +\nkey +\n"
                         "move px 260 300\nscreenshot " TMP_DIR "/markers.bmp\nkey f\n";
    const char *flags[] = {"--elasticity", "0", "--overlays", "none", NULL};
    run_t run;
    image_t image;
    if (!run_script("frame", script, flags, &run)) return;
    int view_w = layout_800().view.w;
    const int band = 26; /* the markers sit 14 px in, 10 px tip */
    if (load_shot("markers", &image)) {
        long all = bodies_in_view(&image);
        long inner = image_count(&image, is_body_color, band, band, view_w - band, HEIGHT - band);
        long bottom = image_count(&image, is_body_color, 0, HEIGHT - band, view_w, HEIGHT);
        EXPECT(all > 40 && inner == 0 && bottom == all,
               "zoomed away from the bodies: %ld body-coloured pixels, %ld at the bottom edge "
               "(markers), %ld inside",
               all, bottom, inner);
        image_free(&image);
    }
    if (load_shot("frame", &image)) {
        long left = image_count(&image, is_body_color, 0, 0, view_w / 2, HEIGHT);
        long right = image_count(&image, is_body_color, view_w / 2, 0, view_w, HEIGHT);
        EXPECT(left > 100 && right > 100, "after F: %ld body pixels left, %ld right", left,
               right);
        EXPECT(shows(&image, "framed 2 bodies", false), "no status line 'framed 2 bodies'");
        image_free(&image);
    }
}

/* Numbers show "0.00", never "-0.00" (a resting body's momentum), and the
 * side bar's lines stay inside it with four-digit collision counts. */
static void test_text_fits_and_shows_no_negative_zero(void) {
    run_t run;
    image_t image;
    const char *flags[] = {"--elasticity", "0", NULL};
    /* A resting triangle: its momentum's y is a hair below zero. */
    if (run_script("resting", "key 3\nclick 3 1\nwait 5s\nmove px 5 5\n", flags, &run) &&
        load_shot("resting", &image)) {
        char momentum[40];
        EXPECT(read_line_after(&image, "momentum ", momentum, 30) &&
                   strcmp(momentum, "(0.00, 0.00) N s") == 0,
               "a resting triangle's momentum reads '%s'", momentum);
        EXPECT(!shows(&image, "-0.0", true), "'-0.0' on screen");
        image_free(&image);
    }
    const char *pile[] = {"--spawn", "2000", "--frames", "100", NULL};
    if (run_script("pile", "move px 5 5\n", pile, &run) && load_shot("pile", &image)) {
        char line[40];
        unsigned long touching = 0, near = 0;
        bool found = read_line_after(&image, "collisions ", line, 30);
        EXPECT(found && sscanf(line, "%lu (%lu near)", &touching, &near) == 2,
               "no collisions line (read '%s')", found ? line : "");
        EXPECT(touching >= 1000, "only %lu collisions in a pile of 2000 bodies", touching);
        expect_text_inside(&image, "2000 bodies");
        image_free(&image);
    }
}

/* --screenshot x.png writes a real PNG with the frame's pixels (the same as
 * a BMP of the same frame); other extensions are refused. */
static void test_png_screenshots_are_png(void) {
    char script[256];
    snprintf(script, sizeof script, "click 0 5\nwait 10\nscreenshot %s\n",
             tmp_path("same", ".bmp"));
    char png_path[256];
    snprintf(png_path, sizeof png_path, "%s", tmp_path("same", ".png"));
    remove(png_path);
    const char *flags[] = {"--screenshot", png_path, NULL};
    run_t run;
    if (!run_script("png", script, flags, &run)) return;
    char *bytes = read_text_file(png_path);
    EXPECT(bytes != NULL && memcmp(bytes, "\x89PNG\r\n\x1a\n", 8) == 0,
           "%s does not start with the PNG signature", png_path);
    free(bytes);
    image_t png, bmp;
    char why[512];
    if (!image_read(png_path, &png, why, sizeof why)) {
        app_fail("%s", why);
        return;
    }
    if (image_read(tmp_path("same", ".bmp"), &bmp, why, sizeof why)) {
        long differ = image_diff(&png, &bmp, 0, NULL);
        EXPECT(differ == 0, "the PNG and the BMP of one frame differ in %ld pixels", differ);
        image_free(&bmp);
    } else {
        app_fail("%s", why);
    }
    image_free(&png);
}

static void check_refusal(const char *what, const char *const *args, int status,
                          const char *const *expect) {
    run_t run;
    run_sandbox(&run, 20, args);
    if (run.status < 0) return;
    EXPECT(run.status == status, "%s: exit status %d, expected %d; output:\n%s", what,
           run.status, status, run.output);
    for (int i = 0; i < 3 && expect[i] != NULL; i++) {
        EXPECT(strstr(run.output, expect[i]) != NULL, "%s: the message does not say \"%s\":\n%s",
               what, expect[i], run.output);
    }
}

static void test_bad_flags_are_refused(void) {
    const char *unknown[] = {"--headless", "--bogus", NULL};
    const char *e1[] = {"unknown option '--bogus'", "--help", NULL};
    check_refusal("unknown flag", unknown, 2, e1);

    const char *frames[] = {"--headless", "--frames", "lots", NULL};
    const char *e2[] = {"--frames", "'lots'", NULL};
    check_refusal("nonsense --frames", frames, 2, e2);

    const char *negative[] = {"--headless", "--frames", "-3", NULL};
    const char *e2b[] = {"--frames", "'-3'", NULL};
    check_refusal("negative --frames", negative, 2, e2b);

    const char *missing[] = {"--headless", "--screenshot", NULL};
    const char *e3[] = {"--screenshot needs a value", NULL};
    check_refusal("flag without its value", missing, 2, e3);

    const char *size[] = {"--headless", "--size", "12xbig", NULL};
    const char *e4[] = {"--size", "'12xbig'", NULL};
    check_refusal("nonsense --size", size, 2, e4);

    const char *small[] = {"--headless", "--size", "640x480", NULL};
    const char *e4b[] = {"--size", "'640x480'", "800x600", NULL};
    check_refusal("window below 800x600", small, 2, e4b);

    const char *elasticity[] = {"--headless", "--elasticity", "nan", NULL};
    const char *e5[] = {"--elasticity", "'nan'", NULL};
    check_refusal("nonsense --elasticity", elasticity, 2, e5);

    const char *bad_dir[] = {"--headless", "--screenshot", TMP_DIR "/no/such/dir/x.png", NULL};
    const char *e6[] = {"cannot save the screenshot", "no/such/dir/x.png", NULL};
    check_refusal("unwritable screenshot", bad_dir, 1, e6);

    const char *integrator[] = {"--headless", "--integrator", "leapfrog", NULL};
    const char *e8[] = {"--integrator: 'leapfrog'",
                        "seed, explicit_euler, symplectic_euler, velocity_verlet, rk4, "
                        "symplectic4, implicit_euler", NULL};
    check_refusal("unknown integrator", integrator, 2, e8);

    const char *jpeg[] = {"--headless", "--screenshot", TMP_DIR "/x.jpg", NULL};
    const char *e7[] = {"--screenshot", "x.jpg", "must end in .png or .bmp"};
    check_refusal("screenshot of an unknown format", jpeg, 2, e7);
    EXPECT(access(TMP_DIR "/x.jpg", F_OK) != 0, "x.jpg was written all the same");

    run_t run;
    const char *help[] = {"--help", NULL};
    run_sandbox(&run, 20, help);
    EXPECT(run.status == 0, "--help exited with %d", run.status);
    const char *documented[] = {"--headless", "--frames", "--screenshot", "--script", ".png",
                                "--integrator", "symplectic_euler", "wait", "click", "throw",
                                "screenshot", "FILE.scene", "FILE:LINE:COLUMN", "--save-dir",
                                "PageDown", "open FILE", "pagedown"};
    for (size_t i = 0; i < sizeof documented / sizeof documented[0]; i++) {
        EXPECT(strstr(run.output, documented[i]) != NULL, "--help does not mention %s",
               documented[i]);
    }
}

static void test_bad_scripts_are_refused(void) {
    const char *missing[] = {"--headless", "--script", TMP_DIR "/no_such_script.txt", NULL};
    const char *e1[] = {"cannot open script", "no_such_script.txt", "No such file"};
    check_refusal("missing script", missing, 2, e1);

    const char *directory[] = {"--headless", "--script", TMP_DIR, NULL};
    const char *e2[] = {"cannot read script", "app_smoke.tmp", "is a directory"};
    check_refusal("a directory as the script", directory, 2, e2);

    struct {
        const char *name;
        const char *text;
        const char *expect[3];
    } cases[] = {
        {"typo", "click 0 5\nclik 1 2\n", {":2:", "unknown command 'clik'", NULL}},
        {"number", "# a comment\n\nwait soon\n", {":3:", "'soon'", NULL}},
        {"arguments", "click 1\n", {":1:", "'click' needs 2 coordinates", NULL}},
        {"key", "key nosuchkey\n", {":1:", "unknown key 'nosuchkey'", NULL}},
        {"range", "wheel 5\nspawn 999999\n", {":2:", "spawn count", NULL}},
        {"button", "drag sideways 0 0 1 1\n", {":1:", "mouse button 'sideways'", NULL}},
        {"format", "wait 2\nscreenshot shot.gif\n", {":2:", "'shot.gif'", ".png or .bmp"}},
        {"open", "wait 2\nopen\n", {":2:", "'open' needs one file name", NULL}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char name[64];
        snprintf(name, sizeof name, "bad_%s", cases[i].name);
        char path[256];
        snprintf(path, sizeof path, "%s", tmp_path(name, ".txt"));
        if (!write_file(path, cases[i].text)) continue;
        const char *args[] = {"--headless", "--script", path, NULL};
        char what[96];
        snprintf(what, sizeof what, "malformed script (%s)", cases[i].name);
        check_refusal(what, args, 2, cases[i].expect);
    }
}

/* Every key in the README's table of keys is in --help's list and on the
 * help screen (H), which fits the smallest window. */
static void test_help_lists_every_readme_key(void) {
    char *readme = read_text_file("README.md");
    if (readme == NULL) return;
    run_t run;
    const char *help[] = {"--help", NULL};
    run_sandbox(&run, 20, help);
    const char *keys = strstr(run.output, "Keys and mouse in the app");
    const char *table = strstr(readme, "| Keys / mouse | What it does |");
    EXPECT(keys != NULL, "--help lists no keys");
    EXPECT(table != NULL, "README.md has no table of keys");
    size_t checked = 0;
    if (keys != NULL && table != NULL) {
        const char *end = strstr(table, "\n\n");
        /* Each `key` in the first column of each row. */
        for (const char *row = strchr(table, '\n'); row != NULL && (end == NULL || row < end);
             row = strchr(row + 1, '\n')) {
            const char *cell_end = strchr(row + 3, '|');
            for (const char *tick = strchr(row, '`'); tick != NULL && cell_end != NULL &&
                                                      tick < cell_end;) {
                const char *close = strchr(tick + 1, '`');
                if (close == NULL || close > cell_end) break;
                char key[32];
                snprintf(key, sizeof key, "%.*s", (int)(close - tick - 1), tick + 1);
                EXPECT(strstr(keys, key) != NULL, "--help does not list the README's key '%s'",
                       key);
                checked++;
                tick = strchr(close + 1, '`');
            }
        }
    }
    EXPECT(checked >= 30, "only %zu keys found in the README's table", checked);
    /* docs/sandbox.md lists the same keys, word for word. */
    char *doc = read_text_file("docs/sandbox.md");
    if (table != NULL && doc != NULL) {
        const char *end = strstr(table, "\n\n");
        size_t length = end != NULL ? (size_t)(end - table) : strlen(table);
        char *copy = malloc(length + 1);
        memcpy(copy, table, length);
        copy[length] = '\0';
        EXPECT(strstr(doc, copy) != NULL,
               "docs/sandbox.md's table of keys differs from the README's");
        free(copy);
    }
    free(doc);
    free(readme);
    image_t image;
    const char *script = "key h\nmove px 5 5\nscreenshot " TMP_DIR "/help_open.bmp\n"
                         "click 0 5\nwait 30\nmove px 5 5\n";
    if (run_script("help", script, NULL, &run) && load_shot("help_open", &image)) {
        /* At 800x600 the longer keys wrap: their first lines. */
        const char *lines[] = {"SANDBOX CONTROLS", "Ctrl + left click, D,",
                               "frame every body", "N / Shift + N", "Z / Shift + Z",
                               "PageDown / PageUp", "Ctrl + S", "Game: Left / Right, A",
                               "Game: Space", "Esc, Q"};
        for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
            EXPECT(shows(&image, lines[i], true), "the help screen lacks '%s'", lines[i]);
        }
        image_free(&image);
    }
    /* A click on the help closes it and drops nothing behind it. */
    if (load_shot("help", &image)) {
        EXPECT(!shows(&image, "SANDBOX CONTROLS", true), "a click left the help open");
        EXPECT(bodies_in_view(&image) == 0, "a click on the help dropped a body");
        image_free(&image);
    }
}

/* ---- the INTEGRATOR panel and sleeping bodies ---- */

/* The INTEGRATOR panel shows `name` (in the accent colour) with `position`
 * ("3 of 7") and `springs` (in red when unstable). */
static void expect_integrator(const image_t *image, const char *what, const char *name,
                              const char *position, const char *springs, bool unstable) {
    unsigned char color[3];
    int x, y;
    EXPECT(find_in_panel(image, "INTEGRATOR", name, &x, &y, color) &&
               same_color(color, PALETTE_ACCENT),
           "%s: the INTEGRATOR panel does not name '%s'", what, name);
    EXPECT(find_in_panel(image, "INTEGRATOR", position, NULL, NULL, NULL),
           "%s: the INTEGRATOR panel does not say '%s'", what, position);
    bool found = find_in_panel(image, "INTEGRATOR", springs, NULL, NULL, color);
    EXPECT(found, "%s: the INTEGRATOR panel does not say '%s'", what, springs);
    EXPECT(!found || same_color(color, unstable ? PALETTE_WARNING : PALETTE_TEXT),
           "%s: '%s' in (%d, %d, %d)", what, springs, color[0], color[1], color[2]);
}

/* N and Shift+N switch the integrator while the scene runs, round the seven,
 * each confirmed on the status line; --integrator picks one by name. */
static void test_integrator_key_switches_live(void) {
    const char *script = "move px 5 5\nscreenshot " TMP_DIR "/integrator_0.bmp\n"
                         "key n\nscreenshot " TMP_DIR "/integrator_1.bmp\n"
                         "key n\nscreenshot " TMP_DIR "/integrator_2.bmp\n"
                         "key shift+n\nkey shift+n\nkey shift+n\n";
    run_t run;
    image_t image;
    if (!run_script("integrator", script, NULL, &run)) return;
    if (load_shot("integrator_0", &image)) {
        expect_integrator(&image, "at start", "seed", "1 of 7", "unstable with springs", true);
        image_free(&image);
    }
    if (load_shot("integrator_1", &image)) {
        expect_integrator(&image, "after N", "explicit Euler", "2 of 7", "unstable with springs",
                          true);
        EXPECT(shows(&image, "integrator: explicit Euler", false),
               "after N: no status line 'integrator: explicit Euler'");
        image_free(&image);
    }
    if (load_shot("integrator_2", &image)) {
        expect_integrator(&image, "after N N", "symplectic Euler", "3 of 7",
                          "stable for w dt < 2.00", false);
        EXPECT(shows(&image, "integrator: symplectic Euler", false) &&
                   shows(&image, "(stable for w dt < 2.00)", false),
               "after N N: no status line 'integrator: symplectic Euler (stable for w dt < "
               "2.00)'");
        image_free(&image);
    }
    if (load_shot("integrator", &image)) {
        expect_integrator(&image, "after three Shift+N", "implicit Euler", "7 of 7",
                          "stable for any w dt", false);
        image_free(&image);
    }
    const char *names[][4] = {{"Velocity_Verlet", "velocity Verlet", "4 of 7", "2.00"},
                              {"rk4", "RK4", "5 of 7", "2.83"},
                              {"symplectic euler", "symplectic Euler", "3 of 7", "2.00"}};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        const char *flags[] = {"--integrator", names[i][0], NULL};
        char what[64], springs[40];
        snprintf(what, sizeof what, "--integrator '%s'", names[i][0]);
        snprintf(springs, sizeof springs, "stable for w dt < %s", names[i][3]);
        if (run_script("integrator_flag", "move px 5 5\n", flags, &run) &&
            load_shot("integrator_flag", &image)) {
            expect_integrator(&image, what, names[i][1], names[i][2], springs, false);
            image_free(&image);
        }
    }
}

/* The drift readout beside "energy drift", as a number (percent). */
static bool read_drift(const image_t *image, double *percent, char *text, size_t max) {
    int x, y;
    text[0] = '\0';
    if (!find_in_panel(image, "INTEGRATOR", "energy drift", &x, &y, NULL)) return false;
    const unsigned char c[3] = {PALETTE_DRIFT.r, PALETTE_DRIFT.g, PALETTE_DRIFT.b};
    image_read_text(image, x, y, c, text, max);
    return sscanf(text, "%lf", percent) == 1;
}

static bool is_drift_color(const unsigned char *p) {
    return same_color(p, PALETTE_DRIFT);
}

static bool is_mark_color(const unsigned char *p) {
    return same_color(p, PALETTE_CHART_MARK);
}

/* The chart's plot: its left column, top and bottom rows (from the "-5 s"
 * label under its left edge). */
typedef struct {
    int left, right, top, mid, bottom;
} plot_t;

static bool find_plot(const image_t *image, plot_t *plot) {
    int x, y;
    if (!find_in_panel(image, "INTEGRATOR", "-5 s", &x, &y, NULL)) {
        app_fail("no '-5 s' under the drift chart");
        return false;
    }
    plot->left = x;
    plot->right = x + 199;
    plot->bottom = y - 4;
    plot->top = plot->bottom - 60;
    plot->mid = plot->top + 30;
    return true;
}

/* A body falls freely for 1.5 s under each scheme (dropped anew after C):
 * the seed integrator keeps its energy (a flat line on the zero row, the
 * smallest scale), explicit Euler gains energy and symplectic Euler loses it
 * (E changes by +-m g^2 dt^2 / 2 a step: about 0.25% of the drop's energy),
 * drawn above and below the zero line on a scale that widened to 0.5%. A
 * switch with the body falling takes a new reference, marked on the chart. */
static void test_energy_drift_chart_tells_the_schemes_apart(void) {
    const char *script = "click 0 25\nwait 90\nmove px 5 5\n"
                         "screenshot " TMP_DIR "/drift_seed.bmp\n"
                         "key c\nkey n\nclick 0 25\nwait 90\nmove px 5 5\n"
                         "screenshot " TMP_DIR "/drift_explicit.bmp\n"
                         "key c\nkey n\nclick 0 25\nwait 90\nmove px 5 5\n"
                         "screenshot " TMP_DIR "/drift_symplectic.bmp\n"
                         "key n\nwait 2\n";
    const char *flags[] = {"--elasticity", "0", NULL};
    run_t run;
    if (!run_script("drift", script, flags, &run)) return;
    const struct {
        const char *shot, *scheme, *scale;
        double low, high; /* the readout (%) */
        int sign;         /* where the newest 1.4 s of the chart are: above zero (1), below, on it */
    } cases[] = {
        {"drift_seed", "seed", "+0.01%", -0.0005, 0.0005, 0},
        {"drift_explicit", "explicit Euler", "+0.5%", 0.2, 0.3, 1},
        {"drift_symplectic", "symplectic Euler", "+0.5%", -0.3, -0.2, -1},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        image_t image;
        if (!load_shot(cases[i].shot, &image)) continue;
        double percent = NAN;
        char text[40];
        bool read = read_drift(&image, &percent, text, 32);
        EXPECT(read && percent >= cases[i].low && percent <= cases[i].high,
               "%s: the drift reads '%s', expected %g%% to %g%%", cases[i].scheme, text,
               cases[i].low, cases[i].high);
        EXPECT(find_in_panel(&image, "INTEGRATOR", cases[i].scale, NULL, NULL, NULL),
               "%s: the chart's scale is not %s", cases[i].scheme, cases[i].scale);
        plot_t plot;
        if (find_plot(&image, &plot)) {
            int x0 = plot.right - 56, x1 = plot.right - 4; /* 0.1 s to 1.4 s ago */
            long above = image_count(&image, is_drift_color, x0, plot.top, x1, plot.mid);
            long on = image_count(&image, is_drift_color, x0, plot.mid, x1, plot.mid + 1);
            long below = image_count(&image, is_drift_color, x0, plot.mid + 1, x1,
                                     plot.bottom + 1);
            long expected_above = cases[i].sign > 0, expected_below = cases[i].sign < 0;
            EXPECT((expected_above ? above > 30 : above == 0) &&
                       (expected_below ? below > 30 : below == 0) &&
                       (cases[i].sign != 0 || on > 40),
                   "%s: the chart's last 1.3 s: %ld drift pixels above zero, %ld on it, %ld "
                   "below", cases[i].scheme, above, on, below);
        }
        image_free(&image);
    }
    image_t image;
    if (load_shot("drift", &image)) {
        double percent = NAN;
        char text[40];
        EXPECT(read_drift(&image, &percent, text, 32) && fabs(percent) < 0.01,
               "right after switching to velocity Verlet the drift reads '%s', not about 0",
               text);
        plot_t plot;
        if (find_plot(&image, &plot)) {
            long marks = image_count(&image, is_mark_color, plot.right - 3, plot.top,
                                     plot.right + 1, plot.bottom + 1);
            EXPECT(marks >= 40, "no mark of the new reference at the chart's right edge (%ld "
                   "pixels)", marks);
        }
        image_free(&image);
    }
}

static bool is_dimmed_body_color(const unsigned char *p) {
    for (int i = 0; i < PALETTE_BODY_COUNT; i++) {
        if (same_color(p, palette_sleeping(PALETTE_BODIES[i]))) return true;
    }
    return false;
}

static long dimmed_in_view(const image_t *image) {
    return image_count(image, is_dimmed_body_color, 0, 0,
                       layout_of(image->width, image->height).view.w, image->height);
}

/* Three bodies come to rest and fall asleep: they are drawn dimmer and the
 * side bar counts them; Z turns the tint off and on; Shift+Z turns sleeping
 * off (every body awake, bright) and on again. */
static void test_sleeping_bodies_drawn_dimmer(void) {
    const char *script = "click -6 1\nclick 0 1\nkey b\nclick 6 1\nwait 3s\nmove px 5 5\n"
                         "screenshot " TMP_DIR "/sleep_dim.bmp\n"
                         "key z\nscreenshot " TMP_DIR "/sleep_tint_off.bmp\n"
                         "key z\nkey shift+z\nwait 2\nscreenshot " TMP_DIR "/sleep_off.bmp\n"
                         "key shift+z\nwait 3s\n";
    const char *flags[] = {"--elasticity", "0", NULL};
    run_t run;
    if (!run_script("sleep", script, flags, &run)) return;
    const struct {
        const char *shot, *what, *bodies, *status, *legend;
        bool dim;
    } cases[] = {
        {"sleep_dim", "at rest", "3  sleeping 3", NULL, "on", true},
        {"sleep_tint_off", "after Z", "3  sleeping 3", "dim sleeping bodies off", "off", false},
        {"sleep_off", "after Z, Shift+Z", "3  sleeping off", "sleeping off: every body awake",
         "on", false},
        {"sleep", "after Shift+Z and 3 s", "3  sleeping 3", NULL, "on", true},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        image_t image;
        if (!load_shot(cases[i].shot, &image)) continue;
        char line[40] = "";
        int x, y;
        unsigned char text_color[3];
        /* Under SIMULATION: the status line may say "bodies" too. */
        if (find_in_panel(&image, "SIMULATION", "bodies ", &x, &y, text_color)) {
            image_read_text(&image, x + 8 * 7, y, text_color, line, 30);
        }
        EXPECT(strcmp(line, cases[i].bodies) == 0,
               "%s: the side bar reads 'bodies %s', expected 'bodies %s'", cases[i].what, line,
               cases[i].bodies);
        long dim = dimmed_in_view(&image), bright = bodies_in_view(&image);
        EXPECT(cases[i].dim ? dim > 300 && bright == 0 : dim == 0 && bright > 300,
               "%s: %ld pixels of dimmed body colours, %ld of bright ones", cases[i].what, dim,
               bright);
        if (cases[i].status != NULL) {
            EXPECT(shows(&image, cases[i].status, false), "%s: no status line '%s'",
                   cases[i].what, cases[i].status);
        }
        char state[8];
        unsigned char color[3];
        if (legend_state(&image, "dim sleeping bodies", state, color)) {
            bool on = strcmp(cases[i].legend, "on") == 0;
            EXPECT(strcmp(state, cases[i].legend) == 0 &&
                       same_color(color, on ? PALETTE_SLEEPING : PALETTE_OFF),
                   "%s: the legend says '%s' in (%d, %d, %d), expected '%s'", cases[i].what,
                   state, color[0], color[1], color[2], cases[i].legend);
        }
        image_free(&image);
    }
}

/* ---- scene files, samples, saving and games ---- */

/* Whether the file names a game that the player controls (the pegs board
 * takes no input: its keys stay the sandbox's). */
/* Whether the file names a game that takes the player's keys: not the pegs
 * board nor the double pendulum's plot but the car's (app/games/). */
static bool is_scene_game(const char *path) {
    static const char *const NO_INPUT[] = {"pegs", "double_pendulum"};
    scene_file_error_t error;
    scene_file_t *file = scene_file_load(path, &error);
    bool game = file != NULL && scene_file_get_game(file)[0] != '\0';
    for (size_t i = 0; game && i < sizeof NO_INPUT / sizeof NO_INPUT[0]; i++) {
        game = strcmp(scene_file_get_game(file), NO_INPUT[i]) != 0;
    }
    scene_file_free(file);
    return game;
}

static bool is_background_or_grid(const unsigned char *p) {
    return same_color(p, PALETTE_BACKGROUND) || same_color(p, PALETTE_GRID);
}

static bool is_drawn(const unsigned char *p) {
    return !is_background_or_grid(p);
}

/* Every sample file opens from the command line, headless, and draws: its
 * name and place in the SCENE panel, its bodies in the view; a game the
 * player controls says its keys. */
static void test_samples_open_from_the_command_line(void) {
    static samples_t samples;
    samples_load(&samples, "assets/scenes", "sandbox", NULL);
    EXPECT(samples.count >= 12, "only %zu samples with assets/scenes", samples.count);
    for (size_t i = 1; i < samples.count; i++) {
        const char *path = samples.items[i].path, *name = samples.items[i].name;
        char shot_name[80], shot[256];
        snprintf(shot_name, sizeof shot_name, "sample_%s", name);
        snprintf(shot, sizeof shot, "%s", tmp_path(shot_name, ".bmp"));
        remove(shot);
        const char *args[] = {"--headless", "--size", SIZE_FLAG, "--frames", "30",
                              path, "--screenshot", shot, NULL};
        run_t run;
        run_sandbox(&run, 60, args);
        if (run.status != 0) {
            app_fail("%s: exit status %d:\n%s", path, run.status, run.output);
            continue;
        }
        image_t image;
        if (!load_shot(shot_name, &image)) continue;
        char shown[40];
        EXPECT(scene_name(&image, shown, 30) && strcmp(shown, name) == 0,
               "%s: the SCENE panel names '%s'", path, shown);
        char position[32];
        snprintf(position, sizeof position, "%zu of %zu", i + 1, samples.count);
        EXPECT(find_in_panel(&image, "SCENE (", position, NULL, NULL, NULL),
               "%s: the SCENE panel does not say '%s'", path, position);
        long drawn = image_count(&image, is_drawn, 0, 0, layout_800().view.w, HEIGHT);
        EXPECT(drawn > 300, "%s: %ld pixels drawn in the view", path, drawn);
        bool game = is_scene_game(path), car = strstr(path, "joint_car") != NULL;
        const char *keys = car ? "GAME KEYS: Left/Right, A/D drive" : "GAME KEYS: Left/Right, A/D move";
        EXPECT(game == shows(&image, keys, false), "%s: %s game, and the side bar %s its keys",
               path, game ? "a" : "no", game ? "does not show" : "shows");
        /* The car has nothing to fire: its hint says what its keys do. */
        EXPECT(!car || (shows(&image, "the wheels; Enter pauses", false) &&
                        !shows(&image, "Space fires", false)),
               "%s: the side bar does not say the car's keys drive its wheels", path);
        expect_text_inside(&image, name);
        image_free(&image);
    }
    samples_free(&samples);
}

/* PageDown goes through the default scene and every sample in the browser's
 * order, and round to the default scene; PageUp goes back, round to the
 * last sample. Each opens with its name in the SCENE panel and on the
 * status line. */
static void test_scene_keys_cycle_through_the_samples(void) {
    static samples_t samples;
    samples_load(&samples, "assets/scenes", "sandbox", NULL);
    size_t count = samples.count;
    char script[8192] = "move px 5 5\nscreenshot " TMP_DIR "/cycle_0.bmp\n";
    size_t used = strlen(script);
    for (size_t k = 1; k <= count; k++) {
        used += (size_t)snprintf(script + used, sizeof script - used,
                                 "key pagedown\nwait 1\nscreenshot " TMP_DIR "/cycle_%zu.bmp\n",
                                 k);
    }
    used += (size_t)snprintf(script + used, sizeof script - used, "key pageup\nwait 1\n");
    run_t run;
    if (!run_script("cycle", script, NULL, &run)) {
        samples_free(&samples);
        return;
    }
    for (size_t k = 0; k <= count + 1; k++) {
        char shot_name[32];
        if (k <= count) snprintf(shot_name, sizeof shot_name, "cycle_%zu", k);
        else snprintf(shot_name, sizeof shot_name, "cycle");
        /* k presses of PageDown (the last: PageDown round, then PageUp). */
        size_t index = k <= count ? k % count : count - 1;
        const char *expected = samples.items[index].name;
        image_t image;
        if (!load_shot(shot_name, &image)) continue;
        char shown[40];
        EXPECT(scene_name(&image, shown, 30) && strcmp(shown, expected) == 0,
               "after %zu keys the SCENE panel names '%s', expected '%s'", k, shown, expected);
        char opened[80];
        snprintf(opened, sizeof opened, "opened %s", expected);
        EXPECT(k == 0 || shows(&image, opened, false), "after %zu keys no status '%s'", k,
               opened);
        image_free(&image);
    }
    samples_free(&samples);
}

/* A refused file on the command line: its FILE:LINE:COLUMN message and
 * status 2. In the app (a file dropped on the window), the message as a
 * warning, and the open scene as it was. */
static void test_bad_scene_files_are_refused(void) {
    const char *bad = TMP_DIR "/bad.scene";
    if (!write_file(bad, "body a { box 1 1 }\nbody b { regular 3 -1 }\n")) return;
    const char *args[] = {"--headless", bad, NULL};
    const char *e1[] = {TMP_DIR "/bad.scene:2:20: expected the radius (m), a number > 0 and <= "
                        "1e+09, found \"-1\"", NULL};
    check_refusal("a malformed scene file", args, 2, e1);

    const char *missing[] = {"--headless", TMP_DIR "/no_such.scene", NULL};
    const char *e2[] = {TMP_DIR "/no_such.scene: cannot read", NULL};
    check_refusal("a missing scene file", missing, 2, e2);

    const char *no_paddle = TMP_DIR "/no_paddle.scene";
    if (write_file(no_paddle, "game breakout\nbody ball { regular 8 0.2; velocity 1 1 }\n")) {
        const char *game[] = {"--headless", no_paddle, NULL};
        const char *e3[] = {"no_paddle.scene: breakout: the scene has no body named paddle",
                            NULL};
        check_refusal("a game that lacks its paddle", game, 2, e3);
    }
    const char *two[] = {"--headless", "assets/scenes/pegs.scene", "assets/scenes/pyramid.scene",
                         NULL};
    const char *e4[] = {"one scene file at a time", NULL};
    check_refusal("two scene files", two, 2, e4);

    /* In the app: the pyramid stays. */
    char script[256];
    snprintf(script, sizeof script, "move px 5 5\nwait 10\nopen %s\nwait 2\n", bad);
    const char *flags[] = {"assets/scenes/pyramid.scene", NULL};
    run_t run;
    image_t image;
    if (!run_script("bad_open", script, flags, &run) || !load_shot("bad_open", &image)) return;
    EXPECT(strstr(run.output, "bad.scene:2:20: expected the radius") != NULL,
           "no message on stderr:\n%s", run.output);
    int x, y;
    unsigned char color[3];
    bool found = image_find_text(&image, "cannot open bad.scene:2:20:", layout_800().sidebar.x,
                                 0, WIDTH, HEIGHT, &x, &y, color);
    EXPECT(found && same_color(color, PALETTE_WARNING),
           "no warning 'cannot open bad.scene:2:20:' on the status line");
    if (found) {
        char next[40];
        image_read_text(&image, x, y + LAYOUT_LINE_H, color, next, 32);
        EXPECT(strcmp(next, "expected the radius (m), a") == 0, "the message goes on '%s'",
               next);
    }
    char shown[40], bodies[40];
    EXPECT(scene_name(&image, shown, 30) && strcmp(shown, "pyramid") == 0,
           "after a refused file the SCENE panel names '%s', not pyramid", shown);
    unsigned long count = 0;
    EXPECT(read_line_after(&image, "bodies ", bodies, 30) && sscanf(bodies, "%lu", &count) == 1 &&
               count == 55,
           "after a refused file the side bar counts 'bodies %s', not the pyramid's 55", bodies);
    image_free(&image);
}

/* The number of bodies of a scene file, or -1 (with the message) when it does
 * not load. */
static long scene_file_bodies(const char *path, char *game, size_t game_size) {
    scene_file_error_t error;
    scene_file_t *file = scene_file_load(path, &error);
    if (file == NULL) {
        app_fail("%s", error.message);
        return -1;
    }
    long bodies = (long)scene_bodies(scene_file_get_scene(file));
    if (game != NULL) snprintf(game, game_size, "%s", scene_file_get_game(file));
    scene_file_free(file);
    return bodies;
}

/* Ctrl+S writes the scene to the first free saved-N.scene (never over a file
 * already there), says where, and the file loads back with the same bodies:
 * the default scene with three bodies dropped in it, and Breakout, which
 * still names its game. */
static void test_save_writes_scenes_that_load_back(void) {
    const char *dir = TMP_DIR "/saves";
    mkdir(dir, 0755);
    char path[256];
    for (int n = 1; n <= 6; n++) {
        snprintf(path, sizeof path, "%s/saved-%d.scene", dir, n);
        remove(path);
    }
    snprintf(path, sizeof path, "%s/saved-1.scene", dir);
    if (!write_file(path, "# someone else's\n")) return;
    const char *script = "click -5 3\nclick 0 3\nkey b\nclick 5 3\nwait 30\nkey ctrl+s\n"
                         "move px 5 5\nscreenshot " TMP_DIR "/save_default.bmp\n"
                         "open assets/scenes/breakout.scene\nwait 30\nkey ctrl+s\n"
                         "screenshot " TMP_DIR "/save_game.bmp\nkey ctrl+s\nwait 1\n";
    const char *flags[] = {"--save-dir", dir, NULL};
    run_t run;
    if (!run_script("save", script, flags, &run)) return;
    char *mine = read_text_file(path);
    EXPECT(mine != NULL && strcmp(mine, "# someone else's\n") == 0,
           "saved-1.scene, which was there before, was replaced");
    free(mine);
    image_t image;
    if (load_shot("save_default", &image)) {
        EXPECT(shows(&image, "saved-2.scene (3 bodies, 3", false),
               "no status line '... saved-2.scene (3 bodies, 3 static)'");
        image_free(&image);
    }
    char game[64];
    snprintf(path, sizeof path, "%s/saved-2.scene", dir);
    long bodies = scene_file_bodies(path, NULL, 0);
    EXPECT(bodies == 6, "saved-2.scene (the default scene and 3 drops) holds %ld bodies", bodies);
    long breakout = scene_file_bodies("assets/scenes/breakout.scene", NULL, 0);
    for (int n = 3; n <= 4; n++) {
        snprintf(path, sizeof path, "%s/saved-%d.scene", dir, n);
        bodies = scene_file_bodies(path, game, sizeof game);
        EXPECT(bodies == breakout && strcmp(game, "breakout") == 0,
               "saved-%d.scene (Breakout after 0.5 s) holds %ld bodies, not %ld, and the game "
               "'%s'", n, bodies, breakout, game);
    }
    snprintf(path, sizeof path, "%s/saved-5.scene", dir);
    EXPECT(access(path, F_OK) != 0, "three presses of Ctrl+S wrote a fourth file");
    if (load_shot("save_game", &image)) {
        EXPECT(shows(&image, "saved-3.scene (1 body, 54", false),
               "no status line '... saved-3.scene (1 body, 54 static)'");
        image_free(&image);
    }
}

/* A pin made with the joint tool is saved by Ctrl+S: the file holds it
 * (a revolute joint from the world at the clicked point (2, 8) to the box),
 * and opened again the box hangs from it, swinging as it did, the pin
 * drawn; without the joint it would lie on the floor. */
static void test_joint_tool_pin_is_saved_and_reloaded(void) {
    const char *dir = TMP_DIR "/joint_saves";
    mkdir(dir, 0755);
    char path[256];
    snprintf(path, sizeof path, "%s/saved-1.scene", dir);
    remove(path);
    char script[1024];
    snprintf(script, sizeof script,
             "key b\nclick 4 6\nkey space\nkey w\nclick 4 6\nclick 2 8\nkey space\n"
             "wait 30\nkey ctrl+s\nopen %s\nwait 3s\nmove px 5 5\n",
             path);
    const char *flags[] = {"--overlays", "none", "--elasticity", "0", "--save-dir", dir, NULL};
    run_t run;
    if (!run_script("joint_reloaded", script, flags, &run)) return;
    scene_file_error_t error;
    scene_file_t *file = scene_file_load(path, &error);
    EXPECT(file != NULL, "the saved file does not load: %s", file ? "" : error.message);
    if (file == NULL) return;
    scene_t *scene = scene_file_get_scene(file);
    EXPECT(scene_joints(scene) == 1, "the saved file holds %zu joints, not 1", scene_joints(scene));
    if (scene_joints(scene) == 1) {
        joint_t *joint = scene_get_joint(scene, 0);
        joint_def_t def = joint_get_def(joint);
        EXPECT(def.type == JOINT_REVOLUTE && def.body1 == NULL &&
                   fabs(def.anchor1.x - 2.0) < 0.05 && fabs(def.anchor1.y - 8.0) < 0.05,
               "the saved joint is a %s from %s at (%g, %g), not a pin from the world at (2, 8)",
               joint_type_name(def.type), def.body1 == NULL ? "the world" : "a body",
               def.anchor1.x, def.anchor1.y);
    }
    scene_file_free(file);
    image_t image;
    world_map_t map;
    if (!load_shot("joint_reloaded", &image)) return;
    if (map_world(&image, &map)) {
        long hanging, low, joint;
        count_pinned_box(&image, &map, &hanging, &low, &joint);
        EXPECT(hanging > 60 && low == 0 && joint > 10,
               "reloaded: %ld body pixels where it hangs, %ld near the floor, %ld of the joint",
               hanging, low, joint);
    }
    image_free(&image);
}

/* Near a colour (the game bodies' colours go through rounding). */
static bool near_color(const unsigned char *p, int r, int g, int b) {
    return abs(p[0] - r) <= 2 && abs(p[1] - g) <= 2 && abs(p[2] - b) <= 2;
}

static bool is_paddle(const unsigned char *p) {
    return near_color(p, 217, 217, 230); /* color 0.85 0.85 0.9 */
}

static bool is_red_brick(const unsigned char *p) {
    return near_color(p, 230, 77, 77); /* color 0.90 0.30 0.30 */
}

static bool is_gun(const unsigned char *p) {
    return near_color(p, 102, 230, 128); /* color 0.4 0.9 0.5 */
}

static bool is_white(const unsigned char *p) {
    return p[0] == 255 && p[1] == 255 && p[2] == 255;
}

/* The middle column of the pixels passing test in the view; -1 if none. */
static double middle_x(const image_t *image, image_color_test_t test) {
    int x0, y0, x1, y1;
    if (!image_bounds(image, test, &x0, &y0, &x1, &y1)) return -1.0;
    return 0.5 * (x0 + x1);
}

/* In Breakout, Right and A move the paddle (and no longer pan the view),
 * Space does not pause (it fires) but Enter does; the side bar shows the
 * score, the lives, the bricks and the keys, and the help screen says they
 * come first; the overlays are off. In Space
 * Invaders, Left moves the gun and Space fires a shot. */
static void test_games_respond_to_their_keys(void) {
    const char *script = "key h\nscreenshot " TMP_DIR "/game_help.bmp\nkey h\n"
                         "move px 700 300\nscreenshot " TMP_DIR "/game_0.bmp\n"
                         "keydown right\nwait 20\nkeyup right\nscreenshot " TMP_DIR "/game_1.bmp\n"
                         "keydown a\nwait 10\nkeyup a\nscreenshot " TMP_DIR "/game_2.bmp\n"
                         "key space\nwait 2\nscreenshot " TMP_DIR "/game_3.bmp\nkey enter\n"
                         "wait 2\n";
    const char *flags[] = {"assets/scenes/breakout.scene", NULL};
    run_t run;
    image_t shots[5];
    const char *names[5] = {"game_0", "game_1", "game_2", "game_3", "game"};
    if (!run_script("game", script, flags, &run)) return;
    for (int i = 0; i < 5; i++) {
        if (!load_shot(names[i], &shots[i])) {
            for (int k = 0; k < i; k++) image_free(&shots[k]);
            return;
        }
    }
    double paddle[3];
    for (int i = 0; i < 3; i++) paddle[i] = middle_x(&shots[i], is_paddle);
    /* The view is 16 m wide in 528 pixels: 33 pixels a metre. Right for
     * 1/3 s at 12 m/s is 4 m. */
    EXPECT(paddle[0] > 0 && paddle[1] - paddle[0] > 100.0 && paddle[2] < paddle[1] - 30.0,
           "the paddle's middle: %.0f at start, %.0f after Right, %.0f after A", paddle[0],
           paddle[1], paddle[2]);
    int b0[4], b2[4];
    bool bricks = image_bounds(&shots[0], is_red_brick, &b0[0], &b0[1], &b0[2], &b0[3]) &&
                  image_bounds(&shots[2], is_red_brick, &b2[0], &b2[1], &b2[2], &b2[3]);
    EXPECT(bricks && memcmp(b0, b2, sizeof b0) == 0,
           "the red bricks moved on screen: Right or A panned the view");
    EXPECT(shows(&shots[0], "score 0  lives 3  bricks 50", false),
           "no 'score 0  lives 3  bricks 50' in the side bar");
    EXPECT(shows(&shots[0], "GAME KEYS: Left/Right, A/D move", false) &&
               shows(&shots[0], "Space fires, Enter pauses", false),
           "the side bar does not say the game's keys");
    char state[8];
    unsigned char color[3];
    if (legend_state(&shots[0], "axes", state, color)) {
        EXPECT(strcmp(state, "off") == 0, "the axes overlay is %s in a game", state);
    }
    char line[40];
    EXPECT(find_in_panel(&shots[3], "SIMULATION", "running", NULL, NULL, NULL),
           "Space paused the game");
    EXPECT(find_in_panel(&shots[4], "SIMULATION", "PAUSED", NULL, NULL, NULL) &&
               shows(&shots[4], "paused (Enter resumes)", false),
           "Enter did not pause the game");
    (void)line;
    for (int i = 0; i < 5; i++) image_free(&shots[i]);
    image_t help;
    if (load_shot("game_help", &help)) {
        EXPECT(shows(&help, "Now playing breakout: the Game: keys come first", true),
               "the help screen does not say the game's keys come first");
        image_free(&help);
    }

    /* Space Invaders: 1 s to the left, clear of the shields, then fire. */
    const char *invaders = "move px 700 300\nkeydown left\nwait 60\nkeyup left\n"
                           "screenshot " TMP_DIR "/invaders_0.bmp\nkey space\nwait 8\n";
    const char *invaders_flags[] = {"assets/scenes/space_invaders.scene", NULL};
    image_t before, after;
    if (!run_script("invaders", invaders, invaders_flags, &run)) return;
    if (!load_shot("invaders_0", &before)) return;
    if (!load_shot("invaders", &after)) {
        image_free(&before);
        return;
    }
    int view_w = layout_800().view.w;
    double gun = middle_x(&before, is_gun);
    EXPECT(gun > 0 && gun < view_w / 2 - 150, "the gun is at %.0f after 1 s of Left", gun);
    long shots_before = image_count(&before, is_white, 0, 0, view_w, HEIGHT);
    long shots_after = image_count(&after, is_white, (int)gun - 10, 0, (int)gun + 10, HEIGHT);
    EXPECT(shots_before == 0 && shots_after >= 8,
           "white shot pixels: %ld before Space, %ld above the gun after", shots_before,
           shots_after);
    EXPECT(shows(&after, "score 0  lives 3  invaders 32", false),
           "no 'score 0  lives 3  invaders 32' in the side bar");
    image_free(&before);
    image_free(&after);
}

/* Whether the end screen's words are drawn in the view, in their colours:
 * the title four times the font's size, the score and "R to play again"
 * twice. */
static bool shows_end_screen(const image_t *image, const char *title, palette_rgb_t title_color,
                             const char *score) {
    int w = layout_of(image->width, image->height).view.w;
    unsigned char c[3];
    int x, y, sx, sy, rx, ry;
    if (!image_find_scaled_text(image, title, 4, 0, 0, w, image->height, &x, &y, c) ||
        !same_color(c, title_color))
        return false;
    if (!image_find_scaled_text(image, score, 2, 0, y, w, image->height, &sx, &sy, c) ||
        !same_color(c, PALETTE_TEXT))
        return false;
    const char *again = "R to play again";
    if (!image_find_scaled_text(image, again, 2, 0, sy, w, image->height, &rx, &ry, c) ||
        !same_color(c, PALETTE_ACCENT))
        return false;
    return sy > y && ry > sy;
}

/* A game won or lost covers the field with its end: "WON" or "GAME OVER" in
 * large letters, the score and "R to play again", which is gone once R has
 * started the game again. A Breakout of one brick the ball meets at once is
 * won in a second; one whose ball starts below the paddle, falling, has
 * lost its three lives in half a second. */
static void test_games_end_with_a_screen_over_the_field(void) {
    const char *walls = "body left { box 1 12; static; position -7.5 5; tag wall }\n"
                        "body right { box 1 12; static; position 7.5 5; tag wall }\n"
                        "body paddle { box 2.4 0.3; static; position 0 2 }\n"
                        "collide ball brick physics 1\ncollide ball paddle physics 1\n"
                        "collide ball left physics 1\ncollide ball right physics 1\n";
    char text[1024];
    snprintf(text, sizeof text,
             "game breakout\nview 0 5 16 12\n"
             "body ball { regular 8 0.2; mass 1; position 0 3; velocity 0 10 }\n"
             "body brick { box 1.2 0.5; static; tag brick; position 0 5 }\n%s",
             walls);
    const char *won = TMP_DIR "/won.scene";
    if (!write_file(won, text)) return;
    snprintf(text, sizeof text,
             "game breakout\nview 0 5 16 12\n"
             "body ball { regular 8 0.2; mass 1; position 4 1.5; velocity 0 -20 }\n"
             "body brick { box 1.2 0.5; static; tag brick; position 0 9 }\n%s",
             walls);
    const char *lost = TMP_DIR "/lost.scene";
    if (!write_file(lost, text)) return;
    const struct {
        const char *file, *name, *title, *score;
        palette_rgb_t color;
    } cases[] = {{won, "end_won", "WON", "score 1", PALETTE_WON},
                 {lost, "end_lost", "GAME OVER", "score 0", PALETTE_WARNING}};
    for (size_t i = 0; i < 2; i++) {
        char script[512], at_start[64], ended[64];
        snprintf(at_start, sizeof at_start, "%s_0", cases[i].name);
        snprintf(ended, sizeof ended, "%s_1", cases[i].name);
        snprintf(script, sizeof script,
                 "move px 700 300\nscreenshot %s\nwait 60\nscreenshot %s\nkey r\nwait 1\n",
                 tmp_path(at_start, ".bmp"), tmp_path(ended, ".bmp"));
        const char *flags[] = {cases[i].file, NULL};
        run_t run;
        image_t before, after, again;
        if (!run_script(cases[i].name, script, flags, &run)) continue;
        if (!load_shot(at_start, &before)) continue;
        if (load_shot(ended, &after)) {
            EXPECT(shows_end_screen(&after, cases[i].title, cases[i].color, cases[i].score),
                   "%s: no end screen over the field ('%s', '%s', 'R to play again')",
                   cases[i].file, cases[i].title, cases[i].score);
            image_free(&after);
        }
        EXPECT(!shows_end_screen(&before, cases[i].title, cases[i].color, cases[i].score),
               "%s: an end screen at the start", cases[i].file);
        if (load_shot(cases[i].name, &again)) {
            EXPECT(!shows_end_screen(&again, cases[i].title, cases[i].color, cases[i].score),
                   "%s: the end screen stays after R", cases[i].file);
            image_free(&again);
        }
        image_free(&before);
    }
}

/* ---- the documented pictures ---- */

/* The line of docs/sandbox-reference.md that runs ./sandbox with `marker`, split into
 * words (at most max, in words[], pointing into the returned copy). */
static char *doc_command(const char *doc, const char *marker, char **words, int max, int *n) {
    for (const char *line = doc; line != NULL && *line != '\0';) {
        const char *end = strchr(line, '\n');
        size_t length = end != NULL ? (size_t)(end - line) : strlen(line);
        char *copy = malloc(length + 1);
        memcpy(copy, line, length);
        copy[length] = '\0';
        if (strncmp(copy, "./sandbox ", 10) == 0 && strstr(copy, marker) != NULL) {
            *n = 0;
            for (char *w = strtok(copy, " "); w != NULL && *n < max; w = strtok(NULL, " ")) {
                words[(*n)++] = w;
            }
            return copy;
        }
        free(copy);
        line = end != NULL ? end + 1 : NULL;
    }
    return NULL;
}

/* The text of the here-document `cat > name <<'EOF'` in doc (free it). */
static char *doc_heredoc(const char *doc, const char *name) {
    char opening[96];
    snprintf(opening, sizeof opening, "cat > %s <<'EOF'\n", name);
    const char *start = strstr(doc, opening);
    if (start == NULL) return NULL;
    start += strlen(opening);
    const char *end = strstr(start, "\nEOF\n");
    if (end == NULL) return NULL;
    char *text = malloc((size_t)(end - start) + 2);
    memcpy(text, start, (size_t)(end - start));
    strcpy(text + (end - start), "\n");
    return text;
}

/* The STEP panel's chart and its scale are wall-clock times, which differ
 * from run to run: copied from the committed picture into the fresh one,
 * so that everything else of the panel (the counts, the stages that ran,
 * those left out) is compared. */
static void ignore_stage_chart(image_t *fresh, const image_t *committed) {
    int x0 = layout_of(committed->width, committed->height).sidebar.x, y = 0;
    if (fresh->width != committed->width || fresh->height != committed->height ||
        !image_find_text(committed, "STEP (the last step", x0, 0, committed->width,
                         committed->height, NULL, &y, NULL)) {
        return;
    }
    for (int row = y + 40; row < y + 97 && row < committed->height; row++) {
        for (int x = x0; x < committed->width; x++) {
            memcpy(fresh->rgb + ((size_t)row * (size_t)fresh->width + (size_t)x) * 3,
                   image_pixel(committed, x, row), 3);
        }
    }
}

/* Runs the documented command with `marker` (its script file, if given,
 * replaced by `script`, its screenshot by one of ours) and compares the
 * picture with the committed one. Up to 0.1% of the pixels may differ by
 * more than 48 in a channel, for machines whose floating point differs; on
 * this machine the pictures are identical. (Grabbing the hexagon next to
 * the demo's triangle instead changes 0.46% of docs/sandbox.png.) */
static void check_doc_picture(const char *doc, const char *marker, const char *doc_script,
                              const char *script, const char *picture) {
    char *words[32];
    int n = 0;
    char *copy = doc_command(doc, marker, words, 30, &n);
    if (copy == NULL) {
        app_fail("docs/sandbox-reference.md has no './sandbox ...' line with '%s'", marker);
        return;
    }
    char shot[256], diff[256];
    snprintf(shot, sizeof shot, "%s", tmp_path(picture + 5, ""));
    snprintf(diff, sizeof diff, "%s", tmp_path(picture + 5, ".diff.bmp"));
    remove(shot);
    const char *args[32];
    int count = 0;
    bool saves = false;
    for (int i = 1; i < n; i++) {
        args[count++] = words[i];
        if (strcmp(words[i], "--screenshot") == 0 && i + 1 < n) {
            args[count++] = shot;
            saves = true;
            i++;
        } else if (doc_script != NULL && strcmp(words[i], doc_script) == 0) {
            args[count - 1] = script;
        }
    }
    args[count] = NULL;
    EXPECT(saves, "the documented command for %s saves no screenshot", picture);
    run_t run;
    run_sandbox(&run, 60, args);
    free(copy);
    if (run.status != 0) {
        app_fail("the documented command for %s exited with %d:\n%s", picture, run.status,
             run.output);
        return;
    }
    image_t fresh, committed;
    char why[512];
    if (!image_read(picture, &committed, why, sizeof why)) {
        app_fail("%s", why);
        return;
    }
    if (image_read(shot, &fresh, why, sizeof why)) {
        ignore_stage_chart(&fresh, &committed);
        long differ = image_diff(&fresh, &committed, 48, diff);
        long allowed = (long)fresh.width * fresh.height / 1000;
        EXPECT(differ >= 0 && differ <= allowed,
               "%s: the documented command draws a different picture (%ld pixels differ, %ld "
               "allowed; %s shows them in red). If the change is meant, redraw the pictures "
               "with app/scripts/docs-pictures.sh",
               picture, differ, allowed, diff);
        image_free(&fresh);
    } else {
        app_fail("%s", why);
    }
    image_free(&committed);
}

static void test_docs_pictures_regenerate(void) {
    char *doc = read_text_file("docs/sandbox-reference.md");
    if (doc == NULL) return;
    check_doc_picture(doc, "--script app/scripts/demo.txt", NULL, NULL, "docs/sandbox.png");
    check_doc_picture(doc, "--script app/scripts/integrator.txt", NULL, NULL,
                      "docs/integrator.png");
    /* The games, the browser, the settings, the stage chart, the tools and
     * the joint presets:
     * app/scripts/NAME.txt draws docs/NAME.png (as docs-pictures.sh's list). */
    static const char *const PAGES[] = {"breakout",     "space_invaders", "pegs",
                                        "samples",      "solver",         "stages",
                                        "ray",          "box",            "explode",
                                        "inspect",      "joint_tool",     "joint_cradle",
                                        "joint_bridge", "joint_double_pendulum",
                                        "joint_ragdoll", "joint_crank",   "joint_car"};
    for (size_t i = 0; i < sizeof PAGES / sizeof PAGES[0]; i++) {
        char marker[96], picture[96];
        snprintf(marker, sizeof marker, "--script app/scripts/%s.txt", PAGES[i]);
        snprintf(picture, sizeof picture, "docs/%s.png", PAGES[i]);
        check_doc_picture(doc, marker, NULL, NULL, picture);
    }
    char *drop = doc_heredoc(doc, "drop.txt");
    EXPECT(drop != NULL, "docs/sandbox-reference.md has no cat > drop.txt <<'EOF' example");
    if (drop != NULL) {
        char script[256];
        snprintf(script, sizeof script, "%s", tmp_path("doc_drop", ".txt"));
        if (write_file(script, drop)) {
            check_doc_picture(doc, "--script drop.txt", "drop.txt", script, "docs/drop.png");
        }
        free(drop);
    }
    free(doc);
}


static const app_test_t TESTS[] = {
    {"app_smoke.dropped_bodies_rest_on_floor", test_dropped_bodies_rest_on_floor},
    {"app_smoke.overlays_on_while_colliding", test_overlays_on_while_colliding},
    {"app_smoke.overlays_off_draw_nothing", test_overlays_off_draw_nothing},
    {"app_smoke.throw_carries_the_drag_velocity", test_throw_carries_the_drag_velocity},
    {"app_smoke.delete_key_removes_body", test_delete_key_removes_body},
    {"app_smoke.joint_tool_pins_and_deletes", test_joint_tool_pins_and_deletes},
    {"app_smoke.default_view_shows_the_container_and_every_panel",
     test_default_view_shows_the_container_and_every_panel},
    {"app_smoke.panel_and_wall_clicks_drop_nothing", test_panel_and_wall_clicks_drop_nothing},
    {"app_smoke.legend_shows_on_and_off", test_legend_shows_on_and_off},
    {"app_smoke.status_lines_confirm_changes", test_status_lines_confirm_changes},
    {"app_smoke.zoom_keys_zoom_about_the_cursor", test_zoom_keys_zoom_about_the_cursor},
    {"app_smoke.edge_markers_and_frame_key", test_edge_markers_and_frame_key},
    {"app_smoke.text_fits_and_shows_no_negative_zero", test_text_fits_and_shows_no_negative_zero},
    {"app_smoke.integrator_key_switches_live", test_integrator_key_switches_live},
    {"app_smoke.energy_drift_chart_tells_the_schemes_apart",
     test_energy_drift_chart_tells_the_schemes_apart},
    {"app_smoke.sleeping_bodies_drawn_dimmer", test_sleeping_bodies_drawn_dimmer},
    {"app_smoke.samples_open_from_the_command_line", test_samples_open_from_the_command_line},
    {"app_smoke.scene_keys_cycle_through_the_samples",
     test_scene_keys_cycle_through_the_samples},
    {"app_smoke.bad_scene_files_are_refused", test_bad_scene_files_are_refused},
    {"app_smoke.save_writes_scenes_that_load_back", test_save_writes_scenes_that_load_back},
    {"app_smoke.joint_tool_pin_is_saved_and_reloaded", test_joint_tool_pin_is_saved_and_reloaded},
    {"app_smoke.games_respond_to_their_keys", test_games_respond_to_their_keys},
    {"app_smoke.games_end_with_a_screen_over_the_field",
     test_games_end_with_a_screen_over_the_field},
    {"app_smoke.png_screenshots_are_png", test_png_screenshots_are_png},
    {"app_smoke.bad_flags_are_refused", test_bad_flags_are_refused},
    {"app_smoke.bad_scripts_are_refused", test_bad_scripts_are_refused},
    {"app_smoke.help_lists_every_readme_key", test_help_lists_every_readme_key},
    {"app_smoke.docs_pictures_regenerate", test_docs_pictures_regenerate},
};
#define TEST_COUNT (sizeof TESTS / sizeof TESTS[0])

/* The rough edges (tests/app_smoke_edges.c), the browser, settings, stage
 * chart and tools (tests/app_smoke_learn.c). */
extern const app_test_t APP_EDGE_TESTS[];
extern const size_t APP_EDGE_TEST_COUNT;
extern const app_test_t APP_LEARN_TESTS[];
extern const size_t APP_LEARN_TEST_COUNT;

/* Every test: this file's, then the other files'. */
static app_test_t all_tests[128];
static size_t all_count;

static void gather(const app_test_t *tests, size_t count) {
    for (size_t i = 0; i < count && all_count < sizeof all_tests / sizeof all_tests[0]; i++) {
        all_tests[all_count++] = tests[i];
    }
}

static void skip_all(const char *reason) {
    for (size_t i = 0; i < all_count; i++) printf("SKIP %s: %s\n", all_tests[i].name, reason);
    printf("0 passed, 0 failed, %zu skipped\n", all_count);
}

int main(int argc, char **argv) {
    const char *filter = argc > 1 ? argv[1] : NULL;
    const char *override = getenv("SANDBOX");
    if (override != NULL && override[0] != '\0') sandbox_path = override;
    gather(TESTS, TEST_COUNT);
    gather(APP_EDGE_TESTS, APP_EDGE_TEST_COUNT);
    gather(APP_LEARN_TESTS, APP_LEARN_TEST_COUNT);
    if (!APP_SMOKE_HAVE_SDL) {
        skip_all("SDL2, SDL2_gfx or SDL2_image development files were not found by pkg-config "
                 "when this was built, so ./sandbox was not built (install: apt-get install -y "
                 "libsdl2-dev libsdl2-gfx-dev libsdl2-image-dev pkg-config)");
        return 0;
    }
    if (access(sandbox_path, X_OK) != 0) {
        /* SDL is there, so the sandbox should have been built: a failure. */
        for (size_t i = 0; i < all_count; i++) {
            printf("FAIL %s: %s is missing or not executable (make sandbox)\n",
                   all_tests[i].name, sandbox_path);
        }
        printf("0 passed, %zu failed\n", all_count);
        return 1;
    }
    mkdir("build", 0755);
    mkdir("build/tests", 0755);
    mkdir(TMP_DIR, 0755);
    return app_run_tests(all_tests, all_count, filter);
}
