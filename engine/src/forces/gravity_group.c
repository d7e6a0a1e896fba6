/* create_newtonian_gravity_group: Newtonian gravity between every two
 * bodies of a group, one force creator over its members. */
#include <math.h>
#include <stdint.h>
#include "dynamics/body_private.h"
#include "dynamics/body_set.h"
#include "base/check.h"
#include "jostle/forces.h"
#include "forces/forces_private.h"
#include "base/memory.h"
#include "scene/scene_private.h"

struct gravity_group {
    scene_t *scene;
    double G;
    body_set_t members;
};

/* The pairs in the order of create_newtonian_gravity called for (i, j),
 * i < j, i-major: the same forces summed in the same order. */
static void gravity_group_force(void *data) {
    gravity_group_t *group = data;
    const body_set_member_t *members = group->members.members;
    size_t count = group->members.count;
    for (size_t i = 0; i < count; i++) {
        for (size_t j = i + 1; j < count; j++) {
            forces_gravity_between(group->scene, group->G, members[i].body, members[j].body);
        }
    }
}

static void gravity_group_forget(void *data) {
    gravity_group_t *group = data;
    body_set_forget_removed(&group->members, NULL);
}

static void gravity_group_free(void *data) {
    gravity_group_t *group = data;
    body_set_free(&group->members);
    memory_free(group);
}

gravity_group_t *create_newtonian_gravity_group(scene_t *scene, double G, list_t *bodies) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(bodies);
    REQUIRE(isfinite(G) && G >= 0.0, "G must be finite and >= 0 (got %g)", G);
    gravity_group_t *group = memory_calloc(1, sizeof(gravity_group_t));
    group->scene = scene;
    group->G = G;
    for (size_t i = 0; i < list_size(bodies); i++) {
        body_t *body = list_get(bodies, i);
        scene_require_added(scene, body, __func__, "bodies", i);
        body_set_add(&group->members, body, 1);
    }
    scene_creator_t creator = {.forcer = gravity_group_force, .aux = group,
                               .freer = gravity_group_free, .forget = gravity_group_forget};
    scene_add_creator(scene, &creator);
    return group;
}

void gravity_group_add(gravity_group_t *group, body_t *body) {
    REQUIRE_NOT_NULL(group);
    REQUIRE_NOT_NULL(body);
    scene_require_added(group->scene, body, __func__, "body", SIZE_MAX);
    body_set_add(&group->members, body, 1);
}
