#ifndef REPORT_H
#define REPORT_H

/*
 * make report (docs/accuracy.md): what its parts share. accuracy.c runs
 * them in order: the step-size sweeps of the cases with exact answers
 * (sweep.c; the free-motion cases of tests/reference.c and the contact
 * cases of contact_cases.c), the long horizons (horizons.c) and the
 * stability regions (regions.c), each writing its CSVs and gnuplot lines
 * under the output directory and its section of the page.
 *
 * Every integrator below INTEGRATOR_COUNT is run: a scheme added to scene.h
 * appears in every table and plot without a change here.
 */

#include <stdbool.h>
#include <stdio.h>
#include "jostle/jostle.h"
#include "reference.h"

enum {
    REPORT_MAX_POINTS = 24,
    REPORT_MAX_ROUNDS = 15,
    REPORT_MAX_CASES = 16,
};

typedef struct {
    bool quick;        /* fewer step sizes, rounds and periods: a smoke run */
    int rounds;        /* timed runs of every point, interleaved */
    const char *out_dir;
    const char *doc_path;
    const char *solver_csv; /* the peers' result lines (solver.c) */
    int threads;       /* for the untimed long runs */
    const char *only;  /* the one case to sweep, or NULL */
    /* Only the figures make check reproduces (no timing, no page): the
     * diagnosed sweeps of some cases, the long runs to 1000 periods, the
     * stability limits, as CSVs. */
    bool reproduce;
} report_options_t;

/* CPU time of the process (s), CLOCK_PROCESS_CPUTIME_ID. */
double report_cpu_seconds(void);
/* Wall-clock time (s), for the share of a core the timed runs got. */
double report_wall_seconds(void);

/* The median, least and largest of n values (sorted in place); NAN for
 * n = 0. */
typedef struct {
    double median, low, high;
} report_spread_t;
report_spread_t report_spread(double *values, int n);

/* Opens dir/name for writing or stops the program. */
FILE *report_open(const char *dir, const char *name);

/* "%.3g", or "-" for NAN. */
const char *report_number(char *text, size_t size, double value);

/* The least-squares slope of y on x and its standard error (NAN for fewer
 * than three points). */
double report_slope(const double *x, const double *y, int n, double *standard_error);

/* Whether dir/name exists and holds at least one data line. */
bool report_has_data(const char *dir, const char *name);

/* One gnuplot plot command built clause by clause: a plot with no clause
 * (no data) draws an empty frame saying so instead of stopping gnuplot. */
typedef struct {
    FILE *gp;
    int clauses;
} report_plot_t;
report_plot_t report_plot_start(FILE *gp);
void report_plot_add(report_plot_t *plot, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
void report_plot_end(report_plot_t *plot);

/* A scene with an exact answer, run at step h under an integrator. */
typedef struct report_case report_case_t;
struct report_case {
    const char *name;       /* in file names and headings */
    const char *title;      /* what the scene is and its exact answer, for the page */
    const char *error_name; /* what the error measures */
    char span[96];          /* over what time, for the page */
    double first_h;         /* the sweep's largest step (s) */
    int which;              /* the reference scene or contact case */
    double periods;         /* for the reference scenes */
    long budget;            /* steps a run may take; 0: the sweep's default */
    /* The run with every diagnostic, untimed: the error, drifts, steps and
     * evaluations, the end state. */
    reference_result_t (*diagnose)(const report_case_t *c, integrator_t integrator, double h);
    /* The timed run's parts: the scene built (untimed), then ticked
     * result.steps times at h (timed), then its end checked (untimed). */
    void *(*build)(const report_case_t *c, integrator_t integrator, double h);
    scene_t *(*scene)(void *run);
    vector_t (*end_centroid)(void *run);
    void (*finish)(void *run);
    /* More lines for the case's section, or NULL. */
    void (*note)(const report_case_t *c, FILE *md);
};

/* The cases of tests/reference.c: oscillator, kepler, kepler09, orbit,
 * drag, bounce. Returns the count written. */
int report_reference_cases(report_case_t *cases, int capacity, bool quick);

/* The contact cases (contact_cases.c). */
int report_contact_cases(report_case_t *cases, int capacity, bool quick);

/* One step size of a sweep. */
typedef struct {
    double h;
    reference_result_t result;
    double seconds[REPORT_MAX_ROUNDS]; /* CPU time of each timed run */
    int timed;
    report_spread_t time; /* of the timed runs (s) */
} report_point_t;

/* One scheme's sweep of one case. */
typedef struct {
    report_point_t points[REPORT_MAX_POINTS];
    int count;
    bool round_off;   /* the errors stopped falling below 1e-6: round-off */
    double cut;       /* errors below this are left out of the fit */
    int first, last;  /* the asymptotic window [first, last]; first < 0: none */
    double order, order_error; /* least-squares slope over it, standard error */
    /* Per step over the timed runs of at least 100 steps: CPU time (s) and
     * force evaluations. */
    report_spread_t step_seconds;
    double evaluations_per_step;
} report_series_t;

/* A case swept under every scheme. */
typedef struct {
    const report_case_t *c;
    report_series_t series[INTEGRATOR_COUNT];
} report_sweep_t;

/* Runs the diagnosed sweeps of `count` cases, then options->rounds timed
 * rounds over all their points, the schemes interleaved at each step size. */
void report_run_sweeps(report_sweep_t *sweeps, int count, const report_options_t *options);

/* The CPU time to reach `target` error: interpolated (log-log) between the
 * last point above it and the first at or below it; *bound is '<' when the
 * first point already reaches it (the time is an upper bound), '>' when no
 * point does (the time of the last point, a lower bound), 0 otherwise. */
double report_time_to_reach(const report_series_t *series, double target, char *bound);

/* The sweep's CSV alone. */
void report_write_sweep_data(const report_sweep_t *sweep, const report_options_t *options);

/* The sweep's CSV and plot lines, and its section of the page. */
void report_write_sweep(const report_sweep_t *sweep, FILE *md, FILE *gp,
                        const report_options_t *options);
/* The table of the cheapest scheme per error, over the sweeps. */
void report_write_picks(const report_sweep_t *sweeps, int count, FILE *md);

/* Head-on collisions against the exact velocities (collisions.c). */
void report_write_collisions(FILE *md, const report_options_t *options);

/* What the page's summary takes from the sections, per scheme. */
typedef struct {
    double spring_limit, drag_limit;      /* closed forms (NAN: none) */
    double energy_growth, phase_growth;   /* kepler's long runs */
    double growth_rate, phase_rate;       /* their steps per period */
} report_summary_t;

/* Long horizons (horizons.c): needs the sweeps of the same scenes for the
 * CPU time per step. With options->reproduce, only the CSVs, to 1000
 * periods. */
void report_run_horizons(const report_sweep_t *sweeps, int count, FILE *md, FILE *gp,
                         const report_options_t *options, report_summary_t *summary);

/* Stability regions (regions.c): regions.csv, and with md and gp not NULL
 * the plot and the section. report_check_regions prints PASS/FAIL lines
 * and returns the failures. */
void report_write_regions(FILE *md, FILE *gp, const report_options_t *options,
                          report_summary_t *summary);
int report_check_regions(void);

#endif // #ifndef REPORT_H
