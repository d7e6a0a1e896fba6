/*
 * make bench-stages: what a scene saves by the stages it leaves out
 * (docs/leave-out.md). Each scene runs as it is and with one optional stage
 * switched at a time (the rest as the scene has them): world contacts on
 * with every pair filtered out (for a scene without them), sleeping off
 * (for a scene with them), the step's record read after every step. The
 * variants of a scene alternate within each round; times are CPU ms per
 * step, the median over the rounds with the least and the largest. Then
 * settled piles with sleeping off and on, and the orbit scene against
 * hand-written loops that add the engine's generality one piece at a time.
 *
 *   bench_stages [REPORT.md]     (default docs/leave-out.md)
 *   bench_stages --orbit STEPS   the orbit against the loops, once, on stdout
 *                                (for callgrind)
 *   bench_stages --facts         the figures that are not timings, one line
 *                                per scene, as the page writes them
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "jostle/jostle.h"

/* Rounds of each table; the page states them from here. */
enum { SCENE_ROUNDS = 7, PILE_ROUNDS = 3, ORBIT_ROUNDS = 7, MAX_ROUNDS = 7 };
static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};

typedef enum { AS_IT_IS, WITH_WORLD, SLEEPING_OFF, RECORD_READ, VARIANTS } variant_t;

typedef struct {
    scene_t *scene;
    bool read_record;
} world_t;

static double cpu_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static body_t *add_box(scene_t *scene, double x, double y, double half, double mass) {
    body_t *body = body_init(polygon_make_box((vector_t){x, y}, half, half), mass, GREY);
    scene_add_body(scene, body);
    return body;
}

static double step_ms(world_t *world, int steps, double dt) {
    double start = cpu_seconds();
    for (int i = 0; i < steps; i++) {
        scene_tick(world->scene, dt);
        if (world->read_record) (void)scene_contact_count(world->scene);
    }
    return (cpu_seconds() - start) * 1e3 / steps;
}

static int compare_doubles(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

typedef struct {
    double median, low, high;
} spread_t;

static spread_t spread(const double *values, int count) {
    double sorted[MAX_ROUNDS];
    memcpy(sorted, values, sizeof(double) * (size_t)count);
    qsort(sorted, (size_t)count, sizeof(double), compare_doubles);
    double median = count % 2 ? sorted[count / 2]
                              : 0.5 * (sorted[count / 2 - 1] + sorted[count / 2]);
    return (spread_t){median, sorted[0], sorted[count - 1]};
}

/* ---- The scenes ---- */

static void build_orbit(world_t *world) {
    scene_t *scene = world->scene;
    scene_set_integrator(scene, INTEGRATOR_SYMPLECTIC_EULER);
    body_t *a = add_box(scene, 0.0, 0.0, 0.1, 1000.0), *b = add_box(scene, 10.0, 0.0, 0.1, 1.0);
    body_set_velocity(b, (vector_t){0.0, 10.0});
    create_newtonian_gravity(scene, 1.0, a, b);
}

static void build_spring_chain(world_t *world) {
    scene_t *scene = world->scene;
    scene_set_integrator(scene, INTEGRATOR_SYMPLECTIC_EULER);
    scene_set_gravity(scene, (vector_t){0.0, -10.0});
    body_t *previous = add_box(scene, 0.0, 0.0, 0.1, INFINITY);
    for (int i = 1; i <= 20; i++) {
        body_t *body = add_box(scene, 0.5 * i, 0.0, 0.1, 1.0);
        create_spring(scene, 1000.0, previous, body);
        previous = body;
    }
}

/* Fifty boxes in a box of four walls, no gravity, seed pair collisions
 * (create_physics_collision) between every two. */
static void build_seed_collisions(world_t *world) {
    scene_t *scene = world->scene;
    body_t *walls[4] = {add_box(scene, 0.0, -11.0, 10.0, INFINITY),
                        add_box(scene, 0.0, 11.0, 10.0, INFINITY),
                        add_box(scene, -11.0, 0.0, 10.0, INFINITY),
                        add_box(scene, 11.0, 0.0, 10.0, INFINITY)};
    body_t *boxes[50];
    for (int i = 0; i < 50; i++) {
        boxes[i] = add_box(scene, -8.0 + 1.8 * (i % 10), -8.0 + 3.5 * (i / 10), 0.4, 1.0);
        body_set_velocity(boxes[i], (vector_t){cos(i * 2.3) * 3.0, sin(i * 2.3) * 3.0});
        for (int w = 0; w < 4; w++) create_physics_collision(scene, boxes[i], walls[w], 1.0);
        for (int j = 0; j < i; j++) create_physics_collision(scene, boxes[i], boxes[j], 1.0);
    }
}

static void build_pyramid(world_t *world) {
    scene_t *scene = world->scene;
    scene_set_gravity(scene, (vector_t){0.0, -10.0});
    scene_set_contacts_enabled(scene, true);
    scene_add_body(scene, body_init(polygon_make_box((vector_t){0.0, -0.5}, 100.0, 0.5),
                                    INFINITY, GREY));
    for (int row = 0; row < 20; row++) {
        for (int k = 0; k < 20 - row; k++) {
            add_box(scene, (k - (20 - row - 1) / 2.0) * 1.0, 0.5 + row, 0.5, 1.0);
        }
    }
}

/* pile(N) of docs/bench-scenes.md (polygons of 3 to 8 sides dropped in a
 * walled box). */
static void build_pile(world_t *world, int count) {
    scene_t *scene = world->scene;
    scene_set_gravity(scene, (vector_t){0.0, -10.0});
    scene_set_contacts_enabled(scene, true);
    const double walls[3][4] = {{40, -0.5, 41, 0.5}, {-0.5, 100, 0.5, 100}, {80.5, 100, 0.5, 100}};
    for (int w = 0; w < 3; w++) {
        scene_add_body(scene, body_init(polygon_make_box((vector_t){walls[w][0], walls[w][1]},
                                                         walls[w][2], walls[w][3]),
                                        INFINITY, GREY));
    }
    const int sides[5] = {3, 4, 5, 6, 8};
    unsigned state = 12345;
    for (int i = 0; i < count; i++) {
        double u[3];
        for (int k = 0; k < 3; k++) {
            state = (unsigned)((1103515245ull * state + 12345ull) % 2147483648ull);
            u[k] = state / 2147483648.0;
        }
        vector_t at = {1.0 + 1.12 * (i % 70) + 0.1 * (u[0] - 0.5),
                       1.0 + 1.12 * (i / 70) + 0.1 * (u[1] - 0.5)};
        body_t *body = body_init(polygon_make_regular((size_t)sides[i % 5], 0.5, at,
                                                      2.0 * M_PI * u[2]),
                                 1.0, GREY);
        scene_add_body(scene, body);
    }
}

static void build_pile_1000(world_t *world) {
    build_pile(world, 1000);
}

static size_t count_asleep(scene_t *scene) {
    size_t asleep = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        asleep += body_is_sleeping(scene_get_body(scene, i));
    }
    return asleep;
}

/* Bodies of finite mass: the ones that can sleep. */
static size_t count_movable(scene_t *scene) {
    size_t movable = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        movable += isfinite(body_get_mass(scene_get_body(scene, i)));
    }
    return movable;
}

/* ---- One switch at a time ---- */

typedef void (*build_t)(world_t *world);

typedef struct {
    const char *name;
    build_t build;
    const char *forces; /* its force creators, for the stages column */
    int warm_steps, steps;
    double dt;
} scene_case_t;

static const scene_case_t SCENES[] = {
    {"orbits (2 bodies)", build_orbit, "1 Newtonian gravity", 0, 20000, 1e-3},
    {"spring chain (20 bodies)", build_spring_chain, "20 springs", 0, 20000, 1e-3},
    {"seed collisions (50 boxes)", build_seed_collisions, "1425 pair collisions", 0, 2000,
     1.0 / 60.0},
    {"pyramid(20), contacts", build_pyramid, "none", 60, 300, 1.0 / 60.0},
    {"settling pile(1000)", build_pile_1000, "none", 0, 300, 1.0 / 60.0},
};
enum { SCENE_COUNT = sizeof SCENES / sizeof SCENES[0] };

/* Whether the switch applies to the scene as it is built. */
static bool applies(variant_t variant, bool contacts) {
    switch (variant) {
    case WITH_WORLD: return !contacts;
    case SLEEPING_OFF: return contacts;
    default: return true;
    }
}

static void switch_on(world_t *world, variant_t variant) {
    scene_t *scene = world->scene;
    if (variant == WITH_WORLD) {
        scene_set_contacts_enabled(scene, true);
        for (size_t i = 0; i < scene_bodies(scene); i++) {
            body_set_collision_filter(scene_get_body(scene, i), 1, 0, 0);
        }
    } else if (variant == SLEEPING_OFF) {
        scene_set_sleeping(scene, false);
    } else if (variant == RECORD_READ) {
        world->read_record = true;
    }
}

/* What the scene as it is runs, measured over its timed steps. */
static void describe_stages(const scene_case_t *c, char *text, size_t size) {
    world_t world = {scene_init(), false};
    c->build(&world);
    bool contacts = scene_get_contacts_enabled(world.scene);
    for (int i = 0; i < c->warm_steps; i++) scene_tick(world.scene, c->dt);
    double points = 0.0;
    size_t evaluations = 0;
    for (int i = 0; i < c->steps; i++) {
        scene_tick(world.scene, c->dt);
        points += (double)scene_get_stats(world.scene).contact_points;
        evaluations += scene_get_stats(world.scene).force_evaluations;
    }
    size_t asleep = count_asleep(world.scene), movable = count_movable(world.scene);
    if (contacts) {
        snprintf(text, size,
                 "forces: %s; world contacts: on, %.1f contact points a step; sleeping: on, "
                 "%zu of %zu movable bodies asleep at the end; record: not read",
                 c->forces, points / c->steps, asleep, movable);
    } else {
        snprintf(text, size,
                 "forces: %s, run %.0f time%s a step; world contacts: off; sleeping: does "
                 "not act (no contacts); record: %s",
                 c->forces, (double)evaluations / c->steps,
                 evaluations == (size_t)c->steps ? "" : "s",
                 strstr(c->forces, "collision") ? "seed collisions only, not read" : "not read");
    }
    scene_free(world.scene);
}

static void compare_switches(const scene_case_t *c, FILE *md) {
    double ms[VARIANTS][MAX_ROUNDS], ratio[VARIANTS][MAX_ROUNDS];
    world_t probe = {scene_init(), false};
    c->build(&probe);
    bool contacts = scene_get_contacts_enabled(probe.scene);
    scene_free(probe.scene);
    for (int r = 0; r < SCENE_ROUNDS; r++) {
        for (int v = 0; v < VARIANTS; v++) {
            if (!applies((variant_t)v, contacts)) continue;
            world_t world = {scene_init(), false};
            c->build(&world);
            switch_on(&world, (variant_t)v);
            for (int i = 0; i < c->warm_steps; i++) scene_tick(world.scene, c->dt);
            ms[v][r] = step_ms(&world, c->steps, c->dt);
            ratio[v][r] = ms[v][r] / ms[AS_IT_IS][r];
            scene_free(world.scene);
        }
        fprintf(stderr, "\r  %-28s round %d/%d", c->name, r + 1, SCENE_ROUNDS);
    }
    char stages[512];
    describe_stages(c, stages, sizeof stages);
    spread_t base = spread(ms[AS_IT_IS], SCENE_ROUNDS);
    fprintf(md, "| %s | %s | %.4g (%.4g-%.4g)", c->name, stages, base.median * 1e3,
            base.low * 1e3, base.high * 1e3);
    for (int v = WITH_WORLD; v < VARIANTS; v++) {
        if (!applies((variant_t)v, contacts)) {
            fprintf(md, " | %s", v == WITH_WORLD ? "on already" : "does not act");
            continue;
        }
        spread_t t = spread(ms[v], SCENE_ROUNDS), q = spread(ratio[v], SCENE_ROUNDS);
        fprintf(md, " | %.4g (%.4g-%.4g): %.2f (%.2f-%.2f)", t.median * 1e3, t.low * 1e3,
                t.high * 1e3, q.median, q.low, q.high);
    }
    fprintf(md, " |\n");
}

/* A pile settled with sleeping off (every body stepped) against the same
 * pile with sleeping on, once it is asleep. pile(4000) falls asleep at
 * about 85 s (a deep pile still slips here and there before). */
static int settle_steps(int count) {
    return count <= 1000 ? 900 : 6000;
}

static void compare_sleeping(int count, FILE *md) {
    double awake[MAX_ROUNDS], asleep[MAX_ROUNDS], ratio[MAX_ROUNDS];
    size_t slept = 0;
    const int settle = settle_steps(count);
    for (int r = 0; r < PILE_ROUNDS; r++) {
        for (int sleeping = 0; sleeping < 2; sleeping++) {
            world_t world = {scene_init(), false};
            build_pile(&world, count);
            scene_set_sleeping(world.scene, sleeping);
            for (int i = 0; i < settle; i++) scene_tick(world.scene, 1.0 / 60.0);
            double ms = step_ms(&world, 300, 1.0 / 60.0);
            (sleeping ? asleep : awake)[r] = ms;
            if (sleeping) slept = count_asleep(world.scene);
            scene_free(world.scene);
        }
        ratio[r] = awake[r] / asleep[r];
        fprintf(stderr, "\r  %-28s round %d/%d", "settled pile", r + 1, PILE_ROUNDS);
    }
    spread_t a = spread(awake, PILE_ROUNDS), s = spread(asleep, PILE_ROUNDS);
    spread_t q = spread(ratio, PILE_ROUNDS);
    fprintf(md, "| pile(%d) after %d s | %.4g (%.4g-%.4g) | %.4g (%.4g-%.4g) | %zu of %d | %.1f "
                "(%.1f-%.1f) |\n",
            count, settle / 60, a.median, a.low, a.high, s.median, s.low, s.high, slept, count,
            q.median, q.low, q.high);
}

/* ---- The orbit against hand-written loops ---- */

/* The state of the two bodies as the loops keep it. */
typedef struct {
    double x[2], y[2], vx[2], vy[2];
} orbit_state_t;

/* Two bodies under Newtonian gravity, symplectic Euler, written as plainly
 * as it goes in its own order of operations (one division for m1 m2 / r^3,
 * then by each mass): not the engine's bits. The time to beat. */
static void plain_loop(orbit_state_t *s, int steps, double dt) {
    double xa = s->x[0], ya = s->y[0], vxa = s->vx[0], vya = s->vy[0];
    double xb = s->x[1], yb = s->y[1], vxb = s->vx[1], vyb = s->vy[1];
    const double ma = 1000, mb = 1;
    for (int i = 0; i < steps; i++) {
        double dx = xb - xa, dy = yb - ya, r2 = dx * dx + dy * dy, r = sqrt(r2);
        double f = ma * mb / (r2 * r);
        vxa += dt * f * dx / ma;
        vya += dt * f * dy / ma;
        vxb -= dt * f * dx / mb;
        vyb -= dt * f * dy / mb;
        xa += dt * vxa;
        ya += dt * vya;
        xb += dt * vxb;
        yb += dt * vyb;
    }
    *s = (orbit_state_t){{xa, xb}, {ya, yb}, {vxa, vxb}, {vya, vyb}};
}

/* The engine's order of operations: the force G m1 m2 / r^2, divided by r,
 * along r; each acceleration the force times the inverse mass. Ends at the
 * engine's bits. */
static void engine_order_loop(orbit_state_t *s, int steps, double dt) {
    double xa = s->x[0], ya = s->y[0], vxa = s->vx[0], vya = s->vy[0];
    double xb = s->x[1], yb = s->y[1], vxb = s->vx[1], vyb = s->vy[1];
    const double G = 1, ma = 1000, mb = 1, inverse_ma = 1 / ma, inverse_mb = 1 / mb;
    for (int i = 0; i < steps; i++) {
        double dx = xb - xa, dy = yb - ya, r = sqrt(dx * dx + dy * dy);
        double k = G * ma * mb / (r * r) / r, fx = k * dx, fy = k * dy;
        vxa += dt * (inverse_ma * fx);
        vya += dt * (inverse_ma * fy);
        vxb -= dt * (inverse_mb * fx);
        vyb -= dt * (inverse_mb * fy);
        xa += dt * vxa;
        ya += dt * vya;
        xb += dt * vxb;
        yb += dt * vyb;
    }
    *s = (orbit_state_t){{xa, xb}, {ya, yb}, {vxa, vxb}, {vya, vyb}};
}

/* A body as the engine keeps one: in memory, reached through a pointer,
 * with force accumulators that the forces add to and the step clears. */
typedef struct {
    double x, y, angle, vx, vy, spin;
    double fx, fy, torque, jx, jy, angular_impulse;
    double mass, inverse_mass, inverse_inertia;
} loop_body_t;

static void gravity_into(loop_body_t *a, loop_body_t *b) {
    double dx = b->x - a->x, dy = b->y - a->y, r = sqrt(dx * dx + dy * dy);
    double k = 1.0 * a->mass * b->mass / (r * r) / r, fx = k * dx, fy = k * dy;
    a->fx += fx;
    a->fy += fy;
    b->fx -= fx;
    b->fy -= fy;
}

/* ... and a force creator called through a pointer. */
typedef void (*loop_force_t)(loop_body_t *a, loop_body_t *b);

static void accumulator_loop(loop_body_t *bodies, int steps, double dt, loop_force_t force) {
    for (int i = 0; i < steps; i++) {
        force(&bodies[0], &bodies[1]);
        for (int k = 0; k < 2; k++) {
            loop_body_t *p = &bodies[k];
            p->vx += dt * (p->inverse_mass * p->fx);
            p->vy += dt * (p->inverse_mass * p->fy);
            p->x += dt * p->vx;
            p->y += dt * p->vy;
            p->fx = p->fy = 0.0;
        }
    }
}

/* ... and the step of any body (docs/design.md): gravity, impulses, torque
 * and spin, the scheme's weight of the old velocity, all zeros here but
 * on the chain from one position to the next; and the result checked to
 * be finite, which lets a failing step name its body and cause. */
static bool general_loop(loop_body_t *bodies, int steps, double dt, loop_force_t force,
                         double gx, double gy, double w) {
    for (int i = 0; i < steps; i++) {
        force(&bodies[0], &bodies[1]);
        for (int k = 0; k < 2; k++) {
            loop_body_t *p = &bodies[k];
            double ax = p->inverse_mass * p->fx + gx, ay = p->inverse_mass * p->fy + gy;
            double vx = p->vx + (dt * ax + p->inverse_mass * p->jx);
            double vy = p->vy + (dt * ay + p->inverse_mass * p->jy);
            double spin = p->spin + p->inverse_inertia * (dt * p->torque + p->angular_impulse);
            double dx = dt * ((1.0 - w) * p->vx + w * vx), dy = dt * ((1.0 - w) * p->vy + w * vy);
            double turn = dt * ((1.0 - w) * p->spin + w * spin);
            double x = p->x + dx, y = p->y + dy, angle = p->angle + turn;
            if (!isfinite(x) || !isfinite(y) || !isfinite(angle) || !isfinite(vx) ||
                !isfinite(vy) || !isfinite(spin)) {
                return false;
            }
            p->x = x, p->y = y, p->angle = angle, p->vx = vx, p->vy = vy, p->spin = spin;
            p->fx = p->fy = p->torque = p->jx = p->jy = p->angular_impulse = 0.0;
        }
    }
    return true;
}

typedef struct {
    const char *name;
    const char *adds;
} loop_row_t;

static const loop_row_t LOOPS[] = {
    {"hand-written loop", "the physics alone, its own order of operations"},
    {"the engine's order of operations", "the same arithmetic as scene_tick (one division by "
                                         "r^2, another by r; forces times inverse masses)"},
    {"+ bodies in memory, force accumulators, a force creator called through a pointer",
     "any number of bodies and forces"},
    {"+ the step of any body, its result checked to be finite",
     "gravity, impulses, torques and spin, every one-stage scheme; a step that overflows "
     "stops with the body and the cause named"},
    {"scene_tick", "everything else scene.h promises: contacts, sleeping, multi-stage schemes, "
                   "removal, the record, threads, bad input stopped"},
};
enum { LOOP_COUNT = sizeof LOOPS / sizeof LOOPS[0] };

static void start_bodies(loop_body_t bodies[2], const orbit_state_t *s) {
    for (int k = 0; k < 2; k++) {
        double mass = k == 0 ? 1000.0 : 1.0;
        bodies[k] = (loop_body_t){s->x[k], s->y[k], 0, s->vx[k], s->vy[k], 0, 0, 0, 0, 0, 0, 0,
                                  mass, 1.0 / mass, 0.0};
    }
}

static void compare_loops(int steps, int rounds, FILE *md) {
    const double dt = 1e-4;
    double ms[LOOP_COUNT][MAX_ROUNDS], end[LOOP_COUNT];
    for (int r = 0; r < rounds; r++) {
        world_t world = {scene_init(), false};
        build_orbit(&world);
        /* The loops start where the engine put the bodies: a box's centroid
         * is computed, (2^-56, 2^-56) for the one at the origin. */
        orbit_state_t start = {{0}, {0}, {0, 0}, {0, 10}};
        for (int k = 0; k < 2; k++) {
            vector_t c = body_get_centroid(scene_get_body(world.scene, (size_t)k));
            start.x[k] = c.x;
            start.y[k] = c.y;
        }
        for (int l = 0; l < LOOP_COUNT; l++) {
            orbit_state_t s = start;
            loop_body_t bodies[2];
            start_bodies(bodies, &start);
            double t0 = cpu_seconds();
            switch (l) {
            case 0: plain_loop(&s, steps, dt); break;
            case 1: engine_order_loop(&s, steps, dt); break;
            case 2: accumulator_loop(bodies, steps, dt, gravity_into); break;
            case 3: general_loop(bodies, steps, dt, gravity_into, 0.0, 0.0, 1.0); break;
            default:
                for (int i = 0; i < steps; i++) scene_tick(world.scene, dt);
                break;
            }
            ms[l][r] = (cpu_seconds() - t0) * 1e3 / steps;
            end[l] = l < 2 ? s.x[1] : l < 4 ? bodies[1].x
                                            : body_get_centroid(scene_get_body(world.scene, 1)).x;
        }
        scene_free(world.scene);
        fprintf(stderr, "\r  %-28s round %d/%d", "orbit against loops", r + 1, rounds);
    }
    fprintf(md, "| orbit, 2 bodies, %d steps | ns per step (range) | times the loop | same "
                "final position as scene_tick | what it adds |\n|---|---|---|---|---|\n",
            steps);
    spread_t base = spread(ms[0], rounds);
    for (int l = 0; l < LOOP_COUNT; l++) {
        double ratio[MAX_ROUNDS];
        for (int r = 0; r < rounds; r++) ratio[r] = ms[l][r] / ms[0][r];
        spread_t t = spread(ms[l], rounds), q = spread(ratio, rounds);
        fprintf(md, "| %s | %.1f (%.1f-%.1f) | %.2f (%.2f-%.2f) | %s | %s |\n", LOOPS[l].name,
                t.median * 1e6, t.low * 1e6, t.high * 1e6, q.median, q.low, q.high,
                l == LOOP_COUNT - 1                ? "-"
                : end[l] == end[LOOP_COUNT - 1] ? "yes, to the bit"
                                                 : "no",
                LOOPS[l].adds);
    }
    (void)base;
}

/* ---- The page ---- */

static void write_page(FILE *md) {
    fprintf(md,
            "# What a scene leaves out, measured\n\n"
            "Generated by `make bench-stages` (tests/bench/bench_stages.c); do not edit by "
            "hand. docs/design.md lists the stages of a step and what makes each run. Times "
            "are CPU time of the scene_tick calls (CLOCK_PROCESS_CPUTIME_ID) per step: the "
            "median over the rounds, the least and the largest in brackets.\n\n"
            "## One switch at a time\n\n"
            "Each scene as it is, and with one optional stage switched, the rest as the scene "
            "has them: *world contacts* on with every pair filtered out (a scene without "
            "them; with them they are its physics), *sleeping* off (a scene with world "
            "contacts; without them sleeping does not act), the step's *record* read after "
            "every step. %d rounds; in each, the variants of a scene run one after another "
            "(each built anew). Microseconds per step; a switched cell gives its time per "
            "step, then that time over the scene's as it is: the median and range of that "
            "ratio over the rounds.\n\n"
            "| scene | what it runs as it is | as it is (us/step) | + world contacts, every "
            "pair filtered | sleeping off | record read every step |\n"
            "|---|---|---|---|---|---|\n",
            SCENE_ROUNDS);
    for (int c = 0; c < SCENE_COUNT; c++) compare_switches(&SCENES[c], md);
    fprintf(md, "\n## Sleeping on a settled pile\n\n"
                "A pile settled with sleeping off, every body stepped, against the same pile "
                "with sleeping on once it is asleep: 300 steps timed after the settling, %d "
                "rounds (each pile built and settled anew).\n\n"
                "| settled pile | sleeping off (ms/step) | sleeping on | bodies asleep | off / "
                "on |\n|---|---|---|---|---|\n",
            PILE_ROUNDS);
    compare_sleeping(1000, md);
    compare_sleeping(4000, md);
    fprintf(md, "\n## The orbit against hand-written loops\n\n"
                "scene_tick on the orbit scene (symplectic Euler, two bodies, Newtonian "
                "gravity) against loops that do the same physics, each row adding one piece of "
                "what the engine does for any scene; %d rounds, the rows one after another in "
                "each. The rows that follow the engine's arithmetic end at scene_tick's final "
                "position to the bit.\n\n",
            ORBIT_ROUNDS);
    compare_loops(1000000, ORBIT_ROUNDS, md);
    fprintf(md, "\nEach row's instructions: `valgrind --tool=callgrind build/bench/bench_stages "
                "--orbit 100000` (each loop is its own function; scene_tick's are those "
                "compare_loops calls).\n");
}

int main(int argc, char **argv) {
    if (argc > 2 && strcmp(argv[1], "--orbit") == 0) {
        compare_loops(atoi(argv[2]), 1, stdout);
        fputc('\n', stderr);
        return 0;
    }
    if (argc == 2 && strcmp(argv[1], "--facts") == 0) {
        for (int c = 0; c < SCENE_COUNT; c++) {
            char stages[512];
            describe_stages(&SCENES[c], stages, sizeof stages);
            printf("| %s | %s |\n", SCENES[c].name, stages);
        }
        return 0;
    }
    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
        fprintf(stderr, "usage: bench_stages [REPORT.md]   (default docs/leave-out.md)\n"
                        "       bench_stages --orbit STEPS\n       bench_stages --facts\n");
        return argc == 2 && strcmp(argv[1], "--help") == 0 ? 0 : 2;
    }
    const char *path = argc > 1 ? argv[1] : "docs/leave-out.md";
    FILE *md = fopen(path, "w");
    if (md == NULL) {
        fprintf(stderr, "bench_stages: cannot write %s\n", path);
        return 1;
    }
    write_page(md);
    fclose(md);
    fprintf(stderr, "\nbench_stages: wrote %s\n", path);
    return 0;
}
