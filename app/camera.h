#ifndef SANDBOX_CAMERA_H
#define SANDBOX_CAMERA_H

/*
 * The view: world metres (y up) to window pixels (y down). `scale` is pixels
 * per metre; `center` is the world point at the middle of the window.
 */

#include <stdbool.h>
#include "vector.h"

typedef struct {
    vector_t center;
    double scale;
    int width;
    int height;
    bool moved; /* panned or zoomed since the last reset */
} camera_t;

/* The default view for a window of width x height pixels: the floor, the
 * walls and the space above them fill the window. */
void camera_init(camera_t *camera, int width, int height);

/* Back to the default view, keeping the window size. */
void camera_reset(camera_t *camera);

/* The window changed size: the default view is fitted again; a view the
 * user moved keeps its centre and scale (the window shows more or less). */
void camera_resize(camera_t *camera, int width, int height);

vector_t camera_to_pixel(const camera_t *camera, vector_t world);
vector_t camera_to_world(const camera_t *camera, vector_t pixel);

/* A length in metres as pixels, and back. */
double camera_length_to_pixels(const camera_t *camera, double metres);
double camera_length_to_world(const camera_t *camera, double pixels);

/* Moves the view so that the world follows the mouse by (dx, dy) pixels. */
void camera_pan_pixels(camera_t *camera, double dx, double dy);

/* Zooms by factor (> 1 zooms in) keeping the world point under pixel fixed;
 * the scale stays within [4, 800] pixels per metre. */
void camera_zoom_at(camera_t *camera, double factor, vector_t pixel);

#endif
