#ifndef SANDBOX_JOINT_TOOL_H
#define SANDBOX_JOINT_TOOL_H

/*
 * The joint tool (W): joins bodies with the engine's joints (jostle/joint.h).
 *   click a body, then click a point: the body is pinned there to the world
 *     (a revolute joint: it swings about the point); click a second body
 *     instead, and the two are pinned together at the second click;
 *   drag from a body to another (or to a point of the world): a rope
 *     between the two points, as long as the drag (a distance joint with
 *     that maximum length and no minimum);
 *   Shift + drag: a rod (a distance joint of that fixed length);
 *   Alt + drag: a weld of the two bodies as they stand, at the middle of
 *     the drag.
 * Two bodies pinned or welded together stop colliding with each other (a
 * common collision group), since they overlap at the joint.
 * The joint under the cursor (within JOINT_TOOL_PICK_PIXELS of its link or
 * an anchor) is lit, with any tool, and D, Del, Backspace or Ctrl + click
 * delete it as they delete a body. Joints need world contacts: in a scene
 * without them the tool says so and joins nothing.
 */

#include <stdbool.h>
#include "core/app.h"
#include "jostle/joint.h"

#define JOINT_TOOL_PICK_PIXELS 6.0
/* A press and release closer than this (pixels) are a click, not a drag. */
#define JOINT_TOOL_CLICK_PIXELS 5.0

/* A left press at world point `at` with the joint tool: DRAG_JOINT when it
 * starts from a body or finishes a pending pin, DRAG_NONE otherwise. */
drag_t joint_tool_press(app_t *app, vector_t at);

/* The left button let go at `at` after DRAG_JOINT: makes the joint. */
void joint_tool_release(app_t *app, vector_t at);

/* The joint tool's first end while it waits or is dragged, in world
 * coordinates; false when there is none (or its body has gone). */
bool joint_tool_pick(app_t *app, vector_t *from);

/* The joint under the cursor (not the grab's), NULL for none. */
joint_t *joint_tool_hovered(app_t *app);

/* Deletes the joint under the cursor; false when there is none. */
bool joint_tool_delete_hovered(app_t *app);

#endif
