#ifndef PREFETCH_H
#define PREFETCH_H

/*
 * Asking the processor ahead for memory a loop will soon touch: the large
 * scenes' steps wait on memory more than they compute (docs/design.md,
 * Memory). A hint only: it never faults, so it may name memory past the end
 * of a buffer, and it changes no result.
 */

#include <stddef.h>
#include <stdint.h>

enum { PREFETCH_LINE = 64 };

/* Asks for every cache line of the `bytes` bytes at `address` (bytes > 0),
 * each once, for reading (for_write 0) or for writing (1, a compile-time
 * constant). A macro: GCC deems a function of prefetches alone const and
 * drops its calls. */
#define PREFETCH_SPAN(address, bytes, for_write)                                     \
    do {                                                                             \
        const char *span_start_ = (const char *)(address);                           \
        const char *span_end_ = span_start_ + (bytes);                               \
        const char *span_line_ = span_start_ - (uintptr_t)span_start_ % PREFETCH_LINE; \
        for (; span_line_ < span_end_; span_line_ += PREFETCH_LINE) {                \
            __builtin_prefetch(span_line_, for_write);                               \
        }                                                                            \
    } while (0)

#endif // #ifndef PREFETCH_H
