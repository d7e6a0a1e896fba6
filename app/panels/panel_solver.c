/* The SOLVER page: the solver's settings, live (core/settings.h), each row
 * with its value and "<" ">" to change it (an on / off row turns over
 * where it is clicked), and a row that resets them; below, WORLD: what the
 * last step held (bodies, islands asleep, contacts, points, the
 * broadphase's pairs) and which of the step's stages this scene runs, from
 * its settings: a scene without contacts leaves out every contact stage. */
#include <SDL2_gfxPrimitives.h>
#include <stdio.h>
#include <string.h>
#include "core/settings.h"
#include "draw/draw.h"
#include "panels/text.h"
#include "panels/ui_section.h"
#include "jostle/scene_state.h"

#define ROW_H (DRAW_LINE_H + 2)
#define ARROWS_W (5 * DRAW_CHAR_W) /* "<   >" at the right end of a row */

static void draw_row(SDL_Renderer *renderer, const app_t *app, const setting_t *setting,
                     SDL_Rect r, int y) {
    draw_text(renderer, r.x, y, PALETTE_TEXT, "%s", setting->name);
    char value[40];
    setting->value(app, value, sizeof value);
    int right = r.x + r.w - (setting->on_off ? 0 : ARROWS_W);
    int x = right - (int)strlen(value) * DRAW_CHAR_W;
    draw_text(renderer, x, y, PALETTE_ACCENT, "%s", value);
    if (setting->on_off) return;
    draw_text(renderer, r.x + r.w - ARROWS_W + DRAW_CHAR_W, y, PALETTE_TEXT_DIM, "<");
    draw_text(renderer, r.x + r.w - DRAW_CHAR_W, y, PALETTE_TEXT_DIM, ">");
}

static void draw_solver(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    for (size_t i = 0; i < SETTING_COUNT; i++) {
        draw_row(renderer, app, &SETTINGS[i], r, r.y + 2 + (int)i * ROW_H);
    }
    int y = r.y + 2 + (int)SETTING_COUNT * ROW_H;
    palette_rgb_t c = PALETTE_OFF;
    rectangleRGBA(renderer, draw_coord(r.x), draw_coord(y - 2), draw_coord(r.x + r.w - 1),
                  draw_coord(y + DRAW_LINE_H - 1), c.r, c.g, c.b, 255);
    draw_text(renderer, r.x + 4, y, PALETTE_TEXT, "reset to the defaults");
}

static drag_t press_solver(app_t *app, SDL_Rect r, vector_t pixel) {
    int row = (int)((pixel.y - r.y - 2) / ROW_H);
    if (pixel.y < r.y || row < 0) return DRAG_NONE;
    if ((size_t)row == SETTING_COUNT) {
        settings_reset(app);
        return DRAG_NONE;
    }
    if ((size_t)row > SETTING_COUNT) return DRAG_NONE;
    const setting_t *setting = &SETTINGS[row];
    if (setting->on_off) {
        setting->change(app, 1);
    } else if (pixel.x >= r.x + r.w - ARROWS_W / 2) {
        setting->change(app, 1);
    } else if (pixel.x >= r.x + r.w - ARROWS_W) {
        setting->change(app, -1);
    }
    return DRAG_NONE;
}

const ui_section_t UI_SOLVER = {"SOLVER (click < > or a switch)",
                                (int)(SETTING_COUNT + 1) * ROW_H + 2, draw_solver, press_solver};

/* ---- WORLD ---- */

/* Sleeping islands: a sleeping body counts its island when it has the
 * lowest address on it. Each walk stops at the first lower address, so a
 * frame costs about n log n steps, not one whole walk per body. */
static size_t sleeping_islands(scene_t *scene, size_t *asleep) {
    size_t islands = 0;
    *asleep = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body) || body_get_island_next(body) == NULL) continue;
        (*asleep)++;
    }
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body) || body_get_island_next(body) == NULL) continue;
        bool lowest = true;
        for (body_t *b = body_get_island_next(body); b != body && lowest;
             b = body_get_island_next(b)) {
            lowest = (uintptr_t)b > (uintptr_t)body;
        }
        islands += lowest;
    }
    return islands;
}

/* The step's stages, and whether this scene runs each (from its settings:
 * the engine does not yet say what each took). */
static void stages(const app_t *app, bool run[9]) {
    scene_t *scene = app->sandbox.scene;
    vector_t g = scene_get_gravity(scene);
    bool contacts = scene_get_contacts_enabled(scene);
    run[0] = g.x != 0.0 || g.y != 0.0 || scene_file_force_count(app->sandbox.file) > 0 ||
             app->sandbox.grab.body != NULL;
    for (int i = 1; i <= 5; i++) run[i] = contacts;
    run[6] = true;
    run[7] = contacts && scene_get_sleeping(scene);
    run[8] = true;
}

static const char *const STAGES[9] = {"forces", "broad",     "narrow", "solver", "shock",
                                      "position", "integrate", "sleep",  "removal"};

#define WORLD_LINES 4
#define STAGE_ROWS 3

static void draw_world(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    scene_t *scene = app->sandbox.scene;
    const sandbox_totals_t *t = &app->totals;
    size_t asleep = 0, islands = sleeping_islands(scene, &asleep);
    size_t touching = app_collision_count(app);
    scene_stats_t stats = scene_get_stats(scene);
    char line[4][48];
    snprintf(line[0], sizeof line[0], "bodies %zu moving, %zu static", t->bodies, t->statics);
    snprintf(line[1], sizeof line[1], "asleep %zu in %zu island%s", asleep, islands,
             islands == 1 ? "" : "s");
    snprintf(line[2], sizeof line[2], "contacts %zu (%zu near)", touching,
             scene_contact_count(scene) - touching);
    snprintf(line[3], sizeof line[3], "points %zu  pairs %zu", stats.contact_points,
             stats.broadphase_pairs);
    for (int i = 0; i < WORLD_LINES; i++) {
        text_fit(line[i], LAYOUT_LINE_CHARS);
        draw_text(renderer, r.x, r.y + 2 + i * DRAW_LINE_H, PALETTE_TEXT, "%s", line[i]);
    }
    int y = r.y + 6 + WORLD_LINES * DRAW_LINE_H;
    draw_text(renderer, r.x, y, PALETTE_TEXT_DIM, "stages (dim: left out here)");
    bool run[9];
    stages(app, run);
    for (int i = 0; i < 9; i++) {
        int col = i % 3, row = i / 3;
        draw_text(renderer, r.x + col * 11 * DRAW_CHAR_W, y + (row + 1) * DRAW_LINE_H,
                  run[i] ? PALETTE_ACCENT : PALETTE_OFF, "%s", STAGES[i]);
    }
}

const ui_section_t UI_WORLD = {"WORLD (the last step)",
                               WORLD_LINES * DRAW_LINE_H + 6 + (STAGE_ROWS + 1) * DRAW_LINE_H,
                               draw_world, NULL};
