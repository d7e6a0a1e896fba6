#ifndef SANDBOX_TEXT_H
#define SANDBOX_TEXT_H

/*
 * Numbers and lines for the side bar, whose lines hold LAYOUT_LINE_CHARS
 * characters of the 8x8 font. Plain C (no SDL), so the tests can check that
 * every line fits. Every number the side bar shows goes through
 * text_number: a value that rounds to zero shows as "0.00", never "-0.00".
 */

#include <stddef.h>

/* value with `decimals` decimals into out (size n); when that takes more than
 * max_chars characters, in thousands, millions, ... ("123.5k", "12M"). */
void text_number(char *out, size_t n, double value, int decimals, size_t max_chars);

/* Cuts text to at most max_chars characters, ending in ".." when it cut. */
void text_fit(char *text, size_t max_chars);

/* Breaks text at spaces into at most max_lines lines of at most max_chars
 * characters (each of `line_size` bytes); the last line is cut with ".."
 * if the text does not fit. Returns the number of lines. */
int text_wrap(const char *text, size_t max_chars, char *lines, size_t line_size,
              int max_lines);

#endif
