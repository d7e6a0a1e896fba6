#include "raster.h"
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

static struct {
    SDL_Renderer *renderer;
    SDL_Surface *canvas;
    int width, height;
} raster;

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

/* Scan-converts a convex polygon straight into the canvas. */
static void canvas_fill(const vector_t *p, int n, palette_rgb_t color) {
    if (n < 3 || raster.width <= 0) return;
    int top = 0, bottom = 0;
    for (int i = 1; i < n; i++) {
        if (p[i].y < p[top].y) top = i;
        if (p[i].y > p[bottom].y) bottom = i;
    }
    double min_y = p[top].y, max_y = p[bottom].y;
    if (!(min_y < raster.height) || !(max_y >= 0)) return;
    int y0 = min_y < 0 ? 0 : ceil_int(min_y - 0.5);
    int y1 = max_y >= raster.height ? raster.height - 1 : floor_int(max_y - 0.5);
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

/* Bresenham between two clipped endpoints. */
static void canvas_line(double fx0, double fy0, double fx1, double fy1, Uint32 pixel) {
    double w = raster.width, h = raster.height;
    bool inside = fx0 >= 0 && fy0 >= 0 && fx1 >= 0 && fy1 >= 0 && fx0 <= w - 1 &&
                  fx1 <= w - 1 && fy0 <= h - 1 && fy1 <= h - 1;
    if (!inside && !clip(&fx0, &fy0, &fx1, &fy1, w, h)) return;
    /* Non-negative now: rounding by truncation. */
    int x0 = (int)(fx0 + 0.5), y0 = (int)(fy0 + 0.5), x1 = (int)(fx1 + 0.5),
        y1 = (int)(fy1 + 0.5);
    int dx = abs(x1 - x0), dy = -abs(y1 - y0);
    int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    int error = dx + dy;
    /* Both ends are on the canvas now, and so is every pixel between. */
    Uint32 *at = row_of(y0) + x0;
    int step_y = sy * (raster.canvas->pitch / 4);
    for (;;) {
        *at = pixel;
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

static void outline(const vector_t *p, int n, palette_rgb_t color) {
    if (n < 2 || raster.width <= 0) return;
    if (raster.canvas != NULL) {
        Uint32 pixel = SDL_MapRGB(raster.canvas->format, color.r, color.g, color.b);
        for (int i = 0; i < n; i++) {
            vector_t a = p[i], b = p[i + 1 < n ? i + 1 : 0];
            canvas_line(a.x, a.y, b.x, b.y, pixel);
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

void raster_batch(const batch_t *batch) {
    if (batch->run_count == 0 || raster.width <= 0) return;
    vector_t p[BATCH_MAX_POLYGON];
    if (raster.canvas != NULL && !batch->translucent) {
        for (size_t i = 0; i < batch->run_count; i++) {
            const batch_run_t *run = &batch->runs[i];
            const batch_vertex_t *v = &batch->vertices[run->first];
            canvas_fill(p, run_pixels(batch, run, p), (palette_rgb_t){v->r, v->g, v->b});
        }
    } else {
        geometry_fill(batch);
    }
    for (size_t i = 0; i < batch->run_count; i++) {
        const batch_run_t *run = &batch->runs[i];
        if (run->outlined) outline(p, run_pixels(batch, run, p), run->outline);
    }
}
