/* What the step did and how the scene's bodies stand (scene.h): the
 * profile, and a body's contacts and island for an inspector. */
#include <stdint.h>
#include "jostle/scene.h"
#include "base/check.h"
#include "base/memory.h"
#include "dynamics/body_private.h"
#include "scene/scene_private.h"

static const char *const STAGE_NAMES[SCENE_STAGE_COUNT] = {
    "forces", "broadphase", "narrowphase", "prepare", "solver", "shock",
    "position", "integrate", "sleep", "removal",
};

const char *scene_stage_name(scene_stage_t stage) {
    REQUIRE((unsigned)stage < SCENE_STAGE_COUNT, "unknown stage %d", (int)stage);
    return STAGE_NAMES[stage];
}

/* The body's index in the scene, found by its id (the scene keeps its
 * bodies in the order of their ids); SIZE_MAX when it is not there. */
static size_t index_of(body_t **bodies, size_t count, const body_t *body) {
    size_t low = 0, high = count;
    while (low < high) {
        size_t middle = low + (high - low) / 2;
        if (bodies[middle]->id < body->id) {
            low = middle + 1;
        } else {
            high = middle;
        }
    }
    if (low < count && bodies[low] == body) return low;
    for (size_t i = 0; i < count; i++) { /* ids wrapped past 2^32 */
        if (bodies[i] == body) return i;
    }
    return SIZE_MAX;
}

static size_t find_root(size_t *parent, size_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

static void join(size_t *parent, size_t a, size_t b) {
    size_t ra = find_root(parent, a), rb = find_root(parent, b);
    /* The smaller index stays the root: it names the island. */
    if (ra < rb) {
        parent[rb] = ra;
    } else if (rb < ra) {
        parent[ra] = rb;
    }
}

static bool in_island(const body_t *body) {
    return body_is_movable(body) && !body->removed;
}

/* island[i]: the smallest index of body i's island, SIZE_MAX for none;
 * returns the number of islands (0 while world contacts are off). */
static size_t find_islands(const scene_t *scene, size_t *island) {
    const world_ops_t *ops;
    size_t count = scene_bodies((scene_t *)scene);
    body_t **bodies = scene_body_array(scene);
    for (size_t i = 0; i < count; i++) island[i] = SIZE_MAX;
    if (scene_world(scene, &ops) == NULL) return 0;
    for (size_t i = 0; i < count; i++) {
        if (in_island(bodies[i])) island[i] = i;
    }
    size_t contacts = scene_world_contact_count(scene);
    for (size_t k = 0; k < contacts; k++) {
        contact_t c = scene_world_get_contact(scene, k);
        if (!c.touching || !in_island(c.body1) || !in_island(c.body2)) continue;
        size_t a = index_of(bodies, count, c.body1), b = index_of(bodies, count, c.body2);
        if (a != SIZE_MAX && b != SIZE_MAX) join(island, a, b);
    }
    /* A sleeping island's bodies are linked in a circle; its contacts are
     * not among the step's. */
    for (size_t i = 0; i < count; i++) {
        const body_t *next = bodies[i]->sleep_next;
        if (next == NULL || !in_island(bodies[i]) || !in_island(next)) continue;
        size_t j = index_of(bodies, count, next);
        if (j != SIZE_MAX) join(island, i, j);
    }
    size_t islands = 0;
    for (size_t i = 0; i < count; i++) {
        if (island[i] == SIZE_MAX) continue;
        island[i] = find_root(island, i);
        islands += island[i] == i;
    }
    return islands;
}

scene_profile_t scene_get_profile(const scene_t *scene) {
    REQUIRE_NOT_NULL(scene);
    scene_profile_t profile = scene_stage_times(scene);
    size_t count = scene_bodies((scene_t *)scene);
    body_t **bodies = scene_body_array(scene);
    for (size_t i = 0; i < count; i++) {
        const body_t *body = bodies[i];
        if (body->removed) continue;
        if (!body_is_movable(body)) {
            profile.static_bodies++;
        } else if (body->asleep) {
            profile.sleeping_bodies++;
        } else {
            profile.awake_bodies++;
        }
    }
    if (count > 0) {
        size_t *island = memory_alloc(count * sizeof(size_t));
        profile.islands = find_islands(scene, island);
        memory_free(island);
    }
    return profile;
}

size_t scene_body_contact_count(scene_t *scene, body_t *body) {
    REQUIRE_NOT_NULL(scene);
    scene_require_added(scene, body, __func__, "body", SIZE_MAX);
    size_t found = 0, count = scene_contact_count(scene);
    for (size_t i = 0; i < count; i++) {
        const contact_t *c = scene_get_contact(scene, i);
        found += c->touching && (c->body1 == body || c->body2 == body);
    }
    return found;
}

size_t scene_body_island(scene_t *scene, body_t *body) {
    REQUIRE_NOT_NULL(scene);
    scene_require_added(scene, body, __func__, "body", SIZE_MAX);
    size_t count = scene_bodies(scene);
    size_t *island = memory_alloc(count * sizeof(size_t));
    find_islands(scene, island);
    size_t found = island[index_of(scene_body_array(scene), count, body)];
    memory_free(island);
    return found;
}
