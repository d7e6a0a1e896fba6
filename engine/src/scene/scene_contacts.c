/* scene_set_contacts_enabled: the one place that links the world contact
 * pipeline into a program (scene_private.h says why). */
#include "base/check.h"
#include "scene/scene_private.h"
#include "world/world.h"

static const world_ops_t WORLD_OPS = {
    world_free,         world_set_iterations, world_set_workers,   world_for_bodies,
    world_wake_changed, world_step,           world_contact_count, world_get_contact,
    world_pair_collides, world_pair_contact,  world_get_memory,    world_restore_memory,
    world_forget_removed, world_get_sleep_phase, world_set_sleep_phase,
    world_get_solver_steps, world_set_solver_steps, world_index_sleepers,
    world_get_step_lengths, world_set_step_lengths,
};

void scene_set_contacts_enabled(scene_t *scene, bool enabled) {
    REQUIRE_NOT_NULL(scene);
    scene_require_idle(scene, __func__, "change the setting between ticks");
    if (enabled == scene_get_contacts_enabled(scene)) return;
    if (!enabled) {
        scene_install_world(scene, NULL, NULL);
        return;
    }
    size_t velocity_iterations, position_iterations;
    scene_get_iterations(scene, &velocity_iterations, &position_iterations);
    world_t *world = world_init(velocity_iterations, position_iterations);
    world_set_workers(world, scene_get_workers(scene));
    scene_install_world(scene, world, &WORLD_OPS);
}
