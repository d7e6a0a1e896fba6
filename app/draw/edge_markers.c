#include "draw/edge_markers.h"
#include <math.h>
#include "draw/batch.h"
#include "draw/raster.h"

static palette_rgb_t rgb_of(rgb_color_t c) {
    return (palette_rgb_t){(unsigned char)lround(fmin(1.0, fmax(0.0, c.r)) * 255.0),
                           (unsigned char)lround(fmin(1.0, fmax(0.0, c.g)) * 255.0),
                           (unsigned char)lround(fmin(1.0, fmax(0.0, c.b)) * 255.0)};
}

static bool off_view(const camera_t *camera, body_t *body) {
    aabb_t box = body_get_bounds(body);
    vector_t low = camera_to_pixel(camera, box.min); /* bottom left: y is flipped */
    vector_t high = camera_to_pixel(camera, box.max);
    return high.x < 0 || low.x >= camera->width || low.y < 0 || high.y >= camera->height;
}

static batch_t markers;

void edge_markers_free(void) {
    batch_free(&markers);
}

/* A triangle at `at` pointing along unit vector `dir`. */
static void add_marker(vector_t at, vector_t dir, palette_rgb_t color) {
    vector_t side = vec_perpendicular(dir);
    vector_t tip = vec_add(at, vec_multiply(10.0, dir));
    vector_t back = vec_subtract(at, vec_multiply(6.0, dir));
    vector_t triangle[3] = {tip, vec_add(back, vec_multiply(8.0, side)),
                            vec_subtract(back, vec_multiply(8.0, side))};
    batch_outlined(&markers, triangle, 3, color, PALETTE_GRAB);
}

void edge_markers_draw(SDL_Renderer *renderer, SDL_Surface *canvas, app_t *app) {
    const camera_t *camera = &app->camera;
    scene_t *scene = app->sandbox.scene;
    const double inset = EDGE_MARKER_INSET;
    if (camera->width <= 2 * inset || camera->height <= 2 * inset) return;
    batch_clear(&markers);
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body) || sandbox_is_static(body) || !off_view(camera, body)) continue;
        /* The nearest point of the inset view to the body, facing it. */
        vector_t target = camera_to_pixel(camera, body_get_centroid(body));
        vector_t at = {fmin(camera->width - inset, fmax(inset, target.x)),
                       fmin(camera->height - inset, fmax(inset, target.y))};
        vector_t d = vec_subtract(target, at);
        double length = vec_get_length(d);
        if (!(length > 0.0) || !isfinite(length)) continue;
        add_marker(at, vec_multiply(1.0 / length, d), rgb_of(body_get_color(body)));
    }
    raster_begin(renderer, canvas);
    raster_batch(&markers);
}
