/* The side bar's ELASTICITY panel: the elasticity of new bodies as a number
 * and a slider (click or drag it; the wheel over it steps it), and the
 * elasticity and mass of the body under the cursor. */
#include <SDL2_gfxPrimitives.h>
#include <math.h>
#include "draw/draw.h"
#include "panels/ui.h"
#include "panels/ui_section.h"

#define SLIDER_H 14
#define VALUE_W (5 * DRAW_CHAR_W) /* "0.50" and a space, left of the slider */
#define KNOB 6

static SDL_Rect slider_rect(const app_t *app) {
    SDL_Rect r = ui_section_content(app, &UI_ELASTICITY);
    return (SDL_Rect){r.x + VALUE_W + KNOB, r.y, r.w - VALUE_W - 2 * KNOB, SLIDER_H};
}

static bool slider_hit(const app_t *app, vector_t pixel) {
    return ui_rect_contains(slider_rect(app), pixel, KNOB);
}

bool ui_slider_hit(const app_t *app, vector_t pixel) {
    return slider_hit(app, ui_to_panels(app, pixel));
}

static double slider_value_at(const app_t *app, vector_t pixel) {
    SDL_Rect r = slider_rect(app);
    double t = (pixel.x - r.x) / (double)r.w;
    return fmin(1.0, fmax(0.0, t)) * APP_ELASTICITY_MAX;
}

double ui_slider_value_at(const app_t *app, vector_t pixel) {
    return slider_value_at(app, ui_to_panels(app, pixel));
}

static void draw_slider(SDL_Renderer *renderer, const app_t *app) {
    SDL_Rect s = slider_rect(app);
    int mid = s.y + s.h / 2;
    palette_rgb_t a = PALETTE_ACCENT;
    boxRGBA(renderer, draw_coord(s.x), draw_coord(mid - 2), draw_coord(s.x + s.w),
            draw_coord(mid + 2), 70, 74, 86, 255);
    int knob = s.x + (int)lround(app->elasticity / APP_ELASTICITY_MAX * s.w);
    boxRGBA(renderer, draw_coord(s.x), draw_coord(mid - 2), draw_coord(knob), draw_coord(mid + 2),
            a.r, a.g, a.b, 255);
    for (int i = 0; i <= 4; i++) {
        int tx = s.x + i * s.w / 4;
        vlineRGBA(renderer, draw_coord(tx), draw_coord(mid + 4), draw_coord(mid + 7), 120, 126,
                  140, 255);
    }
    filledCircleRGBA(renderer, draw_coord(knob), draw_coord(mid), KNOB, a.r, a.g, a.b, 255);
    circleRGBA(renderer, draw_coord(knob), draw_coord(mid), KNOB, 255, 255, 255, 255);
}

static void draw_elasticity(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    draw_text(renderer, r.x, r.y + 3, PALETTE_ACCENT, "%.2f", app->elasticity);
    draw_slider(renderer, app);
    int y = r.y + SLIDER_H + 6;
    if (hovered != NULL) {
        draw_text(renderer, r.x, y, PALETTE_TEXT, "under cursor: e %.2f  m %.2f kg",
                  body_get_elasticity(hovered), body_get_mass(hovered));
    } else {
        draw_text(renderer, r.x, y, PALETTE_TEXT_DIM, "E: to hovered body, Shift+E: all");
    }
}

static drag_t press_elasticity(app_t *app, SDL_Rect content, vector_t pixel) {
    (void)content;
    if (!slider_hit(app, pixel)) return DRAG_NONE;
    app_set_elasticity(app, slider_value_at(app, pixel));
    app_status(app, "elasticity of new bodies %.2f", app->elasticity);
    return DRAG_SLIDER;
}

const ui_section_t UI_ELASTICITY = {"ELASTICITY (Up/Down, slider)",
                                    SLIDER_H + 6 + DRAW_LINE_H, draw_elasticity,
                                    press_elasticity};
