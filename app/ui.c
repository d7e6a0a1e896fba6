#include "ui.h"
#include <SDL2_gfxPrimitives.h>
#include <math.h>
#include <string.h>
#include "draw.h"
#include "input.h"

#define MARGIN 10
#define PAD 8
#define PANEL_W 300
#define SLIDER_H 14

/* The shape and elasticity panel, top right. */
static SDL_Rect panel_rect(const app_t *app) {
    return (SDL_Rect){app->camera.width - PANEL_W - MARGIN, MARGIN, PANEL_W, 136};
}

static SDL_Rect slider_rect(const app_t *app) {
    SDL_Rect panel = panel_rect(app);
    return (SDL_Rect){panel.x + PAD + 4, panel.y + 84, PANEL_W - 2 * PAD - 8, SLIDER_H};
}

static bool in_rect(SDL_Rect r, vector_t p, int grow) {
    return p.x >= r.x - grow && p.x < r.x + r.w + grow && p.y >= r.y - grow &&
           p.y < r.y + r.h + grow;
}

bool ui_slider_hit(const app_t *app, vector_t pixel) {
    return in_rect(slider_rect(app), pixel, 6);
}

double ui_slider_value_at(const app_t *app, vector_t pixel) {
    SDL_Rect r = slider_rect(app);
    double t = (pixel.x - r.x) / (double)r.w;
    return fmin(1.0, fmax(0.0, t)) * APP_ELASTICITY_MAX;
}

bool ui_captures(const app_t *app, vector_t pixel) {
    return in_rect(panel_rect(app), pixel, 0);
}

static void draw_shape_icon(SDL_Renderer *renderer, app_t *app, int cx, int cy, int radius) {
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

static void draw_shape_panel(SDL_Renderer *renderer, app_t *app, body_t *hovered) {
    SDL_Rect p = panel_rect(app);
    draw_panel(renderer, p.x, p.y, p.w, p.h, PALETTE_PANEL, 255);
    int x = p.x + PAD, y = p.y + PAD;
    draw_text(renderer, x, y, PALETTE_TEXT_DIM, "SHAPE  (3-8, B, P, Tab; wheel: size)");
    y += DRAW_LINE_H + 4;
    draw_text(renderer, x, y + 6, PALETTE_TEXT, "%s", sandbox_shape_name(app->shape));
    draw_text(renderer, x, y + 6 + DRAW_LINE_H, PALETTE_TEXT, "size %.2f m", app->shape.size);
    draw_shape_icon(renderer, app, p.x + p.w - PAD - 24, y + 12, 16);
    y += 2 * DRAW_LINE_H + 14;

    draw_text(renderer, x, y, PALETTE_TEXT_DIM, "ELASTICITY of new bodies  (Up/Down)");
    y += DRAW_LINE_H;
    draw_text(renderer, x, y, PALETTE_ACCENT, "%.2f", app->elasticity);

    SDL_Rect s = slider_rect(app);
    int mid = s.y + s.h / 2;
    boxRGBA(renderer, draw_coord(s.x), draw_coord(mid - 2), draw_coord(s.x + s.w),
            draw_coord(mid + 2), 70, 74, 86, 255);
    int knob = s.x + (int)lround(app->elasticity / APP_ELASTICITY_MAX * s.w);
    boxRGBA(renderer, draw_coord(s.x), draw_coord(mid - 2), draw_coord(knob), draw_coord(mid + 2),
            PALETTE_ACCENT.r, PALETTE_ACCENT.g, PALETTE_ACCENT.b, 255);
    for (int i = 0; i <= 4; i++) {
        int tx = s.x + i * s.w / 4;
        vlineRGBA(renderer, draw_coord(tx), draw_coord(mid + 4), draw_coord(mid + 7), 120, 126,
                  140, 255);
    }
    filledCircleRGBA(renderer, draw_coord(knob), draw_coord(mid), 6, PALETTE_ACCENT.r,
                     PALETTE_ACCENT.g, PALETTE_ACCENT.b, 255);
    circleRGBA(renderer, draw_coord(knob), draw_coord(mid), 6, 255, 255, 255, 255);
    y = s.y + s.h + 6;
    if (hovered != NULL) {
        draw_text(renderer, x, y, PALETTE_TEXT, "under cursor: e %.2f  m %.2f kg",
                  body_get_elasticity(hovered), body_get_mass(hovered));
    } else {
        draw_text(renderer, x, y, PALETTE_TEXT_DIM, "E: set the body under the cursor");
    }
}

static void draw_hud(SDL_Renderer *renderer, app_t *app) {
    const app_timing_t *t = &app->timing;
    scene_t *scene = app->sandbox.scene;
    sandbox_totals_t totals = sandbox_totals(&app->sandbox);
    int x = MARGIN + PAD, y = MARGIN + PAD;
    int lines = 6;
    draw_panel(renderer, MARGIN, MARGIN, 46 * DRAW_CHAR_W + 2 * PAD,
               lines * DRAW_LINE_H + 2 * PAD - 4, PALETTE_PANEL, 255);
    /* Until the first half second is counted, the frame time stands in. */
    double fps = t->fps > 0.0 ? t->fps : t->frame_ms > 0.0 ? 1000.0 / t->frame_ms : 0.0;
    draw_text(renderer, x, y, PALETTE_TEXT, "%5.1f FPS   frame %5.2f ms  render %5.2f ms", fps,
              t->frame_ms, t->render_ms);
    y += DRAW_LINE_H;
    draw_text(renderer, x, y, PALETTE_TEXT, "physics %6.3f ms/step  (%d steps/frame)",
              t->physics_ms, t->steps);
    y += DRAW_LINE_H;
    size_t collisions = app_collision_count(app);
    draw_text(renderer, x, y, PALETTE_TEXT, "bodies %zu   collisions this step %zu (%zu near)",
              totals.bodies, collisions, scene_contact_count(scene) - collisions);
    y += DRAW_LINE_H;
    draw_text(renderer, x, y, PALETTE_TEXT, "energy %.1f J  (kinetic %.1f)",
              totals.kinetic + totals.potential, totals.kinetic);
    y += DRAW_LINE_H;
    draw_text(renderer, x, y, PALETTE_TEXT, "momentum (%.2f, %.2f) N s", totals.momentum.x,
              totals.momentum.y);
    y += DRAW_LINE_H;
    palette_rgb_t state = app->paused ? PALETTE_ACCENT : PALETTE_TEXT;
    draw_text(renderer, x, y, state, "%s  time x%.1f  gravity %s", app->paused ? "PAUSED " : "running",
              app->time_scale, app->sandbox.gravity_on ? "on" : "off");
}

static palette_rgb_t overlay_color(overlay_t overlay) {
    switch (overlay) {
    case OVERLAY_AXES: return PALETTE_AXIS;
    case OVERLAY_IMPULSES: return PALETTE_IMPULSE;
    case OVERLAY_POINTS: return PALETTE_POINT;
    case OVERLAY_VELOCITIES: return PALETTE_VELOCITY;
    case OVERLAY_CENTROIDS: return PALETTE_CENTROID;
    case OVERLAY_BOUNDS: return PALETTE_BOUNDS;
    case OVERLAY_COUNT: break;
    }
    return PALETTE_TEXT;
}

/* Bottom left: each overlay with its key, lit when on. */
static void draw_legend(SDL_Renderer *renderer, app_t *app) {
    int h = 2 * DRAW_LINE_H + 2 * PAD - 4;
    int y = app->camera.height - MARGIN - h;
    int w = 0;
    for (int i = 0; i < OVERLAY_COUNT; i++) {
        w += (int)(strlen(app_overlay_key(i)) + strlen(app_overlay_name(i)) + 4) * DRAW_CHAR_W;
    }
    draw_panel(renderer, MARGIN, y, w + 2 * PAD, h, PALETTE_PANEL, 255);
    int x = MARGIN + PAD;
    y += PAD;
    for (int i = 0; i < OVERLAY_COUNT; i++) {
        bool on = app->overlays[i];
        palette_rgb_t c = on ? overlay_color(i) : (palette_rgb_t){90, 95, 108};
        if (on) {
            boxRGBA(renderer, draw_coord(x - 2), draw_coord(y - 2),
                    draw_coord(x + (int)strlen(app_overlay_key(i)) * DRAW_CHAR_W + 1),
                    draw_coord(y + 9), c.r, c.g, c.b, 255);
            draw_text(renderer, x, y, PALETTE_PANEL, "%s", app_overlay_key(i));
        } else {
            draw_text(renderer, x, y, c, "%s", app_overlay_key(i));
        }
        x += (int)(strlen(app_overlay_key(i)) + 1) * DRAW_CHAR_W;
        draw_text(renderer, x, y, c, "%s", app_overlay_name(i));
        x += (int)(strlen(app_overlay_name(i)) + 3) * DRAW_CHAR_W;
    }
    draw_text(renderer, MARGIN + PAD, y + DRAW_LINE_H, PALETTE_TEXT_DIM,
              "overlays (O: all)   H / F1: every key   Space: pause   R: reset   C: clear");
}

static void draw_status(SDL_Renderer *renderer, app_t *app) {
    if (app->status[0] == '\0' || app->now - app->status_time > 2.5) return;
    int w = (int)strlen(app->status) * DRAW_CHAR_W + 2 * PAD;
    /* Top centre, between the HUD and the shape panel, clear of the floor. */
    int x = (app->camera.width - w) / 2;
    int y = MARGIN;
    draw_panel(renderer, x, y, w, DRAW_LINE_H + PAD, PALETTE_PANEL, 220);
    draw_text(renderer, x + PAD, y + PAD / 2 + 1, PALETTE_ACCENT, "%s", app->status);
}

static void draw_help(SDL_Renderer *renderer, app_t *app) {
    int key_w = 30 * DRAW_CHAR_W;
    int action_w = 60 * DRAW_CHAR_W;
    int w = key_w + action_w + 2 * PAD + 16;
    int h = (int)(INPUT_CONTROL_COUNT + 3) * (DRAW_LINE_H + 2) + 2 * PAD;
    int x = (app->camera.width - w) / 2, y = (app->camera.height - h) / 2;
    if (x < 0) x = 0;
    if (y < 0) y = 0;
    draw_panel(renderer, x, y, w, h, PALETTE_PANEL, 235);
    rectangleRGBA(renderer, draw_coord(x), draw_coord(y), draw_coord(x + w - 1),
                  draw_coord(y + h - 1), PALETTE_ACCENT.r, PALETTE_ACCENT.g, PALETTE_ACCENT.b, 255);
    int ty = y + PAD;
    draw_text(renderer, x + PAD, ty, PALETTE_ACCENT, "SANDBOX CONTROLS   (H, F1 or Esc closes)");
    ty += 2 * (DRAW_LINE_H + 2);
    for (size_t i = 0; i < INPUT_CONTROL_COUNT; i++) {
        draw_text(renderer, x + PAD, ty, PALETTE_ACCENT, "%s", INPUT_CONTROLS[i].keys);
        draw_text(renderer, x + PAD + key_w + 16, ty, PALETTE_TEXT, "%s", INPUT_CONTROLS[i].action);
        ty += DRAW_LINE_H + 2;
    }
}

void ui_draw(SDL_Renderer *renderer, app_t *app, body_t *hovered) {
    draw_hud(renderer, app);
    draw_shape_panel(renderer, app, hovered);
    draw_legend(renderer, app);
    draw_status(renderer, app);
    if (app->show_help) draw_help(renderer, app);
}
