/* The side bar's SIMULATION panel: frame rate and timings, bodies,
 * collisions, energy, momentum, and the run state (stats_text.c makes the
 * lines). */
#include "draw/draw.h"
#include "panels/stats_text.h"
#include "panels/ui_section.h"

static stats_values_t values_of(app_t *app) {
    const app_timing_t *t = &app->timing;
    const frame_times_t *shown = &t->meter.shown; /* one window of frames */
    const sandbox_totals_t totals = app->totals; /* measured once a frame */
    size_t collisions = app_collision_count(app);
    return (stats_values_t){
        .headless = app->headless,
        .fps = shown->fps,
        .frame_ms = shown->frame_ms,
        .busy_ms = shown->busy_ms,
        .physics_ms = shown->physics_ms,
        .render_ms = shown->render_ms,
        .steps = t->steps,
        .bodies = totals.bodies,
        .sleeping = totals.sleeping,
        .sleeping_on = app->sandbox.sleeping_on,
        .collisions = collisions,
        .near = scene_contact_count(app->sandbox.scene) - collisions,
        .energy = totals.kinetic + totals.potential,
        .kinetic = totals.kinetic,
        .momentum_x = totals.momentum.x,
        .momentum_y = totals.momentum.y,
        .paused = app->paused,
        .gravity_on = app->sandbox.gravity_on,
        .time_scale = app->time_scale,
    };
}

static void draw_stats(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    stats_values_t values = values_of(app);
    char lines[STATS_LINES][STATS_LINE_SIZE];
    stats_text(&values, lines);
    for (int i = 0; i < STATS_LINES; i++) {
        palette_rgb_t color = i == STATS_LINES - 1 && app->paused ? PALETTE_ACCENT : PALETTE_TEXT;
        draw_text(renderer, r.x, r.y + i * DRAW_LINE_H, color, "%s", lines[i]);
    }
}

const ui_section_t UI_STATS = {"SIMULATION", STATS_LINES * DRAW_LINE_H, draw_stats, NULL};
