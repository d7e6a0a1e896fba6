#ifndef SANDBOX_LAYOUT_H
#define SANDBOX_LAYOUT_H

/*
 * How the window is shared: the world view on the left, a side bar of
 * stacked panels on the right. No panel is drawn over the view, so none can
 * hide a body (but the help screen and a game's end screen, which cover it
 * on purpose); the camera fits the container into the view alone.
 * Plain C (no SDL): the smoke tests include it to know where things are.
 */

#include <stdbool.h>

/* The smallest window the panels and the whole container fit in. */
#define LAYOUT_MIN_WIDTH 800
#define LAYOUT_MIN_HEIGHT 600

/* The side bar's width at scale 1: 32 characters of the 8x8 font between
 * its paddings. */
#define LAYOUT_SIDEBAR_W 272
#define LAYOUT_PAD 8
#define LAYOUT_CHAR_W 8
#define LAYOUT_LINE_H 12
/* Characters a side bar line may hold. */
#define LAYOUT_LINE_CHARS ((LAYOUT_SIDEBAR_W - 2 * LAYOUT_PAD) / LAYOUT_CHAR_W)

typedef struct {
    int x, y, w, h;
} layout_rect_t;

typedef struct {
    layout_rect_t view;    /* the world, at the window's top left */
    layout_rect_t sidebar; /* the panels, along the right edge */
    /* The UI's scale: the side bar, the help and the end screen are drawn
     * at it (text `scale` times the font's size), so that they grow with the
     * window: 1 up to 1280x720 (or any window narrower or lower), then
     * min(width / 1280, height / 720) in quarters (2 at 2560x1440). */
    double scale;
    /* The side bar in UI units, where its panels are laid out: the side bar
     * itself at scale 1, else a surface of its own (x = y = 0) drawn scaled
     * into it. */
    layout_rect_t panels;
} layout_t;

/* The layout of a window of width x height pixels. */
layout_t layout_of(int width, int height);

/* A window pixel in the side bar's UI units (layout.panels). */
void layout_to_panels(const layout_t *layout, double x, double y, double *ux, double *uy);

bool layout_contains(layout_rect_t rect, double x, double y);

#endif
