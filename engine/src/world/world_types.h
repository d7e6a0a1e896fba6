#ifndef WORLD_TYPES_H
#define WORLD_TYPES_H

/*
 * The world's data, shared by the parts of its step: the pipeline
 * (world.c), the narrowphase's contacts (narrowphase.c), impacts taken at
 * their moment (impacts.c) and the state kept between steps
 * (world_state.c). Not world_private.h, and world.h is not included:
 * tests/check_house.sh counts both as world.c's, which calls the files
 * that include this one.
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "dynamics/body_private.h"
#include "dynamics/integrator.h"
#include "collision/broadphase.h"
#include "collision/pair_tracker.h"
#include "collision/manifold.h"
#include "collision/seams.h"
#include "collision/time_of_impact.h"
#include "solver/solver.h"
#include "world/sleep.h"
#include "base/workers.h"
#include "base/scalar.h"

typedef struct world world_t;

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
    pair_tracker_t *pairs;
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
     * body a (the pair tracker hands over its pairs sorted by a). */
    solver_contact_t *contacts;
    solver_anchor_t *anchors;
    contact_source_t *sources;
    size_t contact_count, contact_capacity, anchor_capacity, source_capacity;
    /* Their points, counted as they are made (for the step's stats), and
     * those of them with a restitution (impacts.c has nothing to do
     * without one). */
    size_t point_count, elastic_count;

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
    /* Steps the solver has taken since the world began, which pick the
     * order of the next one's sweeps (solver_sweeps_reversed); kept apart
     * from step_number because a saved scene carries it. */
    uint64_t solver_steps;

    /* The step's pairs of bodies a joint joins without collide_connected
     * (smaller index in the high half, sorted), and the broadphase's pairs
     * less those, when there are any. */
    uint64_t *joined;
    size_t joined_capacity;
    broadphase_pair_t *kept_pairs;
    size_t kept_capacity;

    /* Which static bodies lie flush (seams.h), found again when a static
     * body changes; with workers, each chunk of the loading says whether it
     * saw one change. */
    seams_t seams;
    bool seams_changed[WORKERS_MAX_CHUNKS];

    solver_wide_t wide;
    shock_t shock;
    joint_tree_t joint_tree; /* the joints' tree solve (joint_tree.h) */
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
    size_t chunk_points[WORKERS_MAX_CHUNKS], chunk_elastic[WORKERS_MAX_CHUNKS];

    /* Room for time_of_impact's posed polygons. */
    toi_scratch_t toi_scratch;
};

/* A contact's restitution: the larger of its bodies' elasticities. */
static inline double contact_restitution(const body_t *a, const body_t *b) {
    return max_of(a->elasticity, b->elasticity);
}

static inline uint64_t pair_key(const body_t *a, const body_t *b) {
    return (uint64_t)a->id << 32 | b->id;
}

/* The contact of the pair with this key among the contacts body a had as
 * body a in step `step`, whose buffer is sources[0 .. count); SIZE_MAX when
 * the pair had none. A group left from another step (or an older world) is
 * skipped, and the key check rejects whatever else lies at its indices. */
static inline size_t find_in_step(const contact_source_t *sources, size_t count,
                                  uint64_t step, const body_t *a, uint64_t key) {
    if (a->contact_step != (uint32_t)step) return SIZE_MAX;
    size_t end = (size_t)a->contact_first + a->contact_count;
    if (end > count) return SIZE_MAX;
    for (size_t i = a->contact_first; i < end; i++) {
        if (sources[i].key == key) return i;
    }
    return SIZE_MAX;
}

/* How far a point may be from where a vanished point of its contact was
 * and still take that point's impulses (m): a tenth of the smaller body's
 * radius, so that a scene scaled up or down matches the same points
 * (docs/design.md, Warm starting). */
WORLD_INLINE double warm_reach(const body_t *a, const body_t *b) {
    double smaller = a->radius < b->radius ? a->radius : b->radius;
    return 0.1 * smaller;
}

/* Which of `from`'s points each point of a contact continues
 * (match_points): bit j of takes[i] when point i takes from's point j, bit
 * i of same when that is point i's own feature. */
typedef struct {
    unsigned takes[2];
    unsigned same;
} point_match_t;

/* The nearest of points[0 .. count) to `to` within reach that is not in
 * the mask `taken` (bit per point); -1 when none is. */
WORLD_INLINE int nearest_point(vector_t to, const vector_t *points, int count, unsigned taken,
                               double reach) {
    double nearest = reach * reach; /* squared distances: no root */
    int found = -1;
    for (int k = 0; k < count; k++) {
        if (taken & (1u << k)) continue;
        vector_t d = vec_subtract(points[k], to);
        double squared = vec_dot(d, d);
        if (squared >= nearest) continue;
        nearest = squared;
        found = k;
    }
    return found;
}

/*
 * Which of `from`'s points each point of contact continues. The same
 * feature first. Then a point whose feature is new (the reference face
 * passed to the other body, a corner took over from its neighbour) takes
 * the nearest point of `from` that no feature kept, if within reach of it:
 * the load the pair carried there does not vanish with the feature's name.
 * A point of `from` still left over goes to the nearest point whose
 * feature is new, within reach, which then takes two: a manifold's two
 * points can lie together (a capsule's end against another's), and the
 * single point that followed them took the one that carried nothing,
 * while its twin's 2.35 N s was dropped and the warm start threw a capsule
 * at 6 m/s. points and from_points: where the points are (world frame).
 */
WORLD_INLINE point_match_t match_points(const solver_contact_t *contact, const vector_t *points,
                                        const solver_contact_t *from,
                                        const vector_t *from_points, double reach) {
    point_match_t match = {{0u, 0u}, 0u};
    unsigned kept = 0; /* bit j: from's point j is continued by its feature */
    for (int i = 0; i < contact->point_count; i++) {
        for (int j = 0; j < from->point_count; j++) {
            if (contact->points[i].id != from->points[j].id) continue;
            match.takes[i] = 1u << j;
            match.same |= 1u << i;
            kept |= 1u << j;
        }
    }
    if (match.same == (1u << contact->point_count) - 1u ||
        kept == (1u << from->point_count) - 1u) {
        return match;
    }
    for (int i = 0; i < contact->point_count; i++) {
        if (match.same & (1u << i)) continue;
        int j = nearest_point(points[i], from_points, from->point_count, kept, reach);
        if (j < 0) continue;
        match.takes[i] = 1u << j;
        kept |= 1u << j;
    }
    for (int j = 0; j < from->point_count; j++) {
        if (kept & (1u << j)) continue;
        int i = nearest_point(from_points[j], points, contact->point_count, match.same, reach);
        if (i >= 0) match.takes[i] |= 1u << j;
    }
    return match;
}

/*
 * A point of another feature taking the impulses (normal_impulse,
 * tangent_impulse) of a point of `from`: as the impulse they made, along
 * this step's normal. The reference face may have passed to a face at an
 * angle (a corner against a corner), and the same numbers along the new
 * normal pushed where nothing had pushed: in a settled pile(4000) a 55
 * degree switch carried 2.95 N s and threw a body at 5.9 m/s, and an
 * avalanche of 300 bodies followed. A push that would now pull is dropped,
 * and the friction part stays within the cone of what is left. A point of
 * the same feature keeps its numbers: its normal turns only as its face.
 */
WORLD_INLINE void take_impulses(solver_contact_t *contact, solver_point_t *point,
                                vector_t from_normal, double normal_impulse,
                                double tangent_impulse) {
    if (from_normal.x == contact->normal.x && from_normal.y == contact->normal.y) {
        point->normal_impulse = normal_impulse;
        point->tangent_impulse = tangent_impulse;
        return;
    }
    vector_t impulse = vec_add(vec_multiply(normal_impulse, from_normal),
                               vec_multiply(tangent_impulse, vec_perpendicular(from_normal)));
    double pushed = max_of(vec_dot(impulse, contact->normal), 0.0);
    double limit = contact->friction * pushed;
    point->normal_impulse = pushed;
    point->tangent_impulse =
        max_of(-limit, min_of(vec_dot(impulse, vec_perpendicular(contact->normal)), limit));
}

/* Copies the impulses of `from`'s points to the points of contact that
 * continue them (match_points; take_impulses for another feature's, their
 * sum when it takes two). The same features are copied at once, as most
 * are; match_points runs only when a point is left over and so is one of
 * `from`'s. */
WORLD_INLINE void carry_impulses(solver_contact_t *contact, const vector_t *points,
                                 const solver_contact_t *from, const vector_t *from_points,
                                 double reach) {
    unsigned kept = 0;
    int left = 0;
    for (int i = 0; i < contact->point_count; i++) {
        bool same = false;
        for (int j = 0; j < from->point_count; j++) {
            if (contact->points[i].id != from->points[j].id) continue;
            contact->points[i].normal_impulse = from->points[j].normal_impulse;
            contact->points[i].tangent_impulse = from->points[j].tangent_impulse;
            kept |= 1u << j;
            same = true;
        }
        left += !same;
    }
    if (left == 0 || kept == (1u << from->point_count) - 1u) return;
    point_match_t match = match_points(contact, points, from, from_points, reach);
    for (int i = 0; i < contact->point_count; i++) {
        if ((match.same & (1u << i)) || match.takes[i] == 0) continue;
        double normal = 0.0, tangent = 0.0;
        for (int j = 0; j < from->point_count; j++) {
            if (!(match.takes[i] & (1u << j))) continue;
            normal += from->points[j].normal_impulse;
            tangent += from->points[j].tangent_impulse;
        }
        take_impulses(contact, &contact->points[i], from->normal, normal, tangent);
    }
}

/* Tells body a where its groups of this step's contacts and gaps lie. */
WORLD_INLINE void place_group(const world_t *world, body_t *a, size_t first, size_t end,
                              size_t gap_first, size_t gap_end) {
    a->contact_first = (uint32_t)first;
    a->contact_count = (uint32_t)(end - first);
    a->gap_first = (uint32_t)gap_first;
    a->gap_count = (uint32_t)(gap_end - gap_first);
    a->contact_step = (uint32_t)world->step_number;
}

#endif // #ifndef WORLD_TYPES_H
