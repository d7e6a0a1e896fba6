#ifndef STABILITY_THEORY_H
#define STABILITY_THEORY_H

/*
 * Each integrator's step, as docs/design.md and engine/src/dynamics/integrator.h
 * write it, applied to the damped oscillator x'' = -omega^2 x - 2 zeta
 * omega x' with omega = 1 and step theta: a linear map of (x, v) whose
 * spectral radius squared is the energy factor per step once the run has
 * settled on its slowest-decaying (or fastest-growing) mode. The stability
 * limit is the least theta at which that factor passes 1. This is the
 * theory the stability suite sets beside the engine's runs; with zeta = 0
 * it gives back the limits of integrator_get_stability_limit.
 */

#include <math.h>
#include <stdbool.h>
#include "jostle/scene.h"

typedef struct {
    double x, v;
} theory_state_t;

static inline double theory_acceleration(double x, double v, double zeta) {
    return -x - 2.0 * zeta * v;
}

/* Kick h/2 with the last acceleration a, drift h, kick h/2 with the
 * acceleration at the drifted pose and the velocity a full kick predicts
 * (integrator.c's verlet_step); a is updated for the next sub-step. */
static inline theory_state_t theory_verlet(theory_state_t s, double h, double zeta, double *a) {
    double run = s.v + 0.5 * h * *a;
    double q = s.x + h * run;
    double u = run + 0.5 * h * *a;
    *a = theory_acceleration(q, u, zeta);
    return (theory_state_t){q, run + 0.5 * h * *a};
}

static inline theory_state_t theory_step(integrator_t integrator, theory_state_t s, double h,
                                         double zeta) {
    double a = theory_acceleration(s.x, s.v, zeta);
    switch (integrator) {
    case INTEGRATOR_SEED:
    case INTEGRATOR_EXPLICIT_EULER:
    case INTEGRATOR_SYMPLECTIC_EULER: {
        double w = integrator == INTEGRATOR_SEED ? 0.5
                   : integrator == INTEGRATOR_EXPLICIT_EULER ? 0.0
                                                               : 1.0;
        double v = s.v + h * a;
        return (theory_state_t){s.x + h * ((1.0 - w) * s.v + w * v), v};
    }
    case INTEGRATOR_VELOCITY_VERLET: return theory_verlet(s, h, zeta, &a);
    case INTEGRATOR_SYMPLECTIC4: {
        double cube_root = cbrt(2.0);
        double outer = 1.0 / (2.0 - cube_root), inner = -cube_root * outer;
        s = theory_verlet(s, outer * h, zeta, &a);
        s = theory_verlet(s, inner * h, zeta, &a);
        return theory_verlet(s, outer * h, zeta, &a);
    }
    case INTEGRATOR_IMPLICIT_EULER: {
        /* v' = v + h a(x', v'), x' = x + h v': v' (1 + 2 zeta h + h^2) = v - h x. */
        double v = (s.v - h * s.x) / (1.0 + 2.0 * zeta * h + h * h);
        return (theory_state_t){s.x + h * v, v};
    }
    case INTEGRATOR_RK4: {
        const double offsets[3] = {0.5, 0.5, 1.0}, weights[3] = {2.0, 2.0, 1.0};
        double sum_u = s.v, sum_a = a, u = s.v;
        for (int k = 0; k < 3; k++) {
            double q = s.x + offsets[k] * h * u;
            u = s.v + offsets[k] * h * a;
            a = theory_acceleration(q, u, zeta);
            sum_u += weights[k] * u;
            sum_a += weights[k] * a;
        }
        return (theory_state_t){s.x + h / 6.0 * sum_u, s.v + h / 6.0 * sum_a};
    }
    }
    return s;
}

/* The energy factor per step: the spectral radius squared of the step's
 * matrix. */
static inline double theory_growth(integrator_t integrator, double theta, double zeta) {
    theory_state_t c1 = theory_step(integrator, (theory_state_t){1.0, 0.0}, theta, zeta);
    theory_state_t c2 = theory_step(integrator, (theory_state_t){0.0, 1.0}, theta, zeta);
    double a = c1.x, b = c2.x, c = c1.v, d = c2.v;
    double trace = a + d, det = a * d - b * c, disc = trace * trace - 4.0 * det;
    if (disc < 0.0) return det;
    double radius = (fabs(trace) + sqrt(disc)) / 2.0;
    return radius * radius;
}

/* The least theta in [first, last] at which the growth passes 1 (+1e-12),
 * to 1e-9; 0 when it does at `first`, INFINITY when nowhere. */
static inline double theory_limit(integrator_t integrator, double zeta, double first,
                                  double last) {
    const double step = 1e-3, tolerance = 1e-12;
    if (theory_growth(integrator, first, zeta) > 1.0 + tolerance) return 0.0;
    for (double lo = first; lo < last; lo += step) {
        double hi = fmin(lo + step, last);
        if (theory_growth(integrator, hi, zeta) > 1.0 + tolerance) {
            while (hi - lo > 1e-9) {
                double mid = 0.5 * (lo + hi);
                if (theory_growth(integrator, mid, zeta) > 1.0 + tolerance) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return 0.5 * (lo + hi);
        }
    }
    return INFINITY;
}

#endif // #ifndef STABILITY_THEORY_H
