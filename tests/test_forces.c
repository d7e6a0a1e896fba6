/* forces.h: springs, Newtonian gravity, drag, and the seed's collision force
 * creators (handler calls, destructive and physics collisions, the record). */
#include <stdlib.h>
#include "jostle/jostle.h"
#include "test.h"

static const rgb_color_t BLUE = {0, 0, 1};


/* A square of side 2 h centred at c. */
static body_t *square(vector_t c, double h, double mass) {
    return body_init(polygon_make_box(c, h, h), mass, BLUE);
}

static body_t *added(scene_t *scene, body_t *body) {
    scene_add_body(scene, body);
    return body;
}

static double momentum_x(body_t *a, body_t *b) {
    return body_get_mass(a) * body_get_velocity(a).x + body_get_mass(b) * body_get_velocity(b).x;
}

/* Springs. */

static void spring_is_hooke_with_rest_length_zero(void) {
    /* One tick: each body gets k (x_other - x_self) dt / m, for any
     * separation (rest length 0). */
    scene_t *scene = scene_init();
    body_t *a = added(scene, square(VEC_ZERO, 0.1, 2.0));
    body_t *b = added(scene, square((vector_t){3, 4}, 0.1, 5.0));
    create_spring(scene, 10.0, a, b);
    const double dt = 0.01;
    scene_tick(scene, dt);
    CHECK_VEC(body_get_velocity(a), 10.0 * 3 / 2.0 * dt, 10.0 * 4 / 2.0 * dt, 1e-15);
    CHECK_VEC(body_get_velocity(b), -10.0 * 3 / 5.0 * dt, -10.0 * 4 / 5.0 * dt, 1e-15);
    CHECK_NEAR(momentum_x(a, b), 0.0, 1e-15);
    /* Coincident centroids: no force. k = 0: no force. */
    scene_t *still = scene_init();
    body_t *c = added(still, square((vector_t){1, 1}, 0.1, 1.0));
    body_t *d = added(still, square((vector_t){1, 1}, 0.2, 1.0));
    body_t *e = added(still, square((vector_t){5, 1}, 0.2, 1.0));
    create_spring(still, 3.0, c, d);
    create_spring(still, 0.0, d, e);
    scene_tick(still, dt);
    CHECK_VEC(body_get_velocity(c), 0, 0, 0);
    CHECK_VEC(body_get_velocity(d), 0, 0, 0);
    CHECK_VEC(body_get_velocity(e), 0, 0, 0);
    scene_free(scene);
    scene_free(still);
}

static void spring_oscillator_matches_the_cosine(void) {
    /* An infinite-mass anchor at the origin and m = 2 at x = A, k = 8:
     * x(t) = A cos(2 t). dt = 1e-4 over two periods; the seed scheme's
     * error there is about 6e-4 A, the tolerance 2e-3 A. */
    const double k = 8.0, m = 2.0, A = 0.5, dt = 1e-4;
    const double omega = sqrt(k / m);
    scene_t *scene = scene_init();
    body_t *anchor = added(scene, square(VEC_ZERO, 0.1, INFINITY));
    body_t *bob = added(scene, square((vector_t){A, 0}, 0.1, m));
    create_spring(scene, k, anchor, bob);
    const vector_t anchor_start = body_get_centroid(anchor);
    const double bob_y = body_get_centroid(bob).y;
    const long steps = lround(2 * (2 * M_PI / omega) / dt);
    double worst = 0.0, worst_velocity = 0.0;
    for (long i = 1; i <= steps; i++) {
        scene_tick(scene, dt);
        double t = dt * (double)i;
        worst = fmax(worst, fabs(body_get_centroid(bob).x - A * cos(omega * t)));
        worst_velocity =
            fmax(worst_velocity, fabs(body_get_velocity(bob).x + A * omega * sin(omega * t)));
    }
    CHECK_NEAR(worst, 0.0, 2e-3 * A);
    CHECK_NEAR(worst_velocity, 0.0, 2e-3 * A * omega);
    CHECK_NEAR(body_get_centroid(bob).y, bob_y, 1e-15); /* along the line of centres */
    CHECK_VEC(body_get_centroid(anchor), anchor_start.x, anchor_start.y, 0); /* immovable */
    CHECK_VEC(body_get_velocity(anchor), 0, 0, 0);
    scene_free(scene);
}

/* Springs with a rest length. */

static void spring_with_length_is_hooke_about_its_length(void) {
    /* One tick from (0, 0) and (3, 4), d = 5 along u = (0.6, 0.8): body a
     * gets k (d - L) u dt / m_a, body b the opposite over m_b. Stretched
     * (L = 2) it pulls, compressed (L = 7) it pushes, at its length (L = 5)
     * nothing; L = 0 is create_spring's force. */
    const double k = 10.0, dt = 0.01;
    const double lengths[] = {2.0, 7.0, 5.0, 0.0};
    for (size_t i = 0; i < sizeof lengths / sizeof lengths[0]; i++) {
        scene_t *scene = scene_init();
        body_t *a = added(scene, square(VEC_ZERO, 0.1, 2.0));
        body_t *b = added(scene, square((vector_t){3, 4}, 0.1, 5.0));
        create_spring_with_length(scene, k, lengths[i], a, b);
        scene_tick(scene, dt);
        double pull = k * (5.0 - lengths[i]);
        CHECK_VEC(body_get_velocity(a), pull * 0.6 / 2.0 * dt, pull * 0.8 / 2.0 * dt, 1e-15);
        CHECK_VEC(body_get_velocity(b), -pull * 0.6 / 5.0 * dt, -pull * 0.8 / 5.0 * dt, 1e-15);
        CHECK_NEAR(momentum_x(a, b), 0.0, 1e-15);
        scene_free(scene);
    }
    /* Coincident centroids: no direction, no force (and no NaN). */
    scene_t *still = scene_init();
    body_t *c = added(still, square((vector_t){1, 1}, 0.1, 1.0));
    body_t *d = added(still, square((vector_t){1, 1}, 0.2, 1.0));
    create_spring_with_length(still, 3.0, 0.5, c, d);
    scene_tick(still, dt);
    CHECK_VEC(body_get_velocity(c), 0, 0, 0);
    CHECK_VEC(body_get_velocity(d), 0, 0, 0);
    scene_free(still);
}

static void spring_with_length_oscillates_about_its_length(void) {
    /* An INFINITY anchor at the origin and m = 2 at L + A along (0.6, 0.8),
     * k = 8, L = 1.5, A = 0.25: d(t) = L + A cos(2 t), on the line, with
     * period pi. Velocity Verlet at dt = 1e-3 over two periods: its phase
     * error there is about (omega dt)^2 omega t / 24 = 2e-6 rad, so
     * 1e-5 A bounds the error. */
    const double k = 8.0, m = 2.0, L = 1.5, A = 0.25, dt = 1e-3;
    const double omega = sqrt(k / m);
    const vector_t u = {0.6, 0.8};
    scene_t *scene = scene_init();
    scene_set_integrator(scene, INTEGRATOR_VELOCITY_VERLET);
    body_t *anchor = added(scene, square(VEC_ZERO, 0.1, INFINITY));
    body_t *bob = added(scene, square(vec_multiply(L + A, u), 0.1, m));
    create_spring_with_length(scene, k, L, anchor, bob);
    const vector_t anchor_start = body_get_centroid(anchor);
    const long steps = lround(2 * (2 * M_PI / omega) / dt);
    double worst = 0.0, off_line = 0.0;
    for (long i = 1; i <= steps; i++) {
        scene_tick(scene, dt);
        vector_t x = body_get_centroid(bob);
        worst = fmax(worst, fabs(vec_dot(x, u) - L - A * cos(omega * dt * (double)i)));
        off_line = fmax(off_line, fabs(vec_cross(u, x)));
    }
    CHECK_NEAR(worst, 0.0, 1e-5 * A);
    CHECK_NEAR(off_line, 0.0, 1e-14);
    CHECK_VEC(body_get_centroid(anchor), anchor_start.x, anchor_start.y, 0); /* immovable */
    scene_free(scene);
}

static void spring_with_length_stretches_by_m_g_over_k(void) {
    /* A 3 kg bob under g = 9.81 hangs on k = 50, L = 2 from an INFINITY
     * anchor. Placed at rest at L + m g / k below it, it stays (the forces
     * cancel to rounding). Released at rest at L, it swings between L and
     * L + 2 m g / k; symplectic Euler at omega dt = 4e-4 reaches the
     * lowest point to about (omega dt)^2 = 2e-7 relative: within 1e-6. */
    const double k = 50.0, m = 3.0, L = 2.0, g = 9.81, dt = 1e-4;
    const double stretch = m * g / k;
    for (int released = 0; released <= 1; released++) {
        scene_t *scene = scene_init();
        scene_set_integrator(scene, INTEGRATOR_SYMPLECTIC_EULER);
        scene_set_gravity(scene, (vector_t){0, -g});
        body_t *anchor = added(scene, square(VEC_ZERO, 0.1, INFINITY));
        double start = released ? -L : -(L + stretch);
        body_t *bob = added(scene, square((vector_t){0, start}, 0.1, m));
        create_spring_with_length(scene, k, L, anchor, bob);
        const double x = body_get_centroid(bob).x;
        double lowest = 0.0, highest = -INFINITY;
        const long steps = lround(2 * M_PI / sqrt(k / m) / dt); /* one period */
        for (long i = 0; i < steps; i++) {
            scene_tick(scene, dt);
            lowest = fmin(lowest, body_get_centroid(bob).y);
            highest = fmax(highest, body_get_centroid(bob).y);
        }
        if (released) {
            CHECK_RELATIVE(-lowest, L + 2.0 * stretch, 1e-6);
            CHECK_NEAR(highest, -L, 1e-6 * L);
        } else {
            CHECK_NEAR(lowest, -(L + stretch), 1e-12);
            CHECK_NEAR(highest, -(L + stretch), 1e-12);
        }
        CHECK_NEAR(body_get_centroid(bob).x, x, 1e-15); /* below the anchor, to rounding */
        scene_free(scene);
    }
}

static void spring_with_length_conserves_energy_with_symplectic_euler(void) {
    /* Two free bodies (1 and 3 kg) on k = 20, L = 1, started stretched to
     * 1.3 m and spinning about each other: they stretch, swing and turn for
     * 50 s (about 40 spring periods). Symplectic Euler keeps the energy
     * k (d - L)^2 / 2 + kinetic within omega dt / 2 (2.6e-3) of its start,
     * never drifting; momentum and angular momentum (a central force) it
     * keeps to rounding. Explicit Euler gains energy at every step: more
     * than 10% over the same run. */
    const double k = 20.0, L = 1.0, dt = 1e-3;
    for (int explicit_euler = 0; explicit_euler <= 1; explicit_euler++) {
        scene_t *scene = scene_init();
        scene_set_integrator(scene, explicit_euler ? INTEGRATOR_EXPLICIT_EULER
                                                   : INTEGRATOR_SYMPLECTIC_EULER);
        body_t *a = added(scene, square((vector_t){-0.975, 0}, 0.05, 1.0));
        body_t *b = added(scene, square((vector_t){0.325, 0}, 0.05, 3.0));
        body_set_velocity(a, (vector_t){0, -1.5});
        body_set_velocity(b, (vector_t){0, 0.5});
        create_spring_with_length(scene, k, L, a, b);
        double start_energy = 0.0, start_angular = 0.0, worst = 0.0;
        for (long i = 0; i <= 50000; i++) {
            if (i > 0) scene_tick(scene, dt);
            vector_t xa = body_get_centroid(a), xb = body_get_centroid(b);
            double stretch = vec_get_length(vec_subtract(xb, xa)) - L;
            double energy = body_get_kinetic_energy(a) + body_get_kinetic_energy(b) +
                            0.5 * k * stretch * stretch;
            double angular = vec_cross(xa, vec_multiply(1.0, body_get_velocity(a))) +
                             vec_cross(xb, vec_multiply(3.0, body_get_velocity(b)));
            if (i == 0) {
                start_energy = energy;
                start_angular = angular;
            }
            worst = fmax(worst, fabs(energy - start_energy) / start_energy);
            if (!explicit_euler) CHECK_NEAR(angular, start_angular, 1e-12);
        }
        if (explicit_euler) {
            CHECK(worst > 0.1);
        } else {
            CHECK(worst < 0.5 * sqrt(k / 0.75) * dt); /* omega of the reduced mass */
            CHECK_NEAR(momentum_x(a, b), 0.0, 1e-12);
            CHECK_NEAR(body_get_velocity(a).y + 3.0 * body_get_velocity(b).y, 0.0, 1e-12);
        }
        scene_free(scene);
    }
}

/* Newtonian gravity. */

static void gravity_follows_the_inverse_square_law(void) {
    /* One tick: each is pulled toward the other with G m1 m2 / r^2. */
    const double G = 2.0, dt = 0.001;
    scene_t *scene = scene_init();
    body_t *a = added(scene, square((vector_t){1, 1}, 0.1, 3.0));
    body_t *b = added(scene, square((vector_t){4, 5}, 0.1, 7.0)); /* r = 5 */
    create_newtonian_gravity(scene, G, a, b);
    scene_tick(scene, dt);
    double force = G * 3.0 * 7.0 / 25.0;
    CHECK_VEC(body_get_velocity(a), force / 3.0 * 0.6 * dt, force / 3.0 * 0.8 * dt, 1e-15);
    CHECK_VEC(body_get_velocity(b), -force / 7.0 * 0.6 * dt, -force / 7.0 * 0.8 * dt, 1e-15);
    /* Twice as far: a quarter of the force. */
    scene_t *far = scene_init();
    body_t *c = added(far, square((vector_t){1, 1}, 0.1, 3.0));
    body_t *d = added(far, square((vector_t){7, 9}, 0.1, 7.0)); /* r = 10 */
    create_newtonian_gravity(far, G, c, d);
    scene_tick(far, dt);
    CHECK_NEAR(body_get_velocity(c).y, body_get_velocity(a).y / 4, 1e-15);
    scene_free(scene);
    scene_free(far);
}

static void gravity_is_left_out_when_it_cannot_be_applied(void) {
    /* Centroids closer than 1e-9 m: no force (and no NaN). An INFINITY mass:
     * the pull would be infinite, so no force either (documented). */
    scene_t *scene = scene_init();
    body_t *a = added(scene, square((vector_t){1, 1}, 0.5, 1.0));
    body_t *b = added(scene, square((vector_t){1, 1 + 1e-10}, 0.5, 1.0));
    body_t *sun = added(scene, square((vector_t){10, 0}, 0.5, INFINITY));
    body_t *planet = added(scene, square((vector_t){12, 0}, 0.1, 1.0));
    create_newtonian_gravity(scene, 1.0, a, b);
    create_newtonian_gravity(scene, 1.0, sun, planet);
    scene_tick(scene, 0.1);
    CHECK_VEC(body_get_velocity(a), 0, 0, 0);
    CHECK_VEC(body_get_velocity(b), 0, 0, 0);
    CHECK_VEC(body_get_velocity(planet), 0, 0, 0);
    CHECK_VEC(body_get_velocity(sun), 0, 0, 0);
    scene_free(scene);
}

static double two_body_energy(body_t *a, body_t *b, double G) {
    double r = vec_get_length(vec_subtract(body_get_centroid(b), body_get_centroid(a)));
    return body_get_kinetic_energy(a) + body_get_kinetic_energy(b) -
           G * body_get_mass(a) * body_get_mass(b) / r;
}

static void two_body_gravity_conserves_energy_and_momentum(void) {
    /* m1 = 3 at the origin, m2 = 1 at distance 1, G = 1, relative speed 0.8
     * of circular: an ellipse of period about 1.98, started at apoapsis.
     * Total momentum zero. One period at dt = 1e-6 with the seed scheme:
     * energy drifts about 4e-5 relative; tolerance 1e-4. */
    const double G = 1.0, dt = 1e-6;
    scene_t *scene = scene_init();
    body_t *a = added(scene, body_init(polygon_make_regular(8, 0.05, VEC_ZERO, 0), 3.0, BLUE));
    body_t *b = added(scene, body_init(polygon_make_regular(8, 0.05, (vector_t){1, 0}, 0), 1.0,
                                       BLUE));
    double v = 0.8 * sqrt(G * 4.0 / 1.0);
    body_set_velocity(a, (vector_t){0, -v / 4});
    body_set_velocity(b, (vector_t){0, 3 * v / 4});
    create_newtonian_gravity(scene, G, a, b);
    double semi_major = 1.0 / (2.0 - 0.64);
    double period = 2 * M_PI * sqrt(semi_major * semi_major * semi_major / (G * 4.0));
    const double e0 = two_body_energy(a, b, G);
    double worst_energy = 0.0, worst_momentum = 0.0, closest = 1.0;
    const long steps = lround(period / dt);
    for (long i = 1; i <= steps; i++) {
        scene_tick(scene, dt);
        if (i % 100 == 0) {
            worst_energy = fmax(worst_energy, fabs(two_body_energy(a, b, G) - e0));
            vector_t p = vec_add(vec_multiply(3.0, body_get_velocity(a)), body_get_velocity(b));
            worst_momentum = fmax(worst_momentum, vec_get_length(p));
            closest = fmin(closest, vec_get_length(vec_subtract(body_get_centroid(b),
                                                                body_get_centroid(a))));
        }
    }
    CHECK_RELATIVE(e0 + worst_energy, e0, 1e-4);
    CHECK_NEAR(worst_momentum, 0.0, 1e-12);
    /* It really was an ellipse: apoapsis a (1 + e) = 1, periapsis
     * a (1 - e) = 2 a - 1. */
    CHECK_NEAR(closest, 2 * semi_major - 1, 1e-3);
    /* After one period it is back at apoapsis; the centre of mass has not
     * moved. */
    vector_t r = vec_subtract(body_get_centroid(b), body_get_centroid(a));
    CHECK_VEC(r, 1.0, 0.0, 2e-3);
    vector_t center = vec_multiply(0.25, vec_add(vec_multiply(3.0, body_get_centroid(a)),
                                                 body_get_centroid(b)));
    CHECK_VEC(center, 0.25, 0.0, 1e-9);
    scene_free(scene);
}

/* Drag. */

static void drag_is_minus_gamma_v(void) {
    const double gamma = 3.0, m = 2.0, dt = 0.01;
    scene_t *scene = scene_init();
    body_t *body = added(scene, square(VEC_ZERO, 0.5, m));
    body_set_velocity(body, (vector_t){4, -2});
    create_drag(scene, gamma, body);
    scene_tick(scene, dt);
    double factor = 1 - gamma / m * dt;
    CHECK_VEC(body_get_velocity(body), 4 * factor, -2 * factor, 1e-15);
    scene_free(scene);
}

static void drag_decays_exponentially(void) {
    /* v(t) = v0 exp(-gamma t / m), x(t) = x0 + v0 (m / gamma) (1 - exp(-gamma
     * t / m)). dt = 1e-4 to t = 2: relative error about 2.5e-5. */
    const double gamma = 1.0, m = 2.0, dt = 1e-4, t = 2.0;
    scene_t *scene = scene_init();
    body_t *body = added(scene, square((vector_t){1, 0}, 0.5, m));
    body_set_velocity(body, (vector_t){3, -1});
    create_drag(scene, gamma, body);
    const long steps = lround(t / dt);
    for (long i = 0; i < steps; i++) scene_tick(scene, dt);
    double decay = exp(-gamma * t / m);
    CHECK_RELATIVE(body_get_velocity(body).x, 3 * decay, 1e-4);
    CHECK_RELATIVE(body_get_velocity(body).y, -1 * decay, 1e-4);
    CHECK_RELATIVE(body_get_centroid(body).x, 1 + 3 * m / gamma * (1 - decay), 1e-4);
    CHECK_RELATIVE(body_get_centroid(body).y, -1 * m / gamma * (1 - decay), 1e-4);
    scene_free(scene);
}

/* Collision handlers. */

typedef struct {
    int calls;
    body_t *body1, *body2;
    vector_t axis;
    void *aux;
    double force_const;
} handler_log_t;

static handler_log_t handler_log;

static void logging_handler(body_t *body1, body_t *body2, vector_t axis, void *aux,
                            double force_const) {
    handler_log.calls++;
    handler_log.body1 = body1;
    handler_log.body2 = body2;
    handler_log.axis = axis;
    handler_log.aux = aux;
    handler_log.force_const = force_const;
}

static void handler_runs_once_per_contact_with_its_arguments(void) {
    scene_t *scene = scene_init();
    body_t *a = added(scene, square(VEC_ZERO, 1.0, 1.0));
    body_t *b = added(scene, square((vector_t){5, 0}, 1.0, 2.0));
    int *aux = malloc(sizeof *aux); /* the caller's: the scene never frees it */
    *aux = 99;
    /* Registered as (b, a): the handler gets them in that order and the
     * axis points from b toward a. */
    create_collision(scene, b, a, logging_handler, aux, 0.25);
    scene_tick(scene, 0.01);
    CHECK(handler_log.calls == 0); /* apart */
    body_set_centroid(b, (vector_t){1.5, 0.3});
    scene_tick(scene, 0.01);
    CHECK(handler_log.calls == 1);
    CHECK(handler_log.body1 == b && handler_log.body2 == a);
    CHECK_VEC(handler_log.axis, -1, 0, 1e-15);
    CHECK(handler_log.aux == aux && *(int *)handler_log.aux == 99);
    CHECK(handler_log.force_const == 0.25);
    for (int i = 0; i < 5; i++) scene_tick(scene, 0.01); /* still overlapping */
    CHECK(handler_log.calls == 1);
    body_set_centroid(b, (vector_t){2.5, 0}); /* separated for one tick */
    scene_tick(scene, 0.01);
    CHECK(handler_log.calls == 1);
    body_set_centroid(b, (vector_t){1.9, 0});
    scene_tick(scene, 0.01);
    CHECK(handler_log.calls == 2); /* a new contact */
    /* Overlapping from creation: called on the first tick. */
    body_t *c = added(scene, square((vector_t){0.5, 0}, 0.5, 1.0));
    create_collision(scene, a, c, logging_handler, NULL, 0.0);
    scene_tick(scene, 0.01);
    CHECK(handler_log.calls == 3);
    CHECK(handler_log.body1 == a && handler_log.body2 == c);
    scene_free(scene);
    CHECK(*aux == 99); /* not freed by the scene (AddressSanitizer) */
    free(aux);
}

static void destructive_collision_removes_both_at_the_contact_time(void) {
    /* a (x in [-0.5, 0.5]) moves at 1 m/s toward b (x in [1.05, 2.05]),
     * dt = 0.1: they first overlap after 6 integrations, the 7th tick's
     * force creators see it, and that tick reaps both. */
    scene_t *scene = scene_init();
    body_t *a = added(scene, square(VEC_ZERO, 0.5, 1.0));
    body_t *b = added(scene, square((vector_t){1.55, 0}, 0.5, 1.0));
    body_t *bystander = added(scene, square((vector_t){0, 5}, 0.5, 1.0));
    body_set_velocity(a, (vector_t){1, 0});
    create_destructive_collision(scene, a, b);
    create_spring(scene, 1.0, a, bystander); /* dropped with a */
    int tick = 0;
    while (scene_bodies(scene) == 3 && tick < 20) {
        bool overlapping = find_collision(a, b).collided;
        scene_tick(scene, 0.1);
        tick++;
        /* Gone at the end of exactly the first tick that starts overlapping. */
        CHECK((scene_bodies(scene) == 3) == !overlapping);
    }
    CHECK(tick == 7);
    CHECK(scene_bodies(scene) == 1);
    CHECK(scene_get_body(scene, 0) == bystander);
    /* The spring went with a: the bystander is no longer pulled. */
    vector_t v = body_get_velocity(bystander);
    scene_tick(scene, 0.1);
    CHECK_VEC(body_get_velocity(bystander), v.x, v.y, 0);
    scene_free(scene);
}

/* Physics collisions. */

static void physics_handler_applies_the_formula_along_any_axis(void) {
    /* Called directly: J on body1 = mu (1 + e) (u_b - u_a) axis, body2 gets
     * -J, applied at the next tick; tangential velocities untouched. */
    const double ma = 2.0, mb = 3.0, e = 0.5, dt = 0.01;
    body_t *a = square(VEC_ZERO, 0.5, ma);
    body_t *b = square((vector_t){0.8, 0.6}, 0.5, mb);
    vector_t axis = {0.6, 0.8};
    vector_t va = {2, 1}, vb = {-1, 0.5};
    body_set_velocity(a, va);
    body_set_velocity(b, vb);
    physics_collision_handler(a, b, axis, NULL, e);
    CHECK_VEC(body_get_velocity(a), va.x, va.y, 0); /* not yet applied */
    body_tick(a, dt);
    body_tick(b, dt);
    double ua = vec_dot(va, axis), ub = vec_dot(vb, axis);
    double mu = ma * mb / (ma + mb);
    double j = mu * (1 + e) * (ub - ua);
    CHECK_VEC(body_get_velocity(a), va.x + j / ma * axis.x, va.y + j / ma * axis.y, 1e-14);
    CHECK_VEC(body_get_velocity(b), vb.x - j / mb * axis.x, vb.y - j / mb * axis.y, 1e-14);
    /* Restitution along the axis, tangential parts unchanged, momentum kept. */
    double ua2 = vec_dot(body_get_velocity(a), axis), ub2 = vec_dot(body_get_velocity(b), axis);
    CHECK_NEAR(ub2 - ua2, -e * (ub - ua), 1e-14);
    vector_t tangent = vec_perpendicular(axis);
    CHECK_NEAR(vec_dot(body_get_velocity(a), tangent), vec_dot(va, tangent), 1e-14);
    CHECK_NEAR(vec_dot(body_get_velocity(b), tangent), vec_dot(vb, tangent), 1e-14);
    vector_t p = vec_add(vec_multiply(ma, body_get_velocity(a)),
                         vec_multiply(mb, body_get_velocity(b)));
    CHECK_VEC(p, ma * va.x + mb * vb.x, ma * va.y + mb * vb.y, 1e-13);
    body_free(a);
    body_free(b);
}

/* A ball dropped between two pegs meets both in one tick at elasticity 1.
 * Each impulse is computed from the velocity the other left, so the ball
 * bounces off one and then the other, never faster than it came. Before,
 * both came from its old velocity: the speed rose from 4 to 7.06 m/s. */
static void a_ball_meeting_two_pegs_in_one_tick_gains_no_energy(void) {
    scene_t *scene = scene_init();
    body_t *ball = added(scene, body_init(polygon_make_regular(16, 0.5, (vector_t){0, 0.9}, 0),
                                          1.0, BLUE));
    body_t *left = added(scene, square((vector_t){-0.6, 0.0}, 0.3, INFINITY));
    body_t *right = added(scene, square((vector_t){0.6, 0.0}, 0.3, INFINITY));
    body_set_velocity(ball, (vector_t){0.0, -4.0});
    create_physics_collision(scene, ball, left, 1.0);
    create_physics_collision(scene, ball, right, 1.0);
    for (int i = 0; i < 30; i++) {
        scene_tick(scene, 1.0 / 60.0);
        CHECK(vec_get_length(body_get_velocity(ball)) <= 4.0 + 1e-12);
    }
    CHECK(body_get_velocity(ball).y > 0.0); /* it bounced */
    scene_free(scene);
}

static void physics_handler_with_infinite_masses(void) {
    /* One INFINITY: the reduced mass is the other body's mass, so a wall
     * reflects the normal velocity (e = 1) and does not move. */
    body_t *wall = square(VEC_ZERO, 1.0, INFINITY);
    body_t *ball = square((vector_t){1.5, 0}, 0.5, 2.0);
    body_set_velocity(ball, (vector_t){-3, 1});
    physics_collision_handler(wall, ball, (vector_t){1, 0}, NULL, 1.0);
    body_tick(wall, 0.01);
    body_tick(ball, 0.01);
    CHECK_VEC(body_get_velocity(ball), 3, 1, 1e-15);
    CHECK_VEC(body_get_velocity(wall), 0, 0, 0);
    /* e = 0.5 against a wall given as body2. */
    body_set_velocity(ball, (vector_t){4, 0});
    physics_collision_handler(ball, wall, (vector_t){1, 0}, NULL, 0.5);
    body_tick(ball, 0.01);
    CHECK_VEC(body_get_velocity(ball), -2, 0, 1e-15);
    /* Two INFINITY masses: nothing happens (and nothing is NaN). */
    body_t *other = square((vector_t){2, 0}, 1.0, INFINITY);
    body_set_velocity(other, (vector_t){-1, 0});
    physics_collision_handler(wall, other, (vector_t){1, 0}, NULL, 1.0);
    body_tick(other, 0.01);
    CHECK_VEC(body_get_velocity(other), -1, 0, 0);
    body_free(wall);
    body_free(ball);
    body_free(other);
}

static void physics_handler_with_huge_finite_masses(void) {
    /* m_a m_b overflows a double for masses of 1e200, but the reduced mass
     * (5e199) does not: the equal-mass elastic swap still happens. */
    body_t *a = square(VEC_ZERO, 0.5, 1e200);
    body_t *b = square((vector_t){0.9, 0}, 0.5, 1e200);
    body_set_velocity(a, (vector_t){1, 0});
    physics_collision_handler(a, b, (vector_t){1, 0}, NULL, 1.0);
    body_tick(a, 0.01);
    body_tick(b, 0.01);
    CHECK_VEC(body_get_velocity(a), 0, 0, 1e-15);
    CHECK_VEC(body_get_velocity(b), 1, 0, 1e-15);
    body_free(a);
    body_free(b);
}

/* Two squares of half side 0.5 on the x axis, a at 0 moving at va, b at
 * 1.5 moving at vb, with a physics collision of elasticity e; ticks (dt
 * 0.1) until the collision has happened and 5 more. */
typedef struct {
    scene_t *scene;
    body_t *a, *b;
} pair_t;

static pair_t colliding_pair(double ma, double mb, double va, double vb, double e) {
    pair_t pair = {scene_init(), NULL, NULL};
    pair.a = added(pair.scene, square(VEC_ZERO, 0.5, ma));
    pair.b = added(pair.scene, square((vector_t){1.5, 0}, 0.5, mb));
    body_set_velocity(pair.a, (vector_t){va, 0});
    body_set_velocity(pair.b, (vector_t){vb, 0});
    create_physics_collision(pair.scene, pair.a, pair.b, e);
    return pair;
}

static void equal_masses_elastic_swap_velocities(void) {
    pair_t p = colliding_pair(1.0, 1.0, 2.0, 0.0, 1.0);
    double energy = body_get_kinetic_energy(p.a) + body_get_kinetic_energy(p.b);
    for (int i = 0; i < 3; i++) scene_tick(p.scene, 0.1);
    CHECK_VEC(body_get_velocity(p.a), 2, 0, 0); /* not yet: gap closing */
    for (int i = 0; i < 10; i++) scene_tick(p.scene, 0.1);
    CHECK_VEC(body_get_velocity(p.a), 0, 0, 1e-15);
    CHECK_VEC(body_get_velocity(p.b), 2, 0, 1e-15);
    CHECK_NEAR(body_get_kinetic_energy(p.a) + body_get_kinetic_energy(p.b), energy, 1e-14);
    scene_free(p.scene);
}

static void zero_elasticity_gives_the_common_velocity(void) {
    /* Masses 1 and 3 at 4 and 0 m/s: common velocity 1, and they stay
     * overlapping without a second impulse (velocities stay put). */
    pair_t p = colliding_pair(1.0, 3.0, 4.0, 0.0, 0.0);
    for (int i = 0; i < 4; i++) scene_tick(p.scene, 0.1);
    CHECK_VEC(body_get_velocity(p.a), 1, 0, 1e-15);
    CHECK_VEC(body_get_velocity(p.b), 1, 0, 1e-15);
    CHECK(find_collision(p.a, p.b).collided);
    for (int i = 0; i < 20; i++) {
        scene_tick(p.scene, 0.1);
        CHECK(scene_contact_count(p.scene) == 0); /* no handler ran */
    }
    CHECK(find_collision(p.a, p.b).collided); /* still overlapping */
    CHECK_VEC(body_get_velocity(p.a), 1, 0, 1e-15);
    CHECK_VEC(body_get_velocity(p.b), 1, 0, 1e-15);
    CHECK_NEAR(momentum_x(p.a, p.b), 4.0, 1e-14);
    scene_free(p.scene);
}

static void super_elastic_gains_energy_by_the_formula(void) {
    /* e = 2: the kinetic energy grows by mu (e^2 - 1) (u_a - u_b)^2 / 2. */
    const double ma = 2.0, mb = 1.0, ua = 3.0, ub = -1.0, e = 2.0;
    pair_t p = colliding_pair(ma, mb, ua, ub, e);
    double before = body_get_kinetic_energy(p.a) + body_get_kinetic_energy(p.b);
    for (int i = 0; i < 6; i++) scene_tick(p.scene, 0.1);
    double after = body_get_kinetic_energy(p.a) + body_get_kinetic_energy(p.b);
    double mu = ma * mb / (ma + mb);
    CHECK_NEAR(after - before, 0.5 * mu * (e * e - 1) * (ua - ub) * (ua - ub), 1e-12);
    CHECK(after > before);
    CHECK_NEAR(momentum_x(p.a, p.b), ma * ua + mb * ub, 1e-13);
    /* Separating at e times the approach speed. */
    CHECK_NEAR(body_get_velocity(p.b).x - body_get_velocity(p.a).x, e * (ua - ub), 1e-13);
    scene_free(p.scene);
}

static void ball_bounces_between_infinite_walls(void) {
    /* Walls at x = -3 (registered as body1) and x = 3 (as body2); the ball
     * keeps its speed, the walls never move. */
    scene_t *scene = scene_init();
    body_t *left = added(scene, body_init(polygon_make_box((vector_t){-3, 0}, 0.5, 5), INFINITY,
                                          BLUE));
    body_t *right = added(scene, body_init(polygon_make_box((vector_t){3, 0}, 0.5, 5), INFINITY,
                                           BLUE));
    body_t *ball = added(scene, square(VEC_ZERO, 0.25, 0.7));
    body_set_velocity(ball, (vector_t){2, 0.5});
    create_physics_collision(scene, left, ball, 1.0);
    create_physics_collision(scene, ball, right, 1.0);
    int bounces_right = 0, bounces_left = 0;
    double previous = 2;
    for (int i = 0; i < 800; i++) { /* 8 s: the ball crosses 4.5 m gaps */
        scene_tick(scene, 0.01);
        double vx = body_get_velocity(ball).x;
        if (previous > 0 && vx < 0) bounces_right++;
        if (previous < 0 && vx > 0) bounces_left++;
        previous = vx;
        CHECK_NEAR(fabs(vx), 2.0, 1e-12);
        CHECK_NEAR(body_get_centroid(ball).x, 0.0, 3.0); /* never through a wall */
    }
    CHECK(bounces_right >= 2 && bounces_left >= 1);
    CHECK_NEAR(body_get_velocity(ball).y, 0.5, 1e-15);
    CHECK_VEC(body_get_centroid(left), -3, 0, 0);
    CHECK_VEC(body_get_centroid(right), 3, 0, 0);
    CHECK_VEC(body_get_velocity(left), 0, 0, 0);
    scene_free(scene);
}

static void seed_collisions_are_in_the_record(void) {
    /* Masses 1 and 3, e = 0.5, a at 4 m/s: the handler's impulse on b is
     * mu (1 + e) (u_a - u_b) = 0.75 * 1.5 * 4 = 4.5 N s along +x. */
    pair_t p = colliding_pair(1.0, 3.0, 4.0, 0.0, 0.5);
    int recorded_ticks = 0;
    for (int i = 0; i < 6; i++) {
        scene_tick(p.scene, 0.1);
        size_t count = scene_contact_count(p.scene);
        CHECK(count <= 1);
        if (count == 0) continue;
        recorded_ticks++;
        const contact_t *c = scene_get_contact(p.scene, 0);
        CHECK(c->kind == CONTACT_SEED);
        CHECK(c->touching);
        CHECK(c->body1 == p.a && c->body2 == p.b);
        CHECK_VEC(c->axis, 1, 0, 1e-15);
        CHECK(c->point_count == 1 || c->point_count == 2);
        CHECK_NEAR(c->normal_impulse[0], 0.75 * 1.5 * 4.0, 1e-13);
        for (size_t k = 0; k < c->point_count && k < 2; k++) {
            CHECK(c->separation[k] <= 0.0);
            /* The point lies in the overlap region, between the bodies. */
            CHECK(c->points[k].x >= body_get_centroid(p.a).x - 1.0);
            CHECK(c->points[k].x <= body_get_centroid(p.b).x + 1.0);
        }
    }
    CHECK(recorded_ticks == 1);
    scene_free(p.scene);
}

static void destroyed_bodies_never_linger_in_the_record(void) {
    /* The record is read after the tick: an entry naming a body reaped in
     * that tick would dangle, so none does. */
    scene_t *scene = scene_init();
    body_t *a = added(scene, square(VEC_ZERO, 0.5, 1.0));
    body_t *b = added(scene, square((vector_t){0.5, 0}, 0.5, 1.0));
    create_destructive_collision(scene, a, b);
    scene_tick(scene, 0.1);
    CHECK(scene_bodies(scene) == 0);
    CHECK(scene_contact_count(scene) == 0);
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        const contact_t *c = scene_get_contact(scene, i);
        CHECK(c->body1 != a && c->body1 != b && c->body2 != a && c->body2 != b);
    }
    scene_free(scene);
}

static void force_creators_may_name_bodies_before_they_are_added(void) {
    /* A body in no scene yet may be named; it is then added to that same
     * scene, which frees it. Bodies already in the scene work as always. */
    scene_t *scene = scene_init();
    body_t *a = square(VEC_ZERO, 0.1, 2.0), *b = square((vector_t){3, 4}, 0.1, 5.0);
    body_t *c = added(scene, square((vector_t){-3, 0}, 0.1, 1.0));
    create_spring(scene, 10.0, a, b);
    create_newtonian_gravity(scene, 1.0, a, c);
    create_drag(scene, 0.5, b);
    create_physics_collision(scene, b, c, 1.0);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    create_spring(scene, 1.0, b, c); /* all three in the scene now */
    const double dt = 0.01;
    scene_tick(scene, dt);
    /* a: spring toward b (10 (3, 4)) and gravity toward c (1 * 2 * 1 / 9). */
    CHECK_VEC(body_get_velocity(a), (30.0 - 2.0 / 9.0) / 2.0 * dt, 40.0 / 2.0 * dt, 1e-14);
    scene_free(scene);

    /* Named but never added: the caller's again once that scene is freed. */
    scene_t *first = scene_init(), *second = scene_init();
    body_t *anchor = added(first, square((vector_t){1, 0}, 0.1, 1.0));
    body_t *loose = square(VEC_ZERO, 0.1, 1.0);
    create_spring(first, 1.0, anchor, loose);
    scene_free(first);
    scene_add_body(second, loose);
    scene_free(second);
    CHECK(test_no_leaks());
}

/* Collision handlers with world contacts on: the handler follows the world
 * contact of the pair, one tick after the step in which the pair first
 * touched (forces.h). */

static const double WORLD_DT = 1.0 / 60.0;
static const double MEETING_SPEEDS[] = {0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0};
static const double MEETING_ELASTICITIES[] = {0.0, 0.5, 1.0};
#define COUNT_OF(array) (sizeof(array) / sizeof((array)[0]))

typedef struct {
    int calls;
    body_t *body1, *body2;
    vector_t axis;
    /* dot(axis, centroid2 - centroid1) at the call: > 0 when the axis points
     * from body1 toward body2. */
    double along;
} meeting_log_t;

static void meeting_handler(body_t *body1, body_t *body2, vector_t axis, void *aux,
                            double force_const) {
    (void)force_const;
    meeting_log_t *log = aux;
    log->calls++;
    log->body1 = body1;
    log->body2 = body2;
    log->axis = axis;
    log->along = vec_dot(axis, vec_subtract(body_get_centroid(body2), body_get_centroid(body1)));
}

/* Whether the record of the last tick holds a touching world contact of the
 * pair (in either order). */
static bool world_contact_touching(scene_t *scene, body_t *a, body_t *b) {
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        const contact_t *c = scene_get_contact(scene, i);
        if (c->kind != CONTACT_WORLD || !c->touching) continue;
        if ((c->body1 == a && c->body2 == b) || (c->body1 == b && c->body2 == a)) return true;
    }
    return false;
}

/* The record entry of a handler call of the pair in the last tick, or NULL. */
static const contact_t *seed_entry(scene_t *scene, body_t *body1, body_t *body2) {
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        const contact_t *c = scene_get_contact(scene, i);
        if (c->kind == CONTACT_SEED && c->body1 == body1 && c->body2 == body2) return c;
    }
    return NULL;
}

/* A ball (regular octagon of radius 0.5, mass 1) on the x axis, moving at
 * speed toward a box of half side 0.5 at the origin (static, or of mass 1)
 * which it reaches after 0.5 s plus phase steps; gravity 0, world contacts
 * on, both bodies of elasticity e. The box is added first, so the world
 * orders the pair (box, ball). */
typedef struct {
    scene_t *scene;
    body_t *ball, *box;
} meeting_t;

static meeting_t meeting(double speed, double e, double box_mass, double phase) {
    meeting_t m = {scene_init(), NULL, NULL};
    scene_set_contacts_enabled(m.scene, true);
    m.box = added(m.scene, square(VEC_ZERO, 0.5, box_mass));
    double gap = speed * (0.5 + phase * WORLD_DT);
    m.ball = added(m.scene, body_init(polygon_make_regular(8, 0.5, (vector_t){-1.0 - gap, 0}, 0),
                                      1.0, BLUE));
    body_set_velocity(m.ball, (vector_t){speed, 0});
    body_set_elasticity(m.ball, e);
    body_set_elasticity(m.box, e);
    return m;
}

static void handler_fires_once_per_meeting_at_any_speed_and_elasticity(void) {
    const double box_masses[] = {INFINITY, 1.0};
    const double phases[] = {0.0, 0.5};
    for (size_t s = 0; s < COUNT_OF(MEETING_SPEEDS); s++) {
        for (size_t k = 0; k < COUNT_OF(MEETING_ELASTICITIES); k++) {
            for (size_t mass = 0; mass < COUNT_OF(box_masses); mass++) {
                for (size_t p = 0; p < COUNT_OF(phases); p++) {
                    for (int reversed = 0; reversed < 2; reversed++) {
                        double speed = MEETING_SPEEDS[s], e = MEETING_ELASTICITIES[k];
                        meeting_t m = meeting(speed, e, box_masses[mass], phases[p]);
                        /* Registered in the world's order of the pair and in
                         * the other: the handler gets them as registered. */
                        body_t *body1 = reversed ? m.box : m.ball;
                        body_t *body2 = reversed ? m.ball : m.box;
                        meeting_log_t log = {0};
                        create_collision(m.scene, body1, body2, meeting_handler, &log, 0.0);
                        int first_touch = -1, fired_at = -1;
                        for (int tick = 0; tick < 100; tick++) {
                            int calls = log.calls;
                            scene_tick(m.scene, WORLD_DT);
                            if (log.calls > calls && fired_at < 0) {
                                fired_at = tick;
                                const contact_t *entry = seed_entry(m.scene, body1, body2);
                                CHECK(entry != NULL);
                                if (entry != NULL) {
                                    CHECK(entry->touching);
                                    CHECK(entry->point_count == 1 || entry->point_count == 2);
                                    CHECK_VEC(entry->axis, log.axis.x, log.axis.y, 0);
                                }
                            }
                            if (first_touch < 0 && world_contact_touching(m.scene, m.ball, m.box)) {
                                first_touch = tick;
                            }
                        }
                        if (log.calls != 1 || fired_at != first_touch + 1) {
                            printf("    speed %g, e %g, box mass %g, phase %g, %s: %d calls, "
                                   "first touch at tick %d, fired at %d\n",
                                   speed, e, box_masses[mass], phases[p],
                                   reversed ? "(box, ball)" : "(ball, box)", log.calls,
                                   first_touch, fired_at);
                        }
                        CHECK(log.calls == 1);
                        CHECK(first_touch >= 0);
                        CHECK(fired_at == first_touch + 1); /* the tick after */
                        CHECK(log.body1 == body1 && log.body2 == body2);
                        CHECK(log.along > 0.0);
                        CHECK_NEAR(vec_get_length(log.axis), 1.0, 1e-12);
                        CHECK_NEAR(fabs(log.axis.x), 1.0, 1e-9); /* head on */
                        scene_free(m.scene);
                    }
                }
            }
        }
    }
}

static void resting_pair_fires_once_and_again_after_parting(void) {
    /* A box resting on a static floor under gravity: touching at every step,
     * one call. The world has no contact before its first step, so the call
     * comes at the second tick. Sleeping off: the test reads the resting
     * contact at every step (sleeping_pair_does_not_fire_again covers it). */
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    scene_set_sleeping(scene, false);
    scene_set_gravity(scene, (vector_t){0, -10});
    body_t *floor = added(scene, body_init(polygon_make_box((vector_t){0, -0.5}, 10, 0.5),
                                           INFINITY, BLUE));
    body_t *box = added(scene, square((vector_t){0, 0.5}, 0.5, 1.0));
    meeting_log_t log = {0};
    create_collision(scene, box, floor, meeting_handler, &log, 0.0);
    scene_tick(scene, WORLD_DT);
    CHECK(log.calls == 0);
    scene_tick(scene, WORLD_DT);
    CHECK(log.calls == 1);
    CHECK(log.body1 == box && log.body2 == floor);
    CHECK_VEC(log.axis, 0, -1, 1e-12); /* from the box down to the floor */
    for (int i = 0; i < 120; i++) {
        scene_tick(scene, WORLD_DT);
        CHECK(world_contact_touching(scene, box, floor));
    }
    CHECK(log.calls == 1);
    /* Thrown up 0.45 m, it parts from the floor and lands again: a second
     * meeting. */
    body_set_velocity(box, (vector_t){0, 3});
    int apart_ticks = 0;
    for (int i = 0; i < 120; i++) {
        scene_tick(scene, WORLD_DT);
        apart_ticks += !world_contact_touching(scene, box, floor);
    }
    CHECK(apart_ticks > 30);
    CHECK(log.calls == 2);
    CHECK(log.along > 0.0);
    /* Two movable boxes pushed together (gravity 0, inelastic) drift on as
     * one: one call however long they stay pressed. */
    scene_set_gravity(scene, VEC_ZERO);
    body_t *a = added(scene, square((vector_t){0, 5}, 0.5, 1.0));
    body_t *b = added(scene, square((vector_t){1.2, 5}, 0.5, 2.0));
    body_set_velocity(a, (vector_t){2, 0});
    meeting_log_t pair_log = {0};
    create_collision(scene, a, b, meeting_handler, &pair_log, 0.0);
    for (int i = 0; i < 200; i++) scene_tick(scene, WORLD_DT);
    CHECK(pair_log.calls == 1);
    CHECK(pair_log.along > 0.0);
    CHECK_NEAR(body_get_velocity(a).x, body_get_velocity(b).x, 1e-9);
    scene_free(scene);
}

static void destructive_collision_with_world_contacts_removes_both(void) {
    /* A ball hits a brick (static, or movable) at every speed: both are
     * freed at the end of the tick after the step in which they first
     * touched, and the ball never gets through the brick. */
    const double brick_masses[] = {INFINITY, 1.0};
    for (size_t s = 0; s < COUNT_OF(MEETING_SPEEDS); s++) {
        for (size_t k = 0; k < COUNT_OF(MEETING_ELASTICITIES); k++) {
            for (size_t mass = 0; mass < COUNT_OF(brick_masses); mass++) {
                double speed = MEETING_SPEEDS[s];
                meeting_t m = meeting(speed, MEETING_ELASTICITIES[k], brick_masses[mass], 0.3);
                body_t *bystander = added(m.scene, square((vector_t){0, 10}, 0.5, 1.0));
                create_destructive_collision(m.scene, m.ball, m.box);
                int first_touch = -1, tick = 0;
                for (; tick < 100 && scene_bodies(m.scene) == 3; tick++) {
                    CHECK(body_get_centroid(m.ball).x < body_get_centroid(m.box).x);
                    scene_tick(m.scene, WORLD_DT);
                    if (scene_bodies(m.scene) == 3 && first_touch < 0 &&
                        world_contact_touching(m.scene, m.ball, m.box)) {
                        first_touch = tick;
                    }
                }
                if (scene_bodies(m.scene) != 1 || tick != first_touch + 2) {
                    printf("    speed %g, e %g, brick mass %g: %zu bodies left after %d ticks, "
                           "first touch at tick %d\n",
                           speed, MEETING_ELASTICITIES[k], brick_masses[mass],
                           scene_bodies(m.scene), tick, first_touch);
                }
                CHECK(scene_bodies(m.scene) == 1);
                CHECK(scene_get_body(m.scene, 0) == bystander);
                CHECK(first_touch >= 0);
                CHECK(tick == first_touch + 2); /* reaped in the tick after the touch */
                scene_free(m.scene);
            }
        }
    }
}

/* World contacts on, but the pair kept out of them, by its filters (one
 * group) or by both masses being INFINITY (a kinematic body): the seed's
 * rule, as with contacts off. a (x in [-0.5, 0.5]) moves at 1 m/s toward b
 * (x in [1.05, 2.05]), dt = 0.1: they first overlap after 6 integrations
 * and the 7th tick's handler sees it. */
static void pair_out_of_world_contacts_keeps_the_seed_rule(void) {
    for (int kinematic = 0; kinematic < 2; kinematic++) {
        scene_t *scene = scene_init();
        scene_set_contacts_enabled(scene, true);
        double mass = kinematic ? INFINITY : 1.0;
        body_t *a = added(scene, square(VEC_ZERO, 0.5, mass));
        body_t *b = added(scene, square((vector_t){1.55, 0}, 0.5, mass));
        if (!kinematic) {
            body_set_collision_filter(a, 1, UINT32_MAX, 5);
            body_set_collision_filter(b, 1, UINT32_MAX, 5);
        }
        body_set_velocity(a, (vector_t){1, 0});
        meeting_log_t log = {0};
        create_collision(scene, a, b, meeting_handler, &log, 0.0);
        int tick = 0;
        while (log.calls == 0 && tick < 20) {
            bool overlapping = find_collision(a, b).collided;
            scene_tick(scene, 0.1);
            tick++;
            CHECK((log.calls == 1) == overlapping); /* at once, not a step late */
        }
        CHECK(tick == 7);
        CHECK_VEC(log.axis, 1, 0, 1e-15);
        for (int i = 0; i < 5; i++) scene_tick(scene, 0.1); /* passing through */
        CHECK(log.calls == 1);
        CHECK(body_get_centroid(a).x > 1.0); /* the world did not stop them */
        scene_free(scene);
    }
}

/* A built-in force that does not fit a double stops the program in
 * scene_tick, naming the force, its bodies and the likely cause; never
 * body_add_force, which the user did not call. */

/* An immovable anchor (body 0) and a bob of mass m at (1, 0) (body 1) on a
 * spring of constant k, ticked at 60 Hz until it blows up. */
typedef struct {
    double k, m;
    integrator_t integrator;
} spring_case_t;

static void run_spring_until_it_fails(void *data) {
    const spring_case_t *c = data;
    scene_t *scene = scene_init();
    scene_set_integrator(scene, c->integrator);
    body_t *anchor = added(scene, square(VEC_ZERO, 0.1, INFINITY));
    body_t *bob = added(scene, square((vector_t){1, 0}, 0.1, c->m));
    create_spring(scene, c->k, anchor, bob);
    for (int i = 0; i < 100000; i++) scene_tick(scene, 1.0 / 60.0);
}

static void far_apart_spring(void *unused) {
    (void)unused;
    scene_t *scene = scene_init();
    scene_set_integrator(scene, INTEGRATOR_SYMPLECTIC_EULER);
    body_t *a = added(scene, square((vector_t){-1e110, 0}, 1e97, INFINITY));
    body_t *b = added(scene, square(VEC_ZERO, 0.5, 1.0));
    create_spring(scene, 1e200, a, b); /* dt below the limit 2 sqrt(m / k) = 2e-100 s */
    scene_tick(scene, 1e-101);
}

static void implicit_far_apart_spring(void *unused) {
    (void)unused;
    scene_t *scene = scene_init();
    scene_set_integrator(scene, INTEGRATOR_IMPLICIT_EULER);
    body_t *a = added(scene, square((vector_t){-1e110, 0}, 1e97, INFINITY));
    body_t *b = added(scene, square(VEC_ZERO, 0.5, 1.0));
    create_spring(scene, 1e200, a, b);
    scene_tick(scene, 1.0 / 60.0);
}

/* Under implicit Euler the spring of run_spring_until_it_fails (omega dt =
 * 16.7) never fails: 10^4 steps later the bob rests on its anchor. */
static void implicit_euler_holds_the_spring_the_others_refuse(void) {
    scene_t *scene = scene_init();
    scene_set_integrator(scene, INTEGRATOR_IMPLICIT_EULER);
    body_t *anchor = added(scene, square(VEC_ZERO, 0.1, INFINITY));
    body_t *bob = added(scene, square((vector_t){1, 0}, 0.1, 1.0));
    create_spring(scene, 1e6, anchor, bob);
    for (int i = 0; i < 10000; i++) scene_tick(scene, 1.0 / 60.0);
    CHECK_VEC(body_get_centroid(bob), 0.0, 0.0, 1e-12);
    scene_free(scene);
}

static void fast_body_with_drag(void *unused) {
    (void)unused;
    scene_t *scene = scene_init();
    added(scene, square(VEC_ZERO, 0.5, 1.0));
    body_t *body = added(scene, square((vector_t){5, 0}, 0.5, 1.0));
    body_set_velocity(body, (vector_t){0, 1e300});
    create_drag(scene, 1e10, body);
    scene_tick(scene, 1.0 / 60.0);
}

/* gamma dt / m = 1.6: stable under Euler's schemes (factor -0.6 a step),
 * past symplectic4's drag limit (1.372), where the velocity grows until the
 * force overflows. */
static void symplectic4_drag_past_its_limit(void *unused) {
    (void)unused;
    scene_t *scene = scene_init();
    scene_set_integrator(scene, INTEGRATOR_SYMPLECTIC4);
    body_t *body = added(scene, square(VEC_ZERO, 0.5, 1.0));
    body_set_velocity(body, (vector_t){1.0, 0.0});
    create_drag(scene, 1.6 * 60.0, body);
    for (int i = 0; i < 100000; i++) scene_tick(scene, 1.0 / 60.0);
}

static void heavy_bodies_too_close(void *unused) {
    (void)unused;
    scene_t *scene = scene_init();
    body_t *a = added(scene, square(VEC_ZERO, 1e-6, 1e200));
    body_t *b = added(scene, square((vector_t){1e-5, 0}, 1e-6, 1e200));
    create_newtonian_gravity(scene, 1.0, a, b);
    scene_tick(scene, 1.0 / 60.0);
}

static void unstable_forces_abort_naming_the_force_and_the_cause(void) {
    /* The seed scheme gains energy on any spring; omega = 1000 rad/s. */
    /* Each names the scheme that is stable at this dt. */
    spring_case_t seed = {1e6, 1.0, INTEGRATOR_SEED};
    CHECK_DIES(run_spring_until_it_fails, &seed, "engine error in scene_tick:",
               "spring between body 0 and body 1", "k = 1e+06 N/m", "seed integrator",
               "dt < 2 sqrt(m/k) = 0.002 s", "INTEGRATOR_IMPLICIT_EULER at any dt");
    spring_case_t euler = {1e6, 1.0, INTEGRATOR_EXPLICIT_EULER};
    CHECK_DIES(run_spring_until_it_fails, &euler, "engine error in scene_tick:",
               "spring between body 0 and body 1", "explicit Euler integrator",
               "dt < 2 sqrt(m/k) = 0.002 s", "INTEGRATOR_IMPLICIT_EULER at any dt");
    spring_case_t symplectic = {1e6, 1.0, INTEGRATOR_SYMPLECTIC_EULER};
    CHECK_DIES(run_spring_until_it_fails, &symplectic, "engine error in scene_tick:",
               "spring between body 0 and body 1", "dt = 0.0166667 s is above",
               "dt < 2 sqrt(m/k) = 0.002 s",
               "INTEGRATOR_IMPLICIT_EULER is stable for it at any dt");
    spring_case_t verlet = {1e6, 1.0, INTEGRATOR_VELOCITY_VERLET};
    CHECK_DIES(run_spring_until_it_fails, &verlet, "engine error in scene_tick:",
               "velocity Verlet integrator", "INTEGRATOR_IMPLICIT_EULER is stable for it");
    /* Implicit Euler: the same spring only loses energy; too far apart for
     * k, the message says the scheme is not the cause. */
    CHECK_DIES(implicit_far_apart_spring, NULL, "engine error in scene_tick:", "force stage",
               "spring between body 0 and body 1", "too far apart",
               "the implicit Euler integrator is stable for it at any dt");
    /* A light bob: its velocity overflows before the spring's force does, so
     * the integrate stage reports it, naming the scene's stiffest spring. */
    spring_case_t light = {1.0, 1e-200, INTEGRATOR_SEED};
    CHECK_DIES(run_spring_until_it_fails, &light, "engine error in scene_tick:",
               "integrate stage", "body 1", "velocity is not finite",
               "spring between body 0 and body 1", "dt < 2 sqrt(m/k) = 2e-100 s");
    CHECK_DIES(far_apart_spring, NULL, "engine error in scene_tick:", "force stage",
               "spring between body 0 and body 1", "force is not finite",
               "stretch (1e+110, 0) m", "too far apart");
    CHECK_DIES(fast_body_with_drag, NULL, "engine error in scene_tick:", "force stage",
               "drag on body 1", "gamma = 1e+10 kg/s", "force is not finite",
               "dt < 2 m / gamma = 2e-10 s", "INTEGRATOR_IMPLICIT_EULER is stable for it");
    /* The limit named is the scheme's own (integrator_get_drag_limit). */
    CHECK_DIES(symplectic4_drag_past_its_limit, NULL, "engine error in scene_tick:",
               "drag on body 0", "the drag is unstable at dt = 0.0166667 s",
               "symplectic4", "dt < 1.37192 m / gamma = 0.0142909 s",
               "INTEGRATOR_IMPLICIT_EULER is stable for it");
    CHECK_DIES(heavy_bodies_too_close, NULL, "engine error in scene_tick:", "force stage",
               "newtonian gravity between body 0 and body 1", "force is not finite",
               "too close");
}

static void gravity_between_huge_masses_is_applied(void) {
    /* G m1 m2 overflows a double for two masses of 1e160 kg, but the force,
     * 6.674e149 N at 1e80 m, does not: each accelerates at 6.674e-11 m/s^2. */
    const double G = 6.674e-11;
    scene_t *scene = scene_init();
    body_t *a = added(scene, square(VEC_ZERO, 1e66, 1e160));
    body_t *b = added(scene, square((vector_t){1e80, 0}, 1e66, 1e160));
    create_newtonian_gravity(scene, G, a, b);
    scene_tick(scene, 1.0);
    CHECK_RELATIVE(body_get_velocity(a).x, G, 1e-12);
    CHECK_RELATIVE(body_get_velocity(b).x, -G, 1e-12);
    scene_free(scene);
}

static void huge_closing_speed(void *unused) {
    (void)unused;
    body_t *a = square(VEC_ZERO, 0.5, 1e200);
    body_t *b = square((vector_t){0.9, 0}, 0.5, 1e200);
    body_set_velocity(a, (vector_t){1e110, 0});
    body_set_velocity(b, (vector_t){-1e110, 0});
    physics_collision_handler(a, b, (vector_t){1, 0}, NULL, 1.0);
}

static void physics_handler_refuses_an_impulse_that_overflows(void) {
    CHECK_DIES(huge_closing_speed, NULL, "engine error in physics_collision_handler:",
               "impulse is not finite", "reduced mass 5e+199 kg");
}


/* Programmer errors. */

static body_t *any_body(void) {
    return square(VEC_ZERO, 0.5, 1.0);
}

BAD_CALL(gravity_null_scene, create_newtonian_gravity(NULL, 1.0, any_body(), any_body()))
BAD_CALL(gravity_null_body, create_newtonian_gravity(scene_init(), 1.0, NULL, any_body()))
BAD_CALL(gravity_negative_g, create_newtonian_gravity(scene_init(), -1.0, any_body(), any_body()))
BAD_CALL(gravity_nan_g, create_newtonian_gravity(scene_init(), NAN, any_body(), any_body()))
BAD_CALL(spring_null_body, create_spring(scene_init(), 1.0, any_body(), NULL))
BAD_CALL(spring_negative_k, create_spring(scene_init(), -2.0, any_body(), any_body()))
BAD_CALL(spring_infinite_k, create_spring(scene_init(), INFINITY, any_body(), any_body()))
BAD_CALL(spring_length_negative,
         create_spring_with_length(scene_init(), 1.0, -0.5, any_body(), any_body()))
BAD_CALL(spring_length_nan,
         create_spring_with_length(scene_init(), 1.0, NAN, any_body(), any_body()))
BAD_CALL(spring_length_infinite,
         create_spring_with_length(scene_init(), 1.0, INFINITY, any_body(), any_body()))
BAD_CALL(spring_length_negative_k,
         create_spring_with_length(scene_init(), -1.0, 1.0, any_body(), any_body()))
BAD_CALL(spring_length_null_body,
         create_spring_with_length(scene_init(), 1.0, 1.0, any_body(), NULL))
BAD_CALL(spring_length_null_scene,
         create_spring_with_length(NULL, 1.0, 1.0, any_body(), any_body()))
BAD_CALL(spring_length_to_itself, {
    body_t *body = any_body();
    create_spring_with_length(scene_init(), 1.0, 1.0, body, body);
})
BAD_CALL(spring_to_itself, {
    body_t *body = any_body();
    create_spring(scene_init(), 1.0, body, body);
})
BAD_CALL(drag_null_body, create_drag(scene_init(), 1.0, NULL))
BAD_CALL(drag_null_scene, create_drag(NULL, 1.0, any_body()))
BAD_CALL(drag_negative_gamma, create_drag(scene_init(), -0.5, any_body()))
BAD_CALL(collision_null_handler, create_collision(scene_init(), any_body(), any_body(), NULL,
                                                  NULL, 0.0))
BAD_CALL(collision_null_body, create_collision(scene_init(), NULL, any_body(), logging_handler,
                                               NULL, 0.0))
BAD_CALL(collision_with_itself, {
    body_t *body = any_body();
    create_collision(scene_init(), body, body, logging_handler, NULL, 0.0);
})
BAD_CALL(destructive_null_scene, create_destructive_collision(NULL, any_body(), any_body()))
BAD_CALL(destructive_null_body, create_destructive_collision(scene_init(), any_body(), NULL))
BAD_CALL(physics_negative_elasticity,
         create_physics_collision(scene_init(), any_body(), any_body(), -0.1))
BAD_CALL(physics_nan_elasticity,
         create_physics_collision(scene_init(), any_body(), any_body(), NAN))
BAD_CALL(physics_null_scene, create_physics_collision(NULL, any_body(), any_body(), 1.0))
BAD_CALL(physics_null_body, create_physics_collision(scene_init(), NULL, any_body(), 1.0))
BAD_CALL(physics_with_itself, {
    body_t *body = any_body();
    create_physics_collision(scene_init(), body, body, 1.0);
})
BAD_CALL(destructive_with_itself, {
    body_t *body = any_body();
    create_destructive_collision(scene_init(), body, body);
})
BAD_CALL(handler_negative_elasticity,
         physics_collision_handler(any_body(), any_body(), (vector_t){1, 0}, NULL, -1.0))
BAD_CALL(handler_null_body, physics_collision_handler(NULL, any_body(), (vector_t){1, 0}, NULL,
                                                      1.0))

/* `mine` is in `scene` (or in none, for NULL); `theirs` in another scene,
 * freed with it, which a force creator of `scene` would read afterwards. */
static scene_t *two_scenes(body_t **mine, body_t **theirs) {
    scene_t *scene = scene_init();
    *mine = added(scene, any_body());
    *theirs = added(scene_init(), square((vector_t){2, 0}, 0.5, 1.0));
    return scene;
}

static void spring_to_another_scene(void *unused) {
    (void)unused;
    body_t *mine, *theirs;
    scene_t *scene = two_scenes(&mine, &theirs);
    create_spring(scene, 1.0, mine, theirs);
}
static void spring_from_another_scene(void *unused) {
    (void)unused;
    body_t *mine, *theirs;
    scene_t *scene = two_scenes(&mine, &theirs);
    create_spring(scene, 1.0, theirs, mine);
}
static void gravity_to_another_scene(void *unused) {
    (void)unused;
    body_t *mine, *theirs;
    scene_t *scene = two_scenes(&mine, &theirs);
    create_newtonian_gravity(scene, 1.0, mine, theirs);
}
static void drag_on_another_scene(void *unused) {
    (void)unused;
    body_t *mine, *theirs;
    scene_t *scene = two_scenes(&mine, &theirs);
    create_drag(scene, 1.0, theirs);
}
static void collision_with_another_scene(void *unused) {
    (void)unused;
    body_t *mine, *theirs;
    scene_t *scene = two_scenes(&mine, &theirs);
    create_collision(scene, mine, theirs, logging_handler, NULL, 0.0);
}
static void physics_collision_with_another_scene(void *unused) {
    (void)unused;
    body_t *mine, *theirs;
    scene_t *scene = two_scenes(&mine, &theirs);
    create_physics_collision(scene, mine, theirs, 1.0);
}
static void destructive_collision_with_another_scene(void *unused) {
    (void)unused;
    body_t *mine, *theirs;
    scene_t *scene = two_scenes(&mine, &theirs);
    create_destructive_collision(scene, theirs, mine);
}
static void no_force(void *aux) {
    (void)aux;
}
static void bodies_force_creator_with_another_scene(void *unused) {
    (void)unused;
    body_t *mine, *theirs;
    scene_t *scene = two_scenes(&mine, &theirs);
    list_t *bodies = list_init(2, NULL);
    list_add(bodies, mine);
    list_add(bodies, theirs);
    scene_add_bodies_force_creator(scene, no_force, NULL, bodies, NULL);
}
static void named_then_added_elsewhere(void *unused) {
    /* A body in no scene that a force creator of one scene names is that
     * scene's: adding it to another is refused. */
    (void)unused;
    scene_t *scene = scene_init();
    body_t *a = added(scene, any_body()), *loose = any_body();
    create_spring(scene, 1.0, a, loose);
    scene_add_body(scene_init(), loose);
}

static void a_force_creator_refuses_a_body_of_another_scene(void) {
    CHECK_DIES(spring_to_another_scene, NULL,
               "engine error in create_spring: body2 belongs to another scene");
    CHECK_DIES(spring_from_another_scene, NULL,
               "engine error in create_spring: body1 belongs to another scene");
    CHECK_DIES(gravity_to_another_scene, NULL,
               "engine error in create_newtonian_gravity: body2 belongs to another scene");
    CHECK_DIES(drag_on_another_scene, NULL,
               "engine error in create_drag: body belongs to another scene");
    CHECK_DIES(collision_with_another_scene, NULL,
               "engine error in create_collision: body2 belongs to another scene");
    CHECK_DIES(physics_collision_with_another_scene, NULL,
               "engine error in create_physics_collision: body2 belongs to another scene");
    CHECK_DIES(destructive_collision_with_another_scene, NULL,
               "engine error in create_destructive_collision: body1 belongs to another scene");
    CHECK_DIES(bodies_force_creator_with_another_scene, NULL,
               "engine error in scene_add_bodies_force_creator: bodies[1] belongs to another "
               "scene");
    CHECK_DIES(named_then_added_elsewhere, NULL,
               "engine error in scene_add_body: body is used by a force creator of another "
               "scene");
}

static void bad_input_aborts_with_message(void) {
    CHECK_DIES(gravity_null_scene, NULL, "engine error in create_newtonian_gravity:",
               "scene is NULL");
    CHECK_DIES(gravity_null_body, NULL, "engine error in create_newtonian_gravity:",
               "body1 is NULL");
    CHECK_DIES(gravity_negative_g, NULL, "engine error in create_newtonian_gravity:", "G",
               "got -1");
    CHECK_DIES(gravity_nan_g, NULL, "engine error in create_newtonian_gravity:", "G", "nan");
    CHECK_DIES(spring_null_body, NULL, "engine error in create_spring:", "body2 is NULL");
    CHECK_DIES(spring_negative_k, NULL, "engine error in create_spring:", "k", "got -2");
    CHECK_DIES(spring_infinite_k, NULL, "engine error in create_spring:", "k", "inf");
    CHECK_DIES(spring_to_itself, NULL, "engine error in create_spring:",
               "a spring cannot join a body to itself");
    CHECK_DIES(spring_length_negative, NULL, "engine error in create_spring_with_length:",
               "rest_length must be finite and >= 0 (got -0.5)");
    CHECK_DIES(spring_length_nan, NULL, "engine error in create_spring_with_length:",
               "rest_length", "nan");
    CHECK_DIES(spring_length_infinite, NULL, "engine error in create_spring_with_length:",
               "rest_length", "inf");
    CHECK_DIES(spring_length_negative_k, NULL, "engine error in create_spring_with_length:",
               "k must be finite and >= 0 (got -1)");
    CHECK_DIES(spring_length_null_body, NULL, "engine error in create_spring_with_length:",
               "body2 is NULL");
    CHECK_DIES(spring_length_null_scene, NULL, "engine error in create_spring_with_length:",
               "scene is NULL");
    CHECK_DIES(spring_length_to_itself, NULL, "engine error in create_spring_with_length:",
               "a spring cannot join a body to itself");
    CHECK_DIES(drag_null_body, NULL, "engine error in create_drag:", "body is NULL");
    CHECK_DIES(drag_null_scene, NULL, "engine error in create_drag:", "scene is NULL");
    CHECK_DIES(drag_negative_gamma, NULL, "engine error in create_drag:", "gamma", "got -0.5");
    CHECK_DIES(collision_null_handler, NULL, "engine error in create_collision:",
               "handler is NULL");
    CHECK_DIES(collision_null_body, NULL, "engine error in create_collision:", "body1 is NULL");
    CHECK_DIES(collision_with_itself, NULL, "engine error in create_collision:", "itself");
    CHECK_DIES(destructive_null_scene, NULL, "engine error in create_destructive_collision:",
               "scene is NULL");
    CHECK_DIES(destructive_null_body, NULL, "engine error in create_destructive_collision:",
               "body2 is NULL");
    CHECK_DIES(physics_negative_elasticity, NULL, "engine error in create_physics_collision:",
               "elasticity", "got -0.1");
    CHECK_DIES(physics_nan_elasticity, NULL, "engine error in create_physics_collision:",
               "elasticity", "nan");
    CHECK_DIES(physics_null_scene, NULL, "engine error in create_physics_collision:",
               "scene is NULL");
    CHECK_DIES(physics_null_body, NULL, "engine error in create_physics_collision:",
               "body1 is NULL");
    CHECK_DIES(physics_with_itself, NULL, "engine error in create_physics_collision:",
               "itself");
    CHECK_DIES(destructive_with_itself, NULL, "engine error in create_destructive_collision:",
               "itself");
    CHECK_DIES(handler_negative_elasticity, NULL, "engine error in physics_collision_handler:",
               "elasticity", "got -1");
    CHECK_DIES(handler_null_body, NULL, "engine error in physics_collision_handler:",
               "body1 is NULL");
}

TEST_SUITE(forces, TEST_CASE(spring_is_hooke_with_rest_length_zero),
           TEST_CASE(a_ball_meeting_two_pegs_in_one_tick_gains_no_energy),
           TEST_CASE(spring_oscillator_matches_the_cosine),
           TEST_CASE(spring_with_length_is_hooke_about_its_length),
           TEST_CASE(spring_with_length_oscillates_about_its_length),
           TEST_CASE(spring_with_length_stretches_by_m_g_over_k),
           TEST_CASE(spring_with_length_conserves_energy_with_symplectic_euler),
           TEST_CASE(gravity_follows_the_inverse_square_law),
           TEST_CASE(gravity_is_left_out_when_it_cannot_be_applied),
           TEST_CASE(two_body_gravity_conserves_energy_and_momentum),
           TEST_CASE(drag_is_minus_gamma_v), TEST_CASE(drag_decays_exponentially),
           TEST_CASE(handler_runs_once_per_contact_with_its_arguments),
           TEST_CASE(destructive_collision_removes_both_at_the_contact_time),
           TEST_CASE(physics_handler_applies_the_formula_along_any_axis),
           TEST_CASE(physics_handler_with_infinite_masses),
           TEST_CASE(physics_handler_with_huge_finite_masses),
           TEST_CASE(equal_masses_elastic_swap_velocities),
           TEST_CASE(zero_elasticity_gives_the_common_velocity),
           TEST_CASE(super_elastic_gains_energy_by_the_formula),
           TEST_CASE(ball_bounces_between_infinite_walls),
           TEST_CASE(seed_collisions_are_in_the_record),
           TEST_CASE(destroyed_bodies_never_linger_in_the_record),
           TEST_CASE(force_creators_may_name_bodies_before_they_are_added),
           TEST_CASE(a_force_creator_refuses_a_body_of_another_scene),
           TEST_CASE(handler_fires_once_per_meeting_at_any_speed_and_elasticity),
           TEST_CASE(resting_pair_fires_once_and_again_after_parting),
           TEST_CASE(destructive_collision_with_world_contacts_removes_both),
           TEST_CASE(pair_out_of_world_contacts_keeps_the_seed_rule),
           TEST_CASE(unstable_forces_abort_naming_the_force_and_the_cause),
           TEST_CASE(implicit_euler_holds_the_spring_the_others_refuse),
           TEST_CASE(gravity_between_huge_masses_is_applied),
           TEST_CASE(physics_handler_refuses_an_impulse_that_overflows),
           TEST_CASE(bad_input_aborts_with_message));
