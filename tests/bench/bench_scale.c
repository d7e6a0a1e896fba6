/*
 * How this engine's cost grows with the pile (docs/bench-scenes.md, pile(N))
 * from 1000 to 40000 bodies: ms per step, contact points per step, ms per
 * contact point, their fitted exponents, and bytes of heap per body and per
 * contact. Writes a markdown table to stdout (tests/bench/scale.sh puts it
 * in docs/scale.md beside the peers' ms per step).
 *
 * The pile is bench_scenes.h's own pile_run, through this engine's ops with
 * the step wrapped to read the step's counters; the heap is glibc's
 * mallinfo2, read before the bodies are added, before the first step and
 * after the last.
 */
#include <malloc.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bench_common.h"
#include "bench_scenes.h"
#include "bench_ours.h"

typedef struct {
    double contact_points; /* summed over the run's steps */
    size_t last_contacts;  /* manifolds of the last step */
    int steps;
    size_t heap_empty, heap_built, heap_end;
} scale_probe_t;

static scale_probe_t probe;
static int probe_outside;

/* Bytes handed out by malloc: from the heap and, for large blocks, mapped
 * on their own. */
static size_t heap_in_use(void) {
    struct mallinfo2 info = mallinfo2();
    return info.uordblks + info.hblkhd;
}

static void *scale_world_new(double gy, int contacts, int capacity) {
    probe.heap_empty = heap_in_use();
    return ours_world_new(gy, contacts, capacity);
}

static void scale_step(void *world, double dt) {
    ours_world_t *w = (ours_world_t *)world;
    if (probe.steps == 0) probe.heap_built = heap_in_use();
    ours_step(world, dt);
    scene_stats_t stats = scene_get_stats(w->scene);
    probe.contact_points += (double)stats.contact_points;
    probe.last_contacts = stats.contacts;
    probe.steps++;
    probe.heap_end = heap_in_use();
}

typedef struct {
    int bodies;
    double ms, points, bytes_per_body, bytes_per_contact;
    int outside; /* bodies outside the container at the end (pile_run's figure) */
} scale_row_t;

static int compare_doubles(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median over `runs` runs of the pile's mean ms per step, with the
 * last run's counters. */
static scale_row_t measure(int bodies, int runs) {
    bench_ops_t ops = ours_ops;
    ops.world_new = scale_world_new;
    ops.step = scale_step;
    bench_case_t c = {SCENE_PILE, (double)bodies, BENCH_DT};
    double ms[16];
    for (int r = 0; r < runs; r++) {
        memset(&probe, 0, sizeof probe);
        bench_run_t run;
        pile_run(&ops, &c, &run);
        ms[r] = run.step_ms;
        const char *outside = strstr(run.quality, "outside=");
        probe_outside = outside != NULL ? atoi(outside + strlen("outside=")) : -1;
        fprintf(stderr, "\r  pile(%d) run %d/%d: %.3f ms/step   ", bodies, r + 1, runs, ms[r]);
    }
    qsort(ms, (size_t)runs, sizeof(double), compare_doubles);
    scale_row_t row = {bodies, ms[runs / 2], probe.contact_points / probe.steps, 0.0, 0.0,
                       probe_outside};
    row.bytes_per_body = (double)(probe.heap_built - probe.heap_empty) / bodies;
    row.bytes_per_contact =
        probe.last_contacts > 0 ? (double)(probe.heap_end - probe.heap_built) / probe.last_contacts
                                : 0.0;
    return row;
}

/* The least-squares slope of log y against log x. */
static double fitted_exponent(const double *x, const double *y, int count) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int i = 0; i < count; i++) {
        double lx = log(x[i]), ly = log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    return (count * sxy - sx * sy) / (count * sxx - sx * sx);
}

int main(int argc, char **argv) {
    static const int sizes[] = {1000, 2000, 4000, 10000, 20000, 40000};
    enum { SIZE_COUNT = sizeof sizes / sizeof sizes[0] };
    int runs = argc > 1 ? atoi(argv[1]) : 3;
    if (runs < 1 || runs > 16) {
        fprintf(stderr, "usage: %s [RUNS 1..16]\n", argv[0]);
        return 2;
    }
    scale_row_t rows[SIZE_COUNT];
    double n[SIZE_COUNT], ms[SIZE_COUNT], per_point[SIZE_COUNT];
    for (int i = 0; i < SIZE_COUNT; i++) {
        rows[i] = measure(sizes[i], sizes[i] >= 40000 && runs > 1 ? 1 : runs);
        n[i] = sizes[i];
        ms[i] = rows[i].ms;
        per_point[i] = rows[i].ms / rows[i].points;
    }
    fprintf(stderr, "\n");
    printf("| N | ms per step | contact points per step | us per contact point | heap bytes "
           "per body (built) | heap grown by stepping, per contact | outside at the end |\n"
           "|---|---|---|---|---|---|---|\n");
    for (int i = 0; i < SIZE_COUNT; i++) {
        printf("| %d | %.4g | %.0f | %.4g | %.0f | %.0f | %d |\n", rows[i].bodies, rows[i].ms,
               rows[i].points, 1e3 * per_point[i], rows[i].bytes_per_body,
               rows[i].bytes_per_contact, rows[i].outside);
    }
    printf("\nFitted exponents (least squares on logs, N = %d to %d): ms per step grows as "
           "N^%.2f (N^%.2f from 1000 to 10000), ms per contact point as N^%.2f.\n",
           sizes[0], sizes[SIZE_COUNT - 1], fitted_exponent(n, ms, SIZE_COUNT),
           fitted_exponent(n, ms, 4), fitted_exponent(n, per_point, SIZE_COUNT));
    return 0;
}
