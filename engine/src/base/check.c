#include "base/check.h"
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>

void engine_fail(const char *function, const char *format, ...) {
    va_list args;
    va_start(args, format);
    fprintf(stderr, "engine error in %s: ", function);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    fflush(stderr);
    abort();
}
