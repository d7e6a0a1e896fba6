/*
 * make bench-stages: what a scene pays for the stages it does not use
 * (docs/leave-out.md). Each scene runs as it is and with every optional
 * stage forced on through the public API (world contacts enabled but every
 * pair filtered out, sleeping off, the record read every step), and the
 * orbit scene against a hand-written loop over the same two bodies. Times
 * are CPU ms per step, the median of 7 runs, the variants of a scene in
 * alternation so that the machine's drift falls on both.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "jostle/jostle.h"

enum { RUNS = 7 };
static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};

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

/* Every optional stage on, doing nothing that changes the motion: world
 * contacts (with no pair allowed, in a scene that had them off), sleeping
 * off, the record published. */
static void force_stages_on(world_t *world) {
    if (!scene_get_contacts_enabled(world->scene)) {
        scene_set_contacts_enabled(world->scene, true);
        for (size_t i = 0; i < scene_bodies(world->scene); i++) {
            body_set_collision_filter(scene_get_body(world->scene, i), 1, 0, 0);
        }
    }
    scene_set_sleeping(world->scene, false);
    world->read_record = true;
}

static double step_ms(world_t *world, int steps, double dt) {
    double start = cpu_seconds();
    for (int i = 0; i < steps; i++) {
        scene_tick(world->scene, dt);
        if (world->read_record) (void)scene_contact_count(world->scene);
    }
    return (cpu_seconds() - start) * 1e3 / steps;
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
 * walled box), run until it has settled. */
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

static size_t count_asleep(scene_t *scene) {
    size_t asleep = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        asleep += body_is_sleeping(scene_get_body(scene, i));
    }
    return asleep;
}

/* ---- Measuring ---- */

static int compare_doubles(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *values, int count) {
    qsort(values, (size_t)count, sizeof(double), compare_doubles);
    return values[count / 2];
}

typedef void (*build_t)(world_t *world);

/* The scene as it is against every stage forced on, in alternation. */
static void compare_forced(const char *name, build_t build, int warm_steps, int steps, double dt,
                           FILE *md) {
    double plain[RUNS], forced[RUNS];
    for (int r = 0; r < RUNS; r++) {
        for (int variant = 0; variant < 2; variant++) {
            world_t world = {scene_init(), false};
            build(&world);
            if (variant == 1) force_stages_on(&world);
            for (int i = 0; i < warm_steps; i++) scene_tick(world.scene, dt);
            double ms = step_ms(&world, steps, dt);
            (variant == 0 ? plain : forced)[r] = ms;
            scene_free(world.scene);
        }
        fprintf(stderr, "\r  %-24s run %d/%d", name, r + 1, RUNS);
    }
    double p = median(plain, RUNS), f = median(forced, RUNS);
    fprintf(md, "| %s | %.4g | %.4g | %.2f |\n", name, p, f, f / p);
}

static void build_orbit_scene(world_t *world) {
    build_orbit(world);
}

/* Two bodies under Newtonian gravity, symplectic Euler, by hand: the same
 * physics as the engine's orbit scene written as plainly as it goes, in its
 * own order of operations (one division for m1 m2 / r^3, then by each
 * mass), so it does not end at the engine's bits. The time to beat. */
static double hand_orbit_ms(const vector_t at[2], int steps, double dt, double *x_end) {
    double xa = at[0].x, ya = at[0].y, vxa = 0, vya = 0, xb = at[1].x, yb = at[1].y;
    double vxb = 0, vyb = 10;
    const double ma = 1000, mb = 1;
    double start = cpu_seconds();
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
    *x_end = xb;
    return (cpu_seconds() - start) * 1e3 / steps;
}

/* The same loop in the engine's order of operations: the force G m1 m2 /
 * r^2, divided by r, along r; each acceleration the force times the inverse
 * mass. It ends at the engine's bits, which shows that the engine does this
 * arithmetic (the step of docs/design.md with no gravity, impulse or contact
 * adds only zeros) and how much of the gap that order costs. */
static double engine_order_orbit_ms(const vector_t at[2], int steps, double dt,
                                    double *x_end) {
    double xa = at[0].x, ya = at[0].y, vxa = 0, vya = 0, xb = at[1].x, yb = at[1].y;
    double vxb = 0, vyb = 10;
    const double G = 1, ma = 1000, mb = 1, inverse_ma = 1 / ma, inverse_mb = 1 / mb;
    double start = cpu_seconds();
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
    *x_end = xb;
    return (cpu_seconds() - start) * 1e3 / steps;
}

static void compare_hand_loop(int steps, int runs, FILE *md) {
    const double dt = 1e-4;
    double hand[RUNS], ordered[RUNS], ours[RUNS], x_hand = 0.0, x_ordered = 0.0, x_ours = 0.0;
    for (int r = 0; r < runs; r++) {
        world_t world = {scene_init(), false};
        build_orbit(&world);
        /* The loops start where the engine put the bodies: a box's centroid
         * is computed, (2^-56, 2^-56) for the one at the origin. */
        const vector_t start[2] = {body_get_centroid(scene_get_body(world.scene, 0)),
                                   body_get_centroid(scene_get_body(world.scene, 1))};
        hand[r] = hand_orbit_ms(start, steps, dt, &x_hand);
        ordered[r] = engine_order_orbit_ms(start, steps, dt, &x_ordered);
        ours[r] = step_ms(&world, steps, dt);
        x_ours = body_get_centroid(scene_get_body(world.scene, 1)).x;
        scene_free(world.scene);
        fprintf(stderr, "\r  %-24s run %d/%d", "orbit against a loop", r + 1, runs);
    }
    double h = median(hand, runs), e = median(ordered, runs), o = median(ours, runs);
    fprintf(md, "\n| orbit (2 bodies, %d steps) | ns per step | |\n|---|---|---|\n", steps);
    fprintf(md, "| hand-written loop | %.1f | |\n", h * 1e6);
    fprintf(md, "| the same loop in the engine's order of operations | %.1f | %.2f times the loop%s |\n",
            e * 1e6, e / h, x_ordered == x_ours ? "; same final position as scene_tick to the bit" : "");
    fprintf(md, "| scene_tick | %.1f | %.2f times the loop |\n", o * 1e6, o / h);
    fprintf(md, "\nWhat scene_tick adds to the loop in the engine's order: the step of any "
                "body (docs/design.md) adds gravity, the impulses and the seed scheme's "
                "share of the old velocity, zeros here but on the chain from one position to "
                "the next; forces reach the integrator through the bodies' accumulators; and "
                "it runs about ten times the loop's instructions (`valgrind --tool=callgrind "
                "build/bench/bench_stages --orbit 100000`), which a core shared with another "
                "thread feels: the scene_tick row can move by a quarter from run to run.\n");
}

/* A pile settled with sleeping off (every body stepped) against the same
 * pile with sleeping on, once it is asleep. pile(4000) falls asleep at
 * about 85 s (a deep pile still slips here and there before). */
static void compare_sleeping(int count, FILE *md) {
    double awake[RUNS], asleep[RUNS];
    size_t slept = 0;
    const int settle = count <= 1000 ? 900 : 6000;
    for (int r = 0; r < 3; r++) {
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
        fprintf(stderr, "\r  %-24s run %d/3", "settled pile", r + 1);
    }
    double a = median(awake, 3), s = median(asleep, 3);
    fprintf(md, "| pile(%d) after %d s | %.4g | %.4g (%zu of %d bodies asleep) | %.1f |\n",
            count, settle / 60, a, s, slept, count, a / s);
}

static void build_pile_1000(world_t *world) {
    build_pile(world, 1000);
}

int main(int argc, char **argv) {
    /* --orbit STEPS: the orbit against the hand loop alone, once, on stdout,
     * for a profiler (valgrind --tool=callgrind counts each side's
     * instructions under hand_orbit_ms and step_ms). */
    if (argc > 2 && strcmp(argv[1], "--orbit") == 0) {
        compare_hand_loop(atoi(argv[2]), 1, stdout);
        fputc('\n', stderr);
        return 0;
    }
    if (argc > 2 || (argc == 2 && argv[1][0] == '-')) {
        fprintf(stderr, "usage: bench_stages [REPORT.md]   (default docs/leave-out.md)\n"
                        "       bench_stages --orbit STEPS\n");
        return argc == 2 && strcmp(argv[1], "--help") == 0 ? 0 : 2;
    }
    const char *path = argc > 1 ? argv[1] : "docs/leave-out.md";
    FILE *md = fopen(path, "w");
    if (md == NULL) {
        fprintf(stderr, "bench_stages: cannot write %s\n", path);
        return 1;
    }
    fprintf(md, "# What a scene leaves out, measured\n\n"
                "Generated by `make bench-stages` (tests/bench/bench_stages.c); do not edit by "
                "hand. docs/design.md lists the stages of a step and what makes each run. CPU ms "
                "per step, the median of %d runs, the two variants of a scene in alternation. "
                "*Forced on*: the same scene with world contacts enabled but every pair "
                "filtered out, sleeping off, and the step's record read after every step: "
                "every optional stage runs and changes nothing.\n\n"
                "| scene | as it is (ms/step) | every stage forced on | ratio |\n"
                "|---|---|---|---|\n",
            RUNS);
    compare_forced("orbits (2 bodies)", build_orbit_scene, 0, 20000, 1e-3, md);
    compare_forced("spring chain (20 bodies)", build_spring_chain, 0, 20000, 1e-3, md);
    compare_forced("seed collisions (50 boxes)", build_seed_collisions, 0, 2000, 1.0 / 60.0, md);
    compare_forced("pyramid(20), contacts", build_pyramid, 60, 300, 1.0 / 60.0, md);
    compare_forced("settling pile(1000)", build_pile_1000, 0, 300, 1.0 / 60.0, md);
    fprintf(md, "\n| settled pile | every body stepped (sleeping off) | sleeping on | "
                "awake / asleep |\n|---|---|---|---|\n");
    compare_sleeping(1000, md);
    compare_sleeping(4000, md);
    compare_hand_loop(1000000, RUNS, md);
    fclose(md);
    fprintf(stderr, "\nbench_stages: wrote %s\n", path);
    return 0;
}
