#ifndef CONTACT_H
#define CONTACT_H

/*
 * One entry of a scene's per-step record: two bodies in contact, the
 * collision axis and what the engine did about it. The sandbox draws these;
 * tests read them. Entries are owned by the scene (see scene_get_contact).
 *
 * World contacts include speculative ones: pairs a few millimetres (or, for
 * fast bodies, one step's travel) apart that the solver watched so that they
 * stop at the surface instead of overlapping. Their separations are positive
 * and, unless they closed during the step, their impulses zero; `touching`
 * tells the two kinds apart.
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

typedef struct body body_t;

/* Where the entry came from. */
typedef enum {
    CONTACT_WORLD = 0, /* the world contact pipeline (scene_set_contacts_enabled) */
    CONTACT_SEED,      /* a seed collision force creator (create_collision) */
} contact_kind_t;

typedef struct {
    contact_kind_t kind;
    /* True when a point overlaps (separation <= 0) or an impulse acted this
     * step; false for a speculative contact that stayed apart. Seed
     * collisions always touch. */
    bool touching;
    body_t *body1;
    body_t *body2;
    /* Unit collision axis pointing from body1 toward body2. */
    vector_t axis;
    /* Contact points (world, metres): 0 to 2. A seed collision has 1 or 2:
     * where find_collision found the overlap or, on a pair that world
     * contacts resolve, the points of the world contact that started
     * touching (at the previous step). */
    size_t point_count;
    vector_t points[2];
    /* Signed distance of each point along axis (m): negative when the bodies
     * overlap, positive for a speculative contact not yet touching. A seed
     * collision from a world contact keeps that contact's separations, taken
     * at the start of the step in which it touched: positive when the gap
     * closed during that step. */
    double separation[2];
    /* Impulse magnitudes (N s) applied at each point this step: along the
     * axis (pushing body2 away from body1, >= 0 for world contacts) and along
     * the tangent perp(axis) = (-axis.y, axis.x), on body2. For a seed
     * collision the impulse of its handler is in normal_impulse[0]. */
    double normal_impulse[2];
    double tangent_impulse[2];
} contact_t;

JOSTLE_API_END

#endif // #ifndef CONTACT_H
