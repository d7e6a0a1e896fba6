#include "panels/stats_text.h"
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "panels/text.h"

/* One line, cut to the side bar's width should the numbers ever outgrow it. */
static void put(char line[STATS_LINE_SIZE], const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void put(char line[STATS_LINE_SIZE], const char *format, ...) {
    char text[128];
    va_list args;
    va_start(args, format);
    vsnprintf(text, sizeof(text), format, args);
    va_end(args);
    text_fit(text, LAYOUT_LINE_CHARS);
    memcpy(line, text, strlen(text) + 1);
}

/* A number of at most `width` characters (scientific beyond). */
#define NUMBER(name, value, decimals, width)                                                 \
    char name[24];                                                                           \
    text_number(name, sizeof(name), (value), (decimals), (width))

static void timing_lines(const stats_values_t *v, char lines[STATS_LINES][STATS_LINE_SIZE]) {
    if (v->headless) {
        /* Wall-clock timings would make each run's pictures differ. */
        put(lines[0], "headless: 1/60 s a frame");
        put(lines[1], "physics %d step%s a frame", v->steps, v->steps == 1 ? "" : "s");
        put(lines[2], "(timings: --stats)");
        return;
    }
    NUMBER(fps, v->fps, 1, 6);
    NUMBER(frame, v->frame_ms, 2, 6);
    NUMBER(busy, v->busy_ms, 2, 6);
    NUMBER(physics, v->physics_ms, 3, 7);
    NUMBER(render, v->render_ms, 2, 6);
    put(lines[0], "%s FPS  frame %s ms", fps, frame);
    put(lines[1], "physics %s ms x %d steps", physics, v->steps);
    put(lines[2], "draw %s ms  busy %s ms", render, busy);
}

void stats_text(const stats_values_t *v, char lines[STATS_LINES][STATS_LINE_SIZE]) {
    timing_lines(v, lines);
    if (v->sleeping_on) put(lines[3], "bodies %zu  sleeping %zu", v->bodies, v->sleeping);
    else put(lines[3], "bodies %zu  sleeping off", v->bodies);
    put(lines[4], "collisions %zu (%zu near)", v->collisions, v->near);
    NUMBER(energy, v->energy, 1, 12);
    NUMBER(kinetic, v->kinetic, 1, 12);
    NUMBER(px, v->momentum_x, 2, 7);
    NUMBER(py, v->momentum_y, 2, 7);
    put(lines[5], "energy %s J", energy);
    put(lines[6], "  kinetic %s J", kinetic);
    put(lines[7], "momentum (%s, %s) N s", px, py);
    NUMBER(scale, v->time_scale, 1, 4);
    put(lines[8], "%s  time x%s  gravity %s", v->paused ? "PAUSED " : "running", scale,
        v->gravity_on ? "on" : "off");
}
