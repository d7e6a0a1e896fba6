#ifndef REFERENCE_H
#define REFERENCE_H

/*
 * Scenes with exact answers, run through the public API: the accuracy
 * report (tests/report/accuracy.c, docs/accuracy.md) sweeps them over
 * integrators and step sizes, and make check runs a few of the same runs
 * (tests/test_integrators.c). docs/accuracy.md writes out each scene's
 * formulas.
 */

#include <stdbool.h>
#include "jostle/scene.h"

typedef enum {
    /* A 1 kg body on a spring (omega = 2 pi, period 1 s) to an anchor of
     * infinite mass: x(t) = x0 cos wt + (v0 / w) sin wt. */
    REFERENCE_OSCILLATOR,
    /* Kepler's problem at eccentricity 0.6, G (m1 + m2) = 1, a 0.001 kg
     * body around a 1 kg one, the centre of mass at rest: the relative
     * position starts at (1 - e, 0) with velocity (0, sqrt((1 + e) /
     * (1 - e))); energy -1/2 per unit reduced mass, period 2 pi. */
    REFERENCE_KEPLER,
    /* A 1 kg projectile under gravity (0, -9.81) and linear drag gamma = 0.5
     * kg/s (b = gamma / m): v = v_inf + (v0 - v_inf) e^(-bt). Period 1 s. */
    REFERENCE_DRAG,
    /* The bounce scene of docs/bench-scenes.md (world contacts): a 1 m box
     * dropped from 10 m at elasticity 0.8; apex n at 10 (0.8)^(2n) m. */
    REFERENCE_BOUNCE,
    /* The orbit scene of docs/bench-scenes.md: G = 1, 1000 kg at the
     * origin, 1 kg at (10, 0) with velocity (0, 10). */
    REFERENCE_ORBIT,
    /* REFERENCE_KEPLER at eccentricity 0.9 (pericentre 0.1, apocentre
     * 1.9): a hundred times faster at pericentre than at apocentre. */
    REFERENCE_KEPLER_ECCENTRIC,
    REFERENCE_COUNT,
} reference_scene_t;

typedef struct {
    /* The scene's error (reference_error_name); NAN when diverged. For the
     * oscillator and the orbits it is the error in phase space: position
     * over the amplitude (semi-major axis a) and velocity over omega A
     * (sqrt(mu / a)), combined as a Euclidean norm. Position alone hides
     * symplectic Euler's first-order error: that scheme is Verlet seen
     * through a half kick, which changes velocities only. */
    double error;
    /* Largest |E / E0 - 1| over the run; NAN for a scene that does not
     * conserve energy (drag, bounce). */
    double energy_drift;
    /* Largest |L / L0 - 1| of the total angular momentum (orbits); NAN
     * elsewhere. */
    double momentum_drift;
    long steps;
    /* Passes over the force creators over the run (scene_stats_t). */
    long evaluations;
    /* The centroid of the body the error is measured on, at the end. */
    vector_t end_centroid;
    /* The state left any sane bound (energy a million times the start's,
     * or not finite): the run stopped there. */
    bool diverged;
} reference_result_t;

const char *reference_name(reference_scene_t scene);

/* What `error` measures, e.g. "position error after 10 periods / amplitude". */
const char *reference_error_name(reference_scene_t scene);

/* The scene's period (s): oscillator 1, Kepler 2 pi, drag 1 (s of
 * flight), orbit its Kepler period; the bounce runs to its fifth apex. */
double reference_period(reference_scene_t scene);

/* Runs the scene for `periods` periods (the bounce: to its fifth apex) with
 * steps of h under the integrator. */
reference_result_t reference_run(reference_scene_t scene, integrator_t integrator, double h,
                                 double periods);

/*
 * One run, for a caller that times the steps apart from the measuring
 * (docs/accuracy.md): reference_start builds the scene at t = 0, the caller
 * ticks reference_get_scene's scene by h, and reference_measure compares
 * its state with the exact answer at time t. Not for the bounce, whose
 * error is read along the run (reference_run).
 */
typedef struct reference_sim reference_sim_t;

typedef struct {
    /* As reference_result_t's error, at t. */
    double error;
    /* Position alone: the distance to the exact position over the
     * amplitude (semi-major axis), the phase error once it is large. */
    double position_error;
    /* E / E0 - 1 and L / L0 - 1 (total angular momentum) at t, signed;
     * NAN where not conserved (drag) or zero (the oscillator's L). */
    double energy_error, momentum_error;
} reference_state_t;

reference_sim_t *reference_start(reference_scene_t scene, integrator_t integrator, double h);
scene_t *reference_get_scene(reference_sim_t *sim);
reference_state_t reference_measure(reference_sim_t *sim, double t);
/* E / E0 - 1 and L / L0 - 1 now, cheaply (no exact answer); NAN as above. */
void reference_invariants(reference_sim_t *sim, double *energy_error, double *momentum_error);
/* The centroid of the body the error is measured on, for checking that
 * two runs ended in the same state. */
vector_t reference_tracked_centroid(reference_sim_t *sim);
void reference_finish(reference_sim_t *sim);

/* The steps of a run of `periods` periods at step h (not the bounce's). */
long reference_steps(reference_scene_t scene, double h, double periods);

/* Kepler's problem for the relative position r and velocity v of two
 * bodies with mu = G (m1 + m2), on an ellipse: r and v after time t. */
void reference_kepler_propagate(double mu, vector_t r0, vector_t v0, double t, vector_t *r,
                                vector_t *v);

#endif // #ifndef REFERENCE_H
