#include "draw/raster.h"
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include "core/job_thread.h"

static struct {
    SDL_Renderer *renderer;
    SDL_Surface *canvas;
    int width, height;
} raster;

/* Rows [top, bottom) of the canvas: a thread draws only its own band, so
 * two threads fill one batch at once and every pixel is still written in
 * the batch's order. */
typedef struct {
    int top, bottom;
} band_t;

void raster_begin(SDL_Renderer *renderer, SDL_Surface *canvas) {
    raster.renderer = renderer;
    raster.canvas = canvas != NULL && canvas->format->BytesPerPixel == 4 ? canvas : NULL;
    if (raster.canvas != NULL) {
        SDL_RenderFlush(renderer);
        raster.width = canvas->w;
        raster.height = canvas->h;
    } else if (SDL_GetRendererOutputSize(renderer, &raster.width, &raster.height) != 0) {
        raster.width = raster.height = 0;
    }
}

static Uint32 *row_of(int y) {
    return (Uint32 *)((Uint8 *)raster.canvas->pixels + (size_t)y * (size_t)raster.canvas->pitch);
}

/* ceil and floor for values well inside int's range, without a libm call
 * (x86-64's baseline has no rounding instruction). */
static inline int ceil_int(double v) {
    int i = (int)v;
    return i + (i < v);
}

static inline int floor_int(double v) {
    int i = (int)v;
    return i - (i > v);
}

/* Where the chain of edges from vertex `from` stepping by `step` crosses the
 * horizontal line yc; *edge is the chain's current edge start, advanced as
 * rows go down (yc only grows), so a polygon costs O(rows + vertices). */
static double chain_x(const vector_t *p, int n, int step, int *edge, int bottom, double yc) {
    int a = *edge, b = (a + step + n) % n;
    while (p[b].y <= yc && a != bottom) {
        a = b;
        b = (a + step + n) % n;
    }
    *edge = a;
    double dy = p[b].y - p[a].y;
    return dy > 0.0 ? p[a].x + (yc - p[a].y) * (p[b].x - p[a].x) / dy : p[a].x;
}

/* Scan-converts a convex polygon straight into the band of the canvas. */
static void canvas_fill(const vector_t *p, int n, palette_rgb_t color, band_t band) {
    if (n < 3 || raster.width <= 0) return;
    int top = 0, bottom = 0;
    for (int i = 1; i < n; i++) {
        if (p[i].y < p[top].y) top = i;
        if (p[i].y > p[bottom].y) bottom = i;
    }
    double min_y = p[top].y, max_y = p[bottom].y;
    if (!(min_y < band.bottom) || !(max_y >= band.top)) return;
    int y0 = min_y < band.top ? band.top : ceil_int(min_y - 0.5);
    int y1 = max_y >= band.bottom ? band.bottom - 1 : floor_int(max_y - 0.5);
    Uint32 pixel = SDL_MapRGB(raster.canvas->format, color.r, color.g, color.b);
    /* The two chains from the top vertex down to the bottom one. */
    int forward = top, backward = top;
    for (int y = y0; y <= y1; y++) {
        double yc = y + 0.5;
        if (yc < min_y || yc >= max_y) continue;
        double xa = chain_x(p, n, +1, &forward, bottom, yc);
        double xb = chain_x(p, n, -1, &backward, bottom, yc);
        double left = xa < xb ? xa : xb, right = xa < xb ? xb : xa;
        if (left < -1.0) left = -1.0;
        if (right > raster.width + 1.0) right = raster.width + 1.0;
        int x0 = ceil_int(left - 0.5), x1 = floor_int(right - 0.5);
        if (x0 < 0) x0 = 0;
        if (x1 > raster.width - 1) x1 = raster.width - 1;
        if (x0 > x1) continue;
        SDL_memset4(row_of(y) + x0, pixel, (size_t)(x1 - x0 + 1));
    }
}

/* Liang-Barsky: clips the segment to [0, w-1] x [0, h-1]; false when it
 * misses. */
static bool clip(double *x0, double *y0, double *x1, double *y1, double w, double h) {
    double t0 = 0.0, t1 = 1.0, dx = *x1 - *x0, dy = *y1 - *y0;
    const double p[4] = {-dx, dx, -dy, dy};
    const double q[4] = {*x0, w - 1 - *x0, *y0, h - 1 - *y0};
    for (int i = 0; i < 4; i++) {
        if (p[i] == 0.0) {
            if (q[i] < 0.0) return false;
            continue;
        }
        double t = q[i] / p[i];
        if (p[i] < 0.0) {
            if (t > t1) return false;
            if (t > t0) t0 = t;
        } else {
            if (t < t0) return false;
            if (t < t1) t1 = t;
        }
    }
    double sx = *x0, sy = *y0;
    *x0 = sx + t0 * dx;
    *y0 = sy + t0 * dy;
    *x1 = sx + t1 * dx;
    *y1 = sy + t1 * dy;
    return true;
}

/* Bresenham between two clipped endpoints, the pixels in the band only:
 * the line is clipped to the canvas, never to the band, so that its pixels
 * are those of the whole line. */
static void canvas_line(double fx0, double fy0, double fx1, double fy1, Uint32 pixel,
                        band_t band) {
    double w = raster.width, h = raster.height;
    bool inside = fx0 >= 0 && fy0 >= 0 && fx1 >= 0 && fy1 >= 0 && fx0 <= w - 1 &&
                  fx1 <= w - 1 && fy0 <= h - 1 && fy1 <= h - 1;
    if (!inside && !clip(&fx0, &fy0, &fx1, &fy1, w, h)) return;
    /* Non-negative now: rounding by truncation. */
    int x0 = (int)(fx0 + 0.5), y0 = (int)(fy0 + 0.5), x1 = (int)(fx1 + 0.5),
        y1 = (int)(fy1 + 0.5);
    int low = y0 < y1 ? y0 : y1, high = y0 < y1 ? y1 : y0;
    if (high < band.top || low >= band.bottom) return;
    bool whole = low >= band.top && high < band.bottom;
    int dx = abs(x1 - x0), dy = -abs(y1 - y0);
    int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    int error = dx + dy;
    /* Both ends are on the canvas now, and so is every pixel between. */
    Uint32 *at = row_of(y0) + x0;
    int step_y = sy * (raster.canvas->pitch / 4);
    for (;;) {
        if (whole || (y0 >= band.top && y0 < band.bottom)) *at = pixel;
        if (x0 == x1 && y0 == y1) break;
        int e2 = 2 * error;
        if (e2 >= dy) {
            error += dy;
            x0 += sx;
            at += sx;
        }
        if (e2 <= dx) {
            error += dx;
            y0 += sy;
            at += step_y;
        }
    }
}

static void outline(const vector_t *p, int n, palette_rgb_t color, band_t band) {
    if (n < 2 || raster.width <= 0) return;
    if (raster.canvas != NULL) {
        Uint32 pixel = SDL_MapRGB(raster.canvas->format, color.r, color.g, color.b);
        for (int i = 0; i < n; i++) {
            vector_t a = p[i], b = p[i + 1 < n ? i + 1 : 0];
            canvas_line(a.x, a.y, b.x, b.y, pixel, band);
        }
        return;
    }
    SDL_Point points[65];
    if (n > 64) n = 64;
    for (int i = 0; i <= n; i++) {
        vector_t v = p[i < n ? i : 0];
        double x = fmin(30000.0, fmax(-30000.0, v.x)), y = fmin(30000.0, fmax(-30000.0, v.y));
        points[i] = (SDL_Point){(int)lround(x), (int)lround(y)};
    }
    SDL_SetRenderDrawBlendMode(raster.renderer, SDL_BLENDMODE_NONE);
    SDL_SetRenderDrawColor(raster.renderer, color.r, color.g, color.b, 255);
    SDL_RenderDrawLines(raster.renderer, points, n + 1);
}

/* A run's vertices back in double precision, for the scan converter. */
static int run_pixels(const batch_t *batch, const batch_run_t *run, vector_t *p) {
    for (int k = 0; k < run->count; k++) {
        const batch_vertex_t *v = &batch->vertices[run->first + k];
        p[k] = (vector_t){v->x, v->y};
    }
    return run->count;
}

/* Every triangle in one call, blended when any is translucent. */
static void geometry_fill(const batch_t *batch) {
    SDL_SetRenderDrawBlendMode(raster.renderer,
                               batch->translucent ? SDL_BLENDMODE_BLEND : SDL_BLENDMODE_NONE);
    const batch_vertex_t *v = batch->vertices;
    SDL_RenderGeometryRaw(raster.renderer, NULL, &v->x, sizeof(*v), (const SDL_Color *)&v->r,
                          sizeof(*v), NULL, 0, (int)batch->vertex_count, batch->indices,
                          (int)batch->index_count, sizeof(int));
    /* The outlines below may go straight into the canvas: after the fills. */
    SDL_RenderFlush(raster.renderer);
}

/* The batch's fills, then its outlines, in the band. */
static void draw_band(const batch_t *batch, band_t band) {
    vector_t p[BATCH_MAX_POLYGON];
    if (raster.canvas != NULL && !batch->translucent) {
        for (size_t i = 0; i < batch->run_count; i++) {
            const batch_run_t *run = &batch->runs[i];
            const batch_vertex_t *v = &batch->vertices[run->first];
            canvas_fill(p, run_pixels(batch, run, p), (palette_rgb_t){v->r, v->g, v->b}, band);
        }
    }
    for (size_t i = 0; i < batch->run_count; i++) {
        const batch_run_t *run = &batch->runs[i];
        if (run->outlined) outline(p, run_pixels(batch, run, p), run->outline, band);
    }
}

/* A second thread that draws the lower band of large batches while the
 * caller draws the upper one (the physics threads wait while a frame is
 * drawn); NULL until the first large batch, or when none can be made. */
static job_thread_t *helper;
static bool helper_failed;
static bool split_allowed = true;

void raster_set_split(bool split) {
    split_allowed = split;
}

typedef struct {
    const batch_t *batch;
    band_t band;
} band_job_t;

static void draw_band_job(void *context) {
    const band_job_t *job = context;
    draw_band(job->batch, job->band);
}

/* Smaller batches stay on the calling thread: handing half of a few
 * polygons over is not worth a thread's wake-up (a guess, not tuned). */
enum { RASTER_SPLIT_RUNS = 256 };

static bool helper_ready(void) {
    if (helper == NULL && !helper_failed) {
        helper = job_thread_start("raster");
        helper_failed = helper == NULL;
    }
    return helper != NULL;
}

void raster_free(void) {
    job_thread_stop(helper);
    helper = NULL;
    helper_failed = false;
}

/* The row above which about half of the batch's polygons start (to a
 * sixty-fourth of the height): a pile fills the bottom of the view, so
 * halving the rows would not halve the work. */
enum { BALANCE_BUCKETS = 64 };

static int balanced_row(const batch_t *batch) {
    size_t count[BALANCE_BUCKETS] = {0};
    double per_row = (double)BALANCE_BUCKETS / raster.height;
    for (size_t i = 0; i < batch->run_count; i++) {
        double y = batch->vertices[batch->runs[i].first].y * per_row;
        int bucket = !(y >= 0.0) ? 0 : y >= BALANCE_BUCKETS ? BALANCE_BUCKETS - 1 : (int)y;
        count[bucket]++;
    }
    size_t above = 0;
    int bucket = 0;
    while (bucket < BALANCE_BUCKETS - 1 && 2 * (above + count[bucket]) <= batch->run_count) {
        above += count[bucket++];
    }
    int row = (int)((bucket + 1) / per_row);
    return row < 1 ? 1 : row >= raster.height ? raster.height - 1 : row;
}

void raster_batch(const batch_t *batch) {
    if (batch->run_count == 0 || raster.width <= 0) return;
    band_t all = {0, raster.height};
    if (raster.canvas == NULL || batch->translucent) {
        geometry_fill(batch);
        if (raster.canvas == NULL) {
            draw_band(batch, all);
            return;
        }
    }
    if (!split_allowed || batch->run_count < RASTER_SPLIT_RUNS || raster.height < 2 ||
        !helper_ready()) {
        draw_band(batch, all);
        return;
    }
    int middle = balanced_row(batch);
    band_job_t lower = {batch, {middle, raster.height}};
    job_thread_begin(helper, draw_band_job, &lower);
    draw_band(batch, (band_t){0, middle});
    job_thread_finish(helper);
}
