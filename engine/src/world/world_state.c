/*
 * The world between steps (world.h): the last step's contacts as the scene
 * reads them, and the state a continuation saves and restores
 * (scene_state.h): the contact memory, the sleep phase, the step lengths.
 */
#include "world/world.h"
#include "world/world_types.h"
#include <math.h>
#include "base/memory.h"

size_t world_contact_count(const world_t *world) {
    return world->contact_count;
}

contact_t world_get_contact(const world_t *world, size_t index) {
    const solver_contact_t *c = &world->contacts[index];
    const contact_source_t *source = &world->sources[index];
    /* A chain's segment is reported as its chain. */
    contact_t entry = {.kind = CONTACT_WORLD,
                       .body1 = body_public(source->body_a),
                       .body2 = body_public(source->body_b),
                       .axis = c->normal, .point_count = (size_t)c->point_count};
    for (int j = 0; j < c->point_count; j++) {
        entry.points[j] = source->points[j];
        entry.separation[j] = c->points[j].separation;
        entry.normal_impulse[j] = c->points[j].normal_impulse + c->points[j].restitution_impulse;
        entry.tangent_impulse[j] =
            c->points[j].tangent_impulse + c->points[j].restitution_tangent_impulse;
        entry.touching |= c->points[j].separation <= 0.0 || entry.normal_impulse[j] > 0.0;
    }
    return entry;
}

void world_get_memory(const world_t *world, size_t index, scene_contact_memory_t *memory) {
    const solver_contact_t *c = &world->contacts[index];
    const contact_source_t *source = &world->sources[index];
    const body_t *b = source->body_b;
    *memory = (scene_contact_memory_t){
        .body_a = source->body_a,
        .body_b = body_public(source->body_b),
        .segment = b->segment != NULL ? b->segment->index : 0,
        .normal = c->normal,
        .point_count = c->point_count,
        .flip = source->features.flip,
        .edge_ends = source->features.edge_ends,
        .feature_count = source->features.point_count,
        .face_normal = source->features.normal,
        .face_point = source->features.face_point,
        .face_lead = source->features.lead,
        .pose = source->pose.position,
        .pose_angle = source->pose.angle,
    };
    for (int j = 0; j < c->point_count; j++) {
        const solver_point_t *p = &c->points[j];
        memory->points[j] = (scene_memory_point_t){
            p->id, source->points[j], p->separation, p->normal_impulse, p->tangent_impulse,
            p->restitution_impulse, p->restitution_tangent_impulse};
    }
    for (int j = 0; j < source->features.point_count; j++) {
        memory->feature_points[j] = source->features.points[j];
        memory->feature_ids[j] = source->features.ids[j];
    }
    if (source->previous == NO_CONTACT) return;
    const solver_contact_t *before = &world->old_contacts[source->previous];
    memory->previous_count = before->point_count;
    for (int j = 0; j < before->point_count; j++) {
        const solver_point_t *p = &before->points[j];
        memory->previous[j] = (scene_memory_previous_t){p->id, p->normal_impulse,
                                                        p->tangent_impulse};
    }
}

/* Writes the pair's contact of the step before last from a memory into
 * old_contacts at `at`, which the next step's swap makes the contacts of
 * the step before its last; returns where, or NO_CONTACT when it had none
 * (world_restore_memory). */
static uint32_t add_remembered_before(world_t *world, size_t at,
                                      const scene_contact_memory_t *memory) {
    if (memory->previous_count == 0) return NO_CONTACT;
    solver_contact_t *before = &world->old_contacts[at];
    *before = (solver_contact_t){.point_count = memory->previous_count};
    for (int j = 0; j < memory->previous_count; j++) {
        const scene_memory_previous_t *from = &memory->previous[j];
        before->points[j].id = from->id;
        before->points[j].normal_impulse = from->normal_impulse;
        before->points[j].tangent_impulse = from->tangent_impulse;
    }
    return (uint32_t)at;
}

/* Writes contact n of the step from a memory (world_restore_memory). */
static void add_remembered(world_t *world, size_t n, const scene_contact_memory_t *memory) {
    solver_contact_t *contact = &world->contacts[n];
    contact_source_t *source = &world->sources[n];
    *contact = (solver_contact_t){.normal = memory->normal, .point_count = memory->point_count};
    *source = (contact_source_t){
        .key = pair_key(memory->body_a, memory->body_b),
        .body_a = memory->body_a,
        .body_b = memory->body_b,
        .features = {.flip = memory->flip,
                     .edge_ends = memory->edge_ends,
                     .point_count = memory->feature_count,
                     .normal = memory->face_normal,
                     .face_point = memory->face_point,
                     .lead = memory->face_lead},
        .pose = {memory->pose, memory->pose_angle},
        .previous = add_remembered_before(world, n, memory),
    };
    for (int j = 0; j < memory->point_count; j++) {
        const scene_memory_point_t *from = &memory->points[j];
        solver_point_t *p = &contact->points[j];
        p->id = from->id;
        p->separation = from->separation;
        p->normal_impulse = from->normal_impulse;
        p->tangent_impulse = from->tangent_impulse;
        p->restitution_impulse = from->restitution_impulse;
        p->restitution_tangent_impulse = from->restitution_tangent_impulse;
        source->points[j] = from->point;
    }
    for (int j = 0; j < memory->feature_count; j++) {
        source->features.points[j] = memory->feature_points[j];
        source->features.ids[j] = memory->feature_ids[j];
    }
}

void world_restore_memory(world_t *world, const scene_contact_memory_t *memories,
                          size_t count) {
    /* A new step: whatever groups the bodies had point to an older one. */
    world->step_number++;
    memory_reserve_lines((void **)&world->contacts, &world->contact_capacity, count,
                         sizeof(solver_contact_t));
    memory_reserve((void **)&world->sources, &world->source_capacity, count,
                   sizeof(contact_source_t));
    memory_reserve_lines((void **)&world->old_contacts, &world->old_contact_capacity, count,
                         sizeof(solver_contact_t));
    world->contact_count = count;
    world->gap_count = 0;
    for (size_t i = 0; i < count;) {
        body_t *a = memories[i].body_a;
        size_t first = i;
        for (; i < count && memories[i].body_a == a; i++) {
            add_remembered(world, i, &memories[i]);
        }
        place_group(world, a, first, i, 0, 0);
    }
}

void world_forget_removed(world_t *world) {
    size_t kept = 0;
    for (size_t i = 0; i < world->contact_count;) {
        body_t *a = world->sources[i].body_a;
        size_t first = kept;
        for (; i < world->contact_count && world->sources[i].body_a == a; i++) {
            if (a->removed || world->sources[i].body_b->removed) continue;
            world->contacts[kept] = world->contacts[i];
            world->sources[kept++] = world->sources[i];
        }
        if (!a->removed) {
            a->contact_first = (uint32_t)first;
            a->contact_count = (uint32_t)(kept - first);
        }
    }
    world->contact_count = kept;
    sleep_forget_removed(&world->sleep);
}

unsigned world_get_sleep_phase(const world_t *world) {
    return world->sleep.steps;
}

void world_set_sleep_phase(world_t *world, unsigned phase) {
    world->sleep.steps = phase;
}

uint64_t world_get_solver_steps(const world_t *world) {
    return world->solver_steps;
}

void world_set_solver_steps(world_t *world, uint64_t steps) {
    world->solver_steps = steps;
}

void world_index_sleepers(world_t *world, body_t **bodies, size_t count) {
    sleep_index_asleep(&world->sleep, bodies, count);
}

void world_get_step_lengths(const world_t *world, double *last, double *before) {
    *last = world->last_dt;
    *before = world->older_dt;
}

void world_set_step_lengths(world_t *world, double last, double before) {
    world->last_dt = last;
    world->older_dt = before;
}

/* The last completed step's contact of the pair, between steps. */
static size_t find_current(const world_t *world, const body_t *a, uint64_t key) {
    return find_in_step(world->sources, world->contact_count, world->step_number, a, key);
}

/* Whether contact x is a better one to report for a pair than y: touching
 * first, then the deeper. */
static bool better_contact(const contact_t *x, const contact_t *y) {
    if (x->touching != y->touching) return x->touching;
    double dx = INFINITY, dy = INFINITY;
    for (size_t j = 0; j < x->point_count; j++) dx = fmin(dx, x->separation[j]);
    for (size_t j = 0; j < y->point_count; j++) dy = fmin(dy, y->separation[j]);
    return dx < dy;
}

/* A pair with a chain: the best contact of the other body with one of its
 * segments (each pair's segment is its body b). */
static bool chain_pair_contact(const world_t *world, body_t *body1, body_t *body2,
                               contact_t *contact) {
    bool chain_first = body1->kind == BODY_SHAPE_CHAIN;
    body_t *chain = chain_first ? body1 : body2, *other = chain_first ? body2 : body1;
    bool found = false;
    for (size_t k = 0; k < chain->part_count; k++) {
        size_t index = find_current(world, other, pair_key(other, chain->parts[k]));
        if (index == SIZE_MAX) continue;
        contact_t entry = world_get_contact(world, index);
        if (!found || better_contact(&entry, contact)) *contact = entry;
        found = true;
    }
    if (found && chain_first) {
        contact->body1 = body1;
        contact->body2 = body2;
        contact->axis = vec_negate(contact->axis);
    }
    return found;
}

bool world_pair_contact(const world_t *world, body_t *body1, body_t *body2, contact_t *contact) {
    if (body1->kind == BODY_SHAPE_CHAIN || body2->kind == BODY_SHAPE_CHAIN) {
        return chain_pair_contact(world, body1, body2, contact);
    }
    size_t index = find_current(world, body1, pair_key(body1, body2));
    if (index != SIZE_MAX) {
        *contact = world_get_contact(world, index);
        return true;
    }
    /* The broadphase ordered the pair the other way: the same contact seen
     * from body1. Normal impulses, separations and points do not depend on
     * the side; the tangent impulse on body1 along the flipped tangent is
     * the one on body2 along the original tangent. */
    index = find_current(world, body2, pair_key(body2, body1));
    if (index == SIZE_MAX) return false;
    *contact = world_get_contact(world, index);
    contact->body1 = body1;
    contact->body2 = body2;
    contact->axis = vec_negate(contact->axis);
    return true;
}
