/*
 * Stability regions. Theory: amplification.h's closed forms, derived with
 * sympy from the schemes' definitions (derive_amplification.py). A damped
 * spring x'' = -omega^2 x - 2 zeta omega x' has the eigenvalues lambda =
 * omega (-zeta +- i sqrt(1 - zeta^2)), so h lambda sweeps the upper half
 * plane as (omega h, zeta) run over (0, inf) x [-1, 1]: the imaginary
 * axis is the undamped spring, the rays of angle acos(zeta) from it the
 * damped ones. Drag alone (x'' = -gamma x') has h lambda = -gamma h on the
 * negative real axis. Measured: the engine's damped spring and drag,
 * through the public API, the limit along each ray found by bisection.
 */
#include <math.h>
#include <string.h>
#include "amplification.h"
#include "report.h"

enum { RAYS = 6 };
/* The damping ratios of the rays measured (0: the imaginary axis). */
static const double ZETAS[RAYS] = {0.0, 0.1, 0.3, 0.5, 0.7, 0.9};
/* The largest omega h or gamma h looked at. */
static const double LARGEST = 8.0;
/* Where make check compares the spectral radius of the engine's one-step
 * map with the closed form's, to 1e-9: (omega h, zeta). */
enum { RADIUS_POINTS = 3 };
static const double RADIUS_AT[RADIUS_POINTS][2] = {{0.7, 0.0}, {1.0, 0.1}, {1.3, 0.6}};
/* A measured limit may miss the closed form's by this (make check). */
static const double TOLERANCE = 0.01;
/* The engine's runs: steps, and the growth of the largest |state| from the
 * first half to the second that counts as unstable. */
enum { STEPS = 6000 };
static const double UNSTABLE_GROWTH = 4.0;

static const amplification_t *closed_form(integrator_t integrator) {
    for (int k = 0; k < (int)AMPLIFICATION_SCHEMES; k++) {
        if (strcmp(AMPLIFICATION[k].scheme, integrator_get_name(integrator)) == 0) {
            return &AMPLIFICATION[k];
        }
    }
    return NULL;
}

static double polynomial(const amplification_term_t *terms, int count, double t, double c) {
    double sum = 0.0;
    for (int k = 0; k < count && terms[k].coefficient != 0.0; k++) {
        sum += terms[k].coefficient * pow(t, terms[k].i) * pow(c, terms[k].j);
    }
    return sum;
}

/* A denominator: 1 when the list is empty. */
static double denominator(const amplification_term_t *terms, int count, double t, double c) {
    return terms[0].coefficient == 0.0 ? 1.0 : polynomial(terms, count, t, c);
}

/* The spectral radius of the scheme's step on the damped spring. */
static double theory_radius(const amplification_t *a, double theta, double zeta) {
    double c = 2.0 * zeta, q = denominator(a->denominator, 8, theta, c);
    double trace = polynomial(a->trace, 24, theta, c) / q;
    double det = polynomial(a->det, 24, theta, c) / q;
    double discriminant = trace * trace - 4.0 * det;
    if (discriminant < 0.0) return sqrt(det);
    return (fabs(trace) + sqrt(discriminant)) / 2.0;
}

static double theory_drag(const amplification_t *a, double z) {
    return fabs(polynomial(a->drag, 8, z, 0.0) / denominator(a->drag_denominator, 8, z, 0.0));
}

/* The least x in (0, LARGEST] at which radius(x) passes 1 (to 1e-12): a
 * scan, then bisection; 0 when it does at once, INFINITY when nowhere. */
static double first_exit(double (*radius)(const amplification_t *, double, double),
                         const amplification_t *a, double zeta) {
    const double step = 1e-3, slack = 1e-12;
    if (radius(a, step, zeta) > 1.0 + slack) return 0.0;
    for (double lo = step; lo < LARGEST; lo += step) {
        double hi = fmin(lo + step, LARGEST);
        if (radius(a, hi, zeta) <= 1.0 + slack) continue;
        while (hi - lo > 1e-12 * hi) {
            double mid = 0.5 * (lo + hi);
            if (radius(a, mid, zeta) > 1.0 + slack) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return 0.5 * (lo + hi);
    }
    return INFINITY;
}

static double drag_radius(const amplification_t *a, double gamma_h, double unused) {
    (void)unused;
    return theory_drag(a, -gamma_h);
}

static double theory_limit(const amplification_t *a, double zeta) {
    return first_exit(theory_radius, a, zeta);
}

static double theory_drag_limit(const amplification_t *a) {
    return first_exit(drag_radius, a, 0.0);
}

/* ---- The engine ---- */

static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};

/* The growth per step of the engine's damped spring (omega = 1, zeta; or
 * drag alone, gamma = gamma_h, when drag_only) at step theta: the largest
 * |(x, v)| over the second half of the run over that over the first, to
 * the power 1 / (steps / 2); a run that grows past 1e100 stops there. */
static double engine_radius(integrator_t integrator, double theta, double zeta, bool drag_only) {
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    body_t *anchor = body_init(polygon_make_box(VEC_ZERO, 0.01, 0.01), INFINITY, GREY);
    body_t *body = body_init(polygon_make_box((vector_t){1.0, 0.0}, 0.01, 0.01), 1.0, GREY);
    scene_add_body(scene, anchor);
    scene_add_body(scene, body);
    double h = drag_only ? 1.0 : theta;
    if (drag_only) {
        body_set_velocity(body, (vector_t){1.0, 0.0});
        create_drag(scene, theta, body);
    } else {
        body_set_velocity(body, (vector_t){0.3, 0.0});
        create_spring(scene, 1.0, anchor, body);
        if (zeta > 0.0) create_drag(scene, 2.0 * zeta, body);
    }
    double first = 0.0, second = 0.0, radius = NAN;
    for (int n = 1; n <= STEPS; n++) {
        scene_tick(scene, h);
        vector_t x = body_get_centroid(body), v = body_get_velocity(body);
        double size = drag_only ? fabs(v.x) : hypot(x.x, v.x);
        if (!(size < 1e100)) {
            radius = pow(1e100, 1.0 / n);
            break;
        }
        if (n <= STEPS / 2) {
            first = fmax(first, size);
        } else {
            second = fmax(second, size);
        }
    }
    scene_free(scene);
    if (isnan(radius)) radius = pow(second / first, 2.0 / STEPS);
    return radius;
}

/* The spectral radius of the engine's one-step map at theta: the map is
 * linear, so two single steps from (x, v) = (1, 0) and (0, 1) give its
 * matrix (drag alone: one step gives R). */
static double engine_step_radius(integrator_t integrator, double theta, double zeta,
                                 bool drag_only) {
    double column[2][2];
    for (int k = 0; k < (drag_only ? 1 : 2); k++) {
        scene_t *scene = scene_init();
        scene_set_integrator(scene, integrator);
        body_t *anchor = body_init(polygon_make_box(VEC_ZERO, 0.01, 0.01), INFINITY, GREY);
        body_t *body = body_init(polygon_make_box(VEC_ZERO, 0.01, 0.01), 1.0, GREY);
        scene_add_body(scene, anchor);
        scene_add_body(scene, body);
        body_set_centroid(body, (vector_t){k == 0 && !drag_only ? 1.0 : 0.0, 0.0});
        body_set_velocity(body, (vector_t){k == 1 || drag_only ? 1.0 : 0.0, 0.0});
        if (drag_only) {
            create_drag(scene, theta, body);
        } else {
            create_spring(scene, 1.0, anchor, body);
            if (zeta > 0.0) create_drag(scene, 2.0 * zeta, body);
        }
        scene_tick(scene, drag_only ? 1.0 : theta);
        column[k][0] = body_get_centroid(body).x;
        column[k][1] = body_get_velocity(body).x;
        scene_free(scene);
    }
    if (drag_only) return fabs(column[0][1]);
    double trace = column[0][0] + column[1][1];
    double det = column[0][0] * column[1][1] - column[1][0] * column[0][1];
    double discriminant = trace * trace - 4.0 * det;
    if (discriminant < 0.0) return sqrt(det);
    return (fabs(trace) + sqrt(discriminant)) / 2.0;
}

static double step_radius_adapter(const amplification_t *unused, double theta, double zeta);
static integrator_t adapter_integrator;
static bool adapter_drag;

static double step_radius_adapter(const amplification_t *unused, double theta, double zeta) {
    (void)unused;
    return engine_step_radius(adapter_integrator, theta, zeta, adapter_drag);
}

/* The engine's limit from its one-step map, as first_exit finds theory's. */
static double engine_step_limit(integrator_t integrator, double zeta, bool drag_only) {
    adapter_integrator = integrator;
    adapter_drag = drag_only;
    return first_exit(step_radius_adapter, NULL, zeta);
}

static bool engine_unstable(integrator_t integrator, double theta, double zeta, bool drag_only) {
    return engine_radius(integrator, theta, zeta, drag_only) >
           pow(UNSTABLE_GROWTH, 2.0 / STEPS);
}

/* The engine's limit by bisection in [low, high] (stable at low, unstable
 * at high, else NAN). */
static double engine_limit_between(integrator_t integrator, double zeta, bool drag_only,
                                   double low, double high) {
    if (engine_unstable(integrator, low, zeta, drag_only) ||
        !engine_unstable(integrator, high, zeta, drag_only)) {
        return NAN;
    }
    for (int k = 0; k < 24; k++) {
        double mid = 0.5 * (low + high);
        if (engine_unstable(integrator, mid, zeta, drag_only)) {
            high = mid;
        } else {
            low = mid;
        }
    }
    return 0.5 * (low + high);
}

/* Without a closed form: the first unstable step of a geometric scan up to
 * LARGEST * 100, then bisection; INFINITY when none is. */
static double engine_limit_scanned(integrator_t integrator, double zeta, bool drag_only) {
    double previous = 0.01;
    if (engine_unstable(integrator, previous, zeta, drag_only)) return 0.0;
    for (double theta = previous * 1.25; theta <= LARGEST * 100.0; theta *= 1.25) {
        if (engine_unstable(integrator, theta, zeta, drag_only)) {
            return engine_limit_between(integrator, zeta, drag_only, previous, theta);
        }
        previous = theta;
    }
    return INFINITY;
}

static double engine_limit(integrator_t integrator, double zeta, bool drag_only, double theory) {
    if (isnan(theory) || isinf(theory) || theory == 0.0) {
        return engine_limit_scanned(integrator, zeta, drag_only);
    }
    return engine_limit_between(integrator, zeta, drag_only, 0.5 * theory, 1.5 * theory);
}

/* ---- One scheme's limits, theory beside the engine ---- */

typedef struct {
    /* The rays, then drag: the closed form's limit, the engine's from its
     * one-step map and from long runs. */
    double theory[RAYS + 1], measured[RAYS + 1], run[RAYS + 1];
    /* Where theory says unstable at every step (limit 0): the growth per
     * step at omega h = 0.5 on the undamped spring. */
    double theory_growth, measured_growth;
} limits_t;

static limits_t measure_limits(integrator_t integrator) {
    const amplification_t *a = closed_form(integrator);
    limits_t l;
    for (int r = 0; r <= RAYS; r++) {
        bool drag = r == RAYS;
        double zeta = drag ? 0.0 : ZETAS[r];
        l.theory[r] = a == NULL ? NAN : drag ? theory_drag_limit(a) : theory_limit(a, zeta);
        l.measured[r] = engine_step_limit(integrator, zeta, drag);
        l.run[r] = engine_limit(integrator, zeta, drag, l.measured[r]);
    }
    l.theory_growth = a != NULL ? theory_radius(a, 0.5, 0.0) : NAN;
    l.measured_growth = engine_radius(integrator, 0.5, 0.0, false);
    return l;
}

static bool limit_holds(double theory, double measured) {
    if (isnan(theory)) return true;
    if (theory == 0.0) return measured == 0.0;
    if (isinf(theory)) return isinf(measured);
    return fabs(measured / theory - 1.0) <= TOLERANCE;
}

static bool growth_holds(const limits_t *l) {
    if (l->theory[0] != 0.0) return true;
    return fabs((l->measured_growth - 1.0) / (l->theory_growth - 1.0) - 1.0) <= TOLERANCE;
}

static const char *ray_name(int r, char *text, size_t size) {
    if (r == RAYS) {
        snprintf(text, size, "drag");
    } else {
        snprintf(text, size, "zeta_%g", ZETAS[r]);
    }
    return text;
}

int report_check_regions(void) {
    int passed = 0, failed = 0;
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        if (closed_form((integrator_t)i) == NULL) continue;
        limits_t l = measure_limits((integrator_t)i);
        for (int r = 0; r <= RAYS; r++) {
            char ray[32];
            ray_name(r, ray, sizeof ray);
            bool ok = limit_holds(l.theory[r], l.measured[r]);
            printf("%s regions.%s.%s: theory %.6g, engine's step %.6g (runs %.6g)\n",
                   ok ? "PASS" : "FAIL", integrator_get_name((integrator_t)i), ray, l.theory[r],
                   l.measured[r], l.run[r]);
            ok ? passed++ : failed++;
        }
        const amplification_t *a = closed_form((integrator_t)i);
        for (int p = 0; p < RADIUS_POINTS; p++) {
            double theta = RADIUS_AT[p][0], zeta = RADIUS_AT[p][1];
            double theory = theory_radius(a, theta, zeta);
            double engine = engine_step_radius((integrator_t)i, theta, zeta, false);
            bool ok = fabs(engine / theory - 1.0) <= 1e-9;
            printf("%s regions.%s.radius_at_%g_%g: theory %.12g, engine's step %.12g\n",
                   ok ? "PASS" : "FAIL", integrator_get_name((integrator_t)i), theta, zeta,
                   theory, engine);
            ok ? passed++ : failed++;
        }
        if (l.theory[0] == 0.0) {
            bool ok = growth_holds(&l);
            printf("%s regions.%s.growth_at_0.5: theory %.8g, measured %.8g\n",
                   ok ? "PASS" : "FAIL", integrator_get_name((integrator_t)i), l.theory_growth,
                   l.measured_growth);
            ok ? passed++ : failed++;
        }
    }
    printf("%d passed, %d failed\n", passed, failed);
    return failed;
}

/* ---- The page ---- */

static void write_grid(const amplification_t *a, const report_options_t *options, int index) {
    char name[64];
    snprintf(name, sizeof name, "region-%d.grid", index);
    FILE *grid = report_open(options->out_dir, name);
    const int n = options->quick ? 60 : 240;
    for (int ix = 0; ix <= n; ix++) {
        double x = -5.0 + 5.5 * ix / n;
        for (int iy = 0; iy <= n; iy++) {
            double y = -4.0 + 8.0 * iy / n, theta = hypot(x, y);
            double radius = theta == 0.0 ? 1.0 : theory_radius(a, theta, -x / theta);
            fprintf(grid, "%.5g %.5g %.8g\n", x, y, fmin(radius, 10.0));
        }
        fprintf(grid, "\n");
    }
    fclose(grid);
}

static void write_measured(const limits_t *l, const report_options_t *options, int index) {
    char name[64];
    snprintf(name, sizeof name, "region-%d-measured.dat", index);
    FILE *dat = report_open(options->out_dir, name);
    for (int r = 0; r < RAYS; r++) {
        double t = l->measured[r], zeta = ZETAS[r];
        if (isfinite(t)) fprintf(dat, "%.6g %.6g\n", -zeta * t, t * sqrt(1.0 - zeta * zeta));
    }
    fclose(dat);
    snprintf(name, sizeof name, "region-%d-drag.dat", index);
    dat = report_open(options->out_dir, name);
    if (isfinite(l->measured[RAYS])) fprintf(dat, "%.6g 0\n", -l->measured[RAYS]);
    fclose(dat);
}

static void write_plot(FILE *gp, const limits_t *limits, const char *out_dir) {
    int columns = INTEGRATOR_COUNT <= 6 ? 3 : 4, rows = (INTEGRATOR_COUNT + columns - 1) / columns;
    fprintf(gp, "set terminal svg size %d,%d dynamic font 'sans,10'\n", 380 * columns,
            360 * rows);
    fprintf(gp, "unset logscale\nset format x '%%g'\nset format y '%%g'\nset size ratio -1\n"
                "set contour base\nset cntrparam levels discrete 1\nunset surface\n"
                "set view map\n");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        if (closed_form((integrator_t)i) == NULL) continue;
        fprintf(gp, "set table 'region-%d.contour'\nsplot 'region-%d.grid' using 1:2:3 with "
                    "lines\nunset table\n", i, i);
    }
    fprintf(gp, "set output 'regions.svg'\nset multiplot layout %d,%d title \"Spectral "
                "radius 1 (closed form, line); the engine's limits (dots: damped springs; "
                "square: drag alone)\"\nset xrange [-5:0.5]\nset yrange [-4:4]\nunset key\n"
                "set xlabel 'Re h lambda'\nset ylabel 'Im h lambda'\n",
            rows, columns);
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        (void)limits;
        fprintf(gp, "set title '%s'\n", integrator_get_name((integrator_t)i));
        report_plot_t plot = report_plot_start(gp);
        char file[64];
        if (closed_form((integrator_t)i) != NULL) {
            report_plot_add(&plot, "'region-%d.contour' with lines lt 1 lw 1.5", i);
        }
        snprintf(file, sizeof file, "region-%d-measured.dat", i);
        if (report_has_data(out_dir, file)) {
            report_plot_add(&plot, "'%s' with points pt 7 lc rgb 'black', '%s' using 1:(-$2) "
                                   "with points pt 7 lc rgb 'black'", file, file);
        }
        snprintf(file, sizeof file, "region-%d-drag.dat", i);
        if (report_has_data(out_dir, file)) {
            report_plot_add(&plot, "'%s' with points pt 5 ps 1.2 lc rgb 'red'", file);
        }
        if (plot.clauses > 0) report_plot_add(&plot, "0 with lines lc rgb 'grey'");
        report_plot_end(&plot);
    }
    fprintf(gp, "unset multiplot\nunset contour\nset surface\nunset view\nset size noratio\n"
                "unset xrange\nunset yrange\nset autoscale\nset logscale xy\n"
                "set format y '%%.0e'\nset terminal svg size 760,500 dynamic font 'sans,11'\n"
                "set key outside right top\n");
}

static void format_limit(char *text, size_t size, double value, const char *none) {
    if (isnan(value)) {
        snprintf(text, size, "-");
    } else if (isinf(value)) {
        snprintf(text, size, "%s", none);
    } else {
        snprintf(text, size, "%.4f", value);
    }
}

static void write_cell(FILE *md, double theory, double measured, double run) {
    char t[32], m[32], r[32], none[32], scanned[32];
    snprintf(none, sizeof none, "no limit to %g", LARGEST);
    snprintf(scanned, sizeof scanned, "no limit to %g", LARGEST * 100.0);
    format_limit(t, sizeof t, theory, "no limit");
    format_limit(m, sizeof m, measured, none);
    format_limit(r, sizeof r, run, scanned);
    fprintf(md, " | %s / %s / %s%s", t, m, r,
            limit_holds(theory, measured) ? "" : " **(misses)**");
}

void report_write_regions(FILE *md, FILE *gp, const report_options_t *options,
                          report_summary_t *summary) {
    static limits_t limits[INTEGRATOR_COUNT];
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        fprintf(stderr, "\r  stability regions %-18s", integrator_get_name((integrator_t)i));
        limits[i] = measure_limits((integrator_t)i);
        const amplification_t *a = closed_form((integrator_t)i);
        if (md == NULL) continue;
        if (a != NULL) write_grid(a, options, i);
        write_measured(&limits[i], options, i);
    }
    fprintf(stderr, "\n");
    for (int i = 0; i < INTEGRATOR_COUNT && summary != NULL; i++) {
        summary[i].spring_limit = limits[i].theory[0];
        summary[i].drag_limit = limits[i].theory[RAYS];
    }
    FILE *csv = report_open(options->out_dir, "regions.csv");
    fprintf(csv, "integrator,ray,theory,engine_step,engine_runs\n");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        for (int r = 0; r <= RAYS; r++) {
            char ray[32];
            fprintf(csv, "%s,%s,%.10g,%.10g,%.6g\n", integrator_get_name((integrator_t)i),
                    ray_name(r, ray, sizeof ray), limits[i].theory[r], limits[i].measured[r],
                    limits[i].run[r]);
        }
    }
    fclose(csv);
    if (md == NULL) return;
    write_plot(gp, limits, options->out_dir);
    fprintf(md,
            "\n## 3. Stability regions\n\n"
            "A damped spring x'' = -omega^2 x - 2 zeta omega x' has the eigenvalues lambda = "
            "omega (-zeta ± i sqrt(1 - zeta^2)): as omega h and zeta run over (0, inf) and "
            "[-1, 1], h lambda sweeps the plane, the undamped spring on the imaginary axis and "
            "the damped ones on rays at angle acos(zeta) from it. A scheme's one-step matrix "
            "on (x, v) has a trace and a determinant that are polynomials in omega h and zeta "
            "(rational functions for an implicit scheme): RK4 and explicit Euler are linear "
            "one-step methods on (x, v), so their region "
            "depends on h lambda alone; the others treat x and v apart, and their region is "
            "that of this family. Drag alone, x'' = -gamma x', puts h lambda = -gamma h on "
            "the negative real axis; a step multiplies v by R(-gamma h). The closed forms are "
            "derived with sympy from the schemes' definitions in docs/design.md "
            "(tests/report/derive_amplification.py, which writes "
            "tests/report/amplification.h), not from the engine's code; for instance "
            "symplectic Euler has trace 2 - 2 zeta t - t^2 and determinant 1 - 2 zeta t (t = "
            "omega h), velocity Verlet on drag R(z) = 1 + z + z^2/2, RK4 the degree-4 Taylor "
            "polynomial, symplectic4 on drag 1 + z + z^2/2 - 0.0353 z^3 - 0.4687 z^4 (second "
            "order: its stages take drag at predicted velocities). The line is where the "
            "spectral radius is 1 (stable inside, towards the origin).\n\n"
            "Measured on the engine, through the public API: a spring of omega = 1 on a 1 kg "
            "body (create_spring to an anchor of infinite mass, create_drag for the damping; "
            "drag alone: create_drag, h = 1 s). *Step*: the engine's one-step map is linear, "
            "so two single steps from (x, v) = (1, 0) and (0, 1) give its matrix, and the "
            "limit is where its spectral radius passes 1 (found as for the closed form). "
            "*Runs*: %d steps from (1, 0.3) at each omega h, unstable when the largest |(x, "
            "v)| of the second half is more than %g times that of the first, the limit by "
            "bisection between half and one and a half times the step's (a limit of 0: a "
            "scan up from 0.01); a run cannot see growth slower than about 5e-4 a step, so "
            "this column reads a little above the others where the growth starts slowly. "
            "`make check` fails when the step's limit misses the closed form's by more "
            "than %g%% (tests/report/check_report.sh runs `accuracy --check-regions`).\n\n"
            "![stability regions](report/regions.svg)\n\n",
            STEPS, UNSTABLE_GROWTH, TOLERANCE * 100.0);
    fprintf(md, "Largest stable omega h along each ray, and gamma h for drag alone (closed form "
                "/ the engine's step / the engine's runs):\n\n| integrator");
    for (int r = 0; r < RAYS; r++) {
        if (ZETAS[r] == 0.0) {
            fprintf(md, " | zeta = 0 (imaginary axis)");
        } else {
            fprintf(md, " | zeta = %g", ZETAS[r]);
        }
    }
    fprintf(md, " | drag alone (real axis) | growth per step at omega h = 0.5, zeta = 0 |\n|---");
    for (int r = 0; r <= RAYS + 1; r++) fprintf(md, "|---");
    fprintf(md, "|\n");
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        const limits_t *l = &limits[i];
        fprintf(md, "| %s", integrator_get_name((integrator_t)i));
        for (int r = 0; r <= RAYS; r++) write_cell(md, l->theory[r], l->measured[r], l->run[r]);
        if (isnan(l->theory_growth)) {
            fprintf(md, " | - / %.6f |\n", l->measured_growth);
        } else {
            fprintf(md, " | %.6f / %.6f |\n", l->theory_growth, l->measured_growth);
        }
    }
    fprintf(md, "\nA limit of 0 means unstable at every step on that ray (the seed and explicit "
                "Euler schemes on an undamped spring: the last column gives their growth, the "
                "spectral radius, against the measured one). On a damped ray a scheme is "
                "stable from 0 up to the limit given; the plot shows any stable island beyond "
                "it. CSV: [report/regions.csv](report/regions.csv).\n");
}
