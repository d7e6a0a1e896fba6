#include "panels/ui.h"
#include <SDL2_gfxPrimitives.h>
#include "draw/draw.h"
#include "panels/end_screen.h"
#include "panels/help.h"
#include "panels/ui_section.h"
#include <math.h>
#include "draw/layer.h"

/* The side bar, top to bottom: the status line and the tabs, then the
 * panels of the page shown (F2 to F5, or a click on its tab). A new panel
 * goes in a page's list. */
static const ui_section_t *const TOP[] = {&UI_STATUS, &UI_TABS};
static const ui_section_t *const PLAY[] = {&UI_STATS,     &UI_SHAPE,      &UI_ELASTICITY,
                                           &UI_OVERLAYS,  &UI_INTEGRATOR, &UI_SCENE};
static const ui_section_t *const SAMPLES[] = {&UI_SAMPLES};
static const ui_section_t *const SOLVER[] = {&UI_SOLVER, &UI_STEP};
static const ui_section_t *const TOOLS[] = {&UI_TOOLS, &UI_INSPECTOR, &UI_PLOT};

typedef struct {
    const ui_section_t *const *sections;
    size_t count;
} page_list_t;

#define LIST(a) {a, sizeof(a) / sizeof(a[0])}
static const page_list_t PAGES[UI_PAGE_COUNT] = {LIST(PLAY), LIST(SAMPLES), LIST(SOLVER),
                                                 LIST(TOOLS)};
#define TOP_COUNT (sizeof(TOP) / sizeof(TOP[0]))
#define MAX_SECTIONS 16

#define GAP 7     /* between panels, a rule at its middle */
#define TITLE_H (DRAW_LINE_H + 3)

/* The sections shown now, top to bottom. */
static size_t shown(const app_t *app, const ui_section_t *out[MAX_SECTIONS]) {
    size_t n = 0;
    for (size_t i = 0; i < TOP_COUNT; i++) out[n++] = TOP[i];
    const page_list_t *page = &PAGES[app->page < UI_PAGE_COUNT ? app->page : 0];
    for (size_t i = 0; i < page->count && n < MAX_SECTIONS; i++) out[n++] = page->sections[i];
    return n;
}

/* A panel's whole area (title and content) and its content, stacked. */
typedef struct {
    SDL_Rect whole, content;
} placed_t;

static placed_t place(const app_t *app, const ui_section_t *const *sections, size_t index) {
    layout_rect_t bar = app->layout.panels;
    int y = bar.y + LAYOUT_PAD;
    placed_t placed = {{0, 0, 0, 0}, {0, 0, 0, 0}};
    for (size_t i = 0; i <= index; i++) {
        const ui_section_t *s = sections[i];
        int title = s->title != NULL ? TITLE_H : 0;
        /* Height 0: the rest of the side bar. */
        int height = s->height > 0 ? s->height : bar.y + bar.h - LAYOUT_PAD - y - title;
        if (height < 0) height = 0;
        placed.whole = (SDL_Rect){bar.x, y - GAP / 2, bar.w, title + height + GAP};
        placed.content = (SDL_Rect){bar.x + LAYOUT_PAD, y + title, bar.w - 2 * LAYOUT_PAD,
                                    height};
        y += title + height + GAP;
    }
    return placed;
}

SDL_Rect ui_section_content(const app_t *app, const ui_section_t *section) {
    const ui_section_t *sections[MAX_SECTIONS];
    size_t n = shown(app, sections);
    for (size_t i = 0; i < n; i++) {
        if (sections[i] == section) return place(app, sections, i).content;
    }
    return (SDL_Rect){0, 0, 0, 0};
}

bool ui_rect_contains(SDL_Rect r, vector_t p, int grow) {
    return p.x >= r.x - grow && p.x < r.x + r.w + grow && p.y >= r.y - grow &&
           p.y < r.y + r.h + grow;
}

vector_t ui_to_panels(const app_t *app, vector_t pixel) {
    vector_t p;
    layout_to_panels(&app->layout, pixel.x, pixel.y, &p.x, &p.y);
    return p;
}

drag_t ui_press(app_t *app, vector_t window_pixel) {
    vector_t pixel = ui_to_panels(app, window_pixel);
    const ui_section_t *sections[MAX_SECTIONS];
    size_t n = shown(app, sections);
    for (size_t i = 0; i < n; i++) {
        placed_t placed = place(app, sections, i);
        if (sections[i]->press != NULL && ui_rect_contains(placed.whole, pixel, 0)) {
            return sections[i]->press(app, placed.content, pixel);
        }
    }
    return DRAG_NONE;
}

static void draw_sidebar(SDL_Renderer *renderer, app_t *app, body_t *hovered) {
    layout_rect_t bar = app->layout.panels;
    if (bar.w <= 0) return;
    draw_panel(renderer, bar.x, bar.y, bar.w, bar.h, PALETTE_PANEL, 255);
    vlineRGBA(renderer, draw_coord(bar.x), draw_coord(bar.y), draw_coord(bar.y + bar.h - 1),
              PALETTE_RULE.r, PALETTE_RULE.g, PALETTE_RULE.b, 255);
    const ui_section_t *sections[MAX_SECTIONS];
    size_t n = shown(app, sections);
    for (size_t i = 0; i < n; i++) {
        const ui_section_t *s = sections[i];
        placed_t placed = place(app, sections, i);
        if (i > 0) {
            hlineRGBA(renderer, draw_coord(bar.x + LAYOUT_PAD),
                      draw_coord(bar.x + bar.w - 1 - LAYOUT_PAD), draw_coord(placed.whole.y),
                      PALETTE_RULE.r, PALETTE_RULE.g, PALETTE_RULE.b, 255);
        }
        if (s->title != NULL) {
            draw_text(renderer, placed.content.x, placed.content.y - TITLE_H, PALETTE_TEXT_DIM,
                      "%s", s->title);
        }
        s->draw(renderer, app, hovered, placed.content);
    }
}

/* The side bar and the help, each at the UI's scale: straight into the
 * frame at scale 1, else drawn at scale 1 into a layer and enlarged. */
static layer_t sidebar_layer, help_layer;

static SDL_Rect rect_of(layout_rect_t r) {
    return (SDL_Rect){r.x, r.y, r.w, r.h};
}

void ui_draw(SDL_Renderer *renderer, SDL_Surface *canvas, app_t *app, body_t *hovered) {
    const layout_t *layout = &app->layout;
    SDL_Renderer *target = renderer;
    if (layout->scale != 1.0) target = layer_begin(&sidebar_layer, layout->panels.w, layout->panels.h);
    if (target != NULL) {
        draw_sidebar(target, app, hovered);
        if (target != renderer) layer_end(&sidebar_layer, renderer, canvas, rect_of(layout->sidebar));
    }
    end_screen_draw(renderer, app);
    if (!app->show_help) return;
    if (layout->scale == 1.0) {
        help_draw(renderer, app, layout->view);
        return;
    }
    layout_rect_t page = {0, 0, (int)lround(layout->view.w / layout->scale),
                          (int)lround(layout->view.h / layout->scale)};
    target = layer_begin(&help_layer, page.w, page.h);
    if (target == NULL) return;
    help_draw(target, app, page);
    layer_end(&help_layer, renderer, canvas, rect_of(layout->view));
}

void ui_free(void) {
    layer_free(&sidebar_layer);
    layer_free(&help_layer);
}
