#ifndef APP_RUN_H
#define APP_RUN_H

/* Helpers of the sandbox's smoke tests (tests/app_smoke*.c): running
 * ./sandbox headless with a script, reading its screenshots (colours, where
 * the container is, the side bar's words). Run from the repository root. */

#include <stdbool.h>
#include <stddef.h>
#include <sys/types.h>
#include "app_image.h"
#include "core/layout.h"
#include "draw/palette.h"

#define APP_EXPECT_SHARED
#include "app_expect.h"

#define TMP_DIR "build/tests/app_smoke.tmp"
#define WIDTH 800
#define HEIGHT 600
#define SIZE_FLAG "800x600"

/* ./sandbox, or what SANDBOX names. */
extern const char *sandbox_path;
/* Where tmp_path puts files: TMP_DIR unless a program sets another. */
extern const char *app_tmp_dir;

typedef struct {
    int status;   /* exit status, or -1 when killed or not run */
    char output[8192]; /* stdout and stderr together */
} run_t;

/* World metres to pixels, measured from the container in a screenshot: the
 * static colour spans x = -15 .. 15 (the walls' outer faces) and y = -1 (the
 * floor's bottom) .. 30 (the walls' top). */
typedef struct {
    int left, top, right, bottom; /* the container's pixels */
    double scale;                 /* pixels per metre */
} world_map_t;

/* Runs the sandbox with the given arguments (NULL-terminated), at most
 * timeout_s seconds, capturing its output. */
void run_sandbox(run_t *run, int timeout_s, const char *const *args);

/* Writes text to path; false (a failure counted) when it cannot. */
bool write_file(const char *path, const char *text);

/* A whole text file, NUL-terminated (free it), or NULL (a failure counted). */
char *read_text_file(const char *path);

/* Waits at most timeout_s seconds for child (then kills it), naming it
 * `what` in a failure; its exit status, or -1 (a failure counted) when it
 * was killed or died of a signal. */
int wait_for_child(pid_t child, const char *what, int timeout_s);

/* Exactly one of the palette's body colours. */
bool is_body_color(const unsigned char *p);

/* The axis arrows are opaque yellow (255, 235, 0); the UI's accent
 * (255, 200, 60) and the orange body (242, 140, 40) stay out. */
bool is_axis_color(const unsigned char *p);

/* The impulse arrows are magenta (255, 0, 220) fading out: blended over the
 * background or a body they keep red and blue well above green. */
bool is_impulse_color(const unsigned char *p);

/* Exactly PALETTE_STATIC, PALETTE_TEXT, c. */
bool is_static_color(const unsigned char *p);
bool is_text_color(const unsigned char *p);
bool same_color(const unsigned char *p, palette_rgb_t c);

/* The layout of the tests' 800x600 window. */
layout_t layout_800(void);

/* Finds the container in a screenshot of the default scene (a failure
 * counted when there is none). */
bool map_world(const image_t *image, world_map_t *map);

/* The pixel column of x and the row of y (m) in the default scene. */
int px_x(const world_map_t *map, double x);
int px_y(const world_map_t *map, double y);

/* app_tmp_dir/name.extension, in one of four buffers used in turn. */
const char *tmp_path(const char *name, const char *extension);

/* Runs a script headless (at `size`, NULL for 800x600) with up to four extra
 * arguments (NULL-terminated), the last frame saved to TMP_DIR/name.bmp;
 * false on failure. */
bool run_script_at(const char *name, const char *size, const char *script,
                   const char *const *extra, run_t *run);

/* run_script_at at 800x600. */
bool run_script(const char *name, const char *script, const char *const *extra, run_t *run);

/* Reads TMP_DIR/name.bmp (a screenshot of the last run). */
bool load_shot(const char *name, image_t *image);

/* Whether text is on screen in the side bar (anywhere when anywhere). */
bool shows(const image_t *image, const char *text, bool anywhere);

/* The rest of the side bar line that starts with `label`, e.g. the "0" of
 * "bodies 0"; false when the label is not there. */
bool read_line_after(const image_t *image, const char *label, char *out, size_t max);

/* Body pixels in the view (the side bar's shape icon is body-coloured). */
long bodies_in_view(const image_t *image);

/* No text in the side bar's right padding: no line runs past its border. */
void expect_text_inside(const image_t *image, const char *what);

/* The state ("on" / "off") at the end of an overlay's legend line, and its
 * colour. */
bool legend_state(const image_t *image, const char *name, char *state, unsigned char color[3]);

/* Where text is in the side bar below the panel title `title`. */
bool find_in_panel(const image_t *image, const char *title, const char *text, int *x, int *y,
                   unsigned char color[3]);

/* The name the SCENE panel shows (in the accent colour, below its title). */
bool scene_name(const image_t *image, char *name, size_t max);

#endif
