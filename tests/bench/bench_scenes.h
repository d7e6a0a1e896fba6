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
 *                    overlap, column or all; repeatable or a comma list
 *   --size X         the scene's size (pile N, pyramid B, bounce e, cradle n,
 *                    stack2 r, tunnel v); repeatable or a comma list
 *   --dt X           step of bounce and orbit (e.g. 1/600 or 0.001);
 *                    repeatable or a comma list
 *   --runs R         runs of each scene (default 5); the median is reported
 *   --quick          smaller sizes and 1 run (a smoke run)
 * No --scene: the benchmark set pile 1000, 4000, 10000; pyramid 20, 40;
 * bounce 0.8 at dt 1/60 and 1/600; cradle 5.
 *
 * Quality keys (figures of the first run; runs_differ=1 is added when a later
 * run gave different figures, i.e. the engine is not deterministic):
 *   pile     max_penetration (m, at step 600) outside (bodies whose centre
 *            is outside the container at step 600; must be 0)
 *   pyramid  top_drop (m: the top box's centre height at step 600 minus its
 *            initial height, negative = it came down; standing: > -0.5)
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
 *   column   top_drift (m: the top box's |x - x0| at step 3600), top_drop (m:
 *            its height change, negative = down), max_tilt (rad: the largest
 *            |angle| of any box at step 3600), standing (1 when the top box
 *            is within 0.5 m of where it started)
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
    SCENE_COUNT
} bench_scene_id_t;

static const char *const bench_scene_names[SCENE_COUNT] = {
    "pile", "pyramid", "bounce", "cradle", "orbit", "stack2", "tunnel", "overlap", "column"};

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

/* A timed step: returns its duration in ms. */
static inline double bench_step(const bench_ops_t *ops, void *world, double dt) {
    double t0 = bench_now_ms();
    ops->step(world, dt);
    return bench_now_ms() - t0;
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

/* ---- pile(N) ---- */
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
        bench_shape_t shape = bench_regular_shape(pile_sides[i % 5], PILE_RADIUS);
        int column = i % PILE_COLUMNS, row = i / PILE_COLUMNS;
        double u1 = bench_rng_next(&rng);
        double u2 = bench_rng_next(&rng);
        double u3 = bench_rng_next(&rng);
        double x = 1.0 + PILE_PITCH * column + PILE_JITTER * (u1 - 0.5);
        double y = 1.0 + PILE_PITCH * row + PILE_JITTER * (u2 - 0.5);
        ids[i] = ops->add_body(w, &shape, x, y, 2.0 * M_PI * u3, bench_shape_area(&shape), mu, 0.0,
                               1);
    }
    double total = 0.0, settled = 0.0;
    for (int step = 1; step <= PILE_STEPS; step++) {
        double ms = bench_step(ops, w, BENCH_DT);
        total += ms;
        if (step >= PILE_SETTLED_FIRST) settled += ms;
    }
    out->step_ms = total / PILE_STEPS;
    out->settled_ms = settled / (PILE_STEPS - PILE_SETTLED_FIRST + 1);
    int outside = 0;
    for (int i = 0; i < n; i++) {
        bench_state_t s;
        ops->get_state(w, ids[i], &s);
        if (!(s.x >= PILE_LEFT && s.x <= PILE_RIGHT && s.y >= 0.0)) outside++;
    }
    snprintf(out->quality, sizeof out->quality, "max_penetration=%.4g outside=%d",
             ops->max_penetration(w), outside);
    free(ids);
    ops->world_free(w);
}

/* ---- pyramid(B) ---- */
static inline void pyramid_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    int base = (int)c->size;
    double mu = bench_shape_friction(ops, BENCH_FRICTION);
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, base * (base + 1) / 2 + 1);
    ops->add_static_box(w, 0.0, -0.5, PYRAMID_GROUND_HALF_WIDTH, 0.5, mu,
                        bench_static_elasticity(ops));
    bench_shape_t box = bench_box_shape(PYRAMID_HALF, PYRAMID_HALF);
    int top = -1;
    double top_y0 = 0.0;
    for (int j = 0; j < base; j++) {
        for (int k = 0; k < base - j; k++) {
            double x = (k - (base - j - 1) / 2.0) * 1.0;
            double y = 0.5 + j * 1.0;
            top = ops->add_body(w, &box, x, y, 0.0, bench_shape_area(&box), mu, 0.0, 1);
            top_y0 = y;
        }
    }
    double total = 0.0;
    for (int step = 1; step <= PYRAMID_STEPS; step++) total += bench_step(ops, w, BENCH_DT);
    out->step_ms = total / PYRAMID_STEPS;
    bench_state_t s;
    ops->get_state(w, top, &s);
    snprintf(out->quality, sizeof out->quality, "top_drop=%.4g max_penetration=%.4g", s.y - top_y0,
             ops->max_penetration(w));
    ops->world_free(w);
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
    for (int step = 1; step <= STACK2_STEPS; step++) total += bench_step(ops, w, BENCH_DT);
    out->step_ms = total / STACK2_STEPS;
    bench_state_t sa, sb;
    ops->get_state(w, a, &sa);
    ops->get_state(w, b, &sb);
    int on = fabs(sb.x - sa.x) < 0.5 && sb.y - sa.y > 0.9;
    snprintf(out->quality, sizeof out->quality, "pen_ground_a=%.4g pen_a_b=%.4g b_on_a=%d",
             ops->pair_penetration(w, ground, a), ops->pair_penetration(w, a, b), on);
    ops->world_free(w);
}

/* ---- tunnel(v): 16 phases, each a fresh world ---- */
static inline void tunnel_run(const bench_ops_t *ops, const bench_case_t *c, bench_run_t *out) {
    double v = c->size, dt = BENCH_DT;
    bench_shape_t wall = bench_box_shape(TUNNEL_WALL_HALF_WIDTH, TUNNEL_WALL_HALF_HEIGHT);
    (void)wall;
    bench_shape_t bullet = bench_box_shape(TUNNEL_BULLET_HALF, TUNNEL_BULLET_HALF);
    double total = 0.0, max_back = 0.0;
    int tunnelled = 0;
    for (int k = 0; k < TUNNEL_PHASES; k++) {
        void *w = ops->world_new(0.0, 1, 2);
        ops->add_static_box(w, 0.0, 0.0, TUNNEL_WALL_HALF_WIDTH, TUNNEL_WALL_HALF_HEIGHT, 0.0,
                            bench_static_elasticity(ops));
        double x0 = TUNNEL_START_X - ((k + 0.5) / TUNNEL_PHASES) * v * dt;
        int id = ops->add_body(w, &bullet, x0, 0.0, 0.0, bench_shape_area(&bullet), 0.0, 0.0, 1);
        ops->set_velocity(w, id, v, 0.0);
        for (int step = 1; step <= TUNNEL_STEPS; step++) total += bench_step(ops, w, dt);
        bench_state_t s;
        ops->get_state(w, id, &s);
        if (s.x > 0.0) tunnelled++;
        if (-s.vx > max_back) max_back = -s.vx;
        ops->world_free(w);
    }
    out->step_ms = total / (TUNNEL_PHASES * TUNNEL_STEPS);
    out->tunnelled = tunnelled;
    out->max_return_speed = max_back;
    snprintf(out->quality, sizeof out->quality, "tunnelled=%d/%d max_return_speed=%.4g", tunnelled,
             TUNNEL_PHASES, max_back);
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
    for (int j = 0; j < OVERLAP_BASE; j++) {
        for (int k = 0; k < OVERLAP_BASE - j; k++) {
            double x = (k - (OVERLAP_BASE - j - 1) / 2.0) * OVERLAP_PITCH;
            double y = 0.5 + j * OVERLAP_PITCH;
            ids[count++] = ops->add_body(w, &box, x, y, 0.0, bench_shape_area(&box), mu, 0.0, 1);
        }
    }
    bench_state_t previous[OVERLAP_BASE * (OVERLAP_BASE + 1) / 2];
    for (int i = 0; i < count; i++) ops->get_state(w, ids[i], &previous[i]);
    double total = 0.0, max_speed = 0.0, max_push_speed = 0.0;
    int in_bounds = 1;
    for (int step = 1; step <= OVERLAP_STEPS; step++) {
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
    out->step_ms = total / OVERLAP_STEPS;
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
    for (int step = 1; step <= COLUMN_STEPS; step++) total += bench_step(ops, w, BENCH_DT);
    out->step_ms = total / COLUMN_STEPS;
    double tilt = 0.0;
    bench_state_t s;
    for (int j = 0; j < n; j++) {
        ops->get_state(w, ids[j], &s);
        double a = fabs(remainder(s.angle, 2.0 * M_PI));
        if (a > tilt) tilt = a;
    }
    double drift = fabs(s.x - top_x0), drop = s.y - (0.5 + (n - 1));
    snprintf(out->quality, sizeof out->quality,
             "top_drift=%.4g top_drop=%.4g max_tilt=%.4g standing=%d", drift, drop, tilt,
             drift < 0.5 && drop > -0.5);
    free(ids);
    ops->world_free(w);
}

typedef void (*bench_run_fn)(const bench_ops_t *, const bench_case_t *, bench_run_t *);

static const bench_run_fn bench_runners[SCENE_COUNT] = {
    pile_run,  pyramid_run, bounce_run, cradle_run,
    orbit_run, stack2_run,  tunnel_run, overlap_run, column_run};

/* Whether a variant runs a scene (only_scenes is a comma list or NULL). */
static inline int bench_ops_runs(const bench_ops_t *ops, bench_scene_id_t scene) {
    if (ops->only_scenes == NULL) return 1;
    const char *name = bench_scene_names[scene];
    size_t len = strlen(name);
    const char *p = ops->only_scenes;
    while (*p) {
        const char *end = strchr(p, ',');
        size_t item = end ? (size_t)(end - p) : strlen(p);
        if (item == len && strncmp(p, name, len) == 0) return 1;
        if (!end) break;
        p = end + 1;
    }
    return 0;
}

/* Runs one case `runs` times with one engine and prints its line. */
static inline void bench_run_case(const bench_ops_t *ops, const bench_case_t *c, int runs,
                                  int *summary_tunnelled_v_found, double *summary_first_v,
                                  double *summary_back) {
    double *ms = (double *)malloc(sizeof(double) * (size_t)runs);
    double *settled = (double *)malloc(sizeof(double) * (size_t)runs);
    bench_run_t first, run;
    int differ = 0;
    for (int i = 0; i < runs; i++) {
        bench_run_t *r = i == 0 ? &first : &run;
        memset(r, 0, sizeof *r);
        bench_runners[c->scene](ops, c, r);
        ms[i] = r->step_ms;
        settled[i] = r->settled_ms;
        if (i > 0 && strcmp(first.quality, run.quality) != 0) differ = 1;
    }
    char size[32], quality[800];
    snprintf(size, sizeof size, "%g", c->size);
    snprintf(quality, sizeof quality, "%s%s", first.quality, differ ? " runs_differ=1" : "");
    bench_print_result(ops->name, bench_scene_names[c->scene], size, runs, ms,
                       c->scene == SCENE_PILE ? settled : NULL, quality);
    if (c->scene == SCENE_TUNNEL) {
        if (first.tunnelled > 0 && (!*summary_tunnelled_v_found || c->size < *summary_first_v)) {
            *summary_tunnelled_v_found = 1;
            *summary_first_v = c->size;
        }
        if (first.max_return_speed > *summary_back) *summary_back = first.max_return_speed;
    }
    free(ms);
    free(settled);
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
            "          [--iterations N] [--variant NAME]\n"
            "  scenes: pile pyramid bounce cradle orbit stack2 tunnel overlap column all\n"
            "  no --scene: pile 1000,4000,10000; pyramid 20,40; bounce 0.8 at dt 1/60,1/600;\n"
            "  cradle 5. --size and --dt apply to every scene given (--dt: bounce, orbit).\n"
            "  --iterations N: the solver's velocity iterations (each engine's own default\n"
            "  otherwise; position iterations keep theirs). --variant NAME: only that\n"
            "  variant of the program (e.g. ours, ours-sleeping).\n",
            program);
}

static inline void bench_default_sizes(bench_scene_id_t scene, int quick, double *sizes,
                                       int *count) {
    static const double pile_full[] = {1000, 4000, 10000}, pile_quick[] = {500};
    static const double pyramid_full[] = {20, 40}, pyramid_quick[] = {10};
    static const double stack2_all[] = {1, 10, 100, 1000, 10000};
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
        if (!(sizes[i] > 0.0)) {
            fprintf(stderr, "%s: sizes must be > 0\n", argv[0]);
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
        if (ndts > 0 && (scene == SCENE_BOUNCE || scene == SCENE_ORBIT)) {
            memcpy(case_dts, dts, sizeof(double) * (size_t)ndts);
            ncase_dts = ndts;
        } else {
            bench_default_dts(scene, quick, case_dts, &ncase_dts);
        }
        for (int k = 0; k < ops_count; k++) {
            if (!bench_ops_runs(ops[k], scene)) continue;
            if (bench_variant != NULL && strcmp(bench_variant, ops[k]->name) != 0) continue;
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
            if (scene == SCENE_TUNNEL) {
                char quality[128];
                if (found) {
                    snprintf(quality, sizeof quality, "first_tunnel_v=%g max_return_speed=%.4g",
                             first_v, back);
                } else {
                    snprintf(quality, sizeof quality,
                             "first_tunnel_v=>%g max_return_speed=%.4g",
                             case_sizes[ncase_sizes - 1], back);
                }
                bench_print_result(ops[k]->name, "tunnel", "summary", runs, NULL, NULL, quality);
            }
        }
    }
    return 0;
}

#endif // #ifndef BENCH_SCENES_H
