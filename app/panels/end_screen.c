#include "panels/end_screen.h"
#include <SDL2_gfxPrimitives.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "draw/draw.h"

/* At the UI's scale 1; larger with it (layout.h). */
#define TITLE_SCALE 4
#define LINE_SCALE 2

static int text_width(const char *text, int scale) {
    return (int)strlen(text) * DRAW_CHAR_W * scale;
}

void end_screen_draw(SDL_Renderer *renderer, const app_t *app) {
    if (app->sandbox.game == NULL || app->game_status.outcome == GAME_PLAYING) return;
    bool won = app->game_status.outcome == GAME_WON;
    int title_scale = (int)lround(TITLE_SCALE * app->layout.scale);
    int line_scale = (int)lround(LINE_SCALE * app->layout.scale);
    const char *title = won ? "WON" : "GAME OVER";
    char score[32];
    snprintf(score, sizeof score, "score %d", app->game_status.score);
    const char *again = "R to play again";
    int line_h = 8 * line_scale, gap = line_h / 2;
    int w = text_width(title, title_scale);
    if (text_width(again, line_scale) > w) w = text_width(again, line_scale);
    w += 4 * LAYOUT_PAD;
    int h = 8 * title_scale + 2 * (gap + line_h) + 4 * LAYOUT_PAD;
    layout_rect_t view = app->layout.view;
    int x = view.x + (view.w - w) / 2, y = view.y + (view.h - h) / 2;
    palette_rgb_t accent = won ? PALETTE_WON : PALETTE_WARNING;
    draw_panel(renderer, x, y, w, h, PALETTE_PANEL, 230);
    rectangleRGBA(renderer, draw_coord(x), draw_coord(y), draw_coord(x + w - 1),
                  draw_coord(y + h - 1), accent.r, accent.g, accent.b, 255);
    int ty = y + 2 * LAYOUT_PAD;
    int centre = x + w / 2;
    draw_text_scaled(renderer, centre - text_width(title, title_scale) / 2, ty, title_scale,
                     accent, title);
    ty += 8 * title_scale + gap;
    draw_text_scaled(renderer, centre - text_width(score, line_scale) / 2, ty, line_scale,
                     PALETTE_TEXT, score);
    ty += line_h + gap;
    draw_text_scaled(renderer, centre - text_width(again, line_scale) / 2, ty, line_scale,
                     PALETTE_ACCENT, again);
}
