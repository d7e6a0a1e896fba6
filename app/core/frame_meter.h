#ifndef SANDBOX_FRAME_METER_H
#define SANDBOX_FRAME_METER_H

/*
 * The SIMULATION panel's timings, all from the same window of frames: every
 * FRAME_METER_WINDOW seconds of wall clock the frames of that window give
 * the frame rate, the wall time a frame (so FPS x ms a frame = 1000), the
 * busy time a frame (events, physics, drawing, presenting: all but waiting
 * for the display), the physics time a step and the drawing time a frame.
 * Until the first window is full, the frames so far. Plain C, no SDL.
 */

#include <stdbool.h>

#define FRAME_METER_WINDOW 0.5

typedef struct {
    double fps;
    double frame_ms;   /* wall clock a frame: 1000 / fps */
    double busy_ms;    /* a frame's work, waits left out */
    double physics_ms; /* a step (the last value while no step ran) */
    double render_ms;  /* drawing, a frame */
} frame_times_t;

typedef struct {
    frame_times_t shown; /* of the last whole window */
    bool full;           /* a whole window has been shown */
    /* The window being filled. */
    double wall_s, busy_s, physics_s, render_s;
    long frames, steps;
} frame_meter_t;

/* A frame: wall_s since the previous frame began, busy_s of work, steps
 * physics steps taking physics_s, render_s drawing. */
void frame_meter_add(frame_meter_t *meter, double wall_s, double busy_s, double physics_s,
                     int steps, double render_s);

#endif
