/* The side bar's INTEGRATOR panel: the scene's integrator (N and Shift+N
 * switch it), what it does with springs, and a strip chart of the relative
 * energy drift over the last 5 s of simulated time (energy_drift.h), on a
 * symmetric scale that follows the largest drift shown. */
#include <SDL2_gfxPrimitives.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "draw/draw.h"
#include "scene/integrator_choice.h"
#include "panels/ui_section.h"

/* The chart: value labels left of it, a frame around DRIFT_COLUMNS columns of
 * one pixel, PLOT_H rows with the zero line in the middle. */
#define LABEL_W (6 * DRAW_CHAR_W) /* "+0.05%", "+1000%" */
#define PLOT_GAP 4
#define PLOT_H 61
#define PLOT_TOP (3 * DRAW_LINE_H + 8) /* below the name, the stability and the readout */
#define AXIS_H 12                      /* the time labels below the chart */
#define CONTENT_H (PLOT_TOP + PLOT_H + 2 + AXIS_H)

static void draw_text_right(SDL_Renderer *renderer, int right, int y, palette_rgb_t color,
                            const char *text) {
    draw_text(renderer, right - (int)strlen(text) * DRAW_CHAR_W, y, color, "%s", text);
}

static int row_of(double value, double scale, int mid) {
    double half = (PLOT_H - 1) / 2.0;
    double row = mid - value / scale * half;
    return (int)lround(fmin(mid + half, fmax(mid - half, row)));
}

static void draw_chart(SDL_Renderer *renderer, const energy_drift_t *drift, int x0, int top) {
    int mid = top + (PLOT_H - 1) / 2, bottom = top + PLOT_H - 1, right = x0 + DRIFT_COLUMNS - 1;
    palette_rgb_t frame = PALETTE_RULE, zero = PALETTE_CHART_ZERO;
    rectangleRGBA(renderer, draw_coord(x0 - 1), draw_coord(top - 1), draw_coord(right + 1),
                  draw_coord(bottom + 1), frame.r, frame.g, frame.b, 255);
    hlineRGBA(renderer, draw_coord(x0), draw_coord(right), draw_coord(mid), zero.r, zero.g,
              zero.b, 255);
    /* A tick each second along the bottom, "now" at the right. */
    int per_second = (int)lround(DRIFT_COLUMNS / DRIFT_SECONDS);
    for (int s = 1; s < (int)DRIFT_SECONDS; s++) {
        int x = right - s * per_second;
        vlineRGBA(renderer, draw_coord(x), draw_coord(bottom - 3), draw_coord(bottom), zero.r,
                  zero.g, zero.b, 255);
    }
    double scale = energy_drift_scale(drift);
    SDL_Rect bars[DRIFT_COLUMNS];
    int count = 0;
    palette_rgb_t mark = PALETTE_CHART_MARK;
    for (int age = 0; age < DRIFT_COLUMNS; age++) {
        const drift_column_t *column = energy_drift_column(drift, (size_t)age);
        int x = right - age;
        if (column->rereferenced) {
            vlineRGBA(renderer, draw_coord(x), draw_coord(top), draw_coord(bottom), mark.r,
                      mark.g, mark.b, 255);
        }
        if (!column->filled) continue;
        int high = row_of(column->high, scale, mid), low = row_of(column->low, scale, mid);
        bars[count++] = (SDL_Rect){x, high, 1, low - high + 1};
    }
    palette_rgb_t c = PALETTE_DRIFT;
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    SDL_SetRenderDrawColor(renderer, c.r, c.g, c.b, 255);
    if (count > 0) SDL_RenderFillRects(renderer, bars, count);

    /* The scale, symmetric, at the top and bottom rows; 0 at the middle. */
    char label[16];
    int label_right = x0 - PLOT_GAP;
    energy_drift_format_scale(scale, '+', label, sizeof(label));
    draw_text_right(renderer, label_right, top, PALETTE_TEXT_DIM, label);
    draw_text_right(renderer, label_right, mid - 3, PALETTE_TEXT_DIM, "0");
    energy_drift_format_scale(scale, '-', label, sizeof(label));
    draw_text_right(renderer, label_right, bottom - 7, PALETTE_TEXT_DIM, label);
    int axis_y = bottom + 4;
    draw_text(renderer, x0, axis_y, PALETTE_TEXT_DIM, "-5 s");
    draw_text(renderer, x0 + DRIFT_COLUMNS / 2 - 4 * DRAW_CHAR_W / 2, axis_y, PALETTE_TEXT_DIM,
              "time");
    draw_text_right(renderer, right + 1, axis_y, PALETTE_TEXT_DIM, "now");
}

static void draw_integrator(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    integrator_t integrator = app->sandbox.integrator;
    int y = r.y + 2;
    draw_text(renderer, r.x, y, PALETTE_ACCENT, "%s", integrator_get_name(integrator));
    char position[32];
    snprintf(position, sizeof(position), "%d of %d", (int)integrator + 1, INTEGRATOR_COUNT);
    draw_text_right(renderer, r.x + r.w, y, PALETTE_TEXT_DIM, position);

    char stability[32];
    integrator_choice_stability(integrator, stability, sizeof(stability));
    bool unstable = integrator_choice_unstable(integrator);
    draw_text(renderer, r.x, y + DRAW_LINE_H, unstable ? PALETTE_WARNING : PALETTE_TEXT, "%s",
              stability);

    /* The drift now, beside what it is. */
    const energy_drift_t *drift = &app->drift;
    int readout_y = y + 2 * DRAW_LINE_H + 3;
    draw_text(renderer, r.x, readout_y, PALETTE_TEXT, "energy drift");
    char now[16];
    if (drift->valid) {
        energy_drift_format(drift->drift, now, sizeof(now));
    } else {
        snprintf(now, sizeof(now), "%s", app->totals.bodies == 0 ? "no bodies" : "no energy");
    }
    draw_text_right(renderer, r.x + r.w, readout_y, drift->valid ? PALETTE_DRIFT : PALETTE_OFF,
                    now);

    draw_chart(renderer, drift, r.x + LABEL_W + PLOT_GAP, r.y + PLOT_TOP);
}

const ui_section_t UI_INTEGRATOR = {"INTEGRATOR (N, Shift+N)", CONTENT_H, draw_integrator, NULL};
