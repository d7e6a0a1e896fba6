#ifndef SANDBOX_IMPULSE_TRAIL_H
#define SANDBOX_IMPULSE_TRAIL_H

/*
 * The impulses of recent steps, kept for IMPULSE_TRAIL_SECONDS so that an
 * impact's arrow stays on screen long enough to be seen, fading out. Copied
 * from the engine's per-step contact record after each step (the record
 * itself lives only until the next step).
 */

#include <stddef.h>
#include "jostle/jostle.h"

#define IMPULSE_TRAIL_SECONDS 0.5
#define IMPULSE_TRAIL_CAPACITY 4096

typedef struct {
    vector_t point;   /* world (m) */
    vector_t impulse; /* on body2 (N s) */
    double age;       /* seconds of display time since the step */
} impulse_mark_t;

typedef struct {
    impulse_mark_t marks[IMPULSE_TRAIL_CAPACITY];
    size_t start; /* index of the oldest mark */
    size_t count;
} impulse_trail_t;

void impulse_trail_clear(impulse_trail_t *trail);

/* Adds the impulse at every contact point of the scene's last step whose size
 * is at least min_impulse (N s); when full, the oldest marks go first. */
void impulse_trail_record(impulse_trail_t *trail, scene_t *scene, double min_impulse);

/* Ages every mark by dt seconds and forgets those older than the lifetime. */
void impulse_trail_age(impulse_trail_t *trail, double dt);

/* The i-th mark, oldest first (i < count). */
const impulse_mark_t *impulse_trail_get(const impulse_trail_t *trail, size_t i);

/* The impulse applied at point k of a contact, as a vector on body2. */
vector_t impulse_of_contact(const contact_t *contact, size_t k);

#endif
