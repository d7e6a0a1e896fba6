/*
 * make report: the error of each integrator against its run time on the
 * scenes with exact answers of tests/reference.c, and the 1D collisions.
 * Writes the CSVs under docs/report, docs/report/plots.gp (run by report.sh with
 * gnuplot) and docs/accuracy.md, which also takes the contact solver's
 * figures that report.sh measured with the benchmark programs
 * (docs/report/solver.csv).
 *
 *   accuracy [--runs N] [--quick] [--out DIR] [--doc FILE] [--solver CSV]
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "jostle/jostle.h"
#include "reference.h"

enum { MAX_STEPS_SIZES = 16 };
static const double ORDER[INTEGRATOR_COUNT] = {1, 1, 1, 2, 4, 4, 1};
/* The range an order is fitted over: errors below FIT_HIGH (past the
 * start-up) and above FIT_ROUND_OFF times the smallest error of the scene
 * (round-off), while each halving of h still cuts the error by FIT_DROP. */
static const double FIT_HIGH = 0.1, FIT_ROUND_OFF = 1000.0, FIT_DROP = 0.8;
/* A first-order scheme whose error is still above FIT_HIGH at the smallest
 * step of a long run (its energy drift turns into phase error that grows as
 * t^2) is fitted over this many periods instead. */
static const double SHORT_PERIODS = 1.25;

typedef struct {
    int runs;
    bool quick;
    const char *out_dir;
    const char *doc_path;
    const char *solver_csv;
} options_t;

/* One scene's sweep: h = first_h / 2^k, k = 0 .. sizes - 1, and `extra`
 * more halvings for the first-order schemes where they need them to reach
 * their asymptotic range. */
typedef struct {
    reference_scene_t scene;
    double periods;
    double first_h;
    int sizes;
    int extra;
} sweep_t;

typedef struct {
    double h;
    reference_result_t result;
    double seconds; /* CPU time of one run, the minimum over the runs */
} point_t;

typedef struct {
    point_t points[MAX_STEPS_SIZES];
    int count;
    /* The order p of the model error = A h^p (1 + c h) fitted to the run of
     * points in the fit range: the leading term and the next order's, which
     * RK4 carries far into its range on the orbits; NAN if too few points. */
    double order;
    /* The plain least-squares slope of log error on log h over the run. */
    double slope;
    int fit_points;
    bool short_fit; /* fitted over SHORT_PERIODS (see there) */
} series_t;

static double cpu_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* One warm-up run thrown away, then the fastest of `runs`. */
static point_t measure(const sweep_t *sweep, integrator_t integrator, double h, int runs) {
    point_t point = {h, reference_run(sweep->scene, integrator, h, sweep->periods), INFINITY};
    for (int r = 0; r < runs; r++) {
        double start = cpu_seconds();
        reference_run(sweep->scene, integrator, h, sweep->periods);
        point.seconds = fmin(point.seconds, cpu_seconds() - start);
    }
    return point;
}

/* The least-squares line through (x, y): its slope and residual. */
static double line_fit(const double *x, const double *y, int n, double *residual) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < n; i++) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
    double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx), intercept = (sy - slope * sx) / n;
    *residual = 0.0;
    for (int i = 0; i < n; i++) {
        double r = y[i] - intercept - slope * x[i];
        *residual += r * r;
    }
    return slope;
}

/* log error = log A + p log h + log(1 + c h): for each c of a log-spaced
 * grid of both signs the rest is a line; the c with the least residual
 * wins (c = 0 is the plain line). */
static double two_term_order(const double *h, const double *x, const double *y, int n) {
    double best_residual, best = line_fit(x, y, n, &best_residual);
    for (int k = 0; k < 400; k++) {
        for (int sign = -1; sign <= 1; sign += 2) {
            double c = sign * pow(10.0, (k - 200) / 40.0), z[MAX_STEPS_SIZES], residual;
            bool valid = true;
            for (int i = 0; i < n && valid; i++) {
                valid = 1.0 + c * h[i] > 0.0;
                if (valid) z[i] = y[i] - log(1.0 + c * h[i]);
            }
            if (!valid) continue;
            double order = line_fit(x, z, n, &residual);
            if (residual < best_residual) best_residual = residual, best = order;
        }
    }
    return best;
}

/* Fits the leading run of points in the fit range; floor is the smallest
 * error seen in the scene. */
static void fit_order(series_t *series, const double *errors, double floor) {
    double h[MAX_STEPS_SIZES], x[MAX_STEPS_SIZES], y[MAX_STEPS_SIZES], previous = INFINITY;
    int n = 0;
    for (int i = 0; i < series->count; i++) {
        double error = errors[i];
        if (isnan(error) || error >= FIT_HIGH) continue;
        if (error < FIT_ROUND_OFF * floor || error > FIT_DROP * previous) break;
        h[n] = series->points[i].h;
        x[n] = log(h[n]);
        y[n++] = log(error);
        previous = error;
    }
    series->fit_points = n;
    series->order = series->slope = NAN;
    if (n < 3) return;
    double residual;
    series->slope = line_fit(x, y, n, &residual);
    /* Three points fit a three-parameter model exactly: only the line then. */
    series->order = n >= 5 ? two_term_order(h, x, y, n) : series->slope;
}

static double smallest_error(const series_t series[INTEGRATOR_COUNT]) {
    double floor = INFINITY;
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        for (int k = 0; k < series[i].count; k++) {
            double error = series[i].points[k].result.error;
            if (error > 0.0) floor = fmin(floor, error);
        }
    }
    return floor;
}

/* Fits every series; one that does not reach its asymptotic range over the
 * sweep's periods is fitted again from errors over SHORT_PERIODS. */
static void fit_orders(const sweep_t *sweep, series_t series[INTEGRATOR_COUNT]) {
    double floor = smallest_error(series);
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        series_t *s = &series[i];
        double errors[MAX_STEPS_SIZES];
        for (int k = 0; k < s->count; k++) errors[k] = s->points[k].result.error;
        fit_order(s, errors, floor);
        if (!isnan(s->order) || sweep->scene == REFERENCE_BOUNCE) continue;
        for (int k = 0; k < s->count; k++) {
            errors[k] = reference_run(sweep->scene, (integrator_t)i, s->points[k].h,
                                      SHORT_PERIODS).error;
        }
        fit_order(s, errors, floor);
        s->short_fit = true;
    }
}

static bool first_order(integrator_t integrator) {
    return ORDER[integrator] == 1;
}

/* The schemes whose flight under gravity alone is exact, so their bounce
 * error is round-off at every step size. */
static bool exact_for_constant_forces(integrator_t integrator) {
    return integrator != INTEGRATOR_EXPLICIT_EULER && integrator != INTEGRATOR_SYMPLECTIC_EULER &&
           integrator != INTEGRATOR_IMPLICIT_EULER;
}

static void run_sweep(const sweep_t *sweep, const options_t *options,
                      series_t series[INTEGRATOR_COUNT]) {
    int total = 0, done = 0;
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        total += sweep->sizes + (first_order((integrator_t)i) ? sweep->extra : 0);
    }
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        series_t *s = &series[i];
        s->count = sweep->sizes + (first_order((integrator_t)i) ? sweep->extra : 0);
        for (int k = 0; k < s->count; k++) {
            double h = sweep->first_h / (double)(1L << k);
            s->points[k] = measure(sweep, (integrator_t)i, h, options->runs);
            fprintf(stderr, "\r  %-10s %3d/%d  %-16s h = %-10.4g", reference_name(sweep->scene),
                    ++done, total, integrator_get_name((integrator_t)i), h);
        }
    }
    fit_orders(sweep, series);
    fprintf(stderr, "\n");
}

static FILE *open_output(const char *dir, const char *name) {
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *file = fopen(path, "w");
    if (file == NULL) {
        fprintf(stderr, "accuracy: cannot write %s: %s\n", path, strerror(errno));
        exit(1);
    }
    return file;
}

/* One CSV per scene; one data file per scene and integrator for gnuplot. */
static void write_sweep_data(const sweep_t *sweep, const series_t series[INTEGRATOR_COUNT],
                             const char *dir) {
    char name[256];
    snprintf(name, sizeof name, "%s.csv", reference_name(sweep->scene));
    FILE *csv = open_output(dir, name);
    fprintf(csv, "integrator,h,steps,error,energy_drift,momentum_drift,cpu_seconds,diverged\n");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        snprintf(name, sizeof name, "%s-%d.dat", reference_name(sweep->scene), i);
        FILE *dat = open_output(dir, name);
        for (int k = 0; k < series[i].count; k++) {
            const point_t *p = &series[i].points[k];
            fprintf(csv, "%s,%.10g,%ld,%.6e,%.6e,%.6e,%.6e,%d\n",
                    integrator_get_name((integrator_t)i), p->h, p->result.steps, p->result.error,
                    p->result.energy_drift, p->result.momentum_drift, p->seconds,
                    p->result.diverged);
            /* gnuplot's log axes cannot show 0: round-off floors at 1e-17. */
            if (!p->result.diverged) {
                fprintf(dat, "%.10g %.6e %.6e\n", p->h, fmax(p->result.error, 1e-17),
                        fmax(p->seconds * 1e3, 1e-6));
            }
        }
        fclose(dat);
    }
    fclose(csv);
}

static void write_plots(FILE *gp, const sweep_t *sweep, const series_t series[INTEGRATOR_COUNT]) {
    const char *name = reference_name(sweep->scene);
    fprintf(gp, "set output 'work-%s.svg'\n", name);
    fprintf(gp, "set title '%s: error against run time (one point per step size)'\n", name);
    fprintf(gp, "set xlabel 'CPU time of the run (ms)'\nset ylabel '%s'\n",
            reference_error_name(sweep->scene));
    fprintf(gp, "plot ");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        fprintf(gp, "%s'%s-%d.dat' using 3:2 with linespoints title '%s'", i ? ", " : "", name, i,
                integrator_get_name((integrator_t)i));
    }
    fprintf(gp, "\nset output 'order-%s.svg'\n", name);
    fprintf(gp, "set title '%s: error against step size (fitted slope in the key)'\n", name);
    fprintf(gp, "set xlabel 'step h (s)'\n");
    fprintf(gp, "plot ");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        char order[32] = "no fit";
        if (!isnan(series[i].order)) snprintf(order, sizeof order, "slope %.2f", series[i].order);
        fprintf(gp, "%s'%s-%d.dat' using 1:2 with linespoints title '%s (%s)'", i ? ", " : "",
                name, i, integrator_get_name((integrator_t)i), order);
    }
    fprintf(gp, "\n");
}

/* The least CPU time at which a series reaches `target` error, by log-log
 * interpolation between its points; NAN if it never does. */
static double time_to_reach(const series_t *series, double target) {
    for (int k = 0; k < series->count; k++) {
        const point_t *p = &series->points[k];
        if (p->result.diverged || !(p->result.error <= target)) continue;
        if (k == 0 || series->points[k - 1].result.diverged) return p->seconds;
        const point_t *q = &series->points[k - 1];
        double f = log(target / q->result.error) / log(p->result.error / q->result.error);
        return exp(log(q->seconds) + f * (log(p->seconds) - log(q->seconds)));
    }
    return NAN;
}

static void format_number(char *text, size_t size, double value) {
    if (isnan(value)) {
        snprintf(text, size, "-");
    } else {
        snprintf(text, size, "%.3g", value);
    }
}

static void write_scene_section(FILE *md, const sweep_t *sweep,
                                const series_t series[INTEGRATOR_COUNT]) {
    const char *name = reference_name(sweep->scene);
    fprintf(md, "\n### %s\n\n", name);
    fprintf(md, "![%s: work-precision](report/work-%s.svg)\n", name, name);
    fprintf(md, "![%s: error against h](report/order-%s.svg)\n\n", name, name);
    char span[96];
    if (sweep->scene == REFERENCE_BOUNCE) {
        snprintf(span, sizeof span, "over five bounces");
    } else {
        snprintf(span, sizeof span, "after %g s (%g periods of %.4g s)",
                 sweep->periods * reference_period(sweep->scene), sweep->periods,
                 reference_period(sweep->scene));
    }
    fprintf(md, "Error: %s %s; h from %.4g s halved %d times (%d more for the first-order "
                "schemes). CSV: [report/%s.csv](report/%s.csv).\n\n",
            reference_error_name(sweep->scene), span, sweep->first_h, sweep->sizes - 1,
            sweep->extra, name, name);
    fprintf(md, "| integrator | fitted order (theory) | plain slope | error at h "
                "= %.4g | largest energy drift there | ms to reach 1e-3 | 1e-6 | 1e-9 |\n",
            sweep->first_h / 16.0);
    fprintf(md, "|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        const series_t *s = &series[i];
        const point_t *p = &s->points[4];
        char order[64], slope[32], error[32], energy[32], t3[32], t6[32], t9[32];
        if (sweep->scene == REFERENCE_BOUNCE && exact_for_constant_forces((integrator_t)i)) {
            snprintf(order, sizeof order, "exact for constant gravity");
        } else if (isnan(s->order)) {
            snprintf(order, sizeof order, "not reached (%g)", ORDER[i]);
        } else {
            snprintf(order, sizeof order, "%.2f (%g) over %d points%s", s->order, ORDER[i],
                     s->fit_points, s->short_fit ? ", 1.25 periods*" : "");
        }
        if (p->result.diverged) {
            snprintf(error, sizeof error, "diverged");
        } else {
            format_number(error, sizeof error, p->result.error);
        }
        format_number(energy, sizeof energy, p->result.energy_drift);
        snprintf(slope, sizeof slope, isnan(s->slope) ? "-" : "%.2f", s->slope);
        format_number(t3, sizeof t3, 1e3 * time_to_reach(s, 1e-3));
        format_number(t6, sizeof t6, 1e3 * time_to_reach(s, 1e-6));
        format_number(t9, sizeof t9, 1e3 * time_to_reach(s, 1e-9));
        fprintf(md, "| %s | %s | %s | %s | %s | %s | %s | %s |\n",
                integrator_get_name((integrator_t)i), order, slope, error, energy, t3, t6, t9);
    }
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        if (!series[i].short_fit) continue;
        fprintf(md, "\n\\* Fitted over %g periods: over the sweep's %g periods fewer than "
                    "three of its points fall in the fit range (a first-order scheme on an "
                    "orbit is still above %g at the smallest step, its energy drift turning "
                    "into a phase error that grows as t^2; RK4 on drag is at round-off from "
                    "the largest step).\n",
                SHORT_PERIODS, sweep->periods, FIT_HIGH);
        break;
    }
}

/* ---- 1D collisions: exact velocities after, momentum kept ---- */

typedef struct {
    const char *name;
    double m1, m2, v1, v2, e;
} collision_case_t;

static const collision_case_t COLLISIONS[] = {
    {"elastic, masses 1 and 3", 1.0, 3.0, 2.0, -1.0, 1.0},
    {"inelastic, masses 1 and 3", 1.0, 3.0, 2.0, -1.0, 0.0},
    {"e = 0.5, masses 2 and 2", 2.0, 2.0, 3.0, 0.0, 0.5},
    {"e = 1.5 (gains energy), masses 1 and 1", 1.0, 1.0, 2.0, -2.0, 1.5},
    {"e = 0.8 against infinite mass", 1.0, INFINITY, 5.0, 0.0, 0.8},
};

/* v1' and v2' of a head-on collision with restitution e. */
static void collision_exact(const collision_case_t *c, double *v1, double *v2) {
    if (isinf(c->m2)) {
        *v1 = c->v2 - c->e * (c->v1 - c->v2);
        *v2 = c->v2;
        return;
    }
    double total = c->m1 + c->m2, p = c->m1 * c->v1 + c->m2 * c->v2;
    *v1 = (p - c->m2 * c->e * (c->v1 - c->v2)) / total;
    *v2 = (p + c->m1 * c->e * (c->v1 - c->v2)) / total;
}

/* Two unit boxes 2 m apart, run until well after they meet. world: world
 * contacts (restitution from elasticity); else create_physics_collision. */
static void collision_run(const collision_case_t *c, integrator_t integrator, bool world,
                          double *error, double *momentum_error) {
    const rgb_color_t grey = {0.5f, 0.5f, 0.5f};
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    body_t *a = body_init(polygon_make_box((vector_t){-1.0, 0.0}, 0.5, 0.5), c->m1, grey);
    body_t *b = body_init(polygon_make_box((vector_t){1.0, 0.0}, 0.5, 0.5), c->m2, grey);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    body_set_velocity(a, (vector_t){c->v1, 0.0});
    body_set_velocity(b, (vector_t){c->v2, 0.0});
    if (world) {
        scene_set_contacts_enabled(scene, true);
        body_set_elasticity(a, c->e);
        body_set_elasticity(b, c->e);
        body_set_friction(a, 0.0);
        body_set_friction(b, 0.0);
    } else {
        create_physics_collision(scene, a, b, c->e);
    }
    for (int i = 0; i < 120; i++) scene_tick(scene, 1.0 / 60.0);
    double v1, v2;
    collision_exact(c, &v1, &v2);
    double va = body_get_velocity(a).x, vb = body_get_velocity(b).x;
    double scale = fabs(c->v1) + fabs(c->v2);
    *error = fmax(fabs(va - v1), fabs(vb - v2)) / scale;
    if (isinf(c->m2)) {
        *momentum_error = fabs(vb - c->v2) / scale; /* the wall must not move */
    } else {
        double p0 = c->m1 * c->v1 + c->m2 * c->v2;
        *momentum_error = fabs(c->m1 * va + c->m2 * vb - p0) / (c->m1 * fabs(c->v1) +
                                                                c->m2 * fabs(c->v2));
    }
    scene_free(scene);
}

static void write_collisions(FILE *md, const char *dir) {
    FILE *csv = open_output(dir, "collisions.csv");
    fprintf(csv, "case,pipeline,integrator,velocity_error,momentum_error\n");
    fprintf(md, "\n## 1D collisions\n\n");
    fprintf(md, "Two unit boxes meet head-on at 60 Hz; the velocities after are compared with "
                "v1' = (p - m2 e (v1 - v2)) / (m1 + m2), v2' = (p + m1 e (v1 - v2)) / (m1 + m2) "
                "(against an infinite mass: v1' = -e v1, the wall still). Errors relative to "
                "|v1| + |v2|, the largest over the six integrators; CSV: "
                "[report/collisions.csv](report/collisions.csv).\n\n");
    fprintf(md, "| case | seed pair collision: velocity error | momentum error | world "
                "contacts: velocity error | momentum error |\n|---|---|---|---|---|\n");
    for (size_t k = 0; k < sizeof COLLISIONS / sizeof COLLISIONS[0]; k++) {
        double worst[2][2] = {{0, 0}, {0, 0}};
        for (int world = 0; world < 2; world++) {
            for (int i = 0; i < INTEGRATOR_COUNT; i++) {
                double error, momentum;
                collision_run(&COLLISIONS[k], (integrator_t)i, world, &error, &momentum);
                fprintf(csv, "%s,%s,%s,%.3e,%.3e\n", COLLISIONS[k].name,
                        world ? "world" : "seed", integrator_get_name((integrator_t)i), error,
                        momentum);
                worst[world][0] = fmax(worst[world][0], error);
                worst[world][1] = fmax(worst[world][1], momentum);
            }
        }
        fprintf(md, "| %s | %.2g | %.2g | %.2g | %.2g |\n", COLLISIONS[k].name, worst[0][0],
                worst[0][1], worst[1][0], worst[1][1]);
    }
    fclose(csv);
}

/* ---- The contact solver against the peers (report.sh measured it) ---- */

enum { MAX_SOLVER_ROWS = 64 };

typedef struct {
    char engine[32];
    int iterations;
    double pyramid_ms, top_drop, penetration, column_ms, column_drift;
} solver_row_t;

static int read_solver_rows(const char *path, solver_row_t rows[MAX_SOLVER_ROWS]) {
    FILE *file = path != NULL ? fopen(path, "r") : NULL;
    if (file == NULL) return 0;
    char line[512];
    int count = 0;
    while (fgets(line, sizeof line, file) != NULL && count < MAX_SOLVER_ROWS) {
        solver_row_t *r = &rows[count];
        if (sscanf(line, "%31[^,],%d,%lf,%lf,%lf,%lf,%lf", r->engine, &r->iterations,
                   &r->pyramid_ms, &r->top_drop, &r->penetration, &r->column_ms,
                   &r->column_drift) == 7) {
            count++;
        }
    }
    fclose(file);
    return count;
}

static void write_solver(FILE *md, FILE *gp, const options_t *options) {
    solver_row_t rows[MAX_SOLVER_ROWS];
    int count = read_solver_rows(options->solver_csv, rows);
    fprintf(md, "\n## The contact solver, against Chipmunk2D and Box2D\n\n");
    if (count == 0) {
        fprintf(md, "Not measured in this run (no %s).\n", options->solver_csv
                                                             ? options->solver_csv
                                                             : "solver CSV");
        return;
    }
    const char *engines[3] = {"ours", "chipmunk", "box2d"};
    const char *figures[3][3] = {{"top_drop", "4", "pyramid(20): |top box drop| after 10 s (m)"},
                                 {"penetration", "5", "pyramid(20): largest penetration (m)"},
                                 {"drift", "7", "column(10): top box sideways drift after 60 s (m)"}};
    for (int e = 0; e < 3; e++) {
        char name[64];
        snprintf(name, sizeof name, "solver-%s.dat", engines[e]);
        FILE *dat = open_output(options->out_dir, name);
        for (int i = 0; i < count; i++) {
            const solver_row_t *r = &rows[i];
            if (strcmp(r->engine, engines[e]) != 0) continue;
            fprintf(dat, "%d %.6g %.6e %.6e %.6g %.6e\n", r->iterations, r->pyramid_ms,
                    fmax(fabs(r->top_drop), 1e-7), fmax(r->penetration, 1e-7), r->column_ms,
                    fmax(r->column_drift, 1e-7));
        }
        fclose(dat);
    }
    for (int f = 0; f < 3; f++) {
        /* The data columns: 1 iterations, 2 pyramid ms, 3 |drop|, 4
         * penetration, 5 column ms, 6 column drift. */
        int y = f == 0 ? 3 : f == 1 ? 4 : 6, x = f == 2 ? 5 : 2;
        fprintf(gp, "set output 'solver-%s.svg'\n", figures[f][0]);
        fprintf(gp, "set title '%s against ms per step (one point per iteration count)'\n",
                figures[f][2]);
        fprintf(gp, "set xlabel 'ms per step'\nset ylabel '%s'\nplot ", figures[f][2]);
        for (int e = 0; e < 3; e++) {
            fprintf(gp, "%s'solver-%s.dat' using %d:%d with linespoints title '%s', "
                        "'solver-%s.dat' using %d:%d:1 with labels offset 1,0.6 notitle",
                    e ? ", " : "", engines[e], x, y, engines[e], engines[e], x, y);
        }
        fprintf(gp, "\n");
    }
    fprintf(md, "pyramid(20) and column(10) of [bench-scenes.md](bench-scenes.md), built by the "
                "benchmark programs of tests/bench for all three engines in the same run, at "
                "each velocity iteration count (ours keeps 4 position iterations, Box2D 2.4 "
                "its 3; Chipmunk has one count). Time: median ms per step. Box2D 2.4 gives "
                "every polygon a skin of 0.01 m (b2_polygonRadius), so its pyramid stands "
                "about 0.2 m taller than the boxes: its positive top drop is that skin, not a "
                "rise. CSV: [report/solver.csv](report/solver.csv).\n\n");
    fprintf(md, "![pyramid drop](report/solver-top_drop.svg)\n"
                "![pyramid penetration](report/solver-penetration.svg)\n"
                "![column drift](report/solver-drift.svg)\n\n");
    fprintf(md, "| engine | iterations | pyramid(20) ms/step | top drop (m) | largest "
                "penetration (m) | column(10) ms/step | top drift (m) |\n"
                "|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < count; i++) {
        const solver_row_t *r = &rows[i];
        fprintf(md, "| %s | %d | %.3g | %.3g | %.3g | %.3g | %.3g |\n", r->engine, r->iterations,
                r->pyramid_ms, r->top_drop, r->penetration, r->column_ms, r->column_drift);
    }
}

/* ---- The page ---- */

static void write_intro(FILE *md, const options_t *options) {
    fprintf(md,
            "# Accuracy against run time\n\n"
            "Generated by `make report` (tests/report/accuracy.c and report.sh); do not edit "
            "by hand. Each integrator of scene.h runs scenes whose exact answer is known, at "
            "step sizes halving over three decades or more; each point is one step size: its "
            "error against the exact answer and the CPU time of the run (one warm-up run "
            "thrown away, then the fastest of %d runs). A run whose state leaves any sane "
            "bound is recorded as diverged and drawn as a gap. The fitted order is p of the "
            "model error = A h^p (1 + c h), the leading term and the next order's, fitted by "
            "least squares on the logs (a grid over c, a line for the rest) over the points "
            "with error below %g (past the start-up) and above %g times the scene's smallest "
            "error (round-off), while each halving of h still cuts the error; the plain "
            "slope beside it is the straight line through the same points.%s\n\n",
            options->runs, FIT_HIGH, FIT_ROUND_OFF,
            options->quick ? " **Quick run: fewer step sizes and runs; not the published "
                             "figures.**"
                           : "");
    fprintf(md,
            "## The scenes and their exact answers\n\n"
            "- **oscillator**: a 1 kg body on a spring k = (2 pi)^2 N/m to an anchor of "
            "infinite mass, x0 = 1 m, v0 = pi m/s: x(t) = x0 cos wt + (v0 / w) sin wt, "
            "w = 2 pi rad/s. Error in phase space, sqrt(dx^2 + (dv / w)^2) over the "
            "amplitude, after 10.25 periods: at whole periods symplectic Euler's first-order "
            "error cancels (it is Verlet seen through a half kick, which changes velocities "
            "only), and its order would read 2.\n"
            "- **kepler**: eccentricity 0.6, a 0.001 kg body around a 1 kg one under "
            "create_newtonian_gravity with G (m1 + m2) = 1, centre of mass at rest; the "
            "relative motion starts at q0 = (1 - e, 0), p0 = (0, sqrt((1 + e) / (1 - e))), "
            "energy -1/2 per unit reduced mass, period 2 pi. Exact: Kepler's equation solved "
            "by Newton for the change of eccentric anomaly, then Lagrange's f and g. Error: "
            "the relative position over the semi-major axis and velocity over sqrt(mu / a), "
            "in one norm, after 10.25 orbits; energy and total angular momentum drifts are "
            "the largest over the run.\n"
            "- **orbit**: the orbit scene of [bench-scenes.md](bench-scenes.md) (G = 1, 1000 "
            "kg at the origin, 1 kg at (10, 0) m with (0, 10) m/s: nearly circular), measured "
            "as kepler.\n"
            "- **drag**: a 1 kg projectile from (0, 0) at (10, 10) m/s under gravity (0, "
            "-9.81) and create_drag with b = 0.5 /s: v = v_inf + (v0 - v_inf) e^(-bt), x = x0 "
            "+ v_inf t + (v0 - v_inf) (1 - e^(-bt)) / b, v_inf = g / b. Error: position over "
            "the distance flown, after 5 s.\n"
            "- **bounce**: the bounce scene of [bench-scenes.md](bench-scenes.md) with world "
            "contacts: a 1 m box from 10 m at elasticity 0.8 under g = 10; apex n at 10 e^(2n) "
            "m. Error: the largest relative apex error over five bounces, each apex from the "
            "parabola through the last rising step.\n");
}

static const char *cheapest(const series_t series[INTEGRATOR_COUNT], double target,
                            double *seconds) {
    const char *best = "none";
    *seconds = INFINITY;
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        double t = time_to_reach(&series[i], target);
        if (t < *seconds) {
            *seconds = t;
            best = integrator_get_name((integrator_t)i);
        }
    }
    return best;
}

static void write_reading(FILE *md, const sweep_t *sweeps, int count,
                          series_t (*all)[INTEGRATOR_COUNT]) {
    fprintf(md, "\n## What to pick\n\n"
                "The cheapest integrator that reaches each error, read off the work-precision "
                "lines above (interpolated between step sizes; ms for the whole run):\n\n"
                "| scene | 1e-3 | 1e-6 | 1e-9 |\n|---|---|---|---|\n");
    for (int s = 0; s < count; s++) {
        fprintf(md, "| %s", reference_name(sweeps[s].scene));
        const double targets[3] = {1e-3, 1e-6, 1e-9};
        for (int t = 0; t < 3; t++) {
            double seconds;
            const char *best = cheapest(all[s], targets[t], &seconds);
            if (isinf(seconds)) {
                fprintf(md, " | none in the sweep");
            } else {
                fprintf(md, " | %s (%.3g ms)", best, seconds * 1e3);
            }
        }
        fprintf(md, " |\n");
    }
    fprintf(md,
            "\nHow to read it:\n\n"
            "- **Games and sandboxes with contacts** (bounce, stacks): the seed scheme, the "
            "default, follows gravity exactly and its bounces hit the exact apexes at any "
            "step; so do velocity Verlet, RK4 and symplectic4, at two to four force "
            "evaluations a step. The Euler schemes are first order in flight.\n"
            "- **Springs**: never the seed or explicit Euler schemes, which add energy at "
            "every step (by 1 + (wh)^2 / 2 and 1 + (wh)^2): symplectic Euler or velocity "
            "Verlet keep the energy bounded for wh < 2, and Verlet is second order for one "
            "more force evaluation.\n"
            "- **Orbits** (Newtonian gravity): a symplectic scheme keeps the angular momentum "
            "to round-off and the energy bounded over any number of orbits; the seed and Euler "
            "schemes drift (see the energy column). For accuracy below 1e-6, the fourth-order "
            "schemes are cheaper than Verlet despite four evaluations a step.\n"
            "- **RK4 on the orbits**: its plain slope reads about 4.5, its local slope falling "
            "from 4.8 at the largest steps to 4.0-4.2 at the smallest before round-off: a "
            "fifth-order term (the energy it dissipates at each close passage) weighs where "
            "the errors are measurable. The two-term fit separates it and finds 4; "
            "symplectic4 sits on its asymptote either way.\n"
            "- **Velocity-dependent forces** (drag): RK4 keeps its fourth order; symplectic4 "
            "falls to second order (its stages evaluate drag at predicted velocities, so the "
            "composition is no longer symmetric), and Verlet stays second order.\n");
}

/* What implicit Euler gives up, from the oscillator's sweep (omega = 2 pi,
 * period 1 s) beside symplectic Euler at the same step. */
static void write_implicit(FILE *md, const sweep_t *oscillator,
                           const series_t series[INTEGRATOR_COUNT]) {
    const point_t *implicit = &series[INTEGRATOR_IMPLICIT_EULER].points[4];
    const point_t *symplectic = &series[INTEGRATOR_SYMPLECTIC_EULER].points[4];
    double h = implicit->h, theta = 2.0 * M_PI * h, steps = 1.0 / h;
    double per_period = pow(1.0 + theta * theta, -steps);
    double over_run = pow(per_period, oscillator->periods);
    fprintf(md,
            "- **Stiff springs and drag**: implicit Euler is stable at every step on "
            "create_spring, create_spring_with_length and create_drag "
            "([stability.md](stability.md)), first order, one force evaluation a step and a "
            "linear solve over the springs. What it gives up is energy: every step divides a "
            "spring's by 1 + (omega h)^2. On the oscillator at h = %.4g s (%.0f steps a "
            "period) that is a factor %.4f a period, %.3g over the %g periods of the run; "
            "measured, its energy falls by %.3g (the largest drift column), where symplectic "
            "Euler's stays within %.3g of the start, and its error is %.3g against symplectic "
            "Euler's %.3g. On drag it is as accurate as the explicit Euler schemes and stable "
            "where they are not (gamma h / m > 2). Pick it when a spring or drag is too stiff "
            "for the step you want; otherwise a symplectic scheme keeps the energy.\n",
            h, steps, per_period, over_run, oscillator->periods, implicit->result.energy_drift,
            symplectic->result.energy_drift, implicit->result.error, symplectic->result.error);
}

int main(int argc, char **argv) {
    options_t options = {10, false, "docs/report", "docs/accuracy.md", NULL};
    for (int i = 1; i < argc; i++) {
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(argv[i], "--quick") == 0) {
            options.quick = true;
            options.runs = 1;
        } else if (strcmp(argv[i], "--runs") == 0 && value != NULL) {
            options.runs = atoi(argv[++i]);
        } else if (strcmp(argv[i], "--out") == 0 && value != NULL) {
            options.out_dir = argv[++i];
        } else if (strcmp(argv[i], "--doc") == 0 && value != NULL) {
            options.doc_path = argv[++i];
        } else if (strcmp(argv[i], "--solver") == 0 && value != NULL) {
            options.solver_csv = argv[++i];
        } else {
            fprintf(stderr,
                    "usage: %s [--runs N] [--quick] [--out DIR] [--doc FILE] [--solver CSV]\n",
                    argv[0]);
            return 2;
        }
    }
    if (options.runs < 1) {
        fprintf(stderr, "accuracy: --runs must be >= 1\n");
        return 2;
    }
    double kepler = reference_period(REFERENCE_KEPLER), orbit = reference_period(REFERENCE_ORBIT);
    sweep_t sweeps[] = {
        {REFERENCE_OSCILLATOR, 10.25, 1.0 / 30.0, 11, 0},
        {REFERENCE_KEPLER, 10.25, kepler / 64.0, 11, 3},
        {REFERENCE_ORBIT, 10.25, orbit / 64.0, 11, 3},
        {REFERENCE_DRAG, 5.0, 1.0 / 30.0, 11, 0},
        {REFERENCE_BOUNCE, 1.0, 1.0 / 15.0, 11, 0},
    };
    enum { SWEEPS = sizeof sweeps / sizeof sweeps[0] };
    static series_t all[SWEEPS][INTEGRATOR_COUNT];
    FILE *gp = open_output(options.out_dir, "plots.gp");
    fprintf(gp, "set terminal svg size 720,480 dynamic font 'sans,11'\n"
                "set logscale xy\nset grid\nset key outside right top\nset format y '%%.0e'\n");
    for (int s = 0; s < SWEEPS; s++) {
        if (options.quick) {
            sweeps[s].sizes = 5;
            sweeps[s].extra = 0;
        }
        run_sweep(&sweeps[s], &options, all[s]);
        write_sweep_data(&sweeps[s], all[s], options.out_dir);
        write_plots(gp, &sweeps[s], all[s]);
    }
    FILE *md = fopen(options.doc_path, "w");
    if (md == NULL) {
        fprintf(stderr, "accuracy: cannot write %s: %s\n", options.doc_path, strerror(errno));
        return 1;
    }
    write_intro(md, &options);
    fprintf(md, "\n## Error against run time, per scene\n");
    for (int s = 0; s < SWEEPS; s++) write_scene_section(md, &sweeps[s], all[s]);
    write_reading(md, sweeps, SWEEPS, all);
    write_implicit(md, &sweeps[0], all[0]);
    fprintf(stderr, "  collisions\n");
    write_collisions(md, options.out_dir);
    fprintf(gp, "set logscale x\n");
    write_solver(md, gp, &options);
    fprintf(md, "\n## Reproducing\n\n`make report` (about three minutes on two cores; installs "
                "gnuplot-nox when it can). The CSVs and plots are in docs/report/.\n");
    fclose(md);
    fclose(gp);
    return 0;
}
