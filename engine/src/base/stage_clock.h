#ifndef STAGE_CLOCK_H
#define STAGE_CLOCK_H

/* The stages of a step (scene_profile_t): a lap ends the stage running
 * since the last lap, marking it ran and, when timing, adding its time.
 * Timing reads the clock once per lap (CLOCK_MONOTONIC, a vDSO call of
 * about 40 ns: more than a two-body step's whole physics, so it is off
 * unless asked for); a NULL clock (parts of the step run outside a scene,
 * as tests do) marks nothing. */

#include <stdbool.h>
#include <time.h>
#include "jostle/scene.h"

typedef struct {
    scene_profile_t *profile;
    double mark; /* s, when the stage now running started */
    bool timing; /* read the clock at each lap (scene_set_profiling) */
} stage_clock_t;

static inline double stage_clock_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Starts timing from now, the stage before left uncounted. */
static inline void stage_clock_start(stage_clock_t *clock) {
    if (clock != NULL && clock->timing) clock->mark = stage_clock_now();
}

/* The time since the last lap (or start) was stage's. */
static inline void stage_clock_lap(stage_clock_t *clock, scene_stage_t stage) {
    if (clock == NULL) return;
    clock->profile->ran[stage] = true;
    if (!clock->timing) return;
    double now = stage_clock_now();
    clock->profile->seconds[stage] += now - clock->mark;
    clock->mark = now;
}

#endif // #ifndef STAGE_CLOCK_H
