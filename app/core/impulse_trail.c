#include "core/impulse_trail.h"

void impulse_trail_clear(impulse_trail_t *trail) {
    trail->start = 0;
    trail->count = 0;
}

vector_t impulse_of_contact(const contact_t *contact, size_t k) {
    return vec_add(vec_multiply(contact->normal_impulse[k], contact->axis),
                   vec_multiply(contact->tangent_impulse[k], vec_perpendicular(contact->axis)));
}

static void push(impulse_trail_t *trail, impulse_mark_t mark) {
    if (trail->count == IMPULSE_TRAIL_CAPACITY) {
        trail->marks[trail->start] = mark;
        trail->start = (trail->start + 1) % IMPULSE_TRAIL_CAPACITY;
        return;
    }
    trail->marks[(trail->start + trail->count) % IMPULSE_TRAIL_CAPACITY] = mark;
    trail->count++;
}

void impulse_trail_record(impulse_trail_t *trail, scene_t *scene, double min_impulse) {
    size_t count = scene_contact_count(scene);
    for (size_t i = 0; i < count; i++) {
        const contact_t *contact = scene_get_contact(scene, i);
        size_t points = contact->point_count > 2 ? 2 : contact->point_count;
        for (size_t k = 0; k < points; k++) {
            vector_t impulse = impulse_of_contact(contact, k);
            if (!vec_is_finite(impulse) || vec_get_length(impulse) < min_impulse) continue;
            push(trail, (impulse_mark_t){contact->points[k], impulse, 0.0});
        }
    }
}

void impulse_trail_age(impulse_trail_t *trail, double dt) {
    for (size_t i = 0; i < trail->count; i++) {
        trail->marks[(trail->start + i) % IMPULSE_TRAIL_CAPACITY].age += dt;
    }
    /* Marks are added in time order, so the expired ones are the oldest. */
    while (trail->count > 0 && trail->marks[trail->start].age > IMPULSE_TRAIL_SECONDS) {
        trail->start = (trail->start + 1) % IMPULSE_TRAIL_CAPACITY;
        trail->count--;
    }
}

const impulse_mark_t *impulse_trail_get(const impulse_trail_t *trail, size_t i) {
    return &trail->marks[(trail->start + i) % IMPULSE_TRAIL_CAPACITY];
}
