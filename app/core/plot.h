#ifndef SANDBOX_PLOT_H
#define SANDBOX_PLOT_H

/*
 * A plot of one quantity against simulated time, the last PLOT_SECONDS:
 * the inspected body's height or speed, or the scene's kinetic energy,
 * energy or momentum. Like the energy drift's chart, PLOT_COLUMNS columns
 * of simulated time in a fixed ring, each the lowest and highest value of
 * the frames in it; nothing allocated. Plain C, no SDL.
 */

#include <stdbool.h>
#include <stddef.h>

#define PLOT_COLUMNS 200
#define PLOT_SECONDS 5.0

typedef enum {
    PLOT_HEIGHT = 0, /* the inspected body's centroid y (m) */
    PLOT_SPEED,      /* its speed (m/s) */
    PLOT_KINETIC,    /* the scene's kinetic energy (J) */
    PLOT_ENERGY,     /* its energy, kinetic and potential (J) */
    PLOT_MOMENTUM,   /* the length of its momentum (N s) */
    PLOT_QUANTITY_COUNT
} plot_quantity_t;

typedef struct {
    float low, high;
    bool filled;
} plot_column_t;

typedef struct {
    plot_column_t columns[PLOT_COLUMNS]; /* a ring; columns[head] is the newest */
    size_t head;
    double elapsed;   /* simulated seconds into the newest column */
    plot_quantity_t quantity;
    double latest;    /* the last value given */
    bool has_latest;  /* false while nothing is given (no body inspected) */
} plot_t;

/* An empty plot of the quantity. */
void plot_init(plot_t *plot, plot_quantity_t quantity);

/* A frame of `seconds` simulated time (0 while paused: nothing is added)
 * ending with `value`, or without one (has_value false: no body to
 * measure, the columns stay empty). */
void plot_sample(plot_t *plot, double seconds, bool has_value, double value);

/* The column `age` columns before the newest (age < PLOT_COLUMNS). */
const plot_column_t *plot_column(const plot_t *plot, size_t age);

/* The lowest and highest value on the plot; false when it is empty. A
 * range narrower than 1e-9 of its size (a constant) is widened to show. */
bool plot_range(const plot_t *plot, double *low, double *high);

/* The quantity in words with its unit ("height (m)"), and whether it needs
 * an inspected body. */
const char *plot_quantity_name(plot_quantity_t quantity);
bool plot_needs_body(plot_quantity_t quantity);

#endif
