#include "panels/help.h"
#include <SDL2_gfxPrimitives.h>
#include <string.h>
#include "draw/draw.h"
#include "input/input.h"
#include "panels/text.h"

/* Lines a key or an action may wrap to. */
#define MAX_WRAP 3
#define KEY_CHARS_MAX 36
#define KEY_CHARS_MIN 14
#define LINE_MIN 9 /* rows no closer than this (pixels): the font is 8 high */

typedef struct {
    int x, y, w, h;     /* the page: the whole view */
    int key_chars;      /* the key column's width (characters) */
    int action_chars;   /* the action column's */
    int line_h;         /* pixels from one line to the next */
} page_t;

/* The lines an entry takes: its key or its action, whichever wraps to more. */
static int entry_lines(const input_control_t *control, const page_t *page) {
    char lines[MAX_WRAP][128];
    int keys = text_wrap(control->keys, (size_t)page->key_chars, &lines[0][0], sizeof lines[0],
                         MAX_WRAP);
    int actions = text_wrap(control->action, (size_t)page->action_chars, &lines[0][0],
                            sizeof lines[0], MAX_WRAP);
    return keys > actions ? keys : actions;
}

/* The columns from the view's width, the line height from its height: as
 * close as 12 pixels, closer when every entry must fit. */
static page_t page_of(layout_rect_t view) {
    page_t page = {view.x, view.y, view.w, view.h, 0, 0, DRAW_LINE_H};
    int chars = (view.w - 4 * LAYOUT_PAD) / DRAW_CHAR_W;
    page.key_chars = chars * 36 / 100;
    if (page.key_chars > KEY_CHARS_MAX) page.key_chars = KEY_CHARS_MAX;
    if (page.key_chars < KEY_CHARS_MIN) page.key_chars = KEY_CHARS_MIN;
    page.action_chars = chars - page.key_chars - 2;
    int lines = 3; /* the title, the game's line, a blank */
    for (size_t i = 0; i < INPUT_CONTROL_COUNT; i++) lines += entry_lines(&INPUT_CONTROLS[i], &page);
    int fit = (view.h - 4 * LAYOUT_PAD) / lines;
    if (fit < page.line_h) page.line_h = fit < LINE_MIN ? LINE_MIN : fit;
    return page;
}

/* Text wrapped into a column; returns the lines drawn. */
static int draw_wrapped(SDL_Renderer *renderer, int x, int y, int chars, int line_h,
                        palette_rgb_t color, const char *text) {
    char lines[MAX_WRAP][128];
    int count = text_wrap(text, (size_t)chars, &lines[0][0], sizeof lines[0], MAX_WRAP);
    for (int i = 0; i < count; i++) draw_text(renderer, x, y + i * line_h, color, "%s", lines[i]);
    return count;
}

void help_draw(SDL_Renderer *renderer, app_t *app, layout_rect_t view) {
    page_t page = page_of(view);
    /* The page closes the view while it shows; the side bar stays as it is. */
    draw_panel(renderer, page.x, page.y, page.w, page.h, PALETTE_PANEL, 255);
    rectangleRGBA(renderer, draw_coord(page.x), draw_coord(page.y), draw_coord(page.x + page.w - 1),
                  draw_coord(page.y + page.h - 1), PALETTE_ACCENT.r, PALETTE_ACCENT.g,
                  PALETTE_ACCENT.b, 255);
    int left = page.x + 2 * LAYOUT_PAD, y = page.y + 2 * LAYOUT_PAD;
    draw_text(renderer, left, y, PALETTE_ACCENT, "SANDBOX CONTROLS (H, F1, Esc or a click closes)");
    y += page.line_h;
    if (app_game_mode(app)) {
        /* The line between the title and the table says whose keys win. */
        char line[160];
        snprintf(line, sizeof line,
                 "Now playing %.24s: the Game: keys come first (Ctrl + Left / Right pans)",
                 app->sandbox.name);
        y += page.line_h * draw_wrapped(renderer, left, y, page.key_chars + 2 + page.action_chars,
                                        page.line_h, PALETTE_WON, line);
    }
    y += page.line_h;
    int action_x = left + (page.key_chars + 2) * DRAW_CHAR_W;
    for (size_t i = 0; i < INPUT_CONTROL_COUNT; i++) {
        const input_control_t *control = &INPUT_CONTROLS[i];
        int keys = draw_wrapped(renderer, left, y, page.key_chars, page.line_h, PALETTE_ACCENT,
                                control->keys);
        int actions = draw_wrapped(renderer, action_x, y, page.action_chars, page.line_h,
                                   PALETTE_TEXT, control->action);
        y += page.line_h * (keys > actions ? keys : actions);
    }
}
