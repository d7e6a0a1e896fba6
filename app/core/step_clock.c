#include "core/step_clock.h"
#include <math.h>
#include <stdbool.h>

double step_clock_step(const step_clock_t *clock) {
    return clock->step > 0.0 ? clock->step : STEP_CLOCK_STEP;
}

int step_clock_max_steps(const step_clock_t *clock) {
    double steps = ceil(STEP_CLOCK_MAX_STEPS * STEP_CLOCK_STEP / step_clock_step(clock) - 1e-9);
    return steps > STEP_CLOCK_MAX_STEPS ? (int)fmin(steps, 100000.0) : STEP_CLOCK_MAX_STEPS;
}

void step_clock_set_step(step_clock_t *clock, double step) {
    clock->step = step > 0.0 ? step : 0.0;
    clock->owed = 0.0;
}

int step_clock_advance(step_clock_t *clock, double dt) {
    return step_clock_advance_within(clock, dt, 0);
}

int step_clock_budget(double period, double other, double per_step) {
    if (!(per_step > 0.0)) return 0;
    double fit = floor((period - other) / per_step);
    return fit < 1.0 ? 1 : (int)fmin(fit, 100000.0);
}

double step_clock_step_cost(double cost, double seconds, int steps) {
    if (steps <= 0 || !(seconds >= 0.0)) return cost;
    double per_step = seconds / steps;
    if (cost == 0.0) return per_step;
    return steps >= 2 || per_step < cost ? 0.9 * cost + 0.1 * per_step : cost;
}

int step_clock_advance_within(step_clock_t *clock, double dt, int budget) {
    double step = step_clock_step(clock);
    int max_steps = step_clock_max_steps(clock);
    bool held = budget > 0 && budget < max_steps && clock->owed + dt >= (budget + 1) * step;
    if (held) max_steps = budget;
    double max_debt = fmax(STEP_CLOCK_MAX_DEBT, step);
    clock->owed += dt;
    int steps = 0;
    while (clock->owed >= step && steps < max_steps) {
        clock->owed -= step;
        steps++;
    }
    if (held) {
        clock->held++;
        max_debt = step;
    }
    if (clock->owed > max_debt) {
        clock->forgiven += clock->owed - max_debt;
        clock->owed = max_debt;
    }
    clock->simulated += steps * step;
    return steps;
}
