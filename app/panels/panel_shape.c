/* The side bar's SHAPE panel: the shape the next click drops, drawn in the
 * colour it will get, and its size. */
#include <SDL2_gfxPrimitives.h>
#include <math.h>
#include "draw/draw.h"
#include "panels/ui_section.h"

#define ICON_RADIUS 10

static void draw_icon(SDL_Renderer *renderer, app_t *app, int cx, int cy, int radius) {
    list_t *vertices = app->next_vertices;
    if (vertices == NULL) return;
    size_t n = list_size(vertices);
    if (n > 64) n = 64;
    double extent = 0.0;
    for (size_t i = 0; i < n; i++) {
        extent = fmax(extent, vec_get_length(*(vector_t *)list_get(vertices, i)));
    }
    if (extent <= 0.0) return;
    Sint16 xs[64], ys[64];
    for (size_t i = 0; i < n; i++) {
        vector_t v = *(vector_t *)list_get(vertices, i);
        xs[i] = draw_coord(cx + v.x / extent * radius);
        ys[i] = draw_coord(cy - v.y / extent * radius);
    }
    palette_rgb_t c = PALETTE_BODIES[app->sandbox.next_color % PALETTE_BODY_COUNT];
    filledPolygonRGBA(renderer, xs, ys, (int)n, c.r, c.g, c.b, 255);
    polygonRGBA(renderer, xs, ys, (int)n, 255, 255, 255, 255);
}

static void draw_shape(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    draw_text(renderer, r.x, r.y + 2, PALETTE_TEXT, "%s", sandbox_shape_name(app->shape));
    draw_text(renderer, r.x, r.y + 2 + DRAW_LINE_H, PALETTE_TEXT, "size %.2f m",
              app->shape.size);
    draw_icon(renderer, app, r.x + r.w - ICON_RADIUS - 4, r.y + r.h / 2, ICON_RADIUS);
}

const ui_section_t UI_SHAPE = {"SHAPE (3-8, B, P, Tab; wheel)", 2 * ICON_RADIUS + 4,
                               draw_shape, NULL};
