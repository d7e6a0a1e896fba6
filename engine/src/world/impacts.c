#include "world/impacts.h"
#include <math.h>
#include "base/scalar.h"
#include "solver/velocity_solve.h"

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
 * geometry of the start (velocity_solve.c, set_target). */
static bool impact_in_step(const solver_contact_t *c, const solver_anchor_t *anchor,
                           const solver_state_t *sa, const solver_state_t *sb, double dt,
                           double restitution_threshold) {
    double pull = vec_dot(c->normal, vec_subtract(sb->acceleration, sa->acceleration));
    double threshold = solver_bounce_threshold(c->restitution, sa, sb, restitution_threshold);
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
 * it. Impulses stay with the points that continue them (match_points).
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
    vector_t before_points[2] = {source->points[0], source->points[1]};
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
    c->block = solver_contact_blocks(c, anchor, &world->velocities[c->a],
                                     &world->velocities[c->b]);
    carry_impulses(c, source->points, &before, before_points,
                   warm_reach(source->body_a, source->body_b));
    double cos_a = cos(hit->angle_a), sin_a = sin(hit->angle_a);
    vector_t d = vec_subtract(hit->centroid_b, hit->centroid_a);
    source->features = hit->features;
    source->pose = (relative_pose_t){{cos_a * d.x + sin_a * d.y, -sin_a * d.x + cos_a * d.y},
                                     hit->angle_b - hit->angle_a};
}

/* Contact n taken at the moment of its impact, if the solver will time one
 * (impacts_take). Not inlined: a scene without elastic contacts pays only
 * for the loop that looks for them. */
static __attribute__((noinline)) void take_impact(world_t *world, size_t n, double dt,
                                                   double threshold) {
    const solver_contact_t *c = &world->contacts[n];
    const solver_state_t *sa = &world->states[c->a], *sb = &world->states[c->b];
    if (!impact_in_step(c, &world->anchors[n], sa, sb, dt, threshold)) return;
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
void impacts_take(world_t *world, double dt, size_t largest_polygon, double threshold) {
    toi_scratch_reserve(&world->toi_scratch, largest_polygon);
    if (world->elastic_count == 0) return;
    for (size_t n = 0; n < world->contact_count; n++) {
        if (world->contacts[n].restitution != 0.0) take_impact(world, n, dt, threshold);
    }
}
