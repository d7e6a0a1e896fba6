/* The side bar's SCENE panel: the open scene's name and place in the list of
 * scenes (PageDown, PageUp), and its game's score, lives and what is left,
 * or WON / LOST; a scene without a game shows its timestep. */
#include <string.h>
#include "draw/draw.h"
#include "panels/scene_text.h"
#include "panels/ui_section.h"

static void draw_scene(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    const sandbox_t *sandbox = &app->sandbox;
    int y = r.y + 2;
    char position[SCENE_TEXT_SIZE];
    scene_text_position(app->scene_index, samples_count(&app->samples), position);
    int position_x = r.x + r.w - (int)strlen(position) * DRAW_CHAR_W;
    char name[SANDBOX_NAME_MAX];
    memcpy(name, sandbox->name, sizeof(name));
    int room = (position_x - r.x) / DRAW_CHAR_W - 1;
    if (room >= 0 && (int)strlen(name) > room) name[room] = '\0';
    draw_text(renderer, r.x, y, PALETTE_ACCENT, "%s", name);
    draw_text(renderer, position_x, y, PALETTE_TEXT_DIM, "%s", position);

    char line[SCENE_TEXT_SIZE];
    palette_rgb_t color = PALETTE_TEXT_DIM;
    if (sandbox->game != NULL) {
        game_status_t status = game_status(sandbox->game);
        scene_text_outcome_t outcome = status.outcome == GAME_WON    ? SCENE_TEXT_WON
                                       : status.outcome == GAME_LOST ? SCENE_TEXT_LOST
                                                                     : SCENE_TEXT_PLAYING;
        scene_text_game(scene_file_get_game(sandbox->file), outcome, status.score, status.lives,
                        status.remaining, line);
        color = outcome == SCENE_TEXT_WON    ? PALETTE_WON
                : outcome == SCENE_TEXT_LOST ? PALETTE_WARNING
                                             : PALETTE_TEXT;
    } else {
        scene_text_timestep(sandbox->step, line);
    }
    draw_text(renderer, r.x, y + DRAW_LINE_H, color, "%s", line);
}

const ui_section_t UI_SCENE = {"SCENE (PgDn, PgUp; Ctrl+S saves)", 2 * DRAW_LINE_H + 2,
                               draw_scene, NULL};
