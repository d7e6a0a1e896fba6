/*
 * The web page (build/web/sandbox.html, make web) in headless Chromium,
 * beside the native sandbox: the same scripts (the --script format, passed
 * in the page's address) run in both, and each script's `log` lines must
 * agree: the count of bodies and a game's score exactly, every body's
 * position and angle to 1e-9 (the hash of them says whether the bits agree
 * too: Emscripten's sin and cos differ from glibc's by an ulp for some
 * angles). Also read from the
 * page: its console (no error), a screenshot of it (bodies in the view, the
 * side bar's words, found in the app's 8x8 font), a scene saved with Ctrl+S
 * (downloaded, and opened by the native build) and a scene file chosen on
 * the page (opened). tests/web/browse.js drives Chromium.
 *
 * When emcc, chromium or node is missing, one line says so and every test
 * counts as skipped (make check-web installs them). Run from the
 * repository root; files go to build/tests/web_check.tmp/.
 */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "app_run.h"

int app_failures;

#define WEB_TMP_DIR "build/tests/web_check.tmp"
#define PAGE "build/web/sandbox.html"
#define SANDBOX "./sandbox"
/* The page's bar above the canvas (app/web/shell.html), in CSS pixels. */
#define BAR_H 33
/* The most a page run may take (s): a minute of Breakout takes about 20. */
#define PAGE_TIMEOUT 150

/* ---- running programs ---- */

/* Starts argv (NULL-terminated) with stdout and stderr into out_path;
 * returns its pid, or -1 (a failure said). */
static pid_t start(const char *const *argv, const char *out_path) {
    fflush(stdout);
    pid_t child = fork();
    if (child < 0) {
        app_fail("fork: %s", strerror(errno));
        return -1;
    }
    if (child == 0) {
        FILE *out = freopen(out_path, "w", stdout);
        if (out == NULL || dup2(STDOUT_FILENO, STDERR_FILENO) < 0) _exit(126);
        execvp(argv[0], (char *const *)argv);
        fprintf(stderr, "cannot run %s: %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    return child;
}

/* Waits for child (started by start, named by name, its output in
 * out_path) at most timeout_s seconds; its exit status, or -1 (a failure
 * said). */
static int finish(pid_t child, const char *name, const char *out_path, int timeout_s) {
    if (child < 0) return -1;
    char what[512];
    snprintf(what, sizeof what, "%s (output in %s)", name, out_path);
    return wait_for_child(child, what, timeout_s);
}

/* Runs argv to its end (see start and finish). */
static int run(const char *const *argv, const char *out_path, int timeout_s) {
    return finish(start(argv, out_path), argv[0], out_path, timeout_s);
}

static bool have_command(const char *name) {
    char command[128];
    snprintf(command, sizeof command, "command -v %s >/dev/null 2>&1", name);
    return system(command) == 0;
}

/* text with every byte but letters, digits and -._~ as %XX. */
static char *url_encode(const char *text) {
    char *out = malloc(3 * strlen(text) + 1), *p = out;
    if (out == NULL) return NULL;
    for (const unsigned char *c = (const unsigned char *)text; *c != '\0'; c++) {
        if ((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9') ||
            strchr("-._~", *c) != NULL) {
            *p++ = (char)*c;
        } else {
            p += sprintf(p, "%%%02X", *c);
        }
    }
    *p = '\0';
    return out;
}

/* ---- one script in the page and in the native build ---- */

typedef struct {
    char *native; /* the native run's output */
    char *page;   /* the page's console, "log: ...", "warning: ...", "error: ..." */
    image_t shot; /* the page's screenshot, cropped to the canvas */
    bool ok;
} runs_t;

/* Runs script (WEB_TMP_DIR/name.txt) with `args` (space-separated sandbox
 * options and a scene file, at size WxH) in the page and, when native,
 * in the native build (headless); the page runs with --headless's fixed
 * clock too unless choose is given: a file the page's file chooser gets
 * after its first frame, while frames run at the display's rate. */
static bool run_both(const char *name, const char *args, int width, int height,
                     const char *script, const char *choose, bool native, runs_t *r) {
    memset(r, 0, sizeof *r);
    const char *script_path = tmp_path(name, ".txt");
    if (!write_file(script_path, script)) return false;
    char size[32];
    snprintf(size, sizeof size, "%dx%d", width, height);

    char page[4096];
    if (realpath(PAGE, page) == NULL) {
        app_fail("%s: %s (make web)", PAGE, strerror(errno));
        return false;
    }

    /* The native run goes on beside the page's (two processors). */
    pid_t native_run = -1;
    const char *native_out = tmp_path(name, ".native.txt");
    if (native) {
        const char *argv[16] = {SANDBOX, "--headless", "--size", size, "--script", script_path};
        char words[256];
        snprintf(words, sizeof words, "%s", args);
        int n = 6;
        for (char *w = strtok(words, " "); w != NULL && n < 15; w = strtok(NULL, " ")) argv[n++] = w;
        native_run = start(argv, native_out);
        if (native_run < 0) return false;
    }

    char *query_args = url_encode(args), *query_script = url_encode(script);
    size_t url_size = strlen(page) + strlen(query_args) + strlen(query_script) + 96;
    char *url = malloc(url_size);
    snprintf(url, url_size, "file://%s?args=%s%s%%20--size%%20%s&script=%s", page,
             choose == NULL ? "--headless%20" : "", query_args, size, query_script);
    free(query_args);
    free(query_script);
    char viewport[32];
    snprintf(viewport, sizeof viewport, "%dx%d", width, height + BAR_H);
    const char *shot = tmp_path(name, ".png");
    const char *downloads = tmp_path(name, ".downloads");
    char timeout[16];
    snprintf(timeout, sizeof timeout, "%d", PAGE_TIMEOUT);
    const char *argv[20] = {"node", "tests/web/browse.js", "--url", url, "--size", viewport,
                            "--screenshot", shot, "--downloads", downloads, "--timeout", timeout};
    int n = 12;
    if (choose != NULL) {
        argv[n++] = "--choose";
        argv[n++] = choose;
    }
    remove(shot);
    const char *out = tmp_path(name, ".page.txt");
    int status = run(argv, out, PAGE_TIMEOUT + 30);
    free(url);
    if (native) {
        int native_status = finish(native_run, SANDBOX, native_out, 60);
        r->native = read_text_file(native_out);
        if (native_status != 0) {
            app_fail("the native sandbox exited with %d:\n%s", native_status,
                     r->native ? r->native : "");
            return false;
        }
    }
    r->page = read_text_file(out);
    if (status != 0 || r->page == NULL) {
        app_fail("the page run failed (status %d):\n%s", status, r->page ? r->page : "");
        return false;
    }
    for (const char *line = r->page; line != NULL && *line != '\0';) {
        if (strncmp(line, "error:", 6) == 0 || strncmp(line, "browse:", 7) == 0) {
            const char *end = strchr(line, '\n');
            app_fail("the page's console: %.*s", end ? (int)(end - line) : (int)strlen(line),
                     line);
        }
        line = strchr(line, '\n');
        if (line != NULL) line++;
    }
    if (!strstr(r->page, "sandbox: stopped with status 0")) {
        app_fail("the page did not stop with status 0:\n%s", r->page);
        return false;
    }
    image_t whole;
    char why[512];
    if (!image_read(shot, &whole, why, sizeof why)) {
        app_fail("%s", why);
        return false;
    }
    /* The canvas alone: the rows under the page's bar. */
    if (whole.width != width || whole.height != height + BAR_H) {
        app_fail("the screenshot is %dx%d, expected %dx%d", whole.width, whole.height, width,
                 height + BAR_H);
        image_free(&whole);
        return false;
    }
    r->shot.width = width;
    r->shot.height = height;
    r->shot.rgb = malloc((size_t)width * height * 3);
    memcpy(r->shot.rgb, whole.rgb + (size_t)BAR_H * width * 3, (size_t)width * height * 3);
    image_free(&whole);
    r->ok = app_failures == 0;
    return r->ok;
}

static void runs_free(runs_t *r) {
    free(r->native);
    free(r->page);
    image_free(&r->shot);
}

/* The text after the first "state: " of an output, to the end of its line,
 * into out; false when there is none. */
static bool state_line(const char *output, char *out, size_t size) {
    const char *at = output != NULL ? strstr(output, "state: ") : NULL;
    if (at == NULL) return false;
    size_t length = strcspn(at, "\n");
    snprintf(out, size, "%.*s", (int)length, at);
    return true;
}

/* The state line without its hash ("  hash H" taken out), into out. */
static void without_hash(const char *line, char *out, size_t size) {
    const char *at = strstr(line, "  hash ");
    if (at == NULL) {
        snprintf(out, size, "%s", line);
        return;
    }
    const char *rest = at + 7 + strspn(at + 7, "0123456789abcdef");
    snprintf(out, size, "%.*s%s", (int)(at - line), line, rest);
}

/* The page's state line says what the native one says (frame, bodies, a
 * game's score, lives and what is left); the hash of the positions may
 * differ, as libm's sin and cos may by an ulp (expect_bodies_close). */
static void expect_same_state(const runs_t *r, char *page_state, size_t size) {
    char native[256];
    if (!state_line(r->native, native, sizeof native)) {
        app_fail("no state line from the native build:\n%s", r->native);
        return;
    }
    if (!state_line(r->page, page_state, size)) {
        app_fail("no state line from the page:\n%s", r->page);
        return;
    }
    char a[256], b[256];
    without_hash(native, a, sizeof a);
    without_hash(page_state, b, sizeof b);
    EXPECT(strcmp(a, b) == 0, "the page logged\n      %s\n    the native build\n      %s",
           page_state, native);
}

/* Every body the native build logged (`log bodies`) is where the page has
 * it, to 1e-9 m and rad; count bodies, or any number when count is 0. The
 * two builds' sin and cos (glibc's, Emscripten's musl) differ by an ulp for
 * some angles, so the bits may part while the motion agrees; says the
 * largest difference and whether the bits agree. */
static void expect_bodies_close(const runs_t *r, const char *what, int count) {
    double worst = 0.0;
    int compared = 0;
    const char *native = r->native;
    while ((native = strstr(native, "\nbody ")) != NULL) {
        native++;
        int index;
        double x, y, angle;
        if (sscanf(native, "body %d %lf %lf %lf", &index, &x, &y, &angle) != 4) continue;
        char key[32];
        snprintf(key, sizeof key, "log: body %d ", index);
        const char *page = strstr(r->page, key);
        double px, py, pangle;
        if (page == NULL || sscanf(page + strlen(key), "%lf %lf %lf", &px, &py, &pangle) != 3) {
            app_fail("the page logged no position for body %d", index);
            continue;
        }
        worst = fmax(worst, fmax(fabs(px - x), fmax(fabs(py - y), fabs(pangle - angle))));
        compared++;
    }
    EXPECT(compared > 0 && (count == 0 || compared == count), "compared %d bodies, expected %d",
           compared, count);
    EXPECT(worst <= 1e-9, "the page's bodies are up to %.3g m (or rad) from the native ones", worst);
    char native_state[256], page_state[256];
    bool same_bits = state_line(r->native, native_state, sizeof native_state) &&
                     state_line(r->page, page_state, sizeof page_state) &&
                     strcmp(native_state, page_state) == 0;
    printf("    %s: %d bodies, largest difference %.3g m, %s\n", what, compared, worst,
           same_bits ? "the same bits (hash)" : "hashes differ (libm's last bit)");
}

static int read_number_after(const char *line, const char *label) {
    const char *at = strstr(line, label);
    return at != NULL ? atoi(at + strlen(label)) : -1;
}

/* ---- the screenshot ---- */

/* Anything drawn in the view but its background, grid and container. */
static bool is_scene_pixel(const unsigned char *p) {
    return !same_color(p, PALETTE_BACKGROUND) && !same_color(p, PALETTE_GRID) &&
           !same_color(p, PALETTE_STATIC);
}

/* Bodies in the view and the side bar's panels drawn. */
static void expect_arena_and_side_bar(const image_t *shot, long min_pixels) {
    layout_t layout = layout_of(shot->width, shot->height);
    long drawn = image_count(shot, is_scene_pixel, 0, 0, layout.view.w, shot->height);
    EXPECT(drawn >= min_pixels, "%ld pixels of bodies and overlays in the page's view, expected "
           "%ld or more", drawn, min_pixels);
    EXPECT(shows(shot, "SIMULATION", false) && shows(shot, "ELASTICITY", false) &&
               shows(shot, "INTEGRATOR", false),
           "the side bar's SIMULATION, ELASTICITY and INTEGRATOR panels are not in the page's "
           "screenshot");
}

/* ---- the tests ---- */

/* Drops, a throw, a grab and a shape change in the default scene: the page
 * ends where the native build ends (to 1e-9 m), and draws it. */
static void test_drops_match_native(void) {
    const char *script = "click -6 8\n"
                         "key b\n"
                         "click 0 10\n"
                         "key 3\n"
                         "click 6 12\n"
                         "wait 30\n"
                         "throw -10 15 -4 18 6\n"
                         "key up\n"
                         "click 2 20\n"
                         "wait 240\n"
                         "grab -6 0.4 -3 5 20\n"
                         "wait 60\n"
                         "log bodies\n";
    runs_t r;
    if (run_both("drops", "", 1280, 720, script, NULL, true, &r)) {
        char state[256];
        expect_same_state(&r, state, sizeof state);
        EXPECT(read_number_after(state, "bodies ") == 8, "expected 8 bodies (the container's 3 "
               "and 5 dropped), the page logged: %s", state);
        expect_bodies_close(&r, "drops, throw and grab, 356 frames", 8);
        expect_arena_and_side_bar(&r.shot, 300);
        EXPECT(shows(&r.shot, "sandbox", false), "the SCENE panel does not name the sandbox");
    }
    runs_free(&r);
}

/* A minute of Breakout with the arrow keys (app/scripts/breakout.txt, then
 * 30 s more of presses): the same bricks fall, the same score, the bodies
 * where the native build has them (to 1e-9 m). */
static void test_breakout_minute_matches_native(void) {
    char *first = read_text_file("app/scripts/breakout.txt");
    if (first == NULL) return;
    size_t size = strlen(first) + 2048;
    char *script = malloc(size);
    snprintf(script, size, "%s\n", first);
    free(first);
    for (int i = 0; i < 6; i++) {
        strcat(script, "keydown left\nwait 20\nkeyup left\nwait 130\n"
                       "keydown right\nwait 20\nkeyup right\nwait 130\n");
    }
    strcat(script, "log bodies\n");
    runs_t r;
    if (run_both("breakout", "assets/scenes/breakout.scene", 800, 600, script, NULL, true, &r)) {
        char state[256];
        expect_same_state(&r, state, sizeof state);
        expect_bodies_close(&r, "Breakout, 3600 frames", 0);
        int score = read_number_after(state, "score ");
        EXPECT(read_number_after(state, "frame ") == 3600, "not logged at frame 3600: %s", state);
        EXPECT(score > 0, "no brick was hit in a minute: %s", state);
        char words[32];
        snprintf(words, sizeof words, "score %d", score);
        EXPECT(shows(&r.shot, "breakout", false) && shows(&r.shot, words, false),
               "the SCENE panel does not show breakout and \"%s\"", words);
        expect_arena_and_side_bar(&r.shot, 2000);
    }
    free(script);
    runs_free(&r);
}

/* The pyramid preset after 600 frames: every body where the native build
 * has it, to 1e-9 m and rad. */
static void test_pyramid_matches_native(void) {
    runs_t r;
    if (run_both("pyramid", "assets/scenes/pyramid.scene", 1280, 720, "wait 600\nlog bodies\n", NULL,
                 true, &r)) {
        char state[256];
        expect_same_state(&r, state, sizeof state);
        expect_bodies_close(&r, "pyramid, 600 frames", 56);
    }
    runs_free(&r);
}

/* Ctrl+S in the page downloads saved-1.scene; the native build opens it
 * and finds the bodies where the page had them. */
static void test_saving_downloads_the_scene(void) {
    const char *script = "click -3 6\nclick 3 9\nwait 60\nkey ctrl+s\nlog\n";
    runs_t r;
    if (run_both("save", "", 1280, 720, script, NULL, false, &r)) {
        const char *saved = WEB_TMP_DIR "/save.downloads/saved-1.scene";
        char page_state[256], native_state[256];
        EXPECT(access(saved, R_OK) == 0, "no download %s", saved);
        EXPECT(state_line(r.page, page_state, sizeof page_state), "no state line from the page");
        const char *log_script = tmp_path("save_open", ".txt");
        const char *out = tmp_path("save_open", ".native.txt");
        if (app_failures == 0 && write_file(log_script, "log\n")) {
            const char *argv[] = {SANDBOX, "--headless", "--script", log_script, saved, NULL};
            int status = run(argv, out, 30);
            char *native = read_text_file(out);
            EXPECT(status == 0, "the native build refused the download (%d):\n%s", status,
                   native ? native : "");
            /* The page logged at frame 60, the file opens at frame 0: the
             * rest of the line must agree. */
            if (status == 0 && state_line(native, native_state, sizeof native_state)) {
                const char *a = strstr(page_state, "bodies"), *b = strstr(native_state, "bodies");
                EXPECT(a && b && strcmp(a, b) == 0,
                       "the page saved\n      %s\n    the native build opened\n      %s", a, b);
            }
            free(native);
        }
    }
    runs_free(&r);
}

/* A scene file given to the page's file chooser opens, as a file dropped
 * on the window does (the page's drop handler takes the same path). */
static void test_chosen_scene_file_opens(void) {
    char *cradle = read_text_file("assets/scenes/newtons_cradle.scene");
    const char *chosen = WEB_TMP_DIR "/chosen.scene";
    if (cradle == NULL || !write_file(chosen, cradle)) {
        free(cradle);
        return;
    }
    free(cradle);
    char absolute[4096];
    if (realpath(chosen, absolute) == NULL) {
        app_fail("%s: %s", chosen, strerror(errno));
        return;
    }
    /* A window's clock (no --headless): the file arrives while frames run
     * at the display's rate; two seconds later the state is logged. */
    runs_t r;
    if (run_both("chosen", "", 1280, 720, "wait 2s\nlog\nquit\n", absolute, false, &r)) {
        const char *log_script = tmp_path("chosen_open", ".txt");
        const char *out = tmp_path("chosen_open", ".native.txt");
        char page_state[256], native_state[256];
        if (write_file(log_script, "log\n")) {
            const char *argv[] = {SANDBOX, "--headless", "--script", log_script, chosen, NULL};
            int status = run(argv, out, 30);
            char *native = read_text_file(out);
            if (status == 0 && state_line(native, native_state, sizeof native_state) &&
                state_line(r.page, page_state, sizeof page_state)) {
                int want = read_number_after(native_state, "bodies ");
                int got = read_number_after(page_state, "bodies ");
                EXPECT(got == want, "the page has %d bodies after choosing the cradle, the file "
                       "has %d", got, want);
            } else {
                app_fail("no state lines (native status %d)", status);
            }
            free(native);
        }
        EXPECT(shows(&r.shot, "chosen", false), "the SCENE panel does not name the chosen file");
        EXPECT(strstr(r.page, "cannot open") == NULL, "the page refused the file:\n%s", r.page);
    }
    runs_free(&r);
}

static const app_test_t TESTS[] = {
    {"web.drops_match_native", test_drops_match_native},
    {"web.breakout_minute_matches_native", test_breakout_minute_matches_native},
    {"web.pyramid_matches_native", test_pyramid_matches_native},
    {"web.saving_downloads_the_scene", test_saving_downloads_the_scene},
    {"web.chosen_scene_file_opens", test_chosen_scene_file_opens},
};
#define TEST_COUNT (sizeof TESTS / sizeof TESTS[0])

int main(int argc, char **argv) {
    const char *filter = argc > 1 ? argv[1] : NULL;
    const char *missing = !have_command("emcc")       ? "emcc"
                          : !have_command("chromium") ? "chromium"
                          : !have_command("node")     ? "node"
                          : access(SANDBOX, X_OK) != 0 ? "the native ./sandbox (SDL2)"
                                                       : NULL;
    if (missing != NULL) {
        printf("SKIP web: %s is not installed; make check-web installs what it needs and runs "
               "these %zu tests\n", missing, TEST_COUNT);
        printf("0 passed, 0 failed, %zu skipped\n", TEST_COUNT);
        return 0;
    }
    if (access(PAGE, R_OK) != 0) {
        /* make check builds the page only once SDL2 for WebAssembly is. */
        printf("SKIP web: %s is not built; make web builds it once (about 6 minutes), "
               "then make check runs these %zu tests\n", PAGE, TEST_COUNT);
        printf("0 passed, 0 failed, %zu skipped\n", TEST_COUNT);
        return 0;
    }
    mkdir("build", 0755);
    mkdir("build/tests", 0755);
    mkdir(WEB_TMP_DIR, 0755);
    app_tmp_dir = WEB_TMP_DIR;
    return app_run_tests(TESTS, TEST_COUNT, filter);
}
