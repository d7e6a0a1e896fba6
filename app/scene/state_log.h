#ifndef SANDBOX_STATE_LOG_H
#define SANDBOX_STATE_LOG_H

/*
 * What a script's `log` command prints (docs/sandbox.md): the open scene's
 * state in a few numbers, to compare two runs of one script, such as the web
 * page against the native build (tests/web/). Plain C (engine API and the
 * game rules, no SDL), tested by tests/app_units.c.
 */

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include "scene/sandbox_scene.h"

/* FNV-1a (64 bits) over the bits of each body's centroid x and y and its
 * rotation (the doubles' bytes, least significant first), for every body not
 * removed, in the scene's order: equal for two runs only when every
 * position and angle is equal bit for bit. */
uint64_t state_log_hash(scene_t *scene);

/* One line, "state: frame F  bodies B  hash H" and, in a game, "  score S
 * lives L  remaining R"; with bodies, then a line per body not removed,
 * "body I  X Y ROTATION" (metres and radians, 17 significant digits, I its
 * index in the scene). frame is the number of frames run before. */
void state_log_print(FILE *out, const sandbox_t *sandbox, unsigned long frame, bool bodies);

#endif
