#ifndef BENCH_SCENES_H
#define BENCH_SCENES_H

/*
 * The canonical scenes of docs/bench-scenes.md written once against
 * bench_ops_t (bench_common.h), and the command line shared by the three
 * benchmark programs. Each program defines its engine variants and calls
 * bench_main. Plain C that also compiles as C++.
 *
 * Options:
 *   --scene NAME     pile, pyramid, bounce, cradle, orbit, stack2, tunnel,
 *                    overlap, column, circlepile, capsulepile, mixedpile,
 *                    jointchain, ragdolls or all; repeatable or a comma list
 *   --size X         the scene's size (pile N, pyramid B, bounce e, cradle n,
 *                    stack2 r, tunnel v, jointchain links,
 *                    ragdolls count); repeatable or a comma list
 *   --dt X           step of bounce and orbit (e.g. 1/600 or 0.001);
 *                    repeatable or a comma list
 *   --runs R         runs of each scene (default 5); the median is reported
 *   --quick          smaller sizes and 1 run (a smoke run)
 *   --wall           adds wall_median_ms (wall time of the step calls) to
 *                    each line; mean_ms and median_ms are CPU time of the
 *                    process (CLOCK_PROCESS_CPUTIME_ID)
 *   --count-steps    adds timed_steps (step calls of the last run)
 *   --stages         prints, after each result line, the engine's own
 *                    account of its stages (bench_common.h)
 *   --layout-seed K  the random generator's first state (0 .. 2^31 - 1;
 *                    default 12345, the canonical layout): pile, column and
 *                    the stability scenes drawing random numbers get another
 *                    layout, the pyramids and overlap a sideways jitter of
 *                    each box (bench_common.h); result lines then end with
 *                    layout_seed=K (docs/bench-scenes.md, tests/bench/seeds.sh)
 * No --scene: the benchmark set pile 1000, 4000, 10000; pyramid 20, 40;
 * bounce 0.8 at dt 1/60 and 1/600; cradle 5.
 *
 * Quality keys (figures of the first run; runs_differ=1 is added when a later
 * run gave different figures, i.e. the engine is not deterministic):
 *   pile     max_penetration (m, at step 600) outside (bodies whose centre
 *            is outside the container at step 600; must be 0); the same for
 *            circlepile, capsulepile and mixedpile
 *   pyramid  top_drop (m: the top box's centre height at step 600 minus its
 *            initial height, negative = it came down; standing: > -0.5 and
 *            the top within 0.5 m sideways; Box2D's skins make its towers
 *            grow, so a rise is not a fall)
 *            max_penetration (m, at step 600)
 *   bounce   dt, steps, apex1_rel_err .. apex5_rel_err: (h_n - 10 e^2n) /
 *            (10 e^2n) where h_n is the bottom face height at apex n (see
 *            bounce_run for how an apex is measured)
 *   cradle   max_dev (m/s: the largest |v - v_expected| over the six boxes,
 *            expected +2 for the last box, 0 for the others, after 5 s)
 *            momentum_rel_err (|P - P0| / |P0|) energy_rel_err ((E - E0) / E0,
 *            translational plus rotational)
 *   orbit    dt, steps, energy_rel_drift, angmom_rel_drift ((X - X0) / |X0|),
 *            pos_err (m: B against the exact two-body Kepler solution at the
 *            same time)
 *   stack2   pen_ground_a, pen_a_b (m, at step 600), b_on_a (1/0)
 *   tunnel   one line per v: tunnelled (runs out of 16), max_return_speed
 *            (m/s, largest final speed in -x); then a size=summary line with
 *            first_tunnel_v (smallest v that tunnelled, ">1000" if none)
 *   overlap  max_speed (m/s, any box, any step: the reported velocity),
 *            max_push_speed (m/s: the largest |position change over one
 *            step| / dt of any box, any step; what the recovery really
 *            moves, position corrections included), in_bounds (1 when every
 *            box stayed within x in [-20, 20], y >= 0 at every step),
 *            max_penetration (m, at step 300)
 *   jointchain, ragdolls  see bench_joint_scenes.h
 *   column   top_drift (m: the top box's |x - x0| at step 3600), top_drop (m:
 *            its height change, negative = down), max_tilt (rad: the largest
 *            |angle| of any box at step 3600), standing (1 when the top box
 *            is within 0.5 m of where it started), kinetic_energy (J, all
 *            boxes at the end)
 * pile and pyramid also print steps and, past 3600 steps (pile) or always
 * (pyramid), the figures their comments below list. The stability scenes
 * (spring, springpair, chain, heavytop, headon, tunnelmove, bullet, rod,
 * drop, coincide, gas, settle, wallbounce, scaled, far; docs/stability.md)
 * describe their keys where they are defined.
 */

#include "bench_common.h"

typedef enum {
    SCENE_PILE,
    SCENE_PYRAMID,
    SCENE_BOUNCE,
    SCENE_CRADLE,
    SCENE_ORBIT,
    SCENE_STACK2,
    SCENE_TUNNEL,
    SCENE_OVERLAP,
    SCENE_COLUMN,
    /* The stability scenes (docs/stability.md, make stability). */
    SCENE_SPRING,
    SCENE_SPRINGPAIR,
    SCENE_CHAIN,
    SCENE_HEAVYTOP,
    SCENE_HEADON,
    SCENE_TUNNELMOVE,
    SCENE_BULLET,
    SCENE_ROD,
    SCENE_DROP,
    SCENE_COINCIDE,
    SCENE_GAS,
    SCENE_SETTLE,
    SCENE_WALLBOUNCE,
    SCENE_SCALED,
    SCENE_FAR,
    /* The pile of round and mixed bodies (docs/bench-scenes.md). */
    SCENE_CIRCLEPILE,
    SCENE_CAPSULEPILE,
    SCENE_MIXEDPILE,
    /* Joints (bench_joint_scenes.h): run by the engines with add_revolute. */
    SCENE_JOINTCHAIN,
    SCENE_RAGDOLLS,
    SCENE_COUNT
} bench_scene_id_t;

static const char *const bench_scene_names[SCENE_COUNT] = {
    "pile",     "pyramid",    "bounce", "cradle",   "orbit",    "stack2",
    "tunnel",   "overlap",    "column", "spring",   "springpair", "chain",
    "heavytop", "headon",     "tunnelmove", "bullet", "rod",    "drop",
    "coincide", "gas",        "settle", "wallbounce", "scaled", "far",
    "circlepile", "capsulepile", "mixedpile", "jointchain", "ragdolls"};

/* --quick: smaller sweeps inside the scenes that sweep (spring, springpair,
 * chain). */
static int bench_quick = 0;

typedef struct {
    bench_scene_id_t scene;
    double size;
    double dt;
} bench_case_t;

/* What one run of a scene gives. */
typedef struct {
    double step_ms;    /* mean ms per step over the run */
    double settled_ms; /* pile: mean ms per step over steps 301..600 */
    char quality[768];
    /* tunnel only: for the summary line */
    int tunnelled;
    double max_return_speed;
} bench_run_t;

/* Adds the last step's stages to bench_stage_sums (--stages); a step of
 * the run from PILE_SETTLED_FIRST on counts as settled too (printed for the
 * piles only). */
static inline void bench_add_stages(const bench_ops_t *ops, void *world) {
    bench_stage_sums_t *sums = &bench_stage_sums;
    double ms[BENCH_MAX_STAGES];
    int count = ops->stage_ms(world, sums->names, ms, BENCH_MAX_STAGES);
    sums->count = count;
    int settled = bench_timed_steps >= PILE_SETTLED_FIRST;
    for (int k = 0; k < count; k++) {
        sums->step_ms[k] += ms[k];
        if (settled) sums->settled_ms[k] += ms[k];
    }
    sums->steps++;
    sums->settled_steps += settled;
}

static inline void bench_print_stages_part(const char *engine, const char *scene,
                                           const char *size, const char *part,
                                           const double *sum, long steps) {
    const bench_stage_sums_t *sums = &bench_stage_sums;
    if (steps == 0 || sums->count == 0) return;
    printf("# stages engine=%s scene=%s size=%s part=%s", engine, scene, size, part);
    for (int k = 0; k < sums->count; k++) printf(" %s=%.4g", sums->names[k], sum[k] / steps);
    printf("\n");
}

/* A timed step: returns its CPU time in ms (and adds its wall time to
 * bench_wall_ms under --wall). Never inlined, so that an instruction count
 * can be restricted to it (callgrind --toggle-collect='bench_step*',
 * tests/bench/instructions.sh). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static double bench_step(const bench_ops_t *ops, void *world, double dt) {
    double w0 = bench_wall ? bench_now_ms() : 0.0;
    double t0 = bench_cpu_ms();
    ops->step(world, dt);
    double ms = bench_cpu_ms() - t0;
    if (bench_wall) bench_wall_ms += bench_now_ms() - w0;
    bench_timed_steps++;
    if (bench_stages && ops->stage_ms != NULL) bench_add_stages(ops, world);
    return ms;
}

static inline bench_shape_t bench_box_shape(double hx, double hy) {
    bench_shape_t shape;
    shape.sides = 0;
    shape.radius = 0.0;
    shape.hx = hx;
    shape.hy = hy;
    return shape;
}

static inline bench_shape_t bench_regular_shape(int sides, double radius) {
    bench_shape_t shape;
    shape.sides = sides;
    shape.radius = radius;
    shape.hx = shape.hy = 0.0;
    return shape;
}

static inline bench_shape_t bench_capsule_shape(double half_length, double radius) {
    bench_shape_t shape = bench_regular_shape(BENCH_CAPSULE, radius);
    shape.hx = half_length;
    return shape;
}

/* ---- pile(N) ----
 * With --steps past 3600 (60 s), the pile's motion from 60 s on is measured
 * too: the largest total kinetic energy (J, translation and rotation) and
 * momentum (N s) over those steps, the most bodies faster than 0.01 m/s at
 * one step, and at the last step the kinetic energy, the bodies faster than
 * 0.01 m/s and the largest speed. */
#define PILE_LATE_FIRST 3600
#define PILE_CREEP_SPEED 0.01

/* Body i of a pile: pile, polygons of 3 to 8 sides on a circle of
 * PILE_RADIUS; circlepile, circles of that radius; capsulepile, capsules as
 * long (1 m end to end) and half as thick; mixedpile, a square on that
 * circle, a circle and a capsule in turn. */
static inline bench_shape_t pile_shape(bench_scene_id_t scene, int i) {
    bench_shape_t circle = bench_regular_shape(BENCH_CIRCLE, PILE_RADIUS);
    bench_shape_t capsule = bench_capsule_shape(0.5 * PILE_RADIUS, 0.5 * PILE_RADIUS);
    switch (scene) {
        case SCENE_CIRCLEPILE: return circle;
        case SCENE_CAPSULEPILE: return capsule;
        case SCENE_MIXEDPILE:
            return i % 3 == 0 ? bench_regular_shape(4, PILE_RADIUS) : i % 3 == 1 ? circle : capsule;
        default: return bench_regular_shape(pile_sides[i % 5], PILE_RADIUS);
    }
}

static inline void pile_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    int n = (int)c->size;
    double mu = bench_shape_friction(ops, BENCH_FRICTION);
    double e_static = bench_static_elasticity(ops);
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, n + 3);
    ops->add_static_box(w, 40.0, -0.5, 41.0, 0.5, mu, e_static);   /* floor */
    ops->add_static_box(w, -0.5, 100.0, 0.5, 100.0, mu, e_static); /* left wall */
    ops->add_static_box(w, 80.5, 100.0, 0.5, 100.0, mu, e_static); /* right wall */
    int *ids = (int *)malloc(sizeof(int) * (size_t)n);
    bench_rng_t rng;
    bench_rng_init(&rng);
    for (int i = 0; i < n; i++) {
        bench_shape_t shape = pile_shape(c->scene, i);
        int column = i % PILE_COLUMNS, row = i / PILE_COLUMNS;
        double u1 = bench_rng_next(&rng);
        double u2 = bench_rng_next(&rng);
        double u3 = bench_rng_next(&rng);
        double x = 1.0 + PILE_PITCH * column + PILE_JITTER * (u1 - 0.5);
        double y = 1.0 + PILE_PITCH * row + PILE_JITTER * (u2 - 0.5);
        ids[i] = ops->add_body(w, &shape, x, y, 2.0 * M_PI * u3, bench_shape_area(&shape), mu, 0.0,
                               1);
    }
    int steps = bench_step_count(PILE_STEPS);
    double total = 0.0, settled = 0.0;
    double late_ke = 0.0, late_p = 0.0, ke_end = 0.0, vmax_end = 0.0;
    int late_fast = 0, fast_end = 0;
    int asleep_step = 0; /* the first step after which every body sleeps */
    double asleep_total = 0.0; /* ms over the steps after it */
    int asleep_steps = 0;
    for (int step = 1; step <= steps; step++) {
        double ms = bench_step(ops, w, BENCH_DT);
        if (ops->awake_bodies != NULL && asleep_step == 0 && ops->awake_bodies(w) == 0) {
            asleep_step = step;
        }
        total += ms;
        if (asleep_step > 0 && step > asleep_step) {
            asleep_total += ms;
            asleep_steps++;
        }
        if (step >= PILE_SETTLED_FIRST) settled += ms;
        if (steps > PILE_LATE_FIRST && step >= PILE_LATE_FIRST) {
            double ke = 0.0, px = 0.0, py = 0.0, vmax = 0.0;
            int fast = 0;
            for (int i = 0; i < n; i++) {
                bench_shape_t shape = pile_shape(c->scene, i);
                double m = bench_shape_area(&shape);
                bench_state_t s;
                ops->get_state(w, ids[i], &s);
                double speed = hypot(s.vx, s.vy);
                ke += 0.5 * m * speed * speed +
                      0.5 * bench_shape_inertia(&shape, m) * s.omega * s.omega;
                px += m * s.vx;
                py += m * s.vy;
                if (speed > PILE_CREEP_SPEED) fast++;
                if (speed > vmax) vmax = speed;
            }
            late_ke = fmax(late_ke, ke);
            late_p = fmax(late_p, hypot(px, py));
            if (fast > late_fast) late_fast = fast;
            ke_end = ke, fast_end = fast, vmax_end = vmax;
        }
    }
    out->step_ms = total / steps;
    out->settled_ms = settled / (steps - PILE_SETTLED_FIRST + 1);
    int outside = 0;
    for (int i = 0; i < n; i++) {
        bench_state_t s;
        ops->get_state(w, ids[i], &s);
        if (!(s.x >= PILE_LEFT && s.x <= PILE_RIGHT && s.y >= 0.0)) outside++;
    }
    int len = snprintf(out->quality, sizeof out->quality, "max_penetration=%.4g outside=%d",
                       ops->max_penetration(w), outside);
    if (ops->awake_bodies != NULL) {
        if (asleep_step > 0) {
            len += snprintf(out->quality + len, sizeof out->quality - (size_t)len, " asleep_s=%.2f",
                            asleep_step * BENCH_DT);
            if (asleep_steps > 0) {
                len += snprintf(out->quality + len, sizeof out->quality - (size_t)len,
                                " asleep_ms=%.4g", asleep_total / asleep_steps);
            }
        } else {
            len += snprintf(out->quality + len, sizeof out->quality - (size_t)len,
                            " asleep_s=none awake_end=%d", ops->awake_bodies(w));
        }
    }
    if (steps > PILE_LATE_FIRST) {
        snprintf(out->quality + len, sizeof out->quality - (size_t)len,
                 " steps=%d late_ke_max=%.4g late_p_max=%.4g late_fast_max=%d ke_end=%.4g "
                 "fast_end=%d vmax_end=%.4g",
                 steps, late_ke, late_p, late_fast, ke_end, fast_end, vmax_end);
    }
    free(ids);
    ops->world_free(w);
}

/* ---- pyramid(B), and the pyramids of the stability scenes ----
 * A pyramid of `base` rows of boxes of side `scale` on a ground, moved by
 * (ox, oy), its top box `top_ratio` times as dense as the others. The
 * benchmark's pyramid is scale 1 at the origin with equal boxes. */
typedef struct {
    int base;
    double scale, ox, oy, top_ratio;
    int steps;
    double dt;
} pyramid_config_t;

typedef struct {
    double top_drop, top_drift, max_penetration, kinetic_energy, max_tilt;
    /* over the second half of the steps: the largest total kinetic energy
     * (J) and the largest speed of any box (m/s); only when track_late */
    double late_ke_max, late_speed_max;
} pyramid_result_t;

static inline double pyramid_generic(const bench_ops_t *ops, const pyramid_config_t *cfg,
                                     pyramid_result_t *result, int track_late) {
    int base = cfg->base;
    double s = cfg->scale;
    double mu = bench_shape_friction(ops, BENCH_FRICTION);
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, base * (base + 1) / 2 + 1);
    ops->add_static_box(w, cfg->ox + 0.0, cfg->oy - 0.5 * s, PYRAMID_GROUND_HALF_WIDTH * s,
                        0.5 * s, mu, bench_static_elasticity(ops));
    bench_shape_t box = bench_box_shape(PYRAMID_HALF * s, PYRAMID_HALF * s);
    int count = base * (base + 1) / 2;
    int *ids = (int *)malloc(sizeof(int) * (size_t)count);
    double *inertia = (double *)malloc(sizeof(double) * (size_t)count);
    double *mass = (double *)malloc(sizeof(double) * (size_t)count);
    int top = -1, n = 0;
    double top_x0 = 0.0, top_y0 = 0.0;
    bench_rng_t rng;
    bench_rng_init(&rng);
    for (int j = 0; j < base; j++) {
        for (int k = 0; k < base - j; k++) {
            double x = cfg->ox + (k - (base - j - 1) / 2.0) * 1.0 * s +
                       bench_layout_shift(&rng, BENCH_LAYOUT_JITTER * s);
            double y = cfg->oy + (0.5 + j * 1.0) * s;
            double m = bench_shape_area(&box) * (j == base - 1 ? cfg->top_ratio : 1.0);
            top = ids[n] = ops->add_body(w, &box, x, y, 0.0, m, mu, 0.0, 1);
            mass[n] = m;
            inertia[n++] = bench_shape_inertia(&box, m);
            top_x0 = x;
            top_y0 = y;
        }
    }
    double total = 0.0;
    result->late_ke_max = result->late_speed_max = 0.0;
    for (int step = 1; step <= cfg->steps; step++) {
        total += bench_step(ops, w, cfg->dt);
        if (track_late && 2 * step > cfg->steps) {
            double ke = 0.0;
            for (int i = 0; i < n; i++) {
                bench_state_t now;
                ops->get_state(w, ids[i], &now);
                double speed2 = now.vx * now.vx + now.vy * now.vy;
                ke += 0.5 * mass[i] * speed2 + 0.5 * inertia[i] * now.omega * now.omega;
                result->late_speed_max = fmax(result->late_speed_max, sqrt(speed2));
            }
            result->late_ke_max = fmax(result->late_ke_max, ke);
        }
    }
    bench_state_t st;
    result->kinetic_energy = 0.0;
    result->max_tilt = 0.0;
    for (int i = 0; i < n; i++) {
        ops->get_state(w, ids[i], &st);
        result->kinetic_energy += 0.5 * mass[i] * (st.vx * st.vx + st.vy * st.vy) +
                                  0.5 * inertia[i] * st.omega * st.omega;
        result->max_tilt = fmax(result->max_tilt, fabs(remainder(st.angle, 0.5 * M_PI)));
    }
    ops->get_state(w, top, &st);
    result->top_drop = st.y - top_y0;
    result->top_drift = st.x - top_x0;
    result->max_penetration = ops->max_penetration(w);
    free(ids);
    free(inertia);
    free(mass);
    ops->world_free(w);
    return total / cfg->steps;
}

static inline void pyramid_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    pyramid_config_t cfg = {(int)c->size, 1.0, 0.0, 0.0, 1.0, bench_step_count(PYRAMID_STEPS),
                            BENCH_DT};
    pyramid_result_t r;
    out->step_ms = pyramid_generic(ops, &cfg, &r, 0);
    snprintf(out->quality, sizeof out->quality,
             "top_drop=%.4g max_penetration=%.4g steps=%d kinetic_energy=%.4g standing=%d "
             "top_drift=%.4g",
             r.top_drop, r.max_penetration, cfg.steps, r.kinetic_energy,
             r.top_drop > -0.5 && fabs(r.top_drift) < 0.5, r.top_drift);
}

/* ---- bounce(e) ----
 * The apex measure, the same for every engine: after each step the box's
 * state is read; when vy changes sign from + (step k) to <= 0 (step k + 1),
 * apex n is the top of the ballistic parabola through the state of step k,
 * the last step with vy > 0: h = y_bottom + vy^2 / (2 g), with y_bottom the
 * centre height minus 0.5 (the box does not turn) and g = 10. This removes
 * the up-to-one-step sampling error of taking the highest sampled height.
 * Exact: 10 e^(2n). Stops after the 5th apex (or 30 s). */
static inline void bounce_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    double e = c->size, dt = c->dt;
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, 2);
    ops->add_static_box(w, 0.0, -0.5, BOUNCE_FLOOR_HALF_WIDTH, 0.5, 0.0,
                        bench_static_elasticity(ops));
    bench_shape_t box = bench_box_shape(0.5, 0.5);
    int id = ops->add_body(w, &box, 0.0, BOUNCE_START_BOTTOM + 0.5, 0.0, 1.0, 0.0, e, 1);
    double apex[BOUNCE_APEXES];
    int apexes = 0, steps = 0;
    int max_steps = (int)ceil(BOUNCE_MAX_TIME / dt);
    bench_state_t prev, s;
    ops->get_state(w, id, &prev);
    double total = 0.0;
    while (apexes < BOUNCE_APEXES && steps < max_steps) {
        total += bench_step(ops, w, dt);
        steps++;
        ops->get_state(w, id, &s);
        if (prev.vy > 0.0 && s.vy <= 0.0) {
            apex[apexes++] = prev.y - 0.5 + prev.vy * prev.vy / (2.0 * BENCH_G_ABS);
        }
        prev = s;
    }
    out->step_ms = total / steps;
    char dts[32];
    bench_format_dt(dts, sizeof dts, dt);
    int len = snprintf(out->quality, sizeof out->quality, "dt=%s steps=%d apexes=%d", dts, steps,
                       apexes);
    for (int n = 1; n <= BOUNCE_APEXES; n++) {
        double exact = BOUNCE_START_BOTTOM * pow(e, 2.0 * n);
        double err = n <= apexes ? (apex[n - 1] - exact) / exact : NAN;
        len += snprintf(out->quality + len, sizeof out->quality - (size_t)len,
                        " apex%d_rel_err=%.3e", n, err);
    }
    ops->world_free(w);
}

/* ---- cradle(n) ---- */
static inline void cradle_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    int n = (int)c->size;
    void *w = ops->world_new(0.0, 1, n + 1);
    bench_shape_t box = bench_box_shape(0.5, 0.5);
    int *ids = (int *)malloc(sizeof(int) * (size_t)(n + 1));
    for (int i = 0; i < n; i++) ids[i] = ops->add_body(w, &box, 1.0 * i, 0.0, 0.0, 1.0, 0.0, 1.0, 1);
    ids[n] = ops->add_body(w, &box, CRADLE_STRIKER_X, 0.0, 0.0, 1.0, 0.0, 1.0, 1);
    ops->set_velocity(w, ids[n], CRADLE_SPEED, 0.0);
    double total = 0.0;
    for (int step = 1; step <= CRADLE_STEPS; step++) total += bench_step(ops, w, BENCH_DT);
    out->step_ms = total / CRADLE_STEPS;
    double inertia = bench_shape_inertia(&box, 1.0);
    double max_dev = 0.0, px = 0.0, py = 0.0, energy = 0.0;
    for (int i = 0; i <= n; i++) {
        bench_state_t s;
        ops->get_state(w, ids[i], &s);
        double expected = i == n - 1 ? CRADLE_SPEED : 0.0;
        double dev = hypot(s.vx - expected, s.vy);
        if (dev > max_dev) max_dev = dev;
        px += s.vx;
        py += s.vy;
        energy += 0.5 * (s.vx * s.vx + s.vy * s.vy) + 0.5 * inertia * s.omega * s.omega;
    }
    double p0 = CRADLE_SPEED, e0 = 0.5 * CRADLE_SPEED * CRADLE_SPEED;
    snprintf(out->quality, sizeof out->quality,
             "max_dev=%.4g momentum_rel_err=%.3e energy_rel_err=%.3e", max_dev,
             hypot(px - p0, py) / p0, (energy - e0) / e0);
    free(ids);
    ops->world_free(w);
}

/* ---- orbit ----
 * The exact solution: the relative vector r = x_B - x_A follows a Kepler
 * ellipse with mu = G (m_A + m_B), propagated with Lagrange's f and g in the
 * eccentric anomaly difference (Newton on Kepler's equation); the barycentre
 * moves uniformly; x_B = barycentre + m_A / M r. */
static inline void bench_kepler(double mu, double rx, double ry, double vx, double vy, double t,
                                double *out_x, double *out_y) {
    double r0 = hypot(rx, ry), v2 = vx * vx + vy * vy;
    double a = 1.0 / (2.0 / r0 - v2 / mu);
    double n = sqrt(mu / (a * a * a));
    double sigma = (rx * vx + ry * vy) / sqrt(mu * a);
    double k = 1.0 - r0 / a;
    double m = n * t;
    double de = m;
    for (int i = 0; i < 100; i++) {
        double f = de + sigma * (1.0 - cos(de)) - k * sin(de) - m;
        double fp = 1.0 + sigma * sin(de) - k * cos(de);
        double step = f / fp;
        de -= step;
        if (fabs(step) < 1e-15 * (1.0 + fabs(de))) break;
    }
    double f = 1.0 - a / r0 * (1.0 - cos(de));
    double g = t - (de - sin(de)) / n;
    *out_x = f * rx + g * vx;
    *out_y = f * ry + g * vy;
}

static inline void orbit_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    double dt = c->dt;
    double ma = ORBIT_MASS_A, mb = ORBIT_MASS_B, total_mass = ma + mb, mu = ORBIT_G * total_mass;
    void *w = ops->world_new(0.0, 0, 2);
    bench_shape_t box = bench_box_shape(ORBIT_HALF, ORBIT_HALF);
    int a = ops->add_body(w, &box, 0.0, 0.0, 0.0, ma, 0.0, 0.0, 0);
    int b = ops->add_body(w, &box, ORBIT_X_B, 0.0, 0.0, mb, 0.0, 0.0, 0);
    ops->set_velocity(w, b, 0.0, ORBIT_VY_B);
    ops->add_gravity_pair(w, a, b, ORBIT_G);
    /* initial relative orbit and the period */
    double rx = ORBIT_X_B, ry = 0.0, rvx = 0.0, rvy = ORBIT_VY_B;
    double sma = 1.0 / (2.0 / hypot(rx, ry) - (rvx * rvx + rvy * rvy) / mu);
    double period = 2.0 * M_PI * sqrt(sma * sma * sma / mu);
    long steps = lround(ORBIT_PERIODS * period / dt);
    double e0 = 0.5 * mb * ORBIT_VY_B * ORBIT_VY_B - ORBIT_G * ma * mb / ORBIT_X_B;
    double l0 = mb * ORBIT_X_B * ORBIT_VY_B;
    double total = 0.0;
    for (long i = 0; i < steps; i++) total += bench_step(ops, w, dt);
    out->step_ms = total / (double)steps;
    bench_state_t sa, sb;
    ops->get_state(w, a, &sa);
    ops->get_state(w, b, &sb);
    double dx = sb.x - sa.x, dy = sb.y - sa.y;
    double energy = 0.5 * ma * (sa.vx * sa.vx + sa.vy * sa.vy) +
                    0.5 * mb * (sb.vx * sb.vx + sb.vy * sb.vy) - ORBIT_G * ma * mb / hypot(dx, dy);
    double l = ma * (sa.x * sa.vy - sa.y * sa.vx) + mb * (sb.x * sb.vy - sb.y * sb.vx);
    double t = (double)steps * dt;
    double relx, rely;
    bench_kepler(mu, rx, ry, rvx, rvy, t, &relx, &rely);
    double cmx = mb * ORBIT_X_B / total_mass, cmy = mb * ORBIT_VY_B / total_mass * t;
    double bx = cmx + ma / total_mass * relx, by = cmy + ma / total_mass * rely;
    char dts[32];
    bench_format_dt(dts, sizeof dts, dt);
    snprintf(out->quality, sizeof out->quality,
             "dt=%s steps=%ld energy_rel_drift=%.3e angmom_rel_drift=%.3e pos_err=%.4g", dts,
             steps, (energy - e0) / fabs(e0), (l - l0) / fabs(l0), hypot(sb.x - bx, sb.y - by));
    ops->world_free(w);
}

/* ---- stack2(r) ---- */
static inline void stack2_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    double r = c->size;
    double mu = bench_shape_friction(ops, BENCH_FRICTION);
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, 3);
    int ground = ops->add_static_box(w, 0.0, -0.5, STACK2_GROUND_HALF_WIDTH, 0.5, mu,
                                     bench_static_elasticity(ops));
    bench_shape_t box = bench_box_shape(0.5, 0.5);
    int a = ops->add_body(w, &box, 0.0, 0.5, 0.0, bench_shape_area(&box), mu, 0.0, 1);
    int b = ops->add_body(w, &box, 0.0, 1.5, 0.0, r * bench_shape_area(&box), mu, 0.0, 1);
    double total = 0.0;
    int steps = bench_step_count(STACK2_STEPS);
    for (int step = 1; step <= steps; step++) total += bench_step(ops, w, BENCH_DT);
    out->step_ms = total / steps;
    bench_state_t sa, sb;
    ops->get_state(w, a, &sa);
    ops->get_state(w, b, &sb);
    int on = fabs(sb.x - sa.x) < 0.5 && sb.y - sa.y > 0.9;
    snprintf(out->quality, sizeof out->quality, "pen_ground_a=%.4g pen_a_b=%.4g b_on_a=%d",
             ops->pair_penetration(w, ground, a), ops->pair_penetration(w, a, b), on);
    ops->world_free(w);
}

/* ---- tunnel(v): 16 phases, each a fresh world ----
 * tunnel: a 0.2 m box against a static 0.1 m wall; tunnelmove: against the
 * same wall free to move (density 1: 1 kg against the bullet's 0.04 kg);
 * bullet: a 0.01 m box (0.0001 kg) against the static wall. A run
 * tunnelled when the bullet's centre ends past the wall's; the return
 * speed is how fast the bullet leaves the wall (v_wall - v_bullet along
 * x), 0 after an inelastic impact. */
static inline void tunnel_generic(const bench_ops_t *ops, const bench_case_t *c,
                                  bench_run_t *out, double bullet_half, int movable_wall) {
    double v = c->size, dt = BENCH_DT;
    bench_shape_t wall = bench_box_shape(TUNNEL_WALL_HALF_WIDTH, TUNNEL_WALL_HALF_HEIGHT);
    bench_shape_t bullet = bench_box_shape(bullet_half, bullet_half);
    double total = 0.0, max_back = 0.0;
    int tunnelled = 0;
    for (int k = 0; k < TUNNEL_PHASES; k++) {
        void *w = ops->world_new(0.0, 1, 2);
        int wall_id;
        if (movable_wall) {
            wall_id = ops->add_body(w, &wall, 0.0, 0.0, 0.0, bench_shape_area(&wall), 0.0, 0.0, 1);
        } else {
            wall_id = ops->add_static_box(w, 0.0, 0.0, TUNNEL_WALL_HALF_WIDTH,
                                          TUNNEL_WALL_HALF_HEIGHT, 0.0,
                                          bench_static_elasticity(ops));
        }
        double x0 = TUNNEL_START_X - ((k + 0.5) / TUNNEL_PHASES) * v * dt;
        int id = ops->add_body(w, &bullet, x0, 0.0, 0.0, bench_shape_area(&bullet), 0.0, 0.0, 1);
        ops->set_velocity(w, id, v, 0.0);
        for (int step = 1; step <= TUNNEL_STEPS; step++) total += bench_step(ops, w, dt);
        bench_state_t s, sw;
        ops->get_state(w, id, &s);
        sw.x = sw.vx = 0.0;
        if (movable_wall) ops->get_state(w, wall_id, &sw);
        if (s.x > sw.x) tunnelled++;
        if (sw.vx - s.vx > max_back) max_back = sw.vx - s.vx;
        ops->world_free(w);
    }
    out->step_ms = total / (TUNNEL_PHASES * TUNNEL_STEPS);
    out->tunnelled = tunnelled;
    out->max_return_speed = max_back;
    snprintf(out->quality, sizeof out->quality, "tunnelled=%d/%d max_return_speed=%.4g", tunnelled,
             TUNNEL_PHASES, max_back);
}

static inline void tunnel_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    tunnel_generic(ops, c, out, TUNNEL_BULLET_HALF, 0);
}

static inline void tunnelmove_run(const bench_ops_t *ops, const bench_case_t *c,
                                  bench_run_t *out) {
    tunnel_generic(ops, c, out, TUNNEL_BULLET_HALF, 1);
}

static inline void bullet_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    tunnel_generic(ops, c, out, 0.005, 0);
}

/* ---- overlap ---- */
static inline void overlap_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    (void)c;
    double mu = bench_shape_friction(ops, BENCH_FRICTION);
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, 11);
    ops->add_static_box(w, 0.0, -0.5, OVERLAP_GROUND_HALF_WIDTH, 0.5, mu,
                        bench_static_elasticity(ops));
    bench_shape_t box = bench_box_shape(0.5, 0.5);
    int ids[OVERLAP_BASE * (OVERLAP_BASE + 1) / 2], count = 0;
    bench_rng_t rng;
    bench_rng_init(&rng);
    for (int j = 0; j < OVERLAP_BASE; j++) {
        for (int k = 0; k < OVERLAP_BASE - j; k++) {
            double x = (k - (OVERLAP_BASE - j - 1) / 2.0) * OVERLAP_PITCH +
                       bench_layout_shift(&rng, BENCH_LAYOUT_JITTER);
            double y = 0.5 + j * OVERLAP_PITCH;
            ids[count++] = ops->add_body(w, &box, x, y, 0.0, bench_shape_area(&box), mu, 0.0, 1);
        }
    }
    bench_state_t previous[OVERLAP_BASE * (OVERLAP_BASE + 1) / 2];
    for (int i = 0; i < count; i++) ops->get_state(w, ids[i], &previous[i]);
    double total = 0.0, max_speed = 0.0, max_push_speed = 0.0;
    int in_bounds = 1;
    int steps = bench_step_count(OVERLAP_STEPS);
    for (int step = 1; step <= steps; step++) {
        total += bench_step(ops, w, BENCH_DT);
        for (int i = 0; i < count; i++) {
            bench_state_t s;
            ops->get_state(w, ids[i], &s);
            double speed = hypot(s.vx, s.vy);
            if (speed > max_speed) max_speed = speed;
            /* How fast the position changed, whatever the reported velocity
             * says: recovery that moves positions directly shows here only. */
            double push = hypot(s.x - previous[i].x, s.y - previous[i].y) / BENCH_DT;
            if (push > max_push_speed) max_push_speed = push;
            previous[i] = s;
            if (!(s.x >= -OVERLAP_GROUND_HALF_WIDTH && s.x <= OVERLAP_GROUND_HALF_WIDTH &&
                  s.y >= 0.0))
                in_bounds = 0;
        }
    }
    out->step_ms = total / steps;
    snprintf(out->quality, sizeof out->quality,
             "max_speed=%.4g max_push_speed=%.4g in_bounds=%d max_penetration=%.4g", max_speed,
             max_push_speed, in_bounds, ops->max_penetration(w));
    ops->world_free(w);
}

/* ---- column(n): n unit boxes on the ground, each shifted sideways by a
 * small random amount (a real stack is never exact), 60 s ---- */
static inline void column_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    int n = (int)c->size;
    double mu = bench_shape_friction(ops, BENCH_FRICTION);
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, n + 1);
    ops->add_static_box(w, 0.0, -0.5, STACK2_GROUND_HALF_WIDTH, 0.5, mu,
                        bench_static_elasticity(ops));
    bench_shape_t box = bench_box_shape(0.5, 0.5);
    bench_rng_t rng;
    bench_rng_init(&rng);
    int *ids = (int *)malloc(sizeof(int) * (size_t)n);
    double top_x0 = 0.0;
    for (int j = 0; j < n; j++) {
        top_x0 = COLUMN_JITTER * (bench_rng_next(&rng) - 0.5);
        ids[j] = ops->add_body(w, &box, top_x0, 0.5 + j, 0.0, bench_shape_area(&box), mu, 0.0, 1);
    }
    double total = 0.0;
    int steps = bench_step_count(COLUMN_STEPS);
    for (int step = 1; step <= steps; step++) total += bench_step(ops, w, BENCH_DT);
    out->step_ms = total / steps;
    double tilt = 0.0, ke = 0.0;
    double inertia = bench_shape_inertia(&box, bench_shape_area(&box));
    bench_state_t s;
    for (int j = 0; j < n; j++) {
        ops->get_state(w, ids[j], &s);
        double a = fabs(remainder(s.angle, 2.0 * M_PI));
        if (a > tilt) tilt = a;
        ke += 0.5 * bench_shape_area(&box) * (s.vx * s.vx + s.vy * s.vy) +
              0.5 * inertia * s.omega * s.omega;
    }
    double drift = fabs(s.x - top_x0), drop = s.y - (0.5 + (n - 1));
    snprintf(out->quality, sizeof out->quality,
             "top_drift=%.4g top_drop=%.4g max_tilt=%.4g standing=%d kinetic_energy=%.4g", drift,
             drop, tilt, drift < 0.5 && drop > -0.5, ke);
    free(ids);
    ops->world_free(w);
}

/* ==== The stability scenes (docs/stability.md; tests/stability/) ==== */

/* ---- spring(zeta), springpair(r), chain(n): stiff springs ----
 * One body on a spring, a pair of bodies, or a hanging chain, moving along
 * the springs only (so every engine's spring force is the same linear
 * function, see spring_rest), at dt = 1/60 with the stiffness chosen so
 * that theta = omega dt (omega the highest frequency) sweeps 0.1 to 3 in
 * steps of 0.01 (0.05 with --quick):
 *   spring      a 1 kg body on a spring to a static anchor, damping ratio
 *               zeta = size (damping c = 2 zeta omega m);
 *   springpair  a 1 kg body on a spring to a free body of size kg
 *               (omega^2 = k / reduced mass);
 *   chain       size 1 kg bodies hanging in a chain of springs from a
 *               static anchor under gravity (omega_max = 2 sqrt(k / m)
 *               sin((2n - 1) pi / (2 (2n + 1))), the top mode of a
 *               fixed-free chain).
 * Each run starts at rest 1 cm (the chain: up to 1 cm per body, random)
 * from equilibrium and lasts 2000 steps (1000 with --quick). Its energy
 * about equilibrium E (kinetic plus the springs' stretch beyond their
 * stretch at equilibrium) is read every step; the run is unstable when E
 * is not finite, passes 1e40 E0, or its largest value over the second half
 * is more than twice that over the first (a bounded oscillation, however
 * eccentric its invariant ellipse, has the same largest value in both).
 * growth: the energy factor per step, exp of the least-squares slope of
 * ln E over the run (a run whose energy falls below 1e-8 E0 ends there:
 * damped away, stable).
 * Keys: limit (the least unstable theta of the scan refined by bisection to
 * 1e-5; 0 when unstable from 0.1, inf when stable to 3), stable_above (how
 * many scanned thetas past the limit were stable again), growth_X at theta
 * X = 0.1, 0.5, 1, 1.5, 2, 2.5, 3. */
#define SPRING_DT (1.0 / 60.0)
#define SPRING_AMPLITUDE 0.01
#define SPRING_THETA_FIRST 0.1
#define SPRING_THETA_LAST 3.0
#define SPRING_CHAIN_MAX 64
#define SPRING_DIVERGED 1e40
#define SPRING_DECAYED 1e-8

enum { SPRING_SINGLE, SPRING_PAIR, SPRING_CHAIN };

typedef struct {
    int stable;
    double growth; /* energy factor per step */
} spring_result_t;

/* The top angular frequency of a fixed-free chain of n unit masses on
 * springs of stiffness k, over sqrt(k). */
static inline double spring_chain_factor(int n) {
    return 2.0 * sin((2.0 * n - 1.0) * M_PI / (2.0 * (2.0 * n + 1.0)));
}

static inline spring_result_t spring_measure(const bench_ops_t *ops, int kind, double param,
                                             double theta, int steps) {
    double h = SPRING_DT, rest = ops->spring_rest, omega = theta / h;
    int n = kind == SPRING_CHAIN ? (int)param : 1;
    if (n > SPRING_CHAIN_MAX) n = SPRING_CHAIN_MAX;
    void *w = ops->world_new(kind == SPRING_CHAIN ? BENCH_GRAVITY_Y : 0.0, 0, n + 2);
    bench_shape_t small = bench_box_shape(0.05, 0.05);
    /* ids[0] is the spring's fixed (or heavy) end; ids[1..n] move. */
    int ids[SPRING_CHAIN_MAX + 1];
    double mass[SPRING_CHAIN_MAX + 1], stretch[SPRING_CHAIN_MAX + 1];
    double k;
    if (kind == SPRING_SINGLE) {
        k = omega * omega;
        ids[0] = ops->add_static_box(w, -rest, 0.0, 0.05, 0.05, 0.0, 0.0);
        mass[0] = 0.0;
        ids[1] = ops->add_body(w, &small, SPRING_AMPLITUDE, 0.0, 0.0, 1.0, 0.0, 0.0, 0);
        mass[1] = 1.0;
        stretch[1] = 0.0;
        ops->add_spring(w, ids[0], ids[1], k, 2.0 * param * omega, rest);
    } else if (kind == SPRING_PAIR) {
        k = omega * omega * param / (param + 1.0);
        ids[0] = ops->add_body(w, &small, -rest, 0.0, 0.0, param, 0.0, 0.0, 0);
        mass[0] = param;
        ids[1] = ops->add_body(w, &small, SPRING_AMPLITUDE, 0.0, 0.0, 1.0, 0.0, 0.0, 0);
        mass[1] = 1.0;
        stretch[1] = 0.0;
        ops->add_spring(w, ids[0], ids[1], k, 0.0, rest);
    } else {
        double f = omega / spring_chain_factor(n);
        k = f * f;
        bench_rng_t rng;
        bench_rng_init(&rng);
        ids[0] = ops->add_static_box(w, 0.0, 0.0, 0.05, 0.05, 0.0, 0.0);
        mass[0] = 0.0;
        double y = 0.0;
        for (int j = 1; j <= n; j++) {
            stretch[j] = (n - j + 1) * BENCH_G_ABS / k;
            y -= rest + stretch[j];
            double dy = SPRING_AMPLITUDE * (2.0 * bench_rng_next(&rng) - 1.0);
            ids[j] = ops->add_body(w, &small, 0.0, y + dy, 0.0, 1.0, 0.0, 0.0, 0);
            mass[j] = 1.0;
            ops->add_spring(w, ids[j - 1], ids[j], k, 0.0, rest);
        }
    }
    /* the fixed end of the single spring and the anchor of the chain */
    double fixed_x = kind == SPRING_SINGLE ? -rest : 0.0;
    spring_result_t result = {1, 1.0};
    double e0 = 0.0, max_first = 0.0, max_second = 0.0;
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    int done = 0, decayed = 0;
    for (int step = 0; step <= steps; step++) {
        if (step > 0) ops->step(w, h);
        bench_state_t s[SPRING_CHAIN_MAX + 1];
        for (int j = kind == SPRING_PAIR ? 0 : 1; j <= n; j++) ops->get_state(w, ids[j], &s[j]);
        if (kind != SPRING_PAIR) {
            s[0].x = fixed_x;
            s[0].y = 0.0;
            s[0].vx = s[0].vy = 0.0;
        }
        double e = 0.0;
        for (int j = 0; j <= n; j++) e += 0.5 * mass[j] * (s[j].vx * s[j].vx + s[j].vy * s[j].vy);
        for (int j = 1; j <= n; j++) {
            double d = hypot(s[j].x - s[j - 1].x, s[j].y - s[j - 1].y) - rest - stretch[j];
            e += 0.5 * k * d * d;
        }
        if (step == 0) e0 = e;
        if (!(e <= SPRING_DIVERGED * e0)) { /* also NaN */
            result.stable = 0;
            break;
        }
        /* Damped away: stable. The energy's floor is the rounding of the
         * positions (about 1e-30 of the start for this engine, 1e-11 for
         * Box2D's floats), where the fitted factor would flatten out. */
        if (e < SPRING_DECAYED * e0) {
            decayed = 1;
            break;
        }
        double lx = step, ly = log(e / e0);
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly;
        done++;
        if (2 * step <= steps) {
            max_first = fmax(max_first, e);
        } else {
            max_second = fmax(max_second, e);
        }
    }
    if (result.stable && done > steps && max_second > 2.0 * max_first) result.stable = 0;
    if (done >= 2) {
        double slope = (done * sxy - sx * sy) / (done * sxx - sx * sx);
        result.growth = exp(slope);
    } else if (decayed) {
        result.growth = 0.0; /* gone within a step (critical damping) */
    }
    ops->world_free(w);
    return result;
}

static inline void spring_sweep(const bench_ops_t *ops, int kind, double param, bench_run_t *out) {
    double step = bench_quick ? 0.05 : 0.01;
    int steps = bench_quick ? 1000 : 2000;
    double t0 = bench_now_ms();
    double last_stable = -1.0, first_unstable = -1.0;
    int stable_above = 0;
    int count = (int)floor((SPRING_THETA_LAST - SPRING_THETA_FIRST) / step + 0.5);
    for (int i = 0; i <= count; i++) {
        double theta = SPRING_THETA_FIRST + i * step;
        int stable = spring_measure(ops, kind, param, theta, steps).stable;
        if (first_unstable < 0.0) {
            if (stable) {
                last_stable = theta;
            } else {
                first_unstable = theta;
            }
        } else if (stable) {
            stable_above++;
        }
    }
    double limit;
    if (first_unstable < 0.0) {
        limit = INFINITY;
    } else if (last_stable < 0.0) {
        limit = 0.0;
    } else {
        double lo = last_stable, hi = first_unstable;
        while (hi - lo > 1e-5) {
            double mid = 0.5 * (lo + hi);
            if (spring_measure(ops, kind, param, mid, steps).stable) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        limit = 0.5 * (lo + hi);
    }
    int len = snprintf(out->quality, sizeof out->quality, "limit=%.6g stable_above=%d steps=%d",
                       limit, stable_above, steps);
    static const double samples[7] = {0.1, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0};
    for (int i = 0; i < 7; i++) {
        spring_result_t r = spring_measure(ops, kind, param, samples[i], steps);
        len += snprintf(out->quality + len, sizeof out->quality - (size_t)len, " growth_%g=%.6g",
                        samples[i], r.growth);
    }
    out->step_ms = bench_now_ms() - t0; /* the whole sweep */
}

static inline void spring_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    spring_sweep(ops, SPRING_SINGLE, c->size, out);
}

static inline void springpair_run(const bench_ops_t *ops, const bench_case_t *c,
                                  bench_run_t *out) {
    spring_sweep(ops, SPRING_PAIR, c->size, out);
}

static inline void chain_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    spring_sweep(ops, SPRING_CHAIN, c->size, out);
}

/* ---- heavytop(r): a pyramid of 10 rows whose top box is r times as dense
 * as the others; 600 steps. Keys as pyramid's, plus top_drift (m),
 * max_tilt (rad, any box, modulo a quarter turn), late_ke_max (J) and
 * late_speed_max (m/s, any box) over the last 300 steps. ---- */
static inline void heavytop_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    pyramid_config_t cfg = {10, 1.0, 0.0, 0.0, c->size, bench_step_count(PYRAMID_STEPS), BENCH_DT};
    pyramid_result_t r;
    out->step_ms = pyramid_generic(ops, &cfg, &r, 1);
    snprintf(out->quality, sizeof out->quality,
             "top_drop=%.4g top_drift=%.4g max_penetration=%.4g kinetic_energy=%.4g "
             "max_tilt=%.4g standing=%d late_ke_max=%.4g late_speed_max=%.4g",
             r.top_drop, r.top_drift, r.max_penetration, r.kinetic_energy, r.max_tilt,
             r.top_drop > -0.5 && fabs(r.top_drift) < 0.5, r.late_ke_max,
             r.late_speed_max);
}

/* ---- scaled(s): the pyramid of 10 rows built of boxes of side s (ground,
 * heights and all scaled), gravity unchanged, for 10 s of steps of --dt
 * (default 1/60: 600 steps; dt sqrt(s) / 60 makes the same scene in units
 * of the box and of its fall time). Figures
 * over s: top_drop_rel, top_drift_rel, pen_rel, late_speed_rel (the
 * largest speed of any box over the last 300 steps, in sizes per second).
 * ---- */
static inline void scaled_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    double s = c->size;
    /* 10 s of steps of dt (600 at the default 1/60) */
    int steps = bench_steps > 0 ? bench_steps : (int)ceil(PYRAMID_STEPS * BENCH_DT / c->dt - 1e-9);
    pyramid_config_t cfg = {10, s, 0.0, 0.0, 1.0, steps, c->dt};
    pyramid_result_t r;
    out->step_ms = pyramid_generic(ops, &cfg, &r, 1);
    char dts[32];
    bench_format_dt(dts, sizeof dts, c->dt);
    snprintf(out->quality, sizeof out->quality,
             "dt=%s top_drop_rel=%.4g top_drift_rel=%.4g pen_rel=%.4g max_tilt=%.4g standing=%d "
             "late_speed_rel=%.4g",
             dts, r.top_drop / s, r.top_drift / s, r.max_penetration / s, r.max_tilt,
             r.top_drop > -0.5 * s && fabs(r.top_drift) < 0.5 * s, r.late_speed_max / s);
}

/* ---- far(D): the pyramid of 10 rows of unit boxes moved to (D, -D);
 * 600 steps; late_speed_max as heavytop's. ---- */
static inline void far_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    double d = c->size;
    pyramid_config_t cfg = {10, 1.0, d, -d, 1.0, bench_step_count(PYRAMID_STEPS), BENCH_DT};
    pyramid_result_t r;
    out->step_ms = pyramid_generic(ops, &cfg, &r, 1);
    snprintf(out->quality, sizeof out->quality,
             "top_drop=%.4g top_drift=%.4g max_penetration=%.4g max_tilt=%.4g standing=%d "
             "late_speed_max=%.4g",
             r.top_drop, r.top_drift, r.max_penetration, r.max_tilt,
             r.top_drop > -0.5 && fabs(r.top_drift) < 0.5, r.late_speed_max);
}

/* ---- headon(r): a 1 kg unit box at 5 m/s meets an r kg unit box at rest,
 * elasticity 1, no friction, no gravity; 120 steps. Exact: v1' = 5 (1 - r)
 * / (1 + r), v2' = 10 / (1 + r). vel_err: the larger velocity error over
 * 5 m/s; momentum_err and energy_err relative to the start's. ---- */
static inline void headon_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    double r = c->size, v0 = 5.0;
    void *w = ops->world_new(0.0, 1, 2);
    bench_shape_t box = bench_box_shape(0.5, 0.5);
    int a = ops->add_body(w, &box, -2.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1);
    int b = ops->add_body(w, &box, 0.0, 0.0, 0.0, r, 0.0, 1.0, 1);
    ops->set_velocity(w, a, v0, 0.0);
    double total = 0.0;
    for (int step = 1; step <= 120; step++) total += bench_step(ops, w, BENCH_DT);
    out->step_ms = total / 120;
    bench_state_t sa, sb;
    ops->get_state(w, a, &sa);
    ops->get_state(w, b, &sb);
    double va = v0 * (1.0 - r) / (1.0 + r), vb = 2.0 * v0 / (1.0 + r);
    double err = fmax(hypot(sa.vx - va, sa.vy), hypot(sb.vx - vb, sb.vy)) / v0;
    double p = sa.vx + r * sb.vx;
    double e = 0.5 * (sa.vx * sa.vx + sa.vy * sa.vy) + 0.5 * r * (sb.vx * sb.vx + sb.vy * sb.vy) +
               0.5 * bench_shape_inertia(&box, 1.0) * sa.omega * sa.omega +
               0.5 * bench_shape_inertia(&box, r) * sb.omega * sb.omega;
    snprintf(out->quality, sizeof out->quality,
             "vel_err=%.3e momentum_err=%.3e energy_err=%.3e v1=%.6g v2=%.6g", err,
             fabs(p - v0) / v0, (e - 0.5 * v0 * v0) / (0.5 * v0 * v0), sa.vx, sb.vx);
    ops->world_free(w);
}

/* ---- rod(omega): a 2 m x 0.02 m rod (0.04 kg) spinning clockwise at omega
 * rad/s beside the tunnel's static 0.1 m wall: its centre at x = -0.5 (the
 * wall's near face at -0.05), upright but for a start angle that moves over
 * 0.45 rad in 16 phases, so a tip (speed omega x 1 m) reaches the wall within
 * a quarter turn. No gravity, elasticity 0, friction 0, 120 steps. A run
 * tunnelled when, at the end, a corner of the rod is past the wall's
 * middle (x > 0). max_depth: the deepest a corner went past the near face
 * at any step of any run (m). ---- */
static inline void rod_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    double omega = c->size;
    bench_shape_t rod = bench_box_shape(1.0, 0.01);
    double total = 0.0, max_depth = 0.0, max_back = 0.0;
    int tunnelled = 0;
    for (int k = 0; k < TUNNEL_PHASES; k++) {
        void *w = ops->world_new(0.0, 1, 2);
        ops->add_static_box(w, 0.0, 0.0, TUNNEL_WALL_HALF_WIDTH, TUNNEL_WALL_HALF_HEIGHT, 0.0,
                            bench_static_elasticity(ops));
        double angle = 0.5 * M_PI - 0.45 * (k + 0.5) / TUNNEL_PHASES;
        int id = ops->add_body(w, &rod, -0.5, 0.0, angle, bench_shape_area(&rod), 0.0, 0.0, 1);
        ops->set_angular_velocity(w, id, -omega);
        double deepest_end = -INFINITY;
        for (int step = 1; step <= TUNNEL_STEPS; step++) {
            total += bench_step(ops, w, BENCH_DT);
            bench_state_t s;
            ops->get_state(w, id, &s);
            double cs = cos(s.angle), sn = sin(s.angle), deepest = -INFINITY;
            for (int v = 0; v < 4; v++) {
                double lx, ly;
                bench_shape_vertex(&rod, v, &lx, &ly);
                deepest = fmax(deepest, s.x + cs * lx - sn * ly);
            }
            max_depth = fmax(max_depth, deepest + TUNNEL_WALL_HALF_WIDTH);
            if (step == TUNNEL_STEPS) {
                deepest_end = deepest;
                if (-s.vx > max_back) max_back = -s.vx;
            }
        }
        if (deepest_end > 0.0) tunnelled++;
        ops->world_free(w);
    }
    out->step_ms = total / (TUNNEL_PHASES * TUNNEL_STEPS);
    out->tunnelled = tunnelled;
    out->max_return_speed = max_back;
    snprintf(out->quality, sizeof out->quality, "tunnelled=%d/%d max_depth=%.4g", tunnelled,
             TUNNEL_PHASES, max_depth);
}

/* ---- drop(dt): the box of tests/test_impacts.c (box_lands_at_any_step): a
 * 1 m box, 1 kg, its bottom 1 m above a static floor, elasticity 0,
 * friction 0.6, run for min(2 s / dt, 2000) + 20 steps of dt. Keys: y_err
 * (m, its centre's height minus 0.5 at the end), speed (m/s at the end),
 * rest (1 when within 2 cm of the floor and slower than 1 mm/s). ---- */
static inline void drop_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    double dt = c->dt;
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, 2);
    double mu = bench_shape_friction(ops, BENCH_FRICTION);
    ops->add_static_box(w, 0.0, -0.5, 50.0, 0.5, mu, bench_static_elasticity(ops));
    bench_shape_t box = bench_box_shape(0.5, 0.5);
    int id = ops->add_body(w, &box, 0.0, 1.5, 0.0, 1.0, mu, 0.0, 1);
    int steps = (int)fmin(2.0 / dt, 2000.0) + 20;
    double total = 0.0;
    for (int step = 1; step <= steps; step++) total += bench_step(ops, w, dt);
    out->step_ms = total / steps;
    bench_state_t s;
    ops->get_state(w, id, &s);
    double speed = hypot(s.vx, s.vy), y_err = s.y - 0.5;
    char dts[32];
    bench_format_dt(dts, sizeof dts, dt);
    snprintf(out->quality, sizeof out->quality, "dt=%s steps=%d y_err=%.4g speed=%.4g rest=%d",
             dts, steps, y_err, speed, fabs(y_err) < 0.02 && speed < 1e-3);
    ops->world_free(w);
}

/* ---- coincide(f): two unit boxes (1 kg) created on the ground overlapping
 * by the fraction f of their height (1: in the same place); 300 steps.
 * Keys as overlap's (in_bounds: both within x in [-20, 20], 0 <= y <= 10
 * at every step), plus their final centres. ---- */
static inline void coincide_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    double f = c->size;
    double mu = bench_shape_friction(ops, BENCH_FRICTION);
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, 3);
    ops->add_static_box(w, 0.0, -0.5, OVERLAP_GROUND_HALF_WIDTH, 0.5, mu,
                        bench_static_elasticity(ops));
    bench_shape_t box = bench_box_shape(0.5, 0.5);
    int ids[2];
    ids[0] = ops->add_body(w, &box, 0.0, 0.5, 0.0, 1.0, mu, 0.0, 1);
    ids[1] = ops->add_body(w, &box, 0.0, 0.5 + (1.0 - f), 0.0, 1.0, mu, 0.0, 1);
    bench_state_t previous[2], s[2];
    for (int i = 0; i < 2; i++) ops->get_state(w, ids[i], &previous[i]);
    double total = 0.0, max_speed = 0.0, max_push_speed = 0.0;
    int in_bounds = 1, steps = bench_step_count(OVERLAP_STEPS);
    for (int step = 1; step <= steps; step++) {
        total += bench_step(ops, w, BENCH_DT);
        for (int i = 0; i < 2; i++) {
            ops->get_state(w, ids[i], &s[i]);
            max_speed = fmax(max_speed, hypot(s[i].vx, s[i].vy));
            max_push_speed = fmax(max_push_speed, hypot(s[i].x - previous[i].x,
                                                        s[i].y - previous[i].y) / BENCH_DT);
            previous[i] = s[i];
            if (!(fabs(s[i].x) <= OVERLAP_GROUND_HALF_WIDTH && s[i].y >= 0.0 && s[i].y <= 10.0))
                in_bounds = 0;
        }
    }
    out->step_ms = total / steps;
    snprintf(out->quality, sizeof out->quality,
             "max_speed=%.4g max_push_speed=%.4g in_bounds=%d max_penetration=%.4g a=(%.4g,%.4g) "
             "b=(%.4g,%.4g)",
             max_speed, max_push_speed, in_bounds, ops->max_penetration(w), s[0].x, s[0].y,
             s[1].x, s[1].y);
    ops->world_free(w);
}

/* ---- gas(e), settle(e): n regular polygons (3 to 8 sides, radius 0.5 m,
 * density 1) on a grid of 2 m in a closed square box of side 2 ceil(sqrt n)
 * (four static walls), each with a random angle, a speed up to 5 m/s in a
 * random direction and a spin up to 2 rad/s either way, elasticity e.
 *   gas     20 bodies, no gravity, no friction, 10^4 steps: kinetic energy
 *           (translation and rotation) over the start's at the end
 *           (ke_end_ratio) and its least and largest over the run;
 *   settle  20 bodies, gravity, friction 0.6, 1200 steps (20 s): kinetic
 *           energy at the end (ke_end, J) and its largest over the last
 *           second (ke_last_max).
 * in_bounds: every centre inside the box at every step. ---- */
typedef struct {
    void *world;
    int n;
    int ids[512];
    double mass[512], inertia[512];
    double side;
} gas_t;

static inline void gas_build(const bench_ops_t *ops, gas_t *g, int n, double e, double friction,
                             double gy) {
    if (n > 512) n = 512;
    g->n = n;
    int columns = (int)ceil(sqrt((double)n));
    double side = 2.0 * columns;
    g->side = side;
    g->world = ops->world_new(gy, 1, n + 4);
    double mu = bench_shape_friction(ops, friction), es = bench_static_elasticity(ops);
    ops->add_static_box(g->world, 0.5 * side, -0.5, 0.5 * side + 1.0, 0.5, mu, es);
    ops->add_static_box(g->world, 0.5 * side, side + 0.5, 0.5 * side + 1.0, 0.5, mu, es);
    ops->add_static_box(g->world, -0.5, 0.5 * side, 0.5, 0.5 * side + 1.0, mu, es);
    ops->add_static_box(g->world, side + 0.5, 0.5 * side, 0.5, 0.5 * side + 1.0, mu, es);
    bench_rng_t rng;
    bench_rng_init(&rng);
    for (int i = 0; i < n; i++) {
        bench_shape_t shape = bench_regular_shape(pile_sides[i % 5], 0.5);
        double angle = 2.0 * M_PI * bench_rng_next(&rng);
        double speed = 5.0 * bench_rng_next(&rng), heading = 2.0 * M_PI * bench_rng_next(&rng);
        double spin = 2.0 * (2.0 * bench_rng_next(&rng) - 1.0);
        double m = bench_shape_area(&shape);
        g->mass[i] = m;
        g->inertia[i] = bench_shape_inertia(&shape, m);
        g->ids[i] = ops->add_body(g->world, &shape, 1.0 + 2.0 * (i % columns),
                                  1.0 + 2.0 * (i / columns), angle, m, mu, e, 1);
        ops->set_velocity(g->world, g->ids[i], speed * cos(heading), speed * sin(heading));
        ops->set_angular_velocity(g->world, g->ids[i], spin);
    }
}

/* Kinetic energy (J); *inside cleared when a centre is out of the box. */
static inline double gas_energy(const bench_ops_t *ops, const gas_t *g, int *inside) {
    double ke = 0.0;
    for (int i = 0; i < g->n; i++) {
        bench_state_t s;
        ops->get_state(g->world, g->ids[i], &s);
        ke += 0.5 * g->mass[i] * (s.vx * s.vx + s.vy * s.vy) + 0.5 * g->inertia[i] * s.omega * s.omega;
        if (inside != NULL && !(s.x > 0.0 && s.x < g->side && s.y > 0.0 && s.y < g->side))
            *inside = 0;
    }
    return ke;
}

static inline void gas_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    gas_t *g = (gas_t *)malloc(sizeof(gas_t));
    gas_build(ops, g, 20, c->size, 0.0, 0.0);
    double e0 = gas_energy(ops, g, NULL), lo = 1.0, hi = 1.0, ratio = 1.0, total = 0.0;
    int in_bounds = 1, steps = bench_step_count(10000);
    for (int step = 1; step <= steps; step++) {
        total += bench_step(ops, g->world, BENCH_DT);
        ratio = gas_energy(ops, g, &in_bounds) / e0;
        lo = fmin(lo, ratio);
        hi = fmax(hi, ratio);
    }
    out->step_ms = total / steps;
    snprintf(out->quality, sizeof out->quality,
             "steps=%d ke_end_ratio=%.6g ke_min_ratio=%.6g ke_max_ratio=%.6g in_bounds=%d", steps,
             ratio, lo, hi, in_bounds);
    ops->world_free(g->world);
    free(g);
}

static inline void settle_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    gas_t *g = (gas_t *)malloc(sizeof(gas_t));
    gas_build(ops, g, 20, c->size, BENCH_FRICTION, BENCH_GRAVITY_Y);
    double ke = 0.0, last_max = 0.0, total = 0.0;
    int in_bounds = 1, steps = bench_step_count(1200);
    for (int step = 1; step <= steps; step++) {
        total += bench_step(ops, g->world, BENCH_DT);
        ke = gas_energy(ops, g, &in_bounds);
        if (step > steps - 60) last_max = fmax(last_max, ke);
    }
    out->step_ms = total / steps;
    snprintf(out->quality, sizeof out->quality,
             "steps=%d ke_end=%.4g ke_last_max=%.4g in_bounds=%d", steps, ke, last_max, in_bounds);
    ops->world_free(g->world);
    free(g);
}

/* ---- wallbounce(e): a unit box (1 kg) at (5, 5) moving at 2 m/s along x
 * between two static walls 10 m apart (faces at x = 0 and 10), elasticity
 * e, no gravity, no friction; until 40 bounces, 500 m/s or 20000 steps.
 * Each bounce should multiply the speed by e exactly: ratio_err_max is the
 * largest |(v after / v before) / e - 1| over the bounces, ke_formula_err
 * the end's kinetic energy over e^(2 bounces) times the start's, minus 1;
 * off_axis the largest |vy| or |omega| seen (should stay 0). ---- */
static inline void wallbounce_run(const bench_ops_t *ops, const bench_case_t *c,
                                  bench_run_t *out) {
    double e = c->size;
    void *w = ops->world_new(0.0, 1, 3);
    double es = bench_static_elasticity(ops);
    ops->add_static_box(w, -0.5, 5.0, 0.5, 6.0, 0.0, es);
    ops->add_static_box(w, 10.5, 5.0, 0.5, 6.0, 0.0, es);
    bench_shape_t box = bench_box_shape(0.5, 0.5);
    int id = ops->add_body(w, &box, 5.0, 5.0, 0.0, 1.0, 0.0, e, 1);
    ops->set_velocity(w, id, 2.0, 0.0);
    bench_state_t prev, s;
    ops->get_state(w, id, &prev);
    int bounces = 0, steps = 0, max_steps = bench_step_count(20000);
    double ratio_err = 0.0, off_axis = 0.0, total = 0.0;
    while (bounces < 40 && steps < max_steps && fabs(prev.vx) < 500.0) {
        total += bench_step(ops, w, BENCH_DT);
        steps++;
        ops->get_state(w, id, &s);
        off_axis = fmax(off_axis, fmax(fabs(s.vy), fabs(s.omega)));
        if ((s.vx > 0.0) != (prev.vx > 0.0)) {
            bounces++;
            ratio_err = fmax(ratio_err, fabs(fabs(s.vx) / fabs(prev.vx) / e - 1.0));
        }
        prev = s;
    }
    out->step_ms = total / (steps > 0 ? steps : 1);
    double ke_ratio = (s.vx * s.vx + s.vy * s.vy) / 4.0;
    snprintf(out->quality, sizeof out->quality,
             "bounces=%d steps=%d ratio_err_max=%.3e ke_formula_err=%.3e off_axis=%.3e", bounces,
             steps, ratio_err, ke_ratio / pow(e, 2.0 * bounces) - 1.0, off_axis);
    ops->world_free(w);
}

#include "bench_joint_scenes.h"

/* The scenes an engine runs only with joints (bench_ops_t's add_revolute). */
static inline int bench_scene_needs_joints(bench_scene_id_t scene) {
    return scene == SCENE_JOINTCHAIN || scene == SCENE_RAGDOLLS;
}

static inline int bench_scene_is_pile(bench_scene_id_t scene) {
    return scene == SCENE_PILE || scene == SCENE_CIRCLEPILE || scene == SCENE_CAPSULEPILE ||
           scene == SCENE_MIXEDPILE;
}

typedef void (*bench_run_fn)(const bench_ops_t *, const bench_case_t *, bench_run_t *);

static const bench_run_fn bench_runners[SCENE_COUNT] = {
    pile_run,       pyramid_run,   bounce_run,   cradle_run,    orbit_run,
    stack2_run,     tunnel_run,    overlap_run,  column_run,    spring_run,
    springpair_run, chain_run,     heavytop_run, headon_run,    tunnelmove_run,
    bullet_run,     rod_run,       drop_run,     coincide_run,  gas_run,
    settle_run,     wallbounce_run, scaled_run,  far_run,       pile_run,
    pile_run,       pile_run,      jointchain_run, ragdolls_run};

/* The scenes that print a summary line after their sizes (first speed that
 * tunnelled, largest return speed). */
static inline int bench_scene_has_summary(bench_scene_id_t scene) {
    return scene == SCENE_TUNNEL || scene == SCENE_TUNNELMOVE || scene == SCENE_BULLET ||
           scene == SCENE_ROD;
}

/* The scenes whose step is given by --dt. */
static inline int bench_scene_has_dt(bench_scene_id_t scene) {
    return scene == SCENE_BOUNCE || scene == SCENE_ORBIT || scene == SCENE_DROP ||
           scene == SCENE_SCALED;
}

/* Whether `name` is an item of the comma list `list`. */
static inline int bench_list_has(const char *list, const char *name) {
    size_t len = strlen(name);
    const char *p = list;
    while (*p) {
        const char *end = strchr(p, ',');
        size_t item = end ? (size_t)(end - p) : strlen(p);
        if (item == len && strncmp(p, name, len) == 0) return 1;
        if (!end) break;
        p = end + 1;
    }
    return 0;
}

/* Whether a variant runs a scene (only_scenes is a comma list or NULL). */
static inline int bench_ops_runs(const bench_ops_t *ops, bench_scene_id_t scene) {
    return ops->only_scenes == NULL || bench_list_has(ops->only_scenes, bench_scene_names[scene]);
}

/* Runs one case `runs` times with one engine and prints its line. */
static inline void bench_run_case(const bench_ops_t *ops, const bench_case_t *c, int runs,
                                  int *summary_tunnelled_v_found, double *summary_first_v,
                                  double *summary_back) {
    double *ms = (double *)malloc(sizeof(double) * (size_t)runs);
    double *settled = (double *)malloc(sizeof(double) * (size_t)runs);
    double *wall = (double *)malloc(sizeof(double) * (size_t)runs);
    bench_run_t first, run;
    int differ = 0;
    memset(&bench_stage_sums, 0, sizeof bench_stage_sums);
    for (int i = 0; i < runs; i++) {
        bench_run_t *r = i == 0 ? &first : &run;
        memset(r, 0, sizeof *r);
        bench_wall_ms = 0.0;
        bench_timed_steps = 0;
        bench_runners[c->scene](ops, c, r);
        wall[i] = bench_timed_steps > 0 ? bench_wall_ms / (double)bench_timed_steps : NAN;
        ms[i] = r->step_ms;
        settled[i] = r->settled_ms;
        if (i > 0 && strcmp(first.quality, run.quality) != 0) differ = 1;
    }
    char size[32], quality[800];
    snprintf(size, sizeof size, "%g", c->size);
    int len = snprintf(quality, sizeof quality, "%s%s", first.quality,
                       differ ? " runs_differ=1" : "");
    if (bench_layout_jittered() && len > 0 && (size_t)len < sizeof quality) {
        len += snprintf(quality + len, sizeof quality - (size_t)len, " layout_seed=%llu",
                        (unsigned long long)bench_layout_seed);
    }
    if (bench_wall && len > 0 && (size_t)len < sizeof quality) {
        len += snprintf(quality + len, sizeof quality - (size_t)len, " wall_median_ms=%.4g",
                        bench_median(wall, runs));
    }
    if (bench_count_steps && len > 0 && (size_t)len < sizeof quality) {
        snprintf(quality + len, sizeof quality - (size_t)len, " timed_steps=%ld",
                 bench_timed_steps);
    }
    bench_print_result(ops->name, bench_scene_names[c->scene], size, runs, ms,
                       bench_scene_is_pile(c->scene) ? settled : NULL, quality);
    if (bench_stages) {
        const bench_stage_sums_t *sums = &bench_stage_sums;
        const char *scene = bench_scene_names[c->scene];
        bench_print_stages_part(ops->name, scene, size, "step", sums->step_ms, sums->steps);
        if (bench_scene_is_pile(c->scene)) {
            bench_print_stages_part(ops->name, scene, size, "settled", sums->settled_ms,
                                    sums->settled_steps);
        }
    }
    if (bench_scene_has_summary(c->scene)) {
        if (first.tunnelled > 0 && (!*summary_tunnelled_v_found || c->size < *summary_first_v)) {
            *summary_tunnelled_v_found = 1;
            *summary_first_v = c->size;
        }
        if (first.max_return_speed > *summary_back) *summary_back = first.max_return_speed;
    }
    free(ms);
    free(settled);
    free(wall);
}

/* ---- command line ---- */

#define BENCH_MAX_LIST 64

static inline int bench_parse_number(const char *text, double *out) {
    char *end;
    double value = strtod(text, &end);
    if (end == text) return 0;
    if (*end == '/') { /* a fraction such as 1/600 */
        const char *den_text = end + 1;
        double den = strtod(den_text, &end);
        if (end == den_text || den == 0.0) return 0;
        value /= den;
    }
    if (*end != '\0') return 0;
    *out = value;
    return 1;
}

/* Appends the comma-separated numbers of text to list. */
static inline int bench_parse_list(const char *text, double *list, int *count) {
    char buffer[512];
    snprintf(buffer, sizeof buffer, "%s", text);
    char *save = NULL;
    for (char *item = strtok_r(buffer, ",", &save); item; item = strtok_r(NULL, ",", &save)) {
        if (*count >= BENCH_MAX_LIST || !bench_parse_number(item, &list[*count])) return 0;
        (*count)++;
    }
    return 1;
}

static inline void bench_usage(FILE *out, const char *program) {
    fprintf(out,
            "usage: %s [--scene NAME[,NAME]] [--size X[,X]] [--dt X[,X]] [--runs R] [--quick]\n"
            "          [--iterations N] [--variant NAME[,NAME]] [--steps N] [--layout-seed K]\n"
            "          [--wall] [--count-steps] [--stages]\n"
            "  scenes: pile pyramid bounce cradle orbit stack2 tunnel overlap column\n"
            "  circlepile capsulepile mixedpile jointchain ragdolls all\n"
            "  stability scenes: spring springpair chain heavytop headon tunnelmove bullet rod\n"
            "  drop coincide gas settle wallbounce scaled far\n"
            "  no --scene: pile 1000,4000,10000; pyramid 20,40; bounce 0.8 at dt 1/60,1/600;\n"
            "  cradle 5. --size and --dt apply to every scene given (--dt: bounce, orbit, drop).\n"
            "  --steps N: the step count of pile, pyramid, column, stack2, overlap and the\n"
            "  stability scenes with a fixed count.\n"
            "  --iterations N: the solver's velocity iterations (each engine's own default\n"
            "  otherwise; position iterations keep theirs). --variant NAME[,NAME]: only\n"
            "  these variants of the program (e.g. ours, ours-sleeping; names another\n"
            "  program has are ignored, so one list serves every program).\n"
            "  --layout-seed K: the random layouts' seed (default 12345, the canonical\n"
            "  one); other seeds also jitter the pyramids' and overlap's boxes by 1e-4 m.\n"
            "  Times are CPU time of the process; --wall adds wall_median_ms; --stages\n"
            "  prints each engine's own timing of its stages after each result line.\n",
            program);
}

static inline void bench_default_sizes(bench_scene_id_t scene, int quick, double *sizes,
                                       int *count) {
    static const double pile_full[] = {1000, 4000, 10000}, pile_quick[] = {500};
    static const double pyramid_full[] = {20, 40}, pyramid_quick[] = {10};
    static const double stack2_all[] = {1, 10, 100, 1000, 10000};
    static const double headon_ratios[] = {1, 10, 100, 1000, 1e4, 1e6};
    static const double scaled_sizes[] = {0.01, 1, 1000}, far_offsets[] = {0, 1e6};
    const double *list = NULL;
    int n = 0;
    switch (scene) {
        case SCENE_PILE: list = quick ? pile_quick : pile_full; n = quick ? 1 : 3; break;
        case SCENE_PYRAMID: list = quick ? pyramid_quick : pyramid_full; n = quick ? 1 : 2; break;
        case SCENE_BOUNCE: sizes[0] = 0.8; *count = 1; return;
        case SCENE_CRADLE: sizes[0] = 5; *count = 1; return;
        case SCENE_ORBIT: sizes[0] = 2; *count = 1; return;
        case SCENE_STACK2: list = stack2_all; n = 5; break;
        case SCENE_TUNNEL: list = tunnel_speeds; n = 10; break;
        case SCENE_OVERLAP: sizes[0] = 10; *count = 1; return;
        case SCENE_COLUMN: sizes[0] = 10; sizes[1] = 20; *count = 2; return;
        case SCENE_SPRING: sizes[0] = 0; *count = 1; return;
        case SCENE_SPRINGPAIR: sizes[0] = 1000; *count = 1; return;
        case SCENE_CHAIN: sizes[0] = 20; *count = 1; return;
        case SCENE_HEAVYTOP: sizes[0] = 100; *count = 1; return;
        case SCENE_HEADON: list = headon_ratios; n = 6; break;
        case SCENE_TUNNELMOVE:
        case SCENE_BULLET: list = tunnel_speeds; n = 10; break;
        case SCENE_ROD: list = tunnel_speeds; n = 10; break;
        case SCENE_DROP: sizes[0] = 1; *count = 1; return;
        case SCENE_COINCIDE: sizes[0] = 1; *count = 1; return;
        case SCENE_GAS: sizes[0] = 1; *count = 1; return;
        case SCENE_SETTLE: sizes[0] = 0; *count = 1; return;
        case SCENE_WALLBOUNCE: sizes[0] = 1.1; *count = 1; return;
        case SCENE_SCALED: list = scaled_sizes; n = 3; break;
        case SCENE_FAR: list = far_offsets; n = 2; break;
        case SCENE_CIRCLEPILE:
        case SCENE_CAPSULEPILE:
        case SCENE_MIXEDPILE: list = quick ? pile_quick : pile_full; n = quick ? 1 : 2; break;
        case SCENE_JOINTCHAIN: sizes[0] = 100; *count = 1; return;
        case SCENE_RAGDOLLS: sizes[0] = 20; *count = 1; return;
        default: break;
    }
    for (int i = 0; i < n; i++) sizes[i] = list[i];
    *count = n;
}

static inline void bench_default_dts(bench_scene_id_t scene, int quick, double *dts, int *count) {
    if (scene == SCENE_BOUNCE) {
        dts[0] = 1.0 / 60.0;
        dts[1] = 1.0 / 600.0;
        *count = 2;
    } else if (scene == SCENE_ORBIT) {
        *count = quick ? 3 : 5;
        for (int i = 0; i < *count; i++) dts[i] = pow(10.0, -(i + 1));
    } else if (scene == SCENE_DROP) {
        static const double drop_dts[] = {1.0 / 600.0, 1.0 / 60.0, 0.1, 0.5, 1.0};
        *count = 5;
        for (int i = 0; i < 5; i++) dts[i] = drop_dts[i];
    } else {
        dts[0] = BENCH_DT;
        *count = 1;
    }
}

/* Runs what the command line asks with every variant in ops[0..count-1]. */
static inline int bench_main(int argc, char **argv, const bench_ops_t *const *ops, int ops_count) {
    int selected[SCENE_COUNT * 4], nselected = 0;
    double sizes[BENCH_MAX_LIST], dts[BENCH_MAX_LIST];
    int nsizes = 0, ndts = 0, runs = -1, quick = 0;
    for (int i = 1; i < argc; i++) {
        const char *arg = argv[i];
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
            bench_usage(stdout, argv[0]);
            return 0;
        } else if (strcmp(arg, "--quick") == 0) {
            quick = 1;
            bench_quick = 1;
        } else if (strcmp(arg, "--wall") == 0) {
            bench_wall = 1;
        } else if (strcmp(arg, "--count-steps") == 0) {
            bench_count_steps = 1;
        } else if (strcmp(arg, "--stages") == 0) {
            bench_stages = 1;
        } else if (value == NULL) {
            fprintf(stderr, "%s: unknown option or missing value: %s\n", argv[0], arg);
            bench_usage(stderr, argv[0]);
            return 2;
        } else if (strcmp(arg, "--scene") == 0) {
            char buffer[512];
            snprintf(buffer, sizeof buffer, "%s", value);
            char *save = NULL;
            for (char *item = strtok_r(buffer, ",", &save); item;
                 item = strtok_r(NULL, ",", &save)) {
                int found = 0;
                for (int s = 0; s < SCENE_COUNT; s++) {
                    if (strcmp(item, bench_scene_names[s]) == 0 || strcmp(item, "all") == 0) {
                        if (nselected < SCENE_COUNT * 4) selected[nselected++] = s;
                        found = 1;
                    }
                }
                if (!found) {
                    fprintf(stderr, "%s: unknown scene: %s\n", argv[0], item);
                    return 2;
                }
            }
            i++;
        } else if (strcmp(arg, "--size") == 0 || strcmp(arg, "--dt") == 0) {
            int is_size = arg[2] == 's';
            if (!bench_parse_list(value, is_size ? sizes : dts, is_size ? &nsizes : &ndts)) {
                fprintf(stderr, "%s: bad %s value: %s\n", argv[0], arg, value);
                return 2;
            }
            i++;
        } else if (strcmp(arg, "--variant") == 0) {
            bench_variant = value;
            i++;
        } else if (strcmp(arg, "--iterations") == 0) {
            bench_iterations = atoi(value);
            if (bench_iterations < 1 || bench_iterations > 1000) {
                fprintf(stderr, "%s: --iterations must be in 1..1000\n", argv[0]);
                return 2;
            }
            i++;
        } else if (strcmp(arg, "--steps") == 0) {
            bench_steps = atoi(value);
            if (bench_steps < 1) {
                fprintf(stderr, "%s: --steps must be >= 1\n", argv[0]);
                return 2;
            }
            i++;
        } else if (strcmp(arg, "--layout-seed") == 0) {
            char *end;
            unsigned long long seed = strtoull(value, &end, 10);
            if (*end != '\0' || end == value || seed >= 2147483648ull) {
                fprintf(stderr, "%s: --layout-seed takes 0 .. 2147483647, not %s\n", argv[0],
                        value);
                return 2;
            }
            bench_layout_seed = seed;
            i++;
        } else if (strcmp(arg, "--runs") == 0) {
            runs = atoi(value);
            if (runs < 1) {
                fprintf(stderr, "%s: --runs must be >= 1\n", argv[0]);
                return 2;
            }
            i++;
        } else {
            fprintf(stderr, "%s: unknown option: %s\n", argv[0], arg);
            bench_usage(stderr, argv[0]);
            return 2;
        }
    }
    for (int i = 0; i < nsizes; i++) {
        if (!(sizes[i] >= 0.0 && isfinite(sizes[i]))) {
            fprintf(stderr, "%s: sizes must be finite and >= 0\n", argv[0]);
            return 2;
        }
    }
    for (int i = 0; i < ndts; i++) {
        if (!(dts[i] > 0.0)) {
            fprintf(stderr, "%s: dt must be > 0\n", argv[0]);
            return 2;
        }
    }
    if (runs < 0) runs = quick ? 1 : BENCH_DEFAULT_RUNS;
    if (nselected == 0) {
        selected[nselected++] = SCENE_PILE;
        selected[nselected++] = SCENE_PYRAMID;
        selected[nselected++] = SCENE_BOUNCE;
        selected[nselected++] = SCENE_CRADLE;
    }

    printf("# %s: canonical scenes of SCENES.md; runs=%d%s\n", argv[0], runs,
           quick ? " (quick)" : "");
#ifdef __VERSION__
    printf("# compiler: %s%s\n", __VERSION__,
#ifdef __OPTIMIZE__
           ", optimised"
#else
           ", NOT optimised"
#endif
    );
#endif
    printf("# timing: CPU time of the process (CLOCK_PROCESS_CPUTIME_ID) of the step calls%s\n",
           bench_wall ? "; wall_median_ms: wall time (CLOCK_MONOTONIC) of the same calls" : "");
    if (bench_layout_jittered()) {
        printf("# layout seed %llu (canonical 12345): random layouts drawn from it, pyramid and "
               "overlap boxes shifted sideways by up to %g m\n",
               (unsigned long long)bench_layout_seed, BENCH_LAYOUT_JITTER);
    }
    for (int k = 0; k < ops_count; k++) ops[k]->describe(stdout);
    fflush(stdout);

    for (int i = 0; i < nselected; i++) {
        bench_scene_id_t scene = (bench_scene_id_t)selected[i];
        double case_sizes[BENCH_MAX_LIST], case_dts[BENCH_MAX_LIST];
        int ncase_sizes = 0, ncase_dts = 0;
        if (nsizes > 0) {
            memcpy(case_sizes, sizes, sizeof(double) * (size_t)nsizes);
            ncase_sizes = nsizes;
        } else {
            bench_default_sizes(scene, quick, case_sizes, &ncase_sizes);
        }
        if (ndts > 0 && bench_scene_has_dt(scene)) {
            memcpy(case_dts, dts, sizeof(double) * (size_t)ndts);
            ncase_dts = ndts;
        } else {
            bench_default_dts(scene, quick, case_dts, &ncase_dts);
        }
        for (int k = 0; k < ops_count; k++) {
            if (!bench_ops_runs(ops[k], scene)) continue;
            if (bench_variant != NULL && !bench_list_has(bench_variant, ops[k]->name)) continue;
            if (bench_scene_needs_joints(scene) && ops[k]->add_revolute == NULL) {
                printf("# %s: no joints in this driver: %s skipped\n", ops[k]->name,
                       bench_scene_names[scene]);
                continue;
            }
            int found = 0;
            double first_v = 0.0, back = 0.0;
            for (int s = 0; s < ncase_sizes; s++) {
                for (int d = 0; d < ncase_dts; d++) {
                    bench_case_t c;
                    c.scene = scene;
                    c.size = case_sizes[s];
                    c.dt = case_dts[d];
                    bench_run_case(ops[k], &c, runs, &found, &first_v, &back);
                }
            }
            if (bench_scene_has_summary(scene)) {
                char quality[128];
                if (found) {
                    snprintf(quality, sizeof quality, "first_tunnel_v=%g max_return_speed=%.4g",
                             first_v, back);
                } else {
                    snprintf(quality, sizeof quality,
                             "first_tunnel_v=>%g max_return_speed=%.4g",
                             case_sizes[ncase_sizes - 1], back);
                }
                bench_print_result(ops[k]->name, bench_scene_names[scene], "summary", runs, NULL,
                                   NULL, quality);
            }
        }
    }
    return 0;
}

#endif // #ifndef BENCH_SCENES_H
