/* What the parts of make report share: clocks, spreads, files, fits. */
#include <errno.h>
#include <math.h>
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
