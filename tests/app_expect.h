#ifndef APP_EXPECT_H
#define APP_EXPECT_H

/* The check of the app's test programs (app_units, app_smoke, app_raster): a
 * failed EXPECT prints its message and counts against the current test,
 * whose runner resets app_failures before it and reads it after. Header
 * only: each program has its own counter. */

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

/* A program of several files defines APP_EXPECT_SHARED before including
 * this, in every file, and `int app_failures;` in one. */
#ifdef APP_EXPECT_SHARED
extern int app_failures;
#else
static int app_failures;
#endif

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
static inline void app_fail(const char *format, ...) {
    va_list args;
    va_start(args, format);
    printf("    ");
    vprintf(format, args);
    printf("\n");
    va_end(args);
    app_failures++;
}

#define EXPECT(condition, ...)                                                               \
    do {                                                                                     \
        if (!(condition)) app_fail(__VA_ARGS__);                                             \
    } while (0)

typedef struct {
    const char *name;
    void (*run)(void);
} app_test_t;

/* Runs the tests whose names contain filter (all when NULL), a PASS or
 * FAIL line each, then the "N passed, N failed" line; returns the exit
 * status (1 when any failed). */
static inline int app_run_tests(const app_test_t *tests, size_t count, const char *filter) {
    size_t passed = 0, failed = 0;
    for (size_t i = 0; i < count; i++) {
        if (filter != NULL && strstr(tests[i].name, filter) == NULL) continue;
        app_failures = 0;
        tests[i].run();
        printf("%s %s\n", app_failures == 0 ? "PASS" : "FAIL", tests[i].name);
        fflush(stdout);
        if (app_failures == 0) passed++;
        else failed++;
    }
    printf("%zu passed, %zu failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}

#endif // #ifndef APP_EXPECT_H
