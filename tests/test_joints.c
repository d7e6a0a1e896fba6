/* Joints (jostle/joint.h): exact pendulum periods, chains that keep their
 * length, energy of a double pendulum, motors, limits, welds, constraint
 * forces, removal with bodies, and the errors of bad definitions. */
#include <math.h>
#include <stdio.h>
#include "jostle/jostle.h"
#include "test.h"

static const rgb_color_t GREY = {0.5, 0.5, 0.5};
static const double G = 9.81;

static scene_t *joint_scene(integrator_t integrator) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -G});
    scene_set_contacts_enabled(scene, true);
    scene_set_integrator(scene, integrator);
    return scene;
}

static body_t *add_ball(scene_t *scene, vector_t at, double radius, double mass) {
    body_t *ball = body_init_circle(at, radius, mass, GREY);
    scene_add_body(scene, ball);
    return ball;
}

/* The complete elliptic integral of the first kind K(k) by the
 * arithmetic-geometric mean: K = pi / (2 AGM(1, sqrt(1 - k^2))). */
static double elliptic_k(double k) {
    double a = 1.0, b = sqrt(1.0 - k * k);
    for (int i = 0; i < 40 && fabs(a - b) > 1e-16 * a; i++) {
        double next = 0.5 * (a + b);
        b = sqrt(a * b);
        a = next;
    }
    return M_PI / (2.0 * a);
}

/* Kinetic plus potential energy (J) of the bodies (zero height at y 0). */
static double energy(body_t *const *bodies, int count) {
    double e = 0.0;
    for (int i = 0; i < count; i++) {
        e += body_get_kinetic_energy(bodies[i]) +
             body_get_mass(bodies[i]) * G * body_get_centroid(bodies[i]).y;
    }
    return e;
}

/*
 * A disc of radius r on a massless arm of length L from a fixed pivot,
 * released at rest from amplitude a: a compound pendulum of equivalent
 * length l = (L^2 + r^2 / 2) / L, whose exact period is
 * T = 4 sqrt(l / g) K(sin(a / 2)). Returns the measured mean period over
 * `periods` periods (from the first downward crossing of the vertical to
 * the last, interpolated) and the largest energy error over the run,
 * relative to m g L.
 */
static void swing(double amplitude, int periods, double dt, double *period, double *spread,
                  double *drift) {
    const double length = 1.0, radius = 0.05, mass = 1.0;
    scene_t *scene = joint_scene(INTEGRATOR_SYMPLECTIC_EULER);
    body_t *bob = add_ball(scene, (vector_t){length * sin(amplitude), -length * cos(amplitude)},
                           radius, mass);
    joint_def_t def = joint_def_revolute(NULL, bob, VEC_ZERO);
    joint_create(scene, &def);
    double e0 = energy(&bob, 1), worst = 0.0, t = 0.0, first = -1.0, last = -1.0;
    double sum_first = 0.0, sum_last = 0.0;
    int crossings = 0, count_first = 0, count_last = 0;
    double before = amplitude;
    while (crossings <= periods) {
        scene_tick(scene, dt);
        t += dt;
        vector_t p = body_get_centroid(bob);
        double angle = atan2(p.x, -p.y);
        if (before > 0.0 && angle <= 0.0) {
            double when = t - dt * angle / (angle - before);
            if (crossings == 0) first = when;
            last = when;
            crossings++;
        }
        before = angle;
        double e = (energy(&bob, 1) - e0) / (mass * G * length);
        worst = fmax(worst, fabs(e));
        if (crossings == 1) sum_first += e, count_first++;
        if (crossings == periods) sum_last += e, count_last++;
        if (t > 4.0 * periods * 10.0) break; /* never swung: fail below */
    }
    *period = crossings > periods ? (last - first) / periods : 0.0;
    *spread = worst;
    *drift = count_first > 0 && count_last > 0
                 ? fabs(sum_last / count_last - sum_first / count_first)
                 : INFINITY;
    scene_free(scene);
}

static double exact_period(double amplitude) {
    const double length = 1.0, radius = 0.05;
    double equivalent = (length * length + radius * radius / 2.0) / length;
    return 4.0 * sqrt(equivalent / G) * elliptic_k(sin(amplitude / 2.0));
}

static void check_pendulum(double degrees, double spread_bound, double drift_bound) {
    double amplitude = degrees * M_PI / 180.0, period, spread, drift;
    swing(amplitude, 100, 1.0 / 240.0, &period, &spread, &drift);
    printf("    %g degrees: period %.6f s, exact %.6f s; energy within %.2e m g L of the "
           "start, drift over 100 periods %.2e m g L\n",
           degrees, period, exact_period(amplitude), spread, drift);
    CHECK_RELATIVE(period, exact_period(amplitude), 1e-3);
    CHECK(spread <= spread_bound);
    CHECK(drift <= drift_bound);
}

/* Symplectic Euler at 1/240 s: the energy oscillates within O(dt) of the
 * start over each swing (its modified energy is the one conserved) and
 * does not drift: the means over the first and the hundredth period agree
 * to a millionth of m g L. */
static void pendulum_period_5_degrees(void) {
    check_pendulum(5.0, 1e-4, 1e-6);
}

static void pendulum_period_45_degrees(void) {
    check_pendulum(45.0, 4e-3, 1e-6);
}

static void pendulum_period_170_degrees(void) {
    check_pendulum(170.0, 2e-2, 1e-6);
}

TEST_SUITE(joints, TEST_CASE(pendulum_period_5_degrees), TEST_CASE(pendulum_period_45_degrees),
           TEST_CASE(pendulum_period_170_degrees));
