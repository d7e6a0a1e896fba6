#include "core/energy_drift.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Drifts are kept as floats in the columns; beyond this they are clipped
 * (the chart's scale stops at 1000% anyway). */
#define DRIFT_CLIP 1e6

void energy_drift_init(energy_drift_t *drift) {
    memset(drift, 0, sizeof(*drift));
    drift->step = DRIFT_DEFAULT_STEP;
}

void energy_drift_set_step(energy_drift_t *drift, double step) {
    if (step > 0.0 && isfinite(step)) drift->step = step;
}

void energy_drift_rereference(energy_drift_t *drift) {
    drift->have_reference = false;
}

static void put(drift_column_t *column, double value) {
    float v = (float)fmin(DRIFT_CLIP, fmax(-DRIFT_CLIP, value));
    if (!column->filled) {
        column->low = column->high = v;
        column->filled = true;
    } else {
        column->low = fminf(column->low, v);
        column->high = fmaxf(column->high, v);
    }
}

/* Whether `elapsed` seconds run past a column (rounding forgiven: 3 steps of
 * 1/120 s fill a column of 1/40 s exactly). */
static bool past_column(double elapsed) {
    return elapsed > DRIFT_COLUMN_SECONDS * (1.0 + 1e-6);
}

/* Moves on to the next column after `steps` more steps. A column that no
 * frame fell in (a frame longer than a column, after a late one) carries the
 * last drift on. */
static void advance(energy_drift_t *drift, int steps) {
    drift->elapsed += steps * drift->step;
    while (past_column(drift->elapsed)) {
        drift->elapsed -= DRIFT_COLUMN_SECONDS;
        drift->head = (drift->head + 1) % DRIFT_COLUMNS;
        drift_column_t *column = &drift->columns[drift->head];
        *column = (drift_column_t){0};
        if (past_column(drift->elapsed) && drift->valid) put(column, drift->drift);
        /* A step longer than the whole chart need not walk every column. */
        if (drift->elapsed > (DRIFT_COLUMNS + 1) * DRIFT_COLUMN_SECONDS) {
            drift->elapsed = DRIFT_COLUMNS * DRIFT_COLUMN_SECONDS +
                             fmod(drift->elapsed, DRIFT_COLUMN_SECONDS);
        }
    }
}

void energy_drift_sample(energy_drift_t *drift, int steps, double energy, double kinetic,
                         size_t bodies, unsigned long changes) {
    if (steps > 0) advance(drift, steps);
    drift_column_t *column = &drift->columns[drift->head];
    bool retake = !drift->have_reference || changes != drift->changes;
    if (retake) {
        /* A mark where the chart had a drift to break off from. */
        if (drift->valid) {
            column->rereferenced = true;
            column->filled = false;
        }
        drift->reference = energy;
        drift->kinetic_peak = 0.0;
        drift->have_reference = true;
        drift->changes = changes;
    }
    if (isfinite(kinetic)) drift->kinetic_peak = fmax(drift->kinetic_peak, kinetic);
    double scale = fmax(fabs(drift->reference), drift->kinetic_peak);
    drift->valid = bodies > 0 && isfinite(energy) && isfinite(drift->reference) &&
                   scale >= DRIFT_MIN_ENERGY;
    drift->drift = drift->valid ? (energy - drift->reference) / scale : 0.0;
    if (drift->valid && steps > 0) put(column, drift->drift);
}

const drift_column_t *energy_drift_column(const energy_drift_t *drift, size_t age) {
    if (age >= DRIFT_COLUMNS) age = DRIFT_COLUMNS - 1;
    return &drift->columns[(drift->head + DRIFT_COLUMNS - age) % DRIFT_COLUMNS];
}

double energy_drift_scale(const energy_drift_t *drift) {
    double largest = drift->valid ? fabs(drift->drift) : 0.0;
    for (size_t i = 0; i < DRIFT_COLUMNS; i++) {
        const drift_column_t *column = &drift->columns[i];
        if (!column->filled) continue;
        largest = fmax(largest, fmax(fabs(column->low), fabs(column->high)));
    }
    static const double MANTISSAS[3] = {1.0, 2.0, 5.0};
    for (int exponent = -4; exponent <= 1; exponent++) {
        for (int i = 0; i < 3; i++) {
            double scale = MANTISSAS[i] * pow(10.0, exponent);
            if (scale > DRIFT_MAX_SCALE * (1.0 + 1e-9)) return DRIFT_MAX_SCALE;
            /* (the columns hold floats: -5% is a hair beyond 0.05 there) */
            if (scale * (1.0 + 1e-6) >= largest) return scale;
        }
    }
    return DRIFT_MAX_SCALE;
}

void energy_drift_format(double fraction, char *out, size_t size) {
    double percent = fraction * 100.0;
    double size_of = fabs(percent);
    if (isnan(percent)) {
        snprintf(out, size, "?");
    } else if (size_of < 0.0005) {
        snprintf(out, size, "0.000%%");
    } else if (size_of < 1.0) {
        snprintf(out, size, "%+.3f%%", percent);
    } else if (size_of < 10.0) {
        snprintf(out, size, "%+.2f%%", percent);
    } else if (size_of < 100.0) {
        snprintf(out, size, "%+.1f%%", percent);
    } else if (size_of < 999.5) {
        snprintf(out, size, "%+.0f%%", percent);
    } else {
        snprintf(out, size, "%s", percent > 0 ? ">+999%" : "<-999%");
    }
}

void energy_drift_format_scale(double scale, char sign, char *out, size_t size) {
    snprintf(out, size, "%c%g%%", sign, scale * 100.0);
}
