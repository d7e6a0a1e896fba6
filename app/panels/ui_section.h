#ifndef SANDBOX_UI_SECTION_H
#define SANDBOX_UI_SECTION_H

/*
 * A panel of the side bar. ui.c stacks the panels of its SECTIONS table top
 * to bottom, each under its title; adding a panel is writing one of these
 * (a height, a draw function, optionally a press handler) and adding it to
 * that table.
 */

#include <SDL.h>
#include "core/app.h"

typedef struct {
    const char *title; /* drawn above the content; NULL for none */
    int height;        /* the content's height (pixels) */
    /* Draws the content into `content` (the side bar's width less padding). */
    void (*draw)(SDL_Renderer *renderer, app_t *app, body_t *hovered, SDL_Rect content);
    /* A left press at pixel, inside the panel; returns the drag it starts.
     * NULL: the panel ignores presses (they still drop nothing). */
    drag_t (*press)(app_t *app, SDL_Rect content, vector_t pixel);
} ui_section_t;

extern const ui_section_t UI_STATUS;     /* panel_status.c */
extern const ui_section_t UI_STATS;      /* panel_stats.c */
extern const ui_section_t UI_SHAPE;      /* panel_shape.c */
extern const ui_section_t UI_ELASTICITY; /* panel_elasticity.c */
extern const ui_section_t UI_OVERLAYS;   /* panel_overlays.c */
extern const ui_section_t UI_INTEGRATOR; /* panel_integrator.c */
extern const ui_section_t UI_SCENE;      /* panel_scene.c */

/* Where a panel's content is now; an empty rectangle when it is not shown. */
SDL_Rect ui_section_content(const app_t *app, const ui_section_t *section);

bool ui_rect_contains(SDL_Rect rect, vector_t pixel, int grow);

#endif
