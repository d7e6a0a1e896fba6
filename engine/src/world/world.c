#include "world/world.h"
#include "world/world_types.h"
#include <math.h>
#include <stdlib.h>
#include "base/memory.h"
#include "base/scalar.h"
#include "base/workers.h"
#include "world/impacts.h"
#include "world/narrowphase.h"

/* Every body's box is enlarged by how far it can move in a step plus this
 * (m), so a contact is found a step before it forms. 5 mm rather than 1 cm:
 * the motion term already covers the approach, and the pile(4000) carries 7%
 * fewer speculative points (3% less time) with every quality figure of the
 * canonical scenes unchanged (measured). */
static const double CONTACT_MARGIN = 0.005;

world_t *world_init(size_t velocity_iterations, size_t position_iterations) {
    world_t *world = memory_calloc(1, sizeof(world_t));
    world->pairs = pair_tracker_init();
    world_set_iterations(world, velocity_iterations, position_iterations);
    return world;
}

void world_free(world_t *world) {
    pair_tracker_free(world->pairs);
    memory_free(world->proxies);
    memory_free(world->velocities);
    memory_free(world->states);
    memory_free(world->displacements);
    memory_free(world->margins);
    memory_free(world->contacts);
    memory_free(world->anchors);
    memory_free(world->sources);
    memory_free(world->old_contacts);
    memory_free(world->older_contacts);
    memory_free(world->joined);
    memory_free(world->kept_pairs);
    memory_free(world->old_sources);
    memory_free(world->gaps);
    memory_free(world->old_gaps);
    seams_free(&world->seams);
    solver_wide_free(&world->wide);
    shock_free(&world->shock);
    joint_tree_free(&world->joint_tree);
    sleep_free(&world->sleep);
    memory_free(world->active);
    memory_free(world->active_motions);
    memory_free(world->active_index);
    memory_free(world->links);
    workers_free(world->workers);
    memory_free(world->results);
    memory_free(world->toi_scratch.vectors);
    memory_free(world);
}

void world_set_iterations(world_t *world, size_t velocity_iterations, size_t position_iterations) {
    world->velocity_iterations = (int)velocity_iterations;
    world->position_iterations = (int)position_iterations;
}

void world_set_workers(world_t *world, size_t workers) {
    size_t now = world->workers != NULL ? workers_count(world->workers) : 1;
    if (workers == now) return;
    workers_free(world->workers);
    world->workers = workers > 1 ? workers_init(workers) : NULL;
    world->wide.workers = world->workers;
    pair_tracker_set_workers(world->pairs, world->workers);
}

void world_for_bodies(world_t *world, size_t count, workers_fn_t fn, void *context) {
    workers_for(world->workers, count, fn, context);
}

static void reserve_rows(world_t *world, size_t count) {
    memory_reserve((void **)&world->velocities, &world->velocity_capacity, count,
                   sizeof(solver_velocity_t));
    memory_reserve((void **)&world->states, &world->state_capacity, count, sizeof(solver_state_t));
    memory_reserve((void **)&world->displacements, &world->displacement_capacity, count,
                   sizeof(solver_displacement_t));
    memory_reserve((void **)&world->proxies, &world->proxy_capacity, count,
                   sizeof(broadphase_proxy_t));
    memory_reserve((void **)&world->margins, &world->margin_capacity, count, sizeof(double));
}

/* The box a body sweeps this step: its bounds moved along both velocities
 * it may have (at the start, and free of contacts), grown all round by
 * grow (what rotation and the contact margin add). Only the direction of
 * motion is enlarged, so bodies moving together, like a falling grid, do not
 * pair, while a body and whatever lies ahead of it do. */
WORLD_INLINE aabb_t swept_box(aabb_t bounds, double dt, const solver_state_t *state, double grow) {
    vector_t d1 = vec_multiply(dt, state->v_start), d2 = vec_multiply(dt, state->v_free);
    return (aabb_t){
        {bounds.min.x + min_of(0.0, min_of(d1.x, d2.x)) - grow,
         bounds.min.y + min_of(0.0, min_of(d1.y, d2.y)) - grow},
        {bounds.max.x + max_of(0.0, max_of(d1.x, d2.x)) + grow,
         bounds.max.y + max_of(0.0, max_of(d1.y, d2.y)) + grow},
    };
}

/* What the broadphase's filter reads of a body, removal aside: one rule for
 * the pairs the world makes and for world_pair_collides. */
static void set_filter(broadphase_proxy_t *proxy, const body_t *body) {
    proxy->fixed = body->inverse_mass == 0.0 && body->inverse_inertia == 0.0;
    proxy->category = body->category;
    proxy->mask = body->mask;
    proxy->group = body->group;
}

/* Loads body i's rows for the solver and its broadphase proxy; returns
 * whether the body changed what the seams were found from. */
WORLD_INLINE bool load_body(world_t *world, body_t *body, const integrator_motion_t *motion, size_t i,
                      double dt) {
    body->solver_index = (uint32_t)i;
    body->changed = false; /* world_wake_changed has seen it */
    body_update_pose(body);
    solver_state_t *state = &world->states[i];
    solver_velocity_t *velocity = &world->velocities[i];
    state->v_start = body->velocity;
    state->w_start = body->angular_velocity;
    state->v_free = motion->velocity;
    state->w_free = motion->angular_velocity;
    state->drift = motion->drift;
    state->spin_drift = motion->spin_drift;
    state->acceleration = motion->acceleration;
    state->impact_time = -1.0;
    state->pushing_contacts = 0;
    world->displacements[i].radius = body->radius;
    velocity->v = state->v_free;
    velocity->w = state->w_free;
    velocity->inverse_mass = motion->inverse_mass;
    velocity->inverse_inertia = body->inverse_inertia;
    if (solver_row_is_static(velocity)) {
        /* No -0.0 in a row the solver never changes: its sweeps write such
         * a row unchanged but for turning -0.0 to +0.0, or, sharing a
         * colour over threads, not at all (solver_wide.h). */
        velocity->v = vec_add(velocity->v, (vector_t){0.0, 0.0});
        velocity->w += 0.0;
    }

    /* How far any point of the body can move this step, bounded: the
     * narrowphase keeps speculative points up to this far apart. */
    double speed = max_of(vec_get_length(state->v_start), vec_get_length(state->v_free));
    double spin = max_of(fabs(state->w_start), fabs(state->w_free)) * body->radius;
    world->margins[i] = dt * (speed + spin) + CONTACT_MARGIN;
    broadphase_proxy_t *proxy = &world->proxies[i];
    proxy->box = swept_box(body->bounds, dt, state, dt * spin + CONTACT_MARGIN);
    set_filter(proxy, body);
    /* A chain pairs through its segments (gather_bodies). */
    if (body->removed || body->kind == BODY_SHAPE_CHAIN) proxy->category = 0;
    return (proxy->fixed || body->seam_listed) && seams_body_changed(body);
}

/* The arguments of a loop over bodies split over the workers. */
typedef struct {
    world_t *world;
    body_t **bodies;
    const integrator_motion_t *free_motions; /* loading reads them */
    integrator_motion_t *motions;            /* writing back fills them */
    double dt;
} body_loop_t;

static void load_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const body_loop_t *loop = context;
    bool changed = false;
    for (size_t i = begin; i < end; i++) {
        BODY_PREFETCH(loop->bodies, i + BODY_AHEAD, end, true);
        changed |= load_body(loop->world, loop->bodies[i], &loop->free_motions[i], i, loop->dt);
    }
    loop->world->seams_changed[chunk] = changed;
}

/* Loads each body's rows for the solver and its broadphase proxy; returns
 * whether a static body changed since the seams were found. */
static bool load_bodies(world_t *world, body_t **bodies, const integrator_motion_t *motions,
                        size_t count, const world_step_t *step) {
    reserve_rows(world, count);
    bool changed = false;
    if (world->workers != NULL) {
        body_loop_t loop = {world, bodies, motions, NULL, step->dt};
        size_t chunks = workers_chunks(world->workers, count);
        for (size_t k = 0; k < chunks; k++) world->seams_changed[k] = false;
        workers_for(world->workers, count, load_chunk, &loop);
        for (size_t k = 0; k < chunks; k++) changed |= world->seams_changed[k];
        return changed;
    }
    for (size_t i = 0; i < count; i++) {
        BODY_PREFETCH(bodies, i + BODY_AHEAD, count, true);
        changed |= load_body(world, bodies[i], &motions[i], i, step->dt);
    }
    return changed;
}

/* Hands the solver's results to the bodies' motions: the velocities it
 * chose and the displacements it moved them by. */
WORLD_INLINE void write_back_range(const world_t *world, integrator_motion_t *motions, size_t begin,
                             size_t end) {
    for (size_t i = begin; i < end; i++) {
        const solver_velocity_t *velocity = &world->velocities[i];
        const solver_displacement_t *moved = &world->displacements[i];
        integrator_motion_t *motion = &motions[i];
        motion->velocity = velocity->v;
        motion->angular_velocity = velocity->w;
        motion->displacement = moved->dx;
        motion->rotation = moved->dtheta;
        motion->still = false;
    }
}

static void write_back_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const body_loop_t *loop = context;
    (void)chunk;
    write_back_range(loop->world, loop->motions, begin, end);
}

static void write_back(world_t *world, integrator_motion_t *motions, size_t count) {
    if (world->workers != NULL) {
        body_loop_t loop = {world, NULL, NULL, motions, 0.0};
        workers_for(world->workers, count, write_back_chunk, &loop);
        return;
    }
    write_back_range(world, motions, 0, count);
}

/* Whether a contact holds its bodies together this step. */
static bool is_touching(const solver_contact_t *c) {
    for (int j = 0; j < c->point_count; j++) {
        const solver_point_t *p = &c->points[j];
        if (p->separation <= 0.0 || p->normal_impulse + p->restitution_impulse > 0.0) return true;
    }
    return false;
}

/* The links of the joints solved this step: each joins its bodies'
 * islands (a joint to the world holds its body as a floor does). */
static size_t joint_links(const joint_step_t *joints, sleep_link_t *links) {
    size_t count = 0;
    for (size_t i = 0; i < joints->count; i++) {
        const joint_t *joint = joints->joints[i];
        if (!joint->active) continue;
        const body_t *body1 = joint->def.body1;
        uint32_t row1 = body1 != NULL ? body1->solver_index : SLEEP_WORLD;
        links[count++] = (sleep_link_t){joint->def.body2->solver_index, row1};
    }
    return count;
}

/* The sleep timers over the workers, each chunk counting its ready bodies. */
typedef struct {
    const sleep_step_t *step;
    size_t ready[WORKERS_MAX_CHUNKS];
} sleep_split_t;

static void time_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    sleep_split_t *split = context;
    split->ready[chunk] = sleep_time_bodies(split->step, begin, end);
}

static size_t time_bodies(world_t *world, const sleep_step_t *step) {
    sleep_split_t split = {step, {0}};
    world_for_bodies(world, step->count, time_chunk, &split);
    size_t ready = 0;
    for (size_t k = 0; k < WORKERS_MAX_CHUNKS; k++) ready += split.ready[k];
    return ready;
}

/* Hands the step to sleep.c; the touching contacts are listed and the
 * islands joined only when some body has been slow long enough for its
 * island to sleep, and then every SLEEP_CHECK_STEPS steps (a pile whose
 * bottom rests and top creeps would pay for islands at every step). */
static void update_sleep(world_t *world, body_t **bodies, size_t count, const world_step_t *ws,
                         body_t **all_bodies, size_t all_count) {
    sleep_step_t step = {bodies,          world->velocities, world->displacements,
                         world->states,   world->proxies,    count,
                         ws->dt,          CONTACT_MARGIN,    ws->sleep_linear,
                         ws->sleep_angular, ws->sleep_time};
    if (time_bodies(world, &step) > 0 && sleep_is_check_step(&world->sleep)) {
        memory_reserve((void **)&world->links, &world->link_capacity,
                       world->contact_count + ws->joints.count, sizeof(sleep_link_t));
        size_t link_count = 0;
        for (size_t i = 0; i < world->contact_count; i++) {
            const solver_contact_t *c = &world->contacts[i];
            if (is_touching(c)) {
                world->links[link_count++] = (sleep_link_t){c->a, c->b};
            }
        }
        link_count += joint_links(&ws->joints, world->links + link_count);
        sleep_islands(&world->sleep, &step, world->links, link_count);
    }
    sleep_wake_reached(&world->sleep, &step, all_bodies, all_count, ws->sleep_changes);
}

/* The index of the body among the step's bodies[0 .. count), or -1 when it
 * is not one of them (the world, a sleeping body). */
static int64_t step_index(const body_t *body, body_t *const *bodies, size_t count) {
    if (body == NULL || body->solver_index >= count || bodies[body->solver_index] != body) {
        return -1;
    }
    return body->solver_index;
}

static int compare_keys(const void *a, const void *b) {
    uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
    return (x > y) - (x < y);
}

/* A joint's end as the world collides it: the body, or a chain's segment k
 * (a chain collides through its segments, which stand in its place). */
static size_t end_count(const body_t *body) {
    return body != NULL && body->part_count > 0 ? body->part_count : 1;
}

static const body_t *end_part(const body_t *body, size_t k) {
    return body != NULL && body->part_count > 0 ? body->parts[k] : body;
}

/* The keys of the step's body pairs that a joint joins without
 * collide_connected (joint.h), sorted; returns how many. */
static size_t joined_pairs(world_t *world, body_t *const *bodies, size_t count,
                           const joint_step_t *joints) {
    size_t n = 0;
    for (size_t i = 0; i < joints->count; i++) {
        const joint_def_t *def = &joints->joints[i]->def;
        if (def->collide_connected) continue;
        for (size_t p = 0; p < end_count(def->body1); p++) {
            for (size_t q = 0; q < end_count(def->body2); q++) {
                int64_t a = step_index(end_part(def->body1, p), bodies, count);
                int64_t b = step_index(end_part(def->body2, q), bodies, count);
                if (a < 0 || b < 0) continue;
                uint64_t low = (uint64_t)(a < b ? a : b), high = (uint64_t)(a < b ? b : a);
                memory_reserve((void **)&world->joined, &world->joined_capacity, n + 1,
                               sizeof(uint64_t));
                world->joined[n++] = low << 32 | high;
            }
        }
    }
    if (n > 1) qsort(world->joined, n, sizeof(uint64_t), compare_keys);
    return n;
}

/* Drops from the broadphase's pairs those of bodies a joint joins (the
 * one place the world decides which pairs collide beyond the filters);
 * the order, grouped by body a, stays. Returns the pair count. */
static size_t drop_joined_pairs(world_t *world, body_t *const *bodies, size_t count,
                                const joint_step_t *joints, const broadphase_pair_t **pairs,
                                size_t pair_count) {
    size_t joined = joined_pairs(world, bodies, count, joints);
    if (joined == 0) return pair_count;
    memory_reserve((void **)&world->kept_pairs, &world->kept_capacity, pair_count,
                   sizeof(broadphase_pair_t));
    size_t kept = 0;
    for (size_t i = 0; i < pair_count; i++) {
        uint64_t key = (uint64_t)(*pairs)[i].a << 32 | (*pairs)[i].b;
        if (bsearch(&key, world->joined, joined, sizeof(uint64_t), compare_keys) == NULL) {
            world->kept_pairs[kept++] = (*pairs)[i];
        }
    }
    *pairs = world->kept_pairs;
    return kept;
}

/* The pipeline over bodies[0 .. count), which are all the scene's bodies
 * or, with sleeping, its awake ones. */
static void run_pipeline(world_t *world, body_t **bodies, integrator_motion_t *motions,
                         size_t count, const world_step_t *step, scene_stats_t *stats,
                         body_t **all_bodies, size_t all_count) {
    /* A new world searches before loading, whose checks would read what an
     * older world (since freed) left in the bodies. */
    /* With every body asleep nothing runs but sleeping's bookkeeping,
     * which the sleep stage's time takes. */
    stage_clock_t *clock = count > 0 ? step->clock : NULL;
    if (!world->seams.found) seams_find(&world->seams, bodies, count);
    if (load_bodies(world, bodies, motions, count, step)) {
        seams_find(&world->seams, bodies, count);
    }
    const broadphase_pair_t *pairs;
    size_t pair_count =
        pair_tracker_find(world->pairs, world->proxies, count, &pairs, &stats->broadphase_tests);
    pair_count = drop_joined_pairs(world, bodies, count, &step->joints, &pairs, pair_count);
    stage_clock_lap(clock, SCENE_STAGE_BROADPHASE);
    narrowphase_find_contacts(world, bodies, pairs, pair_count);
    impacts_take(world, step->dt, step->largest_polygon, step->restitution_threshold);
    stage_clock_lap(clock, SCENE_STAGE_NARROWPHASE);
    solver_settings_t settings = {step->dt,
                                  step->position_weight,
                                  world->velocity_iterations,
                                  world->position_iterations,
                                  step->warm_starting,
                                  step->restitution_threshold,
                                  solver_sweeps_reversed(world->solver_steps),
                                  clock};
    world->solver_steps++;
    solver_bodies_t rows = {world->velocities, world->displacements, world->states, count};
    joint_step_t joints = {step->joints.joints, step->joints.count, &world->joint_tree};
    solver_solve(&world->wide, &world->shock, world->contacts, world->anchors,
                 world->contact_count, &rows, &settings, &joints);
    if (step->sleeping) {
        update_sleep(world, bodies, count, step, all_bodies, all_count);
        stage_clock_lap(step->clock, SCENE_STAGE_SLEEP);
    }
    write_back(world, motions, count);

    stats->broadphase_pairs += pair_count;
    stats->contacts += world->contact_count;
    stats->contact_points += world->point_count;
    stage_clock_lap(clock, SCENE_STAGE_SOLVER);
}

/* The bodies of the step and copies of their motions: the awake ones (all
 * when skip_asleep is false), then the segments of the chains among them,
 * static bodies that stand in their chain's place (their index SIZE_MAX:
 * no motion to hand back); returns how many. Segments come last, so each
 * pair with one has it as body b. */
static size_t gather_bodies(world_t *world, body_t **bodies, const integrator_motion_t *motions,
                            size_t count, bool skip_asleep, size_t parts) {
    size_t room = count + parts;
    memory_reserve((void **)&world->active, &world->active_capacity, room, sizeof(body_t *));
    memory_reserve((void **)&world->active_motions, &world->active_motion_capacity, room,
                   sizeof(integrator_motion_t));
    memory_reserve((void **)&world->active_index, &world->active_index_capacity, room,
                   sizeof(size_t));
    size_t active = 0;
    for (size_t i = 0; i < count; i++) {
        if (skip_asleep && bodies[i]->asleep) continue;
        world->active[active] = bodies[i];
        world->active_motions[active] = motions[i];
        world->active_index[active++] = i;
    }
    for (size_t i = 0; i < count && parts > 0; i++) {
        const body_t *chain = bodies[i];
        if (chain->part_count == 0 || chain->removed) continue;
        for (size_t k = 0; k < chain->part_count && active < room; k++) {
            world->active[active] = chain->parts[k];
            world->active_motions[active] = motions[i]; /* a static body's */
            world->active_index[active++] = SIZE_MAX;
        }
    }
    return active;
}

/* The ratios by which warm starting rescales last step's impulses when
 * this step's dt differs (warm_rescaled); the ratio is exactly 1 for an
 * equal dt, and the impulses are then copied unchanged. */
static void time_step(world_t *world, double dt) {
    world->warm_ratio = world->last_dt > 0.0 ? dt / world->last_dt : 1.0;
    world->warm_share = world->last_dt > 0.0 ? dt / (world->last_dt + world->older_dt) : 1.0;
    world->older_dt = world->last_dt;
    world->last_dt = dt;
}

void world_wake_changed(world_t *world, body_t **bodies, size_t count, double dt,
                        vector_t gravity) {
    if (!sleep_any(&world->sleep)) return;
    /* Last step's reach covered a step as long as itself. */
    bool longer = dt > world->last_dt;
    for (size_t i = 0; i < count; i++) {
        if (bodies[i]->changed) {
            sleep_wake_changed(&world->sleep, bodies[i], dt, gravity, CONTACT_MARGIN);
        } else if (longer) {
            sleep_wake_ahead(&world->sleep, bodies[i], dt, gravity, CONTACT_MARGIN);
        }
    }
}

void world_step(world_t *world, body_t **bodies, integrator_motion_t *motions, size_t count,
                const world_step_t *step, scene_stats_t *stats) {
    time_step(world, step->dt);
    body_t **all_bodies = step->all_bodies != NULL ? step->all_bodies : bodies;
    size_t all_count = step->all_bodies != NULL ? step->all_count : count;
    /* Some of the bodies may be asleep, unless the caller left them out. */
    bool sleepers = step->sleeping && sleep_any(&world->sleep) && step->all_bodies == NULL;
    /* Nobody asleep and no chain: every body is in the step, with nothing
     * to gather. */
    if (!sleepers && step->chain_parts == 0) {
        run_pipeline(world, bodies, motions, count, step, stats, all_bodies, all_count);
        return;
    }
    size_t active = gather_bodies(world, bodies, motions, count, sleepers, step->chain_parts);
    if (sleepers) stage_clock_lap(step->clock, SCENE_STAGE_SLEEP);
    run_pipeline(world, world->active, world->active_motions, active, step, stats, all_bodies,
                 all_count);
    for (size_t k = 0; k < active; k++) {
        size_t i = world->active_index[k];
        if (i != SIZE_MAX) motions[i] = world->active_motions[k];
    }
    if (sleepers) stage_clock_lap(step->clock, SCENE_STAGE_SLEEP);
}

bool world_pair_collides(const body_t *body1, const body_t *body2) {
    broadphase_proxy_t proxy1, proxy2;
    set_filter(&proxy1, body1);
    set_filter(&proxy2, body2);
    return broadphase_filters_allow(&proxy1, &proxy2);
}
