#include "core/camera.h"
#include <math.h>

void camera_init(camera_t *camera, int width, int height, vector_t home_min, vector_t home_max) {
    camera->width = width;
    camera->height = height;
    camera->home_min = home_min;
    camera->home_max = home_max;
    camera_reset(camera);
}

/* The scale at which the box min .. max just fits. */
static double fitting_scale(const camera_t *camera, vector_t min, vector_t max) {
    double sx = camera->width / fmax(max.x - min.x, 1e-3);
    double sy = camera->height / fmax(max.y - min.y, 1e-3);
    return fmin(CAMERA_MAX_SCALE, fmax(CAMERA_MIN_SCALE, fmin(sx, sy)));
}

static void fit(camera_t *camera, vector_t min, vector_t max) {
    camera->scale = fitting_scale(camera, min, max);
    camera->center = (vector_t){0.5 * (min.x + max.x), 0.5 * (min.y + max.y)};
}

double camera_zoom(const camera_t *camera) {
    return camera->scale / fitting_scale(camera, camera->home_min, camera->home_max);
}

void camera_reset(camera_t *camera) {
    fit(camera, camera->home_min, camera->home_max);
    camera->moved = false;
}

void camera_frame(camera_t *camera, vector_t min, vector_t max) {
    fit(camera, min, max);
    camera->moved = true;
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
    camera->scale = fmin(CAMERA_MAX_SCALE, fmax(CAMERA_MIN_SCALE, camera->scale * factor));
    /* Put anchor back under pixel. */
    vector_t moved = camera_to_pixel(camera, anchor);
    camera_pan_pixels(camera, pixel.x - moved.x, pixel.y - moved.y);
    camera->moved = true;
}
