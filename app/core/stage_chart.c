#include "core/stage_chart.h"
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
