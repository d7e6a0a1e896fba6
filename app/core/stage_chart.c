#include "core/stage_chart.h"
#include <stdlib.h>
#include <string.h>

void stage_chart_init(stage_chart_t *chart) {
    memset(chart, 0, sizeof(*chart));
}

void stage_chart_add(stage_chart_t *chart, const scene_profile_t *profile) {
    chart->head = (chart->head + 1) % STAGE_CHART_COLUMNS;
    stage_column_t *column = &chart->columns[chart->head];
    for (int s = 0; s < SCENE_STAGE_COUNT; s++) {
        column->seconds[s] = profile->ran[s] ? (float)profile->seconds[s] : 0.0f;
    }
    column->filled = true;
    chart->last = *profile;
    chart->has_last = true;
}

const stage_column_t *stage_chart_column(const stage_chart_t *chart, size_t age) {
    return &chart->columns[(chart->head + STAGE_CHART_COLUMNS - age % STAGE_CHART_COLUMNS) %
                           STAGE_CHART_COLUMNS];
}

static double column_total(const stage_column_t *c) {
    double total = 0.0;
    for (int s = 0; s < SCENE_STAGE_COUNT; s++) total += c->seconds[s];
    return total;
}

static int by_value(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

double stage_chart_scale(const stage_chart_t *chart) {
    double totals[STAGE_CHART_COLUMNS];
    size_t n = 0;
    for (size_t i = 0; i < STAGE_CHART_COLUMNS; i++) {
        if (chart->columns[i].filled) totals[n++] = column_total(&chart->columns[i]);
    }
    if (n == 0) return 0.0;
    qsort(totals, n, sizeof totals[0], by_value);
    double peak = totals[n - 1], median = totals[n / 2];
    return median > 0.0 && peak > 4.0 * median ? 4.0 * median : peak;
}

double stage_chart_peak(const stage_chart_t *chart) {
    double peak = 0.0;
    for (size_t i = 0; i < STAGE_CHART_COLUMNS; i++) {
        const stage_column_t *c = &chart->columns[i];
        if (!c->filled) continue;
        double total = 0.0;
        for (int s = 0; s < SCENE_STAGE_COUNT; s++) total += c->seconds[s];
        if (total > peak) peak = total;
    }
    return peak;
}
