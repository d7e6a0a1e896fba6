/*
 * Smoke tests of the rough edges a new user meets (issue 23, item 5), each
 * a scripted screenshot check: overlays that stay readable in a pile, drops
 * anywhere in the view but inside a body or outside the world, the help
 * beside a readable side bar, O showing all, a default shape about 40
 * pixels across, no drop preview in a game, a status line naming a body the
 * sandbox removes, the throw's vector while dragging, one body count, UI
 * text scaled with the window and a window never smaller than the side bar
 * needs.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "app_run.h"

/* Whether any pixel of the rectangle differs between two screenshots. */
static long region_differs(const image_t *a, const image_t *b, int x0, int y0, int x1, int y1) {
    long differ = 0;
    for (int y = y0; y < y1; y++) {
        for (int x = x0; x < x1; x++) {
            differ += memcmp(image_pixel(a, x, y), image_pixel(b, x, y), 3) != 0;
        }
    }
    return differ;
}

static const char *const OVERLAY_LINES[] = {"axes",      "impulses",       "contact points",
                                            "velocities", "centroids",     "bounding boxes",
                                            "dim sleeping bodies"};
#define OVERLAY_LINE_COUNT (sizeof OVERLAY_LINES / sizeof OVERLAY_LINES[0])

/* How many overlay lines of the legend say `state`. */
static size_t legend_count(const image_t *image, const char *state) {
    size_t count = 0;
    for (size_t i = 0; i < OVERLAY_LINE_COUNT; i++) {
        char got[8];
        unsigned char color[3];
        count += legend_state(image, OVERLAY_LINES[i], got, color) && strcmp(got, state) == 0;
    }
    return count;
}

/* O shows every overlay unless every one is shown already (some are on at
 * start: the first press used to turn them all off). */
static void test_o_shows_all_unless_all_are_shown(void) {
    const char *script = "move px 5 5\nkey o\nscreenshot " TMP_DIR "/o_1.bmp\n"
                         "key o\nscreenshot " TMP_DIR "/o_2.bmp\n"
                         "key o\nkey a\nkey o\n";
    run_t run;
    if (!run_script("o_all", script, NULL, &run)) return;
    const struct {
        const char *shot, *what, *state, *status;
    } cases[] = {
        {"o_1", "O at start", "on", "all overlays on"},
        {"o_2", "O with all on", "off", "all overlays off"},
        {"o_all", "O with all but the axes on", "on", "all overlays on"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        image_t image;
        if (!load_shot(cases[i].shot, &image)) continue;
        size_t count = legend_count(&image, cases[i].state);
        EXPECT(count == OVERLAY_LINE_COUNT, "%s: %zu of %zu overlays '%s'", cases[i].what, count,
               OVERLAY_LINE_COUNT, cases[i].state);
        EXPECT(shows(&image, cases[i].status, false), "%s: no status line '%s'", cases[i].what,
               cases[i].status);
        image_free(&image);
    }
}

/* In a game the mouse shows no shape to drop: a paused Breakout looks the
 * same with the cursor over an empty part of the field as with it on the
 * side bar. */
static void test_no_drop_preview_in_games(void) {
    const char *script = "key enter\nmove px 700 300\nwait 2\nscreenshot " TMP_DIR
                         "/game_away.bmp\nmove -4 6\nwait 2\n";
    const char *flags[] = {"assets/scenes/breakout.scene", NULL};
    run_t run;
    image_t away, over;
    if (!run_script("game_over", script, flags, &run) || !load_shot("game_away", &away)) return;
    if (!load_shot("game_over", &over)) {
        image_free(&away);
        return;
    }
    int view_w = layout_800().view.w;
    long differ = region_differs(&away, &over, 0, 0, view_w, HEIGHT);
    EXPECT(differ == 0, "the cursor over the paused game changed %ld pixels of the field (a "
                        "shape previewed)", differ);
    image_free(&away);
    image_free(&over);
}

/* The status line and the side bar count bodies alike: the bodies that
 * move, static ones said apart ("opened card_house (14 bodies, 1 static)"
 * with "bodies 14"; it said 15 against 14). */
static void test_one_body_count_everywhere(void) {
    const char *dir = TMP_DIR "/count";
    char make[700], path[300];
    snprintf(path, sizeof path, "%s/saved-1.scene", dir);
    snprintf(make, sizeof make, "mkdir -p %s && rm -f %s", dir, path);
    if (system(make) != 0) app_fail("cannot make %s", dir);
    const char *script = "move px 5 5\nopen assets/scenes/card_house.scene\nwait 2\n"
                         "screenshot " TMP_DIR "/count_open.bmp\nkey ctrl+s\nwait 1\n";
    const char *flags[] = {"--save-dir", dir, NULL};
    run_t run;
    image_t image;
    if (!run_script("count", script, flags, &run)) return;
    if (load_shot("count_open", &image)) {
        EXPECT(shows(&image, "opened card_house (14 bodies,", false),
               "no status line 'opened card_house (14 bodies, 1 static)'");
        EXPECT(find_in_panel(&image, "SIMULATION", "bodies 14  sleeping", NULL, NULL, NULL),
               "the SIMULATION panel does not count 'bodies 14'");
        image_free(&image);
    }
    if (load_shot("count", &image)) {
        EXPECT(shows(&image, "saved-1.scene (14 bodies, 1", false),
               "no status line '... saved-1.scene (14 bodies, 1 static)'");
        image_free(&image);
    }
}

/* Shift + drag shows the throw's velocity as an arrow from the shape, in the
 * velocity overlay's colour, with its speed, before the release. */
static bool is_velocity_color(const unsigned char *p) {
    return same_color(p, PALETTE_VELOCITY);
}

static void test_throw_vector_drawn_while_dragging(void) {
    const char *script = "move -8 10\nkeydown shift\npress left -8 10\nwait 1\nmove -7 10.5\n"
                         "wait 1\nmove -6 11\nwait 1\nmove -5 11.5\n"
                         "screenshot " TMP_DIR "/throw_held.bmp\nrelease left\nkeyup shift\n"
                         "wait 1\n";
    const char *flags[] = {"--overlays", "none", NULL};
    run_t run;
    image_t image;
    if (!run_script("throw_vector", script, flags, &run) || !load_shot("throw_held", &image)) {
        return;
    }
    int view_w = layout_800().view.w;
    long arrow = image_count(&image, is_velocity_color, 0, 0, view_w, HEIGHT);
    EXPECT(arrow > 60, "%ld pixels of the throw's arrow while dragging", arrow);
    EXPECT(image_find_text(&image, "m/s", 0, 0, view_w, HEIGHT, NULL, NULL, NULL),
           "the throw's speed is not written beside its arrow");
    image_free(&image);
}

/* The width of the body-coloured pixels in the view (0: none). */
static int body_width_in_view(const image_t *image) {
    int view_w = layout_of(image->width, image->height).view.w, left = view_w, right = -1;
    for (int y = 0; y < image->height; y++) {
        for (int x = 0; x < view_w; x++) {
            if (!is_body_color(image_pixel(image, x, y))) continue;
            if (x < left) left = x;
            if (x > right) right = x;
        }
    }
    return right >= left ? right - left + 1 : 0;
}

/* A hexagon dropped with the default size is about 40 pixels across in the
 * default view, whatever the window and the scene's scale (it was 0.5 m: 17
 * pixels at 800x600, and a third of card_house's view). */
static void test_default_shape_is_about_40_pixels(void) {
    const struct {
        const char *name, *size, *scene, *click;
    } cases[] = {
        {"size_800", "800x600", NULL, "click 0 3\n"},
        {"size_1280", "1280x720", NULL, "click 0 3\n"},
        {"size_cards", "800x600", "assets/scenes/card_house.scene", "click -2 3\n"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char script[128];
        /* The cursor on the side bar, over nothing body-coloured. */
        snprintf(script, sizeof script, "%swait 5\nmove px %d 5\n", cases[i].click,
                 layout_of(atoi(cases[i].size), 600).view.w + 200);
        const char *flags[] = {"--overlays", "none", cases[i].scene, NULL};
        run_t run;
        image_t image;
        if (!run_script_at(cases[i].name, cases[i].size, script, flags, &run) ||
            !load_shot(cases[i].name, &image)) {
            continue;
        }
        int w = body_width_in_view(&image);
        EXPECT(w >= 34 && w <= 48, "%s at %s: the dropped hexagon is %d pixels across",
               cases[i].scene != NULL ? cases[i].scene : "the default scene", cases[i].size, w);
        image_free(&image);
    }
}

/* The status line after a click at (x, y) m: "dropped" when a body was
 * added, else the refusal. */
typedef struct {
    const char *click, *expected;
} drop_case_t;

/* Drops go anywhere the view shows (above the container, beside it, far
 * above a scene file's view once zoomed out), refused only inside a body
 * (static or not) and below the world's floor, each saying which. */
static void test_drops_go_anywhere_but_inside_bodies_or_outside_the_world(void) {
    char script[2048] = "key 3\nclick 0 1\nwait 1s\n";
    const drop_case_t cases[] = {
        {"click 0 0.4", "cannot drop inside a body"},
        {"click 0 -0.5", "cannot drop inside the floor"},
        {"click -14.5 10", "cannot drop inside the left wall"},
        {"move 0 0\nkey -\nkey -\nkey -\nkey -\nkey -\nkey -\nkey -\nkey -\nkey -\nkey -\n"
         "key ctrl+down\nkey ctrl+down\nkey ctrl+down\nclick 0 -50",
         "cannot drop outside the world"},
    };
    size_t used = strlen(script);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        used += (size_t)snprintf(script + used, sizeof script - used,
                                 "%s\nwait 1\nscreenshot " TMP_DIR "/drop_%zu.bmp\n",
                                 cases[i].click, i);
    }
    snprintf(script + used, sizeof script - used, "key 0\nclick 0 31\nclick 15.3 10\nwait 2\n"
                                                  "move px 5 5\n");
    run_t run;
    image_t image;
    if (!run_script("drops", script, NULL, &run)) return;
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char name[32];
        snprintf(name, sizeof name, "drop_%zu", i);
        if (!load_shot(name, &image)) continue;
        int x, y;
        unsigned char color[3];
        bool found = image_find_text(&image, cases[i].expected, layout_800().sidebar.x, 0, WIDTH,
                                     HEIGHT, &x, &y, color);
        EXPECT(found && same_color(color, PALETTE_WARNING), "after '%s': no warning '%s'",
               cases[i].click, cases[i].expected);
        image_free(&image);
    }
    /* Above the walls and outside a wall, both in the view: dropped. */
    if (load_shot("drops", &image)) {
        EXPECT(find_in_panel(&image, "SIMULATION", "bodies 3", NULL, NULL, NULL),
               "a drop above the container or one beside a wall was refused");
        EXPECT(!shows(&image, "cannot drop", false), "a drop in the view was refused");
        image_free(&image);
    }
    /* card_house: zoomed out, a click 4.5 m above the house drops. */
    const char *cards = "key -\nkey -\nkey -\nkey -\nkey -\nkey -\nclick 0 7.5\nwait 2\nmove px 5 5\n";
    const char *flags[] = {"assets/scenes/card_house.scene", NULL};
    if (run_script("drops_cards", cards, flags, &run) && load_shot("drops_cards", &image)) {
        EXPECT(find_in_panel(&image, "SIMULATION", "bodies 15", NULL, NULL, NULL) &&
                   !shows(&image, "cannot drop", false),
               "card_house: a click 4.5 m above the house did not drop a body");
        image_free(&image);
    }
}

/* The help screen covers the view only: the side bar beside it is the same
 * as without it, and every line of the help is inside the view. */
static void check_help(const char *size) {
    char name[40], before[40];
    snprintf(name, sizeof name, "help_%s", size);
    snprintf(before, sizeof before, "help_%s_0", size);
    char script[256];
    snprintf(script, sizeof script, "move px 5 5\nwait 2\nscreenshot %s\nkey h\n",
             tmp_path(before, ".bmp"));
    const char *flags[] = {"--frames", "4", NULL};
    run_t run;
    image_t without, with;
    if (!run_script_at(name, size, script, flags, &run) || !load_shot(before, &without)) return;
    if (!load_shot(name, &with)) {
        image_free(&without);
        return;
    }
    layout_t layout = layout_of(with.width, with.height);
    long differ = region_differs(&without, &with, layout.sidebar.x, 0, with.width, with.height);
    EXPECT(differ == 0, "%s: the help changed %ld pixels of the side bar", size, differ);
    const char *lines[] = {"SANDBOX CONTROLS", "frame every body", "Esc, Q"};
    for (size_t i = 0; i < sizeof lines / sizeof lines[0]; i++) {
        int x, y;
        bool found = image_find_text(&with, lines[i], 0, 0, layout.view.w, with.height, &x, &y,
                                     NULL);
        EXPECT(found, "%s: the help's '%s' is not inside the view", size, lines[i]);
    }
    image_free(&without);
    image_free(&with);
}

static void test_help_leaves_the_side_bar_readable(void) {
    check_help("800x600");
    check_help("1280x720");
}

/* A body the sandbox removes is named on the status line: stiff_spring
 * under the seed integrator flings its weight out of the world. */
static void test_a_removed_body_is_named(void) {
    const char *flags[] = {"--integrator", "seed", "assets/scenes/stiff_spring.scene", NULL};
    run_t run;
    image_t image;
    if (!run_script("removed", "move px 5 5\nwait 1s\n", flags, &run) ||
        !load_shot("removed", &image)) {
        return;
    }
    EXPECT(shows(&image, "removed weight:", false),
           "no status line 'removed weight: ...' after the weight left the world");
    image_free(&image);
}

static bool is_any_axis(const unsigned char *p) {
    return is_axis_color(p);
}

/* In a pile of 2000 bodies the axes are drawn near the cursor and for the
 * strongest impacts only, and the OVERLAYS panel says how many of how many
 * (every contact used to get one: a yellow blob). */
static void test_overlays_stay_readable_in_a_pile(void) {
    const char *flags[] = {"--spawn", "2000", "--frames", "120", NULL};
    run_t run;
    image_t image;
    world_map_t map;
    if (!run_script("pile_axes", "move 0 1\n", flags, &run) || !load_shot("pile_axes", &image)) {
        return;
    }
    if (map_world(&image, &map)) {
        int cx = px_x(&map, 0), cy = px_y(&map, 1);
        int view_w = layout_800().view.w;
        long all = image_count(&image, is_any_axis, 0, 0, view_w, HEIGHT);
        long near = image_count(&image, is_any_axis, cx - 130, cy - 130, cx + 130, cy + 130);
        EXPECT(near > 100, "%ld axis pixels near the cursor", near);
        EXPECT(all - near < 6000, "%ld axis pixels away from the cursor (of %ld)", all - near,
               all);
    }
    int x, y;
    EXPECT(find_in_panel(&image, "OVERLAYS", " of ", &x, &y, NULL),
           "the OVERLAYS panel does not say how many axes of how many are drawn");
    image_free(&image);
}

/* At 2560x1440 the side bar's text is twice the font's size, and the side
 * bar twice as wide. */
static void test_ui_text_scales_with_the_window(void) {
    const char *flags[] = {"--frames", "2", NULL};
    run_t run;
    image_t image;
    if (!run_script_at("scaled", "2560x1440", "move px 5 5\n", flags, &run) ||
        !load_shot("scaled", &image)) {
        return;
    }
    int x, y;
    const char *titles[] = {"SIMULATION", "OVERLAYS", "INTEGRATOR"};
    for (size_t i = 0; i < sizeof titles / sizeof titles[0]; i++) {
        bool found = image_find_scaled_text(&image, titles[i], 2, 0, 0, image.width,
                                            image.height, &x, &y, NULL);
        EXPECT(found && x > image.width - 2 * LAYOUT_SIDEBAR_W,
               "2560x1440: no '%s' at twice the font's size in the side bar", titles[i]);
    }
    image_free(&image);
}

/* A window made smaller than the side bar needs grows back to 800x600
 * (without a window manager nothing else holds the minimum). */
static void test_window_keeps_its_minimum_size(void) {
    const char *script = "move px 5 5\nresize 640 400\nwait 2\n";
    run_t run;
    image_t image;
    if (!run_script("minimum", script, NULL, &run) || !load_shot("minimum", &image)) return;
    EXPECT(image.width == 800 && image.height == 600, "resized to 640x400: the frame is %dx%d",
           image.width, image.height);
    EXPECT(shows(&image, "timestep 1/120 s", false), "the side bar's last line is cut off");
    image_free(&image);
}

const app_test_t APP_EDGE_TESTS[] = {
    {"app_smoke.o_shows_all_unless_all_are_shown", test_o_shows_all_unless_all_are_shown},
    {"app_smoke.no_drop_preview_in_games", test_no_drop_preview_in_games},
    {"app_smoke.one_body_count_everywhere", test_one_body_count_everywhere},
    {"app_smoke.throw_vector_drawn_while_dragging", test_throw_vector_drawn_while_dragging},
    {"app_smoke.default_shape_is_about_40_pixels", test_default_shape_is_about_40_pixels},
    {"app_smoke.drops_go_anywhere_but_inside_bodies_or_outside_the_world",
     test_drops_go_anywhere_but_inside_bodies_or_outside_the_world},
    {"app_smoke.help_leaves_the_side_bar_readable", test_help_leaves_the_side_bar_readable},
    {"app_smoke.a_removed_body_is_named", test_a_removed_body_is_named},
    {"app_smoke.overlays_stay_readable_in_a_pile", test_overlays_stay_readable_in_a_pile},
    {"app_smoke.ui_text_scales_with_the_window", test_ui_text_scales_with_the_window},
    {"app_smoke.window_keeps_its_minimum_size", test_window_keeps_its_minimum_size},
};
const size_t APP_EDGE_TEST_COUNT = sizeof APP_EDGE_TESTS / sizeof APP_EDGE_TESTS[0];
