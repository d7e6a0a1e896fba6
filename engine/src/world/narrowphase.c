/*
 * The step's contacts (narrowphase.h): found from the pairs, matched with
 * last step's to warm-start and to reuse features.
 */
#include "world/narrowphase.h"
#include <math.h>
#include "base/memory.h"
#include "base/prefetch.h"
#include "base/scalar.h"
#include "base/workers.h"
#include "solver/velocity_solve.h"

/* A pair's manifold features are reused while the pair's relative pose
 * stays this close (m, rad) to the pose they were found at. The points are
 * evaluated at the current poses; only where clipping cut the incident edge
 * can a point be up to about a centimetre off where clipping would cut it
 * now. A pile then skips most of the separating-axis work: at 1 cm and
 * 0.02 rad, pile(1000) runs 5.6% fewer instructions than at 5 mm and
 * 0.01 rad, with the same penetrations and the same pyramid (measured). */
static const double REUSE_DISTANCE = 0.01;
static const double REUSE_ANGLE = 0.02;

/* Last step's contact of the pair, while this step's are being found. */
static size_t find_old(const world_t *world, const body_t *a, uint64_t key) {
    return find_in_step(world->old_sources, world->old_count, world->step_number - 1, a, key);
}

/* Last step's gap of the pair with this key, found as find_old finds its
 * contact; NULL when the pair was not apart last step. */
static const pair_gap_t *find_old_gap(const world_t *world, const body_t *a, uint64_t key) {
    if (a->contact_step != (uint32_t)(world->step_number - 1)) return NULL;
    size_t end = (size_t)a->gap_first + a->gap_count;
    if (end > world->old_gap_count) return NULL;
    for (size_t i = a->gap_first; i < end; i++) {
        if (world->old_gaps[i].key == key) return &world->old_gaps[i];
    }
    return NULL;
}

/* How far any face's separation of the pair can have moved since the
 * relative pose `then` (m): in a's frame, no point of b has moved further
 * than |dp| + r_b |da| (dp, da: the change of the relative pose), and in
 * b's frame no point of a further than |dp| + (|p| + r_a) |da|; a face's
 * separation moves no more than the points do. */
static double pose_drift(relative_pose_t then, relative_pose_t now, const body_t *a,
                         const body_t *b) {
    double turn = fabs(now.angle - then.angle);
    return vec_get_length(vec_subtract(now.position, then.position)) +
           (vec_get_length(now.position) + a->radius + b->radius) * turn;
}

/* Whether the pair is still further apart than margin by its gap of last
 * step. */
static bool still_apart(const pair_gap_t *gap, relative_pose_t now, const body_t *a,
                        const body_t *b, double margin) {
    return gap->separation - pose_drift(gap->pose, now, a, b) > margin;
}

/* The point of contact c that is the feature id; NULL when it has none. */
static const solver_point_t *same_point(const solver_contact_t *c, uint32_t id) {
    for (int j = 0; j < c->point_count; j++) {
        if (c->points[j].id == id) return &c->points[j];
    }
    return NULL;
}

/*
 * Last step's impulses carried into a step of another length. An impulse
 * is a force times its step, so what carries over is the point's force:
 * its impulses of the last two steps over their summed length, times this
 * step's dt (a point of one step: its impulses times the ratio of the
 * steps). Last step's force alone also holds the impulse that stopped what
 * the step before left moving, and times the ratio that impulse returns as
 * a kick that grows from step to step (docs/api.md, Step size). The step
 * before is matched by the feature of last step's point.
 */
static void warm_rescaled(const world_t *world, solver_contact_t *contact, point_match_t match,
                          size_t old_index) {
    const solver_contact_t *old = &world->old_contacts[old_index];
    uint32_t previous = world->old_sources[old_index].previous;
    const solver_contact_t *older =
        previous != NO_CONTACT ? &world->older_contacts[previous] : NULL;
    for (int i = 0; i < contact->point_count; i++) {
        if (match.takes[i] == 0) continue;
        double normal = 0.0, tangent = 0.0;
        for (int j = 0; j < old->point_count; j++) {
            if (!(match.takes[i] & (1u << j))) continue;
            const solver_point_t *last = &old->points[j];
            const solver_point_t *before = older != NULL ? same_point(older, last->id) : NULL;
            if (before != NULL) {
                normal += world->warm_share * (last->normal_impulse + before->normal_impulse);
                tangent += world->warm_share * (last->tangent_impulse + before->tangent_impulse);
            } else {
                normal += world->warm_ratio * last->normal_impulse;
                tangent += world->warm_ratio * last->tangent_impulse;
            }
        }
        solver_point_t *point = &contact->points[i];
        if (match.same & (1u << i)) {
            point->normal_impulse = normal;
            point->tangent_impulse = tangent;
        } else {
            take_impulses(contact, point, old->normal, normal, tangent);
        }
    }
}

/* Copies last step's impulses to the points that continue its points
 * (match_points); rescaled when this step is not as long as the last
 * (warm_rescaled). */
WORLD_INLINE void warm_from_old(const world_t *world, solver_contact_t *contact,
                                const contact_source_t *source, size_t old_index) {
    const solver_contact_t *old = &world->old_contacts[old_index];
    const vector_t *old_points = world->old_sources[old_index].points;
    double reach = warm_reach(source->body_a, source->body_b);
    if (world->warm_ratio != 1.0) {
        warm_rescaled(world, contact,
                      match_points(contact, source->points, old, old_points, reach), old_index);
        return;
    }
    carry_impulses(contact, source->points, old, old_points, reach);
}

static relative_pose_t relative_pose(const body_t *a, const body_t *b) {
    return (relative_pose_t){body_to_local(a, b->centroid), b->angle - a->angle};
}

/* Whether last step's features still hold: the pose is within the reuse
 * window, and no other axis can have overtaken the reference face's by
 * more than a fresh search would let it (MANIFOLD_KEEP_TOLERANCE): each
 * separation has moved no more than pose_drift (here with |p| bounded by
 * |x| + |y|, to spare a square root), so the lead has shrunk by no more
 * than twice that. A corner against a corner has axes of nearly equal
 * separation: reused as the bodies slid, their features held a phantom
 * overlap where a fresh search found them apart (pile(10000)). */
WORLD_INLINE bool features_hold(const contact_source_t *old, relative_pose_t now,
                                const body_t *a, const body_t *b) {
    relative_pose_t then = old->pose;
    double dx = now.position.x - then.position.x, dy = now.position.y - then.position.y;
    double turn = fabs(now.angle - then.angle);
    if (!(fabs(dx) < REUSE_DISTANCE && fabs(dy) < REUSE_DISTANCE && turn < REUSE_ANGLE) ||
        old->features.on_run) {
        return false;
    }
    double reach = fabs(now.position.x) + fabs(now.position.y) + a->radius + b->radius;
    double room = 0.5 * (old->features.lead + MANIFOLD_KEEP_TOLERANCE) - reach * turn;
    return room > 0.0 && dx * dx + dy * dy < room * room;
}

/* Writes contact n of the step from the pair's result. */
WORLD_INLINE void add_contact(world_t *world, size_t n, body_t *a, body_t *b,
                        const pair_result_t *found) {
    const manifold_t *manifold = &found->manifold;
    solver_contact_t *contact = &world->contacts[n];
    solver_anchor_t *anchor = &world->anchors[n];
    contact_source_t *source = &world->sources[n];
    /* The solver's other fields are all set by its prepare step; the kind
     * of solve is decided here, where the contact and its anchors are in
     * the cache (read again for it before preparing, they cost a large
     * pile 2.5% of its step). */
    contact->a = a->solver_index;
    contact->b = b->solver_index;
    contact->normal = manifold->normal;
    contact->friction = sqrt(a->friction * b->friction);
    contact->restitution = contact_restitution(a, b);
    contact->slop = solver_contact_slop(a->radius, b->radius);
    contact->point_count = manifold->point_count;
    contact->edge_ends = found->features.edge_ends && manifold->point_count == 2;
    for (int i = 0; i < manifold->point_count; i++) {
        solver_point_t *point = &contact->points[i];
        anchor->r_a[i] = vec_subtract(manifold->points[i].point, a->centroid);
        anchor->r_b[i] = vec_subtract(manifold->points[i].point, b->centroid);
        point->separation = manifold->points[i].separation;
        point->id = manifold->points[i].id;
        point->normal_impulse = point->tangent_impulse = 0.0;
        source->points[i] = manifold->points[i].point;
    }
    contact->block = solver_contact_blocks(contact, anchor, &world->velocities[contact->a],
                                           &world->velocities[contact->b]);
    source->key = pair_key(a, b);
    source->body_a = a;
    source->body_b = b;
    source->features = found->features;
    source->pose = found->pose;
    source->previous = found->old != SIZE_MAX ? (uint32_t)found->old : NO_CONTACT;
    if (found->old != SIZE_MAX) warm_from_old(world, contact, source, found->old);
}

/* The manifold of the broadphase's pair (a, b), reusing last step's
 * features while the pose stays close. Reads the world only. */
WORLD_INLINE void collide_pair(const world_t *world, body_t *a, body_t *b, const broadphase_pair_t *pair,
                         pair_result_t *found) {
    double margin = world->margins[pair->a] + world->margins[pair->b];
    uint64_t key = pair_key(a, b);
    size_t old = find_old(world, a, key);
    found->old = old;
    found->apart = false;
    found->pose = relative_pose(a, b);
    if (old != SIZE_MAX && features_hold(&world->old_sources[old], found->pose, a, b)) {
        found->features = world->old_sources[old].features;
        found->pose = world->old_sources[old].pose; /* measure drift from where they were found */
        found->manifold = manifold_evaluate(&found->features, a, b, margin);
        return;
    }
    const pair_gap_t *gap = old == SIZE_MAX ? find_old_gap(world, a, key) : NULL;
    if (gap != NULL && still_apart(gap, found->pose, a, b, margin)) {
        found->manifold.point_count = 0;
        found->apart = true;
        found->gap = *gap;
        return;
    }
    double separation;
    const manifold_features_t *last = old != SIZE_MAX ? &world->old_sources[old].features : NULL;
    found->manifold = manifold_collide(a, b, margin, last, &found->features, &separation);
    if (separation > margin) {
        found->apart = true;
        found->gap = (pair_gap_t){key, found->pose, separation};
    }
}

/* How many pairs ahead the narrowphase asks for body b's lines that a
 * manifold reads first: its first two, the core of a round shape and the
 * first line of a polygon's world vertices. b is anywhere in the scene, and
 * waiting on it was a third of the time of evaluating a manifold
 * (pile(4000)), and half of colliding two circles (circlepile(4000)).
 * Single lines, not PREFETCH_SPAN: every line of those fields, and every
 * line of last step's source below, made the narrowphase slower (a fifth
 * more perf samples in circlepile(4000)). A macro: GCC deems a function of
 * prefetches alone const and drops its calls. */
enum { PAIR_AHEAD = 4 };
#define PREFETCH_BODY_B(bodies, pairs, at, count)                                      \
    do {                                                                               \
        if ((at) < (count)) {                                                          \
            const body_t *b_ = (bodies)[(pairs)[at].b];                                \
            __builtin_prefetch(b_);                                                    \
            __builtin_prefetch((const char *)b_ + PREFETCH_LINE);                      \
            __builtin_prefetch(b_->core);                                              \
            __builtin_prefetch(&b_->round_radius);                                     \
            __builtin_prefetch(b_->shape);                                             \
        }                                                                              \
    } while (0)

/* How many contacts ahead of the last one matched the narrowphase asks for
 * last step's records: the pairs come in last step's order, mostly, so the
 * old contacts they match are read nearly in sequence, but a record apart,
 * and waiting on each was a third of the time of a settled pile's
 * narrowphase (pile(4000)). The lines asked for are those a match reads:
 * each point's id and impulses, and the source's key, pose and features.
 * A macro: GCC deems a function of prefetches alone const and drops its
 * calls. */
enum { OLD_AHEAD = 8 };
#define PREFETCH_OLD(world, at)                                                              \
    do {                                                                                     \
        if ((at) < (world)->old_count) {                                                     \
            const char *c_ = (const char *)&(world)->old_contacts[at];                       \
            __builtin_prefetch(c_ + offsetof(solver_contact_t, points[0].id));              \
            __builtin_prefetch(c_ + offsetof(solver_contact_t, points[1].tangent_impulse)); \
            const char *s_ = (const char *)&(world)->old_sources[at];                        \
            __builtin_prefetch(s_);                                                          \
            __builtin_prefetch(s_ + 64);                                                     \
            __builtin_prefetch(s_ + sizeof(contact_source_t) - 1);                           \
        }                                                                                    \
    } while (0)

/* How many contacts ahead of the one being written the narrowphase asks
 * for the lines it will write: the buffers it writes were last written two
 * steps ago and have left the cache in a large pile, and the stores then
 * waited to own each line (a sixth of circlepile(4000)'s narrowphase). */
enum { MADE_AHEAD = 4 };
#define PREFETCH_MADE(world, at)                                                      \
    do {                                                                              \
        if ((at) < (world)->contact_capacity) {                                       \
            PREFETCH_SPAN(&(world)->contacts[at], sizeof(solver_contact_t), 1);        \
            PREFETCH_SPAN(&(world)->sources[at], sizeof(contact_source_t), 1);         \
            PREFETCH_SPAN(&(world)->anchors[at], sizeof(solver_anchor_t), 1);          \
        }                                                                             \
    } while (0)

/* The contacts of the pairs whose body a is pairs[0].a; returns how many
 * pairs that is. Last step's contacts of a are found before any of this
 * step's are added, and then a is told where its new group lies. */
static size_t collide_group(world_t *world, body_t **bodies, const broadphase_pair_t *pairs,
                            size_t pair_count) {
    body_t *a = bodies[pairs[0].a];
    size_t first = world->contact_count, gap_first = world->gap_count;
    size_t n = 0;
    for (; n < pair_count && pairs[n].a == pairs[0].a; n++) {
        PREFETCH_BODY_B(bodies, pairs, n + PAIR_AHEAD, pair_count);
        body_t *b = bodies[pairs[n].b];
        pair_result_t found;
        collide_pair(world, a, b, &pairs[n], &found);
        if (found.old != SIZE_MAX) PREFETCH_OLD(world, found.old + OLD_AHEAD);
        if (found.manifold.point_count > 0) {
            size_t made = world->contact_count++;
            PREFETCH_MADE(world, made + MADE_AHEAD);
            add_contact(world, made, a, b, &found);
            world->point_count += (size_t)found.manifold.point_count;
            world->elastic_count += world->contacts[made].restitution != 0.0;
        }
        if (found.apart) world->gaps[world->gap_count++] = found.gap;
    }
    place_group(world, a, first, world->contact_count, gap_first, world->gap_count);
    return n;
}

/*
 * The narrowphase over threads (scene_set_workers), in two passes over the
 * same chunks of pairs, each cut where a group of body a ends so that a
 * group is one chunk's: the first finds each pair's manifold into the
 * pair's own result and counts its chunk's contacts; the second, once the
 * counts are summed in chunk order, writes each chunk's contacts from the
 * index the chunks before it leave. The contacts come out in the order,
 * and with the bytes, that collide_group gives them.
 */
typedef struct {
    world_t *world;
    body_t **bodies;
    const broadphase_pair_t *pairs;
    size_t pair_count;
} split_t;

/* The first pair at or after i that starts a group. */
static size_t group_start(const broadphase_pair_t *pairs, size_t count, size_t i) {
    while (i > 0 && i < count && pairs[i].a == pairs[i - 1].a) i++;
    return i;
}

static void collide_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const split_t *split = context;
    world_t *world = split->world;
    size_t made = 0, apart = 0, points = 0, elastic = 0;
    end = group_start(split->pairs, split->pair_count, end);
    for (size_t i = group_start(split->pairs, split->pair_count, begin); i < end; i++) {
        PREFETCH_BODY_B(split->bodies, split->pairs, i + PAIR_AHEAD, split->pair_count);
        const broadphase_pair_t *pair = &split->pairs[i];
        collide_pair(world, split->bodies[pair->a], split->bodies[pair->b], pair,
                     &world->results[i]);
        if (world->results[i].old != SIZE_MAX) {
            PREFETCH_OLD(world, world->results[i].old + OLD_AHEAD);
        }
        made += world->results[i].manifold.point_count > 0;
        points += (size_t)world->results[i].manifold.point_count;
        elastic += world->results[i].manifold.point_count > 0 &&
                   contact_restitution(split->bodies[pair->a], split->bodies[pair->b]) != 0.0;
        apart += world->results[i].apart;
    }
    world->chunk_first[chunk + 1] = made;
    world->chunk_gap_first[chunk + 1] = apart;
    world->chunk_points[chunk] = points;
    world->chunk_elastic[chunk] = elastic;
}

static void emit_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const split_t *split = context;
    world_t *world = split->world;
    const broadphase_pair_t *pairs = split->pairs;
    size_t n = world->chunk_first[chunk], g = world->chunk_gap_first[chunk];
    end = group_start(pairs, split->pair_count, end);
    for (size_t i = group_start(pairs, split->pair_count, begin); i < end;) {
        body_t *a = split->bodies[pairs[i].a];
        size_t first = n, gap_first = g;
        for (uint32_t group = pairs[i].a; i < end && pairs[i].a == group; i++) {
            /* The results two steps of OLD_AHEAD ahead, so that the one
             * whose old contact is asked for next is in the cache: reading
             * its index from memory was a fifth of this loop's time. */
            if (i + 2 * OLD_AHEAD < end) {
                PREFETCH_SPAN(&world->results[i + 2 * OLD_AHEAD], sizeof(pair_result_t), 0);
            }
            if (i + OLD_AHEAD < end) PREFETCH_OLD(world, world->results[i + OLD_AHEAD].old);
            const pair_result_t *found = &world->results[i];
            if (found->manifold.point_count > 0) {
                PREFETCH_MADE(world, n + MADE_AHEAD);
                add_contact(world, n++, a, split->bodies[pairs[i].b], found);
            }
            if (found->apart) world->gaps[g++] = found->gap;
        }
        place_group(world, a, first, n, gap_first, g);
    }
}

static void narrowphase_split(world_t *world, body_t **bodies, const broadphase_pair_t *pairs,
                              size_t pair_count) {
    memory_reserve((void **)&world->results, &world->result_capacity, pair_count,
                   sizeof(pair_result_t));
    split_t split = {world, bodies, pairs, pair_count};
    workers_for(world->workers, pair_count, collide_chunk, &split);
    size_t chunks = workers_chunks(world->workers, pair_count);
    world->chunk_first[0] = world->chunk_gap_first[0] = 0;
    for (size_t k = 0; k < chunks; k++) {
        world->chunk_first[k + 1] += world->chunk_first[k];
        world->chunk_gap_first[k + 1] += world->chunk_gap_first[k];
        world->point_count += world->chunk_points[k];
        world->elastic_count += world->chunk_elastic[k];
    }
    workers_for(world->workers, pair_count, emit_chunk, &split);
    world->contact_count = world->chunk_first[chunks];
    world->gap_count = world->chunk_gap_first[chunks];
}

/* Last step's contacts and gaps become the old ones, and the old contacts
 * the older; this step's are written over the buffers of the step before
 * (the contacts' over those of two steps before). */
static void swap_contact_buffers(world_t *world) {
    memory_swap((void **)&world->contacts, &world->contact_capacity,
                 (void **)&world->old_contacts, &world->old_contact_capacity);
    memory_swap((void **)&world->contacts, &world->contact_capacity,
                 (void **)&world->older_contacts, &world->older_contact_capacity);
    memory_swap((void **)&world->sources, &world->source_capacity,
                 (void **)&world->old_sources, &world->old_source_capacity);
    memory_swap((void **)&world->gaps, &world->gap_capacity, (void **)&world->old_gaps,
                 &world->old_gap_capacity);
    world->old_count = world->contact_count;
    world->contact_count = 0;
    world->old_gap_count = world->gap_count;
    world->gap_count = 0;
    world->point_count = world->elastic_count = 0;
    world->step_number++;
}

void narrowphase_find_contacts(world_t *world, body_t **bodies, const broadphase_pair_t *pairs,
                               size_t pair_count) {
    swap_contact_buffers(world);
    /* A pair makes at most one contact. The buffers that take turns grow
     * together (they keep their contents), so a new most of pairs costs
     * one step's allocations, not one in each of the next steps. */
    size_t n = pair_count;
    memory_reserve_lines((void **)&world->contacts, &world->contact_capacity, n,
                         sizeof(solver_contact_t));
    memory_reserve_lines((void **)&world->old_contacts, &world->old_contact_capacity, n,
                         sizeof(solver_contact_t));
    memory_reserve_lines((void **)&world->older_contacts, &world->older_contact_capacity, n,
                         sizeof(solver_contact_t));
    memory_reserve((void **)&world->sources, &world->source_capacity, n, sizeof(contact_source_t));
    memory_reserve((void **)&world->old_sources, &world->old_source_capacity, n,
                   sizeof(contact_source_t));
    memory_reserve((void **)&world->anchors, &world->anchor_capacity, n, sizeof(solver_anchor_t));
    memory_reserve((void **)&world->gaps, &world->gap_capacity, n, sizeof(pair_gap_t));
    memory_reserve((void **)&world->old_gaps, &world->old_gap_capacity, n, sizeof(pair_gap_t));
    if (world->workers != NULL) {
        narrowphase_split(world, bodies, pairs, pair_count);
        return;
    }
    for (size_t i = 0; i < pair_count;) {
        i += collide_group(world, bodies, pairs + i, pair_count - i);
    }
}
