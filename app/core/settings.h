#ifndef SANDBOX_SETTINGS_H
#define SANDBOX_SETTINGS_H

/*
 * The solver's settings, live: each a row of the SOLVER page with its value
 * in words and a change to the previous or next value (or on / off), said
 * on the status line and kept in the scene file so that Ctrl+S saves it
 * (scene/sandbox_scene.h). A setting the engine gains is a row of the
 * table in settings.c. Reset: the engine's defaults
 * (scene_reset_solver_settings: 8 and 4 iterations, warm starting, 1 m/s,
 * 0.01 m/s with no bound on the turn, 0.5 s), sleeping on, the sandbox's
 * workers, fixed steps, and the scene file's own integrator and timestep.
 */

#include <stdbool.h>
#include <stddef.h>
#include "core/app.h"

typedef struct {
    const char *name; /* "velocity iterations" */
    /* The value in words ("8", "on", "1/120 s"), at most `size` - 1 bytes. */
    void (*value)(const app_t *app, char *out, size_t size);
    /* To the next value (+1) or the previous one (-1); an on / off row
     * turns over either way. */
    void (*change)(app_t *app, int direction);
    bool on_off; /* a click anywhere on the row turns it over */
} setting_t;

/* The rows, in the SOLVER page's order. */
#define SETTING_COUNT 12
extern const setting_t SETTINGS[SETTING_COUNT];

/* Every setting back to its default, said on the status line. */
void settings_reset(app_t *app);

#endif
