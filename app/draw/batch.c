#include "draw/batch.h"
#include <math.h>
#include <stdlib.h>

void batch_clear(batch_t *batch) {
    batch->vertex_count = 0;
    batch->index_count = 0;
    batch->run_count = 0;
    batch->translucent = false;
    batch->failed = false;
}

void batch_free(batch_t *batch) {
    free(batch->vertices);
    free(batch->indices);
    free(batch->runs);
    *batch = (batch_t){0};
}

/* Makes room for `more` items of `size` bytes after `count`, doubling from
 * `initial` (a few thousand bodies' worth) so that growing is rare. */
static bool grow(void **items, size_t *capacity, size_t count, size_t more, size_t size,
                 size_t initial) {
    if (count + more <= *capacity) return true;
    size_t wanted = *capacity ? *capacity : initial;
    while (wanted < count + more) wanted *= 2;
    void *grown = realloc(*items, wanted * size);
    if (grown == NULL) return false;
    *items = grown;
    *capacity = wanted;
    return true;
}

static bool reserve(batch_t *batch, size_t vertices, size_t indices) {
    bool ok = grow((void **)&batch->vertices, &batch->vertex_capacity, batch->vertex_count,
                   vertices, sizeof(batch_vertex_t), 4096) &&
              grow((void **)&batch->indices, &batch->index_capacity, batch->index_count, indices,
                   sizeof(int), 8192) &&
              grow((void **)&batch->runs, &batch->run_capacity, batch->run_count, 1,
                   sizeof(batch_run_t), 1024);
    if (!ok) batch->failed = true;
    return ok;
}

/* Far off the screen, pixels are clamped: the renderers work in float (SDL's
 * software renderer in fixed point), where huge values go wrong. */
static float clamp_pixel(double v) {
    if (!(v > -30000.0)) return -30000.0f;
    if (v > 30000.0) return 30000.0f;
    return (float)v;
}

static bool add_run(batch_t *batch, const vector_t *pixels, int n, palette_rgb_t color,
                    unsigned char alpha, bool outlined, palette_rgb_t outline) {
    if (n < 3 || n > BATCH_MAX_POLYGON || !reserve(batch, (size_t)n, 3 * (size_t)(n - 2))) {
        return false;
    }
    int first = (int)batch->vertex_count;
    for (int k = 0; k < n; k++) {
        batch->vertices[batch->vertex_count++] = (batch_vertex_t){
            clamp_pixel(pixels[k].x), clamp_pixel(pixels[k].y), color.r, color.g, color.b, alpha};
    }
    /* The fan (0, k, k + 1) of a convex polygon, as a plain triangle list. */
    for (int k = 1; k + 1 < n; k++) {
        batch->indices[batch->index_count++] = first;
        batch->indices[batch->index_count++] = first + k;
        batch->indices[batch->index_count++] = first + k + 1;
    }
    batch->runs[batch->run_count++] = (batch_run_t){first, n, outlined, outline};
    if (alpha < 255) batch->translucent = true;
    return true;
}

bool batch_polygon(batch_t *batch, const vector_t *pixels, int n, palette_rgb_t color,
                   unsigned char alpha) {
    return add_run(batch, pixels, n, color, alpha, false, color);
}

bool batch_outlined(batch_t *batch, const vector_t *pixels, int n, palette_rgb_t fill,
                    palette_rgb_t outline) {
    return add_run(batch, pixels, n, fill, 255, true, outline);
}

bool batch_arrow(batch_t *batch, vector_t tail, vector_t head, palette_rgb_t color,
                 unsigned char alpha, int width) {
    vector_t d = vec_subtract(head, tail);
    double length = vec_get_length(d);
    if (!(length >= 1.0) || !isfinite(length) || alpha == 0) return false;
    vector_t u = vec_multiply(1.0 / length, d);
    vector_t n = vec_perpendicular(u);
    double head_length = fmin(0.5 * length, 6.0 + 2.0 * width);
    double head_half = 0.55 * head_length;
    vector_t base = vec_subtract(head, vec_multiply(head_length, u));
    bool ok = true;
    if (length - head_length >= 1.0) {
        vector_t side = vec_multiply(0.5 * (width < 1 ? 1 : width), n);
        vector_t quad[4] = {vec_add(tail, side), vec_add(base, side), vec_subtract(base, side),
                            vec_subtract(tail, side)};
        ok = batch_polygon(batch, quad, 4, color, alpha);
    }
    vector_t triangle[3] = {head, vec_add(base, vec_multiply(head_half, n)),
                            vec_subtract(base, vec_multiply(head_half, n))};
    return batch_polygon(batch, triangle, 3, color, alpha) && ok;
}

bool batch_polygon_visible(const vector_t *pixels, int n, int width, int height) {
    if (n < 1) return false;
    double min_x = INFINITY, max_x = -INFINITY, min_y = INFINITY, max_y = -INFINITY;
    for (int k = 0; k < n; k++) {
        if (!vec_is_finite(pixels[k])) return false;
        /* Plain comparisons: fmin and fmax are library calls here. */
        if (pixels[k].x < min_x) min_x = pixels[k].x;
        if (pixels[k].x > max_x) max_x = pixels[k].x;
        if (pixels[k].y < min_y) min_y = pixels[k].y;
        if (pixels[k].y > max_y) max_y = pixels[k].y;
    }
    return max_x >= 0.0 && max_y >= 0.0 && min_x < width && min_y < height;
}
