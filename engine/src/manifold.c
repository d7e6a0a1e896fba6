#include "manifold.h"
#include <math.h>
#include "body_private.h"
#include "scalar.h"

/* Prefer polygon a as the reference unless b's face is clearly better, so
 * the choice (and so the feature ids) does not flicker between steps when
 * the two separations are nearly equal. */
static const double REFERENCE_TOLERANCE = 0.0005;

typedef struct {
    double separation;
    size_t edge;
} face_separation_t;

/* The edge of `reference` whose outward normal separates `other` the most:
 * for each edge, the least signed distance of other's vertices from it.
 * Stops early once an edge separates by more than margin.
 *
 * The vertex of `other` nearest an edge's line is its support point in the
 * direction -normal. As the edges turn counter-clockwise, so does that
 * direction, and on a convex counter-clockwise polygon the support vertex
 * only moves forward: one sweep finds all of them, O(n + m) instead of
 * O(n m) (rotating calipers). */
static face_separation_t max_face_separation(const body_t *reference, const body_t *other,
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
    face_separation_t best = {-INFINITY, 0};
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
        if (separation > best.separation) {
            best = (face_separation_t){separation, i};
            if (separation > margin) break;
        }
    }
    return best;
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

manifold_t manifold_collide(body_t *a, body_t *b, double margin, manifold_features_t *features,
                            double *separation) {
    manifold_t manifold = {VEC_ZERO, 0, {{VEC_ZERO, 0.0, 0}, {VEC_ZERO, 0.0, 0}}};
    face_separation_t face_a = max_face_separation(a, b, margin);
    *separation = face_a.separation;
    if (face_a.separation > margin) return manifold;
    face_separation_t face_b = max_face_separation(b, a, margin);
    *separation = max_of(face_a.separation, face_b.separation);
    if (face_b.separation > margin) return manifold;

    bool flip = face_b.separation > face_a.separation + REFERENCE_TOLERANCE;
    const body_t *reference = flip ? b : a;
    const body_t *incident = flip ? a : b;
    size_t ref_edge = flip ? face_b.edge : face_a.edge;
    vector_t ref_normal = reference->world_normals[ref_edge];
    vector_t v1 = reference->world_vertices[ref_edge];
    vector_t v2 = reference->world_vertices[(ref_edge + 1) % reference->count];

    size_t inc_edge = incident_edge(incident, ref_normal);
    size_t inc_next = (inc_edge + 1) % incident->count;
    clip_vertex_t segment[2] = {{incident->world_vertices[inc_edge], (uint32_t)inc_edge},
                                {incident->world_vertices[inc_next], (uint32_t)inc_next}};

    /* Clip to the slab between the side planes of the reference edge. */
    vector_t tangent = vec_normalize(vec_subtract(v2, v1));
    clip_vertex_t once[2], twice[2];
    if (clip_segment(segment, once, vec_negate(tangent), -vec_dot(tangent, v1), CUT_FEATURE[0]) <
        2) {
        return manifold;
    }
    if (clip_segment(once, twice, tangent, vec_dot(tangent, v2), CUT_FEATURE[1]) < 2) {
        return manifold;
    }

    uint32_t base = (flip ? 1u << 24 : 0u) | (uint32_t)ref_edge << 16 | (uint32_t)inc_edge << 8;
    features->flip = flip;
    features->edge_ends = twice[0].feature < CUT_FEATURE[0] && twice[1].feature < CUT_FEATURE[0];
    features->point_count = 2;
    features->normal = reference->local_normals[ref_edge];
    features->face_point = reference->local_vertices[ref_edge];
    for (int i = 0; i < 2; i++) {
        features->points[i] = body_to_local(incident, twice[i].p);
        features->ids[i] = base | (twice[i].feature & 0xff);
    }
    return manifold_evaluate(features, a, b, margin);
}

manifold_t manifold_evaluate(const manifold_features_t *features, const body_t *a,
                             const body_t *b, double margin) {
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
