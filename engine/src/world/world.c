#include "world/world.h"
#include <math.h>
#include <string.h>
#include "dynamics/body_private.h"
#include "collision/broadphase.h"
#include "dynamics/integrator.h"
#include "collision/manifold.h"
#include "base/memory.h"
#include "base/scalar.h"
#include "jostle/scene_state.h"
#include "collision/seams.h"
#include "solver/solver.h"
#include "solver/shock.h"
#include "world/sleep.h"
#include "solver/solver_wide.h"
#include "collision/time_of_impact.h"
#include "base/workers.h"

/* Every body's box is enlarged by how far it can move in a step plus this
 * (m), so a contact is found a step before it forms. 5 mm rather than 1 cm:
 * the motion term already covers the approach, and the pile(4000) carries 7%
 * fewer speculative points (3% less time) with every quality figure of the
 * canonical scenes unchanged (measured). */
static const double CONTACT_MARGIN = 0.005;
/* A pair's manifold features are reused while the pair's relative pose
 * stays this close (m, rad) to the pose they were found at. The points are
 * evaluated at the current poses; only where clipping cut the incident edge
 * can a point be up to about a centimetre off where clipping would cut it
 * now. A pile then skips most of the separating-axis work: at 1 cm and
 * 0.02 rad, pile(1000) runs 5.6% fewer instructions than at 5 mm and
 * 0.01 rad, with the same penetrations and the same pyramid (measured). */
static const double REUSE_DISTANCE = 0.01;
static const double REUSE_ANGLE = 0.02;

/* For the per-pair and per-body functions that one thread's loops and the
 * workers' chunks share, and what they call: inlined into each, as the
 * one-thread loops had them (called, pile(1000) ran 3% more instructions). */
#if defined(__GNUC__)
#define WORLD_INLINE static inline __attribute__((always_inline))
#else
#define WORLD_INLINE static inline
#endif

/* Where b is as seen from a: b's centroid in a's frame and the angle
 * between them. */
typedef struct {
    vector_t position;
    double angle;
} relative_pose_t;

/* A pair whose boxes overlapped while a face of one polygon kept the other
 * more than the margin away: that face's separation (m, a lower bound on
 * the distance between the polygons) at the relative pose it was found at.
 * While the bodies have since moved against each other by less than the
 * separation less the step's margin, the pair is still that far apart, and
 * its separating-axis search is skipped. */
typedef struct {
    uint64_t key;
    relative_pose_t pose;
    double separation;
} pair_gap_t;

/* What a contact needs beyond the solver's constraint: who, where, the key
 * that finds it again next step, its features with the pose they were
 * found at, and where the pair's contact of the step before lies
 * (NO_CONTACT: it had none). */
typedef struct {
    uint64_t key;
    body_t *body_a, *body_b;
    vector_t points[2];
    manifold_features_t features;
    relative_pose_t pose;
    uint32_t previous;
} contact_source_t;
static const uint32_t NO_CONTACT = UINT32_MAX;

/* What the narrowphase finds for one pair: its manifold and features,
 * the pose they were found at, and last step's contact (SIZE_MAX: none);
 * or, when a face kept the polygons apart, the gap (apart true). */
typedef struct {
    manifold_t manifold;
    manifold_features_t features;
    relative_pose_t pose;
    size_t old;
    bool apart;
    pair_gap_t gap;
} pair_result_t;

struct world {
    broadphase_t *broadphase;
    broadphase_proxy_t *proxies;
    size_t proxy_capacity;
    solver_velocity_t *velocities;
    size_t velocity_capacity;
    solver_state_t *states;
    size_t state_capacity;
    solver_displacement_t *displacements;
    size_t displacement_capacity;
    double *margins;
    size_t margin_capacity;

    /* This step's contacts, with their sources in parallel, grouped by
     * body a (the broadphase hands over its pairs sorted by a). */
    solver_contact_t *contacts;
    solver_anchor_t *anchors;
    contact_source_t *sources;
    size_t contact_count, contact_capacity, anchor_capacity, source_capacity;

    /* Last step's contacts and sources: the buffers swap each step, so
     * warm starting and feature reuse read last step's results where the
     * solver left them, with nothing copied. Each body knows where its
     * group starts (body_private.h). */
    solver_contact_t *old_contacts;
    contact_source_t *old_sources;
    size_t old_count, old_contact_capacity, old_source_capacity;
    /* The contacts of the step before last, read only when the step's
     * length changes (warm_rescaled). */
    solver_contact_t *older_contacts;
    size_t older_contact_capacity;
    /* The lengths of the last step and of the one before it (s, 0 before
     * there was one); this step's over last step's, and over their sum. */
    double last_dt, older_dt, warm_ratio, warm_share;

    /* This step's and last step's pairs that were apart (pair_gap_t),
     * grouped by body a as the contacts are. */
    pair_gap_t *gaps, *old_gaps;
    size_t gap_count, old_gap_count, gap_capacity, old_gap_capacity;

    /* Steps taken, to tell a body's contact group of the last step from an
     * older one. */
    uint64_t step_number;

    /* Which static bodies lie flush (seams.h), found again when a static
     * body changes; with workers, each chunk of the loading says whether it
     * saw one change. */
    seams_t seams;
    bool seams_changed[WORKERS_MAX_CHUNKS];

    solver_wide_t wide;
    shock_t shock;
    int velocity_iterations, position_iterations;

    /* Sleeping: the awake bodies of the step, their motions and where
     * those came from; the touching contacts that join islands. */
    sleep_t sleep;
    body_t **active;
    integrator_motion_t *active_motions;
    size_t *active_index;
    size_t active_capacity, active_motion_capacity, active_index_capacity;
    sleep_link_t *links;
    size_t link_capacity;

    /* The threads of scene_set_workers (NULL: the caller's alone), and the
     * threaded narrowphase's results, one per pair, and contacts per chunk
     * (narrowphase_split). */
    workers_t *workers;
    pair_result_t *results;
    size_t result_capacity;
    size_t chunk_first[WORKERS_MAX_CHUNKS + 1];
    size_t chunk_gap_first[WORKERS_MAX_CHUNKS + 1];

    /* Room for time_of_impact's posed polygons. */
    toi_scratch_t toi_scratch;
};

world_t *world_init(size_t velocity_iterations, size_t position_iterations) {
    world_t *world = memory_calloc(1, sizeof(world_t));
    world->broadphase = broadphase_init();
    world_set_iterations(world, velocity_iterations, position_iterations);
    return world;
}

void world_free(world_t *world) {
    broadphase_free(world->broadphase);
    memory_free(world->proxies);
    memory_free(world->velocities);
    memory_free(world->states);
    memory_free(world->displacements);
    memory_free(world->margins);
    memory_free(world->contacts);
    memory_free(world->anchors);
    memory_free(world->sources);
    memory_free(world->old_contacts);
    memory_free(world->older_contacts);
    memory_free(world->old_sources);
    memory_free(world->gaps);
    memory_free(world->old_gaps);
    seams_free(&world->seams);
    solver_wide_free(&world->wide);
    shock_free(&world->shock);
    sleep_free(&world->sleep);
    memory_free(world->active);
    memory_free(world->active_motions);
    memory_free(world->active_index);
    memory_free(world->links);
    workers_free(world->workers);
    memory_free(world->results);
    memory_free(world->toi_scratch.vectors);
    memory_free(world);
}

void world_set_iterations(world_t *world, size_t velocity_iterations, size_t position_iterations) {
    world->velocity_iterations = (int)velocity_iterations;
    world->position_iterations = (int)position_iterations;
}

void world_set_workers(world_t *world, size_t workers) {
    size_t now = world->workers != NULL ? workers_count(world->workers) : 1;
    if (workers == now) return;
    workers_free(world->workers);
    world->workers = workers > 1 ? workers_init(workers) : NULL;
    world->wide.workers = world->workers;
    broadphase_set_workers(world->broadphase, world->workers);
}

void world_for_bodies(world_t *world, size_t count, workers_fn_t fn, void *context) {
    if (world->workers == NULL) {
        fn(context, 0, 0, count);
        return;
    }
    workers_for(world->workers, count, fn, context);
}

static uint64_t pair_key(const body_t *a, const body_t *b) {
    return (uint64_t)a->id << 32 | b->id;
}

static void reserve_rows(world_t *world, size_t count) {
    memory_reserve((void **)&world->velocities, &world->velocity_capacity, count,
                   sizeof(solver_velocity_t));
    memory_reserve((void **)&world->states, &world->state_capacity, count, sizeof(solver_state_t));
    memory_reserve((void **)&world->displacements, &world->displacement_capacity, count,
                   sizeof(solver_displacement_t));
    memory_reserve((void **)&world->proxies, &world->proxy_capacity, count,
                   sizeof(broadphase_proxy_t));
    memory_reserve((void **)&world->margins, &world->margin_capacity, count, sizeof(double));
}

/* The box a body sweeps this step: its bounds moved along both velocities
 * it may have (at the start, and free of contacts), grown all round by
 * grow (what rotation and the contact margin add). Only the direction of
 * motion is enlarged, so bodies moving together, like a falling grid, do not
 * pair, while a body and whatever lies ahead of it do. */
WORLD_INLINE aabb_t swept_box(aabb_t bounds, double dt, const solver_state_t *state, double grow) {
    vector_t d1 = vec_multiply(dt, state->v_start), d2 = vec_multiply(dt, state->v_free);
    return (aabb_t){
        {bounds.min.x + min_of(0.0, min_of(d1.x, d2.x)) - grow,
         bounds.min.y + min_of(0.0, min_of(d1.y, d2.y)) - grow},
        {bounds.max.x + max_of(0.0, max_of(d1.x, d2.x)) + grow,
         bounds.max.y + max_of(0.0, max_of(d1.y, d2.y)) + grow},
    };
}

/* What the broadphase's filter reads of a body, removal aside: one rule for
 * the pairs the world makes and for world_pair_collides. */
static void set_filter(broadphase_proxy_t *proxy, const body_t *body) {
    proxy->fixed = body->inverse_mass == 0.0 && body->inverse_inertia == 0.0;
    proxy->category = body->category;
    proxy->mask = body->mask;
    proxy->group = body->group;
}

/* Loads body i's rows for the solver and its broadphase proxy; returns
 * whether the body changed what the seams were found from. */
WORLD_INLINE bool load_body(world_t *world, body_t *body, const integrator_motion_t *motion, size_t i,
                      double dt) {
    body->solver_index = (uint32_t)i;
    body->changed = false; /* world_wake_changed has seen it */
    body_update_world(body);
    solver_state_t *state = &world->states[i];
    solver_velocity_t *velocity = &world->velocities[i];
    state->v_start = body->velocity;
    state->w_start = body->angular_velocity;
    state->v_free = motion->velocity;
    state->w_free = motion->angular_velocity;
    state->drift = motion->drift;
    state->spin_drift = motion->spin_drift;
    state->acceleration = motion->acceleration;
    state->impact_time = -1.0;
    state->pushing_contacts = 0;
    world->displacements[i].radius = body->radius;
    velocity->v = state->v_free;
    velocity->w = state->w_free;
    velocity->inverse_mass = motion->inverse_mass;
    velocity->inverse_inertia = body->inverse_inertia;
    if (solver_row_is_static(velocity)) {
        /* No -0.0 in a row the solver never changes: its sweeps write such
         * a row unchanged but for turning -0.0 to +0.0, or, sharing a
         * colour over threads, not at all (solver_wide.h). */
        velocity->v = vec_add(velocity->v, (vector_t){0.0, 0.0});
        velocity->w += 0.0;
    }

    /* How far any point of the body can move this step, bounded: the
     * narrowphase keeps speculative points up to this far apart. */
    double speed = max_of(vec_get_length(state->v_start), vec_get_length(state->v_free));
    double spin = max_of(fabs(state->w_start), fabs(state->w_free)) * body->radius;
    world->margins[i] = dt * (speed + spin) + CONTACT_MARGIN;
    broadphase_proxy_t *proxy = &world->proxies[i];
    proxy->box = swept_box(body->bounds, dt, state, dt * spin + CONTACT_MARGIN);
    set_filter(proxy, body);
    if (body->removed) proxy->category = 0;
    return (proxy->fixed || body->seam_listed) && seams_body_changed(body);
}

/* The arguments of a loop over bodies split over the workers. */
typedef struct {
    world_t *world;
    body_t **bodies;
    const integrator_motion_t *free_motions; /* loading reads them */
    integrator_motion_t *motions;            /* writing back fills them */
    double dt;
} body_loop_t;

static void load_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const body_loop_t *loop = context;
    bool changed = false;
    for (size_t i = begin; i < end; i++) {
        changed |= load_body(loop->world, loop->bodies[i], &loop->free_motions[i], i, loop->dt);
    }
    loop->world->seams_changed[chunk] = changed;
}

/* Loads each body's rows for the solver and its broadphase proxy; returns
 * whether a static body changed since the seams were found. */
static bool load_bodies(world_t *world, body_t **bodies, const integrator_motion_t *motions,
                        size_t count, const world_step_t *step) {
    reserve_rows(world, count);
    bool changed = false;
    if (world->workers != NULL) {
        body_loop_t loop = {world, bodies, motions, NULL, step->dt};
        size_t chunks = workers_chunks(world->workers, count);
        for (size_t k = 0; k < chunks; k++) world->seams_changed[k] = false;
        workers_for(world->workers, count, load_chunk, &loop);
        for (size_t k = 0; k < chunks; k++) changed |= world->seams_changed[k];
        return changed;
    }
    for (size_t i = 0; i < count; i++) {
        changed |= load_body(world, bodies[i], &motions[i], i, step->dt);
    }
    return changed;
}

/* The contact of the pair with this key among the contacts body a had as
 * body a in step `step`, whose buffer is sources[0 .. count); SIZE_MAX when
 * the pair had none. A group left from another step (or an older world) is
 * skipped, and the key check rejects whatever else lies at its indices. */
static size_t find_in_step(const contact_source_t *sources, size_t count, uint64_t step,
                           const body_t *a, uint64_t key) {
    if (a->contact_step != (uint32_t)step) return SIZE_MAX;
    size_t end = (size_t)a->contact_first + a->contact_count;
    if (end > count) return SIZE_MAX;
    for (size_t i = a->contact_first; i < end; i++) {
        if (sources[i].key == key) return i;
    }
    return SIZE_MAX;
}

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

/* Whether the pair is still further apart than margin by its gap of last
 * step: in a's frame, no point of b has moved further than |dp| + r_b |da|
 * since the gap was found (dp, da: the change of the relative pose), and
 * in b's frame no point of a further than |dp| + (|p| + r_a) |da|; a
 * face's separation moves no more than the points do. */
static bool still_apart(const pair_gap_t *gap, relative_pose_t now, const body_t *a,
                        const body_t *b, double margin) {
    double turn = fabs(now.angle - gap->pose.angle);
    double moved = vec_get_length(vec_subtract(now.position, gap->pose.position)) +
                   (vec_get_length(now.position) + a->radius + b->radius) * turn;
    return gap->separation - moved > margin;
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
 * a kick that grows from step to step (docs/api.md, Step size).
 */
static void warm_rescaled(const world_t *world, solver_contact_t *contact, size_t old_index) {
    const solver_contact_t *old = &world->old_contacts[old_index];
    uint32_t previous = world->old_sources[old_index].previous;
    const solver_contact_t *older =
        previous != NO_CONTACT ? &world->older_contacts[previous] : NULL;
    for (int i = 0; i < contact->point_count; i++) {
        solver_point_t *point = &contact->points[i];
        const solver_point_t *last = same_point(old, point->id);
        if (last == NULL) continue;
        const solver_point_t *before = older != NULL ? same_point(older, point->id) : NULL;
        if (before != NULL) {
            point->normal_impulse =
                world->warm_share * (last->normal_impulse + before->normal_impulse);
            point->tangent_impulse =
                world->warm_share * (last->tangent_impulse + before->tangent_impulse);
        } else {
            point->normal_impulse = world->warm_ratio * last->normal_impulse;
            point->tangent_impulse = world->warm_ratio * last->tangent_impulse;
        }
    }
}

/* Copies the impulses of `from`'s points to those of contact that are the
 * same features. */
WORLD_INLINE void impulses_by_feature(solver_contact_t *contact, const solver_contact_t *from) {
    for (int i = 0; i < contact->point_count; i++) {
        for (int j = 0; j < from->point_count; j++) {
            if (contact->points[i].id != from->points[j].id) continue;
            contact->points[i].normal_impulse = from->points[j].normal_impulse;
            contact->points[i].tangent_impulse = from->points[j].tangent_impulse;
        }
    }
}

/* Copies last step's impulses to the points that are the same features;
 * rescaled when this step is not as long as the last (warm_rescaled). */
WORLD_INLINE void warm_from_old(const world_t *world, solver_contact_t *contact,
                                size_t old_index) {
    if (world->warm_ratio != 1.0) {
        warm_rescaled(world, contact, old_index);
        return;
    }
    impulses_by_feature(contact, &world->old_contacts[old_index]);
}

static relative_pose_t relative_pose(const body_t *a, const body_t *b) {
    return (relative_pose_t){body_to_local(a, b->centroid), b->angle - a->angle};
}

static bool pose_is_close(relative_pose_t now, relative_pose_t then) {
    return fabs(now.position.x - then.position.x) < REUSE_DISTANCE &&
           fabs(now.position.y - then.position.y) < REUSE_DISTANCE &&
           fabs(now.angle - then.angle) < REUSE_ANGLE;
}

/* Writes contact n of the step from the pair's result. */
WORLD_INLINE void add_contact(world_t *world, size_t n, body_t *a, body_t *b,
                        const pair_result_t *found) {
    const manifold_t *manifold = &found->manifold;
    solver_contact_t *contact = &world->contacts[n];
    solver_anchor_t *anchor = &world->anchors[n];
    contact_source_t *source = &world->sources[n];
    /* The solver's other fields are all set by its prepare step. */
    contact->a = a->solver_index;
    contact->b = b->solver_index;
    contact->normal = manifold->normal;
    contact->friction = sqrt(a->friction * b->friction);
    contact->restitution = max_of(a->elasticity, b->elasticity);
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
    source->key = pair_key(a, b);
    source->body_a = a;
    source->body_b = b;
    source->features = found->features;
    source->pose = found->pose;
    source->previous = found->old != SIZE_MAX ? (uint32_t)found->old : NO_CONTACT;
    if (found->old != SIZE_MAX) warm_from_old(world, contact, found->old);
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
    if (old != SIZE_MAX && pose_is_close(found->pose, world->old_sources[old].pose) &&
        !world->old_sources[old].features.on_run) {
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
    found->manifold = manifold_collide(a, b, margin, &found->features, &separation);
    if (separation > margin) {
        found->apart = true;
        found->gap = (pair_gap_t){key, found->pose, separation};
    }
}

/* How many pairs ahead the narrowphase asks for body b's first two lines:
 * b is anywhere in the scene, and waiting on it was a third of the time of
 * evaluating a manifold (pile(4000)). A macro: GCC deems a function of
 * prefetches alone const and drops its calls. */
enum { PAIR_AHEAD = 4 };
#define PREFETCH_BODY_B(bodies, pairs, at, count)                        \
    do {                                                                 \
        if ((at) < (count)) {                                            \
            const char *line_ = (const char *)(bodies)[(pairs)[at].b];   \
            __builtin_prefetch(line_);                                   \
            __builtin_prefetch(line_ + 64);                              \
        }                                                                \
    } while (0)

/* Tells body a where its groups of this step's contacts and gaps lie. */
WORLD_INLINE void place_group(const world_t *world, body_t *a, size_t first, size_t end,
                              size_t gap_first, size_t gap_end) {
    a->contact_first = (uint32_t)first;
    a->contact_count = (uint32_t)(end - first);
    a->gap_first = (uint32_t)gap_first;
    a->gap_count = (uint32_t)(gap_end - gap_first);
    a->contact_step = (uint32_t)world->step_number;
}

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
        if (found.manifold.point_count > 0) add_contact(world, world->contact_count++, a, b, &found);
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
    size_t made = 0, apart = 0;
    end = group_start(split->pairs, split->pair_count, end);
    for (size_t i = group_start(split->pairs, split->pair_count, begin); i < end; i++) {
        PREFETCH_BODY_B(split->bodies, split->pairs, i + PAIR_AHEAD, split->pair_count);
        const broadphase_pair_t *pair = &split->pairs[i];
        collide_pair(world, split->bodies[pair->a], split->bodies[pair->b], pair,
                     &world->results[i]);
        made += world->results[i].manifold.point_count > 0;
        apart += world->results[i].apart;
    }
    world->chunk_first[chunk + 1] = made;
    world->chunk_gap_first[chunk + 1] = apart;
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
            const pair_result_t *found = &world->results[i];
            if (found->manifold.point_count > 0) {
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
    }
    workers_for(world->workers, pair_count, emit_chunk, &split);
    world->contact_count = world->chunk_first[chunks];
    world->gap_count = world->chunk_gap_first[chunks];
}

/* Exchanges two buffers with their capacities. */
static void swap_buffers(void **now, size_t *now_capacity, void **old, size_t *old_capacity) {
    void *buffer = *now;
    *now = *old;
    *old = buffer;
    size_t capacity = *now_capacity;
    *now_capacity = *old_capacity;
    *old_capacity = capacity;
}

/* Last step's contacts and gaps become the old ones, and the old contacts
 * the older; this step's are written over the buffers of the step before
 * (the contacts' over those of two steps before). */
static void swap_contact_buffers(world_t *world) {
    swap_buffers((void **)&world->contacts, &world->contact_capacity,
                 (void **)&world->old_contacts, &world->old_contact_capacity);
    swap_buffers((void **)&world->contacts, &world->contact_capacity,
                 (void **)&world->older_contacts, &world->older_contact_capacity);
    swap_buffers((void **)&world->sources, &world->source_capacity,
                 (void **)&world->old_sources, &world->old_source_capacity);
    swap_buffers((void **)&world->gaps, &world->gap_capacity, (void **)&world->old_gaps,
                 &world->old_gap_capacity);
    world->old_count = world->contact_count;
    world->contact_count = 0;
    world->old_gap_count = world->gap_count;
    world->gap_count = 0;
    world->step_number++;
}

static void narrowphase(world_t *world, body_t **bodies, const broadphase_pair_t *pairs,
                        size_t pair_count) {
    swap_contact_buffers(world);
    /* A pair makes at most one contact. The buffers that take turns grow
     * together (they keep their contents), so a new most of pairs costs
     * one step's allocations, not one in each of the next steps. */
    size_t n = pair_count;
    memory_reserve((void **)&world->contacts, &world->contact_capacity, n, sizeof(solver_contact_t));
    memory_reserve((void **)&world->old_contacts, &world->old_contact_capacity, n,
                   sizeof(solver_contact_t));
    memory_reserve((void **)&world->older_contacts, &world->older_contact_capacity, n,
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

/* A moment of impact is found to within this fraction of the two bodies'
 * radii (m per m) of touching. */
static const double IMPACT_TOLERANCE = 1e-12;

/* The motion the solver's times of impact assume for a body's row. */
static toi_motion_t impact_motion(const solver_state_t *state) {
    return (toi_motion_t){state->v_start, state->acceleration, state->w_start};
}

/* The velocity at the start of the step of b's point at lever arm r_b over
 * a's at r_a. */
static vector_t start_approach(const solver_state_t *sa, vector_t r_a, const solver_state_t *sb,
                               vector_t r_b) {
    return vec_subtract(vec_add(sb->v_start, vec_cross_scalar(sb->w_start, r_b)),
                        vec_add(sa->v_start, vec_cross_scalar(sa->w_start, r_a)));
}

/* Whether the solver will time an impact of contact c within the step: its
 * points all apart, and one that closes its gap within the step faster than
 * the bounce threshold, at the start velocities and accelerations, in the
 * geometry of the start (solver.c, set_target). */
static bool impact_in_step(const solver_contact_t *c, const solver_anchor_t *anchor,
                           const solver_state_t *sa, const solver_state_t *sb, double dt) {
    double pull = vec_dot(c->normal, vec_subtract(sb->acceleration, sa->acceleration));
    double threshold = solver_bounce_threshold(c->restitution, sa, sb);
    bool impact = false;
    for (int i = 0; i < c->point_count; i++) {
        double gap = c->points[i].separation;
        if (!(gap > 0.0)) return false;
        double speed = vec_dot(c->normal, start_approach(sa, anchor->r_a[i], sb, anchor->r_b[i]));
        double tau = solver_time_of_impact(gap, speed, pull, dt);
        impact |= tau >= 0.0 && speed + pull * tau < -threshold;
    }
    return impact;
}

/*
 * Contact n, found where its bodies were at the start of the step, taken
 * again at moment `hit` of the step: the normal, points and lever arms
 * there. Each point's separation becomes the one that the solver's model of
 * the step (each body at its start velocities and acceleration) closes to
 * the point's separation at that moment, so the solver times an impact at
 * it. Impulses stay with the points of the same features.
 */
static void take_at(world_t *world, size_t n, const toi_contact_t *hit) {
    solver_contact_t *c = &world->contacts[n];
    const solver_state_t *sa = &world->states[c->a], *sb = &world->states[c->b];
    const manifold_t *manifold = &hit->manifold;
    vector_t normal = manifold->normal;
    double t = hit->time;
    double pull = vec_dot(normal, vec_subtract(sb->acceleration, sa->acceleration));
    vector_t r_a[2], r_b[2];
    double separation[2];
    for (int i = 0; i < manifold->point_count; i++) {
        r_a[i] = vec_subtract(manifold->points[i].point, hit->centroid_a);
        r_b[i] = vec_subtract(manifold->points[i].point, hit->centroid_b);
        double speed = vec_dot(normal, start_approach(sa, r_a[i], sb, r_b[i]));
        double at = manifold->points[i].separation;
        separation[i] = at - t * (speed + 0.5 * pull * t);
        /* A pair that passes may part at a point the model would have
         * touching earlier: it keeps the gap it ends with. */
        if (!hit->touches) separation[i] = max_of(separation[i], at);
    }
    solver_contact_t before = *c;
    solver_anchor_t *anchor = &world->anchors[n];
    contact_source_t *source = &world->sources[n];
    c->normal = normal;
    c->point_count = manifold->point_count;
    c->edge_ends = hit->features.edge_ends && manifold->point_count == 2;
    for (int i = 0; i < manifold->point_count; i++) {
        solver_point_t *point = &c->points[i];
        anchor->r_a[i] = r_a[i];
        anchor->r_b[i] = r_b[i];
        point->separation = separation[i];
        point->id = manifold->points[i].id;
        point->normal_impulse = point->tangent_impulse = 0.0;
        source->points[i] = manifold->points[i].point;
    }
    impulses_by_feature(c, &before);
    double cos_a = cos(hit->angle_a), sin_a = sin(hit->angle_a);
    vector_t d = vec_subtract(hit->centroid_b, hit->centroid_a);
    source->features = hit->features;
    source->pose = (relative_pose_t){{cos_a * d.x + sin_a * d.y, -sin_a * d.x + cos_a * d.y},
                                     hit->angle_b - hit->angle_a};
}

/* Contact n taken at the moment of its impact, if the solver will time one
 * (take_impacts). Not inlined: a scene without elastic contacts pays only
 * for the loop that looks for them. */
static __attribute__((noinline)) void take_impact(world_t *world, size_t n, double dt) {
    const solver_contact_t *c = &world->contacts[n];
    const solver_state_t *sa = &world->states[c->a], *sb = &world->states[c->b];
    if (!impact_in_step(c, &world->anchors[n], sa, sb, dt)) return;
    body_t *a = world->sources[n].body_a, *b = world->sources[n].body_b;
    toi_motion_t ma = impact_motion(sa), mb = impact_motion(sb);
    double margin = world->margins[c->a] + world->margins[c->b];
    toi_contact_t hit;
    bool found = time_of_impact(a, &ma, b, &mb, dt, margin,
                                IMPACT_TOLERANCE * (a->radius + b->radius),
                                &world->toi_scratch, &hit);
    if (found && hit.time > 0.0) take_at(world, n, &hit);
}

/*
 * Every elastic contact in which the solver would time an impact within the
 * step is taken where its bodies first touch, or, when they pass without
 * touching, where they are at the end of the step: the collision pass then
 * bounces through the geometry of the moment of impact, and a near miss is
 * not bounced along a normal of the start (docs/design.md, "Impacts within
 * the step").
 */
static void take_impacts(world_t *world, double dt, size_t largest_polygon) {
    toi_scratch_reserve(&world->toi_scratch, largest_polygon);
    for (size_t n = 0; n < world->contact_count; n++) {
        if (world->contacts[n].restitution != 0.0) take_impact(world, n, dt);
    }
}

/* Hands the solver's results to the bodies' motions: the velocities it
 * chose and the displacements it moved them by. */
WORLD_INLINE void write_back_range(const world_t *world, integrator_motion_t *motions, size_t begin,
                             size_t end) {
    for (size_t i = begin; i < end; i++) {
        const solver_velocity_t *velocity = &world->velocities[i];
        const solver_displacement_t *moved = &world->displacements[i];
        integrator_motion_t *motion = &motions[i];
        motion->velocity = velocity->v;
        motion->angular_velocity = velocity->w;
        motion->displacement = moved->dx;
        motion->rotation = moved->dtheta;
    }
}

static void write_back_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const body_loop_t *loop = context;
    (void)chunk;
    write_back_range(loop->world, loop->motions, begin, end);
}

static void write_back(world_t *world, integrator_motion_t *motions, size_t count) {
    if (world->workers != NULL) {
        body_loop_t loop = {world, NULL, NULL, motions, 0.0};
        workers_for(world->workers, count, write_back_chunk, &loop);
        return;
    }
    write_back_range(world, motions, 0, count);
}

/* Whether a contact holds its bodies together this step. */
static bool is_touching(const solver_contact_t *c) {
    for (int j = 0; j < c->point_count; j++) {
        const solver_point_t *p = &c->points[j];
        if (p->separation <= 0.0 || p->normal_impulse + p->restitution_impulse > 0.0) return true;
    }
    return false;
}

/* The sleep timers over the workers, each chunk counting its ready bodies. */
typedef struct {
    const sleep_step_t *step;
    size_t ready[WORKERS_MAX_CHUNKS];
} sleep_split_t;

static void time_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    sleep_split_t *split = context;
    split->ready[chunk] = sleep_time_bodies(split->step, begin, end);
}

static size_t time_bodies(world_t *world, const sleep_step_t *step) {
    sleep_split_t split = {step, {0}};
    world_for_bodies(world, step->count, time_chunk, &split);
    size_t ready = 0;
    for (size_t k = 0; k < WORKERS_MAX_CHUNKS; k++) ready += split.ready[k];
    return ready;
}

/* Hands the step to sleep.c; the touching contacts are listed and the
 * islands joined only when some body has been slow long enough for its
 * island to sleep, and then every SLEEP_CHECK_STEPS steps (a pile whose
 * bottom rests and top creeps would pay for islands at every step). */
static void update_sleep(world_t *world, body_t **bodies, size_t count, double dt,
                         body_t **all_bodies, size_t all_count) {
    sleep_step_t step = {bodies,          world->velocities, world->displacements,
                         world->states,   world->proxies,    count,
                         dt,              CONTACT_MARGIN};
    if (time_bodies(world, &step) > 0 && sleep_is_check_step(&world->sleep)) {
        memory_reserve((void **)&world->links, &world->link_capacity, world->contact_count,
                       sizeof(sleep_link_t));
        size_t link_count = 0;
        for (size_t i = 0; i < world->contact_count; i++) {
            const solver_contact_t *c = &world->contacts[i];
            if (is_touching(c)) {
                world->links[link_count++] = (sleep_link_t){c->a, c->b};
            }
        }
        sleep_islands(&world->sleep, &step, world->links, link_count);
    }
    sleep_wake_reached(&world->sleep, &step, all_bodies, all_count);
}

/* The pipeline over bodies[0 .. count), which are all the scene's bodies
 * or, with sleeping, its awake ones. */
static void run_pipeline(world_t *world, body_t **bodies, integrator_motion_t *motions,
                         size_t count, const world_step_t *step, scene_stats_t *stats,
                         body_t **all_bodies, size_t all_count) {
    /* A new world searches before loading, whose checks would read what an
     * older world (since freed) left in the bodies. */
    if (!world->seams.found) seams_find(&world->seams, bodies, count);
    if (load_bodies(world, bodies, motions, count, step)) {
        seams_find(&world->seams, bodies, count);
    }
    const broadphase_pair_t *pairs;
    size_t pair_count = broadphase_find_pairs(world->broadphase, world->proxies, count, &pairs,
                                              &stats->broadphase_tests);
    narrowphase(world, bodies, pairs, pair_count);
    take_impacts(world, step->dt, step->largest_polygon);
    solver_settings_t settings = {step->dt, step->position_weight, world->velocity_iterations,
                                  world->position_iterations};
    solver_bodies_t rows = {world->velocities, world->displacements, world->states, count};
    solver_solve(&world->wide, &world->shock, world->contacts, world->anchors,
                 world->contact_count, &rows, &settings);
    if (step->sleeping) update_sleep(world, bodies, count, step->dt, all_bodies, all_count);
    write_back(world, motions, count);

    stats->broadphase_pairs += pair_count;
    stats->contacts += world->contact_count;
    for (size_t i = 0; i < world->contact_count; i++) {
        stats->contact_points += (size_t)world->contacts[i].point_count;
    }
}

/* The awake bodies and copies of their motions; returns how many. */
static size_t gather_awake(world_t *world, body_t **bodies, const integrator_motion_t *motions,
                           size_t count) {
    memory_reserve((void **)&world->active, &world->active_capacity, count, sizeof(body_t *));
    memory_reserve((void **)&world->active_motions, &world->active_motion_capacity, count,
                   sizeof(integrator_motion_t));
    memory_reserve((void **)&world->active_index, &world->active_index_capacity, count,
                   sizeof(size_t));
    size_t active = 0;
    for (size_t i = 0; i < count; i++) {
        if (bodies[i]->asleep) continue;
        world->active[active] = bodies[i];
        world->active_motions[active] = motions[i];
        world->active_index[active++] = i;
    }
    return active;
}

/* The ratios by which warm starting rescales last step's impulses when
 * this step's dt differs (warm_rescaled); the ratio is exactly 1 for an
 * equal dt, and the impulses are then copied unchanged. */
static void time_step(world_t *world, double dt) {
    world->warm_ratio = world->last_dt > 0.0 ? dt / world->last_dt : 1.0;
    world->warm_share = world->last_dt > 0.0 ? dt / (world->last_dt + world->older_dt) : 1.0;
    world->older_dt = world->last_dt;
    world->last_dt = dt;
}

void world_wake_changed(world_t *world, body_t **bodies, size_t count, double dt,
                        vector_t gravity) {
    if (!sleep_any(&world->sleep)) return;
    /* Last step's reach covered a step as long as itself. */
    bool longer = dt > world->last_dt;
    for (size_t i = 0; i < count; i++) {
        if (bodies[i]->changed) {
            sleep_wake_changed(&world->sleep, bodies[i], dt, gravity, CONTACT_MARGIN);
        } else if (longer) {
            sleep_wake_ahead(&world->sleep, bodies[i], dt, gravity, CONTACT_MARGIN);
        }
    }
}

void world_step(world_t *world, body_t **bodies, integrator_motion_t *motions, size_t count,
                const world_step_t *step, scene_stats_t *stats) {
    time_step(world, step->dt);
    /* Nobody asleep: every body is in the step, with nothing to gather. */
    if (!step->sleeping || !sleep_any(&world->sleep)) {
        run_pipeline(world, bodies, motions, count, step, stats, bodies, count);
        return;
    }
    size_t active = gather_awake(world, bodies, motions, count);
    run_pipeline(world, world->active, world->active_motions, active, step, stats, bodies, count);
    for (size_t k = 0; k < active; k++) motions[world->active_index[k]] = world->active_motions[k];
}

size_t world_contact_count(const world_t *world) {
    return world->contact_count;
}

contact_t world_get_contact(const world_t *world, size_t index) {
    const solver_contact_t *c = &world->contacts[index];
    const contact_source_t *source = &world->sources[index];
    contact_t entry = {.kind = CONTACT_WORLD, .body1 = source->body_a, .body2 = source->body_b,
                       .axis = c->normal, .point_count = (size_t)c->point_count};
    for (int j = 0; j < c->point_count; j++) {
        entry.points[j] = source->points[j];
        entry.separation[j] = c->points[j].separation;
        entry.normal_impulse[j] = c->points[j].normal_impulse + c->points[j].restitution_impulse;
        entry.tangent_impulse[j] =
            c->points[j].tangent_impulse + c->points[j].restitution_tangent_impulse;
        entry.touching |= c->points[j].separation <= 0.0 || entry.normal_impulse[j] > 0.0;
    }
    return entry;
}

void world_get_memory(const world_t *world, size_t index, scene_contact_memory_t *memory) {
    const solver_contact_t *c = &world->contacts[index];
    const contact_source_t *source = &world->sources[index];
    *memory = (scene_contact_memory_t){
        .body_a = source->body_a,
        .body_b = source->body_b,
        .normal = c->normal,
        .point_count = c->point_count,
        .flip = source->features.flip,
        .edge_ends = source->features.edge_ends,
        .feature_count = source->features.point_count,
        .face_normal = source->features.normal,
        .face_point = source->features.face_point,
        .pose = source->pose.position,
        .pose_angle = source->pose.angle,
    };
    for (int j = 0; j < c->point_count; j++) {
        const solver_point_t *p = &c->points[j];
        memory->points[j] = (scene_memory_point_t){
            p->id, source->points[j], p->separation, p->normal_impulse, p->tangent_impulse,
            p->restitution_impulse, p->restitution_tangent_impulse};
    }
    for (int j = 0; j < source->features.point_count; j++) {
        memory->feature_points[j] = source->features.points[j];
        memory->feature_ids[j] = source->features.ids[j];
    }
    if (source->previous == NO_CONTACT) return;
    const solver_contact_t *before = &world->old_contacts[source->previous];
    memory->previous_count = before->point_count;
    for (int j = 0; j < before->point_count; j++) {
        const solver_point_t *p = &before->points[j];
        memory->previous[j] = (scene_memory_previous_t){p->id, p->normal_impulse,
                                                        p->tangent_impulse};
    }
}

/* Writes the pair's contact of the step before last from a memory into
 * old_contacts at `at`, which the next step's swap makes the contacts of
 * the step before its last; returns where, or NO_CONTACT when it had none
 * (world_restore_memory). */
static uint32_t add_remembered_before(world_t *world, size_t at,
                                      const scene_contact_memory_t *memory) {
    if (memory->previous_count == 0) return NO_CONTACT;
    solver_contact_t *before = &world->old_contacts[at];
    *before = (solver_contact_t){.point_count = memory->previous_count};
    for (int j = 0; j < memory->previous_count; j++) {
        const scene_memory_previous_t *from = &memory->previous[j];
        before->points[j].id = from->id;
        before->points[j].normal_impulse = from->normal_impulse;
        before->points[j].tangent_impulse = from->tangent_impulse;
    }
    return (uint32_t)at;
}

/* Writes contact n of the step from a memory (world_restore_memory). */
static void add_remembered(world_t *world, size_t n, const scene_contact_memory_t *memory) {
    solver_contact_t *contact = &world->contacts[n];
    contact_source_t *source = &world->sources[n];
    *contact = (solver_contact_t){.normal = memory->normal, .point_count = memory->point_count};
    *source = (contact_source_t){
        .key = pair_key(memory->body_a, memory->body_b),
        .body_a = memory->body_a,
        .body_b = memory->body_b,
        .features = {.flip = memory->flip,
                     .edge_ends = memory->edge_ends,
                     .point_count = memory->feature_count,
                     .normal = memory->face_normal,
                     .face_point = memory->face_point},
        .pose = {memory->pose, memory->pose_angle},
        .previous = add_remembered_before(world, n, memory),
    };
    for (int j = 0; j < memory->point_count; j++) {
        const scene_memory_point_t *from = &memory->points[j];
        solver_point_t *p = &contact->points[j];
        p->id = from->id;
        p->separation = from->separation;
        p->normal_impulse = from->normal_impulse;
        p->tangent_impulse = from->tangent_impulse;
        p->restitution_impulse = from->restitution_impulse;
        p->restitution_tangent_impulse = from->restitution_tangent_impulse;
        source->points[j] = from->point;
    }
    for (int j = 0; j < memory->feature_count; j++) {
        source->features.points[j] = memory->feature_points[j];
        source->features.ids[j] = memory->feature_ids[j];
    }
}

void world_restore_memory(world_t *world, const scene_contact_memory_t *memories,
                          size_t count) {
    /* A new step: whatever groups the bodies had point to an older one. */
    world->step_number++;
    memory_reserve((void **)&world->contacts, &world->contact_capacity, count,
                   sizeof(solver_contact_t));
    memory_reserve((void **)&world->sources, &world->source_capacity, count,
                   sizeof(contact_source_t));
    memory_reserve((void **)&world->old_contacts, &world->old_contact_capacity, count,
                   sizeof(solver_contact_t));
    world->contact_count = count;
    world->gap_count = 0;
    for (size_t i = 0; i < count;) {
        body_t *a = memories[i].body_a;
        size_t first = i;
        for (; i < count && memories[i].body_a == a; i++) {
            add_remembered(world, i, &memories[i]);
        }
        place_group(world, a, first, i, 0, 0);
    }
}

void world_forget_removed(world_t *world) {
    size_t kept = 0;
    for (size_t i = 0; i < world->contact_count;) {
        body_t *a = world->sources[i].body_a;
        size_t first = kept;
        for (; i < world->contact_count && world->sources[i].body_a == a; i++) {
            if (a->removed || world->sources[i].body_b->removed) continue;
            world->contacts[kept] = world->contacts[i];
            world->sources[kept++] = world->sources[i];
        }
        if (!a->removed) {
            a->contact_first = (uint32_t)first;
            a->contact_count = (uint32_t)(kept - first);
        }
    }
    world->contact_count = kept;
    sleep_forget_removed(&world->sleep);
}

unsigned world_get_sleep_phase(const world_t *world) {
    return world->sleep.steps;
}

void world_set_sleep_phase(world_t *world, unsigned phase) {
    world->sleep.steps = phase;
}

void world_index_sleepers(world_t *world, body_t **bodies, size_t count) {
    sleep_index_asleep(&world->sleep, bodies, count);
}

void world_get_step_lengths(const world_t *world, double *last, double *before) {
    *last = world->last_dt;
    *before = world->older_dt;
}

void world_set_step_lengths(world_t *world, double last, double before) {
    world->last_dt = last;
    world->older_dt = before;
}

bool world_pair_collides(const body_t *body1, const body_t *body2) {
    broadphase_proxy_t proxy1, proxy2;
    set_filter(&proxy1, body1);
    set_filter(&proxy2, body2);
    return broadphase_filters_allow(&proxy1, &proxy2);
}

/* The last completed step's contact of the pair, between steps. */
static size_t find_current(const world_t *world, const body_t *a, uint64_t key) {
    return find_in_step(world->sources, world->contact_count, world->step_number, a, key);
}

bool world_pair_contact(const world_t *world, body_t *body1, body_t *body2, contact_t *contact) {
    size_t index = find_current(world, body1, pair_key(body1, body2));
    if (index != SIZE_MAX) {
        *contact = world_get_contact(world, index);
        return true;
    }
    /* The broadphase ordered the pair the other way: the same contact seen
     * from body1. Normal impulses, separations and points do not depend on
     * the side; the tangent impulse on body1 along the flipped tangent is
     * the one on body2 along the original tangent. */
    index = find_current(world, body2, pair_key(body2, body1));
    if (index == SIZE_MAX) return false;
    *contact = world_get_contact(world, index);
    contact->body1 = body1;
    contact->body2 = body2;
    contact->axis = vec_negate(contact->axis);
    return true;
}
