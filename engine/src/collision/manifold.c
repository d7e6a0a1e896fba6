#include "collision/manifold.h"
#include <math.h>
#include "dynamics/body_private.h"
#include "base/scalar.h"
#include "collision/seams.h"
#include "collision/round_manifold.h"
#include "collision/segment_manifold.h"

/* Prefer polygon a as the reference unless b's face is clearly better, so
 * the choice (and so the feature ids) does not flicker between steps when
 * the two separations are nearly equal. */
static const double REFERENCE_TOLERANCE = 0.0005;

const double MANIFOLD_KEEP_TOLERANCE = 0.0001;

typedef struct {
    double separation;
    size_t edge;
} face_separation_t;

/* A polygon's two faces that separate the other polygon the most. */
typedef struct {
    face_separation_t best, second;
} face_ranking_t;

/* Faces of the two bodies whose normals are closer than this to opposite
 * (cosine) give nearly the same contact: which of them is the reference is
 * REFERENCE_TOLERANCE's choice, and not an axis that can overtake it. */
static const double FACING_COSINE = 0.995;

/* The faces of `reference` whose outward normals separate `other` the
 * most: for each edge, the least signed distance of other's vertices from
 * it. Stops early once an edge separates by more than margin.
 *
 * The vertex of `other` nearest an edge's line is its support point in the
 * direction -normal. As the edges turn counter-clockwise, so does that
 * direction, and on a convex counter-clockwise polygon the support vertex
 * only moves forward: one sweep finds all of them, O(n + m) instead of
 * O(n m) (rotating calipers). */
static face_ranking_t max_face_separation(const body_t *reference, const body_t *other,
                                          double margin) {
    const vector_t *vertices = other->world_vertices;
    size_t count = other->count;
    vector_t normal = reference->world_normals[0];
    size_t support = 0;
    double least = vec_dot(normal, vertices[0]);
    for (size_t j = 1; j < count; j++) {
        double d = vec_dot(normal, vertices[j]);
        if (d < least) {
            least = d;
            support = j;
        }
    }
    face_ranking_t ranking = {{-INFINITY, 0}, {-INFINITY, 0}};
    for (size_t i = 0; i < reference->count; i++) {
        normal = reference->world_normals[i];
        least = vec_dot(normal, vertices[support]);
        for (size_t step = 0; step < count; step++) {
            size_t next = support + 1 == count ? 0 : support + 1;
            double d = vec_dot(normal, vertices[next]);
            if (!(d < least)) break;
            least = d;
            support = next;
        }
        double separation = least - vec_dot(normal, reference->world_vertices[i]);
        if (separation > ranking.best.separation) {
            ranking.second = ranking.best;
            ranking.best = (face_separation_t){separation, i};
            if (separation > margin) break;
        } else if (separation > ranking.second.separation) {
            ranking.second = (face_separation_t){separation, i};
        }
    }
    return ranking;
}

/* How much the reference face's separation exceeds that of every other
 * axis that could take its place (m): its own body's best other face, and
 * the other body's best face that does not face it (FACING_COSINE). While
 * the bodies move less than half of this, no other axis overtakes it. */
static double reference_lead(const body_t *reference, face_separation_t face,
                             face_ranking_t own, const body_t *other, face_ranking_t theirs) {
    vector_t normal = reference->world_normals[face.edge];
    face_separation_t mine = own.best.edge != face.edge ? own.best : own.second;
    face_separation_t rival = theirs.best;
    if (vec_dot(normal, other->world_normals[rival.edge]) < -FACING_COSINE) rival = theirs.second;
    return face.separation - max_of(mine.separation, rival.separation);
}

/* The separation of `other` from `reference`'s face `edge` (m). */
static double face_separation(const body_t *reference, size_t edge, const body_t *other) {
    vector_t normal = reference->world_normals[edge];
    double least = INFINITY;
    for (size_t j = 0; j < other->count; j++) {
        least = min_of(least, vec_dot(normal, other->world_vertices[j]));
    }
    return least - vec_dot(normal, reference->world_vertices[edge]);
}

/* Last step's reference face of the pair when it is not the face chosen
 * now (flip, *face) but still within MANIFOLD_KEEP_TOLERANCE of the best
 * (*face: it and its separation), so that faces of nearly equal separation
 * (a corner against a corner, the flush faces of many-sided polygons) do
 * not take turns from step to step, each turn a new normal and new points.
 * Mostly last step's face is the one chosen: then nothing is searched. */
static bool keep_last_face(const body_t *a, const body_t *b, const manifold_features_t *last,
                           bool flip, double best, face_separation_t *face) {
    if (last == NULL || last->point_count == 0 || !isfinite(last->lead)) return false;
    const body_t *reference = last->flip ? b : a;
    if (last->flip == flip) {
        vector_t chosen = reference->local_normals[face->edge];
        if (chosen.x == last->normal.x && chosen.y == last->normal.y) return false;
    }
    for (size_t i = 0; i < reference->count; i++) {
        vector_t n = reference->local_normals[i];
        if (n.x != last->normal.x || n.y != last->normal.y) continue;
        double separation = face_separation(reference, i, last->flip ? a : b);
        if (separation < best - MANIFOLD_KEEP_TOLERANCE) return false;
        *face = (face_separation_t){separation, i};
        return true;
    }
    return false;
}

/* The edge of `incident` most anti-parallel to normal. */
static size_t incident_edge(const body_t *incident, vector_t normal) {
    size_t best = 0;
    double least = INFINITY;
    for (size_t i = 0; i < incident->count; i++) {
        double d = vec_dot(incident->world_normals[i], normal);
        if (d < least) {
            least = d;
            best = i;
        }
    }
    return best;
}

typedef struct {
    vector_t p;
    uint32_t feature;
} clip_vertex_t;

/* The feature of a point made by a clipping cut, one per side plane: out
 * of the range of vertex indices, the same low byte in the ids. */
static const uint32_t CUT_FEATURE[2] = {0xffffff80u, 0xffffff81u};

/* Keeps the part of segment in[0..1] where dot(direction, p) <= offset.
 * Returns how many points are left (0 to 2); a point made by the cut gets
 * `cut_feature`. */
static int clip_segment(const clip_vertex_t in[2], clip_vertex_t out[2], vector_t direction,
                        double offset, uint32_t cut_feature) {
    double d0 = vec_dot(direction, in[0].p) - offset;
    double d1 = vec_dot(direction, in[1].p) - offset;
    int n = 0;
    if (d0 <= 0.0) out[n++] = in[0];
    if (d1 <= 0.0) out[n++] = in[1];
    if (d0 * d1 < 0.0) {
        double t = d0 / (d0 - d1);
        out[n].p = vec_add(in[0].p, vec_multiply(t, vec_subtract(in[1].p, in[0].p)));
        out[n].feature = cut_feature;
        n++;
    }
    return n;
}

/* For the clipping that every new manifold runs, inlined into the search
 * as it was before the seams' path shared it (called, pile(1000) ran 0.13%
 * more instructions). */
#if defined(__GNUC__)
#define MANIFOLD_INLINE static inline __attribute__((always_inline))
#else
#define MANIFOLD_INLINE static inline
#endif

/* The incident edge of `incident` (the one most anti-parallel to the
 * reference face ref_edge), clipped to the face's side planes. */
typedef struct {
    size_t inc_edge;
    clip_vertex_t points[2];
} clipped_t;

/* Clips incident's edge most anti-parallel to reference's face ref_edge to
 * the slab -lo_offset <= tangent . p <= hi_offset; false when fewer than
 * two points are left (no manifold). */
MANIFOLD_INLINE bool clip_to_slab(const body_t *reference, size_t ref_edge,
                                  const body_t *incident, vector_t tangent, double lo_offset,
                                  double hi_offset, clipped_t *clipped) {
    size_t inc_edge = incident_edge(incident, reference->world_normals[ref_edge]);
    size_t inc_next = (inc_edge + 1) % incident->count;
    clip_vertex_t segment[2] = {{incident->world_vertices[inc_edge], (uint32_t)inc_edge},
                                {incident->world_vertices[inc_next], (uint32_t)inc_next}};
    clip_vertex_t once[2];
    if (clip_segment(segment, once, vec_negate(tangent), lo_offset, CUT_FEATURE[0]) < 2) {
        return false;
    }
    if (clip_segment(once, clipped->points, tangent, hi_offset, CUT_FEATURE[1]) < 2) {
        return false;
    }
    clipped->inc_edge = inc_edge;
    return true;
}

/* Clips to the slab between the side planes of the reference edge. */
MANIFOLD_INLINE bool clip_incident(const body_t *reference, size_t ref_edge,
                                   const body_t *incident, clipped_t *clipped) {
    vector_t v1 = reference->world_vertices[ref_edge];
    vector_t v2 = reference->world_vertices[(ref_edge + 1) % reference->count];
    vector_t tangent = vec_normalize(vec_subtract(v2, v1));
    return clip_to_slab(reference, ref_edge, incident, tangent, -vec_dot(tangent, v1),
                        vec_dot(tangent, v2), clipped);
}

/* The features of the clipped points on reference's face ref_edge, and the
 * manifold they give. */
MANIFOLD_INLINE manifold_t clipped_manifold(const body_t *a, const body_t *b, bool flip,
                                            size_t ref_edge, const clipped_t *clipped,
                                            double margin, manifold_features_t *features) {
    const body_t *reference = flip ? b : a;
    const body_t *incident = flip ? a : b;
    const clip_vertex_t *twice = clipped->points;
    uint32_t base = (flip ? 1u << 24 : 0u) | (uint32_t)ref_edge << 16 |
                    (uint32_t)clipped->inc_edge << 8;
    features->flip = flip;
    features->edge_ends = twice[0].feature < CUT_FEATURE[0] && twice[1].feature < CUT_FEATURE[0];
    features->on_run = false;
    features->point_count = 2;
    features->normal = reference->local_normals[ref_edge];
    features->face_point = reference->local_vertices[ref_edge];
    for (int i = 0; i < 2; i++) {
        features->points[i] = body_to_local(incident, twice[i].p);
        features->ids[i] = base | (twice[i].feature & 0xff);
    }
    return manifold_evaluate(features, a, b, margin);
}

/*
 * Seams (seams.h): `body` is static and has flush neighbours. A contact
 * must take the normal of a face of the combined surface, and the faces of
 * a flat run must act as one long face:
 * - body's face as the reference: refused when it is internal, or when
 *   every clipped point of the other body lies on its covered part (the
 *   neighbour that covers it holds those points). A face of a run clips the
 *   other body to the whole run, and keeps the contact only when the
 *   middle of the points within the margin lies on its own stretch (its
 *   claim), so that one face of the run holds it, as one long face would;
 * - the other body's face as the reference: refused when body's clipped
 *   points include a seam vertex (no corner there to push on), all lie
 *   on a covered part, or their middle lies off the claim of body's face.
 * A refused contact takes body's best face that is not internal (nor the
 * face just refused for its cover) instead, the face that continues past
 * the seam, and is dropped when that one too holds nothing.
 */

/* Where p lies along body's edge i (m from vertex i). */
static double along_edge(const body_t *body, size_t i, vector_t p) {
    vector_t v1 = body->world_vertices[i];
    vector_t v2 = body->world_vertices[(i + 1) % body->count];
    return vec_dot(vec_normalize(vec_subtract(v2, v1)), vec_subtract(p, v1));
}

static bool both_covered(const body_t *body, size_t edge, const clip_vertex_t points[2]) {
    const seam_edge_t *seam = &body->seam->edges[edge];
    if (seam->start == -INFINITY && seam->end == INFINITY) return false;
    for (int i = 0; i < 2; i++) {
        double t = along_edge(body, edge, points[i].p);
        if (!(t <= seam->start || t >= seam->end)) return false;
    }
    return true;
}

/* body's face that is not internal nor `excluded` with the largest
 * separation from other; SIZE_MAX when there is none. */
static size_t best_open_face(const body_t *body, const body_t *other, size_t excluded,
                             double *separation) {
    size_t best = SIZE_MAX;
    *separation = -INFINITY;
    for (size_t i = 0; i < body->count; i++) {
        if (i == excluded || body->seam->edges[i].internal) continue;
        vector_t normal = body->world_normals[i];
        double least = INFINITY;
        for (size_t j = 0; j < other->count; j++) {
            least = min_of(least, vec_dot(normal, vec_subtract(other->world_vertices[j],
                                                               body->world_vertices[i])));
        }
        if (least > *separation) {
            *separation = least;
            best = i;
        }
    }
    return best;
}

/* Clips other's incident edge to body's face: to the face, or to its whole
 * run when it continues into a neighbour's. */
static bool clip_to_face(const body_t *body, size_t face, const body_t *other,
                         clipped_t *clipped) {
    const seam_edge_t *seam = &body->seam->edges[face];
    if (!seam->chained) return clip_incident(body, face, other, clipped);
    vector_t v1 = body->world_vertices[face];
    vector_t v2 = body->world_vertices[(face + 1) % body->count];
    vector_t tangent = vec_normalize(vec_subtract(v2, v1));
    double start = vec_dot(tangent, v1);
    return clip_to_slab(body, face, other, tangent, -(start + seam->reach_lo),
                        start + seam->reach_hi, clipped);
}

/* Whether body's face, one of a run, holds the contact of the clipped
 * points: the middle of those within the margin of the face's line (a
 * point further is no contact) lies on the face's own stretch. Every face
 * of the run finds the same points and so the same middle (but for
 * rounding, which the shared ends of the stretches absorb). */
static bool claims(const body_t *body, size_t face, const clipped_t *clipped, double margin) {
    vector_t normal = body->world_normals[face];
    vector_t v1 = body->world_vertices[face];
    vector_t sum = VEC_ZERO;
    int near = 0;
    for (int i = 0; i < 2; i++) {
        if (vec_dot(normal, vec_subtract(clipped->points[i].p, v1)) > margin) continue;
        sum = vec_add(sum, clipped->points[i].p);
        near++;
    }
    if (near == 0) return false;
    double t = along_edge(body, face, vec_multiply(1.0 / near, sum));
    const seam_edge_t *seam = &body->seam->edges[face];
    return t >= seam->claim_lo && t <= seam->claim_hi;
}

/* Whether body's clipped incident points rest on a seam, or on a stretch
 * of its face's run that another face holds. */
static bool on_seam(const body_t *body, const clipped_t *clipped, double margin) {
    size_t inc_next = (clipped->inc_edge + 1) % body->count;
    for (int i = 0; i < 2; i++) {
        uint32_t feature = clipped->points[i].feature;
        if (feature == clipped->inc_edge && body->seam->edges[feature].smooth) return true;
        if (feature == inc_next && body->seam->edges[feature].smooth) return true;
    }
    if (body->seam->edges[clipped->inc_edge].chained &&
        !claims(body, clipped->inc_edge, clipped, margin)) {
        return true;
    }
    return both_covered(body, clipped->inc_edge, clipped->points);
}

/* The contact on body's face `face` (clipped), or none when another face
 * of its run holds it. */
static manifold_t face_manifold(const body_t *a, const body_t *b, size_t face,
                                const clipped_t *clipped, double margin,
                                manifold_features_t *features) {
    manifold_t none = {VEC_ZERO, 0, {{VEC_ZERO, 0.0, 0}, {VEC_ZERO, 0.0, 0}}};
    bool static_is_b = b->has_seams;
    const body_t *body = static_is_b ? b : a;
    const seam_edge_t *seam = &body->seam->edges[face];
    if (seam->chained && !claims(body, face, clipped, margin)) return none;
    manifold_t manifold = clipped_manifold(a, b, static_is_b, face, clipped, margin, features);
    features->on_run = seam->chained;
    return manifold;
}

static manifold_t collide_at_seams(const body_t *a, const body_t *b, bool flip, size_t ref_edge,
                                   double margin, manifold_features_t *features) {
    manifold_t none = {VEC_ZERO, 0, {{VEC_ZERO, 0.0, 0}, {VEC_ZERO, 0.0, 0}}};
    bool static_is_b = b->has_seams;
    const body_t *body = static_is_b ? b : a, *other = static_is_b ? a : b;
    clipped_t clipped;
    size_t excluded = SIZE_MAX;
    if (flip == static_is_b) {
        if (!body->seam->edges[ref_edge].internal) {
            if (!clip_to_face(body, ref_edge, other, &clipped)) return none;
            if (!both_covered(body, ref_edge, clipped.points)) {
                return face_manifold(a, b, ref_edge, &clipped, margin, features);
            }
            excluded = ref_edge;
        }
    } else {
        if (!clip_incident(other, ref_edge, body, &clipped)) return none;
        if (!on_seam(body, &clipped, margin)) {
            manifold_t manifold = clipped_manifold(a, b, flip, ref_edge, &clipped, margin, features);
            /* Held while no other face of the run holds it: found again. */
            features->on_run = body->seam->edges[clipped.inc_edge].chained;
            return manifold;
        }
    }
    double separation;
    size_t face = best_open_face(body, other, excluded, &separation);
    if (face == SIZE_MAX || separation > margin) return none;
    if (!clip_to_face(body, face, other, &clipped)) return none;
    if (both_covered(body, face, clipped.points)) return none;
    return face_manifold(a, b, face, &clipped, margin, features);
}

manifold_t manifold_collide(body_t *a, body_t *b, double margin, const manifold_features_t *last,
                            manifold_features_t *features, double *separation) {
    if ((a->kind | b->kind) != BODY_SHAPE_POLYGON) {
        if (a->kind == BODY_SHAPE_SEGMENT || b->kind == BODY_SHAPE_SEGMENT) {
            return segment_manifold_collide(a, b, margin, features, separation);
        }
        return round_manifold_collide(a, b, margin, features, separation);
    }
    manifold_t manifold = {VEC_ZERO, 0, {{VEC_ZERO, 0.0, 0}, {VEC_ZERO, 0.0, 0}}};
    face_ranking_t faces_a = max_face_separation(a, b, margin);
    face_separation_t face_a = faces_a.best;
    *separation = face_a.separation;
    if (face_a.separation > margin) return manifold;
    face_ranking_t faces_b = max_face_separation(b, a, margin);
    face_separation_t face_b = faces_b.best;
    *separation = max_of(face_a.separation, face_b.separation);
    if (face_b.separation > margin) return manifold;

    bool flip = face_b.separation > face_a.separation + REFERENCE_TOLERANCE;
    face_separation_t face = flip ? face_b : face_a;
    bool seams = a->has_seams || b->has_seams;
    if (!seams && keep_last_face(a, b, last, flip, *separation, &face)) flip = last->flip;
    size_t ref_edge = face.edge;
    double lead = flip ? reference_lead(b, face, faces_b, a, faces_a)
                       : reference_lead(a, face, faces_a, b, faces_b);
    if (seams) {
        manifold = collide_at_seams(a, b, flip, ref_edge, margin, features);
        if (manifold.point_count == 0) return manifold;
        /* A seam can move the contact to another face: no lead known. */
        vector_t normal = (flip ? b : a)->local_normals[ref_edge];
        bool same_face = features->flip == flip && features->normal.x == normal.x &&
                         features->normal.y == normal.y;
        features->lead = same_face ? lead : 0.0;
        return manifold;
    }
    clipped_t clipped;
    if (!clip_incident(flip ? b : a, ref_edge, flip ? a : b, &clipped)) return manifold;
    manifold = clipped_manifold(a, b, flip, ref_edge, &clipped, margin, features);
    features->lead = lead;
    return manifold;
}

manifold_t manifold_evaluate(const manifold_features_t *features, const body_t *a,
                             const body_t *b, double margin) {
    if ((a->kind | b->kind) != BODY_SHAPE_POLYGON) {
        /* A round pair's manifold is cheap to find again, and exact. */
        manifold_features_t found;
        double separation;
        if (a->kind == BODY_SHAPE_SEGMENT || b->kind == BODY_SHAPE_SEGMENT) {
            return segment_manifold_collide(a, b, margin, &found, &separation);
        }
        return round_manifold_collide(a, b, margin, &found, &separation);
    }
    manifold_t manifold = {VEC_ZERO, 0, {{VEC_ZERO, 0.0, 0}, {VEC_ZERO, 0.0, 0}}};
    const body_t *reference = features->flip ? b : a;
    const body_t *incident = features->flip ? a : b;
    vector_t normal = body_rotate_vector(reference, features->normal);
    vector_t face = body_to_world(reference, features->face_point);
    for (int i = 0; i < features->point_count; i++) {
        vector_t p = body_to_world(incident, features->points[i]);
        double separation = vec_dot(normal, vec_subtract(p, face));
        if (separation > margin) continue;
        manifold_point_t *point = &manifold.points[manifold.point_count++];
        point->separation = separation;
        point->point = vec_subtract(p, vec_multiply(0.5 * separation, normal));
        point->id = features->ids[i];
    }
    manifold.normal = features->flip ? vec_negate(normal) : normal;
    return manifold;
}
