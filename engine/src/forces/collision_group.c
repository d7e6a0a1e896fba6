/* create_collision_group: create_collision for every pair of a body of one
 * set and a body of the other, as one force creator over its members. The
 * pairs that may start colliding come from a broadphase grid over the
 * members' bounding boxes (the seed's rule needs an overlap) and from the
 * world's touching contacts; the pairs already colliding are kept with
 * their state. A step costs the members and those pairs, not every pair. */
#include "dynamics/body_private.h"
#include "dynamics/body_set.h"
#include "collision/broadphase.h"
#include "base/check.h"
#include "forces/collision_event.h"
#include "jostle/forces.h"
#include "base/memory.h"
#include "scene/scene_private.h"

enum { FIRST = 1, SECOND = 2 };

/* A pair by the members' places: first is the handler's body1. */
typedef struct {
    uint32_t first, second;
    /* Whether the pair was colliding at the last read (state is its). */
    bool known;
    collision_state_t state;
} group_pair_t;

struct collision_group {
    collision_rule_t rule;
    body_set_t members; /* sides FIRST, SECOND or both */
    broadphase_t *broadphase;
    broadphase_proxy_t *proxies;
    size_t proxy_capacity;
    /* The pairs colliding after the last read, in handler order. */
    group_pair_t *pairs;
    size_t pair_count, pair_capacity;
    /* This read's pairs to look at, before sorting. */
    group_pair_t *candidates;
    size_t candidate_count, candidate_capacity;
    size_t *remap;
    size_t remap_capacity;
};

/* The handler's order for the pair of members p and q: a body of the first
 * set as body1; when either order fits, the earlier member first. False
 * when the two are not a pair of the group (both of one set only). */
static bool orient(const body_set_t *members, size_t p, size_t q, group_pair_t *pair) {
    uint8_t sp = members->members[p].sides, sq = members->members[q].sides;
    bool forward = (sp & FIRST) && (sq & SECOND);
    bool backward = (sq & FIRST) && (sp & SECOND);
    if (!forward && !backward) return false;
    bool p_first = forward && (!backward || p < q);
    *pair = (group_pair_t){(uint32_t)(p_first ? p : q), (uint32_t)(p_first ? q : p), false, {0}};
    return true;
}

static void add_candidate(collision_group_t *group, group_pair_t pair) {
    memory_reserve((void **)&group->candidates, &group->candidate_capacity,
                   group->candidate_count + 1, sizeof(group_pair_t));
    group->candidates[group->candidate_count++] = pair;
}

/* The pairs whose bounding boxes overlap: the only ones the seed's rule can
 * find overlapping. The filters keep two members of one set only apart. */
static void add_overlapping(collision_group_t *group) {
    size_t count = group->members.count;
    if (count < 2) return;
    memory_reserve((void **)&group->proxies, &group->proxy_capacity, count,
                   sizeof(broadphase_proxy_t));
    for (size_t i = 0; i < count; i++) {
        body_t *body = group->members.members[i].body;
        uint8_t sides = group->members.members[i].sides;
        body_update_world(body);
        /* A body of one set meets the other set: mask the other side. */
        uint32_t mask = (uint32_t)(((sides & FIRST) ? SECOND : 0) | ((sides & SECOND) ? FIRST : 0));
        group->proxies[i] = (broadphase_proxy_t){body->bounds, false, sides, mask, 0};
    }
    const broadphase_pair_t *pairs;
    size_t tests = 0;
    size_t found = broadphase_find_pairs(group->broadphase, group->proxies, count, &pairs, &tests);
    scene_count_broadphase_tests(group->rule.scene, tests);
    for (size_t k = 0; k < found; k++) {
        group_pair_t pair;
        if (orient(&group->members, pairs[k].a, pairs[k].b, &pair)) add_candidate(group, pair);
    }
}

/* The pairs whose world contact touched in the last step. */
static void add_touching(collision_group_t *group) {
    size_t contacts = scene_world_contact_count(group->rule.scene);
    for (size_t k = 0; k < contacts; k++) {
        contact_t contact = scene_world_get_contact(group->rule.scene, k);
        if (!contact.touching) continue;
        size_t p = body_set_find(&group->members, contact.body1);
        if (p == SIZE_MAX) continue;
        size_t q = body_set_find(&group->members, contact.body2);
        group_pair_t pair;
        if (q != SIZE_MAX && orient(&group->members, p, q, &pair)) add_candidate(group, pair);
    }
}

/* By body1's place, then body2's; a pair's known entry before the others. */
static bool before(const group_pair_t *a, const group_pair_t *b) {
    if (a->first != b->first) return a->first < b->first;
    if (a->second != b->second) return a->second < b->second;
    return a->known && !b->known;
}

static void sift_down(group_pair_t *pairs, size_t root, size_t count) {
    for (size_t child = 2 * root + 1; child < count; root = child, child = 2 * root + 1) {
        if (child + 1 < count && before(&pairs[child], &pairs[child + 1])) child++;
        if (!before(&pairs[root], &pairs[child])) return;
        group_pair_t swap = pairs[root];
        pairs[root] = pairs[child];
        pairs[child] = swap;
    }
}

/* Heapsort: in place, so a step allocates nothing (qsort may). */
static void sort_pairs(group_pair_t *pairs, size_t count) {
    for (size_t i = count / 2; i-- > 0;) sift_down(pairs, i, count);
    for (size_t end = count; end-- > 1;) {
        group_pair_t swap = pairs[0];
        pairs[0] = pairs[end];
        pairs[end] = swap;
        sift_down(pairs, 0, end);
    }
}

static void collision_group_read(void *data) {
    collision_group_t *group = data;
    group->candidate_count = 0;
    for (size_t i = 0; i < group->pair_count; i++) add_candidate(group, group->pairs[i]);
    add_overlapping(group);
    add_touching(group);
    sort_pairs(group->candidates, group->candidate_count);
    memory_reserve((void **)&group->pairs, &group->pair_capacity, group->candidate_count,
                   sizeof(group_pair_t));
    group->pair_count = 0;
    for (size_t i = 0; i < group->candidate_count; i++) {
        group_pair_t pair = group->candidates[i];
        const group_pair_t *previous = &group->candidates[i - (i > 0)];
        if (i > 0 && pair.first == previous->first && pair.second == previous->second) {
            continue; /* the same pair again, found another way */
        }
        /* Read through the set each time: a handler may add members. */
        body_t *body1 = group->members.members[pair.first].body;
        body_t *body2 = group->members.members[pair.second].body;
        collision_event_read(&group->rule, body1, body2, &pair.state);
        if (!pair.state.colliding) continue;
        pair.known = true;
        group->pairs[group->pair_count++] = pair;
    }
}

/* In the reap: the removed members go, and the pairs they were in; the
 * others' places close up, keeping their order. */
static void collision_group_forget(void *data) {
    collision_group_t *group = data;
    memory_reserve((void **)&group->remap, &group->remap_capacity, group->members.count,
                   sizeof(size_t));
    body_set_forget_removed(&group->members, group->remap);
    size_t kept = 0;
    for (size_t i = 0; i < group->pair_count; i++) {
        group_pair_t pair = group->pairs[i];
        size_t first = group->remap[pair.first], second = group->remap[pair.second];
        if (first == SIZE_MAX || second == SIZE_MAX) continue;
        pair.first = (uint32_t)first;
        pair.second = (uint32_t)second;
        group->pairs[kept++] = pair;
    }
    group->pair_count = kept;
}

static void collision_group_free(void *data) {
    collision_group_t *group = data;
    body_set_free(&group->members);
    broadphase_free(group->broadphase);
    memory_free(group->proxies);
    memory_free(group->pairs);
    memory_free(group->candidates);
    memory_free(group->remap);
    memory_free(group);
}

static void join(collision_group_t *group, list_t *bodies, uint8_t side, const char *function,
                 const char *name) {
    for (size_t i = 0; i < list_size(bodies); i++) {
        body_t *body = list_get(bodies, i);
        scene_require_added(group->rule.scene, body, function, name, i);
        body_set_add(&group->members, body, side);
    }
}

collision_group_t *create_collision_group(scene_t *scene, list_t *bodies1, list_t *bodies2,
                                          collision_handler_t handler, void *aux,
                                          double force_const) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(bodies1);
    REQUIRE_NOT_NULL(bodies2);
    REQUIRE_NOT_NULL(handler);
    collision_group_t *group = memory_calloc(1, sizeof(collision_group_t));
    group->rule = (collision_rule_t){scene, handler, aux, force_const};
    group->broadphase = broadphase_init();
    join(group, bodies1, FIRST, __func__, "bodies1");
    join(group, bodies2, SECOND, __func__, "bodies2");
    scene_creator_t creator = {.forcer = collision_group_read, .aux = group,
                               .freer = collision_group_free, .event = true,
                               .forget = collision_group_forget};
    scene_add_creator(scene, &creator);
    return group;
}

void collision_group_add(collision_group_t *group, body_t *body, bool first, bool second) {
    REQUIRE_NOT_NULL(group);
    REQUIRE_NOT_NULL(body);
    REQUIRE(first || second, "the body must join the first set, the second or both");
    scene_require_added(group->rule.scene, body, __func__, "body", SIZE_MAX);
    body_set_add(&group->members, body, (uint8_t)((first ? FIRST : 0) | (second ? SECOND : 0)));
}
