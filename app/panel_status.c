/* The side bar's first panel: the status line that confirms each change (or
 * says why something was refused) for APP_STATUS_SECONDS, else a hint. */
#include <SDL2_gfxPrimitives.h>
#include "draw.h"
#include "text.h"
#include "ui_section.h"

#define STATUS_LINES 2

static void draw_status(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    if (!app_status_showing(app)) {
        draw_text(renderer, r.x, r.y + 2, PALETTE_TEXT_DIM, "H or F1: every key");
        draw_text(renderer, r.x, r.y + 2 + DRAW_LINE_H, PALETTE_TEXT_DIM,
                  "F: frame all  0: whole box");
        return;
    }
    palette_rgb_t color = app->status_warning ? PALETTE_WARNING : PALETTE_ACCENT;
    /* A frame in the message's colour, so that a change catches the eye. */
    rectangleRGBA(renderer, draw_coord(r.x - 4), draw_coord(r.y - 2), draw_coord(r.x + r.w + 3),
                  draw_coord(r.y + r.h + 1), color.r, color.g, color.b, 255);
    char lines[STATUS_LINES][LAYOUT_LINE_CHARS + 1];
    int count = text_wrap(app->status, LAYOUT_LINE_CHARS, &lines[0][0], sizeof(lines[0]),
                          STATUS_LINES);
    for (int i = 0; i < count; i++) {
        draw_text(renderer, r.x, r.y + 2 + i * DRAW_LINE_H, color, "%s", lines[i]);
    }
}

const ui_section_t UI_STATUS = {NULL, STATUS_LINES * DRAW_LINE_H + 2, draw_status, NULL};
