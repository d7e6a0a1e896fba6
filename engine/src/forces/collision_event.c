#include "forces/collision_event.h"
#include <math.h>
#include "dynamics/body_private.h"
#include "jostle/collision.h"
#include "collision/collision_private.h"
#include "scene/scene_private.h"

/* The vertex of `body` deepest along -axis: where body2 reaches furthest into
 * body1 for body = body2 and axis from body1 toward body2. */
static vector_t deepest_vertex(body_t *body, vector_t axis) {
    body_update_world(body);
    vector_t deepest = body->world_vertices[0];
    for (size_t i = 1; i < body->count; i++) {
        if (vec_dot(body->world_vertices[i], axis) < vec_dot(deepest, axis)) {
            deepest = body->world_vertices[i];
        }
    }
    return deepest;
}

static void record_seed_collision(const collision_rule_t *rule, body_t *body1, body_t *body2,
                                  collision_info_t info, vector_t body2_impulse_before) {
    vector_t applied = vec_subtract(body2->impulse, body2_impulse_before);
    contact_t entry = {
        .kind = CONTACT_SEED,
        .touching = true,
        .body1 = body1,
        .body2 = body2,
        .axis = info.axis,
        .point_count = 1,
        .points = {deepest_vertex(body2, info.axis)},
        .separation = {-info.depth},
        .normal_impulse = {vec_dot(applied, info.axis)},
    };
    scene_record_contact(rule->scene, &entry);
}

/* The seed's rule: the handler runs when find_collision starts finding an
 * overlap. */
static void seed_collision(const collision_rule_t *rule, body_t *body1, body_t *body2,
                           collision_state_t *state) {
    collision_info_t info = find_collision(body1, body2);
    if (!info.collided) {
        state->colliding = false;
        return;
    }
    if (state->colliding) return;
    state->colliding = true;
    vector_t body2_impulse_before = body2->impulse;
    rule->handler(body1, body2, info.axis, rule->aux, rule->force_const);
    record_seed_collision(rule, body1, body2, info, body2_impulse_before);
}

/* With world contacts, a colliding pair has parted (its handler may fire
 * again) once it is further apart than PARTING_FRACTION of the smaller
 * body's radius at PARTING_READS reads in a row. Not at any positive
 * separation: bodies moving on together after a meeting hover at rounding
 * size on either side of zero, and a polygon that lands on a corner and
 * tips onto a face lifts off for a few steps (a rocking block's hop, which
 * grows with the body: up to 8% of its radius when dropped from five
 * radii, docs/design.md). Two reads in a row: a single step's lift (up to
 * 12% of a small body's radius) is not a parting. */
static const double PARTING_FRACTION = 0.1;
static const int PARTING_READS = 2;

static double parting_distance(const body_t *body1, const body_t *body2) {
    return PARTING_FRACTION * fmin(body1->radius, body2->radius);
}

/* One read of a colliding pair that is not touching: counts the reads it
 * has been apart; returns whether it has now parted. */
static bool read_parted(body_t *body1, body_t *body2, collision_state_t *state) {
    double gap = collision_separation(body1, body2);
    if (!(gap > parting_distance(body1, body2))) {
        state->apart_reads = 0;
        return false;
    }
    if (++state->apart_reads < PARTING_READS) return false;
    state->apart_reads = 0;
    return true;
}

/* A pair that world contacts resolve: the solver stops a fast pair at the
 * surface before it overlaps, so an overlap test would miss the meeting.
 * The handler runs when the world's contact of the pair starts touching
 * instead, read from the last step (this is stage 1, before this step's
 * contacts exist). */
static void world_collision(const collision_rule_t *rule, body_t *body1, body_t *body2,
                            collision_state_t *state) {
    /* A sleeping pair keeps its state: no contact is computed for it. */
    if (body1->asleep || body2->asleep) return;
    contact_t contact;
    bool found = scene_world_pair_contact(rule->scene, body1, body2, &contact);
    if (!found || !contact.touching) {
        /* The parting is judged on the poses, not on the last step's
         * contact: a pair that slept through it, or too far apart for a
         * speculative contact, has none. */
        if (state->colliding && read_parted(body1, body2, state)) state->colliding = false;
        return;
    }
    state->apart_reads = 0;
    if (state->colliding) return;
    state->colliding = true;
    vector_t body2_impulse_before = body2->impulse;
    rule->handler(body1, body2, contact.axis, rule->aux, rule->force_const);
    /* Where and how far apart the world found them, with the handler's
     * impulse in place of the solver's. */
    vector_t applied = vec_subtract(body2->impulse, body2_impulse_before);
    contact.kind = CONTACT_SEED;
    contact.normal_impulse[0] = vec_dot(applied, contact.axis);
    contact.normal_impulse[1] = 0.0;
    contact.tangent_impulse[0] = contact.tangent_impulse[1] = 0.0;
    scene_record_contact(rule->scene, &contact);
}

void collision_event_read(const collision_rule_t *rule, body_t *body1, body_t *body2,
                          collision_state_t *state) {
    if (scene_world_resolves(rule->scene, body1, body2)) {
        world_collision(rule, body1, body2, state);
    } else {
        seed_collision(rule, body1, body2, state);
    }
}
