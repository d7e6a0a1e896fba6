/* Box and ray queries on the broadphase's grid (broadphase.h), for
 * jostle/query.h: the cells a box covers or a ray crosses, in order. */
#include <math.h>
#include "collision/broadphase.h"
#include "collision/broadphase_private.h"
#include "base/scalar.h"

/* The entries of cell (ix, iy): its bucket's, of that cell. */
typedef struct {
    const cell_entry_t *entry, *end;
    uint64_t key;
} cell_walk_t;

static cell_walk_t walk_cell(const broadphase_t *broadphase, int32_t ix, int32_t iy) {
    uint32_t bucket = hash_cell(ix, iy, (uint32_t)(broadphase->bucket_count - 1));
    cell_entry_t probe = {.ix = ix, .iy = iy};
    return (cell_walk_t){broadphase->sorted + broadphase->bucket_start[bucket],
                         broadphase->sorted + broadphase->bucket_start[bucket + 1],
                         cell_key(&probe)};
}

static const cell_entry_t *next_in_cell(cell_walk_t *walk) {
    while (walk->entry < walk->end) {
        const cell_entry_t *entry = walk->entry++;
        if (cell_key(entry) == walk->key) return entry;
    }
    return NULL;
}

/* An entry overlapping the box is reported in one cell only, the one
 * holding the lower-left corner of their intersection (the pair search's
 * rule). */
static bool report_here(const cell_entry_t *entry, cell_range_t query) {
    return max_of(entry->min_x, query.x0) == entry->ix && max_of(entry->min_y, query.y0) == entry->iy;
}

void broadphase_query_box(const broadphase_t *broadphase, aabb_t box, broadphase_visit_t visit,
                          void *context) {
    if (broadphase->proxy_count == 0 || !aabb_overlaps(box, broadphase->bounds)) return;
    for (size_t l = 0; l < broadphase->large_count; l++) {
        uint32_t proxy = broadphase->large[l];
        if (aabb_overlaps(box, broadphase->proxies[proxy].box) && !visit(context, proxy)) return;
    }
    /* Clipped to the grid's bounds, which moves no intersection's corner. */
    aabb_t clipped = {{max_of(box.min.x, broadphase->bounds.min.x),
                       max_of(box.min.y, broadphase->bounds.min.y)},
                      {min_of(box.max.x, broadphase->bounds.max.x),
                       min_of(box.max.y, broadphase->bounds.max.y)}};
    cell_range_t r = cell_range(&clipped, broadphase->inverse_size);
    size_t entries = broadphase->bucket_start[broadphase->bucket_count];
    if (range_cells(r) > (double)entries) {
        /* More cells than entries: read the entries straight through. */
        for (size_t i = 0; i < entries; i++) {
            const cell_entry_t *entry = &broadphase->sorted[i];
            if (entry->ix < r.x0 || entry->ix > r.x1 || entry->iy < r.y0 || entry->iy > r.y1) {
                continue;
            }
            if (aabb_overlaps(entry->box, box) && report_here(entry, r) &&
                !visit(context, entry->proxy)) {
                return;
            }
        }
        return;
    }
    for (int32_t iy = r.y0; iy <= r.y1; iy++) {
        for (int32_t ix = r.x0; ix <= r.x1; ix++) {
            cell_walk_t walk = walk_cell(broadphase, ix, iy);
            for (const cell_entry_t *entry; (entry = next_in_cell(&walk)) != NULL;) {
                if (aabb_overlaps(entry->box, box) && report_here(entry, r) &&
                    !visit(context, entry->proxy)) {
                    return;
                }
            }
        }
    }
}

/* The part [*t0, *t1] of from + t d that lies in the box (slabs); false
 * when none does. */
static bool clip_to_box(aabb_t box, vector_t from, vector_t d, double *t0, double *t1) {
    double lo[2] = {box.min.x, box.min.y}, hi[2] = {box.max.x, box.max.y};
    double p[2] = {from.x, from.y}, dir[2] = {d.x, d.y};
    for (int k = 0; k < 2; k++) {
        if (dir[k] == 0.0) {
            if (p[k] < lo[k] || p[k] > hi[k]) return false;
            continue;
        }
        double a = (lo[k] - p[k]) / dir[k], b = (hi[k] - p[k]) / dir[k];
        if (a > b) {
            double swap = a;
            a = b;
            b = swap;
        }
        *t0 = max_of(*t0, a);
        *t1 = min_of(*t1, b);
        if (*t0 > *t1) return false;
    }
    return true;
}

/* Visits the proxy unless this query did already, when the ray's part up
 * to max_fraction meets its box; returns the fraction the ray is clipped
 * to from then on. */
static double visit_once(broadphase_t *broadphase, uint32_t proxy, const aabb_t *box,
                         vector_t from, vector_t d, double max_fraction,
                         broadphase_ray_visit_t visit, void *context) {
    if (broadphase->stamps[proxy] == broadphase->query_number) return max_fraction;
    broadphase->stamps[proxy] = broadphase->query_number;
    double t0 = 0.0, t1 = max_fraction;
    if (!clip_to_box(*box, from, d, &t0, &t1)) return max_fraction;
    return min_of(visit(context, proxy), max_fraction);
}

/* One axis of the walk along the ray (Amanatides and Woo): the step
 * between cells, the fraction at which the ray crosses into the next cell,
 * and the fraction one cell takes. */
typedef struct {
    int32_t step;
    double next, delta;
} axis_walk_t;

static axis_walk_t axis_walk(double from, double d, int32_t cell, double inverse_size) {
    if (d == 0.0) return (axis_walk_t){0, INFINITY, INFINITY};
    double size = 1.0 / inverse_size;
    double boundary = ((double)cell + (d > 0.0 ? 1.0 : 0.0)) * size;
    return (axis_walk_t){d > 0.0 ? 1 : -1, (boundary - from) / d, size / fabs(d)};
}

static double visit_cell(broadphase_t *broadphase, int32_t ix, int32_t iy, vector_t from,
                         vector_t d, double max_fraction, broadphase_ray_visit_t visit,
                         void *context) {
    cell_walk_t walk = walk_cell(broadphase, ix, iy);
    for (const cell_entry_t *entry; (entry = next_in_cell(&walk)) != NULL;) {
        max_fraction = visit_once(broadphase, entry->proxy, &entry->box, from, d, max_fraction,
                                  visit, context);
    }
    return max_fraction;
}

void broadphase_query_ray(broadphase_t *broadphase, vector_t from, vector_t to, double max_fraction,
                          broadphase_ray_visit_t visit, void *context) {
    if (broadphase->proxy_count == 0) return;
    if (++broadphase->query_number == 0) { /* the stamps wrapped: start over */
        for (size_t i = 0; i < broadphase->proxy_count; i++) broadphase->stamps[i] = 0;
        broadphase->query_number = 1;
    }
    vector_t d = vec_subtract(to, from);
    for (size_t l = 0; l < broadphase->large_count; l++) {
        uint32_t proxy = broadphase->large[l];
        max_fraction = visit_once(broadphase, proxy, &broadphase->proxies[proxy].box, from, d,
                                  max_fraction, visit, context);
    }
    double t0 = 0.0, t1 = max_fraction;
    if (!clip_to_box(broadphase->bounds, from, d, &t0, &t1)) return;
    double inverse_size = broadphase->inverse_size;
    vector_t start = vec_add(from, vec_multiply(t0, d)), end = vec_add(from, vec_multiply(t1, d));
    int32_t ix = cell_index(start.x, inverse_size), iy = cell_index(start.y, inverse_size);
    int32_t end_x = cell_index(end.x, inverse_size), end_y = cell_index(end.y, inverse_size);
    axis_walk_t wx = axis_walk(from.x, d.x, ix, inverse_size);
    axis_walk_t wy = axis_walk(from.y, d.y, iy, inverse_size);
    /* Rounding may put the walk a cell off the end's: it stops after as
     * many steps as the cells between them, and one more. */
    double steps = fabs((double)end_x - ix) + fabs((double)end_y - iy) + 2.0;
    for (double step = 0.0; step <= steps; step++) {
        max_fraction = visit_cell(broadphase, ix, iy, from, d, max_fraction, visit, context);
        if (ix == end_x && iy == end_y) return;
        double next = min_of(wx.next, wy.next);
        if (next > max_fraction) return;
        bool step_x = wx.next == next, step_y = wy.next == next;
        if (step_x && step_y) {
            /* Through a corner: the two cells beside it too. */
            max_fraction = visit_cell(broadphase, ix + wx.step, iy, from, d, max_fraction, visit,
                                      context);
            max_fraction = visit_cell(broadphase, ix, iy + wy.step, from, d, max_fraction, visit,
                                      context);
        }
        if (step_x) {
            ix += wx.step;
            wx.next += wx.delta;
        }
        if (step_y) {
            iy += wy.step;
            wy.next += wy.delta;
        }
    }
}
