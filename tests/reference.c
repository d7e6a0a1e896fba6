#include "reference.h"
#include <math.h>
#include "jostle/jostle.h"

static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};
static const double KEPLER_ECCENTRICITY = 0.6;
static const double KEPLER_HEAVY = 1.0, KEPLER_LIGHT = 0.001;
static const double DRAG_GAMMA = 0.5, GRAVITY_Y = -9.81;
static const vector_t DRAG_V0 = {10.0, 10.0};
static const double ORBIT_HEAVY = 1000.0, ORBIT_LIGHT = 1.0, ORBIT_R0 = 10.0, ORBIT_V0 = 10.0;
/* Energy this many times the start's (or its size, for a start at zero)
 * counts as diverged. */
static const double DIVERGED = 1e6;

const char *reference_name(reference_scene_t scene) {
    static const char *const names[REFERENCE_COUNT] = {"oscillator", "kepler", "drag", "bounce",
                                                       "orbit"};
    return names[scene];
}

const char *reference_error_name(reference_scene_t scene) {
    switch (scene) {
    case REFERENCE_OSCILLATOR: return "phase-space error / amplitude";
    case REFERENCE_KEPLER:
    case REFERENCE_ORBIT: return "phase-space error of the relative motion";
    case REFERENCE_DRAG: return "position error / distance flown";
    case REFERENCE_BOUNCE: return "largest relative apex error (5 apexes)";
    default: return "?";
    }
}

static body_t *add_square(scene_t *scene, vector_t center, double half, double mass) {
    body_t *body = body_init(polygon_make_box(center, half, half), mass, GREY);
    scene_add_body(scene, body);
    return body;
}

void reference_kepler_propagate(double mu, vector_t r0, vector_t v0, double t, vector_t *r,
                                vector_t *v) {
    double radius0 = vec_get_length(r0);
    double energy = vec_dot(v0, v0) / 2.0 - mu / radius0;
    double a = -mu / (2.0 * energy);
    double n = sqrt(mu / (a * a * a));
    /* e cos E0 and e sin E0, E0 the eccentric anomaly at the start. */
    double c = 1.0 - radius0 / a, s = vec_dot(r0, v0) / sqrt(mu * a);
    double turns = floor(n * t / (2.0 * M_PI));
    double mean = n * t - 2.0 * M_PI * turns;
    /* Kepler's equation in the change of eccentric anomaly, by Newton. */
    double de = mean;
    for (int i = 0; i < 100; i++) {
        double f = de - c * sin(de) + s * (1.0 - cos(de)) - mean;
        double step = f / (1.0 - c * cos(de) + s * sin(de));
        de -= step;
        if (fabs(step) < 1e-16) break;
    }
    double f = 1.0 - a / radius0 * (1.0 - cos(de));
    double g = (mean - (de - sin(de))) / n;
    *r = vec_add(vec_multiply(f, r0), vec_multiply(g, v0));
    double radius = vec_get_length(*r);
    double f_dot = -sqrt(mu * a) / (radius * radius0) * sin(de);
    double g_dot = 1.0 - a / radius * (1.0 - cos(de));
    *v = vec_add(vec_multiply(f_dot, r0), vec_multiply(g_dot, v0));
}

static double kinetic(body_t *body) {
    vector_t v = body_get_velocity(body);
    return 0.5 * body_get_mass(body) * vec_dot(v, v);
}

static double angular_momentum(body_t *body) {
    return body_get_mass(body) * vec_cross(body_get_centroid(body), body_get_velocity(body));
}

static bool is_sane(double energy, double start) {
    return isfinite(energy) && fabs(energy) <= DIVERGED * fmax(fabs(start), 1.0);
}

static double drift(double value, double start) {
    return fabs(value / start - 1.0);
}

static reference_result_t failed(long steps) {
    return (reference_result_t){NAN, NAN, NAN, steps, true};
}

static reference_result_t run_oscillator(integrator_t integrator, double h, double periods) {
    const double omega = 2.0 * M_PI, x0 = 1.0, v0 = 0.5 * omega;
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    body_t *anchor = add_square(scene, VEC_ZERO, 0.05, INFINITY);
    body_t *body = add_square(scene, (vector_t){x0, 0.0}, 0.05, 1.0);
    body_set_velocity(body, (vector_t){v0, 0.0});
    create_spring(scene, omega * omega, anchor, body);
    double e0 = 0.5 * v0 * v0 + 0.5 * omega * omega * x0 * x0;
    long steps = lround(periods / h);
    reference_result_t result = {0.0, 0.0, NAN, steps, false};
    for (long i = 0; i < steps; i++) {
        scene_tick(scene, h);
        double x = body_get_centroid(body).x, v = body_get_velocity(body).x;
        double energy = 0.5 * v * v + 0.5 * omega * omega * x * x;
        if (!is_sane(energy, e0)) {
            scene_free(scene);
            return failed(i + 1);
        }
        result.energy_drift = fmax(result.energy_drift, drift(energy, e0));
    }
    double t = steps * h;
    double exact = x0 * cos(omega * t) + v0 / omega * sin(omega * t);
    double exact_v = v0 * cos(omega * t) - x0 * omega * sin(omega * t);
    double dx = body_get_centroid(body).x - exact, dv = body_get_velocity(body).x - exact_v;
    result.error = hypot(dx, dv / omega) / hypot(x0, v0 / omega);
    scene_free(scene);
    return result;
}

/* Two bodies under Newtonian gravity, the centre of mass at rest at the
 * origin; the error is in their relative position against Kepler's. */
static reference_result_t run_two_bodies(integrator_t integrator, double h, double duration,
                                         double m1, double m2, double G, vector_t r0,
                                         vector_t v0) {
    double total = m1 + m2, mu = G * total;
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    body_t *heavy = add_square(scene, vec_multiply(-m2 / total, r0), 0.01, m1);
    body_t *light = add_square(scene, vec_multiply(m1 / total, r0), 0.01, m2);
    body_set_velocity(heavy, vec_multiply(-m2 / total, v0));
    body_set_velocity(light, vec_multiply(m1 / total, v0));
    create_newtonian_gravity(scene, G, heavy, light);
    double reduced = m1 * m2 / total;
    double e0 = reduced * (vec_dot(v0, v0) / 2.0 - mu / vec_get_length(r0));
    double l0 = angular_momentum(heavy) + angular_momentum(light);
    long steps = lround(duration / h);
    reference_result_t result = {0.0, 0.0, 0.0, steps, false};
    for (long i = 0; i < steps; i++) {
        scene_tick(scene, h);
        vector_t r = vec_subtract(body_get_centroid(light), body_get_centroid(heavy));
        double energy = kinetic(heavy) + kinetic(light) - G * m1 * m2 / vec_get_length(r);
        if (!is_sane(energy, e0)) {
            scene_free(scene);
            return failed(i + 1);
        }
        result.energy_drift = fmax(result.energy_drift, drift(energy, e0));
        double l = angular_momentum(heavy) + angular_momentum(light);
        result.momentum_drift = fmax(result.momentum_drift, drift(l, l0));
    }
    vector_t exact, exact_v;
    reference_kepler_propagate(mu, r0, v0, steps * h, &exact, &exact_v);
    vector_t r = vec_subtract(body_get_centroid(light), body_get_centroid(heavy));
    vector_t v = vec_subtract(body_get_velocity(light), body_get_velocity(heavy));
    double a = -mu / (2.0 * (vec_dot(v0, v0) / 2.0 - mu / vec_get_length(r0)));
    /* Velocities in units of the mean orbital speed sqrt(mu / a). */
    double dr = vec_get_length(vec_subtract(r, exact)) / a;
    double dv = vec_get_length(vec_subtract(v, exact_v)) / sqrt(mu / a);
    result.error = hypot(dr, dv);
    scene_free(scene);
    return result;
}

static reference_result_t run_kepler(integrator_t integrator, double h, double periods) {
    double e = KEPLER_ECCENTRICITY;
    vector_t r0 = {1.0 - e, 0.0}, v0 = {0.0, sqrt((1.0 + e) / (1.0 - e))};
    double G = 1.0 / (KEPLER_HEAVY + KEPLER_LIGHT);
    return run_two_bodies(integrator, h, periods * reference_period(REFERENCE_KEPLER),
                          KEPLER_HEAVY, KEPLER_LIGHT, G, r0, v0);
}

static reference_result_t run_orbit(integrator_t integrator, double h, double periods) {
    return run_two_bodies(integrator, h, periods * reference_period(REFERENCE_ORBIT), ORBIT_HEAVY,
                          ORBIT_LIGHT, 1.0, (vector_t){ORBIT_R0, 0.0},
                          (vector_t){0.0, ORBIT_V0});
}

static reference_result_t run_drag(integrator_t integrator, double h, double periods) {
    const double b = DRAG_GAMMA; /* m = 1 */
    const vector_t v_inf = {0.0, GRAVITY_Y / b};
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    scene_set_gravity(scene, (vector_t){0.0, GRAVITY_Y});
    body_t *body = add_square(scene, VEC_ZERO, 0.05, 1.0);
    body_set_velocity(body, DRAG_V0);
    create_drag(scene, DRAG_GAMMA, body);
    long steps = lround(periods / h);
    for (long i = 0; i < steps; i++) scene_tick(scene, h);
    double t = steps * h, decay = exp(-b * t);
    vector_t exact = vec_add(vec_multiply(t, v_inf),
                             vec_multiply((1.0 - decay) / b, vec_subtract(DRAG_V0, v_inf)));
    reference_result_t result = {0.0, NAN, NAN, steps, false};
    result.error =
        vec_get_length(vec_subtract(body_get_centroid(body), exact)) / vec_get_length(exact);
    if (!isfinite(result.error)) result = failed(steps);
    scene_free(scene);
    return result;
}

/* Apex heights of the box's bottom face from the ballistic parabola through
 * the last step that still rises, as the bench's bounce scene measures. */
static reference_result_t run_bounce(integrator_t integrator, double h) {
    const double e = 0.8, g = 10.0;
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    scene_set_contacts_enabled(scene, true);
    scene_set_gravity(scene, (vector_t){0.0, -g});
    body_t *floor = body_init(polygon_make_box((vector_t){0.0, -0.5}, 20.0, 0.5), INFINITY, GREY);
    scene_add_body(scene, floor);
    body_t *box = add_square(scene, (vector_t){0.0, 10.5}, 0.5, 1.0);
    body_set_elasticity(box, e);
    body_set_elasticity(floor, e);
    body_set_friction(box, 0.0);
    body_set_friction(floor, 0.0);
    double previous_vy = 0.0, previous_y = 0.0, worst = 0.0;
    int found = 0;
    long steps = 0, limit = lround(60.0 / h);
    for (; steps < limit && found < 5; steps++) {
        scene_tick(scene, h);
        double vy = body_get_velocity(box).y, y = body_get_centroid(box).y - 0.5;
        if (previous_vy > 0.0 && vy <= 0.0) {
            double apex = previous_y + previous_vy * previous_vy / (2.0 * g);
            double exact = 10.0 * pow(e, 2.0 * ++found);
            worst = fmax(worst, fabs(apex / exact - 1.0));
        }
        previous_vy = vy;
        previous_y = y;
    }
    scene_free(scene);
    if (found < 5) return failed(steps);
    return (reference_result_t){worst, NAN, NAN, steps, false};
}

double reference_period(reference_scene_t scene) {
    switch (scene) {
    case REFERENCE_KEPLER: return 2.0 * M_PI;
    case REFERENCE_ORBIT: {
        double mu = ORBIT_HEAVY + ORBIT_LIGHT;
        double energy = ORBIT_V0 * ORBIT_V0 / 2.0 - mu / ORBIT_R0;
        double a = -mu / (2.0 * energy);
        return 2.0 * M_PI * sqrt(a * a * a / mu);
    }
    default: return 1.0;
    }
}

reference_result_t reference_run(reference_scene_t scene, integrator_t integrator, double h,
                                 double periods) {
    switch (scene) {
    case REFERENCE_OSCILLATOR: return run_oscillator(integrator, h, periods);
    case REFERENCE_KEPLER: return run_kepler(integrator, h, periods);
    case REFERENCE_DRAG: return run_drag(integrator, h, periods);
    case REFERENCE_BOUNCE: return run_bounce(integrator, h);
    case REFERENCE_ORBIT: return run_orbit(integrator, h, periods);
    default: return failed(0);
    }
}
