/*
 * Smoke tests of the sandbox as a place to learn (issue 23, items 1 to 4),
 * each a scripted screenshot check: the samples browser lists every sample
 * under its category and a click opens one; the SOLVER page changes a
 * setting live and Ctrl+S saves it; the STEP panel names the stages a
 * scene leaves out; the ray and box tools answer with exact geometry.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "app_run.h"
#include "scene/samples.h"

/* The SAMPLES page (F3) shows every category heading and every sample's
 * name; a click on a name opens that sample. */
static void test_samples_browser_opens_a_sample_by_click(void) {
    static samples_t samples;
    samples_load(&samples, "assets/scenes", "sandbox", NULL);
    run_t run;
    image_t image;
    if (!run_script("browser", "key f3\nmove px 5 5\nwait 2\n", NULL, &run) ||
        !load_shot("browser", &image)) {
        samples_free(&samples);
        return;
    }
    for (size_t i = 0; i < samples.count; i++) {
        EXPECT(shows(&image, samples.items[i].name, false), "the browser does not list %s",
               samples.items[i].name);
        EXPECT(shows(&image, samples_category_name(&samples, i), false),
               "the browser has no heading %s", samples_category_name(&samples, i));
    }
    int x = 0, y = 0;
    int x0 = layout_of(image.width, image.height).sidebar.x;
    bool found = image_find_text(&image, "friction", x0, 0, image.width, image.height, &x, &y,
                                 NULL);
    EXPECT(found, "no 'friction' in the browser");
    image_free(&image);
    samples_free(&samples);
    if (!found) return;
    char script[256];
    snprintf(script, sizeof script, "key f3\nclick px %d %d\nwait 2\nkey f2\nmove px 5 5\n",
             x + 4, y + 3);
    if (!run_script("browser_click", script, NULL, &run) || !load_shot("browser_click", &image)) {
        return;
    }
    char shown[40];
    EXPECT(scene_name(&image, shown, 30) && strcmp(shown, "friction") == 0,
           "a click on 'friction' opened '%s'", shown);
    image_free(&image);
}

/* A click on the warm starting row turns it off, said on the status line;
 * Ctrl+S writes it into the saved file; reset brings it back. */
static void test_solver_settings_change_live_and_are_saved(void) {
    const char *dir = TMP_DIR "/solver_saves";
    mkdir(dir, 0755);
    char path[256];
    snprintf(path, sizeof path, "%s/saved-1.scene", dir);
    remove(path);
    run_t run;
    image_t image;
    if (!run_script("solver", "key f4\nmove px 5 5\nwait 2\n", NULL, &run) ||
        !load_shot("solver", &image)) {
        return;
    }
    int x = 0, y = 0;
    int x0 = layout_of(image.width, image.height).sidebar.x;
    bool found = image_find_text(&image, "warm starting", x0, 0, image.width, image.height, &x,
                                 &y, NULL);
    EXPECT(found, "no 'warm starting' row on the SOLVER page");
    image_free(&image);
    if (!found) return;
    char script[256];
    snprintf(script, sizeof script,
             "key f4\nclick px %d %d\nwait 1\nscreenshot " TMP_DIR
             "/solver_off.bmp\nkey ctrl+s\nwait 1\nmove px 5 5\n",
             x + 4, y + 3);
    const char *flags[] = {"--save-dir", dir, NULL};
    if (!run_script("solver_click", script, flags, &run) || !load_shot("solver_off", &image)) {
        return;
    }
    EXPECT(shows(&image, "warm starting off", false), "no status 'warm starting off'");
    image_free(&image);
    char *saved = read_text_file(path);
    EXPECT(saved != NULL && strstr(saved, "\nwarm_starting off\n") != NULL,
           "%s does not say warm_starting off", path);
    free(saved);
}

/* A click on the stepping row runs one step a frame, as long as the frame
 * (headless: 1/60 s), where fixed steps of 1/120 s ran two. */
static void test_frame_stepping_runs_one_step_a_frame(void) {
    run_t run;
    image_t image;
    if (!run_script("stepping", "key f4\nmove px 5 5\nwait 2\n", NULL, &run) ||
        !load_shot("stepping", &image)) {
        return;
    }
    int x = 0, y = 0;
    int x0 = layout_of(image.width, image.height).sidebar.x;
    bool found = image_find_text(&image, "stepping", x0, 0, image.width, image.height, &x, &y,
                                 NULL);
    EXPECT(found, "no 'stepping' row on the SOLVER page");
    image_free(&image);
    if (!found) return;
    char script[256];
    snprintf(script, sizeof script,
             "key f2\nwait 2\nscreenshot " TMP_DIR "/stepping_fixed.bmp\nkey f4\n"
             "click px %d %d\nkey f2\nwait 2\nmove px 5 5\n", x + 4, y + 3);
    if (!run_script("stepping_frame", script, NULL, &run)) return;
    if (load_shot("stepping_fixed", &image)) {
        EXPECT(shows(&image, "physics 2 steps a frame", false), "fixed steps: not 2 a frame");
        image_free(&image);
    }
    if (load_shot("stepping_frame", &image)) {
        EXPECT(shows(&image, "physics 1 step a frame", false), "frame stepping: not 1 a frame");
        image_free(&image);
    }
}

/* The STEP panel (SOLVER page) under orbits.scene, which has no world
 * contacts: forces and integrate run, every contact stage is left out. */
static void test_stage_chart_names_the_stages_left_out(void) {
    run_t run;
    image_t image;
    const char *script = "open assets/scenes/orbits.scene\nkey f4\nwait 30\nmove px 5 5\n";
    if (!run_script("stages", script, NULL, &run) || !load_shot("stages", &image)) return;
    EXPECT(shows(&image, "left out: broad, narrow,", false),
           "the STEP panel does not list the contact stages as left out");
    EXPECT(shows(&image, "prepare, solver, shock,", false),
           "the STEP panel's second line of stages left out is missing");
    EXPECT(shows(&image, "position, sleep, removal", false),
           "the STEP panel's third line of stages left out is missing");
    EXPECT(shows(&image, "5 awake, 0 asleep, 0 static", false), "the body counts are missing");
    image_free(&image);
}

/* The ray from (-7, 2) to (7, 9) across pyramid.scene enters the left face
 * of the fourth row's first box, x = -3.5, at fraction 3.5 / 14 = 0.25 and
 * y = 2 + 0.25 * 7 = 3.75, normal (-1, 0). The box from (-1.9, 1.1) to
 * (1.9, 3.9) overlaps rows two to four, x within 1.9: 5 + 4 + 5 = 14 boxes. */
static void test_ray_and_box_tools_answer_exactly(void) {
    run_t run;
    image_t image;
    const char *script = "open assets/scenes/pyramid.scene\nwait 10\nkey j\n"
                         "drag left -7 2 7 9 10\nwait 2\nmove px 5 5\nscreenshot " TMP_DIR
                         "/ray.bmp\nkey u\ndrag left -1.9 1.1 1.9 3.9 10\nwait 2\nmove px 5 5\n";
    if (!run_script("probe", script, NULL, &run)) return;
    if (load_shot("ray", &image)) {
        EXPECT(shows(&image, "at 0.250", false), "the ray's fraction is not 0.250");
        EXPECT(shows(&image, "point (-3.50, 3.75) m", false), "the ray's point is not shown");
        EXPECT(shows(&image, "normal (-1.00, 0.00)", false), "the ray's normal is not shown");
        image_free(&image);
    }
    if (load_shot("probe", &image)) {
        EXPECT(shows(&image, "14 bodies overlap it", false),
               "the box does not find the 14 boxes it overlaps");
        image_free(&image);
    }
}

/* The inspector on the elastic box of bounce.scene (1 kg, a 0.6 m square:
 * I = m (w^2 + h^2) / 12 = 0.060 kg m^2; elasticity 1, friction 0) and the
 * plot of its height, which bounces between 0.3 and 4.3 m; then an
 * explosion, said on the status line, and the plot of the scene's kinetic
 * energy. */
static void test_inspector_plot_and_explosion(void) {
    run_t run;
    image_t image;
    const char *script = "open assets/scenes/bounce.scene\nkey l\nclick 4 4.3\nwait 3s\n"
                         "move px 795 595\nscreenshot " TMP_DIR "/inspect.bmp\n"
                         "key k\nclick 0 0.5\nwait 1\nmove px 795 595\n";
    if (!run_script("explode", script, NULL, &run)) return;
    if (load_shot("inspect", &image)) {
        EXPECT(shows(&image, "the e100", false), "the inspector does not name the e100");
        EXPECT(shows(&image, "m 1.000 kg  I 0.060 kg m2", false),
               "the inspector's mass and inertia are not 1 kg and 0.060 kg m2");
        EXPECT(shows(&image, "elasticity 1.00  friction 0.00", false),
               "the inspector's material is not elasticity 1, friction 0");
        EXPECT(shows(&image, "height (m)", false) && shows(&image, "4.30", false) &&
                   shows(&image, "0.30", false),
               "the plot of the height does not span 0.30 to 4.30 m");
        image_free(&image);
    }
    if (load_shot("explode", &image)) {
        EXPECT(shows(&image, "explosion:", false) && shows(&image, "N s at the", false),
               "no status line for the explosion");
        image_free(&image);
    }
}

const app_test_t APP_LEARN_TESTS[] = {
    {"app_smoke.samples_browser_opens_a_sample_by_click",
     test_samples_browser_opens_a_sample_by_click},
    {"app_smoke.solver_settings_change_live_and_are_saved",
     test_solver_settings_change_live_and_are_saved},
    {"app_smoke.stage_chart_names_the_stages_left_out",
     test_stage_chart_names_the_stages_left_out},
    {"app_smoke.ray_and_box_tools_answer_exactly", test_ray_and_box_tools_answer_exactly},
    {"app_smoke.inspector_plot_and_explosion", test_inspector_plot_and_explosion},
    {"app_smoke.frame_stepping_runs_one_step_a_frame", test_frame_stepping_runs_one_step_a_frame},
};
const size_t APP_LEARN_TEST_COUNT = sizeof APP_LEARN_TESTS / sizeof APP_LEARN_TESTS[0];
