#include "draw/focus.h"
#include <stdlib.h>

void focus_top_init(focus_top_t *top, size_t k) {
    top->count = 0;
    top->next = 0;
    top->k = k < FOCUS_MAX ? k : FOCUS_MAX;
}

/* A min-heap on weight: the root is the smallest kept, the one to replace. */
static void swap(focus_top_t *top, size_t a, size_t b) {
    size_t i = top->index[a];
    double w = top->weight[a];
    top->index[a] = top->index[b];
    top->weight[a] = top->weight[b];
    top->index[b] = i;
    top->weight[b] = w;
}

static void sift_down(focus_top_t *top, size_t at) {
    for (;;) {
        size_t low = at, left = 2 * at + 1, right = left + 1;
        if (left < top->count && top->weight[left] < top->weight[low]) low = left;
        if (right < top->count && top->weight[right] < top->weight[low]) low = right;
        if (low == at) return;
        swap(top, at, low);
        at = low;
    }
}

void focus_top_offer(focus_top_t *top, size_t index, double w) {
    if (top->k == 0) return;
    if (top->count < top->k) {
        size_t at = top->count++;
        top->index[at] = index;
        top->weight[at] = w;
        while (at > 0 && top->weight[(at - 1) / 2] > top->weight[at]) {
            swap(top, at, (at - 1) / 2);
            at = (at - 1) / 2;
        }
        return;
    }
    if (!(w > top->weight[0])) return;
    top->index[0] = index;
    top->weight[0] = w;
    sift_down(top, 0);
}

static int by_index(const void *a, const void *b) {
    size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return x < y ? -1 : x > y;
}

void focus_top_sort(focus_top_t *top) {
    qsort(top->index, top->count, sizeof top->index[0], by_index);
    top->next = 0;
}

bool focus_top_has(focus_top_t *top, size_t index) {
    while (top->next < top->count && top->index[top->next] < index) top->next++;
    return top->next < top->count && top->index[top->next] == index;
}

void focus_near_offer(focus_top_t *near, size_t index, vector_t p, bool has_cursor,
                      vector_t cursor) {
    if (!has_cursor) return;
    double dx = p.x - cursor.x, dy = p.y - cursor.y, d2 = dx * dx + dy * dy;
    if (d2 <= FOCUS_RADIUS * FOCUS_RADIUS) focus_top_offer(near, index, -d2);
}
