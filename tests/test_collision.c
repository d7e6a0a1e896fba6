/* collision.h: the separating axis test, the axis of least overlap and its
 * direction, the depth, and that it allocates nothing. */
#include <stdlib.h>
#include "jostle/jostle.h"
#include "test.h"

static const rgb_color_t GREEN = {0, 1, 0};



static body_t *box(vector_t c, double half_width, double half_height) {
    return body_init(polygon_make_box(c, half_width, half_height), 1.0, GREEN);
}

static body_t *regular(size_t sides, double radius, vector_t c, double angle) {
    return body_init(polygon_make_regular(sides, radius, c, angle), 1.0, GREEN);
}

/* Checks the documented properties of a collision between a and b: a unit
 * axis pointing from a toward b (when their centroids differ along it), a
 * depth >= 0 that is exactly the push-out distance: moving b by a hair more
 * than depth along the axis separates them, a hair less does not. Leaves b
 * where it was. */
static void check_push_out(body_t *a, body_t *b) {
    collision_info_t info = find_collision(a, b);
    CHECK(info.collided);
    if (!info.collided) return;
    CHECK_NEAR(vec_get_length(info.axis), 1.0, 1e-14);
    CHECK(info.depth >= 0.0);
    vector_t start = body_get_centroid(b);
    body_set_centroid(b, vec_add(start, vec_multiply(info.depth + 1e-9, info.axis)));
    CHECK(!find_collision(a, b).collided);
    if (info.depth > 1e-6) {
        body_set_centroid(b, vec_add(start, vec_multiply(info.depth - 1e-6, info.axis)));
        CHECK(find_collision(a, b).collided);
    }
    body_set_centroid(b, start);
}

static void overlapping_squares(void) {
    body_t *a = box(VEC_ZERO, 1, 1);
    body_t *b = box((vector_t){1.5, 0.2}, 1, 1);
    collision_info_t info = find_collision(a, b);
    CHECK(info.collided);
    CHECK_VEC(info.axis, 1, 0, 0); /* x overlap 0.5 < y overlap 1.8 */
    CHECK_NEAR(info.depth, 0.5, 1e-15);
    check_push_out(a, b);
    /* Swapped, the axis turns round; the depth stays. */
    info = find_collision(b, a);
    CHECK(info.collided);
    CHECK_VEC(info.axis, -1, 0, 0);
    CHECK_NEAR(info.depth, 0.5, 1e-15);
    /* Offset mostly vertically: the y axis. */
    body_set_centroid(b, (vector_t){0.3, -1.9});
    info = find_collision(a, b);
    CHECK(info.collided);
    CHECK_VEC(info.axis, 0, -1, 0);
    CHECK_NEAR(info.depth, 0.1, 1e-14);
    check_push_out(a, b);
    body_free(a);
    body_free(b);
}

static void separated_squares(void) {
    body_t *a = box(VEC_ZERO, 1, 1);
    body_t *b = box((vector_t){2.01, 0}, 1, 1);
    CHECK(!find_collision(a, b).collided);
    CHECK(!find_collision(b, a).collided);
    body_set_centroid(b, (vector_t){0.5, -2.5});
    CHECK(!find_collision(a, b).collided);
    body_set_centroid(b, (vector_t){100, 100});
    CHECK(!find_collision(a, b).collided);
    body_free(a);
    body_free(b);
}

static void triangles_separated_by_an_edge_of_either(void) {
    /* A square [-1, 1]^2 and a triangle whose hypotenuse, on x + y = 2.2,
     * faces the square's corner (1, 1): the x and y axes and the triangle's
     * other edges all overlap; only the hypotenuse's normal separates. A
     * test of one polygon's normals alone would miss it either way round. */
    body_t *square = box(VEC_ZERO, 1, 1);
    body_t *triangle = body_init(POLYGON({1.6, 0.6}, {2, 2}, {0.6, 1.6}), 1.0, GREEN);
    aabb_t sb = body_get_bounds(square), tb = body_get_bounds(triangle);
    CHECK(aabb_overlaps(sb, tb));
    CHECK(!find_collision(square, triangle).collided);
    CHECK(!find_collision(triangle, square).collided);
    /* Moved 0.2 closer along both axes the corner pokes in by 0.2 / sqrt 2
     * along the hypotenuse's normal. */
    body_set_centroid(triangle, vec_add(body_get_centroid(triangle), (vector_t){-0.2, -0.2}));
    collision_info_t info = find_collision(square, triangle);
    CHECK(info.collided);
    CHECK_VEC(info.axis, M_SQRT1_2, M_SQRT1_2, 1e-14);
    CHECK_NEAR(info.depth, 0.2 * M_SQRT1_2, 1e-14);
    check_push_out(square, triangle);
    info = find_collision(triangle, square);
    CHECK(info.collided);
    CHECK_VEC(info.axis, -M_SQRT1_2, -M_SQRT1_2, 1e-14);
    check_push_out(triangle, square);
    /* The square's own normal separates the other way: triangle to the
     * right of x = 1. */
    body_t *right = body_init(POLYGON({1.1, -1}, {3, 0}, {1.1, 1}), 1.0, GREEN);
    CHECK(!find_collision(square, right).collided);
    CHECK(!find_collision(right, square).collided);
    body_free(square);
    body_free(triangle);
    body_free(right);
}

static void hexagons_face_to_face(void) {
    /* First vertex at 30 degrees: flat sides at x = +-sqrt(3)/2 R. */
    const double apothem = sqrt(3.0) / 2.0;
    body_t *a = regular(6, 1.0, VEC_ZERO, M_PI / 6);
    body_t *b = regular(6, 1.0, (vector_t){1.7, 0}, M_PI / 6);
    collision_info_t info = find_collision(a, b);
    CHECK(info.collided);
    CHECK_VEC(info.axis, 1, 0, 1e-15);
    CHECK_NEAR(info.depth, 2 * apothem - 1.7, 1e-14);
    check_push_out(a, b);
    body_set_centroid(b, (vector_t){2 * apothem + 1e-9, 0});
    CHECK(!find_collision(a, b).collided);
    /* Along a slanted face (60 degrees) it is the same distance. */
    vector_t direction = {cos(M_PI / 3), sin(M_PI / 3)};
    body_set_centroid(b, vec_multiply(2 * apothem - 0.05, direction));
    info = find_collision(a, b);
    CHECK(info.collided);
    CHECK_VEC(info.axis, direction.x, direction.y, 1e-14);
    CHECK_NEAR(info.depth, 0.05, 1e-13);
    check_push_out(a, b);
    /* A hexagon and a square. */
    body_t *c = box((vector_t){-apothem - 0.4, 0.3}, 0.5, 0.5);
    info = find_collision(a, c);
    CHECK(info.collided);
    CHECK_VEC(info.axis, -1, 0, 1e-15);
    CHECK_NEAR(info.depth, 0.1, 1e-14);
    body_free(a);
    body_free(b);
    body_free(c);
}

static void rotated_shapes_with_overlapping_boxes_can_be_apart(void) {
    /* Squares turned 45 degrees (diamonds of radius 1) with centres 1.1
     * apart on both axes: their bounding boxes overlap, but the diamonds'
     * edge normal (1, 1) / sqrt 2 separates them. */
    body_t *a = box(VEC_ZERO, M_SQRT1_2, M_SQRT1_2);
    body_t *b = box((vector_t){1.1, 1.1}, M_SQRT1_2, M_SQRT1_2);
    CHECK(find_collision(a, b).collided); /* unrotated they overlap */
    body_set_rotation(a, M_PI / 4);
    body_set_rotation(b, M_PI / 4);
    CHECK(aabb_overlaps(body_get_bounds(a), body_get_bounds(b)));
    CHECK(!find_collision(a, b).collided);
    CHECK(!find_collision(b, a).collided);
    /* Turning one back makes them overlap again: the pose is current. */
    body_set_rotation(b, 0.0);
    collision_info_t info = find_collision(a, b);
    CHECK(info.collided);
    CHECK(vec_dot(info.axis, (vector_t){1, 1}) > 0.0);
    check_push_out(a, b);
    /* Long thin sticks crossing at a shallow angle vs. parallel apart. */
    body_t *s1 = box(VEC_ZERO, 3, 0.1);
    body_t *s2 = box((vector_t){0, 0.5}, 3, 0.1);
    CHECK(!find_collision(s1, s2).collided);
    body_set_rotation(s2, 0.3);
    CHECK(find_collision(s1, s2).collided);
    check_push_out(s1, s2);
    body_free(a);
    body_free(b);
    body_free(s1);
    body_free(s2);
}

static void touching_counts_as_colliding(void) {
    /* Shared edge. */
    body_t *a = box((vector_t){0.5, 0.5}, 0.5, 0.5); /* [0,1]^2 */
    body_t *b = box((vector_t){1.5, 0.5}, 0.5, 0.5); /* [1,2]x[0,1] */
    collision_info_t info = find_collision(a, b);
    CHECK(info.collided);
    CHECK_NEAR(info.depth, 0.0, 1e-15);
    CHECK_VEC(info.axis, 1, 0, 0);
    /* Shared corner only. */
    body_set_centroid(b, (vector_t){1.5, 1.5});
    CHECK(find_collision(a, b).collided);
    CHECK_NEAR(find_collision(a, b).depth, 0.0, 1e-15);
    /* A hair apart. */
    body_set_centroid(b, (vector_t){1.5 + 1e-12, 0.5});
    CHECK(!find_collision(a, b).collided);
    body_free(a);
    body_free(b);
}

static void containment(void) {
    /* A small box inside a big one, off-centre: the least push-out is
     * toward the nearer side, 0.8 along +x, whichever way the centroids
     * point. */
    body_t *big = box(VEC_ZERO, 2, 2);
    body_t *small = box((vector_t){1.4, 0}, 0.2, 0.2);
    collision_info_t info = find_collision(big, small);
    CHECK(info.collided);
    CHECK_VEC(info.axis, 1, 0, 0);
    CHECK_NEAR(info.depth, 0.8, 1e-15);
    check_push_out(big, small);
    /* Reversed: the big body (body2) must move 0.8 along -x. */
    info = find_collision(small, big);
    CHECK(info.collided);
    CHECK_VEC(info.axis, -1, 0, 0);
    CHECK_NEAR(info.depth, 0.8, 1e-15);
    check_push_out(small, big);
    /* A triangle inside a hexagon, and two identical concentric shapes. */
    body_t *hexagon = regular(6, 2.0, VEC_ZERO, 0.0);
    body_t *triangle = regular(3, 0.5, (vector_t){0.2, -0.3}, 0.4);
    CHECK(find_collision(hexagon, triangle).collided);
    CHECK(find_collision(triangle, hexagon).collided);
    check_push_out(hexagon, triangle);
    body_t *twin = box(VEC_ZERO, 2, 2);
    info = find_collision(big, twin);
    CHECK(info.collided);
    CHECK_NEAR(info.depth, 4.0, 1e-15);
    CHECK_NEAR(vec_get_length(info.axis), 1.0, 1e-15);
    body_free(big);
    body_free(small);
    body_free(hexagon);
    body_free(triangle);
    body_free(twin);
}

static void axis_points_from_body1_toward_body2(void) {
    /* Pentagons and boxes around a centre at many angles and turns. */
    body_t *center = regular(5, 1.0, VEC_ZERO, 0.1);
    int collided = 0;
    for (int i = 0; i < 24; i++) {
        double angle = 2 * M_PI * i / 24.0;
        vector_t where = vec_multiply(1.1, (vector_t){cos(angle), sin(angle)});
        body_t *other = box(where, 0.6, 0.4);
        body_set_rotation(other, 0.37 * i);
        collision_info_t info = find_collision(center, other);
        if (info.collided) {
            collided++;
            CHECK(vec_dot(info.axis, where) > 0.0);
            CHECK_NEAR(vec_get_length(info.axis), 1.0, 1e-14);
            collision_info_t back = find_collision(other, center);
            CHECK(back.collided);
            CHECK(vec_dot(back.axis, where) < 0.0);
            CHECK_NEAR(back.depth, info.depth, 1e-12);
            check_push_out(center, other);
            check_push_out(other, center);
        }
        body_free(other);
    }
    CHECK(collided == 24); /* their inscribed circles, radii 0.81 and 0.4, overlap */
    body_free(center);
}

static void find_collision_allocates_nothing(void) {
    body_t *a = regular(7, 1.0, VEC_ZERO, 0.0);
    body_t *b = regular(5, 1.0, (vector_t){1.5, 0.2}, 0.3);
    body_t *c = box((vector_t){5, 5}, 1, 1);
    size_t before = engine_allocation_count();
    int hits = 0;
    for (int i = 0; i < 1000; i++) {
        body_set_rotation(b, 0.01 * i); /* world vertices recomputed each time */
        hits += find_collision(a, b).collided;
        hits += find_collision(a, c).collided;
    }
    CHECK(engine_allocation_count() == before);
    CHECK(hits > 0);
    body_free(a);
    body_free(b);
    body_free(c);
}

static void null_body1(void *unused) {
    (void)unused;
    find_collision(NULL, box(VEC_ZERO, 1, 1));
}
static void null_body2(void *unused) {
    (void)unused;
    find_collision(box(VEC_ZERO, 1, 1), NULL);
}

static void bad_input_aborts_with_message(void) {
    CHECK_DIES(null_body1, NULL, "engine error in find_collision:", "body1 is NULL");
    CHECK_DIES(null_body2, NULL, "engine error in find_collision:", "body2 is NULL");
}

TEST_SUITE(collision, TEST_CASE(overlapping_squares), TEST_CASE(separated_squares),
           TEST_CASE(triangles_separated_by_an_edge_of_either), TEST_CASE(hexagons_face_to_face),
           TEST_CASE(rotated_shapes_with_overlapping_boxes_can_be_apart),
           TEST_CASE(touching_counts_as_colliding), TEST_CASE(containment),
           TEST_CASE(axis_points_from_body1_toward_body2),
           TEST_CASE(find_collision_allocates_nothing), TEST_CASE(bad_input_aborts_with_message));
