/* The TOOLS page: the tools (tools/tools.h), the one in use lit, a click
 * choosing one; the INSPECTOR of the body chosen with the inspect tool,
 * live; and a PLOT of one quantity against the last 5 s of simulated time
 * (a click on it plots the next quantity). */
#include <SDL2_gfxPrimitives.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "draw/draw.h"
#include "panels/text.h"
#include "panels/ui_section.h"
#include "tools/tools.h"
#include "jostle/scene_state.h"

#define ROW_H (DRAW_LINE_H + 1)

#define PROBE_LINES TOOLS_PROBE_LINES

static void draw_tools(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    for (int i = 0; i < TOOL_COUNT; i++) {
        int y = r.y + 2 + i * ROW_H;
        bool on = app->tool == (tool_t)i;
        palette_rgb_t c = on ? PALETTE_ACCENT : PALETTE_TEXT_DIM;
        draw_text(renderer, r.x, y, c, "%s %-8s", on ? ">" : " ", tools_name((tool_t)i));
        draw_text(renderer, r.x + 11 * DRAW_CHAR_W, y, on ? PALETTE_TEXT : PALETTE_OFF, "%s",
                  tools_what((tool_t)i));
        const char *key = tools_key((tool_t)i);
        draw_text(renderer, r.x + r.w - (int)strlen(key) * DRAW_CHAR_W, y, c, "%s", key);
    }
    /* What the ray or the box finds now. */
    char lines[PROBE_LINES][64];
    int n = tools_probe_words(app, lines, LAYOUT_LINE_CHARS);
    int y = r.y + 4 + TOOL_COUNT * ROW_H;
    for (int i = 0; i < n; i++) {
        draw_text(renderer, r.x, y + i * DRAW_LINE_H, i == 0 ? PALETTE_ACCENT : PALETTE_TEXT, "%s",
                  lines[i]);
    }
}

static drag_t press_tools(app_t *app, SDL_Rect r, vector_t pixel) {
    int row = (int)((pixel.y - r.y - 2) / ROW_H);
    if (pixel.y >= r.y && row >= 0 && row < TOOL_COUNT && (tool_t)row != app->tool) {
        tools_choose(app, (tool_t)row);
    }
    return DRAG_NONE;
}

const ui_section_t UI_TOOLS = {"TOOLS (click, or the key)",
                               TOOL_COUNT * ROW_H + 4 + PROBE_LINES * DRAW_LINE_H, draw_tools,
                               press_tools};

/* ---- INSPECTOR ---- */

#define INSPECTOR_LINES 8

static void inspector_lines(app_t *app, body_t *body, char lines[][LAYOUT_LINE_CHARS + 1]) {
    char words[SCENE_FILE_NAME_MAX + 8];
    sandbox_body_words(&app->sandbox, body, words, sizeof words);
    char a[16], b[16], c[16];
    double mass = body_get_mass(body);
    vector_t v = body_get_velocity(body), p = body_get_centroid(body);
    char text[INSPECTOR_LINES][96];
    snprintf(text[0], sizeof text[0], "%s", words);
    if (isinf(mass)) {
        snprintf(text[1], sizeof text[1], "static (infinite mass)");
    } else {
        text_number(a, sizeof a, mass, 3, 8);
        text_number(b, sizeof b, body_get_inertia(body), 3, 8);
        snprintf(text[1], sizeof text[1], "m %s kg  I %s kg m2", a, b);
    }
    text_number(a, sizeof a, p.x, 2, 7);
    text_number(b, sizeof b, p.y, 2, 7);
    text_number(c, sizeof c, body_get_rotation(body), 2, 6);
    snprintf(text[2], sizeof text[2], "at (%s, %s) m  %s rad", a, b, c);
    text_number(a, sizeof a, v.x, 2, 7);
    text_number(b, sizeof b, v.y, 2, 7);
    snprintf(text[3], sizeof text[3], "v (%s, %s) m/s", a, b);
    text_number(a, sizeof a, body_get_angular_velocity(body), 2, 7);
    text_number(b, sizeof b, body_get_kinetic_energy(body), 2, 8);
    snprintf(text[4], sizeof text[4], "w %s rad/s  KE %s J", a, b);
    scene_t *scene = app->sandbox.scene;
    size_t island = scene_body_island(scene, body);
    if (island == SIZE_MAX) {
        snprintf(text[5], sizeof text[5], "contacts %zu, no island",
                 scene_body_contact_count(scene, body));
    } else {
        snprintf(text[5], sizeof text[5], "contacts %zu, island %zu",
                 scene_body_contact_count(scene, body), island);
    }
    text_number(a, sizeof a, body_get_sleep_timer(body).slow_time, 2, 6);
    if (body_is_sleeping(body)) snprintf(text[6], sizeof text[6], "asleep");
    else snprintf(text[6], sizeof text[6], "awake, slow for %s s", a);
    text_number(a, sizeof a, body_get_elasticity(body), 2, 5);
    text_number(b, sizeof b, body_get_friction(body), 2, 5);
    snprintf(text[7], sizeof text[7], "elasticity %s  friction %s", a, b);
    for (int i = 0; i < INSPECTOR_LINES; i++) {
        text_fit(text[i], LAYOUT_LINE_CHARS);
        memcpy(lines[i], text[i], strlen(text[i]) + 1);
    }
}

static void draw_inspector(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    body_t *body = app->sandbox.inspected;
    if (body == NULL) {
        draw_text(renderer, r.x, r.y + 2, PALETTE_TEXT_DIM, "L, then click a body");
        return;
    }
    char lines[INSPECTOR_LINES][LAYOUT_LINE_CHARS + 1];
    inspector_lines(app, body, lines);
    for (int i = 0; i < INSPECTOR_LINES; i++) {
        draw_text(renderer, r.x, r.y + 2 + i * DRAW_LINE_H, i == 0 ? PALETTE_ACCENT : PALETTE_TEXT,
                  "%s", lines[i]);
    }
}

const ui_section_t UI_INSPECTOR = {"INSPECTOR (live)", INSPECTOR_LINES * DRAW_LINE_H + 2,
                                   draw_inspector, NULL};

/* ---- PLOT ---- */

#define PLOT_H 61

static void draw_plot(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    const plot_t *plot = &app->plot;
    draw_text(renderer, r.x, r.y + 2, PALETTE_TEXT, "%s", plot_quantity_name(plot->quantity));
    char now[16] = "-";
    if (plot->has_latest) text_number(now, sizeof now, plot->latest, 3, 9);
    draw_text(renderer, r.x + r.w - (int)strlen(now) * DRAW_CHAR_W, r.y + 2, PALETTE_DRIFT, "%s",
              now);
    int top = r.y + DRAW_LINE_H + 6, left = r.x + r.w - PLOT_COLUMNS;
    int bottom = top + PLOT_H - 1, right = left + PLOT_COLUMNS - 1;
    palette_rgb_t frame = PALETTE_RULE;
    rectangleRGBA(renderer, draw_coord(left - 1), draw_coord(top - 1), draw_coord(right + 1),
                  draw_coord(bottom + 1), frame.r, frame.g, frame.b, 255);
    double low, high;
    if (!plot_range(plot, &low, &high)) {
        draw_text(renderer, left + 8, top + PLOT_H / 2 - 4, PALETTE_OFF, "%s",
                  plot_needs_body(plot->quantity) && app->sandbox.inspected == NULL
                      ? "no body inspected"
                      : "nothing yet");
        return;
    }
    SDL_Rect bars[PLOT_COLUMNS];
    int count = 0;
    for (int age = 0; age < PLOT_COLUMNS; age++) {
        const plot_column_t *c = plot_column(plot, (size_t)age);
        if (!c->filled) continue;
        int y_high = bottom - (int)lround((c->high - low) / (high - low) * (PLOT_H - 1));
        int y_low = bottom - (int)lround((c->low - low) / (high - low) * (PLOT_H - 1));
        bars[count++] = (SDL_Rect){right - age, y_high, 1, y_low - y_high + 1};
    }
    palette_rgb_t c = PALETTE_DRIFT;
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    SDL_SetRenderDrawColor(renderer, c.r, c.g, c.b, 255);
    if (count > 0) SDL_RenderFillRects(renderer, bars, count);
    char label[16];
    text_number(label, sizeof label, high, 2, 6);
    draw_text(renderer, r.x, top, PALETTE_TEXT_DIM, "%s", label);
    text_number(label, sizeof label, low, 2, 6);
    draw_text(renderer, r.x, bottom - 7, PALETTE_TEXT_DIM, "%s", label);
    draw_text(renderer, left, bottom + 4, PALETTE_TEXT_DIM, "-5 s");
    draw_text(renderer, right + 1 - 3 * DRAW_CHAR_W, bottom + 4, PALETTE_TEXT_DIM, "now");
}

static drag_t press_plot(app_t *app, SDL_Rect r, vector_t pixel) {
    (void)r;
    (void)pixel;
    tools_next_plot(app);
    return DRAG_NONE;
}

const ui_section_t UI_PLOT = {"PLOT (click: next quantity)", DRAW_LINE_H + 6 + PLOT_H + 14,
                              draw_plot, press_plot};
