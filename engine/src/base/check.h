#ifndef CHECK_H
#define CHECK_H

/* Programmer-error checks that stay on in release builds: a failed check
 * prints "engine error in FUNCTION: MESSAGE" on stderr and aborts, so a bad
 * argument is reported where it entered the engine, not steps later as a NaN. */

#include <math.h>
#include <stddef.h>

#if defined(__GNUC__)
__attribute__((noreturn, format(printf, 2, 3)))
#endif
void engine_fail(const char *function, const char *format, ...);

#define REQUIRE(condition, ...)                                                              \
    do {                                                                                     \
        if (!(condition)) engine_fail(__func__, __VA_ARGS__);                                \
    } while (0)

#define REQUIRE_NOT_NULL(pointer) REQUIRE((pointer) != NULL, "%s is NULL", #pointer)

#define REQUIRE_FINITE(value) REQUIRE(isfinite(value), "%s is not finite (%g)", #value, (double)(value))

#define REQUIRE_FINITE_VECTOR(v)                                                             \
    REQUIRE(isfinite((v).x) && isfinite((v).y), "%s is not finite (%g, %g)", #v, (v).x, (v).y)

#endif // #ifndef CHECK_H
