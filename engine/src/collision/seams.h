#ifndef SEAMS_H
#define SEAMS_H

/*
 * Seams between static bodies. Where two static bodies lie flush (the tiles
 * of a floor or a wall), a body sliding across the joint must meet one
 * surface, as if the tiles were one body: not the side of the next tile
 * (hidden behind the first) nor its corner (which the surface continues).
 * Without this, a box sliding over tiles catches a joint and flips: the
 * "ghost collision" that Box2D answers with chain shapes and Chipmunk with
 * segment neighbours.
 *
 * This module finds, for each static body, what its flush static neighbours
 * do to its edges; the narrowphase (manifold.c, and segment_manifold.c at
 * a chain's open ends) reads the result and keeps contact normals to faces
 * of the combined surface. Two edges of two static
 * bodies are flush when both ends of each lie within SEAM_TOLERANCE of the
 * other's line (1 micrometre, or a thousandth of the shorter edge when that
 * is less). Then:
 *
 * - opposite edges (the bodies on either side of the line) *cover* each
 *   other where they overlap: no contact may rest only on a covered part;
 * - edges in the same direction that meet or overlap end to end *continue*
 *   each other into one flat *run*, and the vertex where one continues
 *   into the other is a *seam vertex*: it is not a corner of the combined
 *   surface;
 * - where faces of a run overlap (a chain's segment lying on a static
 *   box's face, or two boxes' faces over each other), one of them holds
 *   each stretch (seam_edge_t's claim), so that a body there gets one
 *   contact: along the run, the face that reaches furthest takes over
 *   from the one before at the middle of their overlap, a face that
 *   reaches no further than the one holding before it holds nothing, and
 *   of two that reach as far (within the tolerance) a polygon's face holds.
 *
 * Static means infinite mass and inertia, at rest (a kinematic body moving
 * at a velocity takes no part) and not removed; two static bodies are
 * neighbours only when their collision filters are the same, so that every
 * body collides with both or with neither.
 *
 * The seams are found through a broadphase over the static bodies, at the
 * first step of a world and again whenever a static body comes, goes (is
 * removed, starts moving or becomes movable), moves or changes its
 * collision filter, which the world notices while it loads the bodies
 * (seams_body_changed). A scene whose static bodies do not change pays a
 * check of each static body's pose, velocity and filter per step; one
 * whose static bodies have no flush neighbour pays nothing more in the
 * narrowphase. A change searches all static bodies again (O(S) with the
 * grid), so a scene that changes its static bodies often pays that.
 *
 * Allocation: at a search only; arrays grow to the largest scene seen.
 */

#include <stdbool.h>
#include <stddef.h>
#include "dynamics/body_private.h"
#include "collision/broadphase.h"

/* Edges of two static bodies closer than this to each other's line (m) are
 * flush; a thousandth of the shorter edge when that is less. */
extern const double SEAM_TOLERANCE;

/* What the neighbours of a static body do to its edge from vertex i to
 * vertex i + 1 (edges[i] of its record); lengths are in metres along the
 * edge from vertex i. */
typedef struct seam_edge {
    /* [0, start] and [end, length] are covered; -INFINITY and INFINITY
     * when no cover reaches that end. */
    double start, end;
    /* The flat run of edges that continue each other, this one among them:
     * [reach_lo, reach_hi] contains [0, length]. A contact on this face
     * clips the other body to the whole run, as one long face would. */
    double reach_lo, reach_hi;
    /* Of the faces of a run, the one whose stretch [claim_lo, claim_hi]
     * holds the middle of the contact's points keeps the contact: each end
     * where the face continues into a neighbour's is shared with it by the
     * tolerance (at the middle of their overlap where they overlap), each
     * end where the run stops is open (infinite); empty (INFINITY,
     * -INFINITY) for a face that holds nothing. */
    double claim_lo, claim_hi;
    /* The whole edge is covered: no contact takes its normal. */
    bool internal;
    /* Vertex i is a seam vertex. */
    bool smooth;
    /* A neighbour's face continues this one (the run is longer than it),
     * or overlaps it and holds part of it. */
    bool chained;
} seam_edge_t;

/* What a search saw of a static body: its pose and collision filter then,
 * and what its neighbours do to each of its edges. */
typedef struct seam_record {
    vector_t centroid;
    double angle;
    uint32_t category, mask, group;
    seam_edge_t *edges; /* one per edge */
} seam_record_t;

typedef struct {
    /* Whether the seams have been searched for at all (a new world must). */
    bool found;
    broadphase_t *broadphase;
    broadphase_proxy_t *proxies;
    size_t proxy_capacity;
    body_t **statics;
    size_t static_capacity;
    seam_record_t *records;
    size_t record_capacity;
    seam_edge_t *edges;
    size_t edge_capacity;
    struct seam_cover *covers;
    size_t cover_count, cover_capacity;
    /* The runs: a union-find forest over the edges, and each root's extent
     * along its own line. */
    size_t *run_parent;
    size_t run_parent_capacity;
    double *run_lo, *run_hi;
    size_t run_lo_capacity, run_hi_capacity;
    /* The faces of the runs, sorted run by run to share out their claims. */
    struct seam_member *members;
    size_t member_count, member_capacity;
} seams_t;

void seams_free(seams_t *seams);

/* Whether the body counts as static for the seams: a polygon, or a
 * chain's segment by its free face (its edge 1, from its end back to its
 * start; its edge 0 is its back and takes no part), so that a chain that
 * continues a static polygon's face flush joins its run (segment_manifold.h
 * reads the seams at the chain's open ends; the chain's own joins it knows
 * itself). A round body has no flat faces. */
static inline bool seams_is_static(const body_t *body) {
    return (body->kind == BODY_SHAPE_POLYGON || body->kind == BODY_SHAPE_SEGMENT) &&
           body->inverse_mass == 0.0 &&
           body->inverse_inertia == 0.0 && !body->removed &&
           body->velocity.x == 0.0 && body->velocity.y == 0.0 && body->angular_velocity == 0.0;
}

/* Whether the body's part in the seams is not what the last search saw: it
 * became or stopped being static, or moved or changed its filter while
 * static. The caller asks only for bodies of infinite mass and inertia and
 * for listed ones (body->seam_listed); the others cannot have changed. */
static inline bool seams_body_changed(const body_t *body) {
    bool is_static = seams_is_static(body);
    if (is_static != body->seam_listed) return true;
    if (!is_static) return false;
    const seam_record_t *seen = body->seam;
    return body->centroid.x != seen->centroid.x || body->centroid.y != seen->centroid.y ||
           body->angle != seen->angle || body->category != seen->category ||
           body->mask != seen->mask || body->group != seen->group;
}

/* Searches the static bodies among bodies[0 .. count) (every static body of
 * the scene: they never sleep) for flush neighbours, and sets each one's
 * seam record and has_seams; clears them on bodies no longer static. */
void seams_find(seams_t *seams, body_t **bodies, size_t count);

#endif // #ifndef SEAMS_H
