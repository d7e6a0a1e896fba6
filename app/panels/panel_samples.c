/* The SAMPLES page: every sample under its category (scene/samples.h), the
 * open one in the accent colour; a click opens one (PageDown and PageUp go
 * through them in this order). Below the list, the note of the sample
 * under the cursor, else of the open one: what to look at. */
#include <SDL2_gfxPrimitives.h>
#include <string.h>
#include "draw/draw.h"
#include "panels/text.h"
#include "panels/ui.h"
#include "panels/ui_section.h"
#include "scene/sample_categories.h"

#define ROW_H DRAW_LINE_H
#define NOTE_LINES 5

/* Row r of the list: a category's heading (sample -1) or a sample. */
typedef struct {
    int sample; /* -1: the heading of `category` */
    int category;
} row_t;

/* The rows in order; returns how many (at most max). */
static int rows_of(const samples_t *samples, row_t *rows, int max) {
    int n = 0, last = -2;
    for (size_t i = 0; i < samples->count && n < max; i++) {
        int category = samples->items[i].category;
        if (category != last && n < max) rows[n++] = (row_t){-1, category};
        last = category;
        if (n < max) rows[n++] = (row_t){(int)i, category};
    }
    return n;
}

/* The sample at a pixel of the list, or -1. */
static int sample_at(const app_t *app, SDL_Rect r, vector_t pixel) {
    row_t rows[SAMPLES_MAX + SAMPLE_CATEGORY_COUNT + 1];
    int n = rows_of(&app->samples, rows, (int)(sizeof rows / sizeof rows[0]));
    if (pixel.x < r.x || pixel.x >= r.x + r.w || pixel.y < r.y) return -1;
    int row = (int)((pixel.y - r.y) / ROW_H);
    return row < n ? rows[row].sample : -1;
}

static void draw_samples(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    row_t rows[SAMPLES_MAX + SAMPLE_CATEGORY_COUNT + 1];
    int n = rows_of(&app->samples, rows, (int)(sizeof rows / sizeof rows[0]));
    int room = (r.h - (NOTE_LINES + 1) * ROW_H) / ROW_H;
    if (n > room) n = room;
    for (int k = 0; k < n; k++) {
        int y = r.y + k * ROW_H;
        if (rows[k].sample < 0) {
            draw_text(renderer, r.x, y, PALETTE_TEXT_DIM, "%s",
                      samples_category_name(&app->samples, (size_t)rows[k + 1 < n ? k + 1 : k].sample));
            continue;
        }
        const sample_t *sample = &app->samples.items[rows[k].sample];
        bool open = rows[k].sample == app->scene_index;
        draw_text(renderer, r.x + 2 * DRAW_CHAR_W, y, open ? PALETTE_ACCENT : PALETTE_TEXT, "%s",
                  sample->name);
    }
    /* The note of the sample under the cursor, else of the open one. */
    int shown = app->mouse_inside ? sample_at(app, r, ui_to_panels(app, app->mouse)) : -1;
    if (shown < 0) shown = app->scene_index;
    int y = r.y + r.h - NOTE_LINES * ROW_H;
    hlineRGBA(renderer, draw_coord(r.x), draw_coord(r.x + r.w - 1), draw_coord(y - ROW_H / 2),
              PALETTE_RULE.r, PALETTE_RULE.g, PALETTE_RULE.b, 255);
    if (shown < 0 || (size_t)shown >= app->samples.count) {
        draw_text(renderer, r.x, y, PALETTE_TEXT_DIM, "a file from elsewhere");
        return;
    }
    const sample_t *sample = &app->samples.items[shown];
    char lines[NOTE_LINES][LAYOUT_LINE_CHARS + 1];
    char text[SCENE_FILE_NOTE_MAX + SAMPLE_NAME_MAX + 4];
    snprintf(text, sizeof text, "%s: %s", sample->name,
             sample->note[0] != '\0' ? sample->note : "(no note)");
    int count = text_wrap(text, LAYOUT_LINE_CHARS, &lines[0][0], sizeof lines[0], NOTE_LINES);
    for (int i = 0; i < count; i++) {
        draw_text(renderer, r.x, y + i * ROW_H, i == 0 ? PALETTE_ACCENT : PALETTE_TEXT, "%s",
                  lines[i]);
    }
}

static drag_t press_samples(app_t *app, SDL_Rect r, vector_t pixel) {
    int sample = sample_at(app, r, pixel);
    if (sample >= 0) app_open_sample(app, (size_t)sample);
    return DRAG_NONE;
}

const ui_section_t UI_SAMPLES = {"SAMPLES (click; PgDn, PgUp)", 0, draw_samples, press_samples};
