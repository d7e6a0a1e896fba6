#ifndef SANDBOX_STATS_TEXT_H
#define SANDBOX_STATS_TEXT_H

/*
 * The lines of the side bar's SIMULATION panel, from plain numbers. Each
 * line fits the side bar (LAYOUT_LINE_CHARS) whatever the numbers: counts of
 * tens of thousands, energies of millions of joules. Plain C, tested by
 * tests/app_units.c.
 */

#include <stdbool.h>
#include <stddef.h>
#include "core/layout.h"

typedef struct {
    bool headless;       /* no clock: timings are not shown (they would differ each run) */
    /* From one window of frames (core/frame_meter.h): fps x frame_ms = 1000. */
    double fps, frame_ms, busy_ms, physics_ms, render_ms;
    int steps;           /* physics steps in the last frame */
    size_t bodies, collisions, near;
    size_t sleeping;     /* bodies asleep */
    bool sleeping_on;    /* whether the scene lets bodies sleep at all */
    double energy, kinetic; /* J */
    double momentum_x, momentum_y; /* N s */
    bool paused, gravity_on;
    double time_scale;
} stats_values_t;

#define STATS_LINES 9
#define STATS_LINE_SIZE (LAYOUT_LINE_CHARS + 1)

void stats_text(const stats_values_t *values, char lines[STATS_LINES][STATS_LINE_SIZE]);

#endif
