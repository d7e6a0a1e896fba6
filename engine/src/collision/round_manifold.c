#include "collision/round_manifold.h"
#include <math.h>
#include "base/scalar.h"

/* As manifold.c: a's face is the reference unless b's is clearly better. */
static const double REFERENCE_TOLERANCE = 0.0005;

/* Id bits: a point of a reference face, a point between two vertices, a
 * point between two segments (capsules side by side, or a body on a
 * chain's run), named by its place along a's core (name_along). */
static const uint32_t FACE_ID = 0x40000000u, VERTEX_ID = 0x60000000u, ALONG_ID = 0x50000000u;

/* A shape's core in the world: count vertices, faces from v[i] to
 * v[i + 1] with outward normals n[i] (a segment has two, one per side; a
 * point none), and the radius around it. */
typedef struct {
    size_t count, faces;
    const vector_t *v, *n;
    double radius;
    vector_t room[4];
} core_t;

static void core_of(const body_t *body, core_t *core) {
    if (body->kind == BODY_SHAPE_SEGMENT) {
        /* One face: a chain's segment collides on its free side. */
        core->count = 2;
        core->faces = 1;
        core->v = body->world_vertices;
        core->room[2] = body_rotate_vector(body, body->segment->normal);
        core->n = core->room + 2;
        core->radius = 0.0;
        return;
    }
    if (body->kind == BODY_SHAPE_POLYGON) {
        core->count = core->faces = body->count;
        core->v = body->world_vertices;
        core->n = body->world_normals;
        core->radius = 0.0;
        return;
    }
    body_world_core(body, core->room);
    core->v = core->room;
    core->n = core->room + 2;
    core->radius = body->round_radius;
    if (body->kind == BODY_SHAPE_CIRCLE) {
        core->count = 1;
        core->faces = 0;
        return;
    }
    core->count = core->faces = 2;
    vector_t d = vec_subtract(core->room[1], core->room[0]);
    core->room[2] = vec_normalize((vector_t){d.y, -d.x});
    core->room[3] = vec_negate(core->room[2]);
}

/* How far the other core's vertices lie beyond face f of `core` (m). */
static double face_separation(const core_t *core, size_t f, const core_t *other) {
    double least = INFINITY;
    for (size_t j = 0; j < other->count; j++) {
        least = min_of(least, vec_dot(core->n[f], vec_subtract(other->v[j], core->v[f])));
    }
    return least;
}

typedef struct {
    double separation;
    size_t face;
} best_face_t;

static best_face_t best_face(const core_t *core, const core_t *other) {
    best_face_t best = {-INFINITY, 0};
    for (size_t f = 0; f < core->faces; f++) {
        double s = face_separation(core, f, other);
        if (s > best.separation) best = (best_face_t){s, f};
    }
    return best;
}

/* The nearest points of two cores found from vertex-to-edge distances (the
 * distance when the cores do not overlap), and their features: an edge's
 * interior (edge >= 0) or a vertex. */
typedef struct {
    double distance_squared;
    vector_t p[2];
    int edge[2], vertex[2];
} closest_t;

/* Edges of a core without repeats: a segment's two faces are one edge. */
static size_t distinct_edges(const core_t *core) {
    return core->count == 2 ? 1 : core->count == 1 ? 0 : core->count;
}

/* Each vertex of core `from` (side s of the pair) against the other core. */
static void vertices_against(const core_t *from, const core_t *to, int s, closest_t *best) {
    for (size_t i = 0; i < from->count; i++) {
        vector_t p = from->v[i];
        size_t edges = distinct_edges(to);
        for (size_t j = 0; j < (edges == 0 ? 1 : edges); j++) {
            vector_t q = to->v[j];
            int edge = -1, vertex = (int)j;
            if (edges > 0) {
                size_t k = (j + 1) % to->count;
                vector_t d = vec_subtract(to->v[k], to->v[j]);
                double t = vec_dot(vec_subtract(p, to->v[j]), d) / vec_dot(d, d);
                if (t >= 1.0) {
                    q = to->v[k];
                    vertex = (int)k;
                } else if (t > 0.0) {
                    q = vec_add(to->v[j], vec_multiply(t, d));
                    edge = (int)j;
                    vertex = -1;
                }
            }
            double d2 = vec_get_length_squared(vec_subtract(q, p));
            if (d2 < best->distance_squared) {
                best->distance_squared = d2;
                best->p[s] = p;
                best->p[1 - s] = q;
                best->edge[s] = -1;
                best->vertex[s] = (int)i;
                best->edge[1 - s] = edge;
                best->vertex[1 - s] = vertex;
            }
        }
    }
}

/* Whether two segments cross at a point inside both. */
static bool segments_cross(const core_t *a, const core_t *b) {
    vector_t da = vec_subtract(a->v[1], a->v[0]), db = vec_subtract(b->v[1], b->v[0]);
    double o1 = vec_cross(da, vec_subtract(b->v[0], a->v[0]));
    double o2 = vec_cross(da, vec_subtract(b->v[1], a->v[0]));
    double o3 = vec_cross(db, vec_subtract(a->v[0], b->v[0]));
    double o4 = vec_cross(db, vec_subtract(a->v[1], b->v[0]));
    return o1 * o2 < 0.0 && o3 * o4 < 0.0;
}

typedef struct {
    vector_t p;
    uint32_t feature;
} clip_point_t;

/* Keeps the part of in[0..n) where dot(direction, p) <= offset, in order.
 * A cut point takes the place and the feature of the end it cuts off, so a
 * point keeps its id while an end that lies on the side plane crosses it
 * (one capsule stacked end over end on another). */
static int clip(const clip_point_t *in, int n, clip_point_t out[2], vector_t direction,
                double offset) {
    if (n < 2) {
        if (n == 1 && vec_dot(direction, in[0].p) <= offset) {
            out[0] = in[0];
            return 1;
        }
        return 0;
    }
    double d[2] = {vec_dot(direction, in[0].p) - offset, vec_dot(direction, in[1].p) - offset};
    int k = 0;
    for (int i = 0; i < 2; i++) {
        if (d[i] <= 0.0) {
            out[k++] = in[i];
        } else if (d[1 - i] < 0.0) {
            double t = d[0] / (d[0] - d[1]);
            out[k].p = vec_add(in[0].p, vec_multiply(t, vec_subtract(in[1].p, in[0].p)));
            out[k++].feature = in[i].feature;
        }
    }
    return k;
}

static manifold_t no_manifold(vector_t normal) {
    return (manifold_t){normal, 0, {{VEC_ZERO, 0.0, 0}, {VEC_ZERO, 0.0, 0}}};
}

/*
 * Names the points between two segments a and b by their order along a's
 * core (a lone point: by which side of the middle of the cores' overlap it
 * lies on), the same whichever core's face is the reference: two capsules
 * lying one on the other whose relative tilt rocks about nothing swap
 * reference faces, and with ids of the reference they lost their warm
 * start at every swap (a pile of capsules kept creeping).
 */
static void name_along(manifold_t *m, const core_t *a, const core_t *b) {
    vector_t d = vec_subtract(a->v[1], a->v[0]);
    double s[2] = {0.0, 0.0};
    for (int i = 0; i < m->point_count; i++) {
        s[i] = vec_dot(d, vec_subtract(m->points[i].point, a->v[0]));
    }
    bool high[2] = {false, true};
    if (m->point_count == 2) {
        high[0] = s[0] > s[1];
        high[1] = !high[0];
    } else if (m->point_count == 1) {
        double t0 = vec_dot(d, vec_subtract(b->v[0], a->v[0]));
        double t1 = vec_dot(d, vec_subtract(b->v[1], a->v[0]));
        double lo = max_of(0.0, min_of(t0, t1)), hi = min_of(vec_dot(d, d), max_of(t0, t1));
        high[0] = s[0] > 0.5 * (lo + hi);
    }
    for (int i = 0; i < m->point_count; i++) m->points[i].id = ALONG_ID | (high[i] ? 1u : 0u);
}

/* The manifold on face f of core r (b's when flip): the incident core's
 * centre, or its edge most opposed to the face clipped to the face's side
 * planes. */
static manifold_t face_manifold(const core_t *r, size_t f, const core_t *in, bool flip,
                                double margin) {
    vector_t normal = r->n[f], v1 = r->v[f], v2 = r->v[(f + 1) % r->count];
    manifold_t manifold = no_manifold(flip ? vec_negate(normal) : normal);
    clip_point_t points[2];
    int n = 1;
    size_t incident = 0;
    if (in->count == 1) {
        points[0] = (clip_point_t){in->v[0], 0};
    } else {
        double least = INFINITY;
        for (size_t j = 0; j < in->faces; j++) {
            double d = vec_dot(in->n[j], normal);
            if (d < least) {
                least = d;
                incident = j;
            }
        }
        size_t next = (incident + 1) % in->count;
        clip_point_t edge[2] = {{in->v[incident], (uint32_t)incident}, {in->v[next], (uint32_t)next}};
        vector_t tangent = vec_normalize(vec_subtract(v2, v1));
        clip_point_t once[2];
        int k = clip(edge, 2, once, vec_negate(tangent), -vec_dot(tangent, v1));
        n = clip(once, k, points, tangent, vec_dot(tangent, v2));
    }
    double radii = r->radius + in->radius;
    uint32_t base = FACE_ID | (flip ? 1u << 24 : 0u) | ((uint32_t)f & 0xff) << 16 |
                    ((uint32_t)incident & 0xff) << 8;
    for (int i = 0; i < n; i++) {
        double separation = vec_dot(normal, vec_subtract(points[i].p, v1)) - radii;
        if (separation > margin) continue;
        manifold_point_t *point = &manifold.points[manifold.point_count++];
        point->separation = separation;
        point->point =
            vec_subtract(points[i].p, vec_multiply(in->radius + 0.5 * separation, normal));
        point->id = base | (points[i].feature & 0xff);
    }
    if (r->count == 2 && in->count == 2) name_along(&manifold, flip ? in : r, flip ? r : in);
    return manifold;
}

/* The face of a core's edge `edge` that faces direction d. */
static size_t facing(const core_t *core, int edge, vector_t d) {
    if (core->count == 2) return core->faces == 1 || vec_dot(core->n[0], d) >= 0.0 ? 0 : 1;
    return (size_t)edge;
}

/* One point on the line between two vertices. */
static manifold_t vertex_manifold(const core_t *a, const core_t *b, const closest_t *c,
                                  double margin) {
    double distance = sqrt(c->distance_squared);
    vector_t normal = distance > 0.0 ? vec_multiply(1.0 / distance, vec_subtract(c->p[1], c->p[0]))
                                     : (vector_t){0.0, 1.0};
    manifold_t manifold = no_manifold(normal);
    double separation = distance - a->radius - b->radius;
    if (separation > margin) return manifold;
    manifold.point_count = 1;
    manifold.points[0].separation = separation;
    manifold.points[0].point =
        vec_add(c->p[0], vec_multiply(a->radius + 0.5 * separation, normal));
    manifold.points[0].id = VERTEX_ID | ((uint32_t)c->vertex[0] & 0xff) << 16 |
                            ((uint32_t)c->vertex[1] & 0xff) << 8;
    return manifold;
}

/* Whether the cores share a point; `sat` is the best face separation. */
static bool cores_overlap(const core_t *a, const core_t *b, double sat, const closest_t *c) {
    if (a->count >= 3 || b->count >= 3) return sat <= 0.0;
    if (a->count == 2 && b->count == 2 && segments_cross(a, b)) return true;
    return c->distance_squared == 0.0;
}

/* The manifold on the face that separates the cores most: a's, unless b's
 * is clearly better. */
static manifold_t reference_manifold(const core_t *a, const core_t *b, best_face_t face_a,
                                     best_face_t face_b, double margin) {
    bool flip = face_b.separation > face_a.separation + REFERENCE_TOLERANCE;
    return flip ? face_manifold(b, face_b.face, a, true, margin)
                : face_manifold(a, face_a.face, b, false, margin);
}

/* The least separation of a manifold's points (INFINITY: none). */
static double least_separation(const manifold_t *m) {
    double least = INFINITY;
    for (int i = 0; i < m->point_count; i++) least = min_of(least, m->points[i].separation);
    return least;
}

/* The manifold of two cores that do not overlap, from their nearest
 * features: a face when a vertex lies nearest an edge's interior (which
 * face, between two segments, by the faces' separations as for overlapping
 * cores, so that two nearly parallel capsules keep one reference while
 * their nearest vertex swaps sides). Two vertices nearest: the line between
 * them, unless both cores have edges and the best face's clipped points
 * come as near (to REFERENCE_TOLERANCE): then the ends lie over each other
 * (a capsule stacked end over end on another, or on a face that ends
 * under its end) and the face's two points hold it, where one point at an
 * end would let it rock. */
static manifold_t apart_manifold(const core_t *a, const core_t *b, const closest_t *c,
                                 best_face_t face_a, best_face_t face_b, double margin) {
    vector_t d = vec_subtract(c->p[1], c->p[0]);
    if ((c->edge[0] >= 0 || c->edge[1] >= 0) && a->count == 2 && b->count == 2) {
        return reference_manifold(a, b, face_a, face_b, margin);
    }
    if (c->edge[0] >= 0) return face_manifold(a, facing(a, c->edge[0], d), b, false, margin);
    if (c->edge[1] >= 0)
        return face_manifold(b, facing(b, c->edge[1], vec_negate(d)), a, true, margin);
    if (a->count >= 2 && b->count >= 2) {
        manifold_t face = reference_manifold(a, b, face_a, face_b, margin);
        double ends = sqrt(c->distance_squared) - a->radius - b->radius;
        if (least_separation(&face) <= ends + REFERENCE_TOLERANCE) return face;
    }
    return vertex_manifold(a, b, c, margin);
}

/* Any two cores: overlapping, on the face of least overlap; apart, from
 * their nearest features. */
static manifold_t cores_manifold(const core_t *a, const core_t *b, double margin,
                                 double *separation) {
    double radii = a->radius + b->radius;
    best_face_t face_a = best_face(a, b), face_b = best_face(b, a);
    closest_t c = {INFINITY, {VEC_ZERO, VEC_ZERO}, {-1, -1}, {-1, -1}};
    vertices_against(a, b, 0, &c);
    vertices_against(b, a, 1, &c);
    if (a->faces + b->faces > 0 &&
        cores_overlap(a, b, max_of(face_a.separation, face_b.separation), &c)) {
        bool flip = face_b.separation > face_a.separation + REFERENCE_TOLERANCE;
        *separation = (flip ? face_b.separation : face_a.separation) - radii;
        return reference_manifold(a, b, face_a, face_b, margin);
    }
    *separation = sqrt(c.distance_squared) - radii;
    return *separation > margin ? no_manifold(VEC_ZERO)
                                : apart_manifold(a, b, &c, face_a, face_b, margin);
}

/* Two circles: the line of their centres, as vertex_manifold gives it for
 * two one-vertex cores, straight from the bodies without building either
 * core (a pile of circles calls this for every pair, every step). */
static manifold_t circle_pair(const body_t *body_a, const body_t *body_b, double margin,
                              manifold_features_t *features, double *separation) {
    vector_t centre_a = vec_add(body_a->centroid, vec_rotate_cs(body_a->core[0], body_a->rotation_cos,
                                                                body_a->rotation_sin));
    vector_t centre_b = vec_add(body_b->centroid, vec_rotate_cs(body_b->core[0], body_b->rotation_cos,
                                                                body_b->rotation_sin));
    double ra = body_a->round_radius, rb = body_b->round_radius;
    double distance = sqrt(vec_get_length_squared(vec_subtract(centre_b, centre_a)));
    *separation = distance - (ra + rb);
    *features = (manifold_features_t){.point_count = 0, .lead = INFINITY};
    if (*separation > margin) return no_manifold(VEC_ZERO);
    vector_t normal = distance > 0.0 ? vec_multiply(1.0 / distance, vec_subtract(centre_b, centre_a))
                                     : (vector_t){0.0, 1.0};
    manifold_t manifold = no_manifold(normal);
    double gap = distance - ra - rb; /* vertex_manifold's rounding, which may differ by an ulp */
    if (gap > margin) return manifold;
    manifold.point_count = 1;
    manifold.points[0].separation = gap;
    manifold.points[0].point = vec_add(centre_a, vec_multiply(ra + 0.5 * gap, normal));
    manifold.points[0].id = VERTEX_ID;
    *features = (manifold_features_t){.point_count = 1, .lead = INFINITY, .ids = {VERTEX_ID}};
    return manifold;
}

manifold_t round_manifold_collide(const body_t *body_a, const body_t *body_b, double margin,
                                  manifold_features_t *features, double *separation) {
    if (body_a->kind == BODY_SHAPE_CIRCLE && body_b->kind == BODY_SHAPE_CIRCLE) {
        return circle_pair(body_a, body_b, margin, features, separation);
    }
    core_t a, b;
    core_of(body_a, &a);
    core_of(body_b, &b);
    manifold_t manifold = cores_manifold(&a, &b, margin, separation);
    *features = (manifold_features_t){.point_count = manifold.point_count, .lead = INFINITY};
    for (int i = 0; i < manifold.point_count; i++) features->ids[i] = manifold.points[i].id;
    return manifold;
}

manifold_t round_manifold_on_face(vector_t v1, vector_t v2, vector_t normal, const body_t *other,
                                  bool face_is_b, double margin) {
    core_t face = {2, 1, NULL, NULL, 0.0, {v1, v2, normal, VEC_ZERO}};
    face.v = face.room;
    face.n = face.room + 2;
    core_t in;
    core_of(other, &in);
    return face_manifold(&face, 0, &in, face_is_b, margin);
}
