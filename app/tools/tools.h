#ifndef SANDBOX_TOOLS_H
#define SANDBOX_TOOLS_H

/*
 * The tools: what a left click in the view does besides dropping a shape
 * (core/app.h's tool_t): an explosion at the cursor (K) and the body
 * inspector (L). Each is chosen by its key (the same key again goes back to
 * dropping) or a click in the TOOLS page, and says so on the status line.
 */

#include <stdbool.h>
#include "core/app.h"

/* How long an explosion's ring shows (s). */
#define TOOLS_BLAST_SECONDS 0.4

/* The tool's name and key, for the TOOLS page and the help. */
const char *tools_name(tool_t tool);
const char *tools_key(tool_t tool);

/* Chooses a tool (the one in use again: back to dropping). */
void tools_choose(app_t *app, tool_t tool);

/* The explosion's radius (m) at the current zoom. */
double tools_explosion_radius(const app_t *app);

/* A left click at world point `at` with the tool in use (not TOOL_DROP). */
void tools_click(app_t *app, vector_t at);

/* After a frame's steps (after app_frame_done): the plot takes its value
 * for the `simulated` seconds the frame ran, the explosion's ring ages by
 * `display` seconds. */
void tools_frame(app_t *app, double display, double simulated);

/* The quantity the TOOLS page plots, next in turn; the plot starts anew. */
void tools_next_plot(app_t *app);

/* The plotted quantity's value now; false when it has none (no body
 * inspected for a body's quantity). */
bool tools_plot_value(app_t *app, double *value);

#endif
