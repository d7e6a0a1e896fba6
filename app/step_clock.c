#include "step_clock.h"

int step_clock_advance(step_clock_t *clock, double dt) {
    clock->owed += dt;
    int steps = 0;
    while (clock->owed >= STEP_CLOCK_STEP && steps < STEP_CLOCK_MAX_STEPS) {
        clock->owed -= STEP_CLOCK_STEP;
        steps++;
    }
    if (clock->owed > STEP_CLOCK_MAX_DEBT) {
        clock->forgiven += clock->owed - STEP_CLOCK_MAX_DEBT;
        clock->owed = STEP_CLOCK_MAX_DEBT;
    }
    clock->simulated += steps * STEP_CLOCK_STEP;
    return steps;
}
