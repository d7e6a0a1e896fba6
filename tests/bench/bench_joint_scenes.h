#ifndef BENCH_JOINT_SCENES_H
#define BENCH_JOINT_SCENES_H

/*
 * The joint scenes of docs/bench-scenes.md, written against bench_ops_t's
 * add_revolute and set_group; included by bench_scenes.h (which runs them
 * only on engines that have joints). Plain C that also compiles as C++.
 *
 * Every joint's gap (the distance between its two anchors, which a rigid
 * pin keeps at 0) is read from the bodies' states, so every engine is
 * measured the same way: each anchor is kept in its body's frame (centroid,
 * unrotated) from the pose the joint was made in.
 *
 *   jointchain(n)  n box links of 0.5 m by 0.125 m (mass = area), pinned
 *                  end to end, the first to the world at the origin, laid
 *                  out along +x and released from rest: the chain swings
 *                  down and whips; 600 steps. Keys: max_stretch and
 *                  end_stretch (the sum of the joints' gaps over the
 *                  chain's length 0.5 n, largest over the steps and at the
 *                  last one), max_gap (m, the widest single joint, any
 *                  step), tip_min_y (m, the lowest the far end's centre
 *                  went).
 *   ragdolls(n)    n ragdolls of joint_ragdoll.scene's bodies, masses and
 *                  limits (ten bodies, nine pins with limits), each turned
 *                  by a random angle, dropped in rows of 4 into a box 12.8 m
 *                  wide; one ragdoll's bodies make no contact with one
 *                  another; 600 steps. Keys: max_gap and end_gap (m, the
 *                  widest joint gap over the steps and at the last one),
 *                  max_past_limit (rad, the farthest any joint went past a
 *                  limit, any step), max_penetration (m, at the last step),
 *                  below (bodies whose centre is below the floor's top at
 *                  the end; must be 0), outside (centres outside the box),
 *                  vmax_end (m/s, the fastest body at the end), moving_end
 *                  (bodies faster than 0.1 m/s at the end).
 */

#define JOINT_STEPS 600
#define JOINTCHAIN_LINK 0.5 /* m, pin to pin */
#define JOINTCHAIN_THICKNESS 0.125
#define RAGDOLL_PARTS 10
#define RAGDOLL_JOINTS 9
#define RAGDOLL_COLUMNS 4
#define RAGDOLL_PITCH 3.2  /* m between ragdolls' torsos; each reaches 1.46 m */
#define RAGDOLL_JITTER 0.1 /* m */
#define RAGDOLL_BOX_WIDTH (RAGDOLL_COLUMNS * RAGDOLL_PITCH)
#define RAGDOLL_MOVING_SPEED 0.1 /* m/s */

/* A joint as the scenes measure it: its bodies (body1 -1: the world), each
 * anchor in its body's frame (the world's: world coordinates), and for a
 * limited one the bodies' relative angle when made and the limits. */
typedef struct {
    int body1, body2;
    double l1x, l1y, l2x, l2y;
    double angle0;
    int limit;
    double lower, upper;
} bench_pin_t;

static inline void bench_to_local(const bench_state_t *s, double x, double y, double *lx,
                                  double *ly) {
    double c = cos(s->angle), sn = sin(s->angle), dx = x - s->x, dy = y - s->y;
    *lx = c * dx + sn * dy;
    *ly = -sn * dx + c * dy;
}

static inline void bench_to_world(const bench_state_t *s, double lx, double ly, double *x,
                                  double *y) {
    double c = cos(s->angle), sn = sin(s->angle);
    *x = s->x + c * lx - sn * ly;
    *y = s->y + sn * lx + c * ly;
}

/* A body's state, or the world's (at rest at the origin) for -1. */
static inline void bench_pin_state(const bench_ops_t *ops, void *w, int body, bench_state_t *s) {
    if (body >= 0) {
        ops->get_state(w, body, s);
    } else {
        memset(s, 0, sizeof *s);
    }
}

/* Makes a revolute joint at the world point (x, y) and keeps its anchors. */
static inline bench_pin_t bench_pin(const bench_ops_t *ops, void *w, int body1, int body2,
                                    double x, double y, int limit, double lower, double upper) {
    bench_pin_t pin;
    bench_state_t s1, s2;
    bench_pin_state(ops, w, body1, &s1);
    bench_pin_state(ops, w, body2, &s2);
    pin.body1 = body1;
    pin.body2 = body2;
    bench_to_local(&s1, x, y, &pin.l1x, &pin.l1y);
    bench_to_local(&s2, x, y, &pin.l2x, &pin.l2y);
    pin.angle0 = s2.angle - s1.angle;
    pin.limit = limit;
    pin.lower = lower;
    pin.upper = upper;
    ops->add_revolute(w, body1, body2, x, y, limit, lower, upper);
    return pin;
}

/* The distance (m) between the joint's two anchors now; with past_limit,
 * also how far (rad, >= 0) its angle is beyond a limit. */
static inline double bench_pin_gap(const bench_ops_t *ops, void *w, const bench_pin_t *pin,
                                   double *past_limit) {
    bench_state_t s1, s2;
    bench_pin_state(ops, w, pin->body1, &s1);
    bench_pin_state(ops, w, pin->body2, &s2);
    double x1, y1, x2, y2;
    bench_to_world(&s1, pin->l1x, pin->l1y, &x1, &y1);
    bench_to_world(&s2, pin->l2x, pin->l2y, &x2, &y2);
    if (past_limit != NULL) {
        double a = s2.angle - s1.angle - pin->angle0;
        a = atan2(sin(a), cos(a));
        *past_limit = !pin->limit ? 0.0 : fmax(0.0, fmax(pin->lower - a, a - pin->upper));
    }
    return hypot(x2 - x1, y2 - y1);
}

/* ---- jointchain(n) ---- */
static inline void jointchain_run(const bench_ops_t *ops, const bench_case_t *c,
                                  bench_run_t *out) {
    int n = c->size >= 1.0 ? (int)c->size : 1;
    double mu = bench_shape_friction(ops, BENCH_FRICTION);
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, n);
    bench_shape_t link = bench_box_shape(0.5 * JOINTCHAIN_LINK, 0.5 * JOINTCHAIN_THICKNESS);
    bench_pin_t *pins = (bench_pin_t *)malloc(sizeof(bench_pin_t) * (size_t)n);
    int previous = -1;
    for (int i = 0; i < n; i++) {
        int id = ops->add_body(w, &link, (i + 0.5) * JOINTCHAIN_LINK, 0.0, 0.0,
                               bench_shape_area(&link), mu, 0.0, 1);
        pins[i] = bench_pin(ops, w, previous, id, i * JOINTCHAIN_LINK, 0.0, 0, 0.0, 0.0);
        previous = id;
    }
    int steps = bench_step_count(JOINT_STEPS);
    double total = 0.0, length = n * JOINTCHAIN_LINK;
    double max_stretch = 0.0, stretch = 0.0, max_gap = 0.0, tip_min_y = 0.0;
    for (int step = 1; step <= steps; step++) {
        total += bench_step(ops, w, BENCH_DT);
        double sum = 0.0;
        for (int i = 0; i < n; i++) {
            double gap = bench_pin_gap(ops, w, &pins[i], NULL);
            sum += gap;
            max_gap = fmax(max_gap, gap);
        }
        stretch = sum / length;
        max_stretch = fmax(max_stretch, stretch);
        bench_state_t tip;
        ops->get_state(w, previous, &tip);
        tip_min_y = fmin(tip_min_y, tip.y);
    }
    out->step_ms = total / steps;
    snprintf(out->quality, sizeof out->quality,
             "steps=%d max_stretch=%.4g end_stretch=%.4g max_gap=%.4g tip_min_y=%.4g", steps,
             max_stretch, stretch, max_gap, tip_min_y);
    free(pins);
    ops->world_free(w);
}

/* ---- ragdolls(n) ----
 * joint_ragdoll.scene's ragdoll standing upright, its torso's centre at the
 * origin: each body's shape (a box of half extents hx, hy, or a circle of
 * radius hx when hy is 0), centre, angle (rad) and mass (kg). */
typedef struct {
    double hx, hy, x, y, angle, mass;
} ragdoll_part_t;

static const ragdoll_part_t ragdoll_parts[RAGDOLL_PARTS] = {
    {0.45, 0.2, 0.0, 0.0, 0.5 * M_PI, 4.0},       /* torso */
    {0.22, 0.0, 0.0, 0.69, 0.5 * M_PI, 1.5},      /* head */
    {0.225, 0.07, -0.3, 0.225, -0.5 * M_PI, 0.6}, /* upper arms */
    {0.225, 0.06, -0.3, -0.225, -0.5 * M_PI, 0.5}, /* lower arms */
    {0.225, 0.07, 0.3, 0.225, -0.5 * M_PI, 0.6},
    {0.225, 0.06, 0.3, -0.225, -0.5 * M_PI, 0.5},
    {0.25, 0.08, -0.12, -0.7, -0.5 * M_PI, 1.2}, /* thighs */
    {0.25, 0.07, -0.12, -1.2, -0.5 * M_PI, 1.0}, /* shins */
    {0.25, 0.08, 0.12, -0.7, -0.5 * M_PI, 1.2},
    {0.25, 0.07, 0.12, -1.2, -0.5 * M_PI, 1.0},
};

/* Its pins: the two parts, the pin's point in the upright pose and the
 * limits (rad, from the upright pose's relative angle). */
typedef struct {
    int part1, part2;
    double x, y, lower, upper;
} ragdoll_joint_t;

static const ragdoll_joint_t ragdoll_joints[RAGDOLL_JOINTS] = {
    {0, 1, 0.0, 0.47, -0.5, 0.5},   /* neck */
    {0, 2, -0.3, 0.45, -2.5, 0.5},  /* shoulders */
    {0, 4, 0.3, 0.45, -0.5, 2.5},
    {2, 3, -0.3, 0.0, -2.5, 0.0},   /* elbows */
    {4, 5, 0.3, 0.0, 0.0, 2.5},
    {0, 6, -0.12, -0.45, -1.5, 0.5}, /* hips */
    {0, 8, 0.12, -0.45, -0.5, 1.5},
    {6, 7, -0.12, -0.95, 0.0, 2.0},  /* knees */
    {8, 9, 0.12, -0.95, -2.0, 0.0},
};

static inline void ragdolls_run(const bench_ops_t *ops, const bench_case_t *c,
                                bench_run_t *out) {
    int n = c->size >= 1.0 ? (int)c->size : 1;
    double mu = bench_shape_friction(ops, BENCH_FRICTION);
    double e_static = bench_static_elasticity(ops);
    void *w = ops->world_new(BENCH_GRAVITY_Y, 1, n * RAGDOLL_PARTS + 3);
    int rows = (n + RAGDOLL_COLUMNS - 1) / RAGDOLL_COLUMNS;
    double width = RAGDOLL_BOX_WIDTH, wall_half = 0.5 * RAGDOLL_PITCH * (rows + 1);
    ops->add_static_box(w, 0.5 * width, -0.5, 0.5 * width + 1.0, 0.5, mu, e_static); /* floor */
    ops->add_static_box(w, -0.5, wall_half, 0.5, wall_half, mu, e_static);
    ops->add_static_box(w, width + 0.5, wall_half, 0.5, wall_half, mu, e_static);
    int *ids = (int *)malloc(sizeof(int) * (size_t)(n * RAGDOLL_PARTS));
    bench_pin_t *pins = (bench_pin_t *)malloc(sizeof(bench_pin_t) * (size_t)(n * RAGDOLL_JOINTS));
    bench_rng_t rng;
    bench_rng_init(&rng);
    for (int k = 0; k < n; k++) {
        int column = k % RAGDOLL_COLUMNS, row = k / RAGDOLL_COLUMNS;
        double u1 = bench_rng_next(&rng);
        double u2 = bench_rng_next(&rng);
        double u3 = bench_rng_next(&rng);
        double cx = RAGDOLL_PITCH * (column + 0.5) + RAGDOLL_JITTER * (u1 - 0.5);
        double cy = 0.5 * RAGDOLL_PITCH + RAGDOLL_PITCH * row + RAGDOLL_JITTER * (u2 - 0.5);
        double turn = 2.0 * M_PI * u3, ct = cos(turn), st = sin(turn);
        for (int p = 0; p < RAGDOLL_PARTS; p++) {
            const ragdoll_part_t *part = &ragdoll_parts[p];
            bench_shape_t shape = part->hy > 0.0 ? bench_box_shape(part->hx, part->hy)
                                                 : bench_regular_shape(BENCH_CIRCLE, part->hx);
            int id = ops->add_body(w, &shape, cx + ct * part->x - st * part->y,
                                   cy + st * part->x + ct * part->y, part->angle + turn,
                                   part->mass, mu, 0.0, 1);
            ops->set_group(w, id, k + 1);
            ids[k * RAGDOLL_PARTS + p] = id;
        }
        for (int j = 0; j < RAGDOLL_JOINTS; j++) {
            const ragdoll_joint_t *joint = &ragdoll_joints[j];
            pins[k * RAGDOLL_JOINTS + j] =
                bench_pin(ops, w, ids[k * RAGDOLL_PARTS + joint->part1],
                          ids[k * RAGDOLL_PARTS + joint->part2], cx + ct * joint->x - st * joint->y,
                          cy + st * joint->x + ct * joint->y, 1, joint->lower, joint->upper);
        }
    }
    int steps = bench_step_count(JOINT_STEPS);
    double total = 0.0, max_gap = 0.0, end_gap = 0.0, max_past = 0.0;
    for (int step = 1; step <= steps; step++) {
        total += bench_step(ops, w, BENCH_DT);
        end_gap = 0.0;
        for (int j = 0; j < n * RAGDOLL_JOINTS; j++) {
            double past;
            end_gap = fmax(end_gap, bench_pin_gap(ops, w, &pins[j], &past));
            max_past = fmax(max_past, past);
        }
        max_gap = fmax(max_gap, end_gap);
    }
    out->step_ms = total / steps;
    int below = 0, outside = 0, moving = 0;
    double vmax = 0.0;
    for (int i = 0; i < n * RAGDOLL_PARTS; i++) {
        bench_state_t s;
        ops->get_state(w, ids[i], &s);
        below += s.y < 0.0;
        outside += !(s.x >= 0.0 && s.x <= width);
        vmax = fmax(vmax, hypot(s.vx, s.vy));
        moving += hypot(s.vx, s.vy) > RAGDOLL_MOVING_SPEED;
    }
    snprintf(out->quality, sizeof out->quality,
             "steps=%d max_gap=%.4g end_gap=%.4g max_past_limit=%.4g max_penetration=%.4g "
             "below=%d outside=%d vmax_end=%.4g moving_end=%d",
             steps, max_gap, end_gap, max_past, ops->max_penetration(w), below, outside, vmax,
             moving);
    free(pins);
    free(ids);
    ops->world_free(w);
}

#endif // #ifndef BENCH_JOINT_SCENES_H
