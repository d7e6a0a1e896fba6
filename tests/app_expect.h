#ifndef APP_EXPECT_H
#define APP_EXPECT_H

/* The check of the app's two test programs (app_units, app_smoke): a
 * failed EXPECT prints its message and counts against the current test,
 * whose runner resets app_failures before it and reads it after. Header
 * only: each program has its own counter. */

#include <stdarg.h>
#include <stdio.h>

static int app_failures;

#if defined(__GNUC__)
__attribute__((format(printf, 1, 2)))
#endif
static void app_fail(const char *format, ...) {
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

#endif // #ifndef APP_EXPECT_H
