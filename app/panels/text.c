#include "panels/text.h"
#include <math.h>
#include <stdio.h>
#include <string.h>

void text_number(char *out, size_t n, double value, int decimals, size_t max_chars) {
    if (!isfinite(value)) {
        snprintf(out, n, "%s", isnan(value) ? "nan" : value > 0 ? "inf" : "-inf");
        return;
    }
    snprintf(out, n, "%.*f", decimals, value);
    /* A value that rounds to zero at this precision is shown unsigned. */
    if (out[0] == '-' && strspn(out + 1, "0.") == strlen(out + 1)) {
        value = 0.0;
        snprintf(out, n, "%.*f", decimals, value);
    }
    /* Too long: thousands (k), millions (M), ... with as many decimals as fit. */
    static const char *const SUFFIXES[] = {"k", "M", "G", "T", "P"};
    double scaled = value;
    for (size_t s = 0; s < sizeof(SUFFIXES) / sizeof(SUFFIXES[0]); s++) {
        if (strlen(out) <= max_chars) return;
        scaled /= 1000.0;
        if (fabs(scaled) >= 999.5) continue; /* the next suffix reads better */
        for (int d = decimals; d >= 0; d--) {
            snprintf(out, n, "%.*f%s", d, scaled, SUFFIXES[s]);
            if (strlen(out) <= max_chars) return;
        }
    }
    if (strlen(out) > max_chars) snprintf(out, n, "%.0e", value);
}

void text_fit(char *text, size_t max_chars) {
    if (strlen(text) <= max_chars) return;
    if (max_chars < 2) {
        text[max_chars] = '\0';
        return;
    }
    text[max_chars - 2] = '.';
    text[max_chars - 1] = '.';
    text[max_chars] = '\0';
}

int text_wrap(const char *text, size_t max_chars, char *lines, size_t line_size,
              int max_lines) {
    int count = 0;
    const char *p = text;
    while (*p == ' ') p++;
    while (*p != '\0' && count < max_lines) {
        char *line = lines + (size_t)count * line_size;
        size_t room = max_chars < line_size - 1 ? max_chars : line_size - 1;
        size_t length = strlen(p);
        size_t take = length;
        if (length > room) {
            /* The last space that keeps the line within room, else a hard cut. */
            take = room;
            for (size_t i = room; i > 0; i--) {
                if (p[i] == ' ') {
                    take = i;
                    break;
                }
            }
        }
        int last = count == max_lines - 1;
        if (last && take < length) {
            /* The rest does not fit: as much as the line holds, ending in
             * ".." (the copy alone would be cut to the line's size without
             * a mark). */
            memcpy(line, p, room);
            line[room] = '\0';
            if (room >= 2) line[room - 2] = line[room - 1] = '.';
        } else {
            memcpy(line, p, take);
            line[take] = '\0';
        }
        count++;
        p += take;
        while (*p == ' ') p++;
        if (last) break;
    }
    return count;
}
