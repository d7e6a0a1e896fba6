#ifndef JOSTLE_H
#define JOSTLE_H

/* jostle: a 2D rigid-body physics engine. The whole public API in one
 * include (but scene files: jostle/scene_file.h), plus engine-wide facts.
 * JOSTLE_VERSION_* are the version of these headers (docs/api.md, "Headers
 * and versions"). */

#include <stddef.h>
#include "aabb.h"
#include "body.h"
#include "collision.h"
#include "color.h"
#include "contact.h"
#include "forces.h"
#include "joint.h"
#include "list.h"
#include "polygon.h"
#include "query.h"
#include "scene.h"
#include "scene_state.h"
#include "vector.h"
#include "export.h"

#define JOSTLE_VERSION_MAJOR 1
#define JOSTLE_VERSION_MINOR 0
#define JOSTLE_VERSION_PATCH 0

JOSTLE_API_BEGIN

/* How many blocks the engine has allocated (malloc, calloc, or a realloc that
 * grew a block) since the program started. Tests read it before and after a
 * warm scene_tick to show that a step allocates nothing. */
size_t engine_allocation_count(void);

JOSTLE_API_END

#endif // #ifndef JOSTLE_H
