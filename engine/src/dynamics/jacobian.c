#include "dynamics/jacobian.h"
#include <math.h>

sym2_t jacobian_spring_stiffness(double k, double rest_length, vector_t between) {
    if (rest_length == 0.0) return (sym2_t){k, 0.0, k};
    double d = vec_get_length(between);
    if (!(d > 0.0) || !isfinite(1.0 / d)) return (sym2_t){0.0, 0.0, 0.0};
    double ux = between.x / d, uy = between.y / d;
    double across = k * fmax(0.0, 1.0 - rest_length / d), along = k;
    /* along u u^T + across (I - u u^T) */
    double extra = along - across;
    return (sym2_t){across + extra * ux * ux, extra * ux * uy, across + extra * uy * uy};
}
