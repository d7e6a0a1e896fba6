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

/* Asks for every cache line of the `bytes` bytes at `address` (bytes > 0,
 * a compile-time constant), for reading (for_write 0) or for writing (1,
 * also a constant). Addresses a line apart, then the last byte: each line
 * of the span is asked for, a line at most twice, in straight-line code
 * (a loop over the aligned lines ran pyramid(40) 4% more instructions).
 * A macro: GCC deems a function of prefetches alone const and drops its
 * calls. */
#define PREFETCH_SPAN(address, bytes, for_write)                                     \
    do {                                                                             \
        const char *span_start_ = (const char *)(address);                           \
        for (size_t span_at_ = 0; span_at_ < (bytes); span_at_ += PREFETCH_LINE) {    \
            __builtin_prefetch(span_start_ + span_at_, for_write);                   \
        }                                                                            \
        __builtin_prefetch(span_start_ + (bytes) - 1, for_write);                    \
    } while (0)

#endif // #ifndef PREFETCH_H
