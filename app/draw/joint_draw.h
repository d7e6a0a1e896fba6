#ifndef SANDBOX_JOINT_DRAW_H
#define SANDBOX_JOINT_DRAW_H

/*
 * Draws the scene's joints over the bodies (jostle/joint.h), each as it
 * stands now:
 *   every joint: its anchors as small rings, a line from each body's
 *     centroid to its anchor (so one sees what holds what), and the link
 *     between the anchors;
 *   revolute: the pin as a ring; with a limit, two rays at the limit angles
 *     (in body1's frame) and an arc between them; a motor's curved arrow
 *     turning the way it drives;
 *   distance: a rod solid; a rope (min length below max) dashed while slack;
 *   weld: a square at the anchor;
 *   prismatic and wheel: the axis through anchor1, with ticks at the limits;
 *     a wheel's motor as the revolute's arrow round anchor2;
 *   mouse: a line from the grab point to the target, a ring at the target;
 *   motor joint: a line between the centroids.
 * The joint `selected` (the one under the cursor, NULL for none) is drawn
 * in the accent colour.
 */

#include <SDL.h>
#include "core/app.h"
#include "jostle/joint.h"

void joint_draw_all(SDL_Renderer *renderer, app_t *app, joint_t *selected);

#endif
