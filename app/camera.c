#include "camera.h"
#include <math.h>

/* The region the default view shows (metres): the floor's top is y = 0 and
 * the inner faces of the walls are at x = +-14 (sandbox_scene.c). */
static const double VIEW_MIN_X = -15.5, VIEW_MAX_X = 15.5;
static const double VIEW_MIN_Y = -1.5, VIEW_MAX_Y = 18.5;
static const double MIN_SCALE = 4.0, MAX_SCALE = 800.0;

void camera_init(camera_t *camera, int width, int height) {
    camera->width = width;
    camera->height = height;
    camera_reset(camera);
}

void camera_reset(camera_t *camera) {
    double sx = camera->width / (VIEW_MAX_X - VIEW_MIN_X);
    double sy = camera->height / (VIEW_MAX_Y - VIEW_MIN_Y);
    camera->scale = fmin(sx, sy);
    if (!(camera->scale > 0.0)) camera->scale = 1.0;
    camera->center = (vector_t){0.5 * (VIEW_MIN_X + VIEW_MAX_X), 0.5 * (VIEW_MIN_Y + VIEW_MAX_Y)};
    camera->moved = false;
}

void camera_resize(camera_t *camera, int width, int height) {
    camera->width = width;
    camera->height = height;
    if (!camera->moved) camera_reset(camera);
}

vector_t camera_to_pixel(const camera_t *camera, vector_t world) {
    return (vector_t){0.5 * camera->width + (world.x - camera->center.x) * camera->scale,
                      0.5 * camera->height - (world.y - camera->center.y) * camera->scale};
}

vector_t camera_to_world(const camera_t *camera, vector_t pixel) {
    return (vector_t){camera->center.x + (pixel.x - 0.5 * camera->width) / camera->scale,
                      camera->center.y - (pixel.y - 0.5 * camera->height) / camera->scale};
}

double camera_length_to_pixels(const camera_t *camera, double metres) {
    return metres * camera->scale;
}

double camera_length_to_world(const camera_t *camera, double pixels) {
    return pixels / camera->scale;
}

void camera_pan_pixels(camera_t *camera, double dx, double dy) {
    camera->center.x -= dx / camera->scale;
    camera->center.y += dy / camera->scale;
    camera->moved = true;
}

void camera_zoom_at(camera_t *camera, double factor, vector_t pixel) {
    vector_t anchor = camera_to_world(camera, pixel);
    camera->scale = fmin(MAX_SCALE, fmax(MIN_SCALE, camera->scale * factor));
    /* Put anchor back under pixel. */
    vector_t moved = camera_to_pixel(camera, anchor);
    camera_pan_pixels(camera, pixel.x - moved.x, pixel.y - moved.y);
    camera->moved = true;
}
