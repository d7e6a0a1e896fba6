#include "collision/segment_manifold.h"
#include <math.h>
#include "base/scalar.h"
#include "collision/round_manifold.h"
#include "collision/seams.h"

/* A join whose directions differ by less than this sine is flat (as the
 * chain's runs count it, body_chain.c). */
static const double FLAT_SINE = 1e-9;

/* A segment in the world: its ends, unit direction and free side's normal,
 * and at each end (0: the start, 1: the end) whether a neighbour
 * continues it, the neighbour's free side's normal, and whether the chain
 * bends away from the free side there; its straight run and claim (m
 * along e from p1, body_segment_t's, as the seams extend them). */
typedef struct {
    vector_t p1, p2, e, n;
    bool has[2], convex[2];
    vector_t side[2];
    double run_lo, run_hi, claim_lo, claim_hi;
} segment_frame_t;

static vector_t left_normal(vector_t d) {
    return (vector_t){-d.y, d.x};
}

/*
 * A static polygon's face (or another chain's segment) that continues or
 * overlaps the segment flush, found by the seams (seams.h) on the
 * segment's free face, its edge 1 from p2 back to p1: the segment's run
 * reaches over the seam's run, an open end where the neighbour continues
 * it is a flat join, and the segment holds only the part of its claim
 * that the seams give its face (shared with the neighbour's face by the
 * seams' tolerance where it continues, as the faces of flush static boxes
 * do; none where the neighbour's face holds it). The chain's own joins
 * stay as the chain made them.
 */
static void join_seams(const body_t *segment, segment_frame_t *f) {
    const seam_edge_t *free_face = &segment->seam->edges[1];
    if (!free_face->chained) return;
    double length = vec_get_length(vec_subtract(f->p2, f->p1));
    f->run_lo = min_of(f->run_lo, length - free_face->reach_hi);
    f->run_hi = max_of(f->run_hi, length - free_face->reach_lo);
    /* Vertex 0 is p1, where edge 1 ends; vertex 1 is p2, where it starts. */
    f->has[0] |= segment->seam->edges[0].smooth;
    f->has[1] |= segment->seam->edges[1].smooth;
    f->claim_lo = max_of(f->claim_lo, length - free_face->claim_hi);
    f->claim_hi = min_of(f->claim_hi, length - free_face->claim_lo);
}

static segment_frame_t frame_of(const body_t *segment) {
    const body_segment_t *s = segment->segment;
    segment_frame_t f;
    f.p1 = segment->world_vertices[0];
    f.p2 = segment->world_vertices[1];
    f.e = vec_normalize(vec_subtract(f.p2, f.p1));
    f.n = body_rotate_vector(segment, s->normal);
    for (int end = 0; end < 2; end++) {
        f.has[end] = s->has_ghost[end];
        f.convex[end] = false;
        f.side[end] = f.n;
        if (!f.has[end]) continue;
        vector_t ghost = body_to_world(segment, s->ghost[end]);
        vector_t d = end == 0 ? vec_subtract(f.p1, ghost) : vec_subtract(ghost, f.p2);
        d = vec_normalize(d);
        f.side[end] = left_normal(d);
        /* Turning right, the chain bends away from its left (free) side. */
        f.convex[end] = (end == 0 ? vec_cross(d, f.e) : vec_cross(f.e, d)) < -FLAT_SINE;
    }
    f.run_lo = s->run_lo;
    f.run_hi = s->run_hi;
    f.claim_lo = s->claim_lo;
    f.claim_hi = s->claim_hi;
    if (segment->seam_listed) join_seams(segment, &f);
    return f;
}

static manifold_t none(vector_t normal) {
    return (manifold_t){normal, 0, {{VEC_ZERO, 0.0, 0}, {VEC_ZERO, 0.0, 0}}};
}

/* Whether a body centred at c lies behind the surface near the segment. */
static bool behind(const segment_frame_t *f, vector_t c) {
    if (vec_dot(f->n, vec_subtract(c, f->p1)) >= 0.0) return false;
    if (f->convex[0] && vec_dot(f->side[0], vec_subtract(c, f->p1)) >= 0.0) return false;
    if (f->convex[1] && vec_dot(f->side[1], vec_subtract(c, f->p2)) >= 0.0) return false;
    return true;
}

/* The other shape against the segment's straight run, kept when the
 * middle of its points lies on the segment's claim. */
static manifold_t on_run(const segment_frame_t *f, const body_t *other,
                         double margin, double *separation) {
    vector_t lo = vec_add(f->p1, vec_multiply(f->run_lo, f->e));
    vector_t hi = vec_add(f->p1, vec_multiply(f->run_hi, f->e));
    manifold_t m = round_manifold_on_face(lo, hi, f->n, other, false, margin);
    if (m.point_count == 0) return m;
    double middle = 0.0;
    for (int i = 0; i < m.point_count; i++) {
        middle += vec_dot(f->e, vec_subtract(m.points[i].point, f->p1));
        *separation = min_of(*separation, m.points[i].separation);
    }
    middle /= m.point_count;
    if (!(middle >= f->claim_lo && middle <= f->claim_hi)) return none(m.normal);
    return m;
}

/* Whether a normal leaning toward the convex join at `end` is this
 * segment's: one beyond the neighbour's face normal is the neighbour's
 * face's; one between the two faces' normals is the corner's, and belongs
 * to the segment whose face normal is nearer it (the one that starts there
 * on a tie). The two segments weigh the same numbers (both faces' normals
 * from the join's directions), so exactly one keeps a corner contact. */
static bool corner_is_mine(const segment_frame_t *f, int end, vector_t normal) {
    vector_t mine = left_normal(f->e), theirs = f->side[end];
    double beyond = end == 0 ? vec_cross(theirs, normal) : vec_cross(normal, theirs);
    if (beyond > 0.0) return false;
    double nearer_mine = vec_dot(normal, mine), nearer_theirs = vec_dot(normal, theirs);
    return end == 0 ? nearer_mine >= nearer_theirs : nearer_mine > nearer_theirs;
}

/* The segment's manifold with other, the normal from the segment. */
static manifold_t segment_first(const body_t *segment, const body_t *other, double margin,
                                double *separation) {
    manifold_features_t found;
    manifold_t raw = round_manifold_collide(segment, other, margin, &found, separation);
    if (*separation > margin) return none(raw.normal);
    segment_frame_t f = frame_of(segment);
    /* Lying on a face that holds all of it (seams.h), it makes no contact. */
    if (!(f.claim_lo <= f.claim_hi)) return none(raw.normal);
    if (behind(&f, other->centroid)) return none(raw.normal);
    if (raw.point_count == 0) return on_run(&f, other, margin, separation);
    vector_t normal = raw.normal;
    double along = vec_dot(normal, f.e);
    int end = along < 0.0 ? 0 : along > 0.0 ? 1 : -1;
    if (end < 0) return on_run(&f, other, margin, separation);
    if (!f.has[end]) return raw; /* an open chain's end: a free corner */
    if (!f.convex[end]) return on_run(&f, other, margin, separation);
    return corner_is_mine(&f, end, normal) ? raw : none(raw.normal);
}

manifold_t segment_manifold_collide(const body_t *a, const body_t *b, double margin,
                                    manifold_features_t *features, double *separation) {
    bool segment_is_b = b->kind == BODY_SHAPE_SEGMENT && a->kind != BODY_SHAPE_SEGMENT;
    manifold_t m = segment_is_b ? segment_first(b, a, margin, separation)
                                : segment_first(a, b, margin, separation);
    if (segment_is_b) m.normal = vec_negate(m.normal);
    *features = (manifold_features_t){.point_count = m.point_count, .lead = INFINITY};
    for (int i = 0; i < m.point_count; i++) features->ids[i] = m.points[i].id;
    return m;
}
