#include "core/layout.h"
#include <math.h>

/* The window at which the UI starts to grow. */
#define SCALE_FROM_WIDTH 1280.0
#define SCALE_FROM_HEIGHT 720.0

static double scale_of(int width, int height) {
    double fit = fmin(width / SCALE_FROM_WIDTH, height / SCALE_FROM_HEIGHT);
    double quarters = floor(4.0 * fit) / 4.0;
    return quarters > 1.0 ? quarters : 1.0;
}

layout_t layout_of(int width, int height) {
    layout_t layout;
    layout.scale = scale_of(width, height);
    int sidebar_w = (int)lround(LAYOUT_SIDEBAR_W * layout.scale);
    if (sidebar_w > width) sidebar_w = width;
    layout.view = (layout_rect_t){0, 0, width - sidebar_w, height};
    layout.sidebar = (layout_rect_t){width - sidebar_w, 0, sidebar_w, height};
    layout.panels = layout.scale == 1.0
                        ? layout.sidebar
                        : (layout_rect_t){0, 0, (int)lround(sidebar_w / layout.scale),
                                          (int)floor(height / layout.scale)};
    return layout;
}

void layout_to_panels(const layout_t *layout, double x, double y, double *ux, double *uy) {
    *ux = (x - layout->sidebar.x) / layout->scale + layout->panels.x;
    *uy = (y - layout->sidebar.y) / layout->scale + layout->panels.y;
}

bool layout_contains(layout_rect_t rect, double x, double y) {
    return x >= rect.x && x < rect.x + rect.w && y >= rect.y && y < rect.y + rect.h;
}
