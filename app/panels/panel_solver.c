/* The SOLVER page: the solver's settings, live (core/settings.h), each row
 * with its value and "<" ">" to change it (an on / off row turns over
 * where it is clicked), and a row that resets them; below, STEP: the
 * bodies and islands, a chart of the step's time by stage
 * (core/stage_chart.h) and the stages the scene leaves out (an orbits
 * scene, without contacts, runs no contact stage at all). */
#include <SDL2_gfxPrimitives.h>
#include <stdio.h>
#include <string.h>
#include "core/settings.h"
#include "draw/draw.h"
#include "panels/text.h"
#include "panels/ui_section.h"

#define ROW_H (DRAW_LINE_H + 2)
#define ARROWS_W (5 * DRAW_CHAR_W) /* "<   >" at the right end of a row */

static void draw_row(SDL_Renderer *renderer, const app_t *app, const setting_t *setting,
                     SDL_Rect r, int y) {
    draw_text(renderer, r.x, y, PALETTE_TEXT, "%s", setting->name);
    char value[40];
    setting->value(app, value, sizeof value);
    int right = r.x + r.w - (setting->on_off ? 0 : ARROWS_W);
    int x = right - (int)strlen(value) * DRAW_CHAR_W;
    draw_text(renderer, x, y, PALETTE_ACCENT, "%s", value);
    if (setting->on_off) return;
    draw_text(renderer, r.x + r.w - ARROWS_W + DRAW_CHAR_W, y, PALETTE_TEXT_DIM, "<");
    draw_text(renderer, r.x + r.w - DRAW_CHAR_W, y, PALETTE_TEXT_DIM, ">");
}

static void draw_solver(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    for (size_t i = 0; i < SETTING_COUNT; i++) {
        draw_row(renderer, app, &SETTINGS[i], r, r.y + 2 + (int)i * ROW_H);
    }
    int y = r.y + 2 + (int)SETTING_COUNT * ROW_H;
    palette_rgb_t c = PALETTE_OFF;
    rectangleRGBA(renderer, draw_coord(r.x), draw_coord(y - 2), draw_coord(r.x + r.w - 1),
                  draw_coord(y + DRAW_LINE_H - 1), c.r, c.g, c.b, 255);
    draw_text(renderer, r.x + 4, y, PALETTE_TEXT, "reset to the defaults");
}

static drag_t press_solver(app_t *app, SDL_Rect r, vector_t pixel) {
    int row = (int)((pixel.y - r.y - 2) / ROW_H);
    if (pixel.y < r.y || row < 0) return DRAG_NONE;
    if ((size_t)row == SETTING_COUNT) {
        settings_reset(app);
        return DRAG_NONE;
    }
    if ((size_t)row > SETTING_COUNT) return DRAG_NONE;
    const setting_t *setting = &SETTINGS[row];
    if (setting->on_off) {
        setting->change(app, 1);
    } else if (pixel.x >= r.x + r.w - ARROWS_W / 2) {
        setting->change(app, 1);
    } else if (pixel.x >= r.x + r.w - ARROWS_W) {
        setting->change(app, -1);
    }
    return DRAG_NONE;
}

const ui_section_t UI_SOLVER = {"SOLVER (click < > or a switch)",
                                (int)(SETTING_COUNT + 1) * ROW_H + 2, draw_solver, press_solver};

/* ---- STEP ---- */

#define CHART_H 48

_Static_assert(PALETTE_STAGE_COUNT == SCENE_STAGE_COUNT, "palette.h colours every stage");
/* The stages' names as the legend shows them (scene_stage_name's, cut to
 * fit a third of the side bar). */
static const char *const SHORT[SCENE_STAGE_COUNT] = {
    "forces", "broad",    "narrow",    "prepare", "solver",
    "shock",  "position", "integrate", "sleep",   "removal"};
#define COUNT_LINES 2
#define LEGEND_ROWS ((SCENE_STAGE_COUNT + 2) / 3)
#define LEFT_OUT_LINES 3

/* The chart: a column per frame (its last step), the stages stacked
 * bottom up in their colours, scaled by stage_chart_scale (a taller
 * column is cut at the top). */
static void draw_chart(SDL_Renderer *renderer, const stage_chart_t *chart, SDL_Rect r, int top) {
    int label_w = 8 * DRAW_CHAR_W;
    int width = r.w - label_w < STAGE_CHART_COLUMNS ? r.w - label_w : STAGE_CHART_COLUMNS;
    int left = r.x + r.w - width, bottom = top + CHART_H - 1;
    palette_rgb_t frame = PALETTE_RULE;
    rectangleRGBA(renderer, draw_coord(left - 1), draw_coord(top - 1), draw_coord(left + width),
                  draw_coord(bottom + 1), frame.r, frame.g, frame.b, 255);
    double peak = stage_chart_scale(chart);
    if (!(peak > 0.0)) {
        draw_text(renderer, left + 6, top + CHART_H / 2 - 4, PALETTE_OFF, "no step yet");
        return;
    }
    if (peak < 1e-4) draw_text(renderer, r.x, top, PALETTE_TEXT_DIM, "%.2g us", 1e6 * peak);
    else if (peak < 1e-3) draw_text(renderer, r.x, top, PALETTE_TEXT_DIM, "%.0f us", 1e6 * peak);
    else draw_text(renderer, r.x, top, PALETTE_TEXT_DIM, "%.1f ms", 1e3 * peak);
    draw_text(renderer, r.x, bottom - 7, PALETTE_TEXT_DIM, "0");
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    static SDL_Rect rects[SCENE_STAGE_COUNT][STAGE_CHART_COLUMNS];
    int counts[SCENE_STAGE_COUNT] = {0};
    for (int age = 0; age < width; age++) {
        const stage_column_t *c = stage_chart_column(chart, (size_t)age);
        if (!c->filled) continue;
        double below = 0.0;
        for (int s = 0; s < SCENE_STAGE_COUNT; s++) {
            if (!(c->seconds[s] > 0.0f)) continue;
            int y0 = bottom - (int)lround(fmin(below / peak, 1.0) * (CHART_H - 1));
            below += c->seconds[s];
            int y1 = bottom - (int)lround(fmin(below / peak, 1.0) * (CHART_H - 1));
            if (y1 == y0) continue; /* under half a pixel */
            rects[s][counts[s]++] = (SDL_Rect){left + width - 1 - age, y1 + 1, 1, y0 - y1};
        }
    }
    for (int s = 0; s < SCENE_STAGE_COUNT; s++) {
        palette_rgb_t c = PALETTE_STAGES[s];
        SDL_SetRenderDrawColor(renderer, c.r, c.g, c.b, 255);
        if (counts[s] > 0) SDL_RenderFillRects(renderer, rects[s], counts[s]);
    }
}

static void draw_step(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    const stage_chart_t *chart = &app->stages;
    const scene_profile_t *p = &chart->last;
    char line[COUNT_LINES][64];
    if (chart->has_last) {
        snprintf(line[0], sizeof line[0], "%zu awake, %zu asleep, %zu static", p->awake_bodies,
                 p->sleeping_bodies, p->static_bodies);
        snprintf(line[1], sizeof line[1], "%zu island%s, %zu contact%s", p->islands,
                 p->islands == 1 ? "" : "s", app_collision_count(app),
                 app_collision_count(app) == 1 ? "" : "s");
    } else {
        snprintf(line[0], sizeof line[0], "waiting for a step");
        line[1][0] = '\0';
    }
    for (int i = 0; i < COUNT_LINES; i++) {
        text_fit(line[i], LAYOUT_LINE_CHARS);
        draw_text(renderer, r.x, r.y + 2 + i * DRAW_LINE_H, PALETTE_TEXT, "%s", line[i]);
    }
    int top = r.y + 6 + COUNT_LINES * DRAW_LINE_H;
    draw_chart(renderer, chart, r, top);
    /* The legend: each stage in its colour, dim without its square when the
     * last step left it out. */
    int y = top + CHART_H + 5, col_w = r.w / 3;
    for (int s = 0; s < SCENE_STAGE_COUNT; s++) {
        int x = r.x + (s % 3) * col_w, row_y = y + (s / 3) * DRAW_LINE_H;
        bool ran = chart->has_last && p->ran[s];
        palette_rgb_t c = PALETTE_STAGES[s];
        if (ran) {
            boxRGBA(renderer, draw_coord(x), draw_coord(row_y), draw_coord(x + 6),
                    draw_coord(row_y + 6), c.r, c.g, c.b, 255);
        }
        draw_text(renderer, x + 9, row_y, ran ? PALETTE_TEXT : PALETTE_OFF, "%s", SHORT[s]);
    }
    y += LEGEND_ROWS * DRAW_LINE_H + 3;
    if (!chart->has_last) return;
    char text[200] = "left out:";
    size_t n = 0;
    for (int s = 0; s < SCENE_STAGE_COUNT; s++) {
        if (p->ran[s]) continue;
        size_t used = strlen(text);
        snprintf(text + used, sizeof text - used, "%s %s", n > 0 ? "," : "", SHORT[s]);
        n++;
    }
    if (n == 0) snprintf(text, sizeof text, "every stage ran");
    char lines[LEFT_OUT_LINES][LAYOUT_LINE_CHARS + 1];
    int count = text_wrap(text, LAYOUT_LINE_CHARS, &lines[0][0], sizeof lines[0], LEFT_OUT_LINES);
    for (int i = 0; i < count; i++) {
        draw_text(renderer, r.x, y + i * DRAW_LINE_H, PALETTE_TEXT_DIM, "%s", lines[i]);
    }
}

const ui_section_t UI_STEP = {"STEP (the last step by stage)",
                               COUNT_LINES * DRAW_LINE_H + 6 + CHART_H + 5 +
                                   LEGEND_ROWS * DRAW_LINE_H + 3 + LEFT_OUT_LINES * DRAW_LINE_H,
                               draw_step, NULL};
