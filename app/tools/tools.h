#ifndef SANDBOX_TOOLS_H
#define SANDBOX_TOOLS_H

/*
 * The tools: what a left click in the view does besides dropping a shape
 * (core/app.h's tool_t), each on the engine's queries (jostle/query.h):
 *   ray (J)      drag a ray: its first hit, the point, normal and fraction;
 *   box (U)      drag a box: the bodies whose shapes overlap it;
 *   explode (K)  click: an impulse on the bodies within the radius drawn
 *                round the cursor, falling off with distance;
 *   inspect (L)  click a body: the TOOLS page shows it, live;
 *   joint (W)    pins, ropes, rods and welds between bodies (joint_tool.h).
 * Each is chosen by its key (the same key again goes back to dropping) or a
 * click in the TOOLS page, and says so on the status line.
 */

#include <stdbool.h>
#include <stddef.h>
#include "core/app.h"
#include "jostle/query.h"

/* How long an explosion's ring shows (s). */
#define TOOLS_BLAST_SECONDS 0.4
/* The explosion's radius on screen, whatever the zoom, and the speed it
 * gives at its centre to a body of the mean mass of those it reaches, per
 * metre of radius (so a blast looks alike at any zoom). */
#define TOOLS_BLAST_RADIUS_PIXELS 120.0
#define TOOLS_BLAST_SPEED_PER_METRE 4.0
/* The most bodies the box tool lights up (it counts them all). */
#define TOOLS_BOX_MAX 4096

/* The tool's name, key and what it does in a few words, for the TOOLS page. */
const char *tools_name(tool_t tool);
const char *tools_key(tool_t tool);
const char *tools_what(tool_t tool);

/* Chooses a tool (the one in use again: back to dropping). */
void tools_choose(app_t *app, tool_t tool);

/* The explosion's radius (m) at the current zoom. */
double tools_explosion_radius(const app_t *app);

/* A left press at world point `at` with the tool in use (not TOOL_DROP);
 * returns the drag it starts (DRAG_PROBE for the ray and the box). */
drag_t tools_press(app_t *app, vector_t at);
/* The ray's or box's far end follows the cursor; on release it stays, and
 * the status line says what it found. */
void tools_probe_move(app_t *app, vector_t at);
void tools_probe_release(app_t *app, vector_t at);

/* What the ray drawn finds now: false when no ray is shown or it hits
 * nothing. */
bool tools_ray_hit(app_t *app, ray_hit_t *hit);
/* The bodies overlapping the box drawn now (the first `capacity` written),
 * and how many there are; 0 when no box is shown. */
size_t tools_box_bodies(app_t *app, body_t **bodies, size_t capacity);

/* The probe's result in words, up to TOOLS_PROBE_LINES lines of at most
 * `chars` characters (for the TOOLS page); returns the lines written. */
#define TOOLS_PROBE_LINES 4
int tools_probe_words(app_t *app, char lines[][64], size_t chars);

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
