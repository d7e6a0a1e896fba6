/* The side bar's first panel: the status line that confirms each change (or
 * says why something was refused: a drop, a scene file with its line and
 * column) for APP_STATUS_SECONDS, else a hint; in a game, its keys. */
#include <SDL2_gfxPrimitives.h>
#include <string.h>
#include "draw/draw.h"
#include "panels/text.h"
#include "panels/ui_section.h"

#define STATUS_LINES 3

static void draw_status(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    if (!app_status_showing(app)) {
        static const char *const SANDBOX_HINT[STATUS_LINES] = {
            "H or F1: every key", "F: frame all  0: whole box", NULL};
        static const char *const FILE_HINT[STATUS_LINES] = {
            "H or F1: every key", "F: frame all  0: the file's view", NULL};
        /* A game's keys come first while it runs: say which. */
        static const char *const GAME_HINT[STATUS_LINES] = {
            "GAME KEYS: Left/Right, A/D move", "Space fires, Enter pauses", "H or F1: every key"};
        static const char *const CAR_HINT[STATUS_LINES] = {
            "GAME KEYS: Left/Right, A/D drive", "the wheels; Enter pauses", "H or F1: every key"};
        bool car =
            app_game_mode(app) && strcmp(scene_file_get_game(app->sandbox.file), "car") == 0;
        const char *const *hint = app_game_mode(app)       ? (car ? CAR_HINT : GAME_HINT)
                                  : app->sandbox.is_default ? SANDBOX_HINT
                                                            : FILE_HINT;
        for (int i = 0; i < STATUS_LINES && hint[i] != NULL; i++) {
            draw_text(renderer, r.x, r.y + 2 + i * DRAW_LINE_H,
                      i == 0 && app_game_mode(app) ? PALETTE_ACCENT : PALETTE_TEXT_DIM, "%s",
                      hint[i]);
        }
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
