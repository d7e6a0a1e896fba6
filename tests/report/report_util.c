/* What the parts of make report share: clocks, spreads, files, fits. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "report.h"

double report_cpu_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double report_wall_seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int compare_doubles(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

report_spread_t report_spread(double *values, int n) {
    if (n <= 0) return (report_spread_t){NAN, NAN, NAN};
    qsort(values, (size_t)n, sizeof(double), compare_doubles);
    double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return (report_spread_t){median, values[0], values[n - 1]};
}

FILE *report_open(const char *dir, const char *name) {
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *file = fopen(path, "w");
    if (file == NULL) {
        fprintf(stderr, "accuracy: cannot write %s: %s\n", path, strerror(errno));
        exit(1);
    }
    return file;
}

const char *report_number(char *text, size_t size, double value) {
    if (isnan(value)) {
        snprintf(text, size, "-");
    } else {
        snprintf(text, size, "%.3g", value);
    }
    return text;
}

double report_slope(const double *x, const double *y, int n, double *standard_error) {
    *standard_error = NAN;
    if (n < 3) return NAN;
    double mx = 0, my = 0;
    for (int i = 0; i < n; i++) mx += x[i], my += y[i];
    mx /= n;
    my /= n;
    double sxx = 0, sxy = 0;
    for (int i = 0; i < n; i++) sxx += (x[i] - mx) * (x[i] - mx), sxy += (x[i] - mx) * (y[i] - my);
    double slope = sxy / sxx, residual = 0;
    for (int i = 0; i < n; i++) {
        double r = y[i] - my - slope * (x[i] - mx);
        residual += r * r;
    }
    *standard_error = sqrt(residual / (n - 2) / sxx);
    return slope;
}

bool report_has_data(const char *dir, const char *name) {
    char path[1024], line[256];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *file = fopen(path, "r");
    if (file == NULL) return false;
    bool found = false;
    while (!found && fgets(line, sizeof line, file) != NULL) found = line[0] != '\n';
    fclose(file);
    return found;
}

report_plot_t report_plot_start(FILE *gp) {
    return (report_plot_t){gp, 0};
}

void report_plot_add(report_plot_t *plot, const char *format, ...) {
    if (plot->gp == NULL) return;
    fputs(plot->clauses++ ? ", " : "plot ", plot->gp);
    va_list args;
    va_start(args, format);
    vfprintf(plot->gp, format, args);
    va_end(args);
}

void report_plot_end(report_plot_t *plot) {
    if (plot->clauses == 0) {
        fputs("set xrange [1:10]\nset yrange [1:10]\nplot 1/0 title 'no data'\n"
              "set autoscale x\nset autoscale y\n",
              plot->gp);
        return;
    }
    fputs("\n", plot->gp);
}
