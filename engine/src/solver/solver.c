#include "solver/solver.h"
#include "base/workers.h"
#include "solver/collision_pass.h"
#include "solver/position_pass.h"
#include "solver/shock.h"
#include "solver/solver_split.h"
#include "solver/solver_wide.h"
#include "solver/velocity_solve.h"

/* The loops over bodies of solver_solve that the workers share
 * (scene_set_workers): each body writes only its own row. */
typedef struct {
    const solver_bodies_t *bodies;
    const solver_settings_t *settings;
} solve_split_t;

static void advance_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const solve_split_t *split = context;
    (void)chunk;
    solver_advance(split->bodies, split->settings, begin, end);
}

static void limit_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const solve_split_t *split = context;
    (void)chunk;
    solver_limit_corrections(split->bodies, split->settings->dt, begin, end);
}

/* fn over every body: on the workers when there are. */
static void for_bodies(workers_t *workers, solve_split_t *split, workers_fn_t fn) {
    workers_for(workers, split->bodies->body_count, fn, split);
}

/* Warm starting off: every contact starts from zero impulse instead of the
 * impulses the narrowphase carried over from its features' last step. */
static void forget_impulses(solver_contact_t *contacts, size_t contact_count) {
    for (size_t i = 0; i < contact_count; i++) {
        for (int j = 0; j < contacts[i].point_count; j++) {
            contacts[i].points[j].normal_impulse = 0.0;
            contacts[i].points[j].tangent_impulse = 0.0;
        }
    }
}

/* The k-th of the loose contacts in the step's order. */
static solver_contact_t *loose_contact(const solver_wide_t *wide, solver_contact_t *contacts,
                                       size_t k, bool reverse) {
    return &contacts[wide->loose[reverse ? wide->loose_count - 1 - k : k]];
}

/*
 * Once the step's motion is fixed (solver_advance), one more iteration of
 * the normals runs with every raised target counted as 0: the end
 * velocities keep no push that only undid a resting approach (set_target),
 * as Box2D v3's relax iterations keep no position bias.
 */
static void relax(solver_wide_t *wide, solver_contact_t *contacts, solver_velocity_t *velocities,
                  bool reverse) {
    solver_split_relax(wide, velocities, reverse);
    for (size_t k = 0; k < wide->loose_count; k++) {
        solver_relax_velocity(loose_contact(wide, contacts, k, reverse), velocities);
    }
}

void solver_solve(solver_wide_t *wide, shock_t *shock, solver_contact_t *contacts,
                  const solver_anchor_t *anchors, size_t contact_count,
                  const solver_bodies_t *bodies, const solver_settings_t *settings,
                  const joint_step_t *joints) {
    solver_velocity_t *velocities = bodies->velocities;
    solve_split_t split = {bodies, settings};
    bool reverse = settings->reverse;
    if (!settings->warm_starting) forget_impulses(contacts, contact_count);
    /* A step pays for the collision pass only with an elastic contact, and
     * for timing impacts only with an impact. */
    prepared_t found =
        solver_split_prepare(wide, contacts, anchors, contact_count, bodies, settings);
    stage_clock_lap(settings->clock, SCENE_STAGE_PREPARE);
    bool any_elastic = found.elastic, any_impact = found.impact;
    /* Bounces before warm starting: last step's impulses, applied one by
     * one inside a deep pile, leave approaches above the threshold that no
     * impact made, and bouncing those kept a pile at e = 0.5 boiling. */
    if (any_elastic) {
        any_impact |= solver_collision_pass(contacts, contact_count, velocities, bodies->states,
                                            settings->dt, settings->restitution_threshold,
                                            settings->velocity_iterations);
        stage_clock_lap(settings->clock, SCENE_STAGE_SOLVER);
    }
    solver_split_warm_start(wide, velocities);
    for (size_t i = 0; i < wide->loose_count; i++) {
        solver_warm_start(&contacts[wide->loose[i]], velocities);
    }
    if (joints->count > 0) {
        joint_solver_prepare(joints, bodies, settings);
    }
    /* Shock propagation before the last iteration, which then spreads its
     * pushes back over both bodies of each contact (shock.h). */
    int shock_after = settings->velocity_iterations > 1 ? settings->velocity_iterations - 1 : 1;
    for (int iteration = 1; iteration <= settings->velocity_iterations; iteration++) {
        /* The last iteration, which spreads shock propagation's pushes,
         * always forward: the pyramids leaned less (docs/design.md). */
        bool backward = reverse && iteration < settings->velocity_iterations;
        solver_split_iterate(wide, velocities, backward);
        for (size_t k = 0; k < wide->loose_count; k++) {
            solver_solve_velocity(loose_contact(wide, contacts, k, backward), velocities);
        }
        if (joints->count > 0) joint_solver_iterate(joints, bodies);
        if (iteration == shock_after) {
            stage_clock_lap(settings->clock, SCENE_STAGE_SOLVER);
            shock_propagate(shock, wide, contacts, contact_count, velocities, bodies->body_count,
                            reverse);
            stage_clock_lap(settings->clock, SCENE_STAGE_SHOCK);
        }
    }
    if (any_impact) {
        solver_split_store(wide, contacts);
        solver_mark_impacts(contacts, contact_count, velocities, bodies->states);
    }
    stage_clock_lap(settings->clock, SCENE_STAGE_SOLVER);
    for_bodies(wide->workers, &split, advance_chunk);
    if (found.raised) relax(wide, contacts, velocities, reverse);
    if (found.raised || !any_impact) solver_split_store(wide, contacts);
    if (joints->count > 0) joint_solver_settle(joints, bodies);
    for (int iteration = 0; iteration < settings->position_iterations; iteration++) {
        /* The lift before the last iteration, which then spreads its moves
         * over both bodies of each contact (shock.h). */
        if (iteration == settings->position_iterations - 1) {
            shock_lift(shock, wide->workers, contacts, bodies, joints);
        }
        bool backward = (iteration % 2 == 1) != reverse;
        solver_split_correct_positions(wide, bodies->displacements, backward);
        for (size_t k = 0; k < wide->loose_count; k++) {
            solver_solve_position(loose_contact(wide, contacts, k, reverse), velocities,
                                  bodies->displacements);
        }
        if (joints->count > 0) joint_solver_correct(joints);
    }
    for_bodies(wide->workers, &split, limit_chunk);
    /* The tree's projection after the bound on the corrections, which is
     * the contacts': held by it, a whipping chain's joints stayed open by
     * the step's centripetal drift. */
    if (joints->count > 0) joint_solver_project(joints, bodies);
    stage_clock_lap(settings->clock, SCENE_STAGE_POSITION);
}
