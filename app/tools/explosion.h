#ifndef SANDBOX_EXPLOSION_H
#define SANDBOX_EXPLOSION_H

/*
 * An explosion: an impulse on every body of finite mass whose centroid is
 * within `radius` of the centre, away from it, falling off linearly with
 * the distance: a body at distance d gains the velocity
 * speed (1 - d / radius) (its impulse is its mass times that), none at the
 * radius and beyond. A body at the very centre is pushed up. Engine API
 * only (body_add_impulse wakes a sleeping body).
 */

#include <stddef.h>
#include "jostle/jostle.h"

/* The sandbox's explosion: this radius on screen, whatever the zoom, and a
 * centre speed in proportion to the radius in metres. */
#define EXPLOSION_RADIUS_PIXELS 120.0 /* the radius on screen, whatever the zoom */
#define EXPLOSION_SPEED_PER_METRE 4.0 /* centre speed (m/s) per metre of radius */

/* Pushes the bodies; returns how many it pushed. */
size_t explosion_apply(scene_t *scene, vector_t centre, double radius, double speed);

#endif
