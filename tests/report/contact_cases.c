/*
 * Contact cases with exact answers (docs/accuracy.md, section 4), built on
 * the public API with world contacts, sleeping off (the cases are about
 * the motion, not about resting), on a floor of infinite mass whose top is
 * y = 0:
 *   - friction_spring: a box on a spring sliding under Coulomb friction;
 *   - incline_below, incline_above: a box on a slope 1 degree below and
 *     above the stick-slip angle atan(mu) (gravity tilted instead of the
 *     floor: the same motion in the slope's frame);
 *   - rocking: a slender block released tilted on one corner (Housner);
 *   - cradle3, cradle5: a box striking a row of touching equal boxes at
 *     e = 1.
 */
#include <math.h>
#include <stdlib.h>
#include "report.h"

static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};
static const double G = 9.81;

/* friction_spring: 1 kg box, k = (2 pi)^2 N/m (period 1 s), mu = 0.02. */
static const double SPRING_OMEGA = 2.0 * M_PI, SPRING_MU = 0.02, SPRING_X0 = 1.0;
static const double SPRING_TIME = 2.25;
/* incline: mu = 0.5 on both bodies (mixed: 0.5), 1 degree off atan(mu). */
static const double INCLINE_MU = 0.5, INCLINE_OFFSET = M_PI / 180.0, INCLINE_TIME = 2.0;
/* rocking: a 0.2 m by 1 m block of 1 kg, released at half its critical
 * angle atan(b / h), run to 0.8 of the time of its first impact. */
static const double ROCK_B = 0.1, ROCK_H = 0.5, ROCK_TILT = 0.5, ROCK_FRACTION = 0.8;
/* cradle: 1 m boxes, the striker 0.5 m from the row at 1 m/s. */
static const double CRADLE_V0 = 1.0, CRADLE_TIME = 2.0;
/* Steps a run may take: contacts cost a thousand times a free body's step. */
static const long CONTACT_BUDGET = 1L << 14;

typedef enum {
    FRICTION_SPRING,
    INCLINE_BELOW,
    INCLINE_ABOVE,
    ROCKING,
    CRADLE3,
    CRADLE5,
    CONTACT_CASES
} contact_case_t;

typedef struct {
    contact_case_t which;
    scene_t *scene;
    body_t *body;           /* the box measured (the cradle's last) */
    body_t *row[6];         /* the cradle's boxes */
    int boxes;
} contact_run_t;

static body_t *add_box(scene_t *scene, vector_t center, double hx, double hy, double mass) {
    body_t *body = body_init(polygon_make_box(center, hx, hy), mass, GREY);
    scene_add_body(scene, body);
    return body;
}

static body_t *add_floor(scene_t *scene, double friction) {
    body_t *floor = add_box(scene, (vector_t){0.0, -0.5}, 100.0, 0.5, INFINITY);
    body_set_friction(floor, friction);
    body_set_elasticity(floor, 0.0);
    return floor;
}

static double incline_angle(contact_case_t which) {
    return atan(INCLINE_MU) + (which == INCLINE_ABOVE ? INCLINE_OFFSET : -INCLINE_OFFSET);
}

/* The rocking block's critical angle, p^2 = 3 g / (4 R), R the half
 * diagonal (I about a corner = 4/3 m R^2). */
static double rock_alpha(void) {
    return atan(ROCK_B / ROCK_H);
}

static double rock_p(void) {
    return sqrt(3.0 * G / (4.0 * hypot(ROCK_B, ROCK_H)));
}

static void rock_step(double *theta, double *rate, double h) {
    double alpha = rock_alpha(), p2 = rock_p() * rock_p(), x = *theta, v = *rate;
    double a1 = v, b1 = -p2 * sin(alpha - x);
    double a2 = v + 0.5 * h * b1, b2 = -p2 * sin(alpha - (x + 0.5 * h * a1));
    double a3 = v + 0.5 * h * b2, b3 = -p2 * sin(alpha - (x + 0.5 * h * a2));
    double a4 = v + h * b3, b4 = -p2 * sin(alpha - (x + h * a3));
    *theta = x + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    *rate = v + h / 6.0 * (b1 + 2.0 * b2 + 2.0 * b3 + b4);
}

/* The exact rocking before the first impact: theta'' = -p^2 sin(alpha -
 * theta) about the corner, theta the tilt, by classical RK4 at 1e-5 s
 * (error below 1e-12). Returns theta at t; *impact is the first time theta
 * reaches 0 (linear between the steps around it). */
static double rock_exact(double t, double *impact) {
    const double h = 1e-5;
    double theta = ROCK_TILT * rock_alpha(), rate = 0.0, time = 0.0, at_t = NAN;
    *impact = NAN;
    while (isnan(*impact) || isnan(at_t)) {
        if (isnan(at_t) && time + h > t) {
            double x = theta, v = rate;
            rock_step(&x, &v, t - time);
            at_t = x;
        }
        double previous = theta;
        rock_step(&theta, &rate, h);
        if (isnan(*impact) && theta <= 0.0) *impact = time + h * previous / (previous - theta);
        time += h;
        if (time > 100.0) break;
    }
    return at_t;
}

static double rock_impact_time(void) {
    static double impact = NAN;
    if (isnan(impact)) rock_exact(0.0, &impact);
    return impact;
}

static double duration(contact_case_t which) {
    switch (which) {
    case FRICTION_SPRING: return SPRING_TIME;
    case INCLINE_BELOW:
    case INCLINE_ABOVE: return INCLINE_TIME;
    case ROCKING: return ROCK_FRACTION * rock_impact_time();
    default: return CRADLE_TIME;
    }
}

static void build_friction_spring(contact_run_t *run) {
    add_floor(run->scene, SPRING_MU);
    scene_set_gravity(run->scene, (vector_t){0.0, -G});
    body_t *anchor = add_box(run->scene, (vector_t){0.0, 0.5}, 0.01, 0.01, INFINITY);
    body_set_collision_filter(anchor, 2, 0, 0);
    run->body = add_box(run->scene, (vector_t){SPRING_X0, 0.5}, 0.5, 0.5, 1.0);
    body_set_friction(run->body, SPRING_MU);
    body_set_elasticity(run->body, 0.0);
    create_spring(run->scene, SPRING_OMEGA * SPRING_OMEGA, anchor, run->body);
}

static void build_incline(contact_run_t *run) {
    double angle = incline_angle(run->which);
    add_floor(run->scene, INCLINE_MU);
    scene_set_gravity(run->scene, (vector_t){G * sin(angle), -G * cos(angle)});
    run->body = add_box(run->scene, (vector_t){0.0, 0.5}, 0.5, 0.5, 1.0);
    body_set_friction(run->body, INCLINE_MU);
    body_set_elasticity(run->body, 0.0);
}

/* The block leans right on its right bottom corner, at the origin. */
static void build_rocking(contact_run_t *run) {
    double tilt = ROCK_TILT * rock_alpha();
    add_floor(run->scene, 1.0);
    scene_set_gravity(run->scene, (vector_t){0.0, -G});
    vector_t center = {-ROCK_B * cos(tilt) + ROCK_H * sin(tilt),
                       ROCK_B * sin(tilt) + ROCK_H * cos(tilt)};
    run->body = add_box(run->scene, center, ROCK_B, ROCK_H, 1.0);
    body_set_rotation(run->body, -tilt);
    body_set_friction(run->body, 1.0);
    body_set_elasticity(run->body, 0.0);
}

static void build_cradle(contact_run_t *run, int boxes) {
    run->boxes = boxes;
    for (int i = 0; i < boxes; i++) {
        double x = i == 0 ? -1.0 : (double)i;
        body_t *box = add_box(run->scene, (vector_t){x, 0.0}, 0.5, 0.5, 1.0);
        body_set_elasticity(box, 1.0);
        body_set_friction(box, 0.0);
        run->row[i] = box;
    }
    body_set_velocity(run->row[0], (vector_t){CRADLE_V0, 0.0});
    run->body = run->row[boxes - 1];
}

static contact_run_t *build_run(contact_case_t which, integrator_t integrator) {
    contact_run_t *run = calloc(1, sizeof *run);
    if (run == NULL) abort();
    run->which = which;
    run->scene = scene_init();
    scene_set_integrator(run->scene, integrator);
    scene_set_contacts_enabled(run->scene, true);
    scene_set_sleeping(run->scene, false);
    switch (which) {
    case FRICTION_SPRING: build_friction_spring(run); break;
    case INCLINE_BELOW:
    case INCLINE_ABOVE: build_incline(run); break;
    case ROCKING: build_rocking(run); break;
    case CRADLE3: build_cradle(run, 3); break;
    default: build_cradle(run, 5); break;
    }
    return run;
}

/* Coulomb friction and a spring: between turning points the box moves
 * about x_c = -s mu g / omega^2 (s the sign of its velocity) with the
 * spring's period, each half period shrinking the swing by 2 mu g /
 * omega^2; it stops at a turning point where k |x| <= mu m g. */
static double friction_spring_exact(double t) {
    double omega = SPRING_OMEGA, shift = SPRING_MU * G / (omega * omega), x = SPRING_X0;
    double half = M_PI / omega;
    for (;;) {
        if (fabs(x) <= shift) return x;
        double centre = x > 0.0 ? shift : -shift;
        if (t <= half) return centre + (x - centre) * cos(omega * t);
        x = 2.0 * centre - x;
        t -= half;
    }
}

/* The error at t, the time the run reached (steps h). */
static double error_of(const contact_run_t *run, double t) {
    switch (run->which) {
    case FRICTION_SPRING:
        return fabs(body_get_centroid(run->body).x - friction_spring_exact(t)) / SPRING_X0;
    case INCLINE_BELOW: return fabs(body_get_centroid(run->body).x);
    case INCLINE_ABOVE: {
        double angle = incline_angle(run->which);
        double exact = 0.5 * G * (sin(angle) - INCLINE_MU * cos(angle)) * t * t;
        return fabs(body_get_centroid(run->body).x / exact - 1.0);
    }
    case ROCKING: {
        double impact, theta = rock_exact(t, &impact);
        return fabs(-body_get_rotation(run->body) - theta) / (ROCK_TILT * rock_alpha());
    }
    default: {
        double error = fabs(body_get_velocity(run->row[run->boxes - 1]).x - CRADLE_V0);
        for (int i = 0; i < run->boxes - 1; i++) {
            error += vec_get_length(body_get_velocity(run->row[i]));
        }
        return error / CRADLE_V0;
    }
    }
}

static void *build(const report_case_t *c, integrator_t integrator, double h) {
    (void)h;
    return build_run((contact_case_t)c->which, integrator);
}

static scene_t *scene_of(void *run) {
    return ((contact_run_t *)run)->scene;
}

static vector_t end_centroid(void *run) {
    return body_get_centroid(((contact_run_t *)run)->body);
}

static void finish(void *run) {
    scene_free(((contact_run_t *)run)->scene);
    free(run);
}

static reference_result_t diagnose(const report_case_t *c, integrator_t integrator, double h) {
    contact_run_t *run = build_run((contact_case_t)c->which, integrator);
    long steps = lround(duration(run->which) / h);
    reference_result_t result = {NAN, NAN, NAN, steps, 0, VEC_ZERO, false};
    for (long i = 0; i < steps; i++) {
        scene_tick(run->scene, h);
        result.evaluations += (long)scene_get_stats(run->scene).force_evaluations;
    }
    result.error = error_of(run, (double)steps * h);
    result.end_centroid = end_centroid(run);
    if (!isfinite(result.error)) result.diverged = true;
    finish(run);
    return result;
}

/* The first impact: the angular velocity a few steps after it over that
 * just before, beside Housner's 1 - 3/2 sin^2 alpha (angular momentum
 * about the new corner kept, no bounce, no slip). */
static void rocking_note(const report_case_t *c, FILE *md) {
    const double h = 1.0 / 960.0;
    double alpha = rock_alpha(), housner = 1.0 - 1.5 * sin(alpha) * sin(alpha);
    fprintf(md, "\nThe first impact at h = 1/960 s: the angular velocity 5 steps after it over "
                "that at the last step before (Housner, for an impact that keeps the angular "
                "momentum about the new corner, with no bounce and no slip: 1 - 3/2 sin^2 alpha "
                "= %.4f):",
            housner);
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        contact_run_t *run = build_run((contact_case_t)c->which, (integrator_t)i);
        double before = NAN, ratio = NAN;
        int after = -1;
        for (long n = 0; n < lround(3.0 * rock_impact_time() / h); n++) {
            double omega = body_get_angular_velocity(run->body);
            scene_tick(run->scene, h);
            if (after < 0 && -body_get_rotation(run->body) <= 0.0) {
                before = omega;
                after = 0;
            } else if (after >= 0 && ++after == 5) {
                ratio = body_get_angular_velocity(run->body) / before;
                break;
            }
        }
        finish(run);
        fprintf(md, "%s %s %.4f", i ? "," : "", integrator_get_name((integrator_t)i), ratio);
    }
    fprintf(md, ".\n");
}

static report_case_t contact_case(contact_case_t which, const char *name, const char *title,
                                  const char *error_name, double first_h) {
    report_case_t c = {name, title, error_name, "", first_h, (int)which, 0.0, CONTACT_BUDGET,
                       diagnose, build, scene_of, end_centroid, finish,
                       which == ROCKING ? rocking_note : NULL};
    snprintf(c.span, sizeof c.span, "after %.4g s", duration(which));
    return c;
}

int report_contact_cases(report_case_t *cases, int capacity, bool quick) {
    (void)quick;
    static char rocking[1024], above[512];
    double slope = incline_angle(INCLINE_ABOVE);
    snprintf(above, sizeof above,
             "the same box 1 degree above the stick-slip angle. Exact: it slides with a = g "
             "(sin a - mu cos a) = %.4f m/s^2 from rest. Error: distance slid over the exact "
             "a t^2 / 2, relative",
             G * (sin(slope) - INCLINE_MU * cos(slope)));
    double alpha = rock_alpha(), p = rock_p(), tilt = ROCK_TILT * alpha;
    snprintf(rocking, sizeof rocking,
             "a 0.2 m by 1 m block of 1 kg (half-width b = %g m, half-height %g m, half-diagonal "
             "R = %.4f m, critical angle alpha = atan(b / h) = %.4f rad) released at rest, "
             "tilted by %.4f rad onto its right bottom corner, friction 1, elasticity 0. Until "
             "its first impact it turns about that corner: theta'' = -p^2 sin(alpha - theta), "
             "p^2 = 3 g / (4 R) (p = %.4f /s), integrated to 1e-12 as the exact answer; "
             "Housner's small-angle solution theta = alpha - (alpha - theta0) cosh(p t) puts "
             "the impact at %.4f s, the exact one at %.4f s. Error: the tilt at 0.8 of the "
             "time to impact over the initial tilt",
             ROCK_B, ROCK_H, hypot(ROCK_B, ROCK_H), alpha, tilt, p,
             acosh(alpha / (alpha - tilt)) / p, rock_impact_time());
    report_case_t list[CONTACT_CASES] = {
        contact_case(FRICTION_SPRING, "friction_spring",
                     "a 1 m box of 1 kg on the floor, on a spring k = (2 pi)^2 N/m to an anchor "
                     "at its height, released at rest 1 m out, friction mu = 0.02 on both "
                     "bodies, g = 9.81. Exact: between turning points the box swings about x = "
                     "-s mu g / omega^2 (s the sign of its velocity), each half period shrinking "
                     "the swing by 2 mu g / omega^2, until it stops where k |x| <= mu m g. "
                     "Error: position over the initial stretch, mid-swing",
                     "position error / initial stretch", 1.0 / 32.0),
        contact_case(INCLINE_BELOW, "incline_below",
                     "a 1 m box of 1 kg at rest on a slope 1 degree below the stick-slip angle "
                     "atan(mu) = 26.57 degrees (mu = 0.5; gravity 9.81 tilted, the floor flat). "
                     "Exact: it stays put. Error: how far it slid (m)",
                     "distance slid (m)", 1.0 / 30.0),
        contact_case(INCLINE_ABOVE, "incline_above", above, "relative error of the distance slid",
                     1.0 / 30.0),
        contact_case(ROCKING, "rocking", rocking, "tilt error / initial tilt", 1.0 / 60.0),
        contact_case(CRADLE3, "cradle3",
                     "a 1 m box of 1 kg at 1 m/s strikes a row of two touching equal boxes at "
                     "rest (elasticity 1 on all, friction 0, no gravity). Exact (momentum and "
                     "energy through touching bodies): the last leaves at 1 m/s, the others at "
                     "rest. Error: |v_last - v0| plus the others' speeds, over v0",
                     "velocity error / v0", 1.0 / 30.0),
        contact_case(CRADLE5, "cradle5", "the same with a row of four touching boxes",
                     "velocity error / v0", 1.0 / 30.0),
    };
    int count = 0;
    for (int i = 0; i < CONTACT_CASES && count < capacity; i++) cases[count++] = list[i];
    return count;
}
