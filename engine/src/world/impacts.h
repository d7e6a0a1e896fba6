#ifndef IMPACTS_H
#define IMPACTS_H

/*
 * Impacts taken at their moment: every elastic contact of the step in
 * which the solver will time an impact is found again where its bodies
 * first touch (time_of_impact.h), so the collision pass bounces through
 * the geometry of that moment. Runs after the narrowphase, before the
 * solver; largest_polygon sizes the scratch room once.
 */

#include <stddef.h>
#include "world/world_types.h"

void impacts_take(world_t *world, double dt, size_t largest_polygon, double threshold);

#endif // #ifndef IMPACTS_H
