#ifndef SANDBOX_ENERGY_DRIFT_H
#define SANDBOX_ENERGY_DRIFT_H

/*
 * The scene's relative energy drift over the last few seconds of simulated
 * time, for the INTEGRATOR panel's strip chart:
 *
 *     drift = (E - E_ref) / max(|E_ref|, K_peak)
 *
 * E is what the caller measures after each frame's steps (the sandbox: the
 * kinetic plus gravitational potential energy of every body of finite mass)
 * and K_peak the largest kinetic energy since E_ref. The potential's zero
 * is arbitrary, so |E_ref| alone can be as near 0 as it likes (a pendulum
 * released at the height of its pivot); the energy the motion exchanges is
 * then the scale that means something.
 * E_ref is the first E after a change that is not the integrator's doing:
 * bodies added or removed (the caller's change counter moves), or a
 * rereference asked for (the integrator switched, gravity toggled, a grab let
 * go). Each column of the chart holds the lowest and highest drift of the
 * frames that fell in its 1/40 s of simulated time (3 steps of 1/120 s; the
 * step is the scene's, energy_drift_set_step), so a spike shorter than a
 * column still shows. Fixed size, no allocation; plain C (no SDL, no engine), tested
 * by tests/app_units.c.
 */

#include <stdbool.h>
#include <stddef.h>

/* 200 columns of 1/40 s (3 steps of 1/120 s): the last 5 s of simulated
 * time. */
#define DRIFT_COLUMNS 200
#define DRIFT_COLUMN_SECONDS (1.0 / 40.0)
#define DRIFT_SECONDS 5.0
/* The step when none is set (s). */
#define DRIFT_DEFAULT_STEP (1.0 / 120.0)
/* The vertical scale: 1, 2, 5 times a power of ten, from 0.01% to 1000%. */
#define DRIFT_MIN_SCALE 1e-4
#define DRIFT_MAX_SCALE 10.0
/* Below this scale, max(|E_ref|, K_peak) (J), a relative drift means
 * nothing: none is shown. */
#define DRIFT_MIN_ENERGY 1e-6

typedef struct {
    float low, high;   /* the drift of the frames in this column */
    bool filled;       /* some frame gave a drift */
    bool rereferenced; /* E_ref was taken again in this column */
} drift_column_t;

typedef struct {
    drift_column_t columns[DRIFT_COLUMNS]; /* a ring; columns[head] is the newest */
    size_t head;
    double elapsed;         /* simulated seconds into the newest column */
    double step;            /* seconds per step */
    double reference;       /* E_ref (J) */
    double kinetic_peak;    /* K_peak (J) */
    bool have_reference;    /* false: the next sample takes one */
    unsigned long changes;  /* the caller's change counter at E_ref */
    double drift;           /* the latest drift */
    bool valid;             /* whether `drift` means anything (bodies, a scale large enough) */
} energy_drift_t;

/* Empty, for steps of DRIFT_DEFAULT_STEP; the first sample takes the
 * reference. */
void energy_drift_init(energy_drift_t *drift);

/* Steps of `step` seconds from now on (a scene with another timestep). */
void energy_drift_set_step(energy_drift_t *drift, double step);

/* Takes E_ref again at the next sample. */
void energy_drift_rereference(energy_drift_t *drift);

/*
 * After a frame in which `steps` physics steps ran, the energy then and the
 * kinetic part of it (J), how many bodies it counts, and the caller's change
 * counter (bodies added or removed move it). A frame without steps (paused) records nothing on the
 * chart but may still take a new reference (a body dropped while paused).
 */
void energy_drift_sample(energy_drift_t *drift, int steps, double energy, double kinetic,
                         size_t bodies, unsigned long changes);

/* A column by age: 0 the newest, DRIFT_COLUMNS - 1 the oldest. */
const drift_column_t *energy_drift_column(const energy_drift_t *drift, size_t age);

/* The chart's half height as a fraction: the smallest of 1, 2, 5 times a power
 * of ten that holds every drift on the chart, from DRIFT_MIN_SCALE to
 * DRIFT_MAX_SCALE. */
double energy_drift_scale(const energy_drift_t *drift);

/* A drift as a signed percentage that fits 7 characters ("+0.012%",
 * "-1.35%", "+12.3%", "+250%"); one that rounds to zero is "0.000%". */
void energy_drift_format(double fraction, char *out, size_t size);

/* A scale as the chart's label, with its sign ("+0.05%", "-1%", "+1000%"). */
void energy_drift_format_scale(double scale, char sign, char *out, size_t size);

#endif
