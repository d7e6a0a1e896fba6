#include "jostle/polygon.h"
#include <math.h>
#include "base/check.h"
#include "base/memory.h"
#include "geometry/polygon_array.h"

/* Copies a list's vertices into a small stack buffer when they fit, so the
 * seed functions share the array code without allocating in the common case. */
enum { STACK_VERTICES = 64 };

typedef struct {
    vector_t stack[STACK_VERTICES];
    vector_t *vertices;
    size_t count;
} vertex_buffer_t;

/* The vertex at index i, which must not be NULL; `function` is the public
 * function to name in the message. */
static vector_t *get_vertex(list_t *polygon, size_t i, const char *function) {
    vector_t *vertex = list_get(polygon, i);
    if (vertex == NULL) engine_fail(function, "vertex %zu is NULL", i);
    return vertex;
}

static void buffer_load(vertex_buffer_t *buffer, list_t *polygon, const char *function) {
    buffer->count = list_size(polygon);
    buffer->vertices = buffer->count <= STACK_VERTICES
                           ? buffer->stack
                           : memory_alloc(buffer->count * sizeof(vector_t));
    for (size_t i = 0; i < buffer->count; i++) {
        buffer->vertices[i] = *get_vertex(polygon, i, function);
    }
}

static void buffer_release(vertex_buffer_t *buffer) {
    if (buffer->vertices != buffer->stack) memory_free(buffer->vertices);
}

double polygon_array_signed_area(const vector_t *vertices, size_t count) {
    if (count < 3) return 0.0;
    /* A fan from the first vertex: products of absolute coordinates would
     * bury the area in their rounding far from the origin (a unit box at
     * 1e8 m came out 0). The two edges at that vertex add nothing. */
    vector_t origin = vertices[0];
    double twice_area = 0.0;
    for (size_t i = 1; i + 1 < count; i++) {
        twice_area += vec_cross(vec_subtract(vertices[i], origin),
                                vec_subtract(vertices[i + 1], origin));
    }
    return 0.5 * twice_area;
}

vector_t polygon_array_centroid(const vector_t *vertices, size_t count) {
    if (count == 0) return VEC_ZERO;
    /* Work relative to the first vertex: the shoelace sums then do not lose
     * digits to a polygon far from the origin. */
    vector_t origin = vertices[0];
    double twice_area = 0.0;
    vector_t sum = VEC_ZERO;
    for (size_t i = 0; i < count; i++) {
        vector_t a = vec_subtract(vertices[i], origin);
        vector_t b = vec_subtract(vertices[(i + 1) % count], origin);
        double cross = vec_cross(a, b);
        twice_area += cross;
        sum = vec_add(sum, vec_multiply(cross, vec_add(a, b)));
    }
    if (twice_area == 0.0) {
        /* Degenerate: fall back to the vertex mean so callers get a point. */
        vector_t mean = VEC_ZERO;
        for (size_t i = 0; i < count; i++) mean = vec_add(mean, vec_subtract(vertices[i], origin));
        return vec_add(origin, vec_multiply(1.0 / (double)count, mean));
    }
    return vec_add(origin, vec_multiply(1.0 / (3.0 * twice_area), sum));
}

double polygon_array_moment(const vector_t *vertices, size_t count, double mass) {
    vector_t centroid = polygon_array_centroid(vertices, count);
    double numerator = 0.0, denominator = 0.0;
    for (size_t i = 0; i < count; i++) {
        vector_t a = vec_subtract(vertices[i], centroid);
        vector_t b = vec_subtract(vertices[(i + 1) % count], centroid);
        double cross = vec_cross(a, b);
        numerator += cross * (vec_dot(a, a) + vec_dot(a, b) + vec_dot(b, b));
        denominator += cross;
    }
    /* I = rho/12 sum cross (a.a + a.b + b.b), rho = mass / area,
     * area = sum cross / 2; the ratio is winding-independent. */
    return mass * numerator / (6.0 * denominator);
}

/* The least sine of the turn between consecutive edges for a strictly
 * convex vertex. Edges are differences of two vertices, rounded once, so
 * their cross product over their lengths is good to ~1e-15 wherever the
 * polygon is and whatever its size; 1e-12 stays clear of that and still
 * accepts a regular polygon of millions of sides. */
static const double MIN_TURN_SINE = 1e-12;

const char *polygon_array_check(const vector_t *vertices, size_t count) {
    if (count < 3) return "polygon has fewer than 3 vertices";
    for (size_t i = 0; i < count; i++) {
        if (!vec_is_finite(vertices[i])) return "polygon has a vertex that is not finite";
    }
    double area = polygon_array_signed_area(vertices, count);
    /* The squared size, relative to the first vertex like the area. */
    double scale = 0.0;
    for (size_t i = 0; i < count; i++) {
        scale = fmax(scale, vec_get_length_squared(vec_subtract(vertices[i], vertices[0])));
    }
    /* Edges reach twice the size, so their products reach 4 scale: past
     * that the tests below would compare infinities. */
    if (!isfinite(area) || !isfinite(4.0 * scale)) {
        return "polygon is too large: its area overflows";
    }
    if (!(fabs(area) > 1e-12 * scale) || scale == 0.0) return "polygon has zero area";
    double sign = area > 0.0 ? 1.0 : -1.0;
    /* Zero-length edges first: the turn test below would otherwise meet one
     * as the `next` edge and blame convexity. */
    for (size_t i = 0; i < count; i++) {
        vector_t edge = vec_subtract(vertices[(i + 1) % count], vertices[i]);
        if (vec_get_length_squared(edge) <= 1e-24 * scale) return "polygon repeats a vertex";
    }
    for (size_t i = 0; i < count; i++) {
        vector_t edge = vec_subtract(vertices[(i + 1) % count], vertices[i]);
        vector_t next = vec_subtract(vertices[(i + 2) % count], vertices[(i + 1) % count]);
        /* The sine of the turn, not the bare cross product: against the
         * polygon's size, fine polygons' short edges looked straight. A
         * straight angle is refused too: its two edges would share a normal
         * in the narrowphase. */
        double sine = sign * vec_cross(edge, next) / (vec_get_length(edge) * vec_get_length(next));
        if (sine < -MIN_TURN_SINE) {
            return "polygon is not strictly convex: a vertex turns against the winding";
        }
        if (!(sine > MIN_TURN_SINE)) {
            return "polygon is not strictly convex: three consecutive vertices are collinear";
        }
    }
    /* Every turn has the same sign; the polygon could still wind around more
     * than once (a pentagram). Its turning angles then add up to more than
     * 2 pi. */
    double total_turn = 0.0;
    for (size_t i = 0; i < count; i++) {
        vector_t edge = vec_subtract(vertices[(i + 1) % count], vertices[i]);
        vector_t next = vec_subtract(vertices[(i + 2) % count], vertices[(i + 1) % count]);
        total_turn += atan2(fabs(vec_cross(edge, next)), vec_dot(edge, next));
    }
    if (total_turn > 2.0 * M_PI + 1e-6) return "polygon winds around more than once";
    return NULL;
}

double polygon_area(list_t *polygon) {
    REQUIRE_NOT_NULL(polygon);
    vertex_buffer_t buffer;
    buffer_load(&buffer, polygon, __func__);
    double area = polygon_array_signed_area(buffer.vertices, buffer.count);
    buffer_release(&buffer);
    return area;
}

vector_t polygon_centroid(list_t *polygon) {
    REQUIRE_NOT_NULL(polygon);
    vertex_buffer_t buffer;
    buffer_load(&buffer, polygon, __func__);
    vector_t centroid = polygon_array_centroid(buffer.vertices, buffer.count);
    buffer_release(&buffer);
    return centroid;
}

double polygon_moment_of_inertia(list_t *polygon, double mass) {
    REQUIRE_NOT_NULL(polygon);
    REQUIRE(mass > 0.0, "mass must be > 0 (got %g)", mass);
    const char *problem = polygon_check(polygon);
    REQUIRE(problem == NULL, "%s", problem);
    vertex_buffer_t buffer;
    buffer_load(&buffer, polygon, __func__);
    double moment = polygon_array_moment(buffer.vertices, buffer.count, mass);
    buffer_release(&buffer);
    return moment;
}

const char *polygon_check(list_t *polygon) {
    if (polygon == NULL) return "polygon is NULL";
    vertex_buffer_t buffer;
    buffer.count = list_size(polygon);
    for (size_t i = 0; i < buffer.count; i++) {
        if (list_get(polygon, i) == NULL) return "polygon has a NULL vertex";
    }
    buffer_load(&buffer, polygon, __func__);
    const char *problem = polygon_array_check(buffer.vertices, buffer.count);
    buffer_release(&buffer);
    return problem;
}

bool polygon_is_counterclockwise(list_t *polygon) {
    REQUIRE_NOT_NULL(polygon);
    return polygon_area(polygon) > 0.0;
}

void polygon_translate(list_t *polygon, vector_t translation) {
    REQUIRE_NOT_NULL(polygon);
    for (size_t i = 0; i < list_size(polygon); i++) {
        vector_t *vertex = get_vertex(polygon, i, __func__);
        *vertex = vec_add(*vertex, translation);
    }
}

void polygon_rotate(list_t *polygon, double angle, vector_t point) {
    REQUIRE_NOT_NULL(polygon);
    double c = cos(angle), s = sin(angle);
    for (size_t i = 0; i < list_size(polygon); i++) {
        vector_t *vertex = get_vertex(polygon, i, __func__);
        *vertex = vec_add(point, vec_rotate_cs(vec_subtract(*vertex, point), c, s));
    }
}

static vector_t *vector_new(vector_t v) {
    vector_t *copy = memory_alloc(sizeof(vector_t));
    *copy = v;
    return copy;
}

list_t *polygon_make_regular(size_t sides, double radius, vector_t center, double angle) {
    REQUIRE(sides >= 3, "a polygon needs at least 3 sides (got %zu)", sides);
    REQUIRE(radius > 0.0 && isfinite(radius), "radius must be finite and > 0 (got %g)", radius);
    REQUIRE_FINITE_VECTOR(center);
    REQUIRE_FINITE(angle);
    list_t *polygon = list_init(sides, memory_free);
    for (size_t i = 0; i < sides; i++) {
        double theta = angle + 2.0 * M_PI * (double)i / (double)sides;
        list_add(polygon, vector_new(vec_add(center, (vector_t){radius * cos(theta),
                                                                  radius * sin(theta)})));
    }
    return polygon;
}

list_t *polygon_make_box(vector_t center, double half_width, double half_height) {
    REQUIRE(half_width > 0.0 && half_height > 0.0 && isfinite(half_width) &&
                isfinite(half_height),
            "half extents must be finite and > 0 (got %g, %g)", half_width, half_height);
    REQUIRE_FINITE_VECTOR(center);
    list_t *polygon = list_init(4, memory_free);
    list_add(polygon, vector_new(vec_add(center, (vector_t){-half_width, -half_height})));
    list_add(polygon, vector_new(vec_add(center, (vector_t){half_width, -half_height})));
    list_add(polygon, vector_new(vec_add(center, (vector_t){half_width, half_height})));
    list_add(polygon, vector_new(vec_add(center, (vector_t){-half_width, half_height})));
    return polygon;
}
