/* The side bar's OVERLAYS panel: each overlay with its key and its state
 * (and, for the axes and impulses, how many were drawn of how many),
 * "on" in the overlay's own colour or "off" in grey, so the two states never
 * look alike (the bounding boxes' grey-blue is close to the grey of "off").
 * A click on a line toggles that overlay, as its key does. */
#include <SDL2_gfxPrimitives.h>
#include <string.h>
#include <stdio.h>
#include "draw/draw.h"
#include "panels/text.h"
#include "panels/ui_section.h"

#define ROW_H DRAW_LINE_H

static palette_rgb_t overlay_color(overlay_t overlay) {
    switch (overlay) {
    case OVERLAY_AXES: return PALETTE_AXIS;
    case OVERLAY_IMPULSES: return PALETTE_IMPULSE;
    case OVERLAY_POINTS: return PALETTE_POINT;
    case OVERLAY_VELOCITIES: return PALETTE_VELOCITY;
    case OVERLAY_CENTROIDS: return PALETTE_CENTROID;
    case OVERLAY_BOUNDS: return PALETTE_BOUNDS;
    case OVERLAY_SLEEPING: return PALETTE_SLEEPING;
    case OVERLAY_COUNT: break;
    }
    return PALETTE_TEXT;
}

/* The key in a box: filled in the overlay's colour when on, hollow when off. */
static void draw_key(SDL_Renderer *renderer, int x, int y, overlay_t overlay, bool on) {
    palette_rgb_t c = on ? overlay_color(overlay) : PALETTE_OFF;
    Sint16 x0 = draw_coord(x - 2), y0 = draw_coord(y - 2), x1 = draw_coord(x + DRAW_CHAR_W + 1),
           y1 = draw_coord(y + 9);
    if (on) boxRGBA(renderer, x0, y0, x1, y1, c.r, c.g, c.b, 255);
    else rectangleRGBA(renderer, x0, y0, x1, y1, c.r, c.g, c.b, 255);
    draw_text(renderer, x, y, on ? PALETTE_PANEL : c, "%s", app_overlay_key(overlay));
}

/* " 32 of 9021" when the overlay drew some of its arrows only (near the
 * cursor and the strongest: draw/focus.h), else "". */
static const char *shown_of(const app_t *app, overlay_t overlay) {
    static char text[24];
    size_t shown = app->overlay_shown[overlay], total = app->overlay_total[overlay];
    if (shown >= total) return "";
    char a[8], b[8];
    text_number(a, sizeof a, (double)shown, 0, 5);
    text_number(b, sizeof b, (double)total, 0, 5);
    snprintf(text, sizeof text, " %s of %s", a, b);
    return text;
}

static void draw_overlays(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    for (int i = 0; i < OVERLAY_COUNT; i++) {
        bool on = app->overlays[i];
        int y = r.y + 2 + i * ROW_H;
        palette_rgb_t c = on ? overlay_color(i) : PALETTE_OFF;
        draw_key(renderer, r.x + 2, y, i, on);
        draw_text(renderer, r.x + 3 * DRAW_CHAR_W, y, c, "%s%s", app_overlay_name(i),
                  on ? shown_of(app, i) : "");
        const char *state = on ? "on" : "off";
        draw_text(renderer, r.x + r.w - (int)strlen(state) * DRAW_CHAR_W, y, c, "%s", state);
    }
}

static drag_t press_overlays(app_t *app, SDL_Rect r, vector_t pixel) {
    int row = (int)((pixel.y - r.y) / ROW_H);
    if (pixel.y >= r.y && row >= 0 && row < OVERLAY_COUNT) app_toggle_overlay(app, row);
    return DRAG_NONE;
}

const ui_section_t UI_OVERLAYS = {"OVERLAYS (key or click; O: all)", OVERLAY_COUNT * ROW_H + 2,
                                  draw_overlays, press_overlays};
