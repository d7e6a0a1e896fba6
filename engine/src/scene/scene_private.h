#ifndef SCENE_PRIVATE_H
#define SCENE_PRIVATE_H

/* What the force creators of forces.c need from the scene beyond scene.h. */

#include "jostle/contact.h"
#include "jostle/scene.h"
#include "jostle/scene_state.h"
#include "base/workers.h"
#include "dynamics/jacobian.h"
#include "world/world.h"
#include "solver/joint_list.h"

/* Stops the program, naming `function`, when it was called back from
 * inside scene_tick or scene_free of this scene, which are still using it;
 * `instead` says what to do. */
void scene_require_idle(const scene_t *scene, const char *function, const char *instead);

/* A force creator with what scene.h's cannot say. An event of the step (a
 * collision of forces.h) is called at the first stage of a multi-stage
 * integrator only. forget, when not NULL, is called with aux in every reap
 * before the removed bodies are freed: a creator over a group of bodies
 * lets go of its removed ones there instead of being dropped (its bodies
 * list is then NULL). */
typedef struct {
    force_creator_t forcer;
    void *aux;
    free_func_t freer;
    list_t *bodies; /* the bodies it depends on; NULL for none */
    bool event;
    void (*forget)(void *aux);
    /* A spring's: the highest frequency sqrt(k / m) it imposes (rad/s; 0
     * when it imposes none), and the words that name it and its stability
     * at the tick's dt, for the message of a tick that overflows. NULL for
     * other force creators. */
    double (*stiffness)(const void *aux);
    void (*explain)(const void *aux, char *message, size_t size);
    /* A force that knows its derivatives (create_spring, _with_length,
     * create_drag) writes them at the bodies' poses now, for implicit
     * Euler (jacobian.h); NULL, or false returned, and that scheme takes
     * the force explicitly. */
    bool (*jacobian)(const void *aux, force_jacobian_t *jacobian);
    /* Its forces depend on its bodies' centroids and masses alone, and it
     * adds nothing else (no impulse, torque or event): a multi-stage
     * integrator may then reuse the forces it found at the end of a step
     * (integrator_begin). */
    bool positional;
} scene_creator_t;

void scene_add_creator(scene_t *scene, const scene_creator_t *creator);

/* Stops the program, naming `function` and the body (`name`, or
 * name[index] when index is not SIZE_MAX), unless the body is in the
 * scene: a group orders its members by when they joined and owns none. */
void scene_require_added(const scene_t *scene, const body_t *body, const char *function,
                         const char *name, size_t index);

/* Adds the number of bounding-box comparisons a collision group made to
 * the tick's scene_stats_t.broadphase_tests. */
void scene_count_broadphase_tests(scene_t *scene, size_t tests);

/* The world contacts of the last step (none while contacts are off), as
 * scene_get_contact gives them: between ticks and in stage 1. */
size_t scene_world_contact_count(const scene_t *scene);
contact_t scene_world_get_contact(const scene_t *scene, size_t index);

/* Appends an entry to the record of the tick in progress. */
void scene_record_contact(scene_t *scene, const contact_t *entry);

/* Lets a force creator of `scene` name `body`: stops the program (naming
 * `function` and the parameter `name`) when the body belongs to another
 * scene; a body in no scene yet becomes this scene's, to be added here. */
void scene_claim_body(scene_t *scene, body_t *body, const char *name, const char *function);

/*
 * The world contact pipeline as the scene calls it. scene_contacts.c
 * installs it when contacts are enabled, so a program that never enables
 * them links none of the broadphase, narrowphase, colouring or solver
 * (make check asserts it with nm).
 */
typedef struct {
    void (*free)(world_t *world);
    void (*set_iterations)(world_t *world, size_t velocity_iterations,
                           size_t position_iterations);
    void (*set_workers)(world_t *world, size_t workers);
    void (*for_bodies)(world_t *world, size_t count, workers_fn_t fn, void *context);
    void (*wake_changed)(world_t *world, body_t **bodies, size_t count, double dt,
                         vector_t gravity);
    void (*step)(world_t *world, body_t **bodies, integrator_motion_t *motions, size_t count,
                 const world_step_t *step, scene_stats_t *stats);
    size_t (*contact_count)(const world_t *world);
    contact_t (*get_contact)(const world_t *world, size_t index);
    bool (*pair_collides)(const body_t *body1, const body_t *body2);
    bool (*pair_contact)(const world_t *world, body_t *body1, body_t *body2, contact_t *contact);
    /* The state a continuation needs (scene_state.c). */
    void (*get_memory)(const world_t *world, size_t index, scene_contact_memory_t *memory);
    void (*restore_memory)(world_t *world, const scene_contact_memory_t *memories, size_t count);
    void (*forget_removed)(world_t *world);
    unsigned (*get_sleep_phase)(const world_t *world);
    void (*set_sleep_phase)(world_t *world, unsigned phase);
    uint64_t (*get_solver_steps)(const world_t *world);
    void (*set_solver_steps)(world_t *world, uint64_t steps);
    void (*index_sleepers)(world_t *world, body_t **bodies, size_t count);
    void (*get_step_lengths)(const world_t *world, double *last, double *before);
    void (*set_step_lengths)(world_t *world, double last, double before);
} world_ops_t;

/* Hands the scene a world (NULL with ops NULL: contacts off), freeing the
 * one it had. */
void scene_install_world(scene_t *scene, world_t *world, const world_ops_t *ops);

/* The scene's world and its functions (NULL, with *ops NULL, while
 * contacts are off), and its bodies, scene_bodies of them, in order. */
world_t *scene_world(const scene_t *scene, const world_ops_t **ops);
body_t **scene_body_array(const scene_t *scene);

/* The solver iterations the scene keeps for its world. */
void scene_get_iterations(const scene_t *scene, size_t *velocity_iterations,
                          size_t *position_iterations);

/* Whether world contacts resolve the pair (contacts on and the world's
 * filters allow it), and the pair's contact of the last step (false when
 * it had none): between ticks and in stage 1. */
bool scene_world_resolves(const scene_t *scene, const body_t *body1, const body_t *body2);
bool scene_world_pair_contact(const scene_t *scene, body_t *body1, body_t *body2,
                              contact_t *contact);

/* For the message of a tick that fails: the body's index in the scene
 * (SIZE_MAX when it is not in it) and the dt of the tick in progress. */
size_t scene_body_index(const scene_t *scene, const body_t *body);
double scene_step_dt(const scene_t *scene);

/* The queries' state (scene_query.c): made by init at the first query and
 * freed by freer with the scene, so that a program that asks none links no
 * grid (the scene's world pipeline is kept out the same way). */
void *scene_query_state(scene_t *scene, void *(*init)(void), void (*freer)(void *queries));

/* A number that changes whenever the scene's bodies may have moved or been
 * added or removed: a tick, a stage of one, a body added, a pose set on one
 * of its bodies (body_private.h's moves). */
uint64_t scene_moves(const scene_t *scene);

/* The scene's joints (joint.c creates and destroys them). */
joint_list_t *scene_joint_list(scene_t *scene);

/* The last tick's stage times and ran flags (the counts left 0). */
scene_profile_t scene_stage_times(const scene_t *scene);

#endif // #ifndef SCENE_PRIVATE_H
