/*
 * Long horizons: the oscillator over 10^6 periods, Kepler at e = 0.6 and
 * e = 0.9 over 10^5, under each scheme at a few steps per period. Each run
 * records, at checkpoints spaced evenly in log t, the largest energy and
 * angular momentum errors since the last checkpoint and the phase error
 * there; the growth of each is fitted as t^p. The runs are not timed (the
 * cost of reaching a horizon is its steps times the CPU time per step the
 * short sweeps measured), so they run on several threads.
 */
#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

enum { MAX_RATES = 6, MAX_CHECKPOINTS = 80, PER_DECADE = 10 };

/* A quick run's budget of steps per run; a full run's is the scene's
 * (the finer step sizes stop short of the longest horizon). */
static const long QUICK_LONG_BUDGET = 1L << 14;
/* Errors at or above these have saturated (the phase error of an orbit
 * cannot pass 2 (1 + e) semi-major axes): the growth fit stops there. */
static const double SATURATED = 0.3;
/* The growth fit starts here (periods), past the first orbits. */
static const double FIT_FROM = 10.0;

typedef struct {
    reference_scene_t scene;
    double periods;            /* the longest horizon */
    int rates;
    double steps_per_period[MAX_RATES];
    int shown;                 /* the rate the growth plots show */
    double horizons[3];        /* of the work-precision diagrams */
    long budget;               /* steps a run may take */
} horizon_scene_t;

typedef struct {
    double periods, energy, momentum, position, error;
} checkpoint_t;

typedef struct {
    const horizon_scene_t *hs;
    integrator_t integrator;
    int rate;
    double h;
    long budget;
    checkpoint_t checkpoints[MAX_CHECKPOINTS];
    int count;
    bool diverged;
    double reached; /* periods */
} horizon_run_t;

static void run_one(horizon_run_t *run) {
    const horizon_scene_t *hs = run->hs;
    double period = reference_period(hs->scene);
    run->h = period / run->hs->steps_per_period[run->rate];
    reference_sim_t *sim = reference_start(hs->scene, run->integrator, run->h);
    scene_t *scene = reference_get_scene(sim);
    long done = 0;
    double energy = 0.0, momentum = 0.0;
    bool momentum_conserved = false;
    for (int c = 0; c < MAX_CHECKPOINTS; c++) {
        double periods = pow(10.0, (double)c / PER_DECADE);
        if (periods > hs->periods * (1.0 + 1e-9)) break;
        long target = reference_steps(hs->scene, run->h, periods);
        if (target > run->budget) break;
        for (; done < target; done++) {
            scene_tick(scene, run->h);
            double e, l;
            reference_invariants(sim, &e, &l);
            if (!(fabs(e) < 1e6)) {
                run->diverged = true;
                break;
            }
            energy = fmax(energy, fabs(e));
            if (!isnan(l)) {
                momentum = fmax(momentum, fabs(l));
                momentum_conserved = true;
            }
        }
        if (run->diverged) break;
        reference_state_t state = reference_measure(sim, (double)done * run->h);
        run->checkpoints[run->count++] = (checkpoint_t){
            periods, energy, momentum_conserved ? momentum : NAN, state.position_error,
            state.error};
        run->reached = periods;
        energy = momentum = 0.0;
    }
    reference_finish(sim);
}

typedef struct {
    horizon_run_t *runs;
    int count;
    atomic_int next;
} pool_t;

static void *worker(void *context) {
    pool_t *pool = context;
    for (;;) {
        int i = atomic_fetch_add(&pool->next, 1);
        if (i >= pool->count) return NULL;
        run_one(&pool->runs[i]);
        fprintf(stderr, "\r  long runs %d/%d   ", i + 1, pool->count);
    }
}

static void run_all(horizon_run_t *runs, int count, int threads) {
    pool_t pool = {runs, count, 0};
    pthread_t ids[16];
    if (threads > 16) threads = 16;
    for (int t = 1; t < threads; t++) pthread_create(&ids[t], NULL, worker, &pool);
    worker(&pool);
    for (int t = 1; t < threads; t++) pthread_join(ids[t], NULL);
    fprintf(stderr, "\n");
}

/* The exponent p of y ~ t^p over the checkpoints from FIT_FROM periods
 * until y saturates; NAN with fewer than four. */
static double growth(const horizon_run_t *run, int quantity, double *standard_error) {
    double x[MAX_CHECKPOINTS], y[MAX_CHECKPOINTS];
    int n = 0;
    for (int c = 0; c < run->count; c++) {
        const checkpoint_t *p = &run->checkpoints[c];
        double value = quantity == 0 ? p->energy : quantity == 1 ? p->momentum : p->position;
        if (isnan(value) || p->periods < FIT_FROM) continue;
        if (value >= SATURATED) break;
        x[n] = log(p->periods);
        y[n++] = log(fmax(value, 1e-17));
    }
    *standard_error = NAN;
    if (n < 4) return NAN;
    return report_slope(x, y, n, standard_error);
}

static const char *growth_word(double p) {
    if (isnan(p)) return "";
    if (fabs(p) < 0.25) return "bounded";
    if (fabs(p - 0.5) < 0.2) return "~t^1/2";
    if (fabs(p - 1.0) < 0.25) return "~t";
    if (fabs(p - 2.0) < 0.3) return "~t^2";
    return "";
}

static const report_series_t *sweep_series(const report_sweep_t *sweeps, int count,
                                           reference_scene_t scene, integrator_t integrator) {
    for (int c = 0; c < count; c++) {
        if (strcmp(sweeps[c].c->name, reference_name(scene)) == 0) {
            return &sweeps[c].series[integrator];
        }
    }
    return NULL;
}

static void write_data(const horizon_scene_t *hs, const horizon_run_t *runs, int count,
                       const report_options_t *options, bool plot_files) {
    const char *name = reference_name(hs->scene);
    char file[256];
    snprintf(file, sizeof file, "horizon-%s.csv", name);
    FILE *csv = report_open(options->out_dir, file);
    fprintf(csv, "integrator,steps_per_period,periods,energy_max,momentum_max,position_error,"
                 "error\n");
    for (int r = 0; r < count; r++) {
        const horizon_run_t *run = &runs[r];
        if (run->hs != hs) continue;
        snprintf(file, sizeof file, "horizon-%s-%d-%d.dat", name, (int)run->integrator, run->rate);
        FILE *dat = plot_files ? report_open(options->out_dir, file) : NULL;
        for (int c = 0; c < run->count; c++) {
            const checkpoint_t *p = &run->checkpoints[c];
            fprintf(csv, "%s,%g,%.6g,%.6e,%.6e,%.6e,%.6e\n",
                    integrator_get_name(run->integrator), hs->steps_per_period[run->rate],
                    p->periods, p->energy, p->momentum, p->position, p->error);
            if (dat == NULL) continue;
            fprintf(dat, "%.6g %.6e %.6e %.6e %.6e\n", p->periods, fmax(p->energy, 1e-17),
                    isnan(p->momentum) ? 1e-17 : fmax(p->momentum, 1e-17),
                    fmax(p->position, 1e-17), fmax(p->error, 1e-17));
        }
        if (dat != NULL) fclose(dat);
    }
    fclose(csv);
}

/* The error at a horizon of every run that reached it, against its cost. */
static void write_precision_data(const horizon_scene_t *hs, const horizon_run_t *runs, int count,
                                 const report_sweep_t *sweeps, int sweep_count,
                                 const report_options_t *options) {
    const char *name = reference_name(hs->scene);
    for (int k = 0; k < 3; k++) {
        for (int i = 0; i < INTEGRATOR_COUNT; i++) {
            char file[256];
            snprintf(file, sizeof file, "precision-%s-%d-%d.dat", name, k, i);
            FILE *dat = report_open(options->out_dir, file);
            const report_series_t *series =
                sweep_series(sweeps, sweep_count, hs->scene, (integrator_t)i);
            for (int r = 0; r < count; r++) {
                const horizon_run_t *run = &runs[r];
                if (run->hs != hs || run->integrator != (integrator_t)i) continue;
                for (int c = 0; c < run->count; c++) {
                    const checkpoint_t *p = &run->checkpoints[c];
                    if (fabs(p->periods / hs->horizons[k] - 1.0) > 1e-9) continue;
                    double steps = (double)reference_steps(hs->scene, run->h, p->periods);
                    report_spread_t per_step = series != NULL ? series->step_seconds
                                                              : (report_spread_t){NAN, NAN, NAN};
                    fprintf(dat, "%.6e %.6e %.6e %.6e %g\n", fmax(p->error, 1e-17),
                            steps * per_step.median * 1e3, steps * per_step.low * 1e3,
                            steps * per_step.high * 1e3, hs->steps_per_period[run->rate]);
                }
            }
            fclose(dat);
        }
    }
}

static void write_plots(const horizon_scene_t *hs, FILE *gp, const char *out_dir) {
    const char *name = reference_name(hs->scene);
    const char *quantities[3] = {"largest |E/E0 - 1| since the last point",
                                 "largest |L/L0 - 1| since the last point",
                                 "phase (position) error / semi-major axis"};
    int shown = hs->scene == REFERENCE_OSCILLATOR ? 2 : 3;
    fprintf(gp, "set output 'growth-%s.svg'\nset terminal svg size 1200,440 dynamic font "
                "'sans,10'\nset multiplot layout 1,%d title \"%s: errors against time at %g "
                "steps per period\"\nset xlabel 'periods'\n",
            name, shown, name, hs->steps_per_period[hs->shown]);
    for (int q = 0; q < 3; q++) {
        if (q == 1 && hs->scene == REFERENCE_OSCILLATOR) continue;
        fprintf(gp, "set title \"%s\"\nset ylabel ''\n%s\n", quantities[q],
                q == 2 ? "set key outside below horizontal maxrows 2" : "unset key");
        report_plot_t plot = report_plot_start(gp);
        for (int i = 0; i < INTEGRATOR_COUNT; i++) {
            char file[128];
            snprintf(file, sizeof file, "horizon-%s-%d-%d.dat", name, i, hs->shown);
            if (!report_has_data(out_dir, file)) continue;
            report_plot_add(&plot, "'%s' using 1:%d with lines lt %d lw 1.5 title '%s'", file,
                            q + 2, i + 1, integrator_get_name((integrator_t)i));
        }
        report_plot_end(&plot);
    }
    fprintf(gp, "unset multiplot\n");
    fprintf(gp, "set output 'precision-%s.svg'\nset multiplot layout 1,3 title \"%s: error at "
                "a horizon against the CPU time to reach it (one point per step size)\"\n"
                "set xlabel 'CPU ms (steps x median per step)'\nunset key\n",
            name, name);
    for (int k = 0; k < 3; k++) {
        fprintf(gp, "set title '%g periods'\n%s\n", hs->horizons[k],
                k == 2 ? "set key outside below horizontal maxrows 2" : "unset key");
        report_plot_t plot = report_plot_start(gp);
        for (int i = 0; i < INTEGRATOR_COUNT; i++) {
            char file[128];
            snprintf(file, sizeof file, "precision-%s-%d-%d.dat", name, k, i);
            if (!report_has_data(out_dir, file)) continue;
            report_plot_add(&plot, "'%s' using 2:1:3:4 with xerrorlines lt %d title '%s'", file,
                            i + 1, integrator_get_name((integrator_t)i));
        }
        report_plot_end(&plot);
    }
    fprintf(gp, "unset multiplot\nset terminal svg size 760,500 dynamic font 'sans,11'\n"
                "set key outside right top\n");
}

static void write_growth_cell(FILE *md, const horizon_run_t *run, int quantity) {
    double error, p = growth(run, quantity, &error);
    if (isnan(p)) {
        fprintf(md, " | -");
    } else {
        fprintf(md, " | %.2f ± %.2f %s", p, error, growth_word(p));
    }
}

static void write_section(const horizon_scene_t *hs, const horizon_run_t *runs, int count,
                          FILE *md) {
    const char *name = reference_name(hs->scene);
    bool orbit = hs->scene != REFERENCE_OSCILLATOR;
    fprintf(md, "\n### %s over %g periods\n\n", name, hs->periods);
    fprintf(md, "![%s: errors against time](report/growth-%s.svg)\n", name, name);
    fprintf(md, "![%s: work-precision at three horizons](report/precision-%s.svg)\n\n", name,
            name);
    fprintf(md, "Budget: %ld steps a run. Steps per period: ", hs->budget);
    for (int r = 0; r < hs->rates; r++) fprintf(md, "%s%g", r ? ", " : "", hs->steps_per_period[r]);
    fprintf(md, ". CSV: [report/horizon-%s.csv](report/horizon-%s.csv).\n\n", name, name);
    fprintf(md, "| integrator | steps per period | periods reached | growth of |E/E0 - 1|%s | "
                "growth of the phase error | phase error at the end |\n",
            orbit ? " | growth of |L/L0 - 1|" : "");
    fprintf(md, "|---|---|---|---|%s---|---|\n", orbit ? "---|" : "");
    for (int r = 0; r < count; r++) {
        const horizon_run_t *run = &runs[r];
        if (run->hs != hs) continue;
        fprintf(md, "| %s | %g | %s%g", integrator_get_name(run->integrator),
                hs->steps_per_period[run->rate], run->diverged ? "diverged after " : "",
                run->reached);
        write_growth_cell(md, run, 0);
        if (orbit) write_growth_cell(md, run, 1);
        write_growth_cell(md, run, 2);
        double end = run->count > 0 ? run->checkpoints[run->count - 1].position : NAN;
        char text[32];
        fprintf(md, " | %s |\n", report_number(text, sizeof text, end));
    }
}

void report_run_horizons(const report_sweep_t *sweeps, int count, FILE *md, FILE *gp,
                         const report_options_t *options, report_summary_t *summary) {
    horizon_scene_t scenes[3] = {
        {REFERENCE_OSCILLATOR, 1e6, 3, {8, 16, 32}, 0, {10, 1e3, 1e5}, 8000000},
        {REFERENCE_KEPLER, 1e5, 4, {16, 32, 64, 128}, 2, {10, 1e3, 1e5}, 6400000},
        {REFERENCE_KEPLER_ECCENTRIC, 1e5, 4, {32, 64, 128, 256}, 1, {10, 1e3, 1e5}, 6400000},
    };
    for (int s = 0; s < 3 && (options->quick || options->reproduce); s++) {
        scenes[s].periods = options->quick ? 100 : 1000;
        scenes[s].horizons[0] = 1;
        scenes[s].horizons[1] = 10;
        scenes[s].horizons[2] = 100;
    }
    static horizon_run_t runs[3 * INTEGRATOR_COUNT * MAX_RATES];
    int n = 0;
    for (int s = 0; s < 3; s++) {
        /* The costliest first, so that the threads finish together. */
        for (int r = scenes[s].rates - 1; r >= 0; r--) {
            for (int i = 0; i < INTEGRATOR_COUNT; i++) {
                memset(&runs[n], 0, sizeof runs[n]);
                runs[n].hs = &scenes[s];
                runs[n].integrator = (integrator_t)i;
                runs[n].rate = r;
                runs[n].budget = options->quick ? QUICK_LONG_BUDGET : scenes[s].budget;
                n++;
            }
        }
    }
    run_all(runs, n, options->threads);
    /* The summary: Kepler's energy at the rate the plots show, its phase at
     * the finest rate (the phase error saturates early at the coarser). */
    for (int r = 0; r < n && summary != NULL; r++) {
        const horizon_run_t *run = &runs[r];
        if (run->hs->scene != REFERENCE_KEPLER) continue;
        double error;
        report_summary_t *s = &summary[run->integrator];
        if (run->rate == run->hs->shown) {
            s->energy_growth = growth(run, 0, &error);
            s->growth_rate = run->hs->steps_per_period[run->rate];
        }
        if (run->rate == run->hs->rates - 1) {
            s->phase_growth = growth(run, 2, &error);
            s->phase_rate = run->hs->steps_per_period[run->rate];
        }
    }
    if (options->reproduce) {
        for (int s = 0; s < 3; s++) write_data(&scenes[s], runs, n, options, false);
        return;
    }
    fprintf(md, "\n## 2. Long horizons\n\n"
                "Each scheme runs each scene at a few steps per period, each run until the "
                "scene's horizon or the scene's budget of steps (the steps the coarsest rate "
                "takes to the horizon). At checkpoints %d to a decade of time the run "
                "records the largest energy error and angular momentum error since the last "
                "checkpoint (checked after every step) and the phase error there (the distance "
                "to the exact position over the amplitude or semi-major axis: it saturates near "
                "2 (1 + e) while the orbit stays bound, and grows without bound once it is "
                "lost). The growth of each is the least-squares slope p of log error "
                "on log t from %g periods on, until the error reaches %g: p near 0 is bounded, "
                "near 1 linear (t), near 2 quadratic (t^2); ± its standard error. The "
                "work-precision diagrams take the error (in phase space, as in section 1) of "
                "every run that reached each horizon, against the CPU time to reach it: its "
                "steps times the median CPU time per step of the same scheme on the same scene "
                "in section 1 (bars: the least and largest per step there). These runs are "
                "not timed themselves.\n",
            PER_DECADE, FIT_FROM, SATURATED);
    for (int s = 0; s < 3; s++) {
        write_data(&scenes[s], runs, n, options, true);
        write_precision_data(&scenes[s], runs, n, sweeps, count, options);
        write_plots(&scenes[s], gp, options->out_dir);
        write_section(&scenes[s], runs, n, md);
    }
}
