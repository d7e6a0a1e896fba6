#ifndef SOLVER_H
#define SOLVER_H

/*
 * The contact solver: sequential impulses with accumulated-impulse clamping
 * (Catto), warm starting, Coulomb friction, a two-point block solve for the
 * normal impulses (so a box lands and leaves flat), restitution at the
 * time of impact, and non-linear Gauss-Seidel position correction.
 *
 * It works on plain arrays (solver_body_t rows, solver_contact_t
 * constraints) that world.c fills from the bodies and writes back; it knows
 * nothing of scenes or lists.
 *
 * The integrator decides where a velocity puts a body: x' = x + dt ((1 - w) v
 * + w v'), with w its position weight (1/2 for the seed scheme). The solver
 * predicts positions with the same w, so a speculative contact stops a body
 * exactly at the surface, whatever the scheme.
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "vector.h"

typedef struct {
    vector_t v;           /* velocity being solved: ends as the step's new velocity */
    double w;
    vector_t v_start;     /* at the start of the step */
    double w_start;
    vector_t v_free;      /* what it would be at the end without contacts */
    double w_free;
    vector_t acceleration; /* (force / mass) + gravity: for times of impact */
    double inverse_mass, inverse_inertia;
    vector_t dx;          /* displacement this step, advanced then corrected */
    double dtheta;
} solver_body_t;

typedef struct {
    vector_t r_a, r_b;       /* from each centroid to the contact point (world) */
    double separation;       /* at the start of the step (m) */
    double normal_impulse;   /* accumulated (N s), >= 0 */
    double tangent_impulse;  /* accumulated (N s), |.| <= friction * normal */
    double normal_mass, tangent_mass;
    double target;           /* lower bound on the end relative normal velocity */
    double position_target;  /* impact points: the exact end separation */
    bool impact;             /* closes within this step at restitution speed */
    uint32_t id;
} solver_point_t;

typedef struct {
    uint32_t a, b;           /* rows in the solver_body_t array */
    vector_t normal;         /* unit, from a toward b */
    double friction, restitution;
    int point_count;
    solver_point_t points[2];
    /* Inverse of the 2x2 normal effective-mass matrix (block solve). */
    double k11, k12, k22;
    double m11, m12, m22;
    bool block;
} solver_contact_t;

typedef struct {
    double dt;
    double position_weight;
    int velocity_iterations;
    int position_iterations;
} solver_settings_t;

/* Below this approach speed (m/s) contacts are inelastic: a resting body
 * must not bounce on the speed gravity gives it in one step. */
extern const double SOLVER_RESTITUTION_THRESHOLD;
/* Overlap the position correction leaves alone (m), so resting contacts
 * persist from step to step instead of flickering. */
extern const double SOLVER_LINEAR_SLOP;

/* Everything after the narrowphase: prepare, warm start, velocity
 * iterations, advance, position iterations. On return bodies[i].v and .w are
 * the new velocities and .dx, .dtheta the displacements of the step. */
void solver_solve(solver_contact_t *contacts, size_t contact_count, solver_body_t *bodies,
                  size_t body_count, const solver_settings_t *settings);

#endif // #ifndef SOLVER_H
