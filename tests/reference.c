#include "reference.h"
#include <math.h>
#include <stdlib.h>
#include "jostle/jostle.h"

static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};
static const double KEPLER_ECCENTRICITY = 0.6, KEPLER_ECCENTRIC = 0.9;
static const double KEPLER_HEAVY = 1.0, KEPLER_LIGHT = 0.001;
static const double DRAG_GAMMA = 0.5, GRAVITY_Y = -9.81;
static const vector_t DRAG_V0 = {10.0, 10.0};
static const double ORBIT_HEAVY = 1000.0, ORBIT_LIGHT = 1.0, ORBIT_R0 = 10.0, ORBIT_V0 = 10.0;
static const double OSCILLATOR_OMEGA = 2.0 * M_PI, OSCILLATOR_X0 = 1.0, BOUNCE_G = 10.0;
/* Energy this many times the start's (or its size, for a start at zero)
 * counts as diverged. */
static const double DIVERGED = 1e6;

const char *reference_name(reference_scene_t scene) {
    static const char *const names[REFERENCE_COUNT] = {"oscillator", "kepler", "drag", "bounce",
                                                       "orbit", "kepler09"};
    return names[scene];
}

const char *reference_error_name(reference_scene_t scene) {
    switch (scene) {
    case REFERENCE_OSCILLATOR: return "phase-space error / amplitude";
    case REFERENCE_KEPLER:
    case REFERENCE_KEPLER_ECCENTRIC:
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

/* ---- One run ---- */

struct reference_sim {
    reference_scene_t which;
    scene_t *scene;
    /* The oscillator's and the drag's body is b; the orbits' heavy body a,
     * light body b. */
    body_t *a, *b;
    double e0, l0;
    /* The orbits: G, mu = G (m1 + m2), the relative start, semi-major axis. */
    double G, mu, semi_major;
    vector_t r0, v0;
};

static void start_oscillator(reference_sim_t *sim) {
    const double omega = OSCILLATOR_OMEGA, x0 = OSCILLATOR_X0, v0 = 0.5 * omega;
    sim->a = add_square(sim->scene, VEC_ZERO, 0.05, INFINITY);
    sim->b = add_square(sim->scene, (vector_t){x0, 0.0}, 0.05, 1.0);
    body_set_velocity(sim->b, (vector_t){v0, 0.0});
    create_spring(sim->scene, omega * omega, sim->a, sim->b);
    sim->e0 = 0.5 * v0 * v0 + 0.5 * omega * omega * x0 * x0;
}

/* Two bodies under Newtonian gravity, the centre of mass at rest at the
 * origin; the error is in their relative position against Kepler's. */
static void start_two_bodies(reference_sim_t *sim, double m1, double m2, double G, vector_t r0,
                             vector_t v0) {
    double total = m1 + m2;
    sim->G = G;
    sim->mu = G * total;
    sim->r0 = r0;
    sim->v0 = v0;
    sim->a = add_square(sim->scene, vec_multiply(-m2 / total, r0), 0.01, m1);
    sim->b = add_square(sim->scene, vec_multiply(m1 / total, r0), 0.01, m2);
    body_set_velocity(sim->a, vec_multiply(-m2 / total, v0));
    body_set_velocity(sim->b, vec_multiply(m1 / total, v0));
    create_newtonian_gravity(sim->scene, G, sim->a, sim->b);
    double specific = vec_dot(v0, v0) / 2.0 - sim->mu / vec_get_length(r0);
    sim->e0 = m1 * m2 / total * specific;
    sim->l0 = angular_momentum(sim->a) + angular_momentum(sim->b);
    sim->semi_major = -sim->mu / (2.0 * specific);
}

static void start_kepler(reference_sim_t *sim, double e) {
    vector_t r0 = {1.0 - e, 0.0}, v0 = {0.0, sqrt((1.0 + e) / (1.0 - e))};
    start_two_bodies(sim, KEPLER_HEAVY, KEPLER_LIGHT, 1.0 / (KEPLER_HEAVY + KEPLER_LIGHT), r0,
                     v0);
}

static void start_drag(reference_sim_t *sim) {
    scene_set_gravity(sim->scene, (vector_t){0.0, GRAVITY_Y});
    sim->b = add_square(sim->scene, VEC_ZERO, 0.05, 1.0);
    body_set_velocity(sim->b, DRAG_V0);
    create_drag(sim->scene, DRAG_GAMMA, sim->b);
}

static void start_bounce(reference_sim_t *sim) {
    const double e = 0.8;
    scene_set_contacts_enabled(sim->scene, true);
    scene_set_gravity(sim->scene, (vector_t){0.0, -BOUNCE_G});
    sim->a = body_init(polygon_make_box((vector_t){0.0, -0.5}, 20.0, 0.5), INFINITY, GREY);
    scene_add_body(sim->scene, sim->a);
    sim->b = add_square(sim->scene, (vector_t){0.0, 10.5}, 0.5, 1.0);
    body_set_elasticity(sim->b, e);
    body_set_elasticity(sim->a, e);
    body_set_friction(sim->b, 0.0);
    body_set_friction(sim->a, 0.0);
}

reference_sim_t *reference_start(reference_scene_t scene, integrator_t integrator, double h) {
    (void)h;
    reference_sim_t *sim = calloc(1, sizeof *sim);
    if (sim == NULL) abort();
    sim->which = scene;
    sim->scene = scene_init();
    sim->l0 = NAN;
    scene_set_integrator(sim->scene, integrator);
    switch (scene) {
    case REFERENCE_OSCILLATOR: start_oscillator(sim); break;
    case REFERENCE_KEPLER: start_kepler(sim, KEPLER_ECCENTRICITY); break;
    case REFERENCE_KEPLER_ECCENTRIC: start_kepler(sim, KEPLER_ECCENTRIC); break;
    case REFERENCE_ORBIT:
        start_two_bodies(sim, ORBIT_HEAVY, ORBIT_LIGHT, 1.0, (vector_t){ORBIT_R0, 0.0},
                         (vector_t){0.0, ORBIT_V0});
        break;
    case REFERENCE_DRAG: start_drag(sim); break;
    case REFERENCE_BOUNCE: start_bounce(sim); break;
    default: abort();
    }
    return sim;
}

scene_t *reference_get_scene(reference_sim_t *sim) {
    return sim->scene;
}

vector_t reference_tracked_centroid(reference_sim_t *sim) {
    return body_get_centroid(sim->b);
}

void reference_finish(reference_sim_t *sim) {
    scene_free(sim->scene);
    free(sim);
}

static bool is_orbit(reference_scene_t scene) {
    return scene == REFERENCE_KEPLER || scene == REFERENCE_KEPLER_ECCENTRIC ||
           scene == REFERENCE_ORBIT;
}

/* The energy now (NAN for the drag). */
static double energy_now(reference_sim_t *sim) {
    if (sim->which == REFERENCE_OSCILLATOR) {
        double x = body_get_centroid(sim->b).x, v = body_get_velocity(sim->b).x;
        return 0.5 * v * v + 0.5 * OSCILLATOR_OMEGA * OSCILLATOR_OMEGA * x * x;
    }
    if (is_orbit(sim->which)) {
        vector_t r = vec_subtract(body_get_centroid(sim->b), body_get_centroid(sim->a));
        return kinetic(sim->a) + kinetic(sim->b) -
               sim->G * body_get_mass(sim->a) * body_get_mass(sim->b) / vec_get_length(r);
    }
    return NAN;
}

void reference_invariants(reference_sim_t *sim, double *energy_error, double *momentum_error) {
    *energy_error = sim->which == REFERENCE_OSCILLATOR || is_orbit(sim->which)
                        ? energy_now(sim) / sim->e0 - 1.0
                        : NAN;
    *momentum_error = NAN;
    if (is_orbit(sim->which)) {
        double l = angular_momentum(sim->a) + angular_momentum(sim->b);
        *momentum_error = l / sim->l0 - 1.0;
    }
}

reference_state_t reference_measure(reference_sim_t *sim, double t) {
    reference_state_t state = {NAN, NAN, NAN, NAN};
    if (sim->which == REFERENCE_BOUNCE) return state;
    reference_invariants(sim, &state.energy_error, &state.momentum_error);
    if (sim->which == REFERENCE_OSCILLATOR) {
        const double omega = OSCILLATOR_OMEGA, x0 = OSCILLATOR_X0, v0 = 0.5 * omega;
        double exact = x0 * cos(omega * t) + v0 / omega * sin(omega * t);
        double exact_v = v0 * cos(omega * t) - x0 * omega * sin(omega * t);
        double dx = body_get_centroid(sim->b).x - exact, dv = body_get_velocity(sim->b).x - exact_v;
        double amplitude = hypot(x0, v0 / omega);
        state.error = hypot(dx, dv / omega) / amplitude;
        state.position_error = fabs(dx) / amplitude;
    } else if (is_orbit(sim->which)) {
        vector_t exact, exact_v;
        reference_kepler_propagate(sim->mu, sim->r0, sim->v0, t, &exact, &exact_v);
        vector_t r = vec_subtract(body_get_centroid(sim->b), body_get_centroid(sim->a));
        vector_t v = vec_subtract(body_get_velocity(sim->b), body_get_velocity(sim->a));
        double a = sim->semi_major;
        /* Velocities in units of the mean orbital speed sqrt(mu / a). */
        double dr = vec_get_length(vec_subtract(r, exact)) / a;
        double dv = vec_get_length(vec_subtract(v, exact_v)) / sqrt(sim->mu / a);
        state.error = hypot(dr, dv);
        state.position_error = dr;
    } else {
        const double b = DRAG_GAMMA; /* m = 1 */
        const vector_t v_inf = {0.0, GRAVITY_Y / b};
        double decay = exp(-b * t);
        vector_t exact = vec_add(vec_multiply(t, v_inf),
                                 vec_multiply((1.0 - decay) / b, vec_subtract(DRAG_V0, v_inf)));
        state.error = vec_get_length(vec_subtract(body_get_centroid(sim->b), exact)) /
                      vec_get_length(exact);
        state.position_error = state.error;
    }
    return state;
}

double reference_period(reference_scene_t scene) {
    switch (scene) {
    case REFERENCE_KEPLER:
    case REFERENCE_KEPLER_ECCENTRIC: return 2.0 * M_PI;
    case REFERENCE_ORBIT: {
        double mu = ORBIT_HEAVY + ORBIT_LIGHT;
        double energy = ORBIT_V0 * ORBIT_V0 / 2.0 - mu / ORBIT_R0;
        double a = -mu / (2.0 * energy);
        return 2.0 * M_PI * sqrt(a * a * a / mu);
    }
    default: return 1.0;
    }
}

long reference_steps(reference_scene_t scene, double h, double periods) {
    return lround(periods * reference_period(scene) / h);
}

/* ---- The diagnosed run: every step checked ---- */

static reference_result_t failed(long steps) {
    return (reference_result_t){NAN, NAN, NAN, steps, 0, {NAN, NAN}, true};
}

static reference_result_t run_measured(reference_scene_t scene, integrator_t integrator,
                                       double h, double periods) {
    reference_sim_t *sim = reference_start(scene, integrator, h);
    long steps = reference_steps(scene, h, periods);
    bool conserves = scene != REFERENCE_DRAG;
    reference_result_t result = {0.0, conserves ? 0.0 : NAN, is_orbit(scene) ? 0.0 : NAN, steps,
                                 0, VEC_ZERO, false};
    for (long i = 0; i < steps; i++) {
        scene_tick(sim->scene, h);
        result.evaluations += (long)scene_get_stats(sim->scene).force_evaluations;
        if (!conserves) continue;
        double energy_error, momentum_error;
        reference_invariants(sim, &energy_error, &momentum_error);
        if (!is_sane(energy_now(sim), sim->e0)) {
            reference_finish(sim);
            return failed(i + 1);
        }
        result.energy_drift = fmax(result.energy_drift, fabs(energy_error));
        if (is_orbit(scene)) result.momentum_drift = fmax(result.momentum_drift, fabs(momentum_error));
    }
    result.error = reference_measure(sim, steps * h).error;
    result.end_centroid = reference_tracked_centroid(sim);
    if (!isfinite(result.error)) result = failed(steps);
    reference_finish(sim);
    return result;
}

/* Apex heights of the box's bottom face from the ballistic parabola through
 * the last step that still rises, as the bench's bounce scene measures. */
static reference_result_t run_bounce(integrator_t integrator, double h) {
    const double e = 0.8, g = BOUNCE_G;
    reference_sim_t *sim = reference_start(REFERENCE_BOUNCE, integrator, h);
    double previous_vy = 0.0, previous_y = 0.0, worst = 0.0;
    int found = 0;
    long steps = 0, limit = lround(60.0 / h), evaluations = 0;
    for (; steps < limit && found < 5; steps++) {
        scene_tick(sim->scene, h);
        evaluations += (long)scene_get_stats(sim->scene).force_evaluations;
        double vy = body_get_velocity(sim->b).y, y = body_get_centroid(sim->b).y - 0.5;
        if (previous_vy > 0.0 && vy <= 0.0) {
            double apex = previous_y + previous_vy * previous_vy / (2.0 * g);
            double exact = 10.0 * pow(e, 2.0 * ++found);
            worst = fmax(worst, fabs(apex / exact - 1.0));
        }
        previous_vy = vy;
        previous_y = y;
    }
    vector_t end = reference_tracked_centroid(sim);
    reference_finish(sim);
    if (found < 5) return failed(steps);
    return (reference_result_t){worst, NAN, NAN, steps, evaluations, end, false};
}

reference_result_t reference_run(reference_scene_t scene, integrator_t integrator, double h,
                                 double periods) {
    if (scene == REFERENCE_BOUNCE) return run_bounce(integrator, h);
    return run_measured(scene, integrator, h, periods);
}
