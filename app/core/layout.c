#include "core/layout.h"

layout_t layout_of(int width, int height) {
    int sidebar_w = width > LAYOUT_SIDEBAR_W ? LAYOUT_SIDEBAR_W : width;
    layout_t layout;
    layout.view = (layout_rect_t){0, 0, width - sidebar_w, height};
    layout.sidebar = (layout_rect_t){width - sidebar_w, 0, sidebar_w, height};
    return layout;
}

bool layout_contains(layout_rect_t rect, double x, double y) {
    return x >= rect.x && x < rect.x + rect.w && y >= rect.y && y < rect.y + rect.h;
}
