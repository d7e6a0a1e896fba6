/*
 * Smoke tests of the real sandbox (./sandbox), driven from outside through
 * its --headless, --script and --screenshot flags: drop bodies, let them
 * fall, and read the screenshot's pixels for the body and overlay colours;
 * feed it bad flags and scripts and check the messages. It needs no SDL
 * itself: when the sandbox could not be built (SDL2 or SDL2_gfx missing) the
 * tests are reported as skipped with the reason.
 *
 * Run from the repository root (make check does). SANDBOX=path overrides
 * ./sandbox; files go to build/tests/app_smoke.tmp/.
 */
#include <errno.h>
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
#include "palette.h"

#ifndef APP_SMOKE_HAVE_SDL
#define APP_SMOKE_HAVE_SDL 0
#endif

#define TMP_DIR "build/tests/app_smoke.tmp"
#define WIDTH 800
#define HEIGHT 600
#define SIZE_FLAG "800x600"

static const char *sandbox_path = "./sandbox";
static int failures; /* of the current test */

static void fail(const char *format, ...) {
    va_list args;
    va_start(args, format);
    printf("    ");
    vprintf(format, args);
    printf("\n");
    va_end(args);
    failures++;
}

#define EXPECT(condition, ...)                                                               \
    do {                                                                                     \
        if (!(condition)) fail(__VA_ARGS__);                                                 \
    } while (0)

/* ---- running the sandbox ---- */

typedef struct {
    int status;   /* exit status, or -1 when killed or not run */
    char output[8192]; /* stdout and stderr together */
} run_t;

/* Runs the sandbox with the given arguments (NULL-terminated), at most
 * timeout_s seconds, capturing its output. */
static void run_sandbox(run_t *run, int timeout_s, const char *const *args) {
    run->status = -1;
    run->output[0] = '\0';
    char *argv[32];
    size_t n = 0;
    argv[n++] = (char *)sandbox_path;
    for (size_t i = 0; args[i] != NULL && n < 31; i++) argv[n++] = (char *)args[i];
    argv[n] = NULL;

    int fds[2];
    if (pipe(fds) != 0) {
        fail("pipe: %s", strerror(errno));
        return;
    }
    fflush(stdout);
    pid_t child = fork();
    if (child < 0) {
        fail("fork: %s", strerror(errno));
        return;
    }
    if (child == 0) {
        dup2(fds[1], STDOUT_FILENO);
        dup2(fds[1], STDERR_FILENO);
        close(fds[0]);
        close(fds[1]);
        execv(argv[0], argv);
        fprintf(stderr, "cannot run %s: %s\n", argv[0], strerror(errno));
        _exit(127);
    }
    close(fds[1]);
    size_t size = 0;
    ssize_t got;
    char buffer[4096];
    while ((got = read(fds[0], buffer, sizeof buffer)) > 0) {
        size_t room = sizeof(run->output) - 1 - size;
        size_t take = (size_t)got < room ? (size_t)got : room;
        memcpy(run->output + size, buffer, take);
        size += take;
    }
    run->output[size] = '\0';
    close(fds[0]);
    /* The pipe closed: the child is exiting; wait with a deadline. */
    int status = 0;
    struct timespec pause = {0, 10 * 1000 * 1000};
    for (int waited = 0;; waited++) {
        pid_t done = waitpid(child, &status, WNOHANG);
        if (done == child) break;
        if (waited > timeout_s * 100) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            fail("the sandbox did not exit within %d s", timeout_s);
            return;
        }
        nanosleep(&pause, NULL);
    }
    if (WIFSIGNALED(status)) {
        fail("the sandbox died with signal %d; output:\n%s", WTERMSIG(status), run->output);
        return;
    }
    run->status = WEXITSTATUS(status);
}

static bool write_file(const char *path, const char *text) {
    FILE *file = fopen(path, "w");
    if (file == NULL) {
        fail("cannot write %s: %s", path, strerror(errno));
        return false;
    }
    fputs(text, file);
    fclose(file);
    return true;
}

/* ---- reading screenshots ---- */

typedef struct {
    int width, height;
    unsigned char *rgb; /* top row first, 3 bytes a pixel */
} image_t;

static uint32_t le32(const unsigned char *p) {
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Reads an uncompressed 24- or 32-bit BMP (what SDL_SaveBMP writes). */
static bool read_bmp(const char *path, image_t *image) {
    image->rgb = NULL;
    FILE *file = fopen(path, "rb");
    if (file == NULL) {
        fail("no screenshot %s: %s", path, strerror(errno));
        return false;
    }
    fseek(file, 0, SEEK_END);
    long size = ftell(file);
    fseek(file, 0, SEEK_SET);
    unsigned char *data = size > 54 ? malloc((size_t)size) : NULL;
    bool ok = data != NULL && fread(data, 1, (size_t)size, file) == (size_t)size;
    fclose(file);
    if (!ok || data[0] != 'B' || data[1] != 'M') {
        fail("%s is not a BMP file", path);
        free(data);
        return false;
    }
    uint32_t offset = le32(data + 10);
    int32_t width = (int32_t)le32(data + 18), height = (int32_t)le32(data + 22);
    int bpp = data[28] | data[29] << 8;
    uint32_t compression = le32(data + 30);
    bool top_down = height < 0;
    if (top_down) height = -height;
    size_t stride = ((size_t)width * (size_t)(bpp / 8) + 3) & ~(size_t)3;
    if ((bpp != 24 && bpp != 32) || (compression != 0 && compression != 3) || width <= 0 ||
        height <= 0 || offset + stride * (size_t)height > (size_t)size) {
        fail("%s: unsupported BMP (%d bits, compression %u, %dx%d)", path, bpp, compression,
             width, height);
        free(data);
        return false;
    }
    image->width = width;
    image->height = height;
    image->rgb = malloc((size_t)width * (size_t)height * 3);
    for (int y = 0; y < height; y++) {
        const unsigned char *row = data + offset + stride * (size_t)(top_down ? y : height - 1 - y);
        for (int x = 0; x < width; x++) {
            const unsigned char *p = row + (size_t)x * (size_t)(bpp / 8);
            unsigned char *q = image->rgb + ((size_t)y * (size_t)width + (size_t)x) * 3;
            q[0] = p[2];
            q[1] = p[1];
            q[2] = p[0];
        }
    }
    free(data);
    return true;
}

static const unsigned char *pixel(const image_t *image, int x, int y) {
    return image->rgb + ((size_t)y * (size_t)image->width + (size_t)x) * 3;
}

static bool is_body_color(const unsigned char *p) {
    for (int i = 0; i < PALETTE_BODY_COUNT; i++) {
        if (p[0] == PALETTE_BODIES[i].r && p[1] == PALETTE_BODIES[i].g &&
            p[2] == PALETTE_BODIES[i].b) {
            return true;
        }
    }
    return false;
}

/* The axis arrows are opaque yellow (255, 235, 0); the UI's accent
 * (255, 200, 60) and the orange body (242, 140, 40) stay out. */
static bool is_axis_color(const unsigned char *p) {
    return p[0] > 230 && p[1] > 215 && p[2] < 60;
}

/* The impulse arrows are magenta (255, 0, 220) fading out: blended over the
 * background or a body they keep red and blue well above green. */
static bool is_impulse_color(const unsigned char *p) {
    return p[0] > 110 && p[2] > 100 && p[1] < 70 && p[0] - p[1] > 90 && p[2] - p[1] > 80;
}

static bool is_static_color(const unsigned char *p) {
    return p[0] == PALETTE_STATIC.r && p[1] == PALETTE_STATIC.g && p[2] == PALETTE_STATIC.b;
}

typedef bool (*color_test_t)(const unsigned char *);

/* Pixels of a colour in [x0, x1) x [y0, y1), clipped to the image. */
static long count_in(const image_t *image, color_test_t test, int x0, int y0, int x1, int y1) {
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > image->width) x1 = image->width;
    if (y1 > image->height) y1 = image->height;
    long count = 0;
    for (int y = y0; y < y1; y++) {
        for (int x = x0; x < x1; x++) count += test(pixel(image, x, y));
    }
    return count;
}

/* The floor's top row: the first static-coloured pixel going down column x
 * from below the top panels. */
static int floor_top(const image_t *image, int x) {
    for (int y = 160; y < image->height; y++) {
        if (is_static_color(pixel(image, x, y))) return y;
    }
    return -1;
}

/* ---- the tests ---- */

static const char *shot_path(const char *name) {
    static char path[256];
    snprintf(path, sizeof path, TMP_DIR "/%s.bmp", name);
    return path;
}

static const char *script_path(const char *name) {
    static char path[256];
    snprintf(path, sizeof path, TMP_DIR "/%s.txt", name);
    return path;
}

/* Runs a script headless at 800x600 with up to four extra arguments
 * (NULL-terminated); false on failure. */
static bool run_script(const char *name, const char *script, const char *const *extra,
                       run_t *run) {
    if (!write_file(script_path(name), script)) return false;
    char shot[256], script_file[256];
    snprintf(shot, sizeof shot, "%s", shot_path(name));
    snprintf(script_file, sizeof script_file, "%s", script_path(name));
    remove(shot);
    const char *args[12] = {"--headless", "--size", SIZE_FLAG, "--script", script_file,
                            "--screenshot", shot};
    for (int i = 0; i < 4 && extra[i] != NULL; i++) args[7 + i] = extra[i];
    run_sandbox(run, 60, args);
    if (run->status != 0) {
        fail("the sandbox exited with %d; output:\n%s", run->status, run->output);
        return false;
    }
    return true;
}

/* Three bodies dropped at pixel columns 200, 400 and 600 come to rest on the
 * floor: their colours are there, just above the floor, and no longer where
 * they were dropped. */
static void test_dropped_bodies_rest_on_floor(void) {
    run_t run;
    const char *script = "# three bodies, no bounce, 3 s to settle\n"
                         "click px 200 250\n"
                         "key b\n"
                         "click px 400 250\n"
                         "key p\n"
                         "click px 600 250\n"
                         "wait 3s\n"
                         "move px 790 590\n";
    const char *flags[] = {"--elasticity", "0", "--overlays", "none", NULL};
    if (!run_script("rest", script, flags, &run)) return;
    image_t image;
    if (!read_bmp(shot_path("rest"), &image)) return;
    EXPECT(image.width == WIDTH && image.height == HEIGHT, "screenshot is %dx%d, not %dx%d",
           image.width, image.height, WIDTH, HEIGHT);
    int floor_y = floor_top(&image, 700);
    EXPECT(floor_y > HEIGHT / 2, "no floor found in column 700 (got row %d)", floor_y);
    if (floor_y <= HEIGHT / 2) goto done;
    const int columns[3] = {200, 400, 600};
    for (int i = 0; i < 3; i++) {
        int x = columns[i];
        long resting = count_in(&image, is_body_color, x - 40, floor_y - 50, x + 40, floor_y);
        long above = count_in(&image, is_body_color, x - 40, 200, x + 40, 300);
        EXPECT(resting > 80, "column %d: %ld body-coloured pixels just above the floor (row %d), "
                             "expected a resting body", x, resting, floor_y);
        EXPECT(above == 0, "column %d: %ld body-coloured pixels where it was dropped", x, above);
    }
done:
    free(image.rgb);
}

/* A large body dropped near the floor (no bounce), screenshot just after it
 * lands, while it rests there: the axis arrows (yellow) and the fading
 * impulse arrows (magenta) are drawn at the contact. */
static void test_overlays_on_while_colliding(void) {
    run_t run;
    const char *script = "wheel 5\n"        /* size 0.5 -> 0.8 m */
                         "click px 400 470\n" /* lands after about 30 frames */
                         "wait 40\n"
                         "move px 790 590\n";
    const char *flags[] = {"--elasticity", "0", NULL};
    if (!run_script("overlays_on", script, flags, &run)) return;
    image_t image;
    if (!read_bmp(shot_path("overlays_on"), &image)) return;
    int floor_y = floor_top(&image, 700);
    EXPECT(floor_y > HEIGHT / 2, "no floor found in column 700");
    int y0 = floor_y - 120, y1 = floor_y + 10;
    long bodies = count_in(&image, is_body_color, 300, y0, 500, floor_y);
    long axes = count_in(&image, is_axis_color, 300, y0, 500, y1);
    long impulses = count_in(&image, is_impulse_color, 300, y0, 500, y1);
    EXPECT(bodies > 200, "the dropped body is not on the floor (%ld body pixels)", bodies);
    EXPECT(axes > 20, "only %ld axis-coloured pixels at the collision", axes);
    EXPECT(impulses > 20, "only %ld impulse-coloured pixels at the collision", impulses);
    free(image.rgb);
}

/* The same drop with the axes and impulses toggled off by their keys: none of
 * their colours anywhere in the frame. */
static void test_overlays_off_draw_nothing(void) {
    run_t run;
    const char *script = "key a\n"
                         "key i\n"
                         "wheel 5\n"
                         "click px 400 470\n" /* lands after about 30 frames */
                         "wait 40\n"
                         "move px 790 590\n";
    const char *flags[] = {"--elasticity", "0", NULL};
    if (!run_script("overlays_off", script, flags, &run)) return;
    image_t image;
    if (!read_bmp(shot_path("overlays_off"), &image)) return;
    int floor_y = floor_top(&image, 700);
    long bodies = count_in(&image, is_body_color, 300, floor_y - 120, 500, floor_y);
    long axes = count_in(&image, is_axis_color, 0, 0, image.width, image.height);
    long impulses = count_in(&image, is_impulse_color, 0, 0, image.width, image.height);
    EXPECT(bodies > 200, "the dropped body is not on the floor (%ld body pixels)", bodies);
    EXPECT(axes == 0, "%ld axis-coloured pixels with the axes overlay off", axes);
    EXPECT(impulses == 0, "%ld impulse-coloured pixels with the impulses overlay off", impulses);
    free(image.rgb);
}

/* Shift + drag to the right throws the body: it lands in the right half. */
static void test_throw_carries_the_drag_velocity(void) {
    run_t run;
    const char *script = "throw px 150 300 180 300 5\n" /* 14 m/s to the right */
                         "wait 2s\n"
                         "move px 790 590\n";
    const char *flags[] = {"--elasticity", "0", "--overlays", "none", NULL};
    if (!run_script("throw", script, flags, &run)) return;
    image_t image;
    if (!read_bmp(shot_path("throw"), &image)) return;
    long left = count_in(&image, is_body_color, 0, 160, 300, image.height);
    long right = count_in(&image, is_body_color, 400, 160, image.width, image.height);
    EXPECT(right > 80 && left == 0,
           "thrown body: %ld body pixels right of x = 400, %ld left of x = 300", right, left);
    free(image.rgb);
}

/* D with the cursor on a body deletes it. */
static void test_delete_key_removes_body(void) {
    run_t run;
    /* Drop at x = 0, let it settle, hover where it rests, delete. */
    const char *delete_script = "click px 400 450\n"
                                "wait 2s\n"
                                "move 0 0.3\n"
                                "key d\n"
                                "wait 2\n"
                                "move px 790 590\n";
    const char *flags[] = {"--overlays", "none", "--elasticity", "0", NULL};
    if (!run_script("delete", delete_script, flags, &run)) return;
    image_t image;
    if (!read_bmp(shot_path("delete"), &image)) return;
    long bodies = count_in(&image, is_body_color, 0, 160, image.width, image.height);
    EXPECT(bodies == 0, "%ld body pixels after deleting the only body", bodies);
    free(image.rgb);
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

    const char *elasticity[] = {"--headless", "--elasticity", "nan", NULL};
    const char *e5[] = {"--elasticity", "'nan'", NULL};
    check_refusal("nonsense --elasticity", elasticity, 2, e5);

    const char *bad_dir[] = {"--headless", "--screenshot", TMP_DIR "/no/such/dir/x.bmp", NULL};
    const char *e6[] = {"cannot save the screenshot", "no/such/dir/x.bmp", NULL};
    check_refusal("unwritable screenshot", bad_dir, 1, e6);

    run_t run;
    const char *help[] = {"--help", NULL};
    run_sandbox(&run, 20, help);
    EXPECT(run.status == 0, "--help exited with %d", run.status);
    const char *documented[] = {"--headless", "--frames", "--screenshot", "--script",
                                "wait", "click", "throw", "screenshot"};
    for (size_t i = 0; i < sizeof documented / sizeof documented[0]; i++) {
        EXPECT(strstr(run.output, documented[i]) != NULL, "--help does not mention %s",
               documented[i]);
    }
}

static void test_bad_scripts_are_refused(void) {
    const char *missing[] = {"--headless", "--script", TMP_DIR "/no_such_script.txt", NULL};
    const char *e1[] = {"cannot open script", "no_such_script.txt", NULL};
    check_refusal("missing script", missing, 2, e1);

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
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char name[64];
        snprintf(name, sizeof name, "bad_%s", cases[i].name);
        if (!write_file(script_path(name), cases[i].text)) continue;
        const char *args[] = {"--headless", "--script", script_path(name), NULL};
        char what[96];
        snprintf(what, sizeof what, "malformed script (%s)", cases[i].name);
        check_refusal(what, args, 2, cases[i].expect);
    }
}

typedef struct {
    const char *name;
    void (*run)(void);
} smoke_test_t;

static const smoke_test_t TESTS[] = {
    {"app_smoke.dropped_bodies_rest_on_floor", test_dropped_bodies_rest_on_floor},
    {"app_smoke.overlays_on_while_colliding", test_overlays_on_while_colliding},
    {"app_smoke.overlays_off_draw_nothing", test_overlays_off_draw_nothing},
    {"app_smoke.throw_carries_the_drag_velocity", test_throw_carries_the_drag_velocity},
    {"app_smoke.delete_key_removes_body", test_delete_key_removes_body},
    {"app_smoke.bad_flags_are_refused", test_bad_flags_are_refused},
    {"app_smoke.bad_scripts_are_refused", test_bad_scripts_are_refused},
};
#define TEST_COUNT (sizeof TESTS / sizeof TESTS[0])

static void skip_all(const char *reason) {
    for (size_t i = 0; i < TEST_COUNT; i++) printf("SKIP %s: %s\n", TESTS[i].name, reason);
    printf("0 passed, 0 failed, %zu skipped\n", TEST_COUNT);
}

int main(int argc, char **argv) {
    const char *filter = argc > 1 ? argv[1] : NULL;
    const char *override = getenv("SANDBOX");
    if (override != NULL && override[0] != '\0') sandbox_path = override;
    if (!APP_SMOKE_HAVE_SDL) {
        skip_all("SDL2 or SDL2_gfx development files were not found by pkg-config when this "
                 "was built, so ./sandbox was not built (install: apt-get install -y "
                 "libsdl2-dev libsdl2-gfx-dev pkg-config)");
        return 0;
    }
    if (access(sandbox_path, X_OK) != 0) {
        /* SDL is there, so the sandbox should have been built: a failure. */
        for (size_t i = 0; i < TEST_COUNT; i++) {
            printf("FAIL %s: %s is missing or not executable (make sandbox)\n", TESTS[i].name,
                   sandbox_path);
        }
        printf("0 passed, %zu failed\n", TEST_COUNT);
        return 1;
    }
    mkdir("build", 0755);
    mkdir("build/tests", 0755);
    mkdir(TMP_DIR, 0755);
    size_t passed = 0, failed = 0;
    for (size_t i = 0; i < TEST_COUNT; i++) {
        if (filter != NULL && strstr(TESTS[i].name, filter) == NULL) continue;
        failures = 0;
        TESTS[i].run();
        printf("%s %s\n", failures == 0 ? "PASS" : "FAIL", TESTS[i].name);
        fflush(stdout);
        if (failures == 0) passed++;
        else failed++;
    }
    printf("%zu passed, %zu failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
