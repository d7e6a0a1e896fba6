/*
 * The step-size sweeps: each case under each scheme at h = first_h / 2^k,
 * first diagnosed (untimed: error, drifts, evaluations, end state), then
 * timed in rounds (CPU time of the ticks alone, the schemes interleaved
 * at each step size), then the asymptotic window and its slope.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

/* Errors at or above FIT_HIGH are still in the start-up; a series whose
 * errors stop falling (two halvings each cutting them by less than
 * ROUND_OFF_DROP) below ROUND_OFF_BELOW, or that reaches LOWEST_ERROR, has
 * met round-off, and its errors below ROUND_OFF_FACTOR times its least are
 * left out of the fit. The fit window is the run of the rest that reaches
 * the smallest steps and whose per-halving slopes span at most
 * WINDOW_TOLERANCE (relative) of their median. */
static const double FIT_HIGH = 0.1, ROUND_OFF_BELOW = 1e-6, ROUND_OFF_DROP = 0.8;
static const double LOWEST_ERROR = 1e-14, ROUND_OFF_FACTOR = 1000.0, WINDOW_TOLERANCE = 0.1;
/* No run of more steps than this is made. */
static const long STEP_BUDGET = 1L << 18, QUICK_STEP_BUDGET = 1L << 12;
/* Runs of fewer steps do not count for the cost per step. */
static const long PER_STEP_MIN_STEPS = 100;

static double timed_cpu = 0.0, timed_wall = 0.0;

double report_timed_core_share(void);
double report_timed_core_share(void) {
    return timed_wall > 0.0 ? timed_cpu / timed_wall : NAN;
}

static bool usable(const report_point_t *p) {
    return !p->result.diverged && p->result.error > 0.0 && isfinite(p->result.error);
}

/* log2 of the error's fall from point k - 1 to point k (h halved). */
static double halving_slope(const report_series_t *s, int k) {
    return log2(s->points[k - 1].result.error / s->points[k].result.error);
}

static void diagnose_series(const report_case_t *c, integrator_t integrator, report_series_t *s,
                            long budget) {
    double h = c->first_h;
    memset(s, 0, sizeof *s);
    for (int k = 0; k < REPORT_MAX_POINTS; k++, h /= 2.0) {
        if (k > 0 && 2 * s->points[k - 1].result.steps > budget) break;
        report_point_t *p = &s->points[s->count++];
        p->h = h;
        p->result = c->diagnose(c, integrator, h);
        if (!usable(p)) {
            if (!p->result.diverged && p->result.error == 0.0) s->round_off = true;
            if (s->round_off) break;
            continue;
        }
        double error = p->result.error;
        if (error < LOWEST_ERROR) {
            s->round_off = true;
            break;
        }
        if (k >= 2 && error < ROUND_OFF_BELOW && usable(&s->points[k - 1]) &&
            usable(&s->points[k - 2]) &&
            error > ROUND_OFF_DROP * s->points[k - 1].result.error &&
            s->points[k - 1].result.error > ROUND_OFF_DROP * s->points[k - 2].result.error) {
            s->round_off = true;
            break;
        }
    }
}

static bool in_fit_range(const report_series_t *s, int k) {
    const report_point_t *p = &s->points[k];
    return usable(p) && p->result.error < FIT_HIGH && p->result.error > s->cut;
}

/* Whether the per-halving slopes over points [a, b] span at most
 * WINDOW_TOLERANCE of their median (a drifting slope is not asymptotic). */
static bool slopes_agree(const report_series_t *s, int a, int b) {
    double slopes[REPORT_MAX_POINTS];
    int n = 0;
    for (int k = a + 1; k <= b; k++) slopes[n++] = halving_slope(s, k);
    report_spread_t spread = report_spread(slopes, n);
    return spread.high - spread.low <= WINDOW_TOLERANCE * fmax(fabs(spread.median), 1.0);
}

/* The asymptotic window: the run of points in the fit range that ends at
 * the smallest step whose last two per-halving slopes agree, extended
 * towards larger steps while the slopes keep agreeing. */
static void choose_window(report_series_t *s) {
    s->first = s->last = -1;
    s->order = s->order_error = NAN;
    double least = INFINITY;
    for (int k = 0; k < s->count; k++) {
        if (usable(&s->points[k])) least = fmin(least, s->points[k].result.error);
    }
    s->cut = s->round_off && isfinite(least) ? ROUND_OFF_FACTOR * least : 0.0;
    for (int last = s->count - 1; last >= 2 && s->first < 0; last--) {
        if (!in_fit_range(s, last) || !in_fit_range(s, last - 1) ||
            !in_fit_range(s, last - 2) || !slopes_agree(s, last - 2, last)) {
            continue;
        }
        int first = last - 2;
        while (first > 0 && in_fit_range(s, first - 1) && slopes_agree(s, first - 1, last)) {
            first--;
        }
        s->first = first;
        s->last = last;
    }
    if (s->first < 0) return;
    double x[REPORT_MAX_POINTS], y[REPORT_MAX_POINTS];
    int n = 0;
    for (int k = s->first; k <= s->last; k++, n++) {
        x[n] = log(s->points[k].h);
        y[n] = log(s->points[k].result.error);
    }
    s->order = report_slope(x, y, n, &s->order_error);
}

/* One timed run: the scene built, ticked `steps` times (only this is
 * timed), and its end checked against the diagnosed run's. */
static double timed_run(const report_case_t *c, integrator_t integrator, const report_point_t *p) {
    void *run = c->build(c, integrator, p->h);
    scene_t *scene = c->scene(run);
    long steps = p->result.steps;
    double h = p->h, wall = report_wall_seconds(), start = report_cpu_seconds();
    for (long i = 0; i < steps; i++) scene_tick(scene, h);
    double seconds = report_cpu_seconds() - start;
    timed_wall += report_wall_seconds() - wall;
    timed_cpu += seconds;
    vector_t end = c->end_centroid(run);
    c->finish(run);
    if (memcmp(&end, &p->result.end_centroid, sizeof end) != 0) {
        fprintf(stderr,
                "accuracy: %s under %s at h = %g: the timed run ended at (%.17g, %.17g), the "
                "diagnosed run at (%.17g, %.17g): the diagnostics changed the run\n",
                c->name, integrator_get_name(integrator), h, end.x, end.y,
                p->result.end_centroid.x, p->result.end_centroid.y);
        exit(1);
    }
    return seconds;
}

static void summarize_times(report_series_t *s) {
    double per_step[REPORT_MAX_POINTS * REPORT_MAX_ROUNDS];
    int n = 0;
    long most_steps = 0;
    s->evaluations_per_step = NAN;
    for (int k = 0; k < s->count; k++) {
        report_point_t *p = &s->points[k];
        double copy[REPORT_MAX_ROUNDS];
        memcpy(copy, p->seconds, sizeof copy);
        p->time = report_spread(copy, p->timed);
        if (p->result.diverged) continue;
        if (p->result.steps > most_steps) {
            most_steps = p->result.steps;
            s->evaluations_per_step = (double)p->result.evaluations / (double)p->result.steps;
        }
        if (p->result.steps < PER_STEP_MIN_STEPS) continue;
        for (int r = 0; r < p->timed; r++) per_step[n++] = p->seconds[r] / (double)p->result.steps;
    }
    s->step_seconds = report_spread(per_step, n);
}

void report_run_sweeps(report_sweep_t *sweeps, int count, const report_options_t *options) {
    for (int c = 0; c < count; c++) {
        long budget = options->quick ? QUICK_STEP_BUDGET : STEP_BUDGET;
        if (sweeps[c].c->budget > 0 && sweeps[c].c->budget < budget) budget = sweeps[c].c->budget;
        for (int i = 0; i < INTEGRATOR_COUNT; i++) {
            fprintf(stderr, "\r  sweep %-12s %-18s", sweeps[c].c->name,
                    integrator_get_name((integrator_t)i));
            diagnose_series(sweeps[c].c, (integrator_t)i, &sweeps[c].series[i], budget);
            choose_window(&sweeps[c].series[i]);
        }
    }
    for (int r = 0; r < options->rounds; r++) {
        for (int c = 0; c < count; c++) {
            fprintf(stderr, "\r  timing round %d/%d %-12s      ", r + 1, options->rounds,
                    sweeps[c].c->name);
            for (int k = 0; k < REPORT_MAX_POINTS; k++) {
                for (int i = 0; i < INTEGRATOR_COUNT; i++) {
                    report_series_t *s = &sweeps[c].series[i];
                    if (k >= s->count || s->points[k].result.diverged) continue;
                    report_point_t *p = &s->points[k];
                    p->seconds[p->timed++] = timed_run(sweeps[c].c, (integrator_t)i, p);
                }
            }
        }
    }
    for (int c = 0; c < count; c++) {
        for (int i = 0; i < INTEGRATOR_COUNT; i++) summarize_times(&sweeps[c].series[i]);
    }
    fprintf(stderr, "\n");
}

double report_time_to_reach(const report_series_t *s, double target, char *bound) {
    *bound = 0;
    int previous = -1;
    for (int k = 0; k < s->count; k++) {
        const report_point_t *p = &s->points[k];
        if (!usable(p) || p->timed == 0) continue;
        if (p->result.error <= target) {
            if (previous < 0) {
                *bound = '<';
                return p->time.median;
            }
            const report_point_t *q = &s->points[previous];
            double f = log(target / q->result.error) / log(p->result.error / q->result.error);
            return exp(log(q->time.median) + f * (log(p->time.median) - log(q->time.median)));
        }
        previous = k;
    }
    if (previous < 0) return NAN;
    *bound = '>';
    return s->points[previous].time.median;
}

/* ---- Writing ---- */

void report_write_sweep_data(const report_sweep_t *sweep, const report_options_t *options) {
    const char *name = sweep->c->name;
    char file[256];
    snprintf(file, sizeof file, "%s.csv", name);
    FILE *csv = report_open(options->out_dir, file);
    fprintf(csv, "integrator,h,steps,evaluations,error,energy_drift,momentum_drift,diverged,"
                 "in_fit,cpu_s_median,cpu_s_min,cpu_s_max,timed_runs\n");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        const report_series_t *s = &sweep->series[i];
        snprintf(file, sizeof file, "%s-%d.dat", name, i);
        FILE *dat = report_open(options->out_dir, file);
        for (int k = 0; k < s->count; k++) {
            const report_point_t *p = &s->points[k];
            const reference_result_t *r = &p->result;
            bool in_fit = s->first >= 0 && k >= s->first && k <= s->last;
            fprintf(csv, "%s,%.10g,%ld,%ld,%.6e,%.6e,%.6e,%d,%d,%.4e,%.4e,%.4e,%d\n",
                    integrator_get_name((integrator_t)i), p->h, r->steps, r->evaluations,
                    r->error, r->energy_drift, r->momentum_drift, r->diverged, in_fit,
                    p->time.median, p->time.low, p->time.high, p->timed);
            /* gnuplot's log axes cannot show 0: round-off floors at 1e-17. */
            if (usable(p) || (!r->diverged && r->error == 0.0)) {
                fprintf(dat, "%.10g %.6e %.6e %.6e %.6e %ld %d\n", p->h, fmax(r->error, 1e-17),
                        p->time.median * 1e3, p->time.low * 1e3, p->time.high * 1e3,
                        r->evaluations, in_fit);
            }
        }
        fclose(dat);
    }
    fclose(csv);
}

static bool has_evaluations(const report_series_t *s) {
    for (int k = 0; k < s->count; k++) {
        if (s->points[k].result.evaluations > 0) return true;
    }
    return false;
}

static void write_plots(const report_sweep_t *sweep, FILE *gp, const report_options_t *options) {
    const char *name = sweep->c->name;
    char file[256];
    fprintf(gp, "set output 'work-%s.svg'\n", name);
    fprintf(gp, "set title \"%s: error against CPU time (median; bars: range)\"\n", name);
    fprintf(gp, "set xlabel 'CPU time of the run (ms)'\nset ylabel \"%s\"\n",
            sweep->c->error_name);
    report_plot_t plot = report_plot_start(gp);
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        snprintf(file, sizeof file, "%s-%d.dat", name, i);
        if (!report_has_data(options->out_dir, file)) continue;
        report_plot_add(&plot, "'%s' using 3:2:4:5 with xerrorlines lt %d title '%s'", file, i + 1,
                        integrator_get_name((integrator_t)i));
    }
    report_plot_end(&plot);
    bool any = false;
    for (int i = 0; i < INTEGRATOR_COUNT; i++) any |= has_evaluations(&sweep->series[i]);
    if (any) fprintf(gp, "set output 'evaluations-%s.svg'\n", name);
    fprintf(gp, "set title \"%s: error against force evaluations\"\n", name);
    fprintf(gp, "set xlabel 'force evaluations (passes over the force creators)'\n");
    plot = report_plot_start(any ? gp : NULL);
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        snprintf(file, sizeof file, "%s-%d.dat", name, i);
        if (!has_evaluations(&sweep->series[i]) || !report_has_data(options->out_dir, file)) {
            continue;
        }
        report_plot_add(&plot, "'%s' using ($6 > 0 ? $6 : 1/0):2 with linespoints lt %d title '%s'",
                        file, i + 1, integrator_get_name((integrator_t)i));
    }
    if (any) report_plot_end(&plot);
    fprintf(gp, "set output 'order-%s.svg'\n", name);
    fprintf(gp, "set title \"%s: error against h (filled: fit window)\"\n", name);
    fprintf(gp, "set xlabel 'step h (s)'\n");
    plot = report_plot_start(gp);
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        const report_series_t *s = &sweep->series[i];
        snprintf(file, sizeof file, "%s-%d.dat", name, i);
        if (!report_has_data(options->out_dir, file)) continue;
        char order[64] = "no window";
        if (s->first >= 0) snprintf(order, sizeof order, "slope %.2f", s->order);
        report_plot_add(&plot, "'%s' using 1:2 with linespoints lt %d pt 6 title '%s (%s)', "
                               "'%s' using 1:($7 > 0 ? $2 : 1/0) with points lt %d pt 7 notitle",
                        file, i + 1, integrator_get_name((integrator_t)i), order, file, i + 1);
    }
    report_plot_end(&plot);
}

static void write_slopes(const report_series_t *s, char *text, size_t size) {
    size_t used = 0;
    text[0] = 0;
    for (int k = 1; k < s->count && used + 16 < size; k++) {
        const char *separator = used ? " " : "";
        if (!usable(&s->points[k - 1]) || !usable(&s->points[k])) {
            used += (size_t)snprintf(text + used, size - used, "%s-", separator);
            continue;
        }
        bool fitted = s->first >= 0 && k > s->first && k <= s->last;
        used += (size_t)snprintf(text + used, size - used, fitted ? "%s**%.2f**" : "%s%.2f",
                                 separator, halving_slope(s, k));
    }
    if (used == 0) snprintf(text, size, "-");
}

static void write_reach(char *text, size_t size, const report_series_t *s, double target) {
    char bound;
    double seconds = report_time_to_reach(s, target, &bound);
    if (isnan(seconds)) {
        snprintf(text, size, "-");
    } else if (bound == '<') {
        snprintf(text, size, "< %.3g", seconds * 1e3);
    } else if (bound == '>') {
        snprintf(text, size, "not reached (> %.3g)", seconds * 1e3);
    } else {
        snprintf(text, size, "%.3g", seconds * 1e3);
    }
}

static void write_order(char *text, size_t size, const report_series_t *s) {
    bool all_round_off = s->count > 0;
    for (int k = 0; k < s->count; k++) {
        if (!s->points[k].result.diverged && s->points[k].result.error > 1e-12) {
            all_round_off = false;
        }
    }
    bool all_exact = s->count > 0;
    for (int k = 0; k < s->count; k++) {
        if (s->points[k].result.diverged || s->points[k].result.error != 0.0) all_exact = false;
    }
    if (all_exact) {
        snprintf(text, size, "exact (0) at every h");
    } else if (all_round_off) {
        snprintf(text, size, "round-off at every h");
    } else if (s->first < 0) {
        snprintf(text, size, "no window");
    } else {
        snprintf(text, size, "%.2f ± %.2f (%d points)", s->order, s->order_error,
                 s->last - s->first + 1);
    }
}

void report_write_sweep(const report_sweep_t *sweep, FILE *md, FILE *gp,
                        const report_options_t *options) {
    const report_case_t *c = sweep->c;
    report_write_sweep_data(sweep, options);
    write_plots(sweep, gp, options);
    bool evaluated = false;
    for (int i = 0; i < INTEGRATOR_COUNT; i++) evaluated |= has_evaluations(&sweep->series[i]);
    int common = 4;
    fprintf(md, "\n### %s\n\n%s.\n\n", c->name, c->title);
    fprintf(md, "![%s: work-precision](report/work-%s.svg)\n", c->name, c->name);
    if (evaluated) {
        fprintf(md, "![%s: error against force evaluations](report/evaluations-%s.svg)\n",
                c->name, c->name);
    }
    fprintf(md, "![%s: error against h](report/order-%s.svg)\n\n", c->name, c->name);
    long budget = options->quick ? QUICK_STEP_BUDGET : STEP_BUDGET;
    if (c->budget > 0 && c->budget < budget) budget = c->budget;
    fprintf(md, "Error: %s %s; h from %.4g s, halved until round-off or %ld steps a run. CSV: "
                "[report/%s.csv](report/%s.csv).\n\n",
            c->error_name, c->span, c->first_h, budget, c->name, c->name);
    fprintf(md, "| integrator | evaluations per step | CPU ns per step (range) | per-halving "
                "slopes, largest h first (**fit window**) | fitted order ± s.e. | error at h = "
                "%.4g | largest energy drift there | ms to reach 1e-3 | 1e-6 | 1e-9 |\n",
            c->first_h / (1 << common));
    fprintf(md, "|---|---|---|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        const report_series_t *s = &sweep->series[i];
        char slopes[512], order[64], error[32] = "-", energy[32] = "-", t3[40], t6[40], t9[40];
        char evaluations[32], cost[64];
        write_slopes(s, slopes, sizeof slopes);
        write_order(order, sizeof order, s);
        if (common < s->count) {
            const reference_result_t *r = &s->points[common].result;
            if (r->diverged) {
                snprintf(error, sizeof error, "diverged");
            } else {
                report_number(error, sizeof error, r->error);
                report_number(energy, sizeof energy, r->energy_drift);
            }
        }
        write_reach(t3, sizeof t3, s, 1e-3);
        write_reach(t6, sizeof t6, s, 1e-6);
        write_reach(t9, sizeof t9, s, 1e-9);
        report_number(evaluations, sizeof evaluations, s->evaluations_per_step);
        if (isnan(s->step_seconds.median)) {
            snprintf(cost, sizeof cost, "-");
        } else {
            snprintf(cost, sizeof cost, "%.0f (%.0f-%.0f)", s->step_seconds.median * 1e9,
                     s->step_seconds.low * 1e9, s->step_seconds.high * 1e9);
        }
        fprintf(md, "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
                integrator_get_name((integrator_t)i), evaluations, cost, slopes, order, error,
                energy, t3, t6, t9);
    }
    if (c->note != NULL) c->note(c, md);
}

void report_write_picks(const report_sweep_t *sweeps, int count, FILE *md) {
    const double targets[3] = {1e-3, 1e-6, 1e-9};
    fprintf(md, "| case | 1e-3 | 1e-6 | 1e-9 |\n|---|---|---|---|\n");
    for (int c = 0; c < count; c++) {
        fprintf(md, "| %s", sweeps[c].c->name);
        for (int t = 0; t < 3; t++) {
            double best = INFINITY;
            int winner = -1;
            char winner_bound = 0;
            for (int i = 0; i < INTEGRATOR_COUNT; i++) {
                char bound;
                double seconds = report_time_to_reach(&sweeps[c].series[i], targets[t], &bound);
                if (isnan(seconds) || bound == '>') continue;
                if (seconds < best) {
                    best = seconds;
                    winner = i;
                    winner_bound = bound;
                }
            }
            if (winner < 0) {
                fprintf(md, " | none in the sweep");
            } else {
                fprintf(md, " | %s (%s%.3g ms)", integrator_get_name((integrator_t)winner),
                        winner_bound == '<' ? "< " : "", best * 1e3);
            }
        }
        fprintf(md, " |\n");
    }
}
