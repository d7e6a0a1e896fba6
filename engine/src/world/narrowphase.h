#ifndef NARROWPHASE_H
#define NARROWPHASE_H

/*
 * The narrowphase of the world's step: this step's contacts from the
 * broadphase's pairs (pairs[0 .. pair_count), grouped by body a), each
 * pair's manifold reusing last step's features while the pair's pose stays
 * close, skipped while a face kept it apart, and warm-started from last
 * step's impulses of the same features. Last step's contacts become the
 * old ones first; on the world's threads when it has some, with the same
 * bytes.
 */

#include <stddef.h>
#include "world/world_types.h"

void narrowphase_find_contacts(world_t *world, body_t **bodies, const broadphase_pair_t *pairs,
                               size_t pair_count);

#endif // #ifndef NARROWPHASE_H
