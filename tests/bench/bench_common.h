#ifndef BENCH_COMMON_H
#define BENCH_COMMON_H

/*
 * Shared by the three benchmark programs (bench_engine.c, bench_chipmunk.c,
 * bench_box2d.cpp): the constants of the canonical scenes of
 * docs/bench-scenes.md, their random generator, a monotonic timer,
 * median and mean, the printing of one result line, and the small interface
 * (bench_ops_t) through which bench_scenes.h builds and runs every scene the
 * same way on every engine.
 *
 * Plain C11 that also compiles as C++ (no designated initialisers, no
 * compound literals, no implicit void * conversions).
 *
 * Output format, one line per scene, size and engine:
 *   engine=NAME scene=NAME size=N runs=R mean_ms=M median_ms=M [more key=value]
 * mean_ms and median_ms are the mean and the median over the R runs of each
 * run's mean milliseconds per step, in CPU time of the process
 * (CLOCK_PROCESS_CPUTIME_ID; only the engine's step call is timed: building
 * the scene and reading states for the quality figures are not).
 * Lines starting with '#' are comments (settings, compiler).
 */

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* ---- Scene constants (SCENES.md). Units: m, kg, s. ---- */

#define BENCH_GRAVITY_Y (-10.0)
#define BENCH_G_ABS 10.0
#define BENCH_DT (1.0 / 60.0)
#define BENCH_FRICTION 0.6
#define BENCH_DEFAULT_RUNS 5

/* --iterations: the solver's velocity iterations for every world made
 * after it is set; 0 keeps each engine's default. */
static int bench_iterations = 0;
/* --variant: run only the variant of this name; NULL runs them all. */
static const char *bench_variant = NULL;
/* --steps: the number of steps of the scenes that run a fixed count (pile,
 * pyramid, column, stack2, overlap and the stability scenes that say so);
 * 0 keeps each scene's own. */
static int bench_steps = 0;

/* A scene's step count: --steps when given, else its own. */
static inline int bench_step_count(int own) {
    return bench_steps > 0 ? bench_steps : own;
}

/* pile(N) */
#define PILE_STEPS 600
#define PILE_SETTLED_FIRST 301 /* settled figures: steps 301..600 (1-based) */
#define PILE_COLUMNS 70
#define PILE_PITCH 1.12
#define PILE_JITTER 0.1
#define PILE_RADIUS 0.5
#define PILE_LEFT 0.0
#define PILE_RIGHT 80.0
static const int pile_sides[5] = {3, 4, 5, 6, 8};

/* pyramid(B) */
#define PYRAMID_STEPS 600
#define PYRAMID_HALF 0.5
#define PYRAMID_GROUND_HALF_WIDTH 100.0

/* bounce(e) */
#define BOUNCE_FLOOR_HALF_WIDTH 50.0
#define BOUNCE_START_BOTTOM 10.0
#define BOUNCE_APEXES 5
#define BOUNCE_MAX_TIME 30.0 /* s; far beyond the ~8 s five bounces take */

/* cradle(n) */
#define CRADLE_STRIKER_X (-3.0)
#define CRADLE_SPEED 2.0
#define CRADLE_STEPS 300 /* 5 s: the striker arrives at t = 1 s */

/* orbit */
#define ORBIT_G 1.0
#define ORBIT_MASS_A 1000.0
#define ORBIT_MASS_B 1.0
#define ORBIT_X_B 10.0
#define ORBIT_VY_B 10.0
#define ORBIT_HALF 0.1
#define ORBIT_PERIODS 10

/* stack2(r) */
#define COLUMN_STEPS 3600
#define COLUMN_JITTER 0.02
#define STACK2_STEPS 600
#define STACK2_GROUND_HALF_WIDTH 20.0

/* tunnel(v) */
#define TUNNEL_STEPS 120
#define TUNNEL_PHASES 16
#define TUNNEL_WALL_HALF_WIDTH 0.05
#define TUNNEL_WALL_HALF_HEIGHT 5.0
#define TUNNEL_BULLET_HALF 0.1
#define TUNNEL_START_X (-5.0)
static const double tunnel_speeds[10] = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000};

/* overlap */
#define OVERLAP_STEPS 300
#define OVERLAP_BASE 4
#define OVERLAP_PITCH 0.75
#define OVERLAP_GROUND_HALF_WIDTH 20.0

/* ---- Random numbers ----
 * SCENES.md: s0 = 12345; s(k+1) = (1103515245 s(k) + 12345) mod 2^31;
 * u(k) = s(k) / 2^31. Interpretation used here: the state starts at
 * s = s0, and every draw FIRST advances the state, then returns the new
 * state divided by 2^31 (so the first number drawn is u(1) = s(1) / 2^31;
 * s0 itself is never returned). The product is computed in 64 bits, exactly.
 *
 * s0 is the layout seed (--layout-seed, docs/bench-scenes.md "Layout
 * seeds"): 12345, the canonical layout, unless a run asks for another so
 * that a chaotic quality figure can be judged over several layouts. With a
 * seed other than the canonical one, the scenes with no random layout whose
 * figures are chaotic (the pyramids and overlap) shift each box sideways by
 * up to BENCH_LAYOUT_JITTER (times the scene's scale), drawn from the seed.
 */
#define BENCH_CANONICAL_SEED 12345u
#define BENCH_LAYOUT_JITTER 1e-4 /* m, at scale 1 */

static uint64_t bench_layout_seed = BENCH_CANONICAL_SEED;

typedef struct {
    uint64_t s;
} bench_rng_t;

static inline void bench_rng_init(bench_rng_t *rng) {
    rng->s = bench_layout_seed;
}

/* Whether the layout differs from the canonical one (the jittered scenes
 * then move their boxes). */
static inline int bench_layout_jittered(void) {
    return bench_layout_seed != BENCH_CANONICAL_SEED;
}

static inline double bench_rng_next(bench_rng_t *rng) {
    rng->s = (1103515245ull * rng->s + 12345ull) % 2147483648ull;
    return (double)rng->s / 2147483648.0;
}

/* A sideways shift in [-amplitude, amplitude) for the next box of a
 * jittered scene; 0 (and no draw) with the canonical seed. */
static inline double bench_layout_shift(bench_rng_t *rng, double amplitude) {
    if (!bench_layout_jittered()) return 0.0;
    return amplitude * (2.0 * bench_rng_next(rng) - 1.0);
}

/* ---- Timing and statistics ---- */

/* Milliseconds on the monotonic clock (wall time). */
static inline double bench_now_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* Milliseconds of CPU time of the whole process (every thread): what the
 * step figures are measured in, so that time the process spends waiting for
 * a core another program holds is not counted. */
static inline double bench_cpu_ms(void) {
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

/* --wall: the result lines add wall_median_ms, the wall time of the same
 * step calls (beside CPU time it shows whether the threads of a
 * multi-threaded step had their cores). bench_wall_ms sums it over a run,
 * bench_timed_steps counts the step calls of the run; --count-steps adds
 * timed_steps=N to the result lines (tests/bench/instructions.sh divides an
 * instruction count by it). */
static int bench_wall = 0;
static int bench_count_steps = 0;
static double bench_wall_ms = 0.0;
static long bench_timed_steps = 0;

/* --stages: after each timed step the engine's own account of its stages
 * (bench_ops_t's stage_ms) is summed, over every step of the case's runs
 * and over the pile's settled steps, and printed after the result line as
 *   # stages engine=NAME scene=S size=N part=step|settled STAGE=MS ...
 * (mean ms per step, in the engine's order). Each engine times its stages
 * with its own clock, outside bench_step's timing but inside the run. */
#define BENCH_MAX_STAGES 24
typedef struct {
    const char *names[BENCH_MAX_STAGES];
    double step_ms[BENCH_MAX_STAGES], settled_ms[BENCH_MAX_STAGES];
    int count;
    long steps, settled_steps;
} bench_stage_sums_t;
static int bench_stages = 0;
static bench_stage_sums_t bench_stage_sums;

static inline double bench_mean(const double *values, int count) {
    double sum = 0.0;
    for (int i = 0; i < count; i++) sum += values[i];
    return count > 0 ? sum / count : NAN;
}

static inline int bench_compare_doubles(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median (mean of the two middle values for an even count). */
static inline double bench_median(const double *values, int count) {
    if (count <= 0) return NAN;
    double *sorted = (double *)malloc(sizeof(double) * (size_t)count);
    if (sorted == NULL) return NAN;
    memcpy(sorted, values, sizeof(double) * (size_t)count);
    qsort(sorted, (size_t)count, sizeof(double), bench_compare_doubles);
    double m = count % 2 ? sorted[count / 2] : 0.5 * (sorted[count / 2 - 1] + sorted[count / 2]);
    free(sorted);
    return m;
}

/* "1/60" when 1/dt is (close to) a whole number, else "%g". */
static inline void bench_format_dt(char *out, size_t size, double dt) {
    double inverse = 1.0 / dt;
    if (fabs(inverse - floor(inverse + 0.5)) < 1e-6 * inverse) {
        snprintf(out, size, "1/%.0f", floor(inverse + 0.5));
    } else {
        snprintf(out, size, "%g", dt);
    }
}

/* Prints one result line: the fixed keys, then `quality` (key=value pairs
 * separated by spaces, may be empty). settled_ms may be NULL. */
static inline void bench_print_result(const char *engine, const char *scene, const char *size,
                                      int runs, const double *run_ms, const double *settled_ms,
                                      const char *quality) {
    printf("engine=%s scene=%s size=%s runs=%d", engine, scene, size, runs);
    if (run_ms != NULL) {
        printf(" mean_ms=%.4g median_ms=%.4g", bench_mean(run_ms, runs),
               bench_median(run_ms, runs));
    }
    if (settled_ms != NULL) printf(" settled_median_ms=%.4g", bench_median(settled_ms, runs));
    if (quality != NULL && quality[0] != '\0') printf(" %s", quality);
    printf("\n");
    fflush(stdout);
}

/* ---- The engine interface the scenes are written against ----
 * Each program fills one bench_ops_t per engine variant; bench_scenes.h
 * builds every scene through it, so all engines get the same bodies in the
 * same order with the same numbers. Bodies are named by the int the add
 * functions return (static boxes included).
 */

/* A body shape, centred on its centroid in the body's own frame: sides == 0
 * is a box of half extents (hx, hy); sides >= 3 a regular polygon of
 * circumradius `radius` whose first vertex is at angle 0 (the body's angle
 * then turns it); BENCH_CIRCLE a circle of `radius`; BENCH_CAPSULE a capsule
 * of end circles of `radius` centred at (-hx, 0) and (hx, 0). */
#define BENCH_CIRCLE (-1)
#define BENCH_CAPSULE (-2)
typedef struct {
    int sides;
    double radius;
    double hx, hy;
} bench_shape_t;

typedef struct {
    double x, y, angle;   /* centroid (m), rotation (rad) */
    double vx, vy, omega; /* linear (m/s) and angular (rad/s) velocity */
} bench_state_t;

typedef struct bench_ops {
    /* The name printed after engine=. */
    const char *name;
    /* NULL, or a comma list of the only scenes this variant runs. */
    const char *only_scenes;
    /* How the engine combines two shapes' coefficients: friction by geometric
     * mean (0) or by product (1); restitution by max (0) or by product (1).
     * The scenes pick per-shape values so that the pair gets the scene's
     * coefficient either way (see bench_shape_friction). */
    int friction_product;
    int restitution_product;
    /* Prints '#' comment lines: version and settings. */
    void (*describe)(FILE *out);
    /* A new world with gravity (0, gy); contacts: whether bodies collide at
     * all (orbit: 0). body_capacity is a hint. */
    void *(*world_new)(double gy, int contacts, int body_capacity);
    void (*world_free)(void *world);
    /* A static (infinite mass) axis-aligned box. */
    int (*add_static_box)(void *world, double cx, double cy, double hx, double hy,
                          double friction, double elasticity);
    /* A dynamic body of the given mass (kg), placed with its centroid at
     * (x, y) and rotated by angle; collides == 0 keeps it out of contacts. */
    int (*add_body)(void *world, const bench_shape_t *shape, double x, double y, double angle,
                    double mass, double friction, double elasticity, int collides);
    void (*set_velocity)(void *world, int body, double vx, double vy);
    /* Newtonian gravity G m1 m2 / r^2 between the two bodies' centroids,
     * applied at every step from now on. */
    void (*add_gravity_pair)(void *world, int body1, int body2, double G);
    /* One fixed step of dt seconds (the only thing that is timed). */
    void (*step)(void *world, double dt);
    void (*get_state)(void *world, int body, bench_state_t *out);
    /* The largest penetration (m, >= 0) over the contacts the engine holds
     * after the last step; 0 when none overlaps. */
    double (*max_penetration)(void *world);
    /* The same restricted to the pair (body1, body2); 0 when not in contact. */
    double (*pair_penetration)(void *world, int body1, int body2);
    /* A spring between the two bodies' centroids: force k (length - rest)
     * along the line between them, and a damping force c times their
     * relative velocity (along that line, or in every direction for an
     * engine whose damping is a drag: same thing for motion along the
     * spring), from the next step on. body1 may be static. */
    void (*add_spring)(void *world, int body1, int body2, double k, double damping, double rest);
    void (*set_angular_velocity)(void *world, int body, double omega);
    /* The rest length (m) this engine's springs need: 0 for a zero-length
     * spring; the spring scenes then put the spring's fixed end that far
     * from the moving one, so the force along the line is the same linear
     * function for every engine (Box2D's distance joint clamps its length
     * to at least 5 mm, and both peers' springs lose their direction when
     * the two ends meet). */
    double spring_rest;
    /* How many movable bodies are awake; NULL for an engine whose
     * variants all run with sleeping off. */
    int (*awake_bodies)(void *world);
    /* A revolute joint (a pin): body2's point at the world point (x, y)
     * held on body1's point there (body1 -1: the world), both taken at the
     * bodies' current poses; the two bodies make no contact with each other.
     * With limit, body2's angle less body1's, counted from their relative
     * angle now, is kept in [lower, upper] (rad, lower <= 0 <= upper, within
     * +-0.99 pi). NULL for an engine without joints: the scenes that need
     * them are skipped with a note. */
    void (*add_revolute)(void *world, int body1, int body2, double x, double y, int limit,
                         double lower, double upper);
    /* Bodies given the same group (> 0) make no contact with one another;
     * their other contacts are kept. Needed with add_revolute. */
    void (*set_group)(void *world, int body, int group);
    /* The last step by the engine's own stages (--stages): names and ms,
     * at most max of them, in the order it runs them; returns how many.
     * NULL for an engine that does not say. */
    int (*stage_ms)(void *world, const char **names, double *ms, int max);
} bench_ops_t;

/* Area (m^2) of a shape: mass = area at density 1. */
static inline double bench_shape_area(const bench_shape_t *shape) {
    double r = shape->radius;
    if (shape->sides == BENCH_CIRCLE) return M_PI * r * r;
    if (shape->sides == BENCH_CAPSULE) return 4.0 * shape->hx * r + M_PI * r * r;
    if (shape->sides == 0) return 4.0 * shape->hx * shape->hy;
    return 0.5 * shape->sides * shape->radius * shape->radius * sin(2.0 * M_PI / shape->sides);
}

/* The i-th vertex of a shape in its own frame, counter-clockwise (boxes start
 * at the lower-left corner). */
static inline void bench_shape_vertex(const bench_shape_t *shape, int i, double *x, double *y) {
    if (shape->sides == 0) {
        static const double sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
        *x = sx[i] * shape->hx;
        *y = sy[i] * shape->hy;
    } else {
        double a = 2.0 * M_PI * i / shape->sides;
        *x = shape->radius * cos(a);
        *y = shape->radius * sin(a);
    }
}

static inline int bench_shape_vertex_count(const bench_shape_t *shape) {
    return shape->sides == 0 ? 4 : shape->sides;
}

/* Moment of inertia about the centroid of a uniform shape of mass m. */
static inline double bench_shape_inertia(const bench_shape_t *shape, double mass) {
    double r = shape->radius;
    if (shape->sides == BENCH_CIRCLE) return 0.5 * mass * r * r;
    if (shape->sides == BENCH_CAPSULE) {
        /* A 2 hx by 2 r rectangle and two half-discs, each moved from its
         * own centroid (4 r / (3 pi) past its end) by the parallel-axis rule. */
        double L = 2.0 * shape->hx, area = bench_shape_area(shape);
        double box = mass * 2.0 * r * L / area, half = mass * 0.5 * M_PI * r * r / area;
        double c = 4.0 * r / (3.0 * M_PI);
        double half_moment = half * (0.5 * r * r - c * c) + half * (0.5 * L + c) * (0.5 * L + c);
        return box * (L * L + 4.0 * r * r) / 12.0 + 2.0 * half_moment;
    }
    if (shape->sides == 0) return mass * (4.0 * shape->hx * shape->hx + 4.0 * shape->hy * shape->hy) / 12.0;
    double s = 2.0 * M_PI / shape->sides;
    return mass * shape->radius * shape->radius * (2.0 + cos(s)) / 6.0;
}

/* Per-shape friction so that two shapes with it give the pair `mu`. */
static inline double bench_shape_friction(const bench_ops_t *ops, double mu) {
    return ops->friction_product ? sqrt(mu) : mu;
}

/* Per-shape elasticity of static bodies: with max mixing 0 (the dynamic
 * body's value rules), with product mixing 1 (likewise). */
static inline double bench_static_elasticity(const bench_ops_t *ops) {
    return ops->restitution_product ? 1.0 : 0.0;
}

#endif // #ifndef BENCH_COMMON_H
