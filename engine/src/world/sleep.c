#include "world/sleep.h"
#include <math.h>
#include <stdlib.h>
#include "dynamics/body_private.h"
#include "collision/broadphase.h"
#include "base/memory.h"

/* A body that gravity or a force pulls, and that can rest only pressed on
 * others, gets five times the tolerance (the default's five times is Box2D
 * v3's 0.05 m/s): a pile's bodies creep by millimetres a second long after
 * it has come to rest (docs/design.md, Sleeping). */
static const double SLEEP_PRESSED_FACTOR = 5.0;
/* The tolerance is at most this many body radii per second. */
static const double SLEEP_SIZE_RATE = 0.02;

struct sleep_entry {
    double min_x;
    body_t *body;
};

/* Per island root: whether every body is ready, and whether the island may
 * sleep where it is (resting on something immovable, or pushed by
 * nothing); its bodies are chained from first to last through sleep_next
 * while it is built. */
struct sleep_island {
    bool ready, supported, pushed;
    body_t *first, *last;
};

void sleep_free(sleep_t *sleep) {
    memory_free(sleep->entries);
    memory_free(sleep->parent);
    memory_free(sleep->islands);
}

static uint32_t find_root(uint32_t *parent, uint32_t i) {
    while (parent[i] != i) {
        parent[i] = parent[parent[i]];
        i = parent[i];
    }
    return i;
}

/* Starts the window over which the body's drift is measured. */
static void anchor_at(body_t *body) {
    body->sleep_anchor = body->centroid;
    body->sleep_anchor_angle = body->angle;
    body->sleep_window = 0.0;
}

/* Slow: over each sleep time the body has moved no farther than the
 * tolerance speed covers in that time (its rim's motion counted with its
 * centroid's); its velocities stay within the tolerance plus what one
 * step of its free acceleration adds. Which way it moved does not count:
 * overlaps are lifted out within a second (shock_lift), and a heap's
 * flanks creeping up its walls at a centimetre a second are at rest enough
 * (docs/design.md, Sleeping). A deep pile's solve leaves each body a
 * velocity of that order that the next step takes back (Chipmunk's idle
 * speed is the same dt |g|), so what counts is how far the body goes. The
 * tolerance shrinks for small bodies (a centimetre box at 1 cm/s is still
 * settling). Nor may it turn faster than the angular tolerance. */
static bool is_slow(const sleep_step_t *step, const solver_velocity_t *row,
                    const solver_displacement_t *moved, const solver_state_t *state,
                    body_t *body) {
    double dt = step->dt, sleep_time = step->time;
    double linear = fmin(step->linear_tolerance, SLEEP_SIZE_RATE * body->radius);
    double jitter = dt * vec_get_length(state->acceleration);
    double tolerance = jitter > 0.0 ? SLEEP_PRESSED_FACTOR * linear : linear;
    if (vec_get_length(row->v) + body->radius * fabs(row->w) > tolerance + jitter ||
        fabs(row->w) > step->angular_tolerance) {
        body->sleep_time = 0.0;
        return false;
    }
    if (body->sleep_time == 0.0 || body->sleep_window >= sleep_time) anchor_at(body);
    vector_t drift = vec_subtract(vec_add(body->centroid, moved->dx), body->sleep_anchor);
    double turn = body->angle + moved->dtheta - body->sleep_anchor_angle;
    double moved_by = vec_get_length(drift) + body->radius * fabs(turn);
    if (moved_by > tolerance * sleep_time) {
        anchor_at(body);
        body->sleep_time = 0.0;
    }
    body->sleep_window += dt;
    body->sleep_time += dt;
    return body->sleep_time >= sleep_time;
}

size_t sleep_time_bodies(const sleep_step_t *step, size_t begin, size_t end) {
    size_t ready = 0;
    for (size_t i = begin; i < end; i++) {
        body_t *body = step->bodies[i];
        if (!body_is_movable(body) || body->removed) continue;
        ready += is_slow(step, &step->velocities[i], &step->displacements[i], &step->states[i],
                         body);
    }
    return ready;
}

bool sleep_is_check_step(sleep_t *sleep) {
    if (++sleep->steps < SLEEP_CHECK_STEPS) return false;
    sleep->steps = 0;
    return true;
}

/* Joins the rows into islands over the touching links; an island is ready
 * when every body has been slow for the step's sleep time. */
static void build_islands(sleep_t *sleep, const sleep_step_t *step, const sleep_link_t *links,
                          size_t link_count) {
    memory_reserve((void **)&sleep->parent, &sleep->parent_capacity, step->count,
                   sizeof(uint32_t));
    memory_reserve((void **)&sleep->islands, &sleep->island_capacity, step->count,
                   sizeof(struct sleep_island));
    for (size_t i = 0; i < step->count; i++) {
        sleep->parent[i] = (uint32_t)i;
        sleep->islands[i] = (struct sleep_island){true, false, false, NULL, NULL};
    }
    for (size_t k = 0; k < link_count; k++) {
        if (links[k].b == SLEEP_WORLD) continue;
        body_t *a = step->bodies[links[k].a], *b = step->bodies[links[k].b];
        if (body_is_movable(a) && body_is_movable(b)) {
            uint32_t ra = find_root(sleep->parent, links[k].a);
            uint32_t rb = find_root(sleep->parent, links[k].b);
            if (ra != rb) sleep->parent[ra] = rb;
        }
    }
    for (size_t k = 0; k < link_count; k++) {
        if (links[k].b == SLEEP_WORLD) {
            sleep->islands[find_root(sleep->parent, links[k].a)].supported = true;
            continue;
        }
        body_t *a = step->bodies[links[k].a], *b = step->bodies[links[k].b];
        /* Resting on a body that does not move (a floor, a wall). */
        if (body_is_movable(a) && !body_is_movable(b)) {
            sleep->islands[find_root(sleep->parent, links[k].a)].supported = true;
        } else if (body_is_movable(b) && !body_is_movable(a)) {
            sleep->islands[find_root(sleep->parent, links[k].b)].supported = true;
        }
    }
    for (size_t i = 0; i < step->count; i++) {
        body_t *body = step->bodies[i];
        struct sleep_island *island = &sleep->islands[find_root(sleep->parent, (uint32_t)i)];
        if (!body_is_movable(body)) continue;
        if (body->removed || body->sleep_time < step->time) island->ready = false;
        vector_t a = step->states[i].acceleration;
        if (a.x != 0.0 || a.y != 0.0) island->pushed = true;
    }
}

/* Puts the ready islands to sleep, each body's velocities to 0 and its
 * island linked in a circle. */
void sleep_islands(sleep_t *sleep, const sleep_step_t *step, const sleep_link_t *links,
                   size_t link_count) {
    build_islands(sleep, step, links, link_count);
    size_t slept = 0;
    for (size_t i = 0; i < step->count; i++) {
        body_t *body = step->bodies[i];
        if (!body_is_movable(body) || body->removed) continue;
        struct sleep_island *island = &sleep->islands[find_root(sleep->parent, (uint32_t)i)];
        if (!island->ready || (island->pushed && !island->supported)) continue;
        body_fall_asleep(body);
        step->velocities[i].v = VEC_ZERO;
        step->velocities[i].w = 0.0;
        if (island->first == NULL) {
            island->first = body;
        } else {
            island->last->sleep_next = body;
        }
        island->last = body;
        slept++;
    }
    for (size_t i = 0; i < step->count; i++) {
        struct sleep_island *island = &sleep->islands[i];
        if (island->first != NULL) island->last->sleep_next = island->first;
    }
    sleep->slept += slept;
}

static int compare_entries(const void *a, const void *b) {
    double x = ((const struct sleep_entry *)a)->min_x, y = ((const struct sleep_entry *)b)->min_x;
    return (x > y) - (x < y);
}

static size_t count_asleep(body_t **bodies, size_t count) {
    size_t asleep = 0;
    for (size_t i = 0; i < count; i++) asleep += bodies[i]->asleep;
    return asleep;
}

/* The index of the sleeping bodies, sorted by the left edges of their
 * boxes. */
static void rebuild_index(sleep_t *sleep, body_t **bodies, size_t count, size_t asleep) {
    memory_reserve((void **)&sleep->entries, &sleep->capacity, asleep,
                   sizeof(struct sleep_entry));
    sleep->count = 0;
    sleep->widest = 0.0;
    for (size_t i = 0; i < count; i++) {
        body_t *body = bodies[i];
        if (!body->asleep) continue;
        body_update_pose(body);
        sleep->entries[sleep->count++] = (struct sleep_entry){body->bounds.min.x, body};
        sleep->widest = fmax(sleep->widest, body->bounds.max.x - body->bounds.min.x);
    }
    /* entries is NULL while no body ever slept. */
    if (sleep->count > 1) {
        qsort(sleep->entries, sleep->count, sizeof(struct sleep_entry), compare_entries);
    }
}

static bool boxes_overlap(aabb_t a, aabb_t b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y;
}

/* Wakes every sleeping island whose box the reach overlaps. */
static void wake_within(const sleep_t *sleep, aabb_t reach) {
    /* The first entry whose left edge may lie within reach. */
    double from = reach.min.x - sleep->widest;
    size_t low = 0, high = sleep->count;
    while (low < high) {
        size_t middle = (low + high) / 2;
        if (sleep->entries[middle].min_x < from) {
            low = middle + 1;
        } else {
            high = middle;
        }
    }
    for (size_t k = low; k < sleep->count && sleep->entries[k].min_x <= reach.max.x; k++) {
        body_t *body = sleep->entries[k].body;
        if (body->asleep && boxes_overlap(reach, body->bounds)) body_wake(body);
    }
}

static aabb_t grown(aabb_t box, double by) {
    return (aabb_t){{box.min.x - by, box.min.y - by}, {box.max.x + by, box.max.y + by}};
}

/* How far any point of the body may go in a step of dt before contacts act
 * on it: at its speed now or at the one gravity, its force and its impulse
 * give it by the end of the step, whichever is more, and likewise its spin. */
static double step_travel(const body_t *body, double dt, vector_t gravity) {
    vector_t pull = vec_multiply(body->inverse_mass, body->force);
    if (body->inverse_mass != 0.0) pull = vec_add(pull, gravity);
    vector_t free = vec_add(body->velocity, vec_add(vec_multiply(dt, pull),
                                                    vec_multiply(body->inverse_mass, body->impulse)));
    double spin = body->angular_velocity +
                  body->inverse_inertia * (dt * body->torque + body->angular_impulse);
    double speed = fmax(vec_get_length(body->velocity), vec_get_length(free));
    return dt * (speed + fmax(fabs(body->angular_velocity), fabs(spin)) * body->radius);
}

void sleep_wake_changed(const sleep_t *sleep, body_t *body, double dt, vector_t gravity,
                        double margin) {
    body_update_pose(body);
    double grow = step_travel(body, dt, gravity) + margin;
    wake_within(sleep, grown(body->changed_bounds, grow));
    wake_within(sleep, grown(body->bounds, grow));
}

void sleep_wake_ahead(const sleep_t *sleep, body_t *body, double dt, vector_t gravity,
                      double margin) {
    bool moving = body->velocity.x != 0.0 || body->velocity.y != 0.0 ||
                  body->angular_velocity != 0.0;
    if (body->asleep || body->removed || !moving || body->sleep_time != 0.0) return;
    body_update_pose(body);
    wake_within(sleep, grown(body->bounds, step_travel(body, dt, gravity) + margin));
}

/* Where a body may be by the end of the next step: its box over this one
 * grown by what its end velocities cover in a step, and the margin. */
static aabb_t reach_of(const sleep_step_t *step, size_t i) {
    const solver_velocity_t *row = &step->velocities[i];
    double grow = step->dt * (vec_get_length(row->v) + fabs(row->w) * step->bodies[i]->radius) +
                  step->margin;
    return grown(step->proxies[i].box, grow);
}

void sleep_forget_removed(sleep_t *sleep) {
    size_t kept = 0;
    for (size_t k = 0; k < sleep->count; k++) {
        if (!sleep->entries[k].body->removed) sleep->entries[kept++] = sleep->entries[k];
    }
    sleep->count = kept;
}

void sleep_index_asleep(sleep_t *sleep, body_t **bodies, size_t count) {
    rebuild_index(sleep, bodies, count, count_asleep(bodies, count));
    sleep->slept = 0;
    sleep->checked = false;
}

/* Whether the index may be out of date: an island fell asleep, or who
 * sleeps changed since it was last checked (or that is not known). */
static bool index_may_be_stale(const sleep_t *sleep, const uint64_t *changes) {
    return sleep->slept > 0 || changes == NULL || !sleep->checked ||
           *changes != sleep->checked_changes;
}

void sleep_wake_reached(sleep_t *sleep, const sleep_step_t *step, body_t **all_bodies,
                        size_t all_count, const uint64_t *changes) {
    if (sleep->slept == 0 && sleep->count == 0) return;
    if (index_may_be_stale(sleep, changes)) {
        size_t asleep = count_asleep(all_bodies, all_count);
        if (sleep->slept > 0 || asleep != sleep->count) {
            rebuild_index(sleep, all_bodies, all_count, asleep);
        }
        sleep->checked = changes != NULL;
        if (changes != NULL) sleep->checked_changes = *changes;
    }
    sleep->slept = 0;
    if (sleep->count == 0) return;
    /* A body wakes others when it moved faster than the sleep tolerances
     * this step (its timer restarted), not when it creeps: a pile's last
     * settling body would otherwise wake its sleeping neighbours forever. */
    for (size_t i = 0; i < step->count; i++) {
        const body_t *body = step->bodies[i];
        const solver_velocity_t *row = &step->velocities[i];
        bool moving = (row->v.x != 0.0 || row->v.y != 0.0 || row->w != 0.0) &&
                      body->sleep_time == 0.0;
        if (!body->asleep && !body->removed && moving) wake_within(sleep, reach_of(step, i));
    }
}
