#include <math.h>
#include "test.h"
#include "jostle/vector.h"

static void zero_is_zero(void) {
    CHECK(VEC_ZERO.x == 0.0 && VEC_ZERO.y == 0.0);
}

static void arithmetic(void) {
    vector_t a = {1.5, -2.0}, b = {-0.5, 4.0};
    vector_t sum = vec_add(a, b);
    CHECK(sum.x == 1.0 && sum.y == 2.0);
    vector_t difference = vec_subtract(a, b);
    CHECK(difference.x == 2.0 && difference.y == -6.0);
    vector_t negated = vec_negate(a);
    CHECK(negated.x == -1.5 && negated.y == 2.0);
    vector_t scaled = vec_multiply(-2.0, a);
    CHECK(scaled.x == -3.0 && scaled.y == 4.0);
}

static void products(void) {
    vector_t a = {3.0, 4.0}, b = {-2.0, 1.0};
    CHECK(vec_dot(a, b) == -2.0);
    CHECK(vec_cross(a, b) == 3.0 * 1.0 - 4.0 * -2.0);
    CHECK(vec_cross((vector_t){1, 0}, (vector_t){0, 1}) == 1.0); /* z of x cross y */
    CHECK(vec_cross(b, a) == -vec_cross(a, b));
    CHECK(vec_get_length(a) == 5.0);
    CHECK(vec_get_length_squared(a) == 25.0);
}

static void rotation_is_counterclockwise(void) {
    vector_t r = vec_rotate((vector_t){1.0, 0.0}, M_PI / 2);
    CHECK_NEAR(r.x, 0.0, 1e-15);
    CHECK_NEAR(r.y, 1.0, 1e-15);
    vector_t v = {2.0, -1.0};
    vector_t back = vec_rotate(vec_rotate(v, 0.7), -0.7);
    CHECK_NEAR(back.x, v.x, 1e-15);
    CHECK_NEAR(back.y, v.y, 1e-15);
    CHECK_NEAR(vec_get_length(vec_rotate(v, 2.3)), vec_get_length(v), 1e-15);
}

static void helpers(void) {
    vector_t p = vec_perpendicular((vector_t){1.0, 2.0});
    CHECK(p.x == -2.0 && p.y == 1.0);
    vector_t w = vec_cross_scalar(2.0, (vector_t){1.0, 0.0});
    CHECK(w.x == 0.0 && w.y == 2.0);
    CHECK_NEAR(vec_get_length(vec_normalize((vector_t){3.0, -7.0})), 1.0, 1e-15);
    vector_t z = vec_normalize(VEC_ZERO);
    CHECK(z.x == 0.0 && z.y == 0.0);
    CHECK(!vec_is_finite((vector_t){NAN, 0.0}));
    CHECK(!vec_is_finite((vector_t){0.0, INFINITY}));
    CHECK(vec_is_finite((vector_t){1e300, -1e300}));
}

static void rotate_cs_matches_rotate_and_negative_turns_clockwise(void) {
    vector_t v = {1.5, -0.5};
    for (int i = -8; i <= 8; i++) {
        double angle = 0.4 * i;
        vector_t a = vec_rotate(v, angle), b = vec_rotate_cs(v, cos(angle), sin(angle));
        CHECK_NEAR(a.x, b.x, 1e-15);
        CHECK_NEAR(a.y, b.y, 1e-15);
    }
    vector_t r = vec_rotate((vector_t){0.0, 1.0}, -M_PI / 2);
    CHECK_NEAR(r.x, 1.0, 1e-15);
    CHECK_NEAR(r.y, 0.0, 1e-15);
    /* The cross product of the rotated vector with the original is
     * |v|^2 sin(angle): positive for a counter-clockwise turn. */
    CHECK_NEAR(vec_cross(v, vec_rotate(v, 0.3)), vec_get_length_squared(v) * sin(0.3), 1e-15);
}

static void identities(void) {
    vector_t a = {0.25, -7.0}, b = {2.5, 1.25}; /* exact in binary */
    CHECK(vec_cross(a, a) == 0.0);
    CHECK(vec_dot(a, vec_perpendicular(a)) == 0.0);
    CHECK(vec_cross(a, b) == vec_dot(vec_perpendicular(a), b));
    vector_t sum = vec_add(a, vec_negate(a));
    CHECK(sum.x == 0.0 && sum.y == 0.0);
    vector_t back = vec_subtract(vec_add(a, b), b);
    CHECK(back.x == a.x && back.y == a.y);
    vector_t zero = vec_multiply(0.0, a);
    CHECK(zero.x == 0.0 && zero.y == 0.0);
    CHECK(vec_get_length(VEC_ZERO) == 0.0);
    CHECK(vec_get_length((vector_t){-3.0, 0.0}) == 3.0);
}

TEST_SUITE(vector, TEST_CASE(zero_is_zero), TEST_CASE(arithmetic), TEST_CASE(products),
           TEST_CASE(rotation_is_counterclockwise), TEST_CASE(helpers),
           TEST_CASE(rotate_cs_matches_rotate_and_negative_turns_clockwise),
           TEST_CASE(identities));
