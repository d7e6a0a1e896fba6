/* INTEGRATOR_IMPLICIT_EULER (engine/src/implicit_euler.h): its step against
 * backward Euler's closed forms, stiff springs and drag at any step, the
 * sparse solve under it (spring_system.h, jacobian.h), and how it lives with
 * contacts, sleeping and workers. */
#include <stdlib.h>
#include <string.h>
#include "engine.h"
#include "dynamics/jacobian.h"
#include "reference.h"
#include "dynamics/spring_system.h"
#include "test.h"

static const rgb_color_t GREY = {0.5f, 0.5f, 0.5f};
static const double H = 1.0 / 60.0;

static body_t *added_box(scene_t *scene, vector_t center, double half_w, double half_h,
                         double mass) {
    body_t *body = body_init(polygon_make_box(center, half_w, half_h), mass, GREY);
    scene_add_body(scene, body);
    return body;
}

static body_t *added_small(scene_t *scene, vector_t center, double mass) {
    return added_box(scene, center, 0.05, 0.05, mass);
}

static scene_t *implicit_scene(void) {
    scene_t *scene = scene_init();
    scene_set_integrator(scene, INTEGRATOR_IMPLICIT_EULER);
    return scene;
}

/* ---- Backward Euler's closed forms ---- */

/* Undamped, x'' = -omega^2 x with y = v / omega and theta = omega h:
 * x' = x + theta y', y' = y - theta x', so
 * (x', y') = (x + theta y, y - theta x) / (1 + theta^2): a turn by
 * atan(theta) and a shrink by 1 / sqrt(1 + theta^2) every step, the energy
 * by 1 / (1 + theta^2). Each step is checked against the formula applied to
 * the state before it, while the amplitude is above 1e-6 of the start's.
 * (Rounding grows as theta^2: x' = x + h v' cancels all but 1 / theta of x,
 * and h v' has x's rounding; 4e-9 at theta = 1e4.) */
static void spring_shrinks_by_one_over_sqrt_one_plus_theta_squared(void) {
    const double thetas[] = {0.1, 1.0, 10.0, 100.0, 1000.0};
    for (size_t t = 0; t < sizeof thetas / sizeof thetas[0]; t++) {
        double theta = thetas[t], omega = theta / H, m = 2.5, k = m * omega * omega;
        scene_t *scene = implicit_scene();
        body_t *anchor = added_small(scene, VEC_ZERO, INFINITY);
        body_t *bob = added_small(scene, (vector_t){1.0, 0.0}, m);
        body_set_velocity(bob, (vector_t){0.7 * omega, 0.0});
        create_spring(scene, k, anchor, bob);
        double x = 1.0, y = 0.7, start = hypot(x, y);
        double shrink = 1.0 / sqrt(1.0 + theta * theta);
        int steps = 0;
        while (hypot(x, y) > 1e-6 * start && steps < 50) {
            scene_tick(scene, H);
            double ex = (x + theta * y) / (1.0 + theta * theta);
            double ey = (y - theta * x) / (1.0 + theta * theta);
            double nx = body_get_centroid(bob).x, ny = body_get_velocity(bob).x / omega;
            double amplitude = hypot(x, y);
            CHECK_NEAR(nx, ex, 1e-9 * amplitude);
            CHECK_NEAR(ny, ey, 1e-9 * amplitude);
            CHECK_RELATIVE(hypot(nx, ny) / amplitude, shrink, 1e-9);
            double energy = 0.5 * k * x * x + 0.5 * m * omega * omega * y * y;
            double next = 0.5 * k * nx * nx + 0.5 * m * omega * omega * ny * ny;
            CHECK_RELATIVE(next / energy, 1.0 / (1.0 + theta * theta), 1e-9);
            x = nx, y = ny;
            steps++;
        }
        CHECK(steps >= 2);
        scene_free(scene);
    }
}

/* Two free bodies of 1e-3 and 1 kg: the relative motion follows the
 * single spring's map with the reduced mass, the centre of mass moves on at
 * its own velocity (momentum kept to rounding). */
static void a_free_pair_keeps_momentum_and_shrinks_its_relative_motion(void) {
    const double thetas[] = {0.5, 100.0};
    for (size_t t = 0; t < 2; t++) {
        double m1 = 1e-3, m2 = 1.0, mu = m1 * m2 / (m1 + m2);
        double theta = thetas[t], omega = theta / H, k = mu * omega * omega;
        scene_t *scene = implicit_scene();
        body_t *a = added_small(scene, (vector_t){0.3, 0.4}, m1);
        body_t *b = added_small(scene, (vector_t){-0.2, 0.1}, m2);
        body_set_velocity(a, (vector_t){2.0, -1.0});
        body_set_velocity(b, (vector_t){0.5, 3.0});
        create_spring(scene, k, a, b);
        vector_t momentum = {m1 * 2.0 + m2 * 0.5, m1 * -1.0 + m2 * 3.0};
        vector_t r = {0.5, 0.3}, y = vec_multiply(1.0 / omega, (vector_t){1.5, -4.0});
        for (int step = 0; step < 6; step++) {
            scene_tick(scene, H);
            vector_t p = vec_add(vec_multiply(m1, body_get_velocity(a)),
                                 vec_multiply(m2, body_get_velocity(b)));
            CHECK_VEC(p, momentum.x, momentum.y, 1e-12);
            double d = 1.0 + theta * theta;
            vector_t er = vec_multiply(1.0 / d, vec_add(r, vec_multiply(theta, y)));
            vector_t ey = vec_multiply(1.0 / d, vec_subtract(y, vec_multiply(theta, r)));
            vector_t nr = vec_subtract(body_get_centroid(a), body_get_centroid(b));
            vector_t ny = vec_multiply(1.0 / omega, vec_subtract(body_get_velocity(a),
                                                                 body_get_velocity(b)));
            double amplitude = sqrt(vec_dot(r, r) + vec_dot(y, y));
            CHECK_VEC(nr, er.x, er.y, 1e-9 * amplitude + 1e-15);
            CHECK_VEC(ny, ey.x, ey.y, 1e-9 * amplitude + 1e-15);
            r = nr, y = ny;
        }
        scene_free(scene);
    }
}

/* Drag: v' = (v + h g) / (1 + gamma h / m), so v_n = v_inf + (v0 - v_inf) /
 * (1 + z)^n with v_inf = g m / gamma, at any z = gamma h / m; explicit
 * schemes need z < 2. */
static void drag_divides_the_velocity_by_one_plus_gamma_h_over_m(void) {
    const double zs[] = {0.5, 10.0, 1000.0};
    for (size_t t = 0; t < 3; t++) {
        double z = zs[t], m = 3.0, gamma = z * m / H, g = -9.81;
        scene_t *scene = implicit_scene();
        scene_set_gravity(scene, (vector_t){0.0, g});
        body_t *body = added_small(scene, VEC_ZERO, m);
        body_set_velocity(body, (vector_t){4.0, 2.0});
        create_drag(scene, gamma, body);
        double v_inf = g * m / gamma;
        for (int n = 1; n <= 20; n++) {
            scene_tick(scene, H);
            double decay = pow(1.0 + z, -n);
            CHECK_NEAR(body_get_velocity(body).x, 4.0 * decay, 1e-12);
            CHECK_NEAR(body_get_velocity(body).y, v_inf + (2.0 - v_inf) * decay, 1e-12);
        }
        scene_free(scene);
    }
}

/* The order: the error of the oscillator and of the drag scene
 * (tests/reference.c) halves with h. */
static void its_order_is_one(void) {
    const reference_scene_t scenes[2] = {REFERENCE_OSCILLATOR, REFERENCE_DRAG};
    for (int s = 0; s < 2; s++) {
        double h = 1.0 / 480.0;
        reference_result_t coarse = reference_run(scenes[s], INTEGRATOR_IMPLICIT_EULER, h, 2.25);
        reference_result_t fine = reference_run(scenes[s], INTEGRATOR_IMPLICIT_EULER, h / 4, 2.25);
        CHECK(!coarse.diverged && !fine.diverged);
        double order = log(coarse.error / fine.error) / log(4.0);
        if (fabs(order - 1.0) > 0.05) {
            test_fail(__FILE__, __LINE__, "%s: order %.3f, theory 1", reference_name(scenes[s]),
                      order);
        }
    }
}

/* create_spring_with_length: along a fixed line its force is linear, so
 * the stretch beyond the rest length shrinks as a spring of rest length 0
 * does; a stiff one (omega h = 100 along it) holding a swinging pendulum
 * keeps its length and loses energy. */
static void a_spring_with_a_rest_length_is_implicit_too(void) {
    double theta = 100.0, omega = theta / H, k = omega * omega, rest = 2.0;
    scene_t *scene = implicit_scene();
    body_t *anchor = added_small(scene, VEC_ZERO, INFINITY);
    body_t *bob = added_small(scene, (vector_t){rest + 0.5, 0.0}, 1.0);
    create_spring_with_length(scene, k, rest, anchor, bob);
    double x = 0.5, y = 0.0;
    for (int step = 0; step < 3; step++) {
        scene_tick(scene, H);
        double ex = (x + theta * y) / (1.0 + theta * theta);
        double ey = (y - theta * x) / (1.0 + theta * theta);
        double nx = body_get_centroid(bob).x - rest, ny = body_get_velocity(bob).x / omega;
        CHECK_NEAR(nx, ex, 1e-9 * hypot(x, y));
        CHECK_NEAR(ny, ey, 1e-9 * hypot(x, y));
        x = nx, y = ny;
    }
    scene_free(scene);

    const double g = 9.81;
    scene = implicit_scene();
    scene_set_gravity(scene, (vector_t){0.0, -g});
    anchor = added_small(scene, VEC_ZERO, INFINITY);
    bob = added_small(scene, (vector_t){rest * sin(0.5), -rest * cos(0.5)}, 1.0);
    create_spring_with_length(scene, k, rest, anchor, bob);
    double energy = INFINITY, longest = 0.0, shortest = INFINITY;
    for (int step = 0; step < 600; step++) {
        scene_tick(scene, H);
        vector_t p = body_get_centroid(bob), v = body_get_velocity(bob);
        double d = vec_get_length(p), stretch = d - rest;
        longest = fmax(longest, d), shortest = fmin(shortest, d);
        double now = 0.5 * vec_dot(v, v) + g * p.y + 0.5 * k * stretch * stretch;
        CHECK(now <= energy + 1e-9);
        energy = now;
    }
    /* Straight steps along a circle overshoot it by (h v)^2 / (2 L); the
     * stiff spring takes most of that back within the step. */
    double fastest = sqrt(2.0 * g * rest * (1.0 - cos(0.5)));
    CHECK(shortest > rest);
    CHECK(longest - rest < pow(H * fastest, 2) / rest);
    CHECK(energy < -g * rest * cos(0.5)); /* it swings lower than it started */
    scene_free(scene);
}

/* ---- Stiff springs: never refused, never unstable ---- */

/* omega h = 100 (k = 3.6e7 N/m on 1 kg at 60 Hz), where every explicit
 * scheme blows up: 10^4 steps, every state finite, the energy only falls,
 * and scene_tick never stops. */
static void a_spring_at_omega_h_100_runs_and_loses_energy(void) {
    double omega = 100.0 / H, k = omega * omega;
    scene_t *scene = implicit_scene();
    scene_set_gravity(scene, (vector_t){0.0, -9.81});
    body_t *anchor = added_small(scene, VEC_ZERO, INFINITY);
    body_t *bob = added_small(scene, (vector_t){0.0, -1.0}, 1.0);
    body_set_velocity(bob, (vector_t){50.0, 0.0});
    create_spring(scene, k, anchor, bob);
    double rest = -9.81 / k, energy = INFINITY;
    for (int step = 0; step < 10000; step++) {
        scene_tick(scene, H);
        vector_t x = body_get_centroid(bob), v = body_get_velocity(bob);
        CHECK(isfinite(x.x) && isfinite(x.y) && isfinite(v.x) && isfinite(v.y));
        double dy = x.y - rest;
        double now = 0.5 * vec_dot(v, v) + 0.5 * k * (x.x * x.x + dy * dy);
        CHECK(now <= energy * (1.0 + 1e-12) + 1e-20);
        energy = now;
    }
    CHECK_VEC(body_get_centroid(bob), 0.0, rest, 1e-12);
    scene_free(scene);
}

/* The chain the issue asks for: 100 bodies of 1e-3 to 1 kg (log-spaced,
 * shuffled so that light and heavy alternate) on springs of 1e8 N/m hanging
 * from an anchor under gravity, displaced up to 1 cm and stepped at 1/60 s
 * (omega h up to 5000): every state finite at every step; after 10 s every
 * body at its static equilibrium (spring j stretched by the weight below it
 * over k) to 1e-9 m and at rest to 1e-9 m/s; warm steps allocate nothing. */
static void a_chain_of_stiff_springs_and_mixed_masses_settles(void) {
    enum { N = 100 };
    const double k = 1e8, g = 9.81;
    scene_t *scene = implicit_scene();
    scene_set_gravity(scene, (vector_t){0.0, -g});
    body_t *previous = added_small(scene, VEC_ZERO, INFINITY);
    body_t *bodies[N];
    double mass[N];
    unsigned seed = 12345;
    for (int i = 0; i < N; i++) {
        mass[i] = pow(10.0, -3.0 + 3.0 * ((i * 37) % N) / (N - 1.0));
        seed = seed * 1103515245u + 12345u;
        double dx = 0.01 * ((seed >> 16) % 2001 / 1000.0 - 1.0);
        bodies[i] = added_small(scene, (vector_t){dx, -0.1 * (i + 1)}, mass[i]);
        create_spring(scene, k, previous, bodies[i]);
        previous = bodies[i];
    }
    for (int step = 0; step < 600; step++) {
        if (step == 10) {
            size_t before = engine_allocation_count();
            scene_tick(scene, H);
            CHECK(engine_allocation_count() == before);
            continue;
        }
        scene_tick(scene, H);
        for (int i = 0; i < N; i++) {
            vector_t x = body_get_centroid(bodies[i]), v = body_get_velocity(bodies[i]);
            if (!(isfinite(x.x) && isfinite(x.y) && isfinite(v.x) && isfinite(v.y))) {
                test_fail(__FILE__, __LINE__, "body %d not finite at step %d", i, step);
                scene_free(scene);
                return;
            }
        }
    }
    double y = 0.0, below = 0.0;
    for (int i = 0; i < N; i++) below += mass[i];
    for (int i = 0; i < N; i++) {
        y -= below * g / k;
        below -= mass[i];
        CHECK_VEC(body_get_centroid(bodies[i]), 0.0, y, 1e-9);
        CHECK(vec_get_length(body_get_velocity(bodies[i])) < 1e-9);
    }
    scene_free(scene);
}

/* ---- What it shares with symplectic Euler ---- */

typedef struct {
    body_t *body;
} push_t;

/* A force of the user's: constant plus a velocity-dependent part. */
static void user_force(void *aux) {
    body_t *body = ((push_t *)aux)->body;
    vector_t v = body_get_velocity(body);
    body_add_force(body, (vector_t){1.0 - 0.3 * v.x, 0.5 - 0.3 * v.y});
}

static void run_mixed_scene(integrator_t integrator, double *state, size_t *count) {
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    scene_set_gravity(scene, (vector_t){0.0, -9.81});
    scene_set_contacts_enabled(scene, true);
    added_box(scene, (vector_t){0.0, -0.5}, 20.0, 0.5, INFINITY);
    body_t *sun = added_box(scene, (vector_t){30.0, 30.0}, 0.5, 0.5, 1000.0);
    body_t *planet = added_box(scene, (vector_t){40.0, 30.0}, 0.2, 0.2, 1.0);
    body_set_collision_filter(sun, 2, 2, 0);
    body_set_collision_filter(planet, 2, 2, 0);
    body_set_velocity(planet, (vector_t){0.0, 10.0});
    create_newtonian_gravity(scene, 1.0, sun, planet);
    for (int i = 0; i < 4; i++) {
        body_t *box = added_box(scene, (vector_t){0.3 * i, 0.5 + 1.05 * i}, 0.5, 0.5, 1.0 + i);
        body_set_angular_velocity(box, 0.2 * i);
        push_t *push = malloc(sizeof *push);
        push->body = box;
        list_t *bodies = list_init(1, NULL);
        list_add(bodies, box);
        scene_add_bodies_force_creator(scene, user_force, push, bodies, free);
    }
    for (int step = 0; step < 120; step++) {
        if (step == 3) body_add_impulse(planet, (vector_t){0.1, 0.0});
        scene_tick(scene, H);
    }
    *count = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        vector_t x = body_get_centroid(body), v = body_get_velocity(body);
        double values[6] = {x.x, x.y, body_get_rotation(body), v.x, v.y,
                            body_get_angular_velocity(body)};
        memcpy(state + *count, values, sizeof values);
        *count += 6;
    }
    scene_free(scene);
}

/* A scene without create_spring or create_drag (Newtonian gravity, forces
 * of the user's, impulses, world contacts, rotation) moves bit for bit as
 * under symplectic Euler. */
static void without_springs_or_drag_it_is_symplectic_euler(void) {
    double a[64], b[64];
    size_t na, nb;
    run_mixed_scene(INTEGRATOR_SYMPLECTIC_EULER, a, &na);
    run_mixed_scene(INTEGRATOR_IMPLICIT_EULER, b, &nb);
    CHECK(na == nb && na == 42);
    CHECK(memcmp(a, b, na * sizeof(double)) == 0);
}

typedef struct {
    body_t *anchor, *bob;
    double k;
} user_spring_t;

static void user_spring(void *aux) {
    user_spring_t *s = aux;
    vector_t stretch = vec_subtract(body_get_centroid(s->anchor), body_get_centroid(s->bob));
    body_add_force(s->bob, vec_multiply(s->k, stretch));
}

/* The energy of a bob on a spring written as a force creator of the user's
 * after `steps` steps at omega h = theta, over the start's. */
static double user_spring_energy(integrator_t integrator, double theta, int steps) {
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    user_spring_t *s = malloc(sizeof *s);
    s->anchor = added_small(scene, VEC_ZERO, INFINITY);
    s->bob = added_small(scene, (vector_t){1.0, 0.0}, 1.0);
    s->k = pow(theta / H, 2);
    scene_add_force_creator(scene, user_spring, s, free);
    for (int i = 0; i < steps; i++) scene_tick(scene, H);
    double x = body_get_centroid(s->bob).x, v = body_get_velocity(s->bob).x;
    double energy = 0.5 * v * v + 0.5 * s->k * x * x;
    double start = 0.5 * s->k;
    scene_free(scene);
    return energy / start;
}

/* A force of the user's is taken explicitly: the same spring written as a
 * force creator keeps symplectic Euler's behaviour, bounded below omega h =
 * 2 and growing above. */
static void a_spring_of_the_users_is_explicit(void) {
    CHECK(user_spring_energy(INTEGRATOR_IMPLICIT_EULER, 1.0, 500) ==
          user_spring_energy(INTEGRATOR_SYMPLECTIC_EULER, 1.0, 500));
    CHECK(user_spring_energy(INTEGRATOR_IMPLICIT_EULER, 1.0, 500) < 4.0);
    CHECK(user_spring_energy(INTEGRATOR_IMPLICIT_EULER, 2.5, 100) > 1e10);
}

/* ---- The solve ---- */

/* One step of backward Euler by hand, from the state the scene had: for
 * every free body, m (v' - v) = h (sum of spring forces at x' = x + h v'
 * - gamma v' + m g), read back from the scene after its tick. */
typedef struct {
    int a, b; /* body indices; b < 0: none (drag, or the outside body) */
    double k, gamma;
    body_t *outside; /* a spring's end in no scene */
} link_t;

static void check_backward_euler(scene_t *scene, const link_t *links, size_t count,
                                 double tolerance) {
    size_t n = scene_bodies(scene);
    vector_t *x = calloc(n, sizeof *x), *v = calloc(n, sizeof *v);
    for (size_t i = 0; i < n; i++) {
        x[i] = body_get_centroid(scene_get_body(scene, i));
        v[i] = body_get_velocity(scene_get_body(scene, i));
    }
    scene_tick(scene, H);
    vector_t *force = calloc(n, sizeof *force);
    double largest = 0.0;
    for (size_t l = 0; l < count; l++) {
        const link_t *link = &links[l];
        body_t *a = scene_get_body(scene, (size_t)link->a);
        if (link->outside != NULL) {
            vector_t f = vec_multiply(link->k, vec_subtract(body_get_centroid(link->outside),
                                                            body_get_centroid(a)));
            force[link->a] = vec_add(force[link->a], f);
            largest = fmax(largest, vec_get_length(f));
            continue;
        }
        if (link->b < 0) {
            vector_t f = vec_multiply(-link->gamma, body_get_velocity(a));
            force[link->a] = vec_add(force[link->a], f);
            largest = fmax(largest, vec_get_length(f));
            continue;
        }
        body_t *b = scene_get_body(scene, (size_t)link->b);
        vector_t f = vec_multiply(link->k, vec_subtract(body_get_centroid(b), body_get_centroid(a)));
        force[link->a] = vec_add(force[link->a], f);
        force[link->b] = vec_subtract(force[link->b], f);
        largest = fmax(largest, vec_get_length(f));
    }
    for (size_t i = 0; i < n; i++) {
        body_t *body = scene_get_body(scene, i);
        if (isinf(body_get_mass(body))) continue;
        double m = body_get_mass(body);
        vector_t moved = vec_subtract(body_get_centroid(body), x[i]);
        /* x' = x + h v' */
        CHECK_VEC(moved, H * body_get_velocity(body).x, H * body_get_velocity(body).y, 1e-12);
        vector_t change = vec_multiply(m, vec_subtract(body_get_velocity(body), v[i]));
        vector_t expected = vec_multiply(H, force[i]);
        CHECK_VEC(change, expected.x, expected.y, tolerance * H * largest);
    }
    free(x);
    free(v);
    free(force);
}

/* Loops of springs (the conjugate gradients over the forest) and a tree
 * (the forest alone), stiffnesses from 1 to 1e8 N/m, masses 1e-3 to 10 kg,
 * drag, a duplicate spring, one to an anchor of infinite mass and one to a
 * body that is in no scene: each step solves backward Euler to 1e-9 of the
 * largest force. */
static void each_step_solves_backward_euler_on_loops_and_trees(void) {
    for (int loops = 0; loops < 2; loops++) {
        scene_t *scene = implicit_scene();
        enum { N = 12 };
        for (int i = 0; i < N; i++) {
            double mass = i == 0 ? INFINITY : pow(10.0, -3.0 + 4.0 * ((i * 5) % N) / (N - 1.0));
            body_t *body = added_small(scene, (vector_t){cos(i * 0.5) * (1 + 0.1 * i),
                                                          sin(i * 0.5) * (1 + 0.1 * i)},
                                       mass);
            body_set_velocity(body, (vector_t){0.3 * (i % 3) - 0.2, 0.1 * (i % 5)});
        }
        /* A body the scene does not hold: that end of its spring stays put. */
        body_t *outside = body_init(polygon_make_box((vector_t){5, 5}, 0.1, 0.1), 1.0, GREY);
        link_t links[64];
        size_t count = 0;
        /* A chain from the anchor (body 0): a tree, with a branch to the
         * anchor (held: no loop) and the outside body. */
        for (int i = 1; i < N; i++) {
            links[count++] = (link_t){i - 1, i, pow(10.0, (i * 3) % 9), 0.0, NULL};
        }
        links[count++] = (link_t){0, 6, 1e7, 0.0, NULL};
        links[count++] = (link_t){4, -1, 1e3, 0.0, outside};
        if (loops) {
            links[count++] = (link_t){N - 1, 1, 1e6, 0.0, NULL};
            links[count++] = (link_t){3, 8, 10.0, 0.0, NULL};
            links[count++] = (link_t){2, 9, 1e8, 0.0, NULL};
            links[count++] = (link_t){5, 6, 1e3, 0.0, NULL}; /* beside the chain's own */
        }
        links[count++] = (link_t){3, -1, 0.0, 50.0, NULL};
        links[count++] = (link_t){7, -1, 0.0, 1e6, NULL};
        for (size_t l = 0; l < count; l++) {
            body_t *a = scene_get_body(scene, (size_t)links[l].a);
            if (links[l].outside != NULL) {
                create_spring(scene, links[l].k, a, links[l].outside);
            } else if (links[l].b < 0) {
                create_drag(scene, links[l].gamma, a);
            } else {
                create_spring(scene, links[l].k, a, scene_get_body(scene, (size_t)links[l].b));
            }
        }
        for (int step = 0; step < 5; step++) check_backward_euler(scene, links, count, 1e-9);
        CHECK_VEC(body_get_centroid(outside), 5.0, 5.0, 0.0);
        size_t before = engine_allocation_count(); /* warm: loops and all */
        scene_tick(scene, H);
        CHECK(engine_allocation_count() == before);
        scene_free(scene);
        body_free(outside);
    }
}

/* jacobian.h: a spring's stiffness, k along it and k (1 - L / d) across. */
static void a_springs_jacobian_is_k_along_and_less_across(void) {
    sym2_t s = jacobian_spring_stiffness(7.0, 0.0, (vector_t){3.0, 4.0});
    CHECK(s.xx == 7.0 && s.xy == 0.0 && s.yy == 7.0);
    s = jacobian_spring_stiffness(8.0, 1.0, (vector_t){2.0, 0.0});
    CHECK_NEAR(s.xx, 8.0, 1e-15);
    CHECK_NEAR(s.xy, 0.0, 1e-15);
    CHECK_NEAR(s.yy, 4.0, 1e-15);
    /* Along (3, 4) / 5 at d = 5, L = 1: k u u^T + 0.8 k (I - u u^T). */
    s = jacobian_spring_stiffness(10.0, 1.0, (vector_t){3.0, 4.0});
    CHECK_NEAR(s.xx, 10.0 * 0.36 + 8.0 * 0.64, 1e-13);
    CHECK_NEAR(s.xy, 10.0 * 0.48 - 8.0 * 0.48, 1e-13);
    CHECK_NEAR(s.yy, 10.0 * 0.64 + 8.0 * 0.36, 1e-13);
    /* Compressed (d < L): nothing across, still k along. */
    s = jacobian_spring_stiffness(10.0, 2.0, (vector_t){0.0, 1.0});
    CHECK_NEAR(s.xx, 0.0, 1e-15);
    CHECK_NEAR(s.yy, 10.0, 1e-15);
    /* Coincident ends with a rest length: no direction, no stiffness. */
    s = jacobian_spring_stiffness(10.0, 1.0, VEC_ZERO);
    CHECK(s.xx == 0.0 && s.xy == 0.0 && s.yy == 0.0);
}

/* spring_system.h against a dense solve: a grid of 6 x 6 nodes with 2x2
 * blocks (anisotropic), and a comb of the same nodes (a tree). A tree
 * needs no conjugate-gradient iteration; the grid's 25 loops at most
 * 2 * 25 + 1 in exact arithmetic, here within the code's allowance. With
 * weights over 4 decades and masses of 0.1 to 0.7 kg the answer is the
 * dense one's to 1e-9; over 8 decades and 1e-3 kg (condition number about
 * 1e12, where the two differ by 1e-7) the residual is rounding's:
 * |A x - b| under 1e-15 (|A| |x| + |b|). */
static void dense_solve(double *a, double *b, int n) {
    for (int c = 0; c < n; c++) {
        for (int r = c + 1; r < n; r++) {
            double f = a[r * n + c] / a[c * n + c];
            for (int k = c; k < n; k++) a[r * n + k] -= f * a[c * n + k];
            b[r] -= f * b[c];
        }
    }
    for (int r = n - 1; r >= 0; r--) {
        for (int k = r + 1; k < n; k++) b[r] -= a[r * n + k] * b[k];
        b[r] /= a[r * n + r];
    }
}

static void add_block(double *a, int n, int i, int j, sym2_t m, double sign) {
    a[(2 * i) * n + 2 * j] += sign * m.xx;
    a[(2 * i) * n + 2 * j + 1] += sign * m.xy;
    a[(2 * i + 1) * n + 2 * j] += sign * m.xy;
    a[(2 * i + 1) * n + 2 * j + 1] += sign * m.yy;
}

enum { SIDE = 6, NODES = SIDE * SIDE, DOF = 2 * NODES };

/* Builds the system and its dense copy a, b; returns the number of edges. */
static size_t build_grid(spring_system_t **system, double *a, double *b, bool grid,
                         int decades, double mass) {
    spring_system_begin(system, NODES, 4);
    unsigned seed = 7;
    for (int i = 0; i < NODES; i++) {
        double m = mass * (1 + i % 7);
        sym2_t d = {m, 0.0, m};
        spring_system_add_diagonal(*system, (size_t)i, d);
        add_block(a, DOF, i, i, d, 1.0);
        vector_t rhs = {sin(i), cos(3.0 * i)};
        spring_system_add_rhs(*system, (size_t)i, rhs);
        b[2 * i] = rhs.x, b[2 * i + 1] = rhs.y;
    }
    size_t edges = 0;
    for (int i = 0; i < NODES; i++) {
        int neighbours[2] = {i % SIDE < SIDE - 1 ? i + 1 : -1, i + SIDE < NODES ? i + SIDE : -1};
        for (int k = 0; k < 2; k++) {
            int j = neighbours[k];
            if (j < 0 || (!grid && k == 1 && i % SIDE != 0)) continue; /* the comb: a tree */
            seed = seed * 1103515245u + 12345u;
            double w = pow(10.0, (seed >> 16) % (unsigned)(decades + 1));
            double angle = 0.1 * i + k;
            sym2_t weight = jacobian_spring_stiffness(w, 0.5, (vector_t){cos(angle), sin(angle)});
            spring_system_add_edge(*system, (size_t)i, (size_t)j, weight);
            add_block(a, DOF, i, i, weight, 1.0);
            add_block(a, DOF, j, j, weight, 1.0);
            add_block(a, DOF, i, j, weight, -1.0);
            add_block(a, DOF, j, i, weight, -1.0);
            edges++;
        }
    }
    return edges;
}

static void spring_system_matches_a_dense_solve(void) {
    for (int hard = 0; hard < 2; hard++) {
        for (int grid = 0; grid < 2; grid++) {
            spring_system_t *system = NULL;
            double *a = calloc(DOF * DOF, sizeof *a), *copy = malloc(DOF * DOF * sizeof *a);
            double b[DOF], rhs[DOF];
            size_t edges = build_grid(&system, a, b, grid, hard ? 8 : 4, hard ? 1e-3 : 0.1);
            memcpy(copy, a, DOF * DOF * sizeof *a);
            memcpy(rhs, b, sizeof b);
            vector_t x[NODES];
            size_t iterations = spring_system_solve(system, x);
            size_t loops = edges - (NODES - 1);
            if (grid) {
                CHECK(loops == 25);
                CHECK(iterations >= 1 && iterations <= 2 * (2 * loops + 1) + 8);
            } else {
                CHECK(loops == 0 && iterations == 0);
            }
            dense_solve(a, b, DOF);
            double largest = 0.0, norm_a = 0.0, norm_x = 0.0, norm_b = 0.0, norm_r = 0.0;
            for (int i = 0; i < DOF; i++) largest = fmax(largest, fabs(b[i]));
            for (int r = 0; r < DOF; r++) {
                long double sum = -rhs[r];
                for (int c = 0; c < DOF; c++) {
                    double xc = c % 2 ? x[c / 2].y : x[c / 2].x;
                    sum += (long double)copy[r * DOF + c] * xc;
                    norm_a += copy[r * DOF + c] * copy[r * DOF + c];
                }
                double xr = r % 2 ? x[r / 2].y : x[r / 2].x;
                norm_x += xr * xr;
                norm_b += rhs[r] * rhs[r];
                norm_r += (double)(sum * sum);
            }
            if (hard) {
                CHECK(sqrt(norm_r) < 1e-15 * (sqrt(norm_a) * sqrt(norm_x) + sqrt(norm_b)));
            } else {
                for (int i = 0; i < NODES; i++) {
                    CHECK_NEAR(x[i].x, b[2 * i], 1e-9 * largest);
                    CHECK_NEAR(x[i].y, b[2 * i + 1], 1e-9 * largest);
                }
            }
            free(a);
            free(copy);
            spring_system_free(system);
        }
    }
}

/* ---- Contacts, sleeping, workers ---- */

static double normal_impulse(scene_t *scene) {
    double total = 0.0;
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        const contact_t *c = scene_get_contact(scene, i);
        for (size_t k = 0; k < c->point_count; k++) total += c->normal_impulse[k];
    }
    return total;
}

/* A box held on a floor by a spring to an anchor below it (kept out of
 * contacts), omega h = 0.5 and 100: it rests where it landed and the floor
 * carries the whole load, k d + m g (the contacts meet the box with the
 * mass its spring adds within the step, implicit_euler.h); so does a box
 * that carries a second one on a stiff spring (m1 + m2) g, the second at
 * m2 g / k below the first. */
static void contacts_carry_the_load_of_stiff_springs(void) {
    const double thetas[2] = {0.5, 100.0}, g = 9.81;
    for (int t = 0; t < 2; t++) {
        double k = pow(thetas[t] / H, 2);
        scene_t *scene = implicit_scene();
        scene_set_contacts_enabled(scene, true);
        scene_set_sleeping(scene, false);
        scene_set_gravity(scene, (vector_t){0.0, -g});
        added_box(scene, (vector_t){0.0, -0.5}, 10.0, 0.5, INFINITY);
        body_t *anchor = added_small(scene, (vector_t){0.0, -5.0}, INFINITY);
        body_set_collision_filter(anchor, 2, 0, 0);
        body_t *box = added_box(scene, (vector_t){0.0, 1.5}, 0.5, 0.5, 1.0);
        create_spring(scene, k, anchor, box);
        for (int step = 0; step < 300; step++) scene_tick(scene, H);
        CHECK_NEAR(body_get_centroid(box).y, 0.5, 1e-6);
        CHECK(vec_get_length(body_get_velocity(box)) < 1e-6);
        CHECK_RELATIVE(normal_impulse(scene) / H, k * 5.5 + g, 1e-6);
        scene_free(scene);

        double m1 = 1.0, m2 = 3.0, k2 = pow(thetas[t] / H, 2) * m1 * m2 / (m1 + m2);
        scene = implicit_scene();
        scene_set_contacts_enabled(scene, true);
        scene_set_sleeping(scene, false);
        scene_set_gravity(scene, (vector_t){0.0, -g});
        added_box(scene, (vector_t){0.0, -0.5}, 10.0, 0.5, INFINITY);
        body_t *lower = added_box(scene, (vector_t){0.0, 0.5}, 0.5, 0.5, m1);
        body_t *upper = added_box(scene, (vector_t){0.0, 0.5}, 0.1, 0.1, m2);
        body_set_collision_filter(lower, 1, ~0u, 7);
        body_set_collision_filter(upper, 1, ~0u, 7);
        create_spring(scene, k2, lower, upper);
        for (int step = 0; step < 600; step++) scene_tick(scene, H);
        CHECK_NEAR(body_get_centroid(lower).y, 0.5, 1e-6);
        CHECK_NEAR(body_get_centroid(upper).y - body_get_centroid(lower).y, -m2 * g / k2,
                   1e-6 * m2 * g / k2 + 1e-12);
        CHECK_RELATIVE(normal_impulse(scene) / H, (m1 + m2) * g, 1e-6);
        scene_free(scene);
    }
}

/* A box sliding on a floor under friction mu and drag gamma: while it
 * slides, (m + h gamma) v' = m v - h mu m g, backward Euler with the
 * friction of the whole weight; then it stops. */
static void friction_sees_the_weight_of_a_body_with_drag(void) {
    const double m = 2.0, gamma = 240.0, mu = 0.5, g = 9.81;
    scene_t *scene = implicit_scene();
    scene_set_contacts_enabled(scene, true);
    scene_set_sleeping(scene, false);
    scene_set_gravity(scene, (vector_t){0.0, -g});
    body_t *floor = added_box(scene, (vector_t){0.0, -0.5}, 100.0, 0.5, INFINITY);
    body_set_friction(floor, mu);
    body_t *box = added_box(scene, (vector_t){0.0, 0.5}, 0.5, 0.5, m);
    body_set_friction(box, mu);
    body_set_velocity(box, (vector_t){5.0, 0.0});
    create_drag(scene, gamma, box);
    double v = 5.0;
    for (int step = 0; step < 30; step++) {
        scene_tick(scene, H);
        double expected = (m * v - H * mu * m * g) / (m + H * gamma);
        if (expected > 0.0) {
            CHECK_NEAR(body_get_velocity(box).x, expected, 1e-12);
        } else {
            CHECK_NEAR(body_get_velocity(box).x, 0.0, 1e-3);
        }
        v = body_get_velocity(box).x;
    }
    CHECK(fabs(v) < 1e-6);
    scene_free(scene);
}

/* A box on a stiff spring (omega h = 50) hung from an anchor above is
 * thrown down onto a pile of boxes with drag: every state finite, warm
 * steps allocate nothing, and the same scene on 1 and 3 workers gives the
 * same bytes. */
static void sprung_pile(size_t workers, double *state, bool *finite) {
    scene_t *scene = implicit_scene();
    scene_set_contacts_enabled(scene, true);
    scene_set_sleeping(scene, false);
    scene_set_workers(scene, workers);
    scene_set_gravity(scene, (vector_t){0.0, -9.81});
    added_box(scene, (vector_t){0.0, -0.5}, 20.0, 0.5, INFINITY);
    for (int i = 0; i < 24; i++) {
        body_t *box = added_box(scene, (vector_t){-3.0 + 0.52 * (i % 12), 0.5 + 1.1 * (i / 12)},
                                0.25, 0.5, 1.0);
        create_drag(scene, 0.5, box);
    }
    body_t *anchor = added_small(scene, (vector_t){0.0, 8.0}, INFINITY);
    body_set_collision_filter(anchor, 2, 0, 0);
    body_t *sprung = added_box(scene, (vector_t){0.3, 6.0}, 0.4, 0.4, 2.0);
    create_spring(scene, 2.0 * pow(50.0 / H, 2), anchor, sprung);
    body_set_velocity(sprung, (vector_t){0.0, -30.0});
    *finite = true;
    size_t before = 0;
    for (int step = 0; step < 240; step++) {
        if (step == 200) before = engine_allocation_count();
        scene_tick(scene, H);
        for (size_t i = 0; i < scene_bodies(scene); i++) {
            vector_t x = body_get_centroid(scene_get_body(scene, i));
            *finite &= isfinite(x.x) && isfinite(x.y);
        }
    }
    CHECK(engine_allocation_count() == before); /* warm steps with contacts */
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        vector_t x = body_get_centroid(body), v = body_get_velocity(body);
        double values[4] = {x.x, x.y, v.x, v.y};
        memcpy(state + 4 * i, values, sizeof values);
    }
    scene_free(scene);
}

static void workers_give_the_same_bytes(void) {
    double one[4 * 27], three[4 * 27];
    bool finite_one, finite_three;
    sprung_pile(1, one, &finite_one);
    sprung_pile(3, three, &finite_three);
    CHECK(finite_one && finite_three);
    CHECK(memcmp(one, three, sizeof one) == 0);
}

/* Sleeping: a stack falls asleep while a body on a stiff spring (omega h =
 * 20) swings beside it and settles at its equilibrium; a spring of k = 0
 * from it to the top box (its force is 0, so it wakes nothing) leaves the
 * sleeping box where it is: the step holds it. A push wakes the stack. */
static void a_stack_sleeps_beside_a_stiff_spring(void) {
    const double g = 9.81, k = pow(20.0 / H, 2);
    scene_t *scene = implicit_scene();
    scene_set_contacts_enabled(scene, true);
    scene_set_gravity(scene, (vector_t){0.0, -g});
    added_box(scene, (vector_t){0.0, -0.5}, 20.0, 0.5, INFINITY);
    body_t *boxes[4];
    for (int i = 0; i < 4; i++) {
        boxes[i] = added_box(scene, (vector_t){0.01 * i, 0.5 + 1.02 * i}, 0.5, 0.5, 1.0);
    }
    body_t *anchor = added_small(scene, (vector_t){8.0, 6.0}, INFINITY);
    body_set_collision_filter(anchor, 2, 0, 0);
    body_t *bob = added_small(scene, (vector_t){8.5, 5.0}, 1.0);
    create_spring(scene, k, anchor, bob);
    for (int step = 0; step < 300; step++) scene_tick(scene, H);
    for (int i = 0; i < 4; i++) {
        CHECK(body_is_sleeping(boxes[i]));
        CHECK_NEAR(body_get_centroid(boxes[i]).y, 0.5 + i, 0.02);
    }
    CHECK(!body_is_sleeping(bob));
    CHECK_VEC(body_get_centroid(bob), 8.0, 6.0 - g / k, 1e-12);
    vector_t top = body_get_centroid(boxes[3]);
    create_spring(scene, 0.0, bob, boxes[3]);
    for (int step = 0; step < 60; step++) scene_tick(scene, H);
    CHECK(body_is_sleeping(boxes[3]));
    CHECK_VEC(body_get_centroid(boxes[3]), top.x, top.y, 0.0);
    body_set_velocity(boxes[3], (vector_t){0.5, 0.0});
    scene_tick(scene, H);
    CHECK(!body_is_sleeping(boxes[0]));
    scene_free(scene);
}

TEST_SUITE(implicit_euler,
           TEST_CASE(spring_shrinks_by_one_over_sqrt_one_plus_theta_squared),
           TEST_CASE(a_free_pair_keeps_momentum_and_shrinks_its_relative_motion),
           TEST_CASE(drag_divides_the_velocity_by_one_plus_gamma_h_over_m),
           TEST_CASE(its_order_is_one),
           TEST_CASE(a_spring_with_a_rest_length_is_implicit_too),
           TEST_CASE(a_spring_at_omega_h_100_runs_and_loses_energy),
           TEST_CASE(a_chain_of_stiff_springs_and_mixed_masses_settles),
           TEST_CASE(without_springs_or_drag_it_is_symplectic_euler),
           TEST_CASE(a_spring_of_the_users_is_explicit),
           TEST_CASE(each_step_solves_backward_euler_on_loops_and_trees),
           TEST_CASE(a_springs_jacobian_is_k_along_and_less_across),
           TEST_CASE(spring_system_matches_a_dense_solve),
           TEST_CASE(contacts_carry_the_load_of_stiff_springs),
           TEST_CASE(friction_sees_the_weight_of_a_body_with_drag),
           TEST_CASE(workers_give_the_same_bytes),
           TEST_CASE(a_stack_sleeps_beside_a_stiff_spring));
