#include "panels/help.h"
#include <SDL2_gfxPrimitives.h>
#include "draw/draw.h"
#include "input/input.h"

#define KEY_CHARS 36
#define ACTION_CHARS 56

void help_draw(SDL_Renderer *renderer, app_t *app) {
    int window_w = app->layout.view.w + app->layout.sidebar.w;
    int window_h = app->layout.view.h;
    int rows = (int)INPUT_CONTROL_COUNT + 2; /* the title and a blank line */
    /* Rows as far apart as the window allows (at 800x600 they all fit). */
    int row_h = (window_h - 2 * LAYOUT_PAD) / rows;
    if (row_h > DRAW_LINE_H + 2) row_h = DRAW_LINE_H + 2;
    int w = (KEY_CHARS + ACTION_CHARS + 2) * DRAW_CHAR_W + 2 * LAYOUT_PAD;
    int h = rows * row_h + 2 * LAYOUT_PAD;
    int x = (window_w - w) / 2, y = (window_h - h) / 2;
    if (x < 0) x = 0;
    if (y < 0) y = 0;
    draw_panel(renderer, x, y, w, h, PALETTE_PANEL, 240);
    rectangleRGBA(renderer, draw_coord(x), draw_coord(y), draw_coord(x + w - 1),
                  draw_coord(y + h - 1), PALETTE_ACCENT.r, PALETTE_ACCENT.g, PALETTE_ACCENT.b, 255);
    int ty = y + LAYOUT_PAD;
    draw_text(renderer, x + LAYOUT_PAD, ty, PALETTE_ACCENT,
              "SANDBOX CONTROLS   (H, F1, Esc or a click closes)");
    if (app_game_mode(app)) {
        /* The line between the title and the table says whose keys win. */
        draw_text(renderer, x + LAYOUT_PAD, ty + row_h, PALETTE_WON,
                  "Now playing %.24s: the Game: keys come first (Ctrl + Left / Right pans)",
                  app->sandbox.name);
    }
    ty += 2 * row_h;
    int action_x = x + LAYOUT_PAD + (KEY_CHARS + 2) * DRAW_CHAR_W;
    for (size_t i = 0; i < INPUT_CONTROL_COUNT; i++) {
        draw_text(renderer, x + LAYOUT_PAD, ty, PALETTE_ACCENT, "%s", INPUT_CONTROLS[i].keys);
        draw_text(renderer, action_x, ty, PALETTE_TEXT, "%s", INPUT_CONTROLS[i].action);
        ty += row_h;
    }
}
