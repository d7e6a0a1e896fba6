#include "collision/time_of_impact.h"
#include <math.h>
#include "dynamics/body_private.h"
#include "base/memory.h"
#include "base/scalar.h"
#include "collision/round_manifold.h"

/* Rounds of the search (an axis each) before it gives up, and steps of the
 * root finder on one axis. */
enum { MAX_ROUNDS = 20, MAX_ROOT_STEPS = 60 };
/* Steps of conservative advancement on one axis before it gives up. */
enum { MAX_ADVANCES = 32 };
/* Steps of conservative advancement on a round pair's distance before it
 * gives up (a grazing pass). */
enum { MAX_ROUND_ADVANCES = 200 };

/* A body and its motion over the step. */
typedef struct {
    const body_t *body;
    const toi_motion_t *motion;
} mover_t;

/* Where a body is at a time of the step: its centroid and rotation. */
typedef struct {
    vector_t centroid;
    double cos, sin;
} frame_t;

static frame_t frame_at(const mover_t *mover, double t) {
    const body_t *body = mover->body;
    const toi_motion_t *motion = mover->motion;
    frame_t frame = {vec_add(body->centroid, vec_add(vec_multiply(t, motion->velocity),
                                                     vec_multiply(0.5 * t * t,
                                                                  motion->acceleration))),
                     body->rotation_cos, body->rotation_sin};
    if (motion->angular_velocity != 0.0 && t != 0.0) {
        double angle = body->angle + motion->angular_velocity * t;
        frame.cos = cos(angle);
        frame.sin = sin(angle);
    }
    return frame;
}

static vector_t to_world(const frame_t *frame, vector_t local) {
    return vec_rotate_cs(local, frame->cos, frame->sin);
}

static vector_t to_local(const frame_t *frame, vector_t world) {
    return (vector_t){frame->cos * world.x + frame->sin * world.y,
                      -frame->sin * world.x + frame->cos * world.y};
}

/* The least of dot(d, v) over the body's own vertices v, walking from
 * vertex *at to the least (the dot products rise and fall once around a
 * convex polygon); *at receives it, a good start for a nearby d. */
static double least_along(const body_t *body, vector_t d, size_t *at) {
    size_t count = body->count, i = *at;
    const vector_t *vertices = body->local_vertices;
    double least = vec_dot(d, vertices[i]);
    for (int direction = 0; direction < 2; direction++) {
        for (size_t k = 0; k < count; k++) {
            size_t next = direction == 0 ? (i + 1) % count : (i + count - 1) % count;
            double value = vec_dot(d, vertices[next]);
            if (!(value < least)) break;
            least = value;
            i = next;
        }
    }
    *at = i;
    return least;
}

/* How far polygon `other` lies beyond face `edge` of `reference` (m), both
 * at the given frames; *support is other's nearest vertex. */
static double face_separation(const body_t *reference, const frame_t *at_reference,
                              size_t edge, const body_t *other, const frame_t *at_other,
                              size_t *support) {
    vector_t normal = to_world(at_reference, reference->local_normals[edge]);
    vector_t face = vec_add(at_reference->centroid,
                            to_world(at_reference, reference->local_vertices[edge]));
    double least = least_along(other, to_local(at_other, normal), support) +
                   vec_dot(normal, at_other->centroid);
    return least - vec_dot(normal, face);
}

/* A face of one polygon and how far the other lies beyond it (m). */
typedef struct {
    bool flip;   /* the face is b's */
    size_t edge;
    double separation;
    size_t support;
} axis_t;

typedef struct {
    mover_t a, b;
    /* A bound on how fast any face's separation can change (m/s). */
    double rate;
} pair_t;

/* The face of either polygon beyond which the other lies farthest at t. */
static axis_t separating_axis(const pair_t *pair, double t) {
    frame_t frames[2] = {frame_at(&pair->a, t), frame_at(&pair->b, t)};
    const body_t *bodies[2] = {pair->a.body, pair->b.body};
    axis_t best = {false, 0, -INFINITY, 0};
    for (int flip = 0; flip < 2; flip++) {
        size_t support = 0;
        for (size_t i = 0; i < bodies[flip]->count; i++) {
            double separation = face_separation(bodies[flip], &frames[flip], i,
                                                bodies[1 - flip], &frames[1 - flip], &support);
            if (separation > best.separation) best = (axis_t){flip, i, separation, support};
        }
    }
    return best;
}

/* The separation beyond the axis's face at time t. */
static double axis_separation(const pair_t *pair, axis_t *axis, double t) {
    frame_t frames[2] = {frame_at(&pair->a, t), frame_at(&pair->b, t)};
    const body_t *bodies[2] = {pair->a.body, pair->b.body};
    int r = axis->flip ? 1 : 0;
    return face_separation(bodies[r], &frames[r], axis->edge, bodies[1 - r], &frames[1 - r],
                           &axis->support);
}

/* Whether the axis's separation is concave in t, so that it can cross a
 * level only once on the way down: nothing turns (the face keeps its
 * normal, each vertex's separation is then linear in t plus the relative
 * acceleration's share) and that acceleration does not pull them apart. */
static bool is_concave(const pair_t *pair, const axis_t *axis) {
    if (pair->a.motion->angular_velocity != 0.0 || pair->b.motion->angular_velocity != 0.0) {
        return false;
    }
    const body_t *reference = axis->flip ? pair->b.body : pair->a.body;
    vector_t normal = vec_rotate_cs(reference->local_normals[axis->edge],
                                    reference->rotation_cos, reference->rotation_sin);
    vector_t relative =
        vec_subtract(pair->b.motion->acceleration, pair->a.motion->acceleration);
    double toward = vec_dot(normal, relative);
    return (axis->flip ? -toward : toward) <= 0.0;
}

/*
 * A time in (t, end] at which the axis's separation is within band of
 * level, at or before its first fall to level after t; a negative number
 * when it stays above level until end. from is the separation at t.
 */
static double first_fall(const pair_t *pair, axis_t *axis, double t, double from, double end,
                         double level, double band) {
    double lo = t, s_lo = from, hi = end, s_hi = axis_separation(pair, axis, end);
    if (s_hi > level) {
        /* Conservative advancement: the separation falls no faster than
         * the pair's rate, so it stays above level until lo + (s_lo -
         * level) / rate; and it cannot fall to level and rise back to the
         * end's separation when those two times exceed what is left. */
        if (is_concave(pair, axis)) return -1.0;
        for (int k = 0;; k++) {
            double fall = (s_lo - level) / pair->rate, rise = (s_hi - level) / pair->rate;
            if (fall + rise >= end - lo || k == MAX_ADVANCES) return -1.0;
            if (s_lo - level <= band) return lo;
            double at = lo + fall, s = axis_separation(pair, axis, at);
            if (s <= level) {
                hi = at;
                s_hi = s;
                break;
            }
            lo = at;
            s_lo = s;
        }
    }
    /* Regula falsi with the Illinois rule (the end that stays is weighted
     * down), bisection when the secant lands outside. */
    int kept = 0;
    for (int step = 0; step < MAX_ROOT_STEPS; step++) {
        double at = lo + (hi - lo) * (s_lo - level) / (s_lo - s_hi);
        if (!(at > lo && at < hi)) at = 0.5 * (lo + hi);
        double s = axis_separation(pair, axis, at);
        if (fabs(s - level) <= band) return at;
        if (s > level) {
            lo = at;
            s_lo = s;
            if (kept == -1) s_hi = level + 0.5 * (s_hi - level);
            kept = -1;
        } else {
            hi = at;
            s_hi = s;
            if (kept == 1) s_lo = level + 0.5 * (s_lo - level);
            kept = 1;
        }
        if (hi - lo <= 1e-15 * end) return lo;
    }
    return lo;
}

/* The first time in [0, duration] at which the pair touches, or a negative
 * number when it does not. */
static double first_touch(const pair_t *pair, double duration, double tolerance) {
    double t = 0.0;
    for (int round = 0; round < MAX_ROUNDS; round++) {
        axis_t axis = separating_axis(pair, t);
        if (axis.separation <= tolerance) return t;
        /* Aim inside the tolerance, so that the next round finds them
         * touching without overlapping. */
        t = first_fall(pair, &axis, t, axis.separation, duration, 0.5 * tolerance,
                       0.25 * tolerance);
        if (t < 0.0) return -1.0;
    }
    return -1.0;
}

/*
 * A copy of the mover's body header at time t, its world polygon in `room`
 * (2 count vectors): what manifold_collide and the functions of
 * body_private.h read. The shape stays the body's own.
 */
static void pose_at(body_t *ghost, const mover_t *mover, double t, vector_t *room) {
    const body_t *body = mover->body;
    frame_t frame = frame_at(mover, t);
    *ghost = *body;
    ghost->centroid = frame.centroid;
    ghost->angle = body->angle + mover->motion->angular_velocity * t;
    ghost->rotation_cos = frame.cos;
    ghost->rotation_sin = frame.sin;
    ghost->world_vertices = room;
    ghost->world_normals = room + body->count;
    for (size_t i = 0; i < body->count; i++) {
        ghost->world_vertices[i] = body_to_world(ghost, body->local_vertices[i]);
        ghost->world_normals[i] = body_rotate_vector(ghost, body->local_normals[i]);
    }
}

void toi_scratch_reserve(toi_scratch_t *scratch, size_t largest_polygon) {
    memory_reserve((void **)&scratch->vectors, &scratch->capacity, 4 * largest_polygon,
                   sizeof(vector_t));
}

/* The pair's manifold at time t. */
static bool contact_at(const pair_t *pair, double t, double margin, toi_scratch_t *scratch,
                       toi_contact_t *contact) {
    const body_t *a = pair->a.body, *b = pair->b.body;
    toi_scratch_reserve(scratch, a->count > b->count ? a->count : b->count);
    body_t ghost_a, ghost_b;
    pose_at(&ghost_a, &pair->a, t, scratch->vectors);
    pose_at(&ghost_b, &pair->b, t, scratch->vectors + 2 * a->count);
    double separation;
    contact->manifold = manifold_collide(&ghost_a, &ghost_b, margin, NULL, &contact->features,
                                         &separation);
    contact->time = t;
    contact->centroid_a = ghost_a.centroid;
    contact->centroid_b = ghost_b.centroid;
    contact->angle_a = ghost_a.angle;
    contact->angle_b = ghost_b.angle;
    return contact->manifold.point_count > 0;
}

/*
 * A bound on how fast a face's separation changes over the step (m/s). In
 * the frame of the face's body the other body's points move at most as
 * fast as the centroids move against each other, plus the frame's turn
 * over the centroids' distance, plus the turn between the bodies over the
 * other's radius.
 */
static double separation_rate(const body_t *a, const toi_motion_t *motion_a, const body_t *b,
                              const toi_motion_t *motion_b, double duration) {
    double speed = vec_get_length(vec_subtract(motion_b->velocity, motion_a->velocity)) +
                   duration * vec_get_length(vec_subtract(motion_b->acceleration,
                                                          motion_a->acceleration));
    double distance = vec_get_length(vec_subtract(b->centroid, a->centroid)) + speed * duration;
    double wa = motion_a->angular_velocity, wb = motion_b->angular_velocity;
    return speed + max_of(fabs(wa), fabs(wb)) * distance +
           fabs(wb - wa) * max_of(a->radius, b->radius);
}

/* A pair with a round body or a chain's segment: their exact separation
 * at time t (round_manifold.h), the distance between the shapes when
 * apart. */
static double exact_separation(const pair_t *pair, double t, toi_scratch_t *scratch) {
    const body_t *a = pair->a.body;
    body_t ghost_a, ghost_b;
    pose_at(&ghost_a, &pair->a, t, scratch->vectors);
    pose_at(&ghost_b, &pair->b, t, scratch->vectors + 2 * a->count);
    manifold_features_t features;
    double separation;
    round_manifold_collide(&ghost_a, &ghost_b, -INFINITY, &features, &separation);
    return separation;
}

/* The first touch of a round pair: conservative advancement on the exact
 * distance, which falls no faster than the pair's rate, so each advance by
 * the distance (less half the tolerance) over the rate stops short of the
 * first touch. A negative number when they do not touch in [0, duration]. */
static double round_first_touch(const pair_t *pair, double duration, double tolerance,
                                toi_scratch_t *scratch) {
    const body_t *a = pair->a.body, *b = pair->b.body;
    toi_scratch_reserve(scratch, a->count > b->count ? a->count : b->count);
    double t = 0.0;
    for (int k = 0; k < MAX_ROUND_ADVANCES; k++) {
        double separation = exact_separation(pair, t, scratch);
        if (separation <= tolerance) return t;
        if (!(pair->rate > 0.0)) return -1.0;
        t += (separation - 0.5 * tolerance) / pair->rate;
        if (t > duration) return -1.0;
    }
    return -1.0;
}

bool time_of_impact(const body_t *a, const toi_motion_t *motion_a, const body_t *b,
                    const toi_motion_t *motion_b, double duration, double margin,
                    double tolerance, toi_scratch_t *scratch, toi_contact_t *contact) {
    pair_t pair = {{a, motion_a}, {b, motion_b},
                   separation_rate(a, motion_a, b, motion_b, duration)};
    double t = (a->kind | b->kind) != BODY_SHAPE_POLYGON
                   ? round_first_touch(&pair, duration, tolerance, scratch)
                   : first_touch(&pair, duration, tolerance);
    contact->touches = t >= 0.0;
    if (!contact->touches) return contact_at(&pair, duration, INFINITY, scratch, contact);
    return contact_at(&pair, t, margin, scratch, contact);
}
