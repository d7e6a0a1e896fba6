#ifndef SCENE_H
#define SCENE_H

/*
 * A scene: the bodies, the force creators that act on them, and optionally a
 * world contact pipeline (every body collides with every other, with friction,
 * resting contact and stacking).
 *
 * One scene_tick runs these stages in order, each skipped when the scene has
 * nothing for it (docs/design.md has the picture):
 *   1. forces: the force creators, in the order they were added (again at
 *      each later stage of a multi-stage integrator), and from them each
 *      body's free motion over the step;
 *   2. world contacts, when enabled: broadphase, narrowphase, solver, which
 *      change those motions, leaving out the islands that sleep
 *      (scene_set_sleeping);
 *   3. integrate: move every body by its motion;
 *   4. reap the bodies marked removed and their force creators (below);
 *   5. the step's record (contacts, collisions) is published for reading.
 *
 * Removal contract: body_remove (or scene_remove_body) only marks a body. The
 * body stays in the scene, counted by scene_bodies and returned by
 * scene_get_body, until the end of the next scene_tick, which frees it (and
 * its info), keeps the order of the other bodies, and in the same tick drops
 * every force creator whose bodies list holds a removed body, freeing its aux
 * with its freer. A dropped force creator is never called again. A body
 * marked during a tick (by a collision handler or a force creator) is freed
 * at the end of that same tick; force creators that depend on it still run
 * in that tick (stage 1 comes before stage 4), world contacts leave it out.
 *
 * Ownership: the scene owns its bodies (scene_add_body hands one over) and the
 * aux of each force creator that was given a freer.
 */

#include <stdbool.h>
#include <stddef.h>
#include "body.h"
#include "contact.h"
#include "list.h"
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

typedef struct scene scene_t;

/* A force creator: called once per tick with its aux (once per stage with
 * a multi-stage integrator, see integrator_t); it adds forces and impulses
 * to bodies. */
typedef void (*force_creator_t)(void *aux);

/* A new empty scene: no gravity, world contacts off, seed integrator. */
scene_t *scene_init(void);

/* Frees the scene, its bodies, and the aux of every force creator that has a
 * freer. Not from inside scene_tick or scene_free of the same scene (a
 * force creator, handler or freer): the program stops, saying to free it
 * after scene_tick returns. */
void scene_free(scene_t *scene);

/* The number of bodies, including those marked removed but not yet reaped. */
size_t scene_bodies(scene_t *scene);

/* The body at index (0 <= index < scene_bodies), in the order added. */
body_t *scene_get_body(scene_t *scene, size_t index);

/* Adds a body; the scene now owns it. A body belongs to one scene, once:
 * adding it again, here or to another scene, is refused, and so is adding a
 * body that a force creator of another scene names (below). */
void scene_add_body(scene_t *scene, body_t *body);

/* Deprecated: use body_remove. Marks the body at index for removal. */
void scene_remove_body(scene_t *scene, size_t index);

/* Deprecated: use scene_add_bodies_force_creator. A force creator that
 * depends on no body (it is never dropped by removal). */
void scene_add_force_creator(scene_t *scene, force_creator_t forcer, void *aux,
                             free_func_t freer);

/*
 * Adds a force creator that depends on `bodies` (the scene takes the list; the
 * list never frees the bodies in it, whatever freer it was made with). When
 * any of them is removed, the force creator is dropped and freer(aux) is
 * called (freer may be NULL).
 *
 * Every body must be this scene's: a body of another scene is refused
 * ("bodies[1] belongs to another scene"; the create_* functions of forces.h
 * say "body2 belongs to another scene"), since that scene would free it
 * while this one's force creator still reads it. A body in no scene yet is
 * allowed and becomes this scene's: add it here (adding it to another scene
 * is refused) or keep it alive yourself; scene_free lets it go again.
 */
void scene_add_bodies_force_creator(scene_t *scene, force_creator_t forcer, void *aux,
                                    list_t *bodies, free_func_t freer);

/* Advances the scene by dt seconds (finite, >= 0): the stages listed above.
 * dt = 0 runs no force creator, no world contact and no integration: bodies
 * keep their poses, velocities and accumulated forces and impulses; it only
 * reaps the bodies marked removed (stage 4) and clears the record. Negative,
 * NaN or infinite dt stops the program ("dt must be finite and >= 0").
 *
 * A step whose result does not fit a double stops the program rather than
 * leave NaN or infinity in the scene, with a message naming scene_tick, the
 * stage, the body or force and the likely cause:
 *   - stage 1: a spring, Newtonian gravity or drag of forces.h whose force is
 *     not finite ("force stage: spring between body 0 and body 1 (k = ...):
 *     force is not finite (stretch ...); likely cause: ...");
 *   - stage 3: a body whose position, angle, velocity or angular velocity is
 *     not finite after integrating ("integrate stage: body 1 (centroid (2, 0)
 *     before the step): position is not finite after integrating with dt =
 *     10 s; likely cause: dt is too large for its velocity ..."), with the
 *     scene's stiffest spring and its stability limit when it has springs.
 * Bodies are named by their index (scene_get_body). The usual cause is a
 * spring too stiff for dt: the seed and explicit Euler integrators add energy
 * to every spring at every step, symplectic Euler is stable for
 * dt < 2 sqrt(m / k) (m the reduced mass of the spring's bodies), implicit
 * Euler at every dt; the messages name that way out.
 *
 * Calling back from inside the tick (a force creator, collision handler or
 * freer it runs): scene_tick and scene_free of the same scene, and the
 * settings the step runs with (scene_set_contacts_enabled, _integrator,
 * _sleeping, _solver_iterations, _workers), stop the program, saying to
 * call them after scene_tick returns. scene_set_gravity is allowed and acts
 * from the next step; adding bodies and force creators and removing bodies
 * are allowed as described above. Other scenes may be ticked or freed.
 */
void scene_tick(scene_t *scene, double dt);

/* Additions beyond the seed API. */

/* Uniform gravitational acceleration (m/s^2) for every body of finite mass,
 * applied by the integrator; default (0, 0). Cheaper than a force creator per
 * body and known exactly to the contact solver. A value different from the
 * current one wakes every sleeping body of finite mass (and its island). */
void scene_set_gravity(scene_t *scene, vector_t gravity);
vector_t scene_get_gravity(scene_t *scene);

/*
 * How scene_tick advances bodies; docs/accuracy.md measures each one's
 * error against its cost. For x'' = a(x, v) at step h, with omega the
 * highest frequency of a spring (sqrt(k / m)):
 *   SEED              v' = v + h a, x' = x + h (v + v') / 2: body_tick's
 *                     scheme, the default. Order 1, exact for constant
 *                     forces (gravity, projectiles); unstable with springs:
 *                     energy grows by 1 + (omega h)^2 / 2 every step.
 *   EXPLICIT_EULER    v' = v + h a, x' = x + h v. Order 1; energy grows by
 *                     1 + (omega h)^2 every step.
 *   SYMPLECTIC_EULER  v' = v + h a, x' = x + h v'. Order 1, symplectic:
 *                     energy bounded and orbits closed for omega h < 2.
 *   VELOCITY_VERLET   half kick, drift, half kick. Order 2, symplectic,
 *                     stable for omega h < 2; forces evaluated once a step
 *                     (twice, see below).
 *   RK4               classical Runge-Kutta. Order 4, slowly damps
 *                     oscillations and orbits, stable for omega h < 2.83;
 *                     forces evaluated four times a step.
 *   SYMPLECTIC4       Yoshida's composition of three Verlet steps. Order 4,
 *                     symplectic, stable for omega h < 1.57; forces
 *                     evaluated three times a step (four, see below).
 *   IMPLICIT_EULER    linearly implicit (backward) Euler: v' = v + h a(x',
 *                     v'), x' = x + h v', with the springs of create_spring
 *                     and the drag of create_drag taken at the end of the
 *                     step (their Jacobians, exact for these linear forces,
 *                     solved over the bodies they join); every other force
 *                     (force creators of your own, Newtonian gravity,
 *                     gravity, impulses) acts as under SYMPLECTIC_EULER,
 *                     which a scene without those springs and drag follows
 *                     bit for bit. Order 1; forces evaluated once a step.
 *                     Stable on those springs and drag at every h: it damps
 *                     them, the energy of an undamped spring falling by
 *                     1 / (1 + (omega h)^2) every step (its amplitude by the
 *                     square root), drag's velocity by 1 / (1 + gamma h / m).
 *                     Explicit for the rest: a force of your own that acts
 *                     as a spring keeps symplectic Euler's limit (omega h <
 *                     2).
 * VELOCITY_VERLET and SYMPLECTIC4 start a step from the forces of the last
 * step's last evaluation, which was at the pose the step ended at, when
 * that gives the same bits: world contacts off, every force creator a
 * spring or Newtonian gravity of forces.h, and no body added, removed or
 * moved, no creator added or dropped and no other force or torque set on a
 * body than the last step's. Otherwise they evaluate once more a step
 * (scene_stats_t counts the evaluations).
 * Pick SYMPLECTIC_EULER or VELOCITY_VERLET for springs and orbits; the
 * fourth-order schemes when accuracy matters more than cost; IMPLICIT_EULER
 * when a spring or drag is too stiff for the step (it loses energy instead
 * of blowing up).
 *
 * The multi-stage schemes (VELOCITY_VERLET, RK4, SYMPLECTIC4) call the force
 * creators once per stage, with the bodies moved to the stage's trial pose
 * and velocities (scene_get_stage tells which call it is). The first call,
 * stage 0, is at the start of the step and is the only one at which
 * impulses count, bodies may be added, and the collision creators of
 * forces.h run (collisions are events of the step, not forces). A force
 * set on a body between ticks acts at every stage.
 *
 * With world contacts, the contact solver runs once per step on the
 * scheme's free motion (its velocities and displacement without contacts),
 * and contacts act as a constant force over the step would under the
 * scheme: a velocity change dv from contacts moves the body by dt dv / 2
 * (SEED and the multi-stage schemes), dt dv (SYMPLECTIC_EULER,
 * IMPLICIT_EULER) or not until the next step (EXPLICIT_EULER). Under
 * IMPLICIT_EULER a contact meets a body with the mass its springs and drag
 * add to it within the step, and its impulse passes along the springs, so
 * a surface carries the whole load of the springs that press a body on it
 * (and friction sees it). With VELOCITY_VERLET, RK4 and SYMPLECTIC4 a stiff
 * spring that presses a body into a surface is evaluated at trial poses
 * inside it: the body rests millimetres deep with part of the load, or goes
 * through (docs/stability.md). Impacts are timed within the step
 * under every scheme, so a bounce is exact under the schemes that follow
 * gravity exactly (all but the Euler ones).
 */
typedef enum {
    INTEGRATOR_SEED = 0,
    INTEGRATOR_EXPLICIT_EULER,
    INTEGRATOR_SYMPLECTIC_EULER,
    INTEGRATOR_VELOCITY_VERLET,
    INTEGRATOR_RK4,
    INTEGRATOR_SYMPLECTIC4,
    INTEGRATOR_IMPLICIT_EULER,
} integrator_t;

/* The number of integrators; every value below it is one. */
#define INTEGRATOR_COUNT 7

/* The integrator's name as the docs write it ("seed", "explicit Euler",
 * "symplectic Euler", "velocity Verlet", "RK4", "symplectic4", "implicit
 * Euler"). */
const char *integrator_get_name(integrator_t integrator);

/* The stability limit of omega h on an undamped spring of create_spring,
 * omega = sqrt(k / m) (2 for symplectic Euler); 0 for a scheme that adds
 * energy at every h, INFINITY for one stable at every h (implicit Euler). */
double integrator_get_stability_limit(integrator_t integrator);

/* The stability limit of gamma h / m on a body under create_drag: 2 for the
 * one-stage explicit schemes and velocity Verlet, 2.785 for RK4, 1.372 for
 * symplectic4 (its negative middle step turns drag into a push), INFINITY
 * for implicit Euler. Past it the body's speed grows every step. */
double integrator_get_drag_limit(integrator_t integrator);

void scene_set_integrator(scene_t *scene, integrator_t integrator);
integrator_t scene_get_integrator(scene_t *scene);

/* Inside a force creator: which call of the tick this is, 0 at the start of
 * the step, 1 .. integrator stages - 1 at the later stages of a multi-stage
 * integrator; 0 outside a tick. A creator with effects beyond forces (one
 * that adds impulses or bodies, removes bodies or counts events) acts at
 * stage 0 only. */
int scene_get_stage(const scene_t *scene);

/*
 * World contacts: when enabled (default off), every pair of bodies that the
 * collision filters allow (body_set_collision_filter) and of which at least
 * one has finite mass collides: rotation, friction (Coulomb, per body, mixed
 * by geometric mean), restitution (per body elasticity, mixed by max),
 * resting contact and stacking. Seed collision force creators keep working
 * alongside. On a pair that world contacts resolve, a collision handler
 * (create_collision) runs when the world's contact of the pair starts
 * touching, one tick after the step in which it did (forces.h); a handler
 * that itself resolves the collision (create_physics_collision) needs the
 * pair kept out of world contacts with filters, or it is resolved twice.
 */
void scene_set_contacts_enabled(scene_t *scene, bool enabled);
bool scene_get_contacts_enabled(scene_t *scene);

/*
 * Sleeping (default on; it acts only while world contacts are on): an
 * island of touching bodies whose every body has been slow for 0.5 s, and
 * that rests on a body of infinite mass (or feels no force and no gravity),
 * is taken out of the step. Slow: over each half second the body moved
 * (counting its rim's turn) under 0.01 m/s, or, when gravity or a force
 * pulls it, under 0.05 m/s, with velocities within that plus one step of
 * its pull (all less for bodies under half a metre across). Out of the
 * step means no integration, no contacts, no solving, its velocities 0
 * (body_is_sleeping). It wakes
 * when a moving body comes within a step of it, when a pose, velocity,
 * material, filter, nonzero force, torque or impulse is set on one of its
 * bodies, when one of them is removed, and when gravity changes. A body
 * that changes (pose, velocity, inertia, material or filter set, removed,
 * or added to the scene; static bodies too) wakes, at the start of the
 * next scene_tick, after its force creators, the sleeping islands whose
 * boxes overlap its box before or after the change (docs/api.md,
 * "Sleeping"): a floor taken away drops what slept on it. A sleeping
 * pair's contacts are not in the record, and
 * its collision handler neither fires nor re-arms while it sleeps.
 * Switching sleeping (or world contacts) off wakes every body.
 */
void scene_set_sleeping(scene_t *scene, bool enabled);
bool scene_get_sleeping(scene_t *scene);

/* Contact solver iterations per step: velocity (default 8) and position
 * (default 4); each in [1, 1000]. More iterations: stiffer stacks, slower
 * steps (a 40-row pyramid sinks 0.12 m in 10 s with 3 position iterations,
 * 0.09 m with 4). */
void scene_set_solver_iterations(scene_t *scene, size_t velocity_iterations,
                                 size_t position_iterations);
void scene_get_solver_iterations(const scene_t *scene, size_t *velocity_iterations,
                                 size_t *position_iterations);

/* Warm starting (default on): each contact starts the step's solve from
 * the impulses its same features had at the last step (a point whose
 * feature is new, from the point of last step's that no feature kept, the
 * nearest within a tenth of the smaller body's radius, as the same impulse
 * along this step's normal; docs/design.md, Warm starting), so stacks hold
 * with few iterations. Off, every contact starts from zero impulse (stacks
 * sag and jitter more at the same iterations). */
void scene_set_warm_starting(scene_t *scene, bool enabled);
bool scene_get_warm_starting(const scene_t *scene);

/* The restitution threshold (m/s, default 1, in [0, 100]): contacts
 * approaching slower than this do not bounce, whatever their elasticity,
 * so a resting body does not bounce on the speed gravity gives it in one
 * step; an approach faster than it is also timed as an impact within the
 * step. An elastic pair that nothing accelerates (no gravity, no force)
 * bounces at any speed above 1 mm/s whatever this is (docs/api.md). */
void scene_set_restitution_threshold(scene_t *scene, double threshold);
double scene_get_restitution_threshold(const scene_t *scene);

/* Sleep tolerances (scene_set_sleeping): a body counts as slow while its
 * speed plus its rim's speed from turning (radius |angular velocity|) stays
 * under `linear` (m/s, default 0.01, in (0, 10]; five times that for a body
 * that gravity or a force presses on others, less for bodies under half a
 * metre across, docs/api.md "Sleeping") and while |angular velocity| stays
 * under `angular` (rad/s, default INFINITY: no bound of its own, the turn
 * counting through the rim's speed; else in (0, 100]). A NULL pointer skips
 * its part. */
void scene_set_sleep_tolerance(scene_t *scene, double linear, double angular);
void scene_get_sleep_tolerance(const scene_t *scene, double *linear, double *angular);

/* How long (s, default 0.5, in (0, 1000]) every body of an island must have
 * been slow before the island sleeps. */
void scene_set_sleep_time(scene_t *scene, double seconds);
double scene_get_sleep_time(const scene_t *scene);

/* Restores the solver's settings to their defaults: iterations (8, 4),
 * warm starting on, restitution threshold 1 m/s, sleep tolerances (0.01
 * m/s, INFINITY) and sleep time 0.5 s. Not gravity, the integrator,
 * sleeping on/off, world contacts or workers. */
void scene_reset_solver_settings(scene_t *scene);

/*
 * Workers (default 1): the threads a step of world contacts runs on, the
 * calling thread and workers - 1 of the scene's own, in [1,
 * SCENE_MAX_WORKERS]; anything else stops the program ("workers must be in
 * [1, 64] (got 0)"). Spread over them: the broadphase's filling, sorting
 * and search of its grid cells, the narrowphase, preparing the contacts into
 * colour batches, each colour of batches (the colours one after another),
 * the loops over bodies that load the solver and take its results, the
 * free motions of the explicit one-stage integrators (stage 1, after the force
 * creators) and integration (stage 3). The rest runs on the calling thread as with one
 * worker: implicit Euler's solve, the force creators, the collision handlers and everything else a
 * scene calls back, the colouring, the contacts no colour could take, the
 * restitution pass, shock propagation (but for its levels of 64 bodies or
 * more) and sleeping. A body whose motion is
 * not finite stops the program with the message one worker gives.
 * Results are bit-identical for any worker count: every number is computed
 * by the same operations in the same order, whichever thread computes it.
 * The threads start at the first step that needs them (none while world
 * contacts are off or with 1 worker), wait between steps without using the
 * processor for long, and stop when the count changes or the scene is
 * freed; a step allocates nothing for them. It may be changed between
 * ticks at any time. More workers than the machine has cores only slows a
 * step down.
 */
#define SCENE_MAX_WORKERS 64
void scene_set_workers(scene_t *scene, size_t workers);
size_t scene_get_workers(const scene_t *scene);

/*
 * The step's record: every contact touching or about to touch at the last
 * scene_tick (world contacts with their impulses) and every seed collision
 * whose handler ran in it, except those naming a body freed at the end of
 * that tick (so a destructive collision leaves no entry). Read-only; valid
 * until the next scene_tick or until the scene is freed.
 */
size_t scene_contact_count(scene_t *scene);
const contact_t *scene_get_contact(scene_t *scene, size_t index);

/* Counters of the last scene_tick, for tests and the sandbox's HUD. */
typedef struct {
    size_t broadphase_tests;   /* bounding-box comparisons the broadphase made (the
                                  world's and the collision groups', forces.h; a
                                  step that keeps last step's pairs, resting
                                  bodies, makes one per kept pair) */
    size_t broadphase_pairs;   /* pairs whose bounding boxes overlapped */
    size_t contacts;           /* manifolds with at least one point, speculative
                                  ones included (see contact.h) */
    size_t contact_points;     /* points over all manifolds */
    size_t removed_bodies;     /* bodies reaped at the end of the tick */
    /* Passes over the force creators (one per stage of the integrator; none
     * without creators, and one fewer under VELOCITY_VERLET and SYMPLECTIC4
     * when the step reused the last one's, see integrator_t). */
    size_t force_evaluations;
} scene_stats_t;

scene_stats_t scene_get_stats(scene_t *scene);

/*
 * The step's stages, in the order scene_tick runs them (docs/design.md):
 *   FORCES       the force creators and each body's free motion (stage 1);
 *   BROADPHASE   loading the bodies' rows and boxes, and the pairs whose
 *                boxes overlap;
 *   NARROWPHASE  the pairs' contact manifolds and impacts timed within the
 *                step;
 *   PREPARE      the contacts made ready for the iterations: coloured and
 *                sorted, then lever arms, effective masses, targets and
 *                impacts within the step, four to a batch;
 *   SOLVER       restitution, warm starting and the velocity iterations,
 *                handing results back;
 *   SHOCK        shock propagation (before the last velocity iteration),
 *                with the levels of the lift;
 *   POSITION     advancing the bodies, relaxing, the lift and the position
 *                iterations;
 *   INTEGRATE    moving every body not asleep by its motion (stage 3);
 *   SLEEP        waking islands a change reached, sleep timers, islands
 *                put to sleep;
 *   REMOVAL      reaping the bodies marked removed (stage 4).
 * BROADPHASE to POSITION run only with world contacts and bodies not
 * asleep (static bodies never sleep: they keep these stages running), SLEEP
 * only with world contacts and sleeping on, REMOVAL only when some body was
 * marked removed, FORCES only when there are force creators or something
 * (world contacts, a multi-stage or implicit integrator) needs the free
 * motions first.
 */
typedef enum {
    SCENE_STAGE_FORCES,
    SCENE_STAGE_BROADPHASE,
    SCENE_STAGE_NARROWPHASE,
    SCENE_STAGE_PREPARE,
    SCENE_STAGE_SOLVER,
    SCENE_STAGE_SHOCK,
    SCENE_STAGE_POSITION,
    SCENE_STAGE_INTEGRATE,
    SCENE_STAGE_SLEEP,
    SCENE_STAGE_REMOVAL,
    SCENE_STAGE_COUNT
} scene_stage_t;

/* The stage's name in lower case ("forces", "broadphase", ...); stops the
 * program for a value outside [0, SCENE_STAGE_COUNT). */
const char *scene_stage_name(scene_stage_t stage);

/* The last scene_tick by stage: ran says whether the stage ran at all;
 * seconds is the wall time (CLOCK_MONOTONIC, on the calling thread,
 * whatever the workers) each stage took when profiling is on, 0 otherwise
 * and for a stage that did not run; all zero before the first tick. The counts are of the scene as it is when called:
 * islands, the groups of bodies of finite mass joined by touching world
 * contacts (a sleeping island counts as one; 0 while world contacts are
 * off); awake_bodies, those of finite mass or inertia not asleep;
 * sleeping_bodies, those asleep; static_bodies, those of infinite mass and
 * inertia. Bodies marked removed are not counted. Counting islands costs
 * O(bodies + contacts log bodies) and allocates; the rest is free. */
typedef struct {
    double seconds[SCENE_STAGE_COUNT];
    bool ran[SCENE_STAGE_COUNT];
    size_t islands, awake_bodies, sleeping_bodies, static_bodies;
} scene_profile_t;

scene_profile_t scene_get_profile(const scene_t *scene);

/* Profiling (default off): time each stage of every tick for
 * scene_get_profile. It reads the clock once per stage that runs, about
 * 40 ns each: a two-body orbit's step takes 2.4 times as long with it on,
 * a pile of 1000 bodies 0.01% longer. Results are the same either way. */
void scene_set_profiling(scene_t *scene, bool enabled);
bool scene_get_profiling(const scene_t *scene);

/* For a body inspector. The body must be the scene's (stops otherwise).
 * scene_body_contact_count: the entries of the step's record that name the
 * body and touch (contact_t.touching), world contacts and seed collisions
 * alike (0 for a sleeping body, whose contacts are not in the record);
 * O(contacts). scene_body_island: the island of the body (as
 * scene_profile_t counts them) named by the smallest scene index among its
 * bodies, or SIZE_MAX for none (a body of infinite mass, one marked
 * removed, or world contacts off); O(bodies + contacts log bodies), and
 * allocates. */
size_t scene_body_contact_count(scene_t *scene, body_t *body);
size_t scene_body_island(scene_t *scene, body_t *body);

JOSTLE_API_END

#endif // #ifndef SCENE_H
