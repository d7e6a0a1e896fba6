#include "draw/round_outline.h"
#include <math.h>

/* Segments a full turn needs for chords within a quarter pixel of the rim:
 * the sagitta r (1 - cos(pi / n)) is about r pi^2 / (2 n^2). */
static int turn_segments(double r) {
    double n = ceil(M_PI * sqrt(2.0 * r / 0.25));
    if (n < 8.0) return 8;
    if (n > ROUND_OUTLINE_MAX) return ROUND_OUTLINE_MAX;
    return (int)n;
}

int round_outline(vector_t c1, vector_t c2, double r, vector_t *out) {
    if (!(isfinite(r) && r > 0.0) || !vec_is_finite(c1) || !vec_is_finite(c2)) return 0;
    int n = turn_segments(r);
    vector_t d = vec_subtract(c2, c1);
    double length = vec_get_length(d);
    if (!(length > 1e-9 * r)) {
        for (int k = 0; k < n; k++) {
            double a = 2.0 * M_PI * k / n;
            out[k] = vec_add(c1, (vector_t){r * cos(a), r * sin(a)});
        }
        return n;
    }
    /* A half-turn about each end, both ends of it included, an odd count so
     * that the tip on the core's line is a vertex: the straight sides join
     * them. */
    int per_end = (n / 2 - 1) | 1;
    double base = atan2(d.y, d.x);
    int count = 0;
    for (int end = 0; end < 2; end++) {
        vector_t c = end == 0 ? c2 : c1;
        for (int k = 0; k < per_end; k++) {
            double a = base - M_PI / 2.0 + M_PI * k / (per_end - 1) + M_PI * end;
            out[count++] = vec_add(c, (vector_t){r * cos(a), r * sin(a)});
        }
    }
    return count;
}

vector_t round_rim_point(vector_t centre, double r, double angle) {
    return vec_add(centre, (vector_t){r * cos(angle), -r * sin(angle)});
}
