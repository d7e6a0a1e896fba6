/* The side bar's tabs, under the status line: the pages PLAY, SAMPLES,
 * SOLVER and TOOLS with their keys (F2 to F5); the page shown is filled in
 * the accent colour. A click on a tab shows its page. */
#include <SDL2_gfxPrimitives.h>
#include <string.h>
#include "draw/draw.h"
#include "panels/ui_section.h"

static const char *const NAMES[UI_PAGE_COUNT] = {"PLAY", "SAMPLES", "SOLVER", "TOOLS"};

#define TAB_H (DRAW_LINE_H + 2)

/* Tab i's left and right edges: the content's width shared in proportion
 * to the names' lengths. */
static void tab_edges(SDL_Rect r, int i, int *left, int *right) {
    int total = 0, before = 0;
    for (int k = 0; k < UI_PAGE_COUNT; k++) {
        int w = (int)strlen(NAMES[k]) + 2;
        if (k < i) before += w;
        total += w;
    }
    *left = r.x + r.w * before / total;
    *right = r.x + r.w * (before + (int)strlen(NAMES[i]) + 2) / total - 2;
}

static void draw_tabs(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    for (int i = 0; i < UI_PAGE_COUNT; i++) {
        int left, right;
        tab_edges(r, i, &left, &right);
        bool on = app->page == (ui_page_t)i;
        palette_rgb_t c = on ? PALETTE_ACCENT : PALETTE_OFF;
        if (on) {
            boxRGBA(renderer, draw_coord(left), draw_coord(r.y), draw_coord(right),
                    draw_coord(r.y + TAB_H - 1), c.r, c.g, c.b, 255);
        } else {
            rectangleRGBA(renderer, draw_coord(left), draw_coord(r.y), draw_coord(right),
                          draw_coord(r.y + TAB_H - 1), c.r, c.g, c.b, 255);
        }
        int text_w = (int)strlen(NAMES[i]) * DRAW_CHAR_W;
        draw_text(renderer, (left + right + 1 - text_w) / 2, r.y + 3,
                  on ? PALETTE_PANEL : PALETTE_TEXT_DIM, "%s", NAMES[i]);
    }
}

static drag_t press_tabs(app_t *app, SDL_Rect r, vector_t pixel) {
    for (int i = 0; i < UI_PAGE_COUNT; i++) {
        int left, right;
        tab_edges(r, i, &left, &right);
        if (pixel.x >= left && pixel.x <= right + 1) app->page = (ui_page_t)i;
    }
    return DRAG_NONE;
}

const ui_section_t UI_TABS = {NULL, TAB_H, draw_tabs, press_tabs};
