/* The side bar's SHAPE panel: the shape the next click drops, drawn in the
 * colour it will get, and its size. */
#include <SDL2_gfxPrimitives.h>
#include <math.h>
#include "draw/draw.h"
#include "draw/round_outline.h"
#include "panels/ui_section.h"

#define ICON_RADIUS 10

/* The icon's outline in pixels about (cx, cy), its extent `radius` pixels:
 * a round shape's true boundary, a polygon's vertices. */
static int icon_pixels(const app_t *app, int cx, int cy, int radius, vector_t *pixels) {
    vector_t p1, p2;
    double r;
    if (sandbox_shape_core(app->shape, &p1, &p2, &r)) {
        double scale = radius / app->shape.size;
        return round_outline((vector_t){cx + p1.x * scale, cy - p1.y * scale},
                             (vector_t){cx + p2.x * scale, cy - p2.y * scale}, r * scale,
                             pixels);
    }
    list_t *vertices = app->next_vertices;
    if (vertices == NULL) return 0;
    size_t n = list_size(vertices);
    if (n > ROUND_OUTLINE_MAX) n = ROUND_OUTLINE_MAX;
    double extent = 0.0;
    for (size_t i = 0; i < n; i++) {
        extent = fmax(extent, vec_get_length(*(vector_t *)list_get(vertices, i)));
    }
    if (extent <= 0.0) return 0;
    for (size_t i = 0; i < n; i++) {
        vector_t v = *(vector_t *)list_get(vertices, i);
        pixels[i] = (vector_t){cx + v.x / extent * radius, cy - v.y / extent * radius};
    }
    return (int)n;
}

static void draw_icon(SDL_Renderer *renderer, app_t *app, int cx, int cy, int radius) {
    vector_t pixels[ROUND_OUTLINE_MAX];
    int n = icon_pixels(app, cx, cy, radius, pixels);
    if (n < 3) return;
    Sint16 xs[ROUND_OUTLINE_MAX], ys[ROUND_OUTLINE_MAX];
    for (int i = 0; i < n; i++) {
        xs[i] = draw_coord(pixels[i].x);
        ys[i] = draw_coord(pixels[i].y);
    }
    palette_rgb_t c = PALETTE_BODIES[app->sandbox.next_color % PALETTE_BODY_COUNT];
    filledPolygonRGBA(renderer, xs, ys, n, c.r, c.g, c.b, 255);
    polygonRGBA(renderer, xs, ys, n, 255, 255, 255, 255);
}

static void draw_shape(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect r) {
    (void)hovered;
    draw_text(renderer, r.x, r.y + 2, PALETTE_TEXT, "%s", sandbox_shape_name(app->shape));
    draw_text(renderer, r.x, r.y + 2 + DRAW_LINE_H, PALETTE_TEXT, "size %.2f m",
              app->shape.size);
    draw_icon(renderer, app, r.x + r.w - ICON_RADIUS - 4, r.y + r.h / 2, ICON_RADIUS);
}

const ui_section_t UI_SHAPE = {"SHAPE (1-8, B, P, Tab; wheel)", 2 * ICON_RADIUS + 4,
                               draw_shape, NULL};
