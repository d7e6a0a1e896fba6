#ifndef SCALAR_H
#define SCALAR_H

/* fmin and fmax are library calls under strict IEEE rules (they must order
 * NaNs); the hot loops use these, which inline to one instruction. Neither
 * argument may be NaN. */

static inline double min_of(double a, double b) {
    return a < b ? a : b;
}

static inline double max_of(double a, double b) {
    return a > b ? a : b;
}

#endif // #ifndef SCALAR_H
