/* polygon.h: area, centroid, translate, rotate, moment of inertia, shape
 * checks and the shape makers, on lists of heap vector_t *. */
#include <stdlib.h>
#include <string.h>
#include "jostle/polygon.h"
#include "test.h"


static vector_t vertex(list_t *polygon, size_t i) {
    return *(vector_t *)list_get(polygon, i);
}

/* Reverses a list in place (to make the clockwise twin of a polygon). */
static void reverse(list_t *polygon) {
    size_t n = list_size(polygon);
    for (size_t i = 0; i < n / 2; i++) {
        void *a = list_get(polygon, i), *b = list_get(polygon, n - 1 - i);
        list_set(polygon, i, b);
        list_set(polygon, n - 1 - i, a);
    }
}

static void area_of_known_shapes(void) {
    list_t *square = POLYGON({0, 0}, {2, 0}, {2, 2}, {0, 2});
    CHECK_NEAR(polygon_area(square), 4.0, 1e-15);
    list_free(square);
    list_t *triangle = POLYGON({1, 1}, {4, 1}, {1, 5}); /* legs 3 and 4 */
    CHECK_NEAR(polygon_area(triangle), 6.0, 1e-14);
    list_free(triangle);
    /* A trapezoid with parallel sides 1 and 2, width 2. */
    list_t *trapezoid = POLYGON({0, 0}, {2, 0}, {2, 2}, {0, 1});
    CHECK_NEAR(polygon_area(trapezoid), 3.0, 1e-15);
    list_free(trapezoid);
    /* Far from the origin the shoelace must not lose the answer. */
    list_t *far = POLYGON({1e6, 1e6}, {1e6 + 1, 1e6}, {1e6 + 1, 1e6 + 1}, {1e6, 1e6 + 1});
    CHECK_NEAR(polygon_area(far), 1.0, 1e-6);
    list_free(far);
}

static void area_is_signed_by_winding(void) {
    list_t *ccw = POLYGON({0, 0}, {3, 0}, {3, 1}, {0, 1});
    list_t *cw = POLYGON({0, 0}, {0, 1}, {3, 1}, {3, 0});
    CHECK_NEAR(polygon_area(ccw), 3.0, 1e-15);
    CHECK_NEAR(polygon_area(cw), -3.0, 1e-15);
    CHECK(polygon_is_counterclockwise(ccw));
    CHECK(!polygon_is_counterclockwise(cw));
    list_free(ccw);
    list_free(cw);
}

static void area_of_degenerate_lists_is_zero(void) {
    list_t *empty = list_init(0, free);
    list_t *two = POLYGON({0, 0}, {1, 1});
    list_t *line = POLYGON({0, 0}, {1, 1}, {2, 2});
    CHECK(polygon_area(empty) == 0.0);
    CHECK(polygon_area(two) == 0.0);
    CHECK(polygon_area(line) == 0.0);
    list_free(empty);
    list_free(two);
    list_free(line);
}

static void centroid_is_area_centroid_not_vertex_mean(void) {
    /* Rectangle [0,2]x[0,1] (area 2, centroid (1, 1/2)) plus the triangle
     * (0,1) (2,1) (2,2) (area 1, centroid (4/3, 4/3)): (10/9, 7/9). The
     * vertex mean would be (1, 3/4). */
    list_t *trapezoid = POLYGON({0, 0}, {2, 0}, {2, 2}, {0, 1});
    vector_t c = polygon_centroid(trapezoid);
    CHECK_NEAR(c.x, 10.0 / 9.0, 1e-15);
    CHECK_NEAR(c.y, 7.0 / 9.0, 1e-15);
    /* The same polygon clockwise has the same centroid. */
    reverse(trapezoid);
    c = polygon_centroid(trapezoid);
    CHECK_NEAR(c.x, 10.0 / 9.0, 1e-15);
    CHECK_NEAR(c.y, 7.0 / 9.0, 1e-15);
    list_free(trapezoid);

    /* Extra vertices crowded on one side move the vertex mean, not the
     * centroid: a unit square with four more points on its right edge. */
    list_t *square = POLYGON({0, 0}, {1, 0}, {1, 0.2}, {1, 0.4}, {1, 0.6}, {1, 0.8}, {1, 1},
                             {0, 1});
    c = polygon_centroid(square);
    CHECK_NEAR(c.x, 0.5, 1e-15);
    CHECK_NEAR(c.y, 0.5, 1e-15);
    list_free(square);

    list_t *triangle = POLYGON({0, 0}, {3, 0}, {0, 6});
    c = polygon_centroid(triangle);
    CHECK_NEAR(c.x, 1.0, 1e-15);
    CHECK_NEAR(c.y, 2.0, 1e-15);
    list_free(triangle);

    list_t *far = POLYGON({1e7, -1e7}, {1e7 + 2, -1e7}, {1e7 + 2, -1e7 + 2}, {1e7, -1e7 + 2});
    c = polygon_centroid(far);
    CHECK_NEAR(c.x, 1e7 + 1, 1e-8);
    CHECK_NEAR(c.y, -1e7 + 1, 1e-8);
    list_free(far);
}

static void centroid_of_degenerate_lists(void) {
    /* Documented fallbacks: no area gives the vertex mean; no vertex gives
     * the origin. */
    list_t *line = POLYGON({0, 0}, {1, 2}, {2, 4});
    vector_t c = polygon_centroid(line);
    CHECK_NEAR(c.x, 1.0, 1e-15);
    CHECK_NEAR(c.y, 2.0, 1e-15);
    list_free(line);
    list_t *empty = list_init(0, free);
    c = polygon_centroid(empty);
    CHECK(c.x == 0.0 && c.y == 0.0);
    list_free(empty);
}

static void translate_moves_every_vertex(void) {
    list_t *triangle = POLYGON({0, 0}, {1, 0}, {0, 1});
    double area = polygon_area(triangle);
    vector_t before = polygon_centroid(triangle);
    polygon_translate(triangle, (vector_t){2.5, -1.0});
    CHECK(vertex(triangle, 0).x == 2.5 && vertex(triangle, 0).y == -1.0);
    CHECK(vertex(triangle, 1).x == 3.5 && vertex(triangle, 1).y == -1.0);
    CHECK(vertex(triangle, 2).x == 2.5 && vertex(triangle, 2).y == 0.0);
    vector_t after = polygon_centroid(triangle);
    CHECK_NEAR(after.x, before.x + 2.5, 1e-15);
    CHECK_NEAR(after.y, before.y - 1.0, 1e-15);
    CHECK_NEAR(polygon_area(triangle), area, 1e-15);
    CHECK(list_size(triangle) == 3);
    list_free(triangle);
}

static void rotate_about_a_point_counterclockwise(void) {
    /* Unit square rotated a quarter turn about (1, 0). */
    list_t *square = POLYGON({0, 0}, {1, 0}, {1, 1}, {0, 1});
    polygon_rotate(square, M_PI / 2, (vector_t){1, 0});
    const vector_t expected[4] = {{1, -1}, {1, 0}, {0, 0}, {0, -1}};
    for (size_t i = 0; i < 4; i++) {
        CHECK_NEAR(vertex(square, i).x, expected[i].x, 1e-15);
        CHECK_NEAR(vertex(square, i).y, expected[i].y, 1e-15);
    }
    CHECK_NEAR(polygon_area(square), 1.0, 1e-15); /* still counter-clockwise */
    list_free(square);

    /* Rotating about the centroid keeps the centroid; a full turn (in
     * pieces) comes back. */
    list_t *triangle = POLYGON({0, 0}, {3, 0}, {0, 6});
    vector_t c = polygon_centroid(triangle);
    polygon_rotate(triangle, 0.3, c);
    vector_t c2 = polygon_centroid(triangle);
    CHECK_NEAR(c2.x, c.x, 1e-14);
    CHECK_NEAR(c2.y, c.y, 1e-14);
    polygon_rotate(triangle, 2 * M_PI - 0.3, c);
    CHECK_NEAR(vertex(triangle, 1).x, 3.0, 1e-14);
    CHECK_NEAR(vertex(triangle, 1).y, 0.0, 1e-14);
    /* A negative angle turns clockwise. */
    polygon_rotate(triangle, -M_PI / 2, VEC_ZERO);
    CHECK_NEAR(vertex(triangle, 1).x, 0.0, 1e-14);
    CHECK_NEAR(vertex(triangle, 1).y, -3.0, 1e-14);
    list_free(triangle);
}

static void moment_of_inertia_of_known_shapes(void) {
    /* Box w x h: m (w^2 + h^2) / 12, anywhere, either winding. */
    list_t *box = POLYGON({10, 20}, {13, 20}, {13, 22}, {10, 22});
    CHECK_RELATIVE(polygon_moment_of_inertia(box, 6.0), 6.0 * (9.0 + 4.0) / 12.0, 1e-13);
    reverse(box);
    CHECK_RELATIVE(polygon_moment_of_inertia(box, 6.0), 6.0 * (9.0 + 4.0) / 12.0, 1e-13);
    list_free(box);
    /* Triangle about its centroid: m (a^2 + b^2 + c^2) / 36. */
    list_t *triangle = POLYGON({0, 0}, {3, 0}, {0, 4});
    CHECK_RELATIVE(polygon_moment_of_inertia(triangle, 2.0), 2.0 * (9.0 + 16.0 + 25.0) / 36.0,
                   1e-13);
    list_free(triangle);
    /* Regular n-gon of circumradius R: m R^2 (1 + 2 cos^2(pi / n)) / 6. */
    list_t *hexagon = polygon_make_regular(6, 2.0, (vector_t){-5, 7}, 0.4);
    CHECK_RELATIVE(polygon_moment_of_inertia(hexagon, 3.0),
                   3.0 * 4.0 * (1 + 2 * pow(cos(M_PI / 6), 2)) / 6.0, 1e-13);
    list_free(hexagon);
    /* Many sides: tends to the disc, m R^2 / 2. */
    list_t *disc = polygon_make_regular(400, 1.0, VEC_ZERO, 0.0);
    CHECK_RELATIVE(polygon_moment_of_inertia(disc, 1.0), 0.5, 1e-4);
    list_free(disc);
    /* Scales linearly with mass; INFINITY gives INFINITY. */
    list_t *square = polygon_make_box(VEC_ZERO, 1, 1);
    CHECK_RELATIVE(polygon_moment_of_inertia(square, 5.0),
                   5.0 * polygon_moment_of_inertia(square, 1.0), 1e-15);
    CHECK(isinf(polygon_moment_of_inertia(square, INFINITY)));
    list_free(square);
}

/* A 1 m box centred at `center`. */
static list_t *unit_box_at(vector_t center) {
    return polygon_make_box(center, 0.5, 0.5);
}

static void area_and_check_of_a_unit_box_far_from_the_origin(void) {
    /* A centre off the grid of doubles rounds each corner by up to half the
     * spacing there, so each side is 1 m within one spacing and the area 1
     * within about two: 2^-33 ~ 1.2e-10 at 1e6 m, 2^-19 ~ 1.9e-6 at 1e10 m.
     * At 1e8 m the centre is on the grid: the corners are exact and so must
     * be the area, to rounding. */
    const struct {
        vector_t center;
        double tolerance;
    } cases[] = {
        {{1e6 + 0.3, 1e6 - 0.7}, 1e-9},
        {{1e8, 1e8}, 1e-9},
        {{-1e8 + 0.25, 1e8 + 0.125}, 1e-9},
        {{1e10 + 0.3, -1e10 - 0.7}, 4e-6},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        list_t *box = unit_box_at(cases[i].center);
        CHECK_NEAR(polygon_area(box), 1.0, cases[i].tolerance);
        CHECK(polygon_check(box) == NULL);
        CHECK(polygon_is_counterclockwise(box));
        reverse(box);
        CHECK_NEAR(polygon_area(box), -1.0, cases[i].tolerance);
        CHECK(polygon_check(box) == NULL);
        list_free(box);
    }
    /* A triangle of legs 3 and 4 at 1e8 m (exact corners): area 6. */
    list_t *triangle = POLYGON({1e8, 1e8}, {1e8 + 3, 1e8}, {1e8, 1e8 + 4});
    CHECK_RELATIVE(polygon_area(triangle), 6.0, 1e-9);
    CHECK(polygon_check(triangle) == NULL);
    list_free(triangle);
}

static void check_accepts_a_regular_100000_gon(void) {
    /* Each turn is 2 pi / 1e5 = 6.3e-5 rad between edges 6.3e-5 m long: a
     * valid convex polygon, if a fine one. Area n/2 sin(2 pi / n). */
    const size_t n = 100000;
    list_t *polygon = polygon_make_regular(n, 1.0, (vector_t){3, -4}, 0.1);
    CHECK(polygon_check(polygon) == NULL);
    CHECK_RELATIVE(polygon_area(polygon), 0.5 * (double)n * sin(2 * M_PI / (double)n), 1e-12);
    CHECK_RELATIVE(polygon_moment_of_inertia(polygon, 2.0), 1.0, 1e-8); /* m R^2 / 2 */
    list_free(polygon);
}

static void check_accepts_usable_shapes(void) {
    list_t *ccw = POLYGON({0, 0}, {1, 0}, {0, 1});
    list_t *cw = POLYGON({0, 0}, {0, 1}, {1, 0});
    list_t *tiny = POLYGON({0, 0}, {1e-6, 0}, {1e-6, 1e-6}, {0, 1e-6});
    list_t *far = POLYGON({1e6, 1e6}, {1e6 + 1, 1e6}, {1e6 + 1, 1e6 + 1}, {1e6, 1e6 + 1});
    list_t *many = polygon_make_regular(100, 1.0, VEC_ZERO, 0.0); /* > 64: heap buffer */
    CHECK(polygon_check(ccw) == NULL);
    CHECK(polygon_check(cw) == NULL);
    CHECK(polygon_check(tiny) == NULL);
    CHECK(polygon_check(far) == NULL);
    CHECK(polygon_check(many) == NULL);
    list_free(ccw);
    list_free(cw);
    list_free(tiny);
    list_free(far);
    list_free(many);
}

/* polygon_check's answer contains `expected` (and does not stop the
 * program). */
static bool refused_with(list_t *polygon, const char *expected) {
    const char *problem = polygon_check(polygon);
    bool ok = problem != NULL && strstr(problem, expected) != NULL;
    if (!ok) printf("    polygon_check gave \"%s\", wanted \"%s\"\n", problem, expected);
    if (polygon != NULL) list_free(polygon);
    return ok;
}

static void check_names_each_problem(void) {
    CHECK(refused_with(NULL, "NULL"));
    CHECK(refused_with(list_init(0, free), "fewer than 3 vertices"));
    CHECK(refused_with(POLYGON({0, 0}, {1, 0}), "fewer than 3 vertices"));
    list_t *with_null = POLYGON({0, 0}, {1, 0}, {0, 1});
    free(list_set(with_null, 2, NULL)); /* list_add refuses NULL */
    CHECK(refused_with(with_null, "NULL vertex"));
    CHECK(refused_with(POLYGON({0, 0}, {NAN, 0}, {0, 1}), "not finite"));
    CHECK(refused_with(POLYGON({0, 0}, {INFINITY, 0}, {0, 1}), "not finite"));
    CHECK(refused_with(POLYGON({0, 0}, {1, 1}, {2, 2}), "zero area"));
    CHECK(refused_with(POLYGON({1, 1}, {1, 1}, {1, 1}), "zero area"));
    CHECK(refused_with(POLYGON({0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}), "repeats a vertex"));
    /* A dart: the vertex (1, 1) turns the wrong way. */
    CHECK(refused_with(POLYGON({0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}), "convex"));
    /* The same dart clockwise. */
    CHECK(refused_with(POLYGON({0, 2}, {2, 2}, {1, 1}, {2, 0}, {0, 0}), "convex"));
    /* Three collinear vertices: a straight angle is refused too. */
    CHECK(refused_with(POLYGON({0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}), "convex"));
    /* A bow tie crosses itself. */
    CHECK(refused_with(POLYGON({0, 0}, {4, 2}, {4, 0}, {0, 3}), "convex"));
    /* A symmetric bow tie has no signed area at all. */
    CHECK(refused_with(POLYGON({0, 0}, {2, 2}, {2, 0}, {0, 2}), "zero area"));
    /* A repeat anywhere, including the last vertex repeating the first. */
    CHECK(refused_with(POLYGON({0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 1}), "repeats a vertex"));
    CHECK(refused_with(POLYGON({0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}), "repeats a vertex"));
    /* A pentagram turns the same way at every vertex but winds twice. */
    vector_t star[5];
    for (int i = 0; i < 5; i++) {
        double a = 4.0 * M_PI * i / 5.0;
        star[i] = (vector_t){cos(a), sin(a)};
    }
    CHECK(refused_with(test_make_polygon(star, 5), "more than once"));
}

static void check_refuses_a_box_whose_area_overflows(void) {
    /* 2e200 m wide: its area, 4e400 m^2, is not a double. */
    CHECK(refused_with(polygon_make_box(VEC_ZERO, 1e200, 1e200),
                       "polygon is too large: its area overflows"));
    CHECK(refused_with(POLYGON({-1e300, 0}, {1e300, 0}, {0, 1e300}),
                       "polygon is too large: its area overflows"));
}

static void check_tells_a_reflex_vertex_from_a_straight_angle(void) {
    CHECK(refused_with(POLYGON({0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}),
                       "polygon is not strictly convex: a vertex turns against the winding"));
    CHECK(refused_with(POLYGON({0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}),
                       "polygon is not strictly convex: three consecutive vertices are "
                       "collinear"));
    /* Collinear to rounding far from the origin: the middle vertex of the
     * bottom edge sits on the line through its neighbours. */
    CHECK(refused_with(POLYGON({1e8, 1e8}, {1e8 + 0.5, 1e8}, {1e8 + 1, 1e8}, {1e8 + 1, 1e8 + 1},
                               {1e8, 1e8 + 1}),
                       "collinear"));
}

static void make_regular(void) {
    vector_t center = {3, -2};
    list_t *hexagon = polygon_make_regular(6, 2.0, center, M_PI / 6);
    CHECK(list_size(hexagon) == 6);
    for (size_t i = 0; i < 6; i++) {
        vector_t v = vertex(hexagon, i);
        CHECK_NEAR(vec_get_length(vec_subtract(v, center)), 2.0, 1e-14);
        double angle = atan2(v.y - center.y, v.x - center.x);
        double expected = M_PI / 6 + M_PI / 3 * (double)i;
        CHECK_NEAR(remainder(angle - expected, 2 * M_PI), 0.0, 1e-14);
    }
    CHECK(polygon_check(hexagon) == NULL);
    CHECK(polygon_is_counterclockwise(hexagon));
    CHECK_NEAR(polygon_area(hexagon), 0.5 * 6 * 4.0 * sin(M_PI / 3), 1e-13);
    vector_t c = polygon_centroid(hexagon);
    CHECK_NEAR(c.x, 3.0, 1e-14);
    CHECK_NEAR(c.y, -2.0, 1e-14);
    list_free(hexagon); /* the list owns its vertices (LeakSanitizer) */

    list_t *triangle = polygon_make_regular(3, 1.0, VEC_ZERO, 0.0);
    CHECK(list_size(triangle) == 3);
    CHECK_NEAR(vertex(triangle, 0).x, 1.0, 1e-15);
    CHECK_NEAR(vertex(triangle, 0).y, 0.0, 1e-15);
    list_free(triangle);
}

static void make_box(void) {
    list_t *box = polygon_make_box((vector_t){1, 2}, 3, 0.5);
    CHECK(list_size(box) == 4);
    CHECK(polygon_check(box) == NULL);
    CHECK(polygon_is_counterclockwise(box));
    CHECK_NEAR(polygon_area(box), 6.0, 1e-15);
    vector_t c = polygon_centroid(box);
    CHECK_NEAR(c.x, 1.0, 1e-15);
    CHECK_NEAR(c.y, 2.0, 1e-15);
    CHECK(vertex(box, 0).x == -2.0 && vertex(box, 0).y == 1.5); /* lower-left first */
    for (size_t i = 0; i < 4; i++) {
        vector_t v = vertex(box, i);
        CHECK(v.x == -2.0 || v.x == 4.0);
        CHECK(v.y == 1.5 || v.y == 2.5);
    }
    list_free(box);
}

/* Programmer errors. */
static void area_of_null(void *unused) {
    (void)unused;
    polygon_area(NULL);
}
static void centroid_of_null(void *unused) {
    (void)unused;
    polygon_centroid(NULL);
}
static void translate_null(void *unused) {
    (void)unused;
    polygon_translate(NULL, VEC_ZERO);
}
static void rotate_null(void *unused) {
    (void)unused;
    polygon_rotate(NULL, 1.0, VEC_ZERO);
}
static void ccw_of_null(void *unused) {
    (void)unused;
    polygon_is_counterclockwise(NULL);
}
static list_t *with_null_vertex(void) {
    list_t *polygon = POLYGON({0, 0}, {1, 0}, {0, 1});
    free(list_set(polygon, 2, NULL)); /* list_add refuses NULL */
    return polygon;
}
static void area_with_null_vertex(void *unused) {
    (void)unused;
    polygon_area(with_null_vertex());
}
static void centroid_with_null_vertex(void *unused) {
    (void)unused;
    polygon_centroid(with_null_vertex());
}
static void translate_with_null_vertex(void *unused) {
    (void)unused;
    polygon_translate(with_null_vertex(), (vector_t){1, 1});
}
static void rotate_with_null_vertex(void *unused) {
    (void)unused;
    polygon_rotate(with_null_vertex(), 1.0, VEC_ZERO);
}
static void moment_of_null(void *unused) {
    (void)unused;
    polygon_moment_of_inertia(NULL, 1.0);
}
static void moment_negative_mass(void *unused) {
    (void)unused;
    polygon_moment_of_inertia(polygon_make_box(VEC_ZERO, 1, 1), -1.0);
}
static void moment_zero_mass(void *unused) {
    (void)unused;
    polygon_moment_of_inertia(polygon_make_box(VEC_ZERO, 1, 1), 0.0);
}
static void moment_nan_mass(void *unused) {
    (void)unused;
    polygon_moment_of_inertia(polygon_make_box(VEC_ZERO, 1, 1), NAN);
}
static void moment_of_two_vertices(void *unused) {
    (void)unused;
    polygon_moment_of_inertia(POLYGON({0, 0}, {1, 0}), 1.0);
}
static void moment_of_dart(void *unused) {
    (void)unused;
    polygon_moment_of_inertia(POLYGON({0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}), 1.0);
}
static void regular_two_sides(void *unused) {
    (void)unused;
    polygon_make_regular(2, 1.0, VEC_ZERO, 0.0);
}
static void regular_zero_radius(void *unused) {
    (void)unused;
    polygon_make_regular(5, 0.0, VEC_ZERO, 0.0);
}
static void regular_nan_radius(void *unused) {
    (void)unused;
    polygon_make_regular(5, NAN, VEC_ZERO, 0.0);
}
static void regular_infinite_center(void *unused) {
    (void)unused;
    polygon_make_regular(5, 1.0, (vector_t){INFINITY, 0}, 0.0);
}
static void regular_nan_angle(void *unused) {
    (void)unused;
    polygon_make_regular(5, 1.0, VEC_ZERO, NAN);
}
static void box_zero_width(void *unused) {
    (void)unused;
    polygon_make_box(VEC_ZERO, 0.0, 1.0);
}
static void box_negative_height(void *unused) {
    (void)unused;
    polygon_make_box(VEC_ZERO, 1.0, -1.0);
}
static void box_nan_width(void *unused) {
    (void)unused;
    polygon_make_box(VEC_ZERO, NAN, 1.0);
}
static void box_infinite_height(void *unused) {
    (void)unused;
    polygon_make_box(VEC_ZERO, 1.0, INFINITY);
}
static void box_nan_center(void *unused) {
    (void)unused;
    polygon_make_box((vector_t){0, NAN}, 1.0, 1.0);
}

static void bad_input_aborts_with_message(void) {
    CHECK_DIES(area_of_null, NULL, "engine error in polygon_area:", "NULL");
    CHECK_DIES(centroid_of_null, NULL, "engine error in polygon_centroid:", "NULL");
    CHECK_DIES(translate_null, NULL, "engine error in polygon_translate:", "NULL");
    CHECK_DIES(rotate_null, NULL, "engine error in polygon_rotate:", "NULL");
    CHECK_DIES(ccw_of_null, NULL, "engine error in polygon_is_counterclockwise:", "NULL");
    CHECK_DIES(area_with_null_vertex, NULL, "engine error in polygon_area:", "vertex 2 is NULL");
    CHECK_DIES(centroid_with_null_vertex, NULL, "engine error in polygon_centroid:",
               "vertex 2 is NULL");
    CHECK_DIES(translate_with_null_vertex, NULL, "engine error in polygon_translate:",
               "vertex 2 is NULL");
    CHECK_DIES(rotate_with_null_vertex, NULL, "engine error in polygon_rotate:",
               "vertex 2 is NULL");
    CHECK_DIES(moment_of_null, NULL, "engine error in polygon_moment_of_inertia:", "NULL");
    CHECK_DIES(moment_negative_mass, NULL, "engine error in polygon_moment_of_inertia:", "mass",
               "-1");
    CHECK_DIES(moment_zero_mass, NULL, "engine error in polygon_moment_of_inertia:", "mass");
    CHECK_DIES(moment_nan_mass, NULL, "engine error in polygon_moment_of_inertia:", "mass",
               "nan");
    CHECK_DIES(moment_of_two_vertices, NULL, "engine error in polygon_moment_of_inertia:",
               "fewer than 3 vertices");
    CHECK_DIES(moment_of_dart, NULL, "engine error in polygon_moment_of_inertia:", "convex");
    CHECK_DIES(regular_two_sides, NULL, "engine error in polygon_make_regular:", "3 sides",
               "got 2");
    CHECK_DIES(regular_zero_radius, NULL, "engine error in polygon_make_regular:", "radius");
    CHECK_DIES(regular_nan_radius, NULL, "engine error in polygon_make_regular:", "radius");
    CHECK_DIES(regular_infinite_center, NULL, "engine error in polygon_make_regular:", "center",
               "not finite");
    CHECK_DIES(regular_nan_angle, NULL, "engine error in polygon_make_regular:", "angle",
               "not finite");
    CHECK_DIES(box_zero_width, NULL, "engine error in polygon_make_box:", "half");
    CHECK_DIES(box_negative_height, NULL, "engine error in polygon_make_box:", "half");
    CHECK_DIES(box_nan_width, NULL, "engine error in polygon_make_box:", "half");
    CHECK_DIES(box_infinite_height, NULL, "engine error in polygon_make_box:", "half");
    CHECK_DIES(box_nan_center, NULL, "engine error in polygon_make_box:", "center",
               "not finite");
}

TEST_SUITE(polygon, TEST_CASE(area_of_known_shapes), TEST_CASE(area_is_signed_by_winding),
           TEST_CASE(area_of_degenerate_lists_is_zero),
           TEST_CASE(centroid_is_area_centroid_not_vertex_mean),
           TEST_CASE(centroid_of_degenerate_lists), TEST_CASE(translate_moves_every_vertex),
           TEST_CASE(rotate_about_a_point_counterclockwise),
           TEST_CASE(moment_of_inertia_of_known_shapes), TEST_CASE(check_accepts_usable_shapes),
           TEST_CASE(area_and_check_of_a_unit_box_far_from_the_origin),
           TEST_CASE(check_accepts_a_regular_100000_gon),
           TEST_CASE(check_names_each_problem),
           TEST_CASE(check_refuses_a_box_whose_area_overflows),
           TEST_CASE(check_tells_a_reflex_vertex_from_a_straight_angle),
           TEST_CASE(make_regular), TEST_CASE(make_box),
           TEST_CASE(bad_input_aborts_with_message));
