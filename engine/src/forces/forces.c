#include "jostle/forces.h"
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include "dynamics/body_private.h"
#include "base/check.h"
#include "forces/collision_event.h"
#include "forces/forces_private.h"
#include "dynamics/integrator.h"
#include "base/memory.h"
#include "scene/scene_private.h"

/* Below this distance (m) Newtonian gravity is left out: the force would be
 * unbounded and its direction undefined. */
static const double GRAVITY_MIN_DISTANCE = 1e-9;

typedef struct {
    double constant;
    body_t *body1;
    body_t *body2;
    /* For the message when the force does not fit a double. */
    scene_t *scene;
    double rest_length; /* m, a spring's; 0 for every other force */
} pair_aux_t;

/* A force that does not fit a double stops the tick here rather than in
 * body_add_force, which the user did not call: scene_tick is named, with the
 * force and the likely cause. */
#if defined(__GNUC__)
__attribute__((noreturn, cold, format(printf, 1, 2)))
#endif
static void fail_force(const char *format, ...) {
    char message[1024];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof message, format, args);
    va_end(args);
    engine_fail("scene_tick", "force stage: %s", message);
}

/* "body 3", by the body's index in the scene. */
typedef struct {
    char text[40];
} body_name_t;

static body_name_t body_name(const scene_t *scene, const body_t *body) {
    body_name_t name;
    size_t index = scene_body_index(scene, body);
    if (index == SIZE_MAX) {
        snprintf(name.text, sizeof name.text, "a body not in the scene");
    } else {
        snprintf(name.text, sizeof name.text, "body %zu", index);
    }
    return name;
}

static list_t *bodies_list(body_t *body1, body_t *body2) {
    list_t *bodies = list_init(2, NULL);
    list_add(bodies, body1);
    if (body2 != NULL) list_add(bodies, body2);
    return bodies;
}

/* Bodies of another scene are refused: that scene would free them while
 * this one's force creator still reads them. */
static void claim_pair(scene_t *scene, body_t *body1, body_t *body2, const char *function) {
    scene_claim_body(scene, body1, "body1", function);
    scene_claim_body(scene, body2, "body2", function);
}

static double spring_stiffness(const void *aux);
static void explain_spring(const void *aux, char *message, size_t size);
static bool spring_jacobian(const void *aux, force_jacobian_t *jacobian);
static bool drag_jacobian(const void *aux, force_jacobian_t *jacobian);
static void spring(void *data);
static void spring_with_length(void *data);
static void drag(void *data);
static void newtonian_gravity(void *data);

/* The bodies were claimed (claim_pair); a spring also tells the scene how
 * stiff it is, for the message of a tick that overflows; springs and
 * gravity, that they read only centroids and masses. */
static void add_pair_aux(scene_t *scene, force_creator_t forcer, pair_aux_t value) {
    pair_aux_t *aux = memory_alloc(sizeof(pair_aux_t));
    *aux = value;
    bool is_spring = forcer == spring || forcer == spring_with_length;
    scene_add_creator(scene, &(scene_creator_t){
                                 .forcer = forcer,
                                 .aux = aux,
                                 .freer = memory_free,
                                 .bodies = bodies_list(value.body1, value.body2),
                                 .stiffness = is_spring ? spring_stiffness : NULL,
                                 .explain = is_spring ? explain_spring : NULL,
                                 .jacobian = is_spring          ? spring_jacobian
                                             : forcer == drag ? drag_jacobian
                                                              : NULL,
                                 .positional = is_spring || forcer == newtonian_gravity,
                             });
}

static void add_pair_force_creator(scene_t *scene, force_creator_t forcer, double constant,
                                   body_t *body1, body_t *body2) {
    add_pair_aux(scene, forcer, (pair_aux_t){constant, body1, body2, scene, 0.0});
}

void forces_gravity_between(scene_t *scene, double G, body_t *body1, body_t *body2) {
    vector_t r = vec_subtract(body2->centroid, body1->centroid);
    double distance = vec_get_length(r);
    if (distance < GRAVITY_MIN_DISTANCE) return;
    double m1 = body1->mass, m2 = body2->mass;
    double magnitude = G * m1 * m2 / (distance * distance);
    vector_t force = vec_multiply(magnitude / distance, r);
    if (!vec_is_finite(force)) {
        /* An INFINITY mass makes it inf or NaN: the pull would be infinite
         * and is left out (documented), tested here off the common path. */
        if (isinf(m1) || isinf(m2)) return;
        /* G m1 m2 overflows long before the force does for huge masses. */
        double scaled = G * (m1 / distance) * (m2 / distance);
        force = vec_multiply(scaled, vec_multiply(1.0 / distance, r));
    }
    if (!vec_is_finite(force)) {
        fail_force("newtonian gravity between %s and %s (G = %g N m^2/kg^2): force is not "
                   "finite (masses %g kg and %g kg, distance %g m); likely cause: the bodies "
                   "came too close for their masses: G m1 m2 / r^2 exceeds the largest double",
                   body_name(scene, body1).text, body_name(scene, body2).text, G, m1, m2,
                   distance);
    }
    body_push(body1, force);
    body_push(body2, vec_negate(force));
}

static void newtonian_gravity(void *data) {
    pair_aux_t *aux = data;
    forces_gravity_between(aux->scene, aux->constant, aux->body1, aux->body2);
}

void create_newtonian_gravity(scene_t *scene, double G, body_t *body1, body_t *body2) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(body1);
    REQUIRE_NOT_NULL(body2);
    REQUIRE(isfinite(G) && G >= 0.0, "G must be finite and >= 0 (got %g)", G);
    claim_pair(scene, body1, body2, __func__);
    add_pair_force_creator(scene, newtonian_gravity, G, body1, body2);
}

/* m1 m2 / (m1 + m2), or the finite mass when the other is INFINITY. */
static double reduced_mass(const body_t *body1, const body_t *body2) {
    if (isinf(body1->mass)) return body2->mass;
    if (isinf(body2->mass)) return body1->mass;
    /* Not m1 m2 / (m1 + m2): that product overflows long before the reduced
     * mass does. */
    return body1->mass * (body2->mass / (body1->mass + body2->mass));
}

/* Writes the spring's stability at the tick's dt; returns whether it gains
 * energy there. */
static bool explain_spring_stability(const pair_aux_t *aux, char *message, size_t size) {
    double mass = reduced_mass(aux->body1, aux->body2);
    double omega = sqrt(aux->constant / mass);
    double dt = scene_step_dt(aux->scene);
    integrator_t integrator = scene_get_integrator(aux->scene);
    double limit = 2.0 / omega;
    if (!(omega > 0.0)) {
        snprintf(message, size, "neither of its bodies can move");
        return false;
    }
    char growth[32];
    double factor = integrator_oscillator_growth(integrator, omega * dt);
    if (isfinite(factor)) {
        snprintf(growth, sizeof growth, "%.3g", factor);
    } else {
        snprintf(growth, sizeof growth, "more than %g", DBL_MAX);
    }
    const char *name = integrator_get_name(integrator);
    double theta_limit = integrator_get_stability_limit(integrator);
    if (theta_limit == 0.0) {
        snprintf(message, size,
                 "with the %s integrator a spring gains energy at any dt, this one by a factor "
                 "of %s per step at dt = %g s (m = %g kg, omega = sqrt(k/m) = %g rad/s); "
                 "INTEGRATOR_SYMPLECTIC_EULER keeps it bounded for dt < 2 sqrt(m/k) = %g s, "
                 "INTEGRATOR_IMPLICIT_EULER at any dt (it damps the spring)",
                 name, growth, dt, mass, omega, limit);
        return true;
    }
    if (isinf(theta_limit)) {
        snprintf(message, size,
                 "the %s integrator is stable for it at any dt (its energy falls by a factor "
                 "of %s per step at dt = %g s, m = %g kg)",
                 name, growth, dt, mass);
        return false;
    }
    limit = theta_limit / omega;
    if (omega * dt >= theta_limit) {
        snprintf(message, size,
                 "dt = %g s is above the stability limit of the %s integrator for it, "
                 "dt < %.4g sqrt(m/k) = %g s (m = %g kg): its energy grows by a factor of %s "
                 "per step; INTEGRATOR_IMPLICIT_EULER is stable for it at any dt (it damps "
                 "the spring)",
                 dt, name, theta_limit, limit, mass, growth);
        return true;
    }
    snprintf(message, size,
             "dt = %g s is within the %s integrator's limit for it alone, "
             "dt < %.4g sqrt(m/k) = %g s (m = %g kg), which springs sharing a body lower",
             dt, name, theta_limit, limit, mass);
    return false;
}

static int describe_spring(const pair_aux_t *aux, char *message, size_t size) {
    if (aux->rest_length > 0.0) {
        return snprintf(message, size, "spring between %s and %s (k = %g N/m, rest length %g m)",
                        body_name(aux->scene, aux->body1).text,
                        body_name(aux->scene, aux->body2).text, aux->constant,
                        aux->rest_length);
    }
    return snprintf(message, size, "spring between %s and %s (k = %g N/m)",
                    body_name(aux->scene, aux->body1).text,
                    body_name(aux->scene, aux->body2).text, aux->constant);
}

static double spring_stiffness(const void *data) {
    const pair_aux_t *aux = data;
    if (isinf(aux->body1->mass) && isinf(aux->body2->mass)) return 0.0;
    return sqrt(aux->constant / reduced_mass(aux->body1, aux->body2));
}

static void explain_spring(const void *data, char *message, size_t size) {
    const pair_aux_t *aux = data;
    int written = describe_spring(aux, message, size);
    if (written < 0 || (size_t)written + 2 >= size) return;
    message[written] = ':';
    message[written + 1] = ' ';
    explain_spring_stability(aux, message + written + 2, size - (size_t)written - 2);
}

#if defined(__GNUC__)
__attribute__((noreturn, cold))
#endif
static void fail_spring(const pair_aux_t *aux, vector_t stretch) {
    char spring_text[128], stability[512];
    describe_spring(aux, spring_text, sizeof spring_text);
    if (explain_spring_stability(aux, stability, sizeof stability)) {
        fail_force("%s: force is not finite (stretch (%g, %g) m); likely cause: the spring is "
                   "unstable: %s",
                   spring_text, stretch.x, stretch.y, stability);
    }
    fail_force("%s: force is not finite (stretch (%g, %g) m); likely cause: the bodies are too "
               "far apart for k: k |stretch| exceeds the largest double (%s)",
               spring_text, stretch.x, stretch.y, stability);
}

static void spring(void *data) {
    pair_aux_t *aux = data;
    vector_t stretch = vec_subtract(aux->body2->centroid, aux->body1->centroid);
    vector_t force = vec_multiply(aux->constant, stretch);
    if (!vec_is_finite(force)) fail_spring(aux, stretch);
    body_push(aux->body1, force);
    body_push(aux->body2, vec_negate(force));
}

void create_spring(scene_t *scene, double k, body_t *body1, body_t *body2) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(body1);
    REQUIRE_NOT_NULL(body2);
    REQUIRE(isfinite(k) && k >= 0.0, "k must be finite and >= 0 (got %g)", k);
    REQUIRE(body1 != body2, "a spring cannot join a body to itself");
    claim_pair(scene, body1, body2, __func__);
    add_pair_force_creator(scene, spring, k, body1, body2);
}

/* k (d - L) along the unit vector from body1 to body2, d the distance. */
static void spring_with_length(void *data) {
    pair_aux_t *aux = data;
    vector_t between = vec_subtract(aux->body2->centroid, aux->body1->centroid);
    double distance = vec_get_length(between);
    vector_t direction = vec_multiply(1.0 / distance, between);
    /* Coincident centroids (or so close that 1 / d overflows): no direction
     * to push along; left out, as documented. */
    if (!vec_is_finite(direction)) return;
    vector_t stretch = vec_multiply(distance - aux->rest_length, direction);
    vector_t force = vec_multiply(aux->constant, stretch);
    if (!vec_is_finite(force)) fail_spring(aux, stretch);
    body_push(aux->body1, force);
    body_push(aux->body2, vec_negate(force));
}

void create_spring_with_length(scene_t *scene, double k, double rest_length, body_t *body1,
                               body_t *body2) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(body1);
    REQUIRE_NOT_NULL(body2);
    REQUIRE(isfinite(k) && k >= 0.0, "k must be finite and >= 0 (got %g)", k);
    REQUIRE(isfinite(rest_length) && rest_length >= 0.0,
            "rest_length must be finite and >= 0 (got %g)", rest_length);
    REQUIRE(body1 != body2, "a spring cannot join a body to itself");
    claim_pair(scene, body1, body2, __func__);
    add_pair_aux(scene, spring_with_length, (pair_aux_t){k, body1, body2, scene, rest_length});
}

#if defined(__GNUC__)
__attribute__((noreturn, cold))
#endif
static void fail_drag(const pair_aux_t *aux) {
    const body_t *body = aux->body1;
    double dt = scene_step_dt(aux->scene);
    integrator_t integrator = scene_get_integrator(aux->scene);
    double z = aux->constant * dt / body->mass, limit = integrator_get_drag_limit(integrator);
    char cause[320];
    if (z > limit) {
        snprintf(cause, sizeof cause,
                 "the drag is unstable at dt = %g s: gamma dt / m = %g is above the %s "
                 "integrator's limit, which needs dt < %g m / gamma = %g s (m = %g kg); "
                 "INTEGRATOR_IMPLICIT_EULER is stable for it at any dt",
                 dt, z, integrator_get_name(integrator), limit,
                 limit * body->mass / aux->constant, body->mass);
    } else {
        snprintf(cause, sizeof cause, "the velocity is too large for gamma");
    }
    fail_force("drag on %s (gamma = %g kg/s): force is not finite (velocity (%g, %g) m/s); "
               "likely cause: %s",
               body_name(aux->scene, body).text, aux->constant, body->velocity.x,
               body->velocity.y, cause);
}

static void drag(void *data) {
    pair_aux_t *aux = data;
    vector_t force = vec_multiply(-aux->constant, aux->body1->velocity);
    if (!vec_is_finite(force)) fail_drag(aux);
    body_push(aux->body1, force);
}

/* The Jacobians implicit Euler reads (jacobian.h): a spring's stiffness at
 * its present stretch, drag's damping. */
static bool spring_jacobian(const void *data, force_jacobian_t *jacobian) {
    const pair_aux_t *aux = data;
    vector_t between = vec_subtract(aux->body2->centroid, aux->body1->centroid);
    sym2_t stiffness = jacobian_spring_stiffness(aux->constant, aux->rest_length, between);
    *jacobian = (force_jacobian_t){aux->body1, aux->body2, stiffness, {0.0, 0.0, 0.0}};
    return true;
}

static bool drag_jacobian(const void *data, force_jacobian_t *jacobian) {
    const pair_aux_t *aux = data;
    double gamma = aux->constant;
    *jacobian = (force_jacobian_t){aux->body1, NULL, {0.0, 0.0, 0.0}, {gamma, 0.0, gamma}};
    return true;
}

void create_drag(scene_t *scene, double gamma, body_t *body) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(body);
    REQUIRE(isfinite(gamma) && gamma >= 0.0, "gamma must be finite and >= 0 (got %g)", gamma);
    scene_claim_body(scene, body, "body", __func__);
    add_pair_force_creator(scene, drag, gamma, body, NULL);
}

typedef struct {
    collision_rule_t rule;
    body_t *body1;
    body_t *body2;
    collision_state_t state;
} collision_aux_t;

static void collision_force_creator(void *data) {
    collision_aux_t *aux = data;
    collision_event_read(&aux->rule, aux->body1, aux->body2, &aux->state);
}

void create_collision(scene_t *scene, body_t *body1, body_t *body2,
                      collision_handler_t handler, void *aux, double force_const) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(body1);
    REQUIRE_NOT_NULL(body2);
    REQUIRE_NOT_NULL(handler);
    REQUIRE(body1 != body2, "a body cannot collide with itself");
    claim_pair(scene, body1, body2, __func__);
    collision_aux_t *collision = memory_alloc(sizeof(collision_aux_t));
    *collision = (collision_aux_t){{scene, handler, aux, force_const}, body1, body2, {0}};
    scene_creator_t creator = {.forcer = collision_force_creator, .aux = collision,
                               .freer = memory_free, .bodies = bodies_list(body1, body2),
                               .event = true};
    scene_add_creator(scene, &creator);
}

void destructive_collision_handler(body_t *body1, body_t *body2, vector_t axis, void *aux,
                                   double force_const) {
    (void)axis, (void)aux, (void)force_const;
    body_remove(body1);
    body_remove(body2);
}

void create_destructive_collision(scene_t *scene, body_t *body1, body_t *body2) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(body1);
    REQUIRE_NOT_NULL(body2);
    REQUIRE(body1 != body2, "a body cannot collide with itself");
    claim_pair(scene, body1, body2, __func__);
    create_collision(scene, body1, body2, destructive_collision_handler, NULL, 0.0);
}

void physics_collision_handler(body_t *body1, body_t *body2, vector_t axis, void *aux,
                               double force_const) {
    (void)aux;
    REQUIRE_NOT_NULL(body1);
    REQUIRE_NOT_NULL(body2);
    REQUIRE(isfinite(force_const) && force_const >= 0.0,
            "elasticity must be finite and >= 0 (got %g)", force_const);
    if (isinf(body1->mass) && isinf(body2->mass)) return; /* neither can move */
    double mu = reduced_mass(body1, body2);
    /* The velocities as this tick's impulses left them: a body that meets
     * two others in one tick bounces off each in turn, not twice from its
     * old velocity (which added energy: a ball between two pegs). */
    double u1 = vec_dot(body_velocity_after_impulses(body1), axis);
    double u2 = vec_dot(body_velocity_after_impulses(body2), axis);
    if (u1 - u2 <= 0.0) return; /* already parting along the axis */
    vector_t impulse = vec_multiply(mu * (1.0 + force_const) * (u2 - u1), axis);
    /* Checked here so that the message names this function, not
     * body_add_impulse. */
    REQUIRE(vec_is_finite(impulse),
            "impulse is not finite (reduced mass %g kg, closing speed %g m/s, elasticity %g)",
            mu, u1 - u2, force_const);
    body_add_impulse(body1, impulse);
    body_add_impulse(body2, vec_negate(impulse));
}

void create_physics_collision(scene_t *scene, body_t *body1, body_t *body2, double elasticity) {
    REQUIRE_NOT_NULL(scene);
    REQUIRE_NOT_NULL(body1);
    REQUIRE_NOT_NULL(body2);
    REQUIRE(body1 != body2, "a body cannot collide with itself");
    REQUIRE(isfinite(elasticity) && elasticity >= 0.0,
            "elasticity must be finite and >= 0 (got %g)", elasticity);
    claim_pair(scene, body1, body2, __func__);
    create_collision(scene, body1, body2, physics_collision_handler, NULL, elasticity);
}
