#ifndef SANDBOX_STAGE_CHART_H
#define SANDBOX_STAGE_CHART_H

/*
 * The step's time by stage, live (the SOLVER page's STEP panel): for each
 * frame that stepped, the stage times of its last step (scene_get_profile),
 * in a ring of STAGE_CHART_COLUMNS columns, and which stages that step ran
 * (a stage it left out stays dim in the legend). Nothing allocated. Plain C
 * (engine API), no SDL.
 */

#include <stdbool.h>
#include <stddef.h>
#include "jostle/scene.h"

#define STAGE_CHART_COLUMNS 150

typedef struct {
    float seconds[SCENE_STAGE_COUNT];
    bool filled;
} stage_column_t;

typedef struct {
    stage_column_t columns[STAGE_CHART_COLUMNS]; /* a ring; columns[head] is the newest */
    size_t head;
    scene_profile_t last; /* the newest profile, with its counts */
    bool has_last;
} stage_chart_t;

void stage_chart_init(stage_chart_t *chart);

/* A frame whose last step had this profile. */
void stage_chart_add(stage_chart_t *chart, const scene_profile_t *profile);

/* The column `age` frames before the newest (age < STAGE_CHART_COLUMNS). */
const stage_column_t *stage_chart_column(const stage_chart_t *chart, size_t age);

/* The longest step on the chart (s), 0 when it is empty. */
double stage_chart_peak(const stage_chart_t *chart);

/* The chart's full height (s): the longest step, but at most four times
 * the median step, so that one slow step (the first after a scene opens,
 * a page shown) does not flatten the rest; taller columns are cut at the
 * top. 0 when the chart is empty. */
double stage_chart_scale(const stage_chart_t *chart);

#endif
