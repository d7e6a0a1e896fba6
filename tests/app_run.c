/* Helpers of the sandbox's smoke tests (tests/app_smoke*.c): running
 * ./sandbox headless with a script, reading its screenshots (colours, where
 * the container is, the side bar's words). */
#include "app_run.h"
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

const char *sandbox_path = "./sandbox";
const char *app_tmp_dir = TMP_DIR;

/* ---- running the sandbox ---- */

int wait_for_child(pid_t child, const char *what, int timeout_s) {
    int status = 0;
    struct timespec pause = {0, 10 * 1000 * 1000};
    for (int waited = 0;; waited++) {
        if (waitpid(child, &status, WNOHANG) == child) break;
        if (waited > timeout_s * 100) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            app_fail("%s did not exit within %d s", what, timeout_s);
            return -1;
        }
        nanosleep(&pause, NULL);
    }
    if (WIFSIGNALED(status)) {
        app_fail("%s died with signal %d", what, WTERMSIG(status));
        return -1;
    }
    return WEXITSTATUS(status);
}


/* Runs the sandbox with the given arguments (NULL-terminated), at most
 * timeout_s seconds, capturing its output. */
void run_sandbox(run_t *run, int timeout_s, const char *const *args) {
    run->status = -1;
    run->output[0] = '\0';
    char *argv[32];
    size_t n = 0;
    argv[n++] = (char *)sandbox_path;
    for (size_t i = 0; args[i] != NULL && n < 31; i++) argv[n++] = (char *)args[i];
    argv[n] = NULL;

    int fds[2];
    if (pipe(fds) != 0) {
        app_fail("pipe: %s", strerror(errno));
        return;
    }
    fflush(stdout);
    pid_t child = fork();
    if (child < 0) {
        app_fail("fork: %s", strerror(errno));
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
    /* The pipe closed: the child is exiting. */
    run->status = wait_for_child(child, "the sandbox", timeout_s);
    if (run->status < 0 && run->output[0] != '\0') app_fail("its output:\n%s", run->output);
}


bool write_file(const char *path, const char *text) {
    FILE *file = fopen(path, "w");
    if (file == NULL) {
        app_fail("cannot write %s: %s", path, strerror(errno));
        return false;
    }
    fputs(text, file);
    fclose(file);
    return true;
}

char *read_text_file(const char *path) {
    FILE *file = fopen(path, "rb");
    if (file == NULL) {
        app_fail("cannot read %s: %s", path, strerror(errno));
        return NULL;
    }
    fseek(file, 0, SEEK_END);
    long size = ftell(file);
    fseek(file, 0, SEEK_SET);
    char *text = malloc((size_t)size + 1);
    if (text != NULL && fread(text, 1, (size_t)size, file) == (size_t)size) {
        text[size] = '\0';
    } else {
        free(text);
        text = NULL;
        app_fail("cannot read %s", path);
    }
    fclose(file);
    return text;
}

/* ---- colours ---- */

bool is_body_color(const unsigned char *p) {
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
bool is_axis_color(const unsigned char *p) {
    return p[0] > 230 && p[1] > 215 && p[2] < 60;
}

/* The impulse arrows are magenta (255, 0, 220) fading out: blended over the
 * background or a body they keep red and blue well above green. */
bool is_impulse_color(const unsigned char *p) {
    return p[0] > 110 && p[2] > 100 && p[1] < 70 && p[0] - p[1] > 90 && p[2] - p[1] > 80;
}

bool is_static_color(const unsigned char *p) {
    return p[0] == PALETTE_STATIC.r && p[1] == PALETTE_STATIC.g && p[2] == PALETTE_STATIC.b;
}

bool is_text_color(const unsigned char *p) {
    return p[0] == PALETTE_TEXT.r && p[1] == PALETTE_TEXT.g && p[2] == PALETTE_TEXT.b;
}

bool same_color(const unsigned char *p, palette_rgb_t c) {
    return p[0] == c.r && p[1] == c.g && p[2] == c.b;
}

/* ---- where things are ---- */

layout_t layout_800(void) {
    return layout_of(WIDTH, HEIGHT);
}


bool map_world(const image_t *image, world_map_t *map) {
    if (!image_bounds(image, is_static_color, &map->left, &map->top, &map->right,
                      &map->bottom)) {
        app_fail("no container (static colour) in the screenshot");
        return false;
    }
    map->scale = (map->right - map->left + 1) / 30.0;
    return true;
}

int px_x(const world_map_t *map, double x) {
    return (int)lround(map->left + (x + 15.0) * map->scale);
}

int px_y(const world_map_t *map, double y) {
    return (int)lround(map->bottom + 1 - (y + 1.0) * map->scale);
}

/* ---- running scripts ---- */

const char *tmp_path(const char *name, const char *extension) {
    static char paths[4][256];
    static int next;
    char *path = paths[next++ % 4];
    snprintf(path, 256, "%s/%s%s", app_tmp_dir, name, extension);
    return path;
}

/* Runs a script headless (at `size`, NULL for 800x600) with up to four extra
 * arguments (NULL-terminated), the last frame saved to TMP_DIR/name.bmp;
 * false on failure. */
bool run_script_at(const char *name, const char *size, const char *script,
                          const char *const *extra, run_t *run) {
    char shot[256], script_file[256];
    snprintf(shot, sizeof shot, "%s", tmp_path(name, ".bmp"));
    snprintf(script_file, sizeof script_file, "%s", tmp_path(name, ".txt"));
    if (!write_file(script_file, script)) return false;
    remove(shot);
    const char *args[16] = {"--headless", "--size", size != NULL ? size : SIZE_FLAG,
                            "--script",   script_file, "--screenshot", shot};
    for (int i = 0; i < 6 && extra != NULL && extra[i] != NULL; i++) args[7 + i] = extra[i];
    run_sandbox(run, 60, args);
    if (run->status != 0) {
        app_fail("the sandbox exited with %d; output:\n%s", run->status, run->output);
        return false;
    }
    return true;
}

bool run_script(const char *name, const char *script, const char *const *extra,
                       run_t *run) {
    return run_script_at(name, NULL, script, extra, run);
}

/* Reads TMP_DIR/name.bmp (a screenshot of the last run). */
bool load_shot(const char *name, image_t *image) {
    char why[512];
    if (image_read(tmp_path(name, ".bmp"), image, why, sizeof why)) return true;
    app_fail("%s", why);
    return false;
}

/* Whether text is on screen in the side bar (anywhere when anywhere). */
bool shows(const image_t *image, const char *text, bool anywhere) {
    int x0 = anywhere ? 0 : layout_of(image->width, image->height).sidebar.x;
    return image_find_text(image, text, x0, 0, image->width, image->height, NULL, NULL, NULL);
}

/* The rest of the side bar line that starts with `label`, e.g. the "0" of
 * "bodies 0"; false when the label is not there. */
bool read_line_after(const image_t *image, const char *label, char *out, size_t max) {
    int x, y;
    unsigned char color[3];
    int x0 = layout_of(image->width, image->height).sidebar.x;
    if (!image_find_text(image, label, x0, 0, image->width, image->height, &x, &y, color)) {
        return false;
    }
    image_read_text(image, x + 8 * (int)strlen(label), y, color, out, max);
    return true;
}

/* Body pixels in the view (the side bar's shape icon is body-coloured). */
long bodies_in_view(const image_t *image) {
    return image_count(image, is_body_color, 0, 0, layout_of(image->width, image->height).view.w,
                       image->height);
}

/* No text in the side bar's right padding: no line runs past its border. */
void expect_text_inside(const image_t *image, const char *what) {
    long outside = image_count(image, is_text_color, image->width - LAYOUT_PAD + 2, 0,
                               image->width, image->height);
    EXPECT(outside == 0, "%s: %ld text pixels in the side bar's right padding", what, outside);
}


/* ---- reading the side bar ---- */

/* The state ("on" / "off") at the end of an overlay's legend line, and its
 * colour. */
bool legend_state(const image_t *image, const char *name, char *state,
                         unsigned char color[3]) {
    int x, y, title_y;
    layout_t layout = layout_of(image->width, image->height);
    /* Below the panel's title: the status line may say the same words. */
    if (!image_find_text(image, "OVERLAYS", layout.sidebar.x, 0, image->width, image->height,
                         &x, &title_y, NULL) ||
        !image_find_text(image, name, layout.sidebar.x, title_y + 1, image->width,
                         image->height, &x, &y, NULL)) {
        app_fail("no legend line '%s' under the title OVERLAYS", name);
        return false;
    }
    int end = image->width - LAYOUT_PAD;
    for (int chars = 3; chars >= 2; chars--) {
        const char *word = chars == 3 ? "off" : "on";
        if (image_find_text(image, word, end - 8 * chars, y, end - 8 * chars + 1, y + 1, NULL,
                            NULL, color)) {
            strcpy(state, word);
            return true;
        }
    }
    app_fail("the legend line '%s' ends in neither 'on' nor 'off'", name);
    return false;
}

/* Where text is in the side bar below the panel title `title`. */
bool find_in_panel(const image_t *image, const char *title, const char *text, int *x,
                          int *y, unsigned char color[3]) {
    int tx, ty;
    int x0 = layout_of(image->width, image->height).sidebar.x;
    if (!image_find_text(image, title, x0, 0, image->width, image->height, &tx, &ty, NULL)) {
        return false;
    }
    return image_find_text(image, text, x0, ty + 1, image->width, image->height, x, y, color);
}

/* The name the SCENE panel shows (in the accent colour, below its title). */
bool scene_name(const image_t *image, char *name, size_t max) {
    int x, y;
    name[0] = '\0';
    layout_t layout = layout_of(image->width, image->height);
    if (!image_find_text(image, "SCENE (", layout.sidebar.x, 0, image->width, image->height, &x,
                         &y, NULL)) {
        return false;
    }
    const unsigned char accent[3] = {PALETTE_ACCENT.r, PALETTE_ACCENT.g, PALETTE_ACCENT.b};
    image_read_text(image, x, y + LAYOUT_LINE_H + 3 + 2, accent, name, max);
    return name[0] != '\0';
}
