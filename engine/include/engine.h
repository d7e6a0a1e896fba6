#ifndef ENGINE_H
#define ENGINE_H

/* The whole public API in one include, plus engine-wide facts. */

#include <stddef.h>
#include "aabb.h"
#include "body.h"
#include "collision.h"
#include "color.h"
#include "contact.h"
#include "forces.h"
#include "list.h"
#include "polygon.h"
#include "scene.h"
#include "scene_state.h"
#include "vector.h"

/* How many blocks the engine has allocated (malloc, calloc, or a realloc that
 * grew a block) since the program started. Tests read it before and after a
 * warm scene_tick to show that a step allocates nothing. */
size_t engine_allocation_count(void);

#endif // #ifndef ENGINE_H
