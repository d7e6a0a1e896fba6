/*
 * make stability: numerical stability on stiff and extreme cases, measured
 * beside theory and beside Chipmunk2D and Box2D 2.4 (docs/stability.md).
 *
 * Every case that the peers can run is a scene of tests/bench/bench_scenes.h:
 * this program runs it on this engine in-process, through the same code as
 * build/bench/bench_engine (tests/bench/bench_ours.h), and takes the peers'
 * figures from the key=value lines their benchmark programs printed in the
 * same run (tests/stability/stability.sh collects them, --peers FILE). The
 * cases only this engine has (its integrators' theory, the seed's pair
 * collisions, bad input, a long run, determinism) use the public API
 * directly. Each case has a verdict; --check asserts them (make check runs
 * the --quick version) and ends with "N passed, N failed".
 *
 *   stability [--quick] [--check] [--peers FILE] [--doc FILE] [--out DIR]
 *             [--raw FILE]
 *   stability --child-hash STEPS    (the determinism scene in a process of
 *                                    its own: prints its final hash)
 */
#include <errno.h>
#include <inttypes.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#ifndef BENCH_ENGINE_VERSION
#define BENCH_ENGINE_VERSION "unknown"
#endif
#include "bench_ours.h"
#include "theory.h"

/* ---- options ---- */

static bool quick = false, check = false;
static const char *doc_path = NULL, *out_dir = NULL, *raw_path = NULL;
static double run_started = 0.0;
static bool quiet = false; /* the second building of the tables */

static void progress(const char *format, ...) {
    if (quiet) return;
    va_list args;
    va_start(args, format);
    fprintf(stderr, "[stability %6.1f s] ", (bench_now_ms() - run_started) / 1000.0);
    vfprintf(stderr, format, args);
    fprintf(stderr, "\n");
    va_end(args);
}

/* ---- the lines: every figure, ours and the peers', as the benchmark
 * programs print them: engine=NAME scene=NAME size=X [key=value ...] ---- */

enum { MAX_LINES = 8192 };
static char *lines[MAX_LINES];
static int line_count = 0;

static const char *add_line(const char *format, ...) {
    if (line_count == MAX_LINES) {
        fprintf(stderr, "stability: too many lines\n");
        exit(2);
    }
    char buffer[2048];
    va_list args;
    va_start(args, format);
    vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    lines[line_count] = strdup(buffer);
    return lines[line_count++];
}

/* The value of key in line (up to the next space), or NULL. */
static const char *field(const char *line, const char *key, char *value, size_t size) {
    if (line == NULL) return NULL;
    size_t length = strlen(key);
    for (const char *p = line; (p = strstr(p, key)) != NULL; p += length) {
        if ((p == line || p[-1] == ' ') && p[length] == '=') {
            const char *start = p + length + 1, *end = strchr(start, ' ');
            size_t n = end ? (size_t)(end - start) : strlen(start);
            if (n >= size) n = size - 1;
            memcpy(value, start, n);
            value[n] = '\0';
            return value;
        }
    }
    return NULL;
}

static double num(const char *line, const char *key) {
    char value[128];
    if (field(line, key, value, sizeof value) == NULL) return NAN;
    char *end;
    double x = strtod(value, &end);
    return end == value ? NAN : x;
}

/* The first line of engine, scene and size (as %g) with, when given,
 * key=value among its fields too. */
static const char *find(const char *engine, const char *scene, double size, const char *key,
                        const char *value) {
    char size_text[64];
    snprintf(size_text, sizeof size_text, "%g", size);
    for (int i = 0; i < line_count; i++) {
        char got[128];
        if (field(lines[i], "engine", got, sizeof got) == NULL || strcmp(got, engine) != 0)
            continue;
        if (field(lines[i], "scene", got, sizeof got) == NULL || strcmp(got, scene) != 0) continue;
        if (field(lines[i], "size", got, sizeof got) == NULL || strcmp(got, size_text) != 0)
            continue;
        if (key != NULL && (field(lines[i], key, got, sizeof got) == NULL ||
                            strcmp(got, value) != 0))
            continue;
        return lines[i];
    }
    return NULL;
}

static void load_lines(const char *path) {
    FILE *file = fopen(path, "r");
    if (file == NULL) {
        fprintf(stderr, "stability: cannot read %s: %s\n", path, strerror(errno));
        return;
    }
    char buffer[4096];
    int loaded = 0;
    while (fgets(buffer, sizeof buffer, file)) {
        buffer[strcspn(buffer, "\n")] = '\0';
        if (strncmp(buffer, "engine=", 7) == 0) {
            add_line("%s", buffer);
            loaded++;
        }
    }
    fclose(file);
    progress("read %d lines of the peers from %s", loaded, path);
}

/* ---- this engine's runs of the bench scenes ---- */

/* The integrator's name in the lines and on bench_engine's command line. */
static const char *integrator_key(int integrator) {
    static const char *const keys[INTEGRATOR_COUNT] = {
        "seed", "explicit-euler", "symplectic-euler", "velocity-verlet", "rk4", "symplectic4",
        "implicit-euler"};
    return integrator < 0 || integrator >= INTEGRATOR_COUNT ? "seed" : keys[integrator];
}

/* Runs one case of a scene with ours (or ours-sleeping) under an integrator
 * (-1: the default) and adds its line, as bench_engine prints it plus
 * integrator=NAME; steps 0 keeps the scene's own count. */
/* Runs are memoised: the tables are built twice (before and after the
 * peers' figures arrive), the measuring done once. */
enum { MAX_RUNS = 4096 };
static struct {
    char key[160];
    const char *line;
} runs[MAX_RUNS];
static int run_count = 0;

static const char *run_ours(const bench_ops_t *ops, bench_scene_id_t scene, double size,
                            double dt, int integrator, int steps) {
    char key[160];
    snprintf(key, sizeof key, "%s|%d|%.17g|%.17g|%d|%d", ops->name, (int)scene, size, dt,
             integrator, steps);
    for (int i = 0; i < run_count; i++) {
        if (strcmp(runs[i].key, key) == 0) return runs[i].line;
    }
    bench_integrator = integrator;
    bench_steps = steps;
    bench_case_t c = {scene, size, dt};
    bench_run_t run;
    memset(&run, 0, sizeof run);
    bench_runners[scene](ops, &c, &run);
    bench_integrator = -1;
    bench_steps = 0;
    const char *line = add_line("engine=%s scene=%s size=%g integrator=%s ms=%.4g %s", ops->name,
                                bench_scene_names[scene], size, integrator_key(integrator),
                                run.step_ms, run.quality);
    if (run_count < MAX_RUNS) {
        snprintf(runs[run_count].key, sizeof runs[run_count].key, "%s", key);
        runs[run_count++].line = line;
    }
    return line;
}

/* The same scene over sizes, for the tunnel-like scenes: the first size
 * that tunnelled (INFINITY when none) and the largest return speed. */
typedef struct {
    double first, back, max_depth;
} tunnel_summary_t;

static tunnel_summary_t summarise_tunnel(const char *engine, const char *scene,
                                         const double *sizes, int count, const char *key,
                                         const char *value) {
    tunnel_summary_t s = {INFINITY, 0.0, 0.0};
    for (int i = 0; i < count; i++) {
        const char *line = find(engine, scene, sizes[i], key, value);
        if (line == NULL) {
            s.first = NAN;
            return s;
        }
        char got[64];
        if (field(line, "tunnelled", got, sizeof got) && atoi(got) > 0 && !(sizes[i] >= s.first))
            s.first = sizes[i];
        double back = num(line, "max_return_speed"), depth = num(line, "max_depth");
        if (back > s.back) s.back = back;
        if (depth > s.max_depth) s.max_depth = depth;
    }
    return s;
}

/* ---- the report: sections of tables, each row a case or part of one,
 * with a verdict that --check asserts when the row says so ---- */

enum { MAX_COLUMNS = 7, MAX_ROWS = 48, MAX_SECTIONS = 16, CELL = 320 };

typedef struct {
    char id[96];  /* the check's name: stability.ID */
    char cell[MAX_COLUMNS][CELL];
    int asserted; /* the verdict is checked */
    bool pass;
} row_t;

typedef struct {
    char title[160];
    char text[4096];  /* before the table */
    int columns;
    char header[MAX_COLUMNS][96];
    row_t rows[MAX_ROWS];
    int row_count;
    char notes[6144]; /* after the table */
} table_t;

typedef struct {
    char title[128];
    char text[4096];
    table_t *tables[12];
    int table_count;
} section_t;

static section_t sections[MAX_SECTIONS];
static int section_count = 0;

static section_t *new_section(const char *title, const char *text) {
    section_t *s = &sections[section_count++];
    memset(s, 0, sizeof *s);
    snprintf(s->title, sizeof s->title, "%s", title);
    snprintf(s->text, sizeof s->text, "%s", text);
    return s;
}

/* A table with the given headers (NULL-terminated). */
static table_t *new_table(section_t *section, const char *title, const char *text, ...) {
    table_t *t = calloc(1, sizeof *t);
    section->tables[section->table_count++] = t;
    snprintf(t->title, sizeof t->title, "%s", title ? title : "");
    snprintf(t->text, sizeof t->text, "%s", text ? text : "");
    va_list args;
    va_start(args, text);
    const char *h;
    while ((h = va_arg(args, const char *)) != NULL && t->columns < MAX_COLUMNS) {
        snprintf(t->header[t->columns++], sizeof t->header[0], "%s", h);
    }
    va_end(args);
    return t;
}

static row_t *new_row(table_t *t, const char *id) {
    if (t->row_count == MAX_ROWS) {
        fprintf(stderr, "stability: too many rows in %s\n", t->title);
        exit(2);
    }
    row_t *r = &t->rows[t->row_count++];
    memset(r, 0, sizeof *r);
    snprintf(r->id, sizeof r->id, "%s", id ? id : "");
    r->asserted = id != NULL && id[0] != '\0';
    r->pass = true;
    return r;
}

static void set_cell(row_t *r, int column, const char *format, ...) {
    va_list args;
    va_start(args, format);
    vsnprintf(r->cell[column], CELL, format, args);
    va_end(args);
}

static void append_text(char *text, size_t size, const char *format, ...) {
    size_t used = strlen(text);
    va_list args;
    va_start(args, format);
    vsnprintf(text + used, size - used, format, args);
    va_end(args);
}
#define NOTE(t, ...) append_text((t)->notes, sizeof (t)->notes, __VA_ARGS__)

/* A number for the tables: 4 significant digits, inf and nan spelled out. */
static const char *g4(char *buffer, double x) {
    if (isnan(x)) return strcpy(buffer, "-");
    if (isinf(x)) return strcpy(buffer, x > 0 ? "inf" : "-inf");
    snprintf(buffer, 32, "%.4g", x);
    return buffer;
}
/* Rotating buffers, so that several numbers fit in one printf. */
static const char *G(double x) {
    static char buffers[16][32];
    static int next = 0;
    next = (next + 1) % 16;
    return g4(buffers[next], x);
}
static const char *E(double x) { /* 2 significant digits, for errors */
    static char buffers[16][32];
    static int next = 0;
    next = (next + 1) % 16;
    if (isnan(x)) return strcpy(buffers[next], "-");
    snprintf(buffers[next], 32, "%.2g", x);
    return buffers[next];
}

static bool have_peers = false;
#define NOT_RUN "not run"

/* ==== 1. Stiff springs ==== */

typedef struct {
    const char *scene;
    bench_scene_id_t id;
    double size, zeta;
} spring_case_t;

/* The limit cell: "none (unstable from 0.1)", "above 3" or the value. */
static const char *limit_text(char *buffer, double limit) {
    if (isnan(limit)) return strcpy(buffer, NOT_RUN);
    if (limit == 0.0) return strcpy(buffer, "none: unstable from 0.1");
    if (isinf(limit)) return strcpy(buffer, "none: stable to 3");
    snprintf(buffer, 64, "%.4f", limit);
    return buffer;
}

static void spring_table(section_t *section, const spring_case_t *sc, const char *title,
                         const char *text) {
    table_t *t = new_table(section, title, text, "scheme", "measured limit of omega dt",
                           "theory", "verdict",
                           "energy factor per step at omega dt = 0.5 / 1 / 2 (measured; theory)",
                           NULL);
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        progress("springs: %s size %g, %s", sc->scene, sc->size, integrator_get_name(i));
        const char *line = run_ours(&ours_ops, sc->id, sc->size, BENCH_DT, i, 0);
        double limit = num(line, "limit"), theory = theory_limit(i, sc->zeta, 0.1, 3.0);
        char id[96], buf[64], tbuf[64];
        snprintf(id, sizeof id, "springs.%s_%g.%s", sc->scene, sc->size, integrator_key(i));
        row_t *r = new_row(t, id);
        set_cell(r, 0, "%s", integrator_get_name(i));
        set_cell(r, 1, "%s", limit_text(buf, limit));
        double g[3] = {num(line, "growth_0.5"), num(line, "growth_1"), num(line, "growth_2")};
        double gt[3] = {theory_growth(i, 0.5, sc->zeta), theory_growth(i, 1.0, sc->zeta),
                        theory_growth(i, 2.0, sc->zeta)};
        set_cell(r, 4, "%s / %s / %s; %s / %s / %s", G(g[0]), G(g[1]), G(g[2]), G(gt[0]),
                 G(gt[1]), G(gt[2]));
        if (theory == 0.0) {
            /* No stable range: the growth per step against the formula. */
            double worst = 0.0;
            for (int k = 0; k < 3; k++) worst = fmax(worst, fabs((g[k] - 1.0) / (gt[k] - 1.0) - 1.0));
            set_cell(r, 2, "none: energy x %s per step",
                     i == INTEGRATOR_SEED && sc->zeta == 0.0   ? "(1 + (omega dt)^2 / 2)"
                     : i == INTEGRATOR_EXPLICIT_EULER && sc->zeta == 0.0 ? "(1 + (omega dt)^2)"
                                                                      : "det of its step");
            r->pass = limit == 0.0 && worst < 0.05;
            set_cell(r, 3, "%s: unstable at every step tried; growth within %.2g%% of the formula",
                     r->pass ? "as theory" : "FAILS", 100.0 * worst);
        } else if (isinf(theory)) {
            set_cell(r, 2, "none: stable to 3");
            r->pass = isinf(limit);
            set_cell(r, 3, "%s", r->pass ? "as theory: stable over the sweep" : "FAILS");
        } else {
            double err = limit / theory - 1.0;
            double documented = sc->zeta == 0.0 ? integrator_get_stability_limit(i) : NAN;
            if (!isnan(documented)) {
                set_cell(r, 2, "%s (integrator_get_stability_limit)", limit_text(tbuf, documented));
            } else {
                set_cell(r, 2, "%s (its step's matrix)", limit_text(tbuf, theory));
            }
            r->pass = fabs(err) < 0.05;
            set_cell(r, 3, "%s: limit found, %+.2f%% from theory", r->pass ? "as theory" : "FAILS",
                     100.0 * err);
        }
    }
    /* The peers: their springs are their own schemes. */
    const char *peer_names[2] = {"chipmunk", "box2d"};
    const char *peer_labels[2] = {"Chipmunk2D cpDampedSpring", "Box2D 2.4 b2DistanceJoint (soft)"};
    const char *peer_theory[2] = {
        "2 undamped: the spring's impulse is taken at the positions after the drift (symplectic "
        "Euler); its damping is exact (exponential)",
        "none: a soft constraint, solved implicitly (it damps)"};
    for (int k = 0; k < 2; k++) {
        const char *line = find(peer_names[k], sc->scene, sc->size, NULL, NULL);
        row_t *r = new_row(t, NULL);
        char buf[64];
        set_cell(r, 0, "%s", peer_labels[k]);
        set_cell(r, 1, "%s", line ? limit_text(buf, num(line, "limit")) : NOT_RUN);
        set_cell(r, 2, "%s", peer_theory[k]);
        set_cell(r, 3, "%s", line ? "(measured)" : "");
        if (line) {
            set_cell(r, 4, "%s / %s / %s", G(num(line, "growth_0.5")), G(num(line, "growth_1")),
                     G(num(line, "growth_2")));
        }
    }
}

static void springs_section(void) {
    section_t *s = new_section(
        "Stiff springs",
        "Scenes `spring`, `springpair` and `chain` of tests/bench/bench_scenes.h. A run lasts "
        "2000 steps of 1/60 s (1000 with --quick) with the stiffness chosen so that omega dt, "
        "omega the highest frequency, takes each value from 0.1 to 3 in steps of 0.01 (0.05); "
        "the motion stays along the springs. A run is unstable when the energy about equilibrium "
        "is not finite, passes 1e40 times the start's, or its largest value over the second half "
        "of the run is more than twice that over the first (a bounded oscillation, however "
        "eccentric, has the same largest value in both). The measured limit is the first "
        "unstable omega dt of the sweep, refined by bisection to 1e-5. The energy factor per step "
        "is exp of the least-squares slope of ln E over the run. Theory: the spectral radius "
        "squared of each scheme's step applied to x'' = -omega^2 x - 2 zeta omega x' "
        "(tests/stability/theory.h, from the formulas of docs/design.md); undamped, its limits "
        "are integrator_get_stability_limit's. Verdict: the measured limit within 5% of theory, "
        "or, for a scheme with no stable step, unstable everywhere with its energy factor within "
        "5% of theory (on the factor minus 1). Our springs are `create_spring` (rest length 0) "
        "and, for damping, `create_drag` on the moving body; the peers' fixed end sits 1 m away "
        "with a 1 m rest length, the same linear force along the spring.\n\n"
        "![Energy factor per step of an undamped spring against omega dt: each integrator's "
        "theory (lines; symplectic Euler's lies under velocity Verlet's) and this engine's "
        "runs (dots), with the peers' runs](stability/springs.svg)");
    const spring_case_t cases[] = {
        {"spring", SCENE_SPRING, 0.0, 0.0},
        {"spring", SCENE_SPRING, 0.1, 0.1},
        {"spring", SCENE_SPRING, 0.5, 0.5},
        {"springpair", SCENE_SPRINGPAIR, 1000.0, 0.0},
        {"chain", SCENE_CHAIN, 20.0, 0.0},
    };
    const char *titles[] = {
        "A 1 kg body on a spring to an anchor of infinite mass",
        "The same spring damped, zeta = 0.1 (explicit damping: the drag force at the step's "
        "velocities)",
        "The same spring damped, zeta = 0.5",
        "A 1 kg body on a spring to a free 1000 kg body (omega from the reduced mass)",
        "A chain of 20 bodies of 1 kg on stiff springs hanging from an anchor, under gravity "
        "(omega the top mode: 2 sqrt(k/m) sin(39 pi / 82) = 1.996 sqrt(k/m))",
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        spring_table(s, &cases[i], titles[i], NULL);
    }
    NOTE(s->tables[0],
         "Implicit Euler is stable over the whole sweep and beyond (section 10 runs it to omega "
         "dt = 2000): each step divides the spring's energy by 1 + "
         "(omega dt)^2, which is what Box2D 2.4's soft distance joint measures at omega dt = 1 "
         "and 2; both take the spring's force at the end of the step.\n");
    table_t *damped = s->tables[1];
    NOTE(damped,
         "Explicit damping moves every limit: symplectic Euler's falls to 2 (sqrt(1 + zeta^2) - "
         "zeta) (1.81 at zeta = 0.1, 1.24 at 0.5), and the schemes that gain energy undamped "
         "become stable below a step set by the damping (explicit Euler for omega dt < 2 zeta, "
         "the seed scheme for omega dt < 4 zeta): the drag removes energy faster than the step "
         "adds it.\n");
}

/* ==== 2. Mass ratios ==== */

static const char *stack2_text(const char *line, bool *holds) {
    static char buffers[8][CELL];
    static int next = 0;
    next = (next + 1) % 8;
    if (line == NULL) return NOT_RUN;
    double pg = num(line, "pen_ground_a"), pab = num(line, "pen_a_b");
    bool on = num(line, "b_on_a") == 1.0;
    bool ok = on && pg < 0.01 && pab < 0.01;
    if (holds) *holds = ok;
    snprintf(buffers[next], CELL, "%s: pen %s / %s m", ok ? "holds" : (on ? "on, too deep" : "falls off"),
             G(pg), on ? G(pab) : "-");
    return buffers[next];
}

/* The largest r of `ratios` up to which every stack holds. */
static double holds_to(const char *engine, const double *ratios, int count) {
    double best = 0.0;
    for (int i = 0; i < count; i++) {
        bool holds = false;
        stack2_text(find(engine, "stack2", ratios[i], NULL, NULL), &holds);
        if (!holds) break;
        best = ratios[i];
    }
    return best;
}

/* The largest r of `ratios` up to which B stays on A, however deep. */
static double stays_to(const char *engine, const double *ratios, int count) {
    double best = 0.0;
    for (int i = 0; i < count; i++) {
        if (num(find(engine, "stack2", ratios[i], NULL, NULL), "b_on_a") != 1.0) break;
        best = ratios[i];
    }
    return best;
}

/* One seed-style pair collision (create_physics_collision, contacts off):
 * box 1 of mass m1 at 1 m/s toward box 2 of mass m2 (INFINITY: a wall) at
 * rest, elasticity e; the velocities after against the 1D formula. */
typedef struct {
    double vel_err, momentum_err, energy_err;
    bool wall_still; /* m2 infinite: its velocity and centroid exactly unchanged */
} seed_result_t;

static seed_result_t seed_pair(double m1, double m2, double e) {
    scene_t *scene = scene_init();
    rgb_color_t gray = {0.5, 0.5, 0.5};
    body_t *a = body_init(polygon_make_box((vector_t){-1.2, 0.0}, 0.5, 0.5), m1, gray);
    body_t *b = body_init(polygon_make_box((vector_t){0.0, 0.0}, 0.5, 0.5), m2, gray);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    const double v1 = 1.0;
    body_set_velocity(a, (vector_t){v1, 0.0});
    create_physics_collision(scene, a, b, e);
    vector_t b0 = body_get_centroid(b);
    for (int i = 0; i < 60; i++) scene_tick(scene, 1.0 / 60.0);
    double u1 = body_get_velocity(a).x, u2 = body_get_velocity(b).x;
    seed_result_t r;
    if (isinf(m2)) {
        r.vel_err = fabs(u1 + e * v1) / v1;
        r.momentum_err = NAN;
        r.energy_err = (u1 * u1 - e * e * v1 * v1) / (v1 * v1);
        r.wall_still = u2 == 0.0 && body_get_velocity(b).y == 0.0 &&
                       body_get_centroid(b).x == b0.x && body_get_centroid(b).y == b0.y;
    } else {
        double p = m1 * v1, M = m1 + m2;
        double w1 = (p - m2 * e * v1) / M, w2 = (p + m1 * e * v1) / M;
        r.vel_err = fmax(fabs(u1 - w1), fabs(u2 - w2)) / v1;
        r.momentum_err = fabs(m1 * u1 + m2 * u2 - p) / p;
        double exact = 0.5 * m1 * w1 * w1 + 0.5 * m2 * w2 * w2;
        r.energy_err = (0.5 * m1 * u1 * u1 + 0.5 * m2 * u2 * u2 - exact) / (0.5 * m1 * v1 * v1);
        r.wall_still = true;
    }
    scene_free(scene);
    return r;
}

static void mass_section(void) {
    section_t *s = new_section("Mass ratios", "");
    /* stack2 */
    const double ratios[] = {1, 10, 100, 1000, 10000};
    table_t *t = new_table(
        s, "A heavy box on a light one (`stack2`)",
        "Box B of density r on box A of density 1 on the ground, 10 s. Holds: B still on A "
        "(|dx| < 0.5, dy > 0.9) and both penetrations (ground-A / A-B, at the end) under 0.01 m. "
        "Box2D runs with its default sleeping and without (box2d-nosleep).",
        "r", "this engine", "verdict", "Chipmunk2D", "Box2D 2.4", "Box2D 2.4, no sleeping", NULL);
    for (int i = 0; i < 5; i++) {
        progress("mass ratios: stack2 r = %g", ratios[i]);
        const char *line = run_ours(&ours_ops, SCENE_STACK2, ratios[i], BENCH_DT, -1, 0);
        char id[64];
        snprintf(id, sizeof id, "mass.stack2_%g", ratios[i]);
        row_t *r = new_row(t, id);
        set_cell(r, 0, "%g", ratios[i]);
        set_cell(r, 1, "%s", stack2_text(line, &r->pass));
        set_cell(r, 2, "%s", r->pass ? "holds" : "FAILS");
        set_cell(r, 3, "%s", stack2_text(find("chipmunk", "stack2", ratios[i], NULL, NULL), NULL));
        set_cell(r, 4, "%s", stack2_text(find("box2d", "stack2", ratios[i], NULL, NULL), NULL));
        set_cell(r, 5, "%s",
                 stack2_text(find("box2d-nosleep", "stack2", ratios[i], NULL, NULL), NULL));
    }
    NOTE(t, "Holds to r = %g here; Chipmunk2D to r = %g, Box2D 2.4 to r = %g (%g without "
            "sleeping). Counting only whether B stays on A: Chipmunk2D to r = %g, Box2D 2.4 to "
            "r = %g (%g without sleeping); Box2D's penetrations include its polygons' 1 cm "
            "skin.\n",
         holds_to("ours", ratios, 5), have_peers ? holds_to("chipmunk", ratios, 5) : NAN,
         have_peers ? holds_to("box2d", ratios, 5) : NAN,
         have_peers ? holds_to("box2d-nosleep", ratios, 5) : NAN,
         have_peers ? stays_to("chipmunk", ratios, 5) : NAN,
         have_peers ? stays_to("box2d", ratios, 5) : NAN,
         have_peers ? stays_to("box2d-nosleep", ratios, 5) : NAN);

    /* heavytop */
    const double tops[] = {10, 100, 1000};
    t = new_table(
        s, "A pyramid of 10 rows whose top box is r times heavier (`heavytop`)",
        "55 unit boxes, the top one of density r, 10 s. Stands: the top box within 0.5 m of where "
        "it started and the deepest penetration under 0.01 m (asserted). At rest: no box faster "
        "than 0.01 m/s over the last 5 s (reported). Figures: top box drop and drift (m), deepest "
        "penetration (m), the largest speed of any box (m/s) and total kinetic energy (J) over "
        "the last 5 s.",
        "r", "this engine", "verdict", "Chipmunk2D", "Box2D 2.4", "Box2D 2.4, no sleeping", NULL);
    for (int i = 0; i < 3; i++) {
        progress("mass ratios: heavytop r = %g", tops[i]);
        const char *line = run_ours(&ours_ops, SCENE_HEAVYTOP, tops[i], BENCH_DT, -1, 0);
        const char *engines[4] = {"ours", "chipmunk", "box2d", "box2d-nosleep"};
        char id[64];
        snprintf(id, sizeof id, "mass.heavytop_%g", tops[i]);
        row_t *r = new_row(t, tops[i] == 100 ? id : NULL);
        set_cell(r, 0, "%g", tops[i]);
        for (int k = 0; k < 4; k++) {
            const char *l = k == 0 ? line : find(engines[k], "heavytop", tops[i], NULL, NULL);
            int column = k == 0 ? 1 : k + 2;
            if (l == NULL) {
                set_cell(r, column, NOT_RUN);
                continue;
            }
            bool upright = num(l, "standing") == 1.0;
            bool stands = upright && num(l, "max_penetration") < 0.01;
            bool rests = num(l, "late_speed_max") < 0.01;
            set_cell(r, column, "%s, %s: drop %s, drift %s, pen %s; speed %s, KE %s",
                     upright ? (stands ? "stands" : "stands, deeper than 1 cm") : "FALLS",
                     rests ? "at rest" : "MOVING",
                     G(num(l, "top_drop")), G(num(l, "top_drift")), G(num(l, "max_penetration")),
                     G(num(l, "late_speed_max")), G(num(l, "late_ke_max")));
            if (k == 0) {
                r->pass = stands;
                set_cell(r, 2, "%s%s", stands ? "stands" : "FAILS: falls",
                         stands && !rests ? "; does not come to rest (limit, below)" : "");
            }
        }
    }
    NOTE(t,
         "**Limit: a heavy box held by two light ones jitters.** It stands at every ratio (where "
         "both peers' pyramids fall at r = 1000), but at r = 1000 it never comes to rest: the "
         "top box wanders at up to the speed above (it did at r = 100 too, 0.04 m/s, before the "
         "sweep order alternated; 0.34 m/s when position "
         "correction between movable bodies removed 20%% of an overlap per iteration, not 40%%), "
         "the two boxes under it spread apart. The cause is the shock propagation pass (engine/src/solver/shock.c): before the "
         "last velocity iteration it holds each body's supports still and stops the body's "
         "approach by pushing it alone. A light support cannot be pushed down by its heavy load "
         "in 8 iterations, so the pass lifts the heavy box with an impulse that nothing balances, "
         "which the last iteration and the next step then take back: a cycle. Measured in a "
         "scratch copy of the engine (r = 100, largest total kinetic energy over 10-20 s): 2.4 J "
         "with the pass, 0.045 J without it, 2.5e-6 J without it at 32 iterations, but without "
         "the pass the r = 1000 pyramid collapses (all at the 20%% rate); skipping the pass only where the upper body "
         "is 1.5 times heavier than a support leaves 0.027 J at r = 100 and collapses r = 1000 "
         "too; holding the heavy body by all its supports at once (a small projected "
         "Gauss-Seidel, lower bodies still) changes little (2.0 J). At the 40%% rate, a dead band in "
         "the pass for bodies held by two or more supports (the 40-row pyramid's note, below) "
         "halves the top box's speed at 0.05 mm/s (0.022 against 0.041 m/s at r = 100) and at "
         "0.2 mm/s brings it to 0.0024 m/s (5e-5 J), leaving r = 1000 at 0.03 to 0.05 m/s, but "
         "costs the 20-row pyramid's drift. What settled it was the order of the sweeps "
         "(docs/design.md, Sweep order): reversed on every other step, r = 100's top box is "
         "under 1.5 mm/s over 10-20 s (0.041 m/s swept one way) and r = 10 rests at 4e-12 J.\n");

    /* seed-style pair collisions */
    t = new_table(
        s, "Seed-style pair collisions (`create_physics_collision`, world contacts off)",
        "A 1 kg box at 1 m/s meets a box of mass m2 at rest, elasticity e; velocities after, "
        "against v1' = (p - m2 e v1) / (m1 + m2), v2' = (p + m1 e v1) / (m1 + m2), and against "
        "an infinite mass v1' = -e v1 with the wall exactly still (its velocity and centroid "
        "unchanged to the bit). Errors relative to the closing speed (momentum: to the start's; "
        "energy: to the 1 kg box's start energy). Verdict: every error under 1e-12.",
        "m2 (kg)", "e", "velocity error", "momentum error", "energy error", "verdict", NULL);
    const double masses[] = {1, 1e3, 1e6, INFINITY};
    const double elasticities[] = {0.0, 0.5, 1.0};
    for (int i = 0; i < 4; i++) {
        for (int k = 0; k < 3; k++) {
            seed_result_t res = seed_pair(1.0, masses[i], elasticities[k]);
            char id[64];
            snprintf(id, sizeof id, "mass.seed_pair_%g_e%g", masses[i], elasticities[k]);
            row_t *r = new_row(t, id);
            set_cell(r, 0, "%g", masses[i]);
            set_cell(r, 1, "%g", elasticities[k]);
            set_cell(r, 2, "%s", E(res.vel_err));
            set_cell(r, 3, "%s", E(res.momentum_err));
            set_cell(r, 4, "%s", E(res.energy_err));
            r->pass = res.vel_err < 1e-12 && !(res.momentum_err >= 1e-12) &&
                      fabs(res.energy_err) < 1e-12 && res.wall_still;
            set_cell(r, 5, "%s%s", r->pass ? "exact to rounding" : "FAILS",
                     isinf(masses[i]) ? (res.wall_still ? "; wall exactly still" : "; WALL MOVED")
                                      : "");
        }
    }
    /* head-on with world contacts */
    const double head[] = {1, 10, 100, 1000, 1e4, 1e6};
    t = new_table(s, "The same meeting with contacts (`headon`), elasticity 1, all three engines",
                  "A 1 kg unit box at 5 m/s meets an r kg unit box at rest (world contacts; no "
                  "gravity, no friction), 2 s. Figure: the larger velocity error over 5 m/s, and "
                  "the momentum error. Verdict (this engine): velocity error under 1e-9.",
                  "r", "this engine", "verdict", "Chipmunk2D", "Box2D 2.4", NULL);
    for (int i = 0; i < 6; i++) {
        const char *line = run_ours(&ours_ops, SCENE_HEADON, head[i], BENCH_DT, -1, 0);
        char id[64];
        snprintf(id, sizeof id, "mass.headon_%g", head[i]);
        row_t *r = new_row(t, id);
        set_cell(r, 0, "%g", head[i]);
        set_cell(r, 1, "%s; momentum %s", E(num(line, "vel_err")), E(num(line, "momentum_err")));
        r->pass = num(line, "vel_err") < 1e-9;
        set_cell(r, 2, "%s", r->pass ? "exact to rounding" : "FAILS");
        const char *peers[2] = {"chipmunk", "box2d"};
        for (int k = 0; k < 2; k++) {
            const char *l = find(peers[k], "headon", head[i], NULL, NULL);
            set_cell(r, 3 + k, "%s", l ? "" : NOT_RUN);
            if (l) {
                set_cell(r, 3 + k, "%s; momentum %s%s", E(num(l, "vel_err")),
                         E(num(l, "momentum_err")),
                         num(l, "v2") == 0.0 ? " (the heavy box never moves)" : "");
            }
        }
    }
}

/* ==== 3. Speed and step size ==== */

static const double tunnel_full[] = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000};
static const double rod_full[] = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000};

static const char *through_text(tunnel_summary_t s, bool rod, double top) {
    static char buffers[8][CELL];
    static int next = 0;
    next = (next + 1) % 8;
    if (isnan(s.first)) return NOT_RUN;
    if (rod) {
        if (isinf(s.first)) {
            snprintf(buffers[next], CELL, "none to %g rad/s; deepest %s m", top, G(s.max_depth));
        } else {
            snprintf(buffers[next], CELL, "from %g rad/s; deepest %s m", s.first, G(s.max_depth));
        }
    } else if (isinf(s.first)) {
        snprintf(buffers[next], CELL, "none to %g m/s; rebound %s m/s", top, G(s.back));
    } else {
        snprintf(buffers[next], CELL, "from %g m/s; rebound %s m/s", s.first, G(s.back));
    }
    return buffers[next];
}

static void speed_section(void) {
    section_t *s = new_section("Speed and step size", "");
    const double *speeds = tunnel_full, *spins = rod_full;
    int nspeeds = 13, nspins = 10;
    table_t *t = new_table(
        s, "Fast bodies against thin walls",
        "`tunnel`: a 0.2 m box (0.04 kg) against a static 0.1 m wall; `tunnelmove`: the same wall "
        "free to move (1 kg); `bullet`: a 0.01 m box against the static wall; `rod`: a 2 m x "
        "0.02 m rod spinning beside the static wall so that a tip (speed omega x 1 m) reaches it "
        "within a quarter turn. No gravity, elasticity 0, 16 start phases per speed, 120 steps "
        "of 1/60 s. Figure: the first speed at which a run ended through the wall (the bullet's "
        "centre past the wall's; a rod corner past the wall's middle), the largest rebound speed "
        "(bullet from wall; it should be 0 at elasticity 0) and, for the rod, how deep a corner "
        "went past the near face at any step. Verdict: nothing passes at any speed tried, no "
        "rebound (under 1e-6 m/s), no rod corner past the wall's middle.",
        "engine, integrator", "static wall", "movable wall", "0.01 m bullet", "spinning rod",
        "verdict", NULL);
    for (int i = -1; i < INTEGRATOR_COUNT; i++) {
        int integrator = i < 0 ? INTEGRATOR_SEED : i;
        if (i == INTEGRATOR_SEED) continue; /* the default, done first */
        progress("speed: tunnels under %s", integrator_get_name(integrator));
        for (int k = 0; k < nspeeds; k++) {
            run_ours(&ours_ops, SCENE_TUNNEL, speeds[k], BENCH_DT, integrator, 0);
            run_ours(&ours_ops, SCENE_TUNNELMOVE, speeds[k], BENCH_DT, integrator, 0);
            run_ours(&ours_ops, SCENE_BULLET, speeds[k], BENCH_DT, integrator, 0);
        }
        for (int k = 0; k < nspins; k++) run_ours(&ours_ops, SCENE_ROD, spins[k], BENCH_DT, integrator, 0);
        const char *key = integrator_key(integrator);
        tunnel_summary_t a = summarise_tunnel("ours", "tunnel", speeds, nspeeds, "integrator", key);
        tunnel_summary_t b = summarise_tunnel("ours", "tunnelmove", speeds, nspeeds, "integrator", key);
        tunnel_summary_t c = summarise_tunnel("ours", "bullet", speeds, nspeeds, "integrator", key);
        tunnel_summary_t d = summarise_tunnel("ours", "rod", spins, nspins, "integrator", key);
        char id[64];
        snprintf(id, sizeof id, "speed.tunnels.%s", key);
        row_t *r = new_row(t, id);
        set_cell(r, 0, "this engine, %s", integrator_get_name(integrator));
        set_cell(r, 1, "%s", through_text(a, false, speeds[nspeeds - 1]));
        set_cell(r, 2, "%s", through_text(b, false, speeds[nspeeds - 1]));
        set_cell(r, 3, "%s", through_text(c, false, speeds[nspeeds - 1]));
        set_cell(r, 4, "%s", through_text(d, true, spins[nspins - 1]));
        r->pass = isinf(a.first) && isinf(b.first) && isinf(c.first) && isinf(d.first) &&
                  a.back < 1e-6 && b.back < 1e-6 && c.back < 1e-6;
        set_cell(r, 5, "%s", r->pass ? "nothing passes, no rebound" : "FAILS");
    }
    const char *peers[2] = {"chipmunk", "box2d"}, *labels[2] = {"Chipmunk2D", "Box2D 2.4"};
    for (int k = 0; k < 2; k++) {
        row_t *r = new_row(t, NULL);
        set_cell(r, 0, "%s", labels[k]);
        set_cell(r, 1, "%s", through_text(summarise_tunnel(peers[k], "tunnel", speeds, nspeeds, NULL, NULL), false, speeds[nspeeds - 1]));
        set_cell(r, 2, "%s", through_text(summarise_tunnel(peers[k], "tunnelmove", speeds, nspeeds, NULL, NULL), false, speeds[nspeeds - 1]));
        set_cell(r, 3, "%s", through_text(summarise_tunnel(peers[k], "bullet", speeds, nspeeds, NULL, NULL), false, speeds[nspeeds - 1]));
        set_cell(r, 4, "%s", through_text(summarise_tunnel(peers[k], "rod", spins, nspins, NULL, NULL), true, spins[nspins - 1]));
    }

    /* drop at any dt */
    const double dts[] = {1.0 / 600.0, 1.0 / 60.0, 0.1, 0.5, 1.0};
    const char *dt_names[] = {"1/600", "1/60", "1/10", "1/2", "1/1"};
    t = new_table(
        s, "A box dropped on a floor at any step (`drop`)",
        "The scene of tests/test_impacts.c's box_lands_at_any_step: a 1 m box, 1 kg, its bottom "
        "1 m above a static floor, elasticity 0, for min(2 s / dt, 2000) + 20 steps. Figure: its "
        "centre's height error (m) and speed (m/s) at the end. Verdict: at rest on the floor "
        "(height within 2 mm, speed under 1e-6 m/s) at every dt. The peers are judged at rest "
        "within 2 cm and 1e-3 m/s (Box2D's skin is 1 cm).",
        "engine, integrator", "dt = 1/600 s", "1/60 s", "0.1 s", "0.5 s", "1 s", "verdict", NULL);
    for (int i = 0; i <= INTEGRATOR_COUNT + 1; i++) {
        bool ours = i < INTEGRATOR_COUNT;
        const char *engine = ours ? "ours" : (i == INTEGRATOR_COUNT ? "chipmunk" : "box2d-nosleep");
        char id[64];
        snprintf(id, sizeof id, "speed.drop.%s", ours ? integrator_key(i) : "peer");
        row_t *r = new_row(t, ours ? id : NULL);
        set_cell(r, 0, "%s", ours ? integrator_get_name(i)
                                  : (i == INTEGRATOR_COUNT ? "Chipmunk2D" : "Box2D 2.4, no sleeping"));
        bool all = true;
        for (int k = 0; k < 5; k++) {
            const char *line = ours ? run_ours(&ours_ops, SCENE_DROP, 1.0, dts[k], i, 0)
                                    : find(engine, "drop", 1.0, "dt", dt_names[k]);
            if (line == NULL) {
                set_cell(r, 1 + k, NOT_RUN);
                all = false;
                continue;
            }
            double y = num(line, "y_err"), v = num(line, "speed");
            bool rest = ours ? fabs(y) < 0.002 && v < 1e-6 : num(line, "rest") == 1.0;
            all &= rest;
            set_cell(r, 1 + k, "%s (%s m, %s m/s)", rest ? "rests" : "NO", E(y), E(v));
        }
        r->pass = all;
        set_cell(r, 6, "%s", all ? "rests at every dt" : (ours ? "FAILS" : "not at every dt"));
    }
}

/* ==== 4. Overlap recovery ==== */

static const char *overlap_text(const char *line, bool *ok) {
    static char buffers[8][CELL];
    static int next = 0;
    next = (next + 1) % 8;
    if (line == NULL) return NOT_RUN;
    bool good = num(line, "in_bounds") == 1.0 && num(line, "max_push_speed") < 4.1 &&
                num(line, "max_speed") < 0.1 && num(line, "max_penetration") <= 0.0011;
    if (ok) *ok = good;
    snprintf(buffers[next], CELL, "push %s m/s, speed %s m/s, overlap %s m, %s",
             G(num(line, "max_push_speed")), G(num(line, "max_speed")),
             G(num(line, "max_penetration")),
             num(line, "in_bounds") == 1.0 ? "nothing ejected" : "EJECTED");
    return buffers[next];
}

static void overlap_section(void) {
    section_t *s = new_section("Overlap recovery", "");
    table_t *t = new_table(
        s, NULL,
        "`overlap`: a pyramid of 10 unit boxes with base 4 created with 25% overlap; "
        "`coincide`: two unit boxes created on the ground overlapping by the fraction f of "
        "their height (1: in the same place); 300 steps. Figures: the largest position change "
        "over one step / dt of any box (push), the largest velocity, the overlap left at the end, "
        "whether every box stayed in bounds. Verdict: push under 4.1 m/s (the 4 m/s cap, "
        "SOLVER_MAX_PUSH_SPEED, plus what the velocity moves), velocity under 0.1 m/s, overlap at "
        "most the 1 mm slop, nothing ejected.",
        "case", "this engine", "verdict", "Chipmunk2D", "Box2D 2.4, no sleeping", NULL);
    struct {
        bench_scene_id_t id;
        const char *scene;
        double size;
        const char *label;
    } cases[] = {{SCENE_OVERLAP, "overlap", 10, "overlap: pyramid of 4, 25% overlap"},
                 {SCENE_COINCIDE, "coincide", 1, "coincide f = 1: two boxes in one place"},
                 {SCENE_COINCIDE, "coincide", 0.5, "coincide f = 0.5: half inside each other"}};
    for (int i = 0; i < 3; i++) {
        progress("overlap: %s", cases[i].label);
        const char *line = run_ours(&ours_ops, cases[i].id, cases[i].size, BENCH_DT, -1, 0);
        char id[64];
        snprintf(id, sizeof id, "overlap.%s_%g", cases[i].scene, cases[i].size);
        row_t *r = new_row(t, id);
        set_cell(r, 0, "%s", cases[i].label);
        set_cell(r, 1, "%s", overlap_text(line, &r->pass));
        set_cell(r, 2, "%s", r->pass ? "recovers" : "FAILS");
        set_cell(r, 3, "%s", overlap_text(find("chipmunk", cases[i].scene, cases[i].size, NULL, NULL), NULL));
        set_cell(r, 4, "%s", overlap_text(find("box2d-nosleep", cases[i].scene, cases[i].size, NULL, NULL), NULL));
    }
}

/* ==== 5. Stacks and piles ==== */

static const char *column_text(const char *line, bool *ok) {
    static char buffers[8][CELL];
    static int next = 0;
    next = (next + 1) % 8;
    if (line == NULL) return NOT_RUN;
    bool standing = num(line, "standing") == 1.0;
    if (ok) *ok = standing && num(line, "kinetic_energy") < 1e-6 && num(line, "top_drift") < 0.01;
    snprintf(buffers[next], CELL, "%s: top drift %s m, drop %s m, tilt %s rad, KE %s J",
             standing ? "upright" : "FALLEN", G(num(line, "top_drift")), G(num(line, "top_drop")),
             G(num(line, "max_tilt")), G(num(line, "kinetic_energy")));
    return buffers[next];
}

/* ok: upright, the top within 1 cm of its height, penetration under 1 cm;
 * rests: kinetic energy under 1e-3 J at the end. */
static const char *pyramid_text(const char *line, bool *ok, bool *rests) {
    static char buffers[8][CELL];
    static int next = 0;
    next = (next + 1) % 8;
    if (line == NULL) return NOT_RUN;
    bool standing = num(line, "standing") == 1.0;
    bool at_rest = num(line, "kinetic_energy") < 1e-3;
    if (ok) *ok = standing && fabs(num(line, "top_drop")) < 0.01 && num(line, "max_penetration") < 0.01;
    if (rests) *rests = at_rest;
    snprintf(buffers[next], CELL, "%s, %s: top drop %s m, drift %s m, deepest %s m, KE %s J",
             standing ? "upright" : "FALLEN", at_rest ? "at rest" : "MOVING",
             G(num(line, "top_drop")), G(num(line, "top_drift")),
             G(num(line, "max_penetration")), G(num(line, "kinetic_energy")));
    return buffers[next];
}

static const char *pile_text(const char *line, int n, bool *ok) {
    static char buffers[8][CELL];
    static int next = 0;
    next = (next + 1) % 8;
    if (line == NULL) return NOT_RUN;
    double ke = num(line, "late_ke_max"), p = num(line, "late_p_max");
    if (ok) *ok = ke < 0.5 && p < 1.0 && num(line, "outside") == 0.0;
    snprintf(buffers[next], CELL,
             "KE up to %s J (%s J a body), momentum up to %s N s; at the end %s J, %s bodies "
             "faster than 1 cm/s (most at one step %s), fastest %s m/s, deepest penetration %s m",
             G(ke), G(ke / n), G(p), G(num(line, "ke_end")), G(num(line, "fast_end")),
             G(num(line, "late_fast_max")), G(num(line, "vmax_end")),
             G(num(line, "max_penetration")));
    return buffers[next];
}

static const char *const PYRAMID_LIMIT_NOTE =
    "**The 40-row pyramid rests.** Its total kinetic energy at 60 s is 3.5e-10 J and its top "
    "is 1e-8 m from where it started. Swept in one order every step it never quite stopped "
    "(1e-5 to 1e-3 J from 30 s) and its top leaned 2.4 cm (median of the benchmark's 8 layout "
    "seeds): each step's Gauss-Seidel sweeps left their error on the same side, and shock "
    "propagation's one-sided pushes, taken back by the last iteration and the next step, kept "
    "the tall pyramid rocking. Reversing the sweeps on every other step (docs/design.md, Sweep "
    "order) settles it, and the lean is 4.8 mm (Box2D v3: 1.8 mm). Tried before that and not "
    "applied: a dead band in the shock pass (approaches slower than a set speed left to the "
    "iterations), which settled it too but doubled the 20-row pyramid's lean.\n";

/* The pile of circles and the pile of capsules, beside the polygon pile:
 * the same layout, sizes, run and verdict. Box2D 2.4 has no capsule. */
static void round_piles(table_t *t, int n) {
    const struct {
        const char *scene, *words;
        bench_scene_id_t id;
    } piles[2] = {{"circlepile", "circles", SCENE_CIRCLEPILE},
                  {"capsulepile", "capsules", SCENE_CAPSULEPILE}};
    for (int k = 0; k < 2; k++) {
        progress("stacks: %s(%d), 70 s, sleeping off", piles[k].scene, n);
        const char *line = run_ours(&ours_ops, piles[k].id, n, BENCH_DT, -1, 4200);
        char id[64];
        snprintf(id, sizeof id, "stacks.%s_%d", piles[k].scene, n);
        row_t *r = new_row(t, id);
        set_cell(r, 0, "%s(%d) of %s, 60-70 s, sleeping off", piles[k].scene, n, piles[k].words);
        set_cell(r, 1, "%s", pile_text(line, n, &r->pass));
        set_cell(r, 2, "%s", r->pass ? "settled" : "FAILS");
        set_cell(r, 3, "%s", pile_text(find("chipmunk", piles[k].scene, n, NULL, NULL), n, NULL));
        if (!r->pass && line != NULL) {
            NOTE(t,
                 "**Limit: %s(%d) still creeps at 60-70 s** (momentum up to %s N s, %s bodies "
                 "faster than 1 cm/s at 70 s), as pile(4000) of polygons does (Open problems); "
                 "the same pile of 500 settles (make check asserts it).\n",
                 piles[k].scene, n, G(num(line, "late_p_max")), G(num(line, "fast_end")));
        }
        if (piles[k].id == SCENE_CAPSULEPILE) {
            set_cell(r, 4, "%s", "(no capsule shape)");
            set_cell(r, 5, "%s", "(no capsule shape)");
            continue;
        }
        set_cell(r, 4, "%s", pile_text(find("box2d-nosleep", piles[k].scene, n, NULL, NULL), n, NULL));
        set_cell(r, 5, "%s", pile_text(find("box2d", piles[k].scene, n, NULL, NULL), n, NULL));
    }
}

static void stacks_section(void) {
    section_t *s = new_section("Stacks and piles", "");
    const int pyramid = 40, pile = 2000;
    table_t *t = new_table(
        s, NULL,
        "`column(20)`: 20 unit boxes one on another, each shifted up to 1 cm sideways, 60 s. "
        "`pyramid(40)`: 820 unit boxes, 60 s. Verdicts: the column upright with kinetic energy "
        "under 1e-6 J and the top drifted under 1 cm; the pyramid upright, its top within 1 cm "
        "of its height and the deepest penetration under 1 cm (asserted), at rest when its "
        "kinetic energy is under 1e-3 J (reported). `pile(N)`: the benchmark's pile (N polygons of 3 to 8 "
        "sides dropped into a container) for 70 s: its motion from 60 s on and the deepest "
        "penetration at the end; verdict: total "
        "kinetic energy under 0.5 J and momentum under 1 N s, with sleeping off (with sleeping on "
        "reported). `circlepile(N)` and `capsulepile(N)`: the same with circles of the polygons' "
        "0.5 m radius, or capsules 1 m long of radius 0.25 m, and the same verdict. "
        "`pile(10000)`: the deepest penetration at 10 s, at most 0.30 m.",
        "case", "this engine", "verdict", "Chipmunk2D", "Box2D 2.4, no sleeping", "Box2D 2.4",
        NULL);
    progress("stacks: column(20), 60 s");
    const char *line = run_ours(&ours_ops, SCENE_COLUMN, 20, BENCH_DT, -1, 3600);
    row_t *r = new_row(t, "stacks.column_20");
    set_cell(r, 0, "column(20), 60 s");
    set_cell(r, 1, "%s", column_text(line, &r->pass));
    set_cell(r, 2, "%s", r->pass ? "upright, at rest" : "FAILS");
    set_cell(r, 3, "%s", column_text(find("chipmunk", "column", 20, NULL, NULL), NULL));
    set_cell(r, 4, "%s", column_text(find("box2d-nosleep", "column", 20, NULL, NULL), NULL));
    set_cell(r, 5, "%s", column_text(find("box2d", "column", 20, NULL, NULL), NULL));

    progress("stacks: pyramid(%d), 60 s", pyramid);
    line = run_ours(&ours_ops, SCENE_PYRAMID, pyramid, BENCH_DT, -1, 3600);
    char id[64];
    snprintf(id, sizeof id, "stacks.pyramid_%d", pyramid);
    r = new_row(t, id);
    set_cell(r, 0, "pyramid(%d), 60 s", pyramid);
    bool pyramid_rests = false;
    set_cell(r, 1, "%s", pyramid_text(line, &r->pass, &pyramid_rests));
    set_cell(r, 2, "%s%s", r->pass ? "upright, top within 1 cm" : "FAILS",
             pyramid_rests ? ", at rest" : "; does not come to rest (limit, below)");
    set_cell(r, 3, "%s", pyramid_text(find("chipmunk", "pyramid", pyramid, NULL, NULL), NULL, NULL));
    set_cell(r, 4, "%s", pyramid_text(find("box2d-nosleep", "pyramid", pyramid, NULL, NULL), NULL, NULL));
    set_cell(r, 5, "%s", pyramid_text(find("box2d", "pyramid", pyramid, NULL, NULL), NULL, NULL));
    line = run_ours(&ours_sleeping_ops, SCENE_PYRAMID, pyramid, BENCH_DT, -1, 3600);
    r = new_row(t, NULL);
    set_cell(r, 0, "pyramid(%d), 60 s, sleeping on", pyramid);
    set_cell(r, 1, "%s", pyramid_text(line, NULL, &pyramid_rests));
    set_cell(r, 2, "%s", pyramid_rests ? "asleep (reported)" : "never sleeps (reported)");

    NOTE(t, "%s", PYRAMID_LIMIT_NOTE);
    progress("stacks: pile(%d), 70 s, sleeping off", pile);
    line = run_ours(&ours_ops, SCENE_PILE, pile, BENCH_DT, -1, 4200);
    snprintf(id, sizeof id, "stacks.pile_%d", pile);
    r = new_row(t, id);
    set_cell(r, 0, "pile(%d), 60-70 s, sleeping off", pile);
    set_cell(r, 1, "%s", pile_text(line, pile, &r->pass));
    set_cell(r, 2, "%s", r->pass ? "settled" : "FAILS");
    set_cell(r, 3, "%s", pile_text(find("chipmunk", "pile", pile, NULL, NULL), pile, NULL));
    set_cell(r, 4, "%s", pile_text(find("box2d-nosleep", "pile", pile, NULL, NULL), pile, NULL));
    set_cell(r, 5, "%s", pile_text(find("box2d", "pile", pile, NULL, NULL), pile, NULL));

    progress("stacks: pile(%d), 70 s, sleeping on", pile);
    line = run_ours(&ours_sleeping_ops, SCENE_PILE, pile, BENCH_DT, -1, 4200);
    r = new_row(t, NULL);
    set_cell(r, 0, "pile(%d), 60-70 s, sleeping on", pile);
    bool settled = false;
    set_cell(r, 1, "%s", pile_text(line, pile, &settled));
    set_cell(r, 2, "%s", settled ? "settled (reported)" : "not settled (reported)");
    set_cell(r, 5, "%s", "(the column left: Box2D sleeps by default)");
    round_piles(t, quick ? 500 : pile);

    if (!quick) {
        progress("stacks: pile(10000), 10 s");
        line = run_ours(&ours_ops, SCENE_PILE, 10000, BENCH_DT, -1, 0);
        r = new_row(t, "stacks.pile_10000");
        set_cell(r, 0, "pile(10000), deepest penetration at 10 s");
        double pen = num(line, "max_penetration");
        r->pass = pen <= 0.30 && num(line, "outside") == 0.0;
        set_cell(r, 1, "%s m, %s outside", G(pen), G(num(line, "outside")));
        set_cell(r, 2, "%s", r->pass ? "at most 0.30 m" : "FAILS");
        const char *engines[3] = {"chipmunk", "box2d-nosleep", "box2d-discrete"};
        for (int k = 0; k < 3; k++) {
            const char *l = find(engines[k], "pile", 10000, NULL, NULL);
            set_cell(r, 3 + k, "%s", l ? "" : NOT_RUN);
            if (l) {
                set_cell(r, 3 + k, "%s m, %s outside%s", G(num(l, "max_penetration")),
                         G(num(l, "outside")), k == 2 ? " (continuous collision off)" : "");
            }
        }
    }
}

/* ==== 6. Restitution ==== */

static void restitution_section(void) {
    section_t *s = new_section("Restitution", "");
    table_t *t = new_table(
        s, NULL,
        "`gas(e)`: 20 polygons (3 to 8 sides, 0.5 m) in a closed 10 m box, no gravity, no "
        "friction, random speeds up to 5 m/s and spins up to 2 rad/s, 10^4 steps: kinetic energy "
        "at the end and its least and largest over the run, over the start's. `settle(0)`: the "
        "same box and bodies with gravity and friction 0.6 at elasticity 0, 20 s: kinetic energy "
        "at the end. `wallbounce(e)`: a unit box at 2 m/s between two static walls, no gravity, "
        "40 bounces: the largest |(speed after / speed before) / e - 1| over the bounces, and the "
        "kinetic energy against e^(2 bounces) times the start's. Verdicts: e = 1 keeps the energy "
        "within 1% at every step; e = 0 comes to rest (under 1e-3 J); e > 1 grows by e^2 a "
        "bounce to 1e-9, no faster.",
        "case", "this engine", "verdict", "Chipmunk2D", "Box2D 2.4", NULL);
    const char *peers[2] = {"chipmunk", "box2d"};
    /* gas */
    double gas_e[2] = {1.0, 0.0};
    for (int i = 0; i < 2; i++) {
        progress("restitution: gas e = %g", gas_e[i]);
        const char *line = run_ours(&ours_ops, SCENE_GAS, gas_e[i], BENCH_DT, -1, 0);
        row_t *r = new_row(t, gas_e[i] == 1.0 ? "restitution.gas_e1" : NULL);
        set_cell(r, 0, "gas, e = %g, no gravity or friction", gas_e[i]);
        for (int k = 0; k < 3; k++) {
            const char *l = k == 0 ? line : find(peers[k - 1], "gas", gas_e[i], NULL, NULL);
            set_cell(r, k == 0 ? 1 : k + 2, "%s", l ? "" : NOT_RUN);
            if (l) {
                set_cell(r, k == 0 ? 1 : k + 2, "energy at the end %s, least %s, largest %s",
                         G(num(l, "ke_end_ratio")), G(num(l, "ke_min_ratio")),
                         G(num(l, "ke_max_ratio")));
            }
        }
        if (gas_e[i] == 1.0) {
            r->pass = fabs(num(line, "ke_min_ratio") - 1.0) < 0.01 &&
                      fabs(num(line, "ke_max_ratio") - 1.0) < 0.01 && num(line, "in_bounds") == 1.0;
            set_cell(r, 2, "%s", r->pass ? "kept within 1%" : "FAILS");
        } else {
            set_cell(r, 2, "(reported: without gravity or friction nothing stops bodies sliding "
                           "along each other or a wall)");
        }
    }
    progress("restitution: settle e = 0");
    const char *line = run_ours(&ours_ops, SCENE_SETTLE, 0.0, BENCH_DT, -1, 0);
    row_t *r = new_row(t, "restitution.settle_e0");
    set_cell(r, 0, "settle, e = 0, gravity and friction");
    r->pass = num(line, "ke_end") < 1e-3 && num(line, "in_bounds") == 1.0;
    set_cell(r, 1, "energy at the end %s J", G(num(line, "ke_end")));
    set_cell(r, 2, "%s", r->pass ? "comes to rest" : "FAILS");
    for (int k = 0; k < 2; k++) {
        const char *l = find(peers[k], "settle", 0.0, NULL, NULL);
        set_cell(r, 3 + k, "%s", l ? "" : NOT_RUN);
        if (l) set_cell(r, 3 + k, "energy at the end %s J", G(num(l, "ke_end")));
    }
    double walls[2] = {1.0, 1.1};
    for (int i = 0; i < 2; i++) {
        progress("restitution: wallbounce e = %g", walls[i]);
        line = run_ours(&ours_ops, SCENE_WALLBOUNCE, walls[i], BENCH_DT, -1, 0);
        char id[64];
        snprintf(id, sizeof id, "restitution.wallbounce_e%g", walls[i]);
        r = new_row(t, id);
        set_cell(r, 0, "wallbounce, e = %g", walls[i]);
        for (int k = 0; k < 3; k++) {
            const char *l = k == 0 ? line : find(peers[k - 1], "wallbounce", walls[i], NULL, NULL);
            set_cell(r, k == 0 ? 1 : k + 2, "%s", l ? "" : NOT_RUN);
            if (l) {
                set_cell(r, k == 0 ? 1 : k + 2,
                         "%s bounces: per bounce off e by %s, energy off the formula by %s, "
                         "off-axis speed %s",
                         G(num(l, "bounces")), E(num(l, "ratio_err_max")),
                         E(num(l, "ke_formula_err")), E(num(l, "off_axis")));
            }
        }
        r->pass = num(line, "ratio_err_max") < 1e-9 && fabs(num(line, "ke_formula_err")) < 1e-9 &&
                  num(line, "bounces") >= 40;
        set_cell(r, 2, "%s", r->pass ? "by the formula" : "FAILS");
    }
}

/* ==== 7. Size and place ==== */

static const char *scaled_text(const char *line, bool *ok) {
    static char buffers[8][CELL];
    static int next = 0;
    next = (next + 1) % 8;
    if (line == NULL) return NOT_RUN;
    bool standing = num(line, "standing") == 1.0, rests = num(line, "late_speed_rel") < 0.01;
    if (ok) *ok = standing && rests && num(line, "pen_rel") < 0.01;
    snprintf(buffers[next], CELL, "%s%s: drop %s, drift %s, pen %s, speed %s",
             standing ? "stands" : "FALLS", standing ? (rests ? ", at rest" : ", MOVING") : "",
             G(num(line, "top_drop_rel")), G(num(line, "top_drift_rel")), G(num(line, "pen_rel")),
             G(num(line, "late_speed_rel")));
    return buffers[next];
}

static const char *far_text(const char *line, bool *ok) {
    static char buffers[8][CELL];
    static int next = 0;
    next = (next + 1) % 8;
    if (line == NULL) return NOT_RUN;
    bool standing = num(line, "standing") == 1.0, rests = num(line, "late_speed_max") < 0.01;
    if (ok) *ok = standing && rests && num(line, "max_penetration") < 0.01;
    snprintf(buffers[next], CELL, "%s%s: drop %s m, drift %s m, pen %s m, speed %s m/s",
             standing ? "stands" : "FALLS", standing ? (rests ? ", at rest" : ", MOVING") : "",
             G(num(line, "top_drop")), G(num(line, "top_drift")), G(num(line, "max_penetration")),
             G(num(line, "late_speed_max")));
    return buffers[next];
}

static void place_section(void) {
    section_t *s = new_section("Size and place", "");
    const double sizes[] = {0.01, 1, 1000};
    table_t *t = new_table(
        s, "Boxes of 1 cm, 1 m and 1 km (`scaled`)",
        "The pyramid of 10 rows built of boxes of side s, everything scaled but gravity (10 "
        "m/s^2), for 10 s: at the game's 1/60 s, and at 1/60 sqrt(s / 1 m) s, the step at which "
        "the scaled scene is the 1 m one in units of the box and of its fall time. Figures in "
        "box sizes (per second for the speed, the largest of any box over the last 5 s). "
        "Verdict (the 1 m one): stands, at rest (under 0.01 sizes/s), penetration under 1% of a "
        "box; asserted at the scaled step.",
        "s (m), dt (s)", "this engine", "verdict", "Chipmunk2D", "Box2D 2.4, no sleeping", NULL);
    for (int i = 0; i < 3; i++) {
        for (int k = 0; k < 2; k++) {
            double dt = k == 0 ? BENCH_DT : BENCH_DT * sqrt(sizes[i]);
            if (k == 1 && sizes[i] == 1.0) continue;
            progress("place: scaled s = %g, dt = %g", sizes[i], dt);
            const char *line = run_ours(&ours_ops, SCENE_SCALED, sizes[i], dt, -1, 0);
            char id[64], dts[32];
            snprintf(id, sizeof id, "place.scaled_%g_dt%s", sizes[i], k == 0 ? "60" : "scaled");
            bench_format_dt(dts, sizeof dts, dt);
            row_t *r = new_row(t, k == 1 || sizes[i] != 0.01 ? id : NULL);
            set_cell(r, 0, "%g, %s", sizes[i], dts);
            set_cell(r, 1, "%s", scaled_text(line, &r->pass));
            if (r->asserted) {
                set_cell(r, 2, "%s", r->pass ? "as at 1 m" : "FAILS");
            } else {
                set_cell(r, 2, "%s", r->pass ? "as at 1 m" : "limit: the step is too long for "
                                                             "the box");
            }
            const char *peers[2] = {"chipmunk", "box2d-nosleep"};
            for (int p = 0; p < 2; p++) {
                set_cell(r, 3 + p, "%s", scaled_text(find(peers[p], "scaled", sizes[i], "dt", dts), NULL));
            }
        }
    }
    NOTE(t,
         "**A long step for the box.** At a fixed 1/60 s gravity moves a 1 cm box by g dt^2 = "
         "2.8 mm in one step, 28%% of its size, as a 1 m box at dt = 1/6 s. Both peers' 1 cm "
         "pyramids fall; this engine's stands and rests (its 1 m pyramid at dt = 1/6 s stands too, "
         "drift 5%% of a box, moving at 1.5%% of a box a second). Before the sweep order "
         "alternated (docs/design.md, Sweep order) the 1 cm pyramid kept moving at 8.6%% of a "
         "box a second and rested only from dt = 1/120 s. The absolute tolerances scale or do "
         "not matter here: the slop is 1%% of a small body's radius, the push cap 4 m/s is far "
         "above what a 1 km box needs at 1/60 s.\n");

    const double offsets[] = {0, 1e6, 1e8, 1e10, 1e12};
    const int noffsets = 5;
    t = new_table(
        s, "The pyramid far from the origin (`far`)",
        "The pyramid of 10 rows of unit boxes moved to (D, -D), 10 s. Verdict: the origin's "
        "(stands, at rest: no box faster than 0.01 m/s over the last 5 s, penetration under "
        "1 cm) with the top's drop and drift and the penetration within 1 cm of the origin's "
        "(the pyramid's own chaos moves them by millimetres: at the origin and at 1e6 m they "
        "differ by 0.9 mm where the doubles are 1e-10 m apart); asserted at D = 1e6 m, farther "
        "out the limit.",
        "D (m)", "this engine", "verdict", "Chipmunk2D", "Box2D 2.4, no sleeping", NULL);
    const char *origin = NULL;
    for (int i = 0; i < noffsets; i++) {
        progress("place: far D = %g", offsets[i]);
        const char *line = run_ours(&ours_ops, SCENE_FAR, offsets[i], BENCH_DT, -1, 0);
        if (i == 0) origin = line;
        char id[64];
        snprintf(id, sizeof id, "place.far_%g", offsets[i]);
        row_t *r = new_row(t, offsets[i] <= 1e6 ? id : NULL);
        set_cell(r, 0, "%g", offsets[i]);
        bool rests = false;
        set_cell(r, 1, "%s", far_text(line, &rests));
        double diff = fmax(fabs(num(line, "top_drop") - num(origin, "top_drop")),
                           fmax(fabs(num(line, "top_drift") - num(origin, "top_drift")),
                                fabs(num(line, "max_penetration") - num(origin, "max_penetration"))));
        r->pass = rests && diff <= 0.01;
        set_cell(r, 2, "%s (%s m from the origin's figures)", r->pass ? "as at the origin" : (r->asserted ? "FAILS" : "differs"),
                 E(diff));
        const char *peers[2] = {"chipmunk", "box2d-nosleep"};
        for (int p = 0; p < 2; p++) set_cell(r, 3 + p, "%s", far_text(find(peers[p], "far", offsets[i], NULL, NULL), NULL));
    }
}

/* ==== 8. Degenerate shapes and bad input ==== */

/* Runs fn(arg) in a child process. Returns 0 when it returned (its exit
 * status in *status), 1 when it aborted (SIGABRT), -1 when it died
 * otherwise; its stderr's first line goes to message. */
static int in_child(void (*fn)(const void *), const void *arg, char *message, size_t size,
                    int *status) {
    int fds[2];
    fflush(stdout);
    fflush(stderr);
    if (pipe(fds) != 0) return -1;
    pid_t pid = fork();
    if (pid == 0) {
        close(fds[0]);
        dup2(fds[1], STDERR_FILENO);
        fn(arg);
        _exit(0);
    }
    close(fds[1]);
    size_t used = 0;
    ssize_t n;
    char buffer[4096];
    while ((n = read(fds[0], buffer + used, sizeof buffer - 1 - used)) > 0) used += (size_t)n;
    close(fds[0]);
    buffer[used] = '\0';
    buffer[strcspn(buffer, "\n")] = '\0';
    size_t length = strlen(buffer);
    if (length >= size) length = size - 1;
    memcpy(message, buffer, length);
    message[length] = '\0';
    int wstatus = 0;
    waitpid(pid, &wstatus, 0);
    if (WIFEXITED(wstatus)) {
        if (status) *status = WEXITSTATUS(wstatus);
        return 0;
    }
    return WIFSIGNALED(wstatus) && WTERMSIG(wstatus) == SIGABRT ? 1 : -1;
}

typedef struct {
    const char *label;
    int kind; /* which shape */
    const char *expected; /* polygon_check's words, NULL: usable */
} shape_case_t;

static list_t *shape_of(int kind) {
    list_t *p = list_init(8, free);
#define V(x, y)                                                                \
    do {                                                                       \
        vector_t *v_ = malloc(sizeof *v_);                                     \
        *v_ = (vector_t){(x), (y)};                                            \
        list_add(p, v_);                                                       \
    } while (0)
    switch (kind) {
    case 0: V(0, 0); V(1, 0); V(2, 0); break;                       /* collinear */
    case 1: V(0, 0); V(0.5, 0); V(1, 0); V(1, 1); V(0, 1); break;   /* vertex mid-edge */
    case 2: V(0, 0); V(1, 0); V(1, 0); V(1, 1); V(0, 1); break;     /* repeated vertex */
    case 3: V(0, 0); V(0, 1); V(1, 1); V(1, 0); break;              /* clockwise */
    case 4: V(0, 0); V(1, 0); V(1, 1); V(1e-9, 1); V(0, 1 - 1e-9); break; /* 1.4e-9 m edge */
    case 5: V(0, 0); V(1, 0); V(1, 1); V(1e-13, 1); V(0, 1 - 1e-13); break; /* 1.4e-13 m */
    case 6: V(1, 1); V(1, 1); V(1, 1); break;                       /* one point thrice */
    case 7:
        list_free(p);
        return polygon_make_regular(1000, 0.5, (vector_t){0, 0}, 0.1);
    case 8: V(0, 0); V(NAN, 0); V(1, 1); break;
    case 9: V(0, 0); V(INFINITY, 0); V(1, 1); break;
    case 10: V(0, 0); V(2, 0); V(1, 0.5); V(2, 2); V(0, 2); break;  /* reflex */
    case 11:                                                        /* pentagram */
        for (int i = 0; i < 5; i++) V(cos(0.5 * M_PI + 4.0 * M_PI * i / 5), sin(0.5 * M_PI + 4.0 * M_PI * i / 5));
        break;
    case 12: V(0, 0); V(1, 0); break;
    case 13: V(0, 0); V(1e200, 0); V(1e200, 1e200); V(0, 1e200); break;
    case 14:
        list_free(p);
        return polygon_make_regular(100000, 0.5, (vector_t){0, 0}, 0.1);
    }
#undef V
    return p;
}

static void child_body_init(const void *arg) {
    body_t *b = body_init(shape_of(*(const int *)arg), 1.0, (rgb_color_t){0.5, 0.5, 0.5});
    body_free(b);
}

/* Drops the shape (at 1.5 m, turned 0.3 rad) on a floor for 10 s, sleeping
 * off (a sleeping body would hide a slow roll); exits 0 when every state
 * stayed finite and it ended at rest, 3 otherwise. */
static void child_simulate(const void *arg) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0, -10});
    scene_set_contacts_enabled(scene, true);
    scene_set_sleeping(scene, false);
    rgb_color_t gray = {0.5, 0.5, 0.5};
    scene_add_body(scene, body_init(polygon_make_box((vector_t){0, -0.5}, 20, 0.5), INFINITY, gray));
    list_t *shape = shape_of(*(const int *)arg);
    body_t *b = body_init(shape, 1.0, gray);
    body_set_centroid(b, (vector_t){0, 1.5});
    body_set_rotation(b, 0.3);
    scene_add_body(scene, b);
    bool finite = true;
    for (int i = 0; i < 600; i++) {
        scene_tick(scene, 1.0 / 60);
        vector_t c = body_get_centroid(b), v = body_get_velocity(b);
        finite &= isfinite(c.x) && isfinite(c.y) && isfinite(v.x) && isfinite(v.y) &&
                  isfinite(body_get_rotation(b)) && isfinite(body_get_angular_velocity(b));
    }
    bool rest = vec_get_length(body_get_velocity(b)) < 1e-3 && body_get_centroid(b).y > 0.0;
    list_t *back = body_get_shape(b);
    bool ccw = polygon_is_counterclockwise(back);
    list_free(back);
    scene_free(scene);
    _exit(finite && rest && ccw ? 0 : 3);
}

typedef struct {
    const char *label, *call, *expected; /* expected: the abort's words; NULL: returns */
    void (*fn)(const void *);
} call_case_t;

static void call_mass_nan(const void *a) { (void)a; body_init(polygon_make_box(VEC_ZERO, 1, 1), NAN, (rgb_color_t){0, 0, 0}); }
static void call_mass_zero(const void *a) { (void)a; body_init(polygon_make_box(VEC_ZERO, 1, 1), 0.0, (rgb_color_t){0, 0, 0}); }
static void call_mass_negative(const void *a) { (void)a; body_init(polygon_make_box(VEC_ZERO, 1, 1), -2.0, (rgb_color_t){0, 0, 0}); }
static void call_velocity_nan(const void *a) {
    (void)a;
    body_t *b = body_init(polygon_make_box(VEC_ZERO, 1, 1), 1.0, (rgb_color_t){0, 0, 0});
    body_set_velocity(b, (vector_t){NAN, 0});
}
static void call_force_inf(const void *a) {
    (void)a;
    body_t *b = body_init(polygon_make_box(VEC_ZERO, 1, 1), 1.0, (rgb_color_t){0, 0, 0});
    body_add_force(b, (vector_t){0, INFINITY});
}
static void call_tick_nan(const void *a) { (void)a; scene_tick(scene_init(), NAN); }
static void call_tick_negative(const void *a) { (void)a; scene_tick(scene_init(), -0.1); }
static void call_tick_zero(const void *a) {
    (void)a;
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0, -10});
    body_t *b = body_init(polygon_make_box(VEC_ZERO, 1, 1), 1.0, (rgb_color_t){0, 0, 0});
    body_set_velocity(b, (vector_t){1, 0});
    scene_add_body(scene, b);
    scene_tick(scene, 0.0);
    vector_t c = body_get_centroid(b), v = body_get_velocity(b);
    _exit(c.x == 0.0 && c.y == 0.0 && v.x == 1.0 && v.y == 0.0 ? 0 : 3);
}
static void call_list_add_null(const void *a) { (void)a; list_add(list_init(1, NULL), NULL); }

static void input_section(void) {
    section_t *s = new_section("Degenerate shapes and bad input", "");
    table_t *t = new_table(
        s, "Shapes",
        "Each shape goes to polygon_check (the soft answer), to body_init in a child process "
        "(which must refuse it with the same words, or accept it), and, when accepted, is "
        "dropped 1 m, turned by 0.3 rad, on a floor for 10 s with sleeping off: every state "
        "finite and at rest after (slower than 1 mm/s). Verdict: the answer docs/api.md "
        "documents, and no NaN later.",
        "input", "documented answer", "polygon_check", "body_init, and the drop when accepted",
        "verdict", NULL);
    const shape_case_t shapes[] = {
        {"three collinear points", 0, "polygon has zero area"},
        {"a vertex in the middle of an edge", 1, "three consecutive vertices are collinear"},
        {"a repeated vertex", 2, "polygon repeats a vertex"},
        {"clockwise unit box", 3, NULL},
        {"an edge of 1.4e-9 m on a 1 m box (a corner cut)", 4, NULL},
        {"an edge of 1.4e-13 m on a 1 m box", 5, "polygon repeats a vertex"},
        {"zero area: one point three times", 6, "polygon has zero area"},
        {"a regular 1000-gon", 7, NULL},
        {"a NaN vertex", 8, "polygon has a vertex that is not finite"},
        {"an infinite vertex", 9, "polygon has a vertex that is not finite"},
        {"a reflex vertex (arrow)", 10, "a vertex turns against the winding"},
        {"a pentagram (winds twice)", 11, "polygon winds around more than once"},
        {"two vertices", 12, "polygon has fewer than 3 vertices"},
        {"a box of 1e200 m", 13, "polygon is too large: its area overflows"},
        {"a regular 100000-gon (limit, not asserted)", 14, NULL},
    };
    progress("bad input: %zu shapes", sizeof shapes / sizeof shapes[0]);
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; i++) {
        const shape_case_t *c = &shapes[i];
        char id[96];
        snprintf(id, sizeof id, "input.shape_%d", c->kind);
        row_t *r = new_row(t, c->kind == 14 ? NULL : id);
        set_cell(r, 0, "%s", c->label);
        set_cell(r, 1, "%s", c->expected ? c->expected : "usable");
        list_t *p = shape_of(c->kind);
        const char *problem = polygon_check(p);
        list_free(p);
        set_cell(r, 2, "%s", problem ? problem : "usable (NULL)");
        char message[512];
        int status = -1;
        int how = in_child(child_body_init, &c->kind, message, sizeof message, &status);
        bool ok;
        if (c->expected) {
            ok = problem != NULL && strstr(problem, c->expected) != NULL && how == 1 &&
                 strstr(message, "engine error in body_init: bad shape: ") != NULL &&
                 strstr(message, c->expected) != NULL;
            set_cell(r, 3, "%s", how == 1 ? message : "NOT REFUSED");
        } else {
            int sim_status = -1;
            char sim_message[512];
            double t0 = bench_now_ms();
            int sim = in_child(child_simulate, &c->kind, sim_message, sizeof sim_message, &sim_status);
            double ms = bench_now_ms() - t0;
            ok = problem == NULL && how == 0 && sim == 0 && sim_status == 0;
            set_cell(r, 3, "accepted%s; the drop: %s (%s ms for 600 steps)",
                     c->kind == 3 ? ", stored counter-clockwise" : "",
                     sim == 0 && sim_status == 0 ? "finite, at rest" : (sim == 0 ? "NOT AT REST OR NOT FINITE" : sim_message),
                     G(ms));
        }
        r->pass = ok;
        if (c->kind == 14) {
            set_cell(r, 4, "%s", ok ? "as documented" : "limit: rolls (below)");
        } else {
            set_cell(r, 4, "%s", ok ? "as documented" : "FAILS");
        }
    }
    NOTE(t, "**Limit: polygons of about 100000 sides roll.** A resting edge's two ends are block-"
            "solved while the 2x2 system's condition stays under 1e8 (engine/src/solver/velocity_solve.c, "
            "MAX_EDGE_CONDITION_NUMBER); a 1 m polygon passes that from about 90000 sides (edges "
            "of 0.035 mm; 80000 sides still rest), the ends are then solved one at a time, the first takes the whole "
            "load and the polygon rolls away, slowly gaining speed (0.4 m/s after 10 s for "
            "100000 sides). Until that fix (this branch) it happened from a few hundred sides "
            "(300: 0.32 m/s after 10 s). polygon_check accepts the shape, as docs/api.md says; "
            "a body that round is better given fewer sides.\n");
    t = new_table(s, "Values and calls",
                  "Each call in a child process; the abort's message against docs/api.md's table "
                  "(and the tests that already assert it).",
                  "call", "documented answer", "what happens", "verdict", NULL);
    const call_case_t calls[] = {
        {"mass NaN", "body_init(box, NAN, c)", "engine error in body_init: mass is NaN", call_mass_nan},
        {"mass 0", "body_init(box, 0, c)", "mass must be > 0 or INFINITY (got 0)", call_mass_zero},
        {"mass -2", "body_init(box, -2, c)", "mass must be > 0 or INFINITY (got -2)", call_mass_negative},
        {"velocity NaN", "body_set_velocity(b, (NAN, 0))", "engine error in body_set_velocity: v is not finite (nan, 0)", call_velocity_nan},
        {"force infinite", "body_add_force(b, (0, INFINITY))", "engine error in body_add_force: force is not finite", call_force_inf},
        {"dt NaN", "scene_tick(scene, NAN)", "engine error in scene_tick: dt must be finite and >= 0", call_tick_nan},
        {"dt negative", "scene_tick(scene, -0.1)", "dt must be finite and >= 0 (got -0.1)", call_tick_negative},
        {"dt 0", "scene_tick(scene, 0)", NULL, call_tick_zero},
        {"a NULL element", "list_add(list, NULL)", "engine error in list_add: element is NULL", call_list_add_null},
    };
    for (size_t i = 0; i < sizeof calls / sizeof calls[0]; i++) {
        const call_case_t *c = &calls[i];
        char id[96], message[512];
        snprintf(id, sizeof id, "input.call_%zu", i);
        row_t *r = new_row(t, id);
        int status = -1;
        int how = in_child(c->fn, NULL, message, sizeof message, &status);
        set_cell(r, 0, "%s: `%s`", c->label, c->call);
        if (c->expected) {
            set_cell(r, 1, "aborts: %s", c->expected);
            r->pass = how == 1 && strstr(message, c->expected) != NULL;
            set_cell(r, 2, "%s", how == 1 ? message : "DID NOT ABORT");
        } else {
            set_cell(r, 1, "a pause: applies removals, clears the record; no body moves, "
                           "forces kept (scene.zero_dt_* tests)");
            r->pass = how == 0 && status == 0;
            set_cell(r, 2, "%s", r->pass ? "nothing moved, velocity kept" : "SOMETHING MOVED");
        }
        set_cell(r, 3, "%s", r->pass ? "as documented" : "FAILS");
    }
    NOTE(t, "The same answers are asserted by tests/test_polygon.c, test_body.c, test_scene.c and "
            "test_list.c (polygon.check_names_each_problem, body.bad_input_aborts_with_message, "
            "scene.zero_dt_only_reaps_removed_bodies, list.bad_input_aborts_with_message and "
            "their neighbours); this table is the same contract seen from outside.\n");
}

/* ==== 9. Long run and determinism ==== */

static uint64_t hash_mix(uint64_t hash, double d) {
    uint64_t u;
    memcpy(&u, &d, sizeof u);
    for (int i = 0; i < 8; i++) {
        hash ^= (u >> (8 * i)) & 255u;
        hash *= 1099511628211ull;
    }
    return hash;
}

static uint64_t world_hash(const ours_world_t *w) {
    uint64_t hash = 1469598103934665603ull;
    for (int i = 0; i < w->count; i++) {
        body_t *b = w->bodies[i];
        vector_t c = body_get_centroid(b), v = body_get_velocity(b);
        hash = hash_mix(hash, c.x);
        hash = hash_mix(hash, c.y);
        hash = hash_mix(hash, v.x);
        hash = hash_mix(hash, v.y);
        hash = hash_mix(hash, body_get_rotation(b));
        hash = hash_mix(hash, body_get_angular_velocity(b));
    }
    return hash;
}

enum { LONG_BODIES = 200 };

/* The final hash of a bench scene run through ours_sleeping_ops: taken
 * by a world_free that hashes before it frees. */
static uint64_t freed_hash = 0;
static void hashing_world_free(void *world) {
    freed_hash = world_hash((const ours_world_t *)world);
    ours_world_free(world);
}

/* The determinism scenes: the long run's busy gas for `steps` steps, and
 * pile(500) with sleeping on for `steps` / 4 steps; their final hashes. */
static void determinism_hashes(int steps, uint64_t hashes[2]) {
    gas_t *g = malloc(sizeof *g);
    gas_build(&ours_ops, g, LONG_BODIES, 1.0, 0.0, 0.0);
    ours_world_t *w = g->world;
    for (int i = 0; i < steps; i++) scene_tick(w->scene, BENCH_DT);
    hashes[0] = world_hash(w);
    ours_world_free(w);
    free(g);
    bench_ops_t ops = ours_sleeping_ops;
    ops.world_free = hashing_world_free;
    bench_steps = steps / 4;
    bench_case_t c = {SCENE_PILE, 500, BENCH_DT};
    bench_run_t run;
    memset(&run, 0, sizeof run);
    pile_run(&ops, &c, &run);
    bench_steps = 0;
    hashes[1] = freed_hash;
}

/* Resident memory (bytes) from /proc/self/statm; 0 when unreadable. */
static double resident_bytes(void) {
    FILE *f = fopen("/proc/self/statm", "r");
    long size = 0, resident = 0;
    if (f == NULL) return 0.0;
    if (fscanf(f, "%ld %ld", &size, &resident) != 2) resident = 0;
    fclose(f);
    return (double)resident * (double)sysconf(_SC_PAGESIZE);
}

/* This program, for the determinism check's fresh processes (found by
 * readlink: /proc/self/exe in a popen command is the shell's). */
static char self_path[4096] = "/proc/self/exe";

static bool child_hashes(int steps, uint64_t hashes[2]) {
    char command[sizeof self_path + 64];
    snprintf(command, sizeof command, "%s --child-hash %d", self_path, steps);
    FILE *pipe_in = popen(command, "r");
    if (pipe_in == NULL) return false;
    unsigned long long a = 0, b = 0;
    int got = fscanf(pipe_in, "%llx %llx", &a, &b);
    int status = pclose(pipe_in);
    hashes[0] = a;
    hashes[1] = b;
    return got == 2 && status == 0;
}

typedef struct {
    bool done;
    bool finite;
    int inside;
    double lo, hi, rss_start, rss_end, ms, seconds;
    size_t allocations;
    uint64_t first[2], second[2], child1[2], child2[2];
    bool spawned;
} longrun_t;
static longrun_t longrun;

static void longrun_measure(long steps, int hash_steps) {
    progress("long run: %ld steps of %d bodies", steps, LONG_BODIES);
    gas_t *g = malloc(sizeof *g);
    gas_build(&ours_ops, g, LONG_BODIES, 1.0, 0.0, 0.0);
    ours_world_t *w = g->world;
    double e0 = gas_energy(&ours_ops, g, NULL), lo = 1.0, hi = 1.0;
    double rss_start = 0.0;
    size_t allocations_start = 0;
    bool finite = true;
    int inside = 1;
    double t0 = bench_now_ms(), t_warm = t0;
    for (long i = 1; i <= steps && finite; i++) {
        scene_tick(w->scene, BENCH_DT);
        for (int k = 0; k < w->count; k++) {
            body_t *b = w->bodies[k];
            vector_t c = body_get_centroid(b), v = body_get_velocity(b);
            finite &= isfinite(c.x) && isfinite(c.y) && isfinite(v.x) && isfinite(v.y) &&
                      isfinite(body_get_rotation(b)) && isfinite(body_get_angular_velocity(b));
        }
        if (i % 100 == 0) {
            double ratio = gas_energy(&ours_ops, g, &inside) / e0;
            lo = fmin(lo, ratio);
            hi = fmax(hi, ratio);
        }
        if (i == 1000) {
            rss_start = resident_bytes();
            allocations_start = engine_allocation_count();
            t_warm = bench_now_ms();
        }
        if (i % 100000 == 0) progress("long run: %ld steps, energy within [%.9f, %.9f]", i, lo, hi);
    }
    longrun.rss_end = resident_bytes();
    longrun.allocations = engine_allocation_count() - allocations_start;
    longrun.ms = (bench_now_ms() - t_warm) / (double)(steps - 1000);
    longrun.seconds = (bench_now_ms() - t0) / 1000.0;
    ours_world_free(w);
    free(g);
    longrun.finite = finite;
    longrun.inside = inside;
    longrun.lo = lo;
    longrun.hi = hi;
    longrun.rss_start = rss_start;
    progress("determinism: two runs here, two in fresh processes (%d steps)", hash_steps);
    determinism_hashes(hash_steps, longrun.first);
    determinism_hashes(hash_steps, longrun.second);
    longrun.spawned = child_hashes(hash_steps, longrun.child1) &&
                      child_hashes(hash_steps, longrun.child2);
    longrun.done = true;
}

static void longrun_section(void) {
    section_t *s = new_section("Long run and determinism", "");
    long steps = quick ? 100000 : 1000000;
    int hash_steps = 2000;
    if (!longrun.done) longrun_measure(steps, hash_steps);
    table_t *t = new_table(
        s, NULL,
        "The busy scene: the gas of the restitution section with 200 bodies in a 30 m box "
        "(elasticity 1, no gravity, no friction, sleeping off), so that bodies keep meeting for "
        "ever. Every step every state is checked finite (the engine would also stop on one); the "
        "kinetic energy is read every 100 steps; resident memory from /proc/self/statm after "
        "1000 steps and at the end, and the engine's allocation count (engine_allocation_count) "
        "over the same span (10^5 steps with --quick). Determinism: the busy scene for 2000 "
        "steps, and pile(500) with sleeping on for a quarter of that, twice in this process "
        "and once each in two fresh processes (this program run again with --child-hash: a new "
        "address space, allocation order and ASLR): the final states hashed to the bit.",
        "figure", "value", "verdict", NULL);
    const longrun_t *L = &longrun;
    row_t *r = new_row(t, "longrun.finite");
    set_cell(r, 0, "%ld steps of 200 bodies: every state finite", steps);
    set_cell(r, 1, "%s (%s ms a step, %s s in all)", L->finite ? "yes" : "NO", G(L->ms),
             G(L->seconds));
    r->pass = L->finite && L->inside;
    set_cell(r, 2, "%s", r->pass ? "no NaN, no Inf, nothing left the box" : "FAILS");
    r = new_row(t, "longrun.energy");
    set_cell(r, 0, "kinetic energy over the start's (least, largest)");
    set_cell(r, 1, "%.9f, %.9f", L->lo, L->hi);
    r->pass = L->lo > 0.99 && L->hi < 1.01;
    set_cell(r, 2, "%s", r->pass ? "bounded: within 1%" : "FAILS");
    r = new_row(t, "longrun.memory");
    set_cell(r, 0, "resident memory after 1000 steps, at the end; engine allocations between");
    set_cell(r, 1, "%s MB, %s MB; %zu allocations", G(L->rss_start / 1048576.0),
             G(L->rss_end / 1048576.0), L->allocations);
    r->pass = L->rss_end <= L->rss_start + 1048576.0 && L->allocations == 0;
    set_cell(r, 2, "%s", r->pass ? "flat" : "FAILS: grows");

    const char *names[2] = {"the busy scene", "pile(500), sleeping on"};
    for (int k = 0; k < 2; k++) {
        char id[64];
        snprintf(id, sizeof id, "determinism.%s", k == 0 ? "busy" : "pile");
        r = new_row(t, id);
        set_cell(r, 0, "%s: final state hashes, here twice / two processes", names[k]);
        set_cell(r, 1, "%016" PRIx64 " %016" PRIx64 " / %016" PRIx64 " %016" PRIx64,
                 L->first[k], L->second[k], L->spawned ? L->child1[k] : 0,
                 L->spawned ? L->child2[k] : 0);
        r->pass = L->spawned && L->first[k] == L->second[k] && L->first[k] == L->child1[k] &&
                  L->first[k] == L->child2[k];
        set_cell(r, 2, "%s", r->pass ? "bit-identical" : "FAILS");
    }
}

/* ==== output ==== */

static const char *const OPEN_PROBLEMS =
    "## Open problems\n\n"
    "What this suite found and did not fix, each with its figure above:\n\n"
    "- **Very heavy bodies on light supports jitter** (Mass ratios, heavytop): a box 1000 "
    "times heavier than the two boxes holding it stands but keeps moving at about 1 cm/s. "
    "Cause: the shock propagation pass's one-sided pushes. Tried and measured: without the "
    "pass, the pass skipped for heavy bodies, the heavy body held by all its supports at once; "
    "none both keeps r = 1000 standing and settles it. Alternating the sweep order settled "
    "r = 100.\n"
    "- **Far from the origin**: the pyramid is as at the origin to 1e10 m and jitters at 1e12 "
    "m (doubles 0.12 mm apart against a 1 mm slop); Chipmunk2D, with a 5 mm slop, still "
    "rests there, and Box2D's floats give out at 1e6 m.\n"
    "- **Polygons of about 90000 sides and more roll** on a floor (Degenerate shapes): past "
    "the block solve's condition bound the edge's ends are solved one at a time again.\n"
    "- **pile(4000) creeps** (known before this suite): at 60-70 s hundreds of bodies still "
    "move faster than 1 cm/s with and without the shock pass (measured in a scratch copy: "
    "157 to 1201 of them, total kinetic energy 0.03 to 0.5 J, the fastest at 0.7 m/s "
    "rolling down the heap's surface); pile(2000), the case asked for, settles far inside its "
    "bounds here. A rebuild of pile(2000) with masses from polygon_area instead of the "
    "benchmark's formula (a different chaotic run) peaked at 0.031 J and 0.82 N s over "
    "60-70 s: inside the bounds, with less margin. With sleeping on it is still awake at "
    "120 s (docs/design.md, Sleeping, says why).\n"
    "- **Sleeping stops slow free flight**: with sleeping on, a body that feels no force and "
    "no gravity and moves slower than 0.01 m/s for half a second is put to sleep with "
    "velocity 0, as scene.h documents for resting islands; in a zero-gravity scene that "
    "removes momentum (two boxes meeting at 1 cm/s stopped dead; the suite's free-flight "
    "tests run with sleeping off).\n"
    "- **Multi-stage schemes against a floor under a stiff spring** (Stiff and extreme cases, "
    "the sprung box): velocity Verlet, RK4 and symplectic4 evaluate the spring at trial poses "
    "inside the floor, so the box rests millimetres deep with 94-96% of the load carried, and "
    "RK4's goes through the floor at omega dt = 2.5. The contact acts once per step, not at "
    "each stage.\n"
    "- **A change of step jolts a settled pyramid** (Stiff and extreme cases, dt changed): "
    "going from 1/60 s to 1/240 s gives the bottom row about 1 cm/s for a step; it moves "
    "under a millimetre and settles again within a few steps. Cause not investigated.\n"
    "- **A rigid box wedged between walls slides down** (Stiff and extreme cases): overlapping "
    "both walls, it is pushed out of both at once and carries no normal force, so friction "
    "does not hold it; no energy is gained.\n\n";

/* The energy factor per step against omega dt for each integrator, undamped:
 * the theory's curves on a fine grid and the measured points (the zeta = 0
 * spring's lines), for gnuplot (stability.sh draws them when it can). */
static void write_plot(const char *dir) {
    char path[1024];
    snprintf(path, sizeof path, "%s/springs.dat", dir);
    FILE *f = fopen(path, "w");
    if (f == NULL) return;
    fprintf(f, "# omega_dt");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) fprintf(f, " %s", integrator_key(i));
    fprintf(f, "\n");
    for (int k = 1; k <= 300; k++) {
        double theta = 0.01 * k;
        fprintf(f, "%g", theta);
        for (int i = 0; i < INTEGRATOR_COUNT; i++) fprintf(f, " %.6g", theory_growth(i, theta, 0.0));
        fprintf(f, "\n");
    }
    fclose(f);
    snprintf(path, sizeof path, "%s/springs-measured.dat", dir);
    f = fopen(path, "w");
    if (f == NULL) return;
    static const char *const samples[7] = {"0.1", "0.5", "1", "1.5", "2", "2.5", "3"};
    fprintf(f, "# omega_dt, then the measured energy factor per step of each integrator, chipmunk, box2d\n");
    for (int k = 0; k < 7; k++) {
        char key[32];
        snprintf(key, sizeof key, "growth_%s", samples[k]);
        fprintf(f, "%s", samples[k]);
        for (int i = 0; i < INTEGRATOR_COUNT; i++) {
            fprintf(f, " %.6g", num(find("ours", "spring", 0.0, "integrator", integrator_key(i)), key));
        }
        fprintf(f, " %.6g %.6g\n", num(find("chipmunk", "spring", 0.0, NULL, NULL), key),
                num(find("box2d", "spring", 0.0, NULL, NULL), key));
    }
    fclose(f);
    snprintf(path, sizeof path, "%s/plots.gp", dir);
    f = fopen(path, "w");
    if (f == NULL) return;
    fprintf(f,
            "# gnuplot plots.gp (in docs/stability): the energy factor per step of an undamped "
            "spring against omega dt.\n"
            "set terminal svg size 800,500 font 'sans,12'\n"
            "set output 'springs.svg'\n"
            "set logscale y\nset yrange [0.08:100]\nset xrange [0:3]\n"
            "set xlabel 'omega dt'\nset ylabel 'energy factor per step'\n"
            "set key top left\nset grid\n"
            "plot ");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        fprintf(f, "'springs.dat' using 1:%d with lines lc %d title '%s (theory)', ", i + 2, i + 1,
                integrator_get_name(i));
        fprintf(f, "'springs-measured.dat' using 1:%d with points pt 7 lc %d notitle, ", i + 2,
                i + 1);
    }
    fprintf(f, "'springs-measured.dat' using 1:%d with points pt 4 lc rgb 'black' title "
               "'Chipmunk2D (measured)', 'springs-measured.dat' using 1:%d with points pt 6 lc "
               "rgb 'gray40' title 'Box2D 2.4 (measured)'\n",
            INTEGRATOR_COUNT + 2, INTEGRATOR_COUNT + 3);
    fclose(f);
}

/* A cell for a markdown table: '|' would end it. */
static void put_cell(FILE *f, const char *text) {
    fputc(' ', f);
    for (const char *p = text; *p; p++) {
        if (*p == '|') {
            fputs("/", f);
        } else {
            fputc(*p, f);
        }
    }
    fputs(" |", f);
}

static void count_verdicts(int *passed, int *failed) {
    *passed = *failed = 0;
    for (int i = 0; i < section_count; i++) {
        for (int k = 0; k < sections[i].table_count; k++) {
            const table_t *t = sections[i].tables[k];
            for (int j = 0; j < t->row_count; j++) {
                if (!t->rows[j].asserted) continue;
                if (t->rows[j].pass) {
                    (*passed)++;
                } else {
                    (*failed)++;
                }
            }
        }
    }
}

static void write_doc(const char *path, double seconds) {
    FILE *f = fopen(path, "w");
    if (f == NULL) {
        fprintf(stderr, "stability: cannot write %s: %s\n", path, strerror(errno));
        exit(2);
    }
    int passed, failed;
    count_verdicts(&passed, &failed);
    time_t now = time(NULL);
    char date[64];
    strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", gmtime(&now));
    fprintf(f, "# Numerical stability on stiff and extreme cases\n\n");
    fprintf(f,
            "Generated by `make stability` (tests/stability/stability.c and stability.sh); do not "
            "edit by hand. Each case is measured on this engine (engine %s) and, wherever the "
            "case exists for them, on Chipmunk2D 7.0.3 and Box2D 2.4.1 in the same run, through "
            "the benchmark programs of tests/bench (docs/bench.md): the scenes are written once, "
            "in tests/bench/bench_scenes.h. Run of %s, %s%s, %.0f s. The peers' figures: %s.\n\n",
            BENCH_ENGINE_VERSION, date, quick ? "--quick" : "full sizes",
            check ? ", --check" : "", seconds,
            have_peers ? "build/stability/peers.txt, all the raw lines in "
                         "[stability/lines.txt](stability/lines.txt)"
                       : "not run (no --peers)");
    fprintf(f,
            "**Verdicts: %d hold, %d fail** (the asserted ones; `make check` runs the --quick "
            "version and fails on any). Units SI; dt = 1/60 s unless a case says otherwise; "
            "\"KE\" is kinetic energy (translation and rotation).\n\n",
            passed, failed);
    if (failed > 0) {
        fprintf(f, "Failing:");
        for (int i = 0; i < section_count; i++) {
            for (int k = 0; k < sections[i].table_count; k++) {
                const table_t *t = sections[i].tables[k];
                for (int j = 0; j < t->row_count; j++) {
                    if (t->rows[j].asserted && !t->rows[j].pass) fprintf(f, " `%s`", t->rows[j].id);
                }
            }
        }
        fprintf(f, "\n\n");
    }
    fprintf(f, "| section | verdicts held | limits written up |\n|---|---|---|\n");
    for (int i = 0; i < section_count; i++) {
        int held = 0, asserted = 0, limits = 0;
        for (int k = 0; k < sections[i].table_count; k++) {
            const table_t *t = sections[i].tables[k];
            for (int j = 0; j < t->row_count; j++) {
                asserted += t->rows[j].asserted;
                held += t->rows[j].asserted && t->rows[j].pass;
            }
            for (const char *p = t->notes; (p = strstr(p, "**Limit")) != NULL; p++) limits++;
        }
        fprintf(f, "| %d. %s | %d of %d | %d |\n", i + 1, sections[i].title, held, asserted,
                limits);
    }
    fprintf(f, "\n");
    for (int i = 0; i < section_count; i++) {
        const section_t *s = &sections[i];
        fprintf(f, "## %d. %s\n\n", i + 1, s->title);
        if (s->text[0]) fprintf(f, "%s\n\n", s->text);
        for (int k = 0; k < s->table_count; k++) {
            const table_t *t = s->tables[k];
            if (t->title[0]) fprintf(f, "### %s\n\n", t->title);
            if (t->text[0]) fprintf(f, "%s\n\n", t->text);
            fputc('|', f);
            for (int c = 0; c < t->columns; c++) put_cell(f, t->header[c]);
            fputs("\n|", f);
            for (int c = 0; c < t->columns; c++) fputs("---|", f);
            fputc('\n', f);
            for (int j = 0; j < t->row_count; j++) {
                fputc('|', f);
                for (int c = 0; c < t->columns; c++) put_cell(f, t->rows[j].cell[c]);
                fputc('\n', f);
            }
            fputc('\n', f);
            if (t->notes[0]) fprintf(f, "%s\n", t->notes);
        }
    }
    fprintf(f, "%s", OPEN_PROBLEMS);
    fprintf(f, "## Reproducing\n\n"
               "`make stability` (about two minutes on two cores: this engine's cases in one "
               "process while the peers' programs run beside it; the million-step run is half "
               "a minute of it); `make check` runs `build/stability/stability --quick --check` "
               "(about 20 s: the same cases but a coarser spring sweep, 10^5 steps for the "
               "long run and no pile(10000)). Every scene of "
               "the peers' columns can be run alone, e.g. `build/bench/bench_box2d --scene "
               "stack2 --runs 1`; this engine's with `build/bench/bench_engine --scene stack2 "
               "--runs 1 [--integrator rk4]`.\n");
    fclose(f);
}

/* A CSV field, quoted, its quotes doubled. */
static void put_csv(FILE *f, const char *text) {
    fputc('"', f);
    for (const char *p = text; *p; p++) {
        if (*p == '"') fputc('"', f);
        fputc(*p, f);
    }
    fputc('"', f);
}

static void write_csv(const char *dir) {
    mkdir(dir, 0777);
    char path[1024];
    snprintf(path, sizeof path, "%s/stability.csv", dir);
    FILE *f = fopen(path, "w");
    if (f == NULL) return;
    fprintf(f, "section,table,id,asserted,pass,cells\n");
    for (int i = 0; i < section_count; i++) {
        for (int k = 0; k < sections[i].table_count; k++) {
            const table_t *t = sections[i].tables[k];
            for (int j = 0; j < t->row_count; j++) {
                const row_t *r = &t->rows[j];
                put_csv(f, sections[i].title);
                fputc(',', f);
                put_csv(f, t->title);
                fprintf(f, ",%s,%d,%d", r->id, r->asserted, r->pass);
                for (int c = 0; c < t->columns; c++) {
                    fputc(',', f);
                    put_csv(f, r->cell[c]);
                }
                fputc('\n', f);
            }
        }
    }
    fclose(f);
}

static void write_raw(const char *path) {
    FILE *f = fopen(path, "w");
    if (f == NULL) return;
    for (int i = 0; i < line_count; i++) fprintf(f, "%s\n", lines[i]);
    fclose(f);
}

/* ==== 10. Stiff and extreme cases ==== */

#include "extreme_cases.h"

static void build_sections(void) {
    for (int i = 0; i < section_count; i++) {
        for (int k = 0; k < sections[i].table_count; k++) free(sections[i].tables[k]);
    }
    section_count = 0;
    springs_section();
    mass_section();
    speed_section();
    overlap_section();
    stacks_section();
    restitution_section();
    place_section();
    input_section();
    longrun_section();
    extreme_section();
}

/* Waits (at most an hour) until the file's last line is "# peers done". */
static void wait_for(const char *path) {
    for (int waited = 0; waited < 3600; waited++) {
        FILE *f = fopen(path, "r");
        char buffer[4096], last[4096] = "";
        if (f != NULL) {
            while (fgets(buffer, sizeof buffer, f)) snprintf(last, sizeof last, "%s", buffer);
            fclose(f);
        }
        if (strncmp(last, "# peers done", 12) == 0) return;
        if (waited % 30 == 0) progress("waiting for the peers' figures in %s", path);
        sleep(1);
    }
    progress("gave up waiting for %s", path);
}

int main(int argc, char **argv) {
    const char *peers_path = NULL;
    for (int i = 1; i < argc; i++) {
        const char *value = i + 1 < argc ? argv[i + 1] : NULL;
        if (strcmp(argv[i], "--quick") == 0) {
            quick = true;
        } else if (strcmp(argv[i], "--check") == 0) {
            check = true;
        } else if (strcmp(argv[i], "--child-hash") == 0 && value) {
            uint64_t hashes[2];
            determinism_hashes(atoi(argv[++i]), hashes);
            printf("%016" PRIx64 " %016" PRIx64 "\n", hashes[0], hashes[1]);
            return 0;
        } else if (strcmp(argv[i], "--peers") == 0 && value) {
            peers_path = argv[++i];
        } else if (strcmp(argv[i], "--doc") == 0 && value) {
            doc_path = argv[++i];
        } else if (strcmp(argv[i], "--out") == 0 && value) {
            out_dir = argv[++i];
        } else if (strcmp(argv[i], "--raw") == 0 && value) {
            raw_path = argv[++i];
        } else {
            fprintf(stderr,
                    "usage: %s [--quick] [--check] [--peers FILE] [--doc FILE] [--out DIR] "
                    "[--raw FILE] | --child-hash STEPS\n",
                    argv[0]);
            return 2;
        }
    }
    run_started = bench_now_ms();
    bench_quick = quick;
    ssize_t length = readlink("/proc/self/exe", self_path, sizeof self_path - 1);
    if (length > 0) self_path[length] = '\0';
    build_sections();
    if (peers_path) {
        /* The peers' programs may still be running beside this one
         * (stability.sh): their file is complete at its last line. */
        wait_for(peers_path);
        load_lines(peers_path);
        have_peers = true;
        quiet = true;
        build_sections();
    }
    double seconds = (bench_now_ms() - run_started) / 1000.0;
    if (doc_path) write_doc(doc_path, seconds);
    if (out_dir) {
        write_csv(out_dir);
        write_plot(out_dir);
    }
    if (raw_path) write_raw(raw_path);
    int passed, failed;
    count_verdicts(&passed, &failed);
    if (check) {
        for (int i = 0; i < section_count; i++) {
            for (int k = 0; k < sections[i].table_count; k++) {
                const table_t *t = sections[i].tables[k];
                for (int j = 0; j < t->row_count; j++) {
                    const row_t *r = &t->rows[j];
                    if (!r->asserted) continue;
                    printf("%s stability.%s", r->pass ? "PASS" : "FAIL", r->id);
                    if (!r->pass) {
                        for (int c = 0; c < t->columns; c++) printf(" | %s", r->cell[c]);
                    }
                    printf("\n");
                }
            }
        }
        printf("%d passed, %d failed\n", passed, failed);
    }
    progress("done: %d verdicts hold, %d fail", passed, failed);
    return check && failed > 0 ? 1 : 0;
}
