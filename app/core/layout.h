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

/* The side bar's width: 32 characters of the 8x8 font between its paddings. */
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
} layout_t;

/* The layout of a window of width x height pixels. */
layout_t layout_of(int width, int height);

bool layout_contains(layout_rect_t rect, double x, double y);

#endif
