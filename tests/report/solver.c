/*
 * The contact solver beside the peers (docs/accuracy.md, section 5), from
 * the result lines report.sh gathered with the benchmark programs of
 * tests/bench: pyramid(20) and column(10) per variant and velocity
 * iteration count, over rounds that alternate the programs. Each raw line
 * is "round=R iterations=N|default " and a program's result line; the
 * programs' '#' lines (every setting that differs from a peer's default)
 * are in the settings file beside it.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "report.h"

void report_write_solver(FILE *md, FILE *gp, const report_options_t *options);

enum { MAX_ROWS = 64, MAX_ROUNDS = 16 };

typedef struct {
    char variant[40];
    int iterations; /* 0: the variant's default */
    double pyramid_ms[MAX_ROUNDS], column_ms[MAX_ROUNDS];
    int pyramid_runs, column_runs;
    double top_drop, penetration, drift;
} row_t;

/* The value of key in a line of key=value words; NAN when absent. */
static double value_of(const char *line, const char *key) {
    char pattern[64];
    snprintf(pattern, sizeof pattern, " %s=", key);
    const char *at = strstr(line, pattern);
    if (at == NULL) return NAN;
    return strtod(at + strlen(pattern), NULL);
}

static bool word_of(const char *line, const char *key, char *out, size_t size) {
    char pattern[64];
    snprintf(pattern, sizeof pattern, " %s=", key);
    const char *at = strstr(line, pattern);
    if (at == NULL) return false;
    at += strlen(pattern);
    size_t n = strcspn(at, " \n");
    if (n >= size) n = size - 1;
    memcpy(out, at, n);
    out[n] = 0;
    return true;
}

static row_t *row_for(row_t *rows, int *count, const char *variant, int iterations) {
    for (int i = 0; i < *count; i++) {
        if (strcmp(rows[i].variant, variant) == 0 && rows[i].iterations == iterations) {
            return &rows[i];
        }
    }
    if (*count == MAX_ROWS) return NULL;
    row_t *row = &rows[(*count)++];
    memset(row, 0, sizeof *row);
    snprintf(row->variant, sizeof row->variant, "%s", variant);
    row->iterations = iterations;
    row->top_drop = row->penetration = row->drift = NAN;
    return row;
}

static int read_rows(const char *path, row_t *rows) {
    FILE *file = path != NULL ? fopen(path, "r") : NULL;
    if (file == NULL) return 0;
    char line[2048], padded[2100];
    int count = 0;
    while (fgets(line, sizeof line, file) != NULL) {
        snprintf(padded, sizeof padded, " %s", line);
        char variant[40], scene[32], iterations[16];
        if (!word_of(padded, "engine", variant, sizeof variant) ||
            !word_of(padded, "scene", scene, sizeof scene) ||
            !word_of(padded, "iterations", iterations, sizeof iterations)) {
            continue;
        }
        row_t *row = row_for(rows, &count, variant,
                             strcmp(iterations, "default") == 0 ? 0 : atoi(iterations));
        if (row == NULL) continue;
        double ms = value_of(padded, "median_ms");
        if (strcmp(scene, "pyramid") == 0 && row->pyramid_runs < MAX_ROUNDS) {
            row->pyramid_ms[row->pyramid_runs++] = ms;
            row->top_drop = value_of(padded, "top_drop");
            row->penetration = value_of(padded, "max_penetration");
        } else if (strcmp(scene, "column") == 0 && row->column_runs < MAX_ROUNDS) {
            row->column_ms[row->column_runs++] = ms;
            row->drift = value_of(padded, "top_drift");
        }
    }
    fclose(file);
    return count;
}

static void copy_settings(FILE *md, const report_options_t *options) {
    char path[1024];
    snprintf(path, sizeof path, "%s/solver-settings.txt", options->out_dir);
    FILE *file = fopen(path, "r");
    if (file == NULL) return;
    char line[2048];
    fprintf(md, "Every variant as its program describes it (each setting that differs from the "
                "peer's default is named):\n\n");
    while (fgets(line, sizeof line, file) != NULL) {
        line[strcspn(line, "\n")] = 0;
        if (line[0] == '#') fprintf(md, "- %s\n", line + 2);
    }
    fprintf(md, "\n");
    fclose(file);
}

static void write_plots(FILE *gp, const row_t *rows, int count, const report_options_t *options) {
    /* Each variant by the index of its first row. */
    int first[MAX_ROWS], distinct = 0;
    for (int i = 0; i < count; i++) {
        bool seen = false;
        for (int k = 0; k < distinct; k++) {
            seen |= strcmp(rows[first[k]].variant, rows[i].variant) == 0;
        }
        if (!seen) first[distinct++] = i;
    }
    for (int k = 0; k < distinct; k++) {
        const char *variant = rows[first[k]].variant;
        char name[96];
        snprintf(name, sizeof name, "solver-%s.dat", variant);
        FILE *dat = report_open(options->out_dir, name);
        for (int i = 0; i < count; i++) {
            const row_t *r = &rows[i];
            if (strcmp(r->variant, variant) != 0) continue;
            double p[MAX_ROUNDS], c[MAX_ROUNDS];
            memcpy(p, r->pyramid_ms, sizeof p);
            memcpy(c, r->column_ms, sizeof c);
            report_spread_t ps = report_spread(p, r->pyramid_runs);
            report_spread_t cs = report_spread(c, r->column_runs);
            fprintf(dat, "%d %.6g %.6g %.6g %.6e %.6e %.6g %.6g %.6g %.6e\n", r->iterations,
                    ps.median, ps.low, ps.high, fmax(fabs(r->top_drop), 1e-7),
                    fmax(r->penetration, 1e-7), cs.median, cs.low, cs.high,
                    fmax(fabs(r->drift), 1e-7));
        }
        fclose(dat);
    }
    const char *figures[3][3] = {{"top_drop", "5", "pyramid(20): |top box drop| after 10 s (m)"},
                                 {"penetration", "6", "pyramid(20): largest penetration (m)"},
                                 {"drift", "10", "column(10): |top box sideways drift| (m)"}};
    for (int f = 0; f < 3; f++) {
        int x = f == 2 ? 7 : 2;
        fprintf(gp, "set output 'solver-%s.svg'\n", figures[f][0]);
        fprintf(gp, "set title \"%s (labels: iterations, 0 = default)\"\n", figures[f][2]);
        fprintf(gp, "set xlabel 'CPU ms per step'\nset ylabel \"%s\"\n", figures[f][2]);
        report_plot_t plot = report_plot_start(gp);
        for (int k = 0; k < distinct; k++) {
            const char *v = rows[first[k]].variant;
            report_plot_add(&plot, "'solver-%s.dat' using %d:%s:%d:%d with xerrorlines title '%s', "
                                   "'solver-%s.dat' using %d:%s:1 with labels offset 1,0.6 "
                                   "notitle",
                            v, x, figures[f][1], x + 1, x + 2, v, v, x, figures[f][1]);
        }
        report_plot_end(&plot);
    }
}

void report_write_solver(FILE *md, FILE *gp, const report_options_t *options) {
    static row_t rows[MAX_ROWS];
    char path[1024];
    snprintf(path, sizeof path, "%s/solver-lines.txt", options->out_dir);
    int count = read_rows(options->solver_csv != NULL ? options->solver_csv : path, rows);
    fprintf(md, "\n## 5. The contact solver beside Chipmunk2D, Box2D 2.4 and Box2D v3\n\n");
    if (count == 0) {
        fprintf(md, "Not measured in this run (no result lines: `make report` gathers them with "
                    "the benchmark programs).\n");
        return;
    }
    write_plots(gp, rows, count, options);
    fprintf(md,
            "pyramid(20) and column(10) of [bench-scenes.md](bench-scenes.md), every engine "
            "through the benchmark programs of tests/bench, which build the same bodies for "
            "all. Each engine runs at its own defaults (iterations `default`) and, where it "
            "has the setting, at matched settings over velocity iteration counts 1 to 32 "
            "(this engine keeps its 4 position iterations; Box2D v3 has sub-steps, not "
            "iterations, and runs at its defaults only). Sleeping is off in every variant. "
            "Penetration is measured on the polygons the scene defines (Box2D 2.4's skins "
            "removed; bench-scenes.md says how for each engine). Time: CPU time of the step "
            "calls, ms per step, the median over the rounds (the programs alternate within "
            "each round) with the range. Raw lines: "
            "[report/solver-lines.txt](report/solver-lines.txt).\n\n");
    copy_settings(md, options);
    fprintf(md, "![pyramid drop](report/solver-top_drop.svg)\n"
                "![pyramid penetration](report/solver-penetration.svg)\n"
                "![column drift](report/solver-drift.svg)\n\n");
    fprintf(md, "| variant | iterations | pyramid(20) ms/step (range) | top drop (m) | largest "
                "penetration (m) | column(10) ms/step (range) | top drift (m) |\n"
                "|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < count; i++) {
        const row_t *r = &rows[i];
        double p[MAX_ROUNDS], c[MAX_ROUNDS];
        memcpy(p, r->pyramid_ms, sizeof p);
        memcpy(c, r->column_ms, sizeof c);
        report_spread_t ps = report_spread(p, r->pyramid_runs);
        report_spread_t cs = report_spread(c, r->column_runs);
        char iterations[16];
        if (r->iterations == 0) {
            snprintf(iterations, sizeof iterations, "default");
        } else {
            snprintf(iterations, sizeof iterations, "%d", r->iterations);
        }
        fprintf(md, "| %s | %s | %.3g (%.3g-%.3g) | %.3g | %.3g | %.3g (%.3g-%.3g) | %.3g |\n",
                r->variant, iterations, ps.median, ps.low, ps.high, r->top_drop, r->penetration,
                cs.median, cs.low, cs.high, r->drift);
    }
}
