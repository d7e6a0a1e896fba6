#include "core/plot.h"
#include <math.h>

#define COLUMN_SECONDS (PLOT_SECONDS / PLOT_COLUMNS)

void plot_init(plot_t *plot, plot_quantity_t quantity) {
    *plot = (plot_t){0};
    plot->quantity = quantity < PLOT_QUANTITY_COUNT ? quantity : PLOT_HEIGHT;
}

static void put(plot_column_t *column, double value) {
    float v = (float)value;
    if (!column->filled) {
        column->low = column->high = v;
        column->filled = true;
        return;
    }
    if (v < column->low) column->low = v;
    if (v > column->high) column->high = v;
}

void plot_sample(plot_t *plot, double seconds, bool has_value, double value) {
    plot->has_latest = has_value && isfinite(value);
    if (plot->has_latest) plot->latest = value;
    if (!(seconds > 0.0)) return;
    /* Columns the frame crossed are left as they are (empty when new), the
     * one it ends in takes the value. */
    plot->elapsed += seconds;
    while (plot->elapsed >= COLUMN_SECONDS) {
        plot->elapsed -= COLUMN_SECONDS;
        plot->head = (plot->head + 1) % PLOT_COLUMNS;
        plot->columns[plot->head] = (plot_column_t){0};
    }
    if (plot->has_latest) put(&plot->columns[plot->head], value);
}

const plot_column_t *plot_column(const plot_t *plot, size_t age) {
    return &plot->columns[(plot->head + PLOT_COLUMNS - age % PLOT_COLUMNS) % PLOT_COLUMNS];
}

bool plot_range(const plot_t *plot, double *low, double *high) {
    bool any = false;
    for (size_t i = 0; i < PLOT_COLUMNS; i++) {
        const plot_column_t *c = &plot->columns[i];
        if (!c->filled) continue;
        *low = any ? fmin(*low, c->low) : c->low;
        *high = any ? fmax(*high, c->high) : c->high;
        any = true;
    }
    if (!any) return false;
    double span = *high - *low, size = fmax(fabs(*low), fabs(*high));
    if (span <= 1e-9 * size || span == 0.0) {
        double pad = size > 0.0 ? 0.01 * size : 1.0;
        *low -= pad;
        *high += pad;
    }
    return true;
}

const char *plot_quantity_name(plot_quantity_t quantity) {
    static const char *const NAMES[PLOT_QUANTITY_COUNT] = {
        "height (m)", "speed (m/s)", "kinetic energy (J)", "energy (J)", "momentum (N s)"};
    return quantity < PLOT_QUANTITY_COUNT ? NAMES[quantity] : "?";
}

bool plot_needs_body(plot_quantity_t quantity) {
    return quantity == PLOT_HEIGHT || quantity == PLOT_SPEED;
}
