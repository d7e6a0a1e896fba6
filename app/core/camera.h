#ifndef SANDBOX_CAMERA_H
#define SANDBOX_CAMERA_H

/*
 * The view: world metres (y up) to pixels of the view area (y down), whose
 * top-left corner is the window's. `scale` is pixels per metre; `center` is
 * the world point at the middle of the view area.
 */

#include <stdbool.h>
#include "jostle/vector.h"

typedef struct {
    vector_t center;
    double scale;
    int width;  /* the view area (pixels), not the whole window */
    int height;
    vector_t home_min, home_max; /* the region the default view shows (m) */
    bool moved; /* panned or zoomed since the last reset */
} camera_t;

/* A view area of width x height pixels whose default view shows the world
 * box home_min .. home_max, whole, centred. */
void camera_init(camera_t *camera, int width, int height, vector_t home_min, vector_t home_max);

/* Back to the default view, keeping the size. */
void camera_reset(camera_t *camera);

/* Shows the box min .. max whole and centred (the zoom kept within its
 * limits); the view counts as moved. */
void camera_frame(camera_t *camera, vector_t min, vector_t max);

/* The view area changed size: the default view is fitted again; a view the
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
 * the scale stays within [CAMERA_MIN_SCALE, CAMERA_MAX_SCALE]. */
void camera_zoom_at(camera_t *camera, double factor, vector_t pixel);

/* The scale relative to the default view's (1: the default view's zoom). */
double camera_zoom(const camera_t *camera);

#define CAMERA_MIN_SCALE 4.0
#define CAMERA_MAX_SCALE 800.0

#endif
