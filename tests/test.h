#ifndef TEST_H
#define TEST_H

/*
 * A small test harness in the spirit of Box2D's: no framework, a few macros.
 * Each test is a function; the runner forks a child per test so a crash or an
 * abort fails that test only. A CHECK that fails prints where and why and
 * marks the test failed; the test goes on so one run shows every failure.
 */

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>
#include "jostle/list.h"
#include "jostle/scene.h"
#include "jostle/vector.h"

typedef struct {
    const char *name;
    void (*run)(void);
} test_case_t;

typedef struct {
    const char *name;
    const test_case_t *cases;
    size_t count;
} test_suite_t;

#define TEST_CASE(function) {#function, function}
#define TEST_SUITE(suite_name, ...)                                                          \
    static const test_case_t suite_name##_cases[] = {__VA_ARGS__};                           \
    const test_suite_t suite_##suite_name = {#suite_name, suite_name##_cases,                \
                                             sizeof(suite_name##_cases) /                    \
                                                 sizeof(suite_name##_cases[0])}

extern int test_failures;

void test_fail(const char *file, int line, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#define CHECK(condition)                                                                     \
    do {                                                                                     \
        if (!(condition)) test_fail(__FILE__, __LINE__, "CHECK(%s) failed", #condition);     \
    } while (0)

/* |actual - expected| <= tolerance (absolute). */
#define CHECK_NEAR(actual, expected, tolerance)                                              \
    do {                                                                                     \
        double actual_ = (actual), expected_ = (expected), tolerance_ = (tolerance);         \
        if (!(fabs(actual_ - expected_) <= tolerance_))                                      \
            test_fail(__FILE__, __LINE__, "%s = %.17g, expected %.17g within %g", #actual,   \
                      actual_, expected_, tolerance_);                                       \
    } while (0)

/* |actual - expected| <= tolerance |expected| (relative). */
#define CHECK_RELATIVE(actual, expected, tolerance)                                          \
    do {                                                                                     \
        double actual_ = (actual), expected_ = (expected), tolerance_ = (tolerance);         \
        if (!(fabs(actual_ - expected_) <= tolerance_ * fabs(expected_)))                    \
            test_fail(__FILE__, __LINE__, "%s = %.17g, expected %.17g within %g relative",   \
                      #actual, actual_, expected_, tolerance_);                              \
    } while (0)

/* |actual - expected| <= tolerance for both components of a vector_t. */
#define CHECK_VEC(actual, ex, ey, tolerance)                                                 \
    do {                                                                                     \
        vector_t v_ = (actual);                                                              \
        CHECK_NEAR(v_.x, (ex), (tolerance));                                                 \
        CHECK_NEAR(v_.y, (ey), (tolerance));                                                 \
    } while (0)

/* A new list (freer free) holding heap copies of the n points, in order. */
list_t *test_make_polygon(const vector_t *points, size_t n);

/* test_make_polygon of the listed points: POLYGON({0, 0}, {1, 0}, {0, 1}). */
#define POLYGON(...)                                                                         \
    test_make_polygon((const vector_t[]){__VA_ARGS__},                                       \
                      sizeof((const vector_t[]){__VA_ARGS__}) / sizeof(vector_t))

/* True when every block allocated so far is freed or still reachable
 * (LeakSanitizer, when built with AddressSanitizer as make check does;
 * always true otherwise). The runner forks each test, so a test sees only
 * its own blocks. */
bool test_no_leaks(void);

/* Whether `ticks` ticks of dt of a warm scene allocate nothing, every one
 * of them with contacts in its record (read, so the record has its size). */
bool test_warm_ticks_allocate_nothing(scene_t *scene, int ticks, double dt);

/* Runs function(argument) in a child process and checks that it aborts with
 * a message on stderr containing every one of the given substrings. */
bool test_dies_with(void (*function)(void *), void *argument, const char *const *substrings,
                    size_t count);

/* Defines `static void name(void *)` making one call, for CHECK_DIES:
 * BAD_CALL(free_null, scene_free(NULL)). */
#define BAD_CALL(name, ...)                                                                  \
    static void name(void *unused) {                                                         \
        (void)unused;                                                                        \
        __VA_ARGS__;                                                                         \
    }

#define CHECK_DIES(function, argument, ...)                                                  \
    do {                                                                                     \
        const char *const expected_[] = {__VA_ARGS__};                                       \
        if (!test_dies_with(function, argument, expected_,                                   \
                            sizeof(expected_) / sizeof(expected_[0])))                       \
            test_fail(__FILE__, __LINE__, "%s(%s) did not abort with the expected message",  \
                      #function, #argument);                                                 \
    } while (0)

/* Runs the suites (only tests whose "suite.name" contains filter, when not
 * NULL) and prints one line per test and a final "N passed, N failed".
 * Returns the process exit status. */
int test_run_suites(const test_suite_t *const *suites, size_t count, const char *filter);

#endif // #ifndef TEST_H
