#ifndef SANDBOX_UI_SECTION_H
#define SANDBOX_UI_SECTION_H

/*
 * A panel of the side bar. ui.c stacks the panels of the page shown top to
 * bottom (under the status line and the tabs), each under its title;
 * adding a panel is writing one of these (a height, a draw function,
 * optionally a press handler) and adding it to a page's list there.
 */

#include <SDL.h>
#include "core/app.h"

typedef struct {
    const char *title; /* drawn above the content; NULL for none */
    int height;        /* the content's height (pixels); 0: the rest of the side bar */
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
extern const ui_section_t UI_TABS;       /* panel_tabs.c */
extern const ui_section_t UI_SAMPLES;    /* panel_samples.c */
extern const ui_section_t UI_SOLVER;     /* panel_solver.c */
extern const ui_section_t UI_STEP;      /* panel_solver.c */
extern const ui_section_t UI_TOOLS;      /* panel_tools.c */
extern const ui_section_t UI_INSPECTOR;  /* panel_tools.c */
extern const ui_section_t UI_PLOT;       /* panel_tools.c */

/* Where a panel's content is now; an empty rectangle when it is not shown. */
SDL_Rect ui_section_content(const app_t *app, const ui_section_t *section);

bool ui_rect_contains(SDL_Rect rect, vector_t pixel, int grow);

#endif
