/* scene.h: bodies, force creators, the tick's order, the removal timeline,
 * ownership, gravity and the integrators. */
#include <stdlib.h>
#include "jostle/jostle.h"
#include "test.h"


static const rgb_color_t GREY = {0.5, 0.5, 0.5};


/* Bodies carry an int tag as info; freeing one counts it by tag. */
enum { MAX_TAGS = 16 };
static int info_frees[MAX_TAGS];
static void free_tag(void *info) {
    info_frees[*(int *)info]++;
    free(info);
}

static body_t *tagged_box(int tag, vector_t center, double mass) {
    int *info = malloc(sizeof *info);
    *info = tag;
    return body_init_with_info(polygon_make_box(center, 0.5, 0.5), mass, GREY, info, free_tag);
}

static int tag_of(body_t *body) {
    return *(int *)body_get_info(body);
}

/* A force creator that counts its calls and checks it is not called after
 * its aux was freed (AddressSanitizer would catch the read otherwise). */
typedef struct {
    int id;
    int calls;
    body_t *body; /* optional: touched on each call and in the freer */
} spy_t;

static int aux_frees[MAX_TAGS];
static int call_log[64];
static size_t call_log_length = 0;

static void spy_force(void *aux) {
    spy_t *spy = aux;
    spy->calls++;
    if (call_log_length < 64) call_log[call_log_length++] = spy->id;
    if (spy->body != NULL) (void)body_get_mass(spy->body); /* must still be alive */
}

static void spy_free(void *aux) {
    spy_t *spy = aux;
    aux_frees[spy->id]++;
    /* A freer may still look at the bodies of its creator: the scene frees
     * force creators before bodies. */
    if (spy->body != NULL) (void)body_is_removed(spy->body);
    free(spy);
}

static spy_t *new_spy(int id, body_t *body) {
    spy_t *spy = calloc(1, sizeof *spy);
    spy->id = id;
    spy->body = body;
    return spy;
}

static list_t *bodies_of(body_t *a, body_t *b) {
    list_t *list = list_init(2, NULL);
    if (a != NULL) list_add(list, a);
    if (b != NULL) list_add(list, b);
    return list;
}

static void init_is_empty_with_documented_defaults(void) {
    scene_t *scene = scene_init();
    CHECK(scene_bodies(scene) == 0);
    CHECK_VEC(scene_get_gravity(scene), 0, 0, 0);
    CHECK(scene_get_integrator(scene) == INTEGRATOR_SEED);
    CHECK(scene_contact_count(scene) == 0);
    scene_tick(scene, 0.1); /* an empty scene ticks */
    CHECK(scene_bodies(scene) == 0);
    scene_stats_t stats = scene_get_stats(scene);
    CHECK(stats.removed_bodies == 0);
    scene_free(scene);
    CHECK(test_no_leaks());
}

static void bodies_are_kept_in_the_order_added(void) {
    scene_t *scene = scene_init();
    body_t *bodies[5];
    for (int i = 0; i < 5; i++) {
        bodies[i] = tagged_box(i, (vector_t){i, 0}, 1.0);
        scene_add_body(scene, bodies[i]);
        CHECK(scene_bodies(scene) == (size_t)i + 1);
    }
    for (size_t i = 0; i < 5; i++) CHECK(scene_get_body(scene, i) == bodies[i]);
    scene_free(scene);
}

static void free_releases_bodies_and_aux_with_their_freers(void) {
    scene_t *scene = scene_init();
    body_t *a = tagged_box(1, VEC_ZERO, 1.0), *b = tagged_box(2, (vector_t){3, 0}, 1.0);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    scene_add_bodies_force_creator(scene, spy_force, new_spy(3, a), bodies_of(a, b), spy_free);
    scene_add_force_creator(scene, spy_force, new_spy(4, NULL), spy_free);
    spy_t not_owned = {5, 0, NULL};
    scene_add_force_creator(scene, spy_force, &not_owned, NULL); /* no freer: not freed */
    create_spring(scene, 1.0, a, b);
    create_drag(scene, 0.5, b);
    scene_tick(scene, 0.01);
    body_remove(a); /* marked, not yet reaped: still freed exactly once */
    scene_free(scene);
    CHECK(info_frees[1] == 1 && info_frees[2] == 1);
    CHECK(aux_frees[3] == 1 && aux_frees[4] == 1);
    CHECK(aux_frees[5] == 0 && not_owned.calls == 1);
    CHECK(test_no_leaks());
}

static void tick_runs_force_creators_in_order_then_moves_bodies(void) {
    scene_t *scene = scene_init();
    body_t *body = tagged_box(0, VEC_ZERO, 2.0);
    scene_add_body(scene, body);
    spy_t *first = new_spy(1, body), *second = new_spy(2, NULL), *third = new_spy(3, body);
    scene_add_bodies_force_creator(scene, spy_force, first, bodies_of(body, NULL), spy_free);
    scene_add_force_creator(scene, spy_force, second, spy_free);
    scene_add_bodies_force_creator(scene, spy_force, third, bodies_of(body, NULL), spy_free);
    scene_tick(scene, 0.1);
    scene_tick(scene, 0.1);
    CHECK(call_log_length == 6);
    const int expected[6] = {1, 2, 3, 1, 2, 3};
    for (size_t i = 0; i < 6 && i < call_log_length; i++) CHECK(call_log[i] == expected[i]);
    scene_free(scene);
}

/* Adds a constant force and records where the body was when called. */
typedef struct {
    body_t *body;
    vector_t force;
    vector_t seen[4];
    int calls;
} push_t;

static void push(void *aux) {
    push_t *p = aux;
    if (p->calls < 4) p->seen[p->calls] = body_get_centroid(p->body);
    p->calls++;
    body_add_force(p->body, p->force);
}

static void forces_apply_in_the_same_tick_and_are_cleared(void) {
    /* The force creator runs before the bodies move: it sees the pose of
     * the end of the previous tick, and its force moves the body in this
     * one by the seed scheme. */
    scene_t *scene = scene_init();
    body_t *body = tagged_box(0, (vector_t){1, 1}, 2.0);
    scene_add_body(scene, body);
    push_t p = {body, {4, 0}, {{0, 0}}, 0};
    scene_add_bodies_force_creator(scene, push, &p, bodies_of(body, NULL), NULL);
    const double dt = 0.5;
    scene_tick(scene, dt);
    CHECK_VEC(p.seen[0], 1, 1, 0);
    CHECK_VEC(body_get_velocity(body), 2 * dt, 0, 1e-15); /* F / m dt */
    CHECK_VEC(body_get_centroid(body), 1 + dt * (0 + 1.0) / 2, 1, 1e-15);
    scene_tick(scene, dt);
    CHECK_VEC(p.seen[1], 1.25, 1, 1e-15);
    CHECK_VEC(body_get_velocity(body), 2.0, 0, 1e-15); /* not 3: cleared each tick */
    scene_free(scene);
}

static void removal_is_deferred_to_the_end_of_the_next_tick(void) {
    scene_t *scene = scene_init();
    body_t *bodies[5];
    for (int i = 0; i < 5; i++) {
        bodies[i] = tagged_box(i, (vector_t){2.0 * i, 0}, 1.0);
        body_set_velocity(bodies[i], (vector_t){1, 0});
        scene_add_body(scene, bodies[i]);
    }
    body_remove(bodies[0]);
    body_remove(bodies[2]);
    body_remove(bodies[2]); /* idempotent */
    body_remove(bodies[4]);
    /* Only marked: still counted, still returned, nothing freed. */
    CHECK(scene_bodies(scene) == 5);
    CHECK(scene_get_body(scene, 2) == bodies[2]);
    CHECK(body_is_removed(scene_get_body(scene, 0)));
    CHECK(!body_is_removed(scene_get_body(scene, 1)));
    CHECK(info_frees[0] + info_frees[2] + info_frees[4] == 0);
    scene_tick(scene, 0.1);
    /* Reaped at the end of that tick, each freed once with its info; the
     * others keep their order and moved. */
    CHECK(scene_bodies(scene) == 2);
    CHECK(tag_of(scene_get_body(scene, 0)) == 1);
    CHECK(tag_of(scene_get_body(scene, 1)) == 3);
    CHECK(info_frees[0] == 1 && info_frees[2] == 1 && info_frees[4] == 1);
    CHECK(info_frees[1] == 0 && info_frees[3] == 0);
    CHECK(scene_get_stats(scene).removed_bodies == 3);
    CHECK_NEAR(body_get_centroid(scene_get_body(scene, 0)).x, 2.1, 1e-15);
    scene_tick(scene, 0.1);
    CHECK(scene_bodies(scene) == 2);
    CHECK(scene_get_stats(scene).removed_bodies == 0);
    scene_free(scene);
    CHECK(info_frees[1] == 1 && info_frees[3] == 1 && info_frees[0] == 1);
    CHECK(test_no_leaks());
}

static void deprecated_scene_remove_body_only_marks(void) {
    scene_t *scene = scene_init();
    for (int i = 0; i < 3; i++) scene_add_body(scene, tagged_box(i, (vector_t){i, 0}, 1.0));
    body_t *middle = scene_get_body(scene, 1);
    scene_remove_body(scene, 1);
    CHECK(body_is_removed(middle));
    CHECK(scene_bodies(scene) == 3);
    CHECK(scene_get_body(scene, 1) == middle);
    scene_remove_body(scene, 1); /* still idempotent */
    body_remove(middle);
    CHECK(info_frees[1] == 0);
    scene_tick(scene, 0.1);
    CHECK(scene_bodies(scene) == 2);
    CHECK(tag_of(scene_get_body(scene, 0)) == 0 && tag_of(scene_get_body(scene, 1)) == 2);
    CHECK(info_frees[1] == 1);
    scene_free(scene);
}

static void force_creators_of_a_removed_body_are_dropped_and_freed(void) {
    scene_t *scene = scene_init();
    body_t *a = tagged_box(0, VEC_ZERO, 1.0), *b = tagged_box(1, (vector_t){3, 0}, 1.0),
           *c = tagged_box(2, (vector_t){6, 0}, 1.0);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    scene_add_body(scene, c);
    spy_t *on_b = new_spy(1, b);       /* depends on b alone */
    spy_t *on_a_and_b = new_spy(2, a); /* depends on a and b */
    spy_t *on_c = new_spy(3, c);       /* depends on c: kept */
    spy_t *on_none = new_spy(4, NULL); /* deprecated, no bodies: kept */
    scene_add_bodies_force_creator(scene, spy_force, on_b, bodies_of(b, NULL), spy_free);
    scene_add_bodies_force_creator(scene, spy_force, on_a_and_b, bodies_of(a, b), spy_free);
    scene_add_bodies_force_creator(scene, spy_force, on_c, bodies_of(c, NULL), spy_free);
    scene_add_force_creator(scene, spy_force, on_none, spy_free);
    create_spring(scene, 2.0, b, c); /* its own aux, freed with it */
    scene_tick(scene, 0.01);
    body_remove(b);
    CHECK(aux_frees[1] == 0 && aux_frees[2] == 0); /* only marked */
    call_log_length = 0;
    scene_tick(scene, 0.01);
    /* Still called in the reaping tick (stage 1 runs before stage 4). */
    CHECK(call_log_length == 4);
    CHECK(call_log[0] == 1 && call_log[1] == 2 && call_log[2] == 3 && call_log[3] == 4);
    /* Dropped in that same tick, aux freed once; the others untouched. */
    CHECK(aux_frees[1] == 1 && aux_frees[2] == 1);
    CHECK(aux_frees[3] == 0 && aux_frees[4] == 0);
    CHECK(info_frees[1] == 1 && info_frees[0] == 0 && info_frees[2] == 0);
    CHECK(scene_bodies(scene) == 2);
    /* Never called again (their aux is freed: AddressSanitizer would stop
     * a call); the survivors keep running, a (not removed) survives. */
    int c_calls = on_c->calls, none_calls = on_none->calls;
    for (int i = 0; i < 3; i++) scene_tick(scene, 0.01);
    CHECK(on_c->calls == c_calls + 3 && on_none->calls == none_calls + 3);
    CHECK(body_get_mass(a) == 1.0);
    /* c feels no spring any more: its velocity stays. */
    vector_t v = body_get_velocity(c);
    scene_tick(scene, 0.01);
    CHECK_VEC(body_get_velocity(c), v.x, v.y, 0);
    scene_free(scene);
    CHECK(aux_frees[3] == 1 && aux_frees[4] == 1);
    CHECK(test_no_leaks());
}

/* A freer that would free bodies if the scene let it: the bodies list of a
 * force creator must never free them. */
static int body_list_frees = 0;
static void freeing_body_freer(void *body) {
    body_list_frees++;
    body_free(body);
}

static void bodies_list_never_frees_the_bodies(void) {
    scene_t *scene = scene_init();
    body_t *a = tagged_box(0, VEC_ZERO, 1.0), *b = tagged_box(1, (vector_t){2, 0}, 1.0);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    list_t *dropped_list = list_init(2, freeing_body_freer);
    list_add(dropped_list, a);
    list_add(dropped_list, b);
    scene_add_bodies_force_creator(scene, spy_force, new_spy(1, NULL), dropped_list, spy_free);
    list_t *kept_list = list_init(1, freeing_body_freer);
    list_add(kept_list, b);
    scene_add_bodies_force_creator(scene, spy_force, new_spy(2, NULL), kept_list, spy_free);
    body_remove(a);
    scene_tick(scene, 0.1); /* drops the first force creator and its list */
    CHECK(body_list_frees == 0);
    CHECK(aux_frees[1] == 1);
    CHECK(body_get_mass(b) == 1.0); /* b alive */
    scene_free(scene);              /* frees the second list, and b once */
    CHECK(body_list_frees == 0);
    CHECK(info_frees[0] == 1 && info_frees[1] == 1);
    CHECK(test_no_leaks());
}

/* Removes its body when called on the given tick. */
typedef struct {
    body_t *body;
    int countdown;
} remover_t;

static void remove_when_due(void *aux) {
    remover_t *r = aux;
    if (--r->countdown == 0) body_remove(r->body);
}

static void body_removed_during_a_tick_is_reaped_at_its_end(void) {
    /* A force creator (like a destructive collision) marks a body during
     * stage 1: the same tick reaps it, after every force creator ran. */
    scene_t *scene = scene_init();
    body_t *a = tagged_box(0, VEC_ZERO, 1.0), *b = tagged_box(1, (vector_t){2, 0}, 1.0);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    remover_t remover = {a, 2};
    scene_add_bodies_force_creator(scene, remove_when_due, &remover, bodies_of(a, NULL), NULL);
    spy_t *later = new_spy(1, a); /* runs after the remover, in the same tick */
    scene_add_bodies_force_creator(scene, spy_force, later, bodies_of(a, NULL), spy_free);
    scene_tick(scene, 0.1);
    CHECK(scene_bodies(scene) == 2);
    scene_tick(scene, 0.1);
    CHECK(scene_bodies(scene) == 1);
    CHECK(scene_get_body(scene, 0) == b);
    CHECK(info_frees[0] == 1 && aux_frees[1] == 1);
    scene_tick(scene, 0.1); /* neither creator runs again */
    scene_free(scene);
    CHECK(test_no_leaks());
}

/* Marks its body removed on every call (a force creator that must not run
 * in a zero step). */
static void remove_on_call(void *aux) {
    body_remove(aux);
}

static void zero_dt_only_reaps_removed_bodies(void) {
    /* dt = 0 runs no force creator, no world contact, no integration: it
     * frees the marked bodies (and their force creators) and clears the
     * record. */
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0, -9.8});
    scene_set_contacts_enabled(scene, true);
    body_t *a = tagged_box(0, (vector_t){1, 2}, 2.0);
    body_t *b = tagged_box(1, (vector_t){20, 0}, 1.0), *c = tagged_box(2, (vector_t){20.5, 0}, 1.0);
    body_t *doomed = tagged_box(3, (vector_t){10, 0}, 1.0);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    scene_add_body(scene, c); /* overlaps b: contacts would push them apart */
    scene_add_body(scene, doomed);
    create_physics_collision(scene, b, c, 1.0);
    spy_t *spy = new_spy(1, a);
    scene_add_bodies_force_creator(scene, spy_force, spy, bodies_of(a, NULL), spy_free);
    scene_add_bodies_force_creator(scene, spy_force, new_spy(2, doomed), bodies_of(doomed, NULL),
                                   spy_free);
    scene_add_bodies_force_creator(scene, remove_on_call, c, bodies_of(c, NULL), NULL);
    body_set_velocity(a, (vector_t){3, -1});
    body_set_angular_velocity(a, 0.5);
    body_add_force(a, (vector_t){4, 0});
    body_add_impulse(a, (vector_t){0, 2});
    body_remove(doomed);

    scene_tick(scene, 0.0);
    CHECK(spy->calls == 0 && call_log_length == 0);
    CHECK(!body_is_removed(c)); /* remove_on_call did not run */
    CHECK_VEC(body_get_centroid(a), 1, 2, 0);
    CHECK_VEC(body_get_velocity(a), 3, -1, 0);
    CHECK(body_get_angular_velocity(a) == 0.5 && body_get_rotation(a) == 0.0);
    CHECK_VEC(body_get_centroid(b), 20, 0, 0);
    CHECK_VEC(body_get_centroid(c), 20.5, 0, 0);
    CHECK_VEC(body_get_velocity(b), 0, 0, 0);
    CHECK_VEC(body_get_velocity(c), 0, 0, 0);
    CHECK(scene_contact_count(scene) == 0);
    /* The marked body and its force creator are gone; the others stay. */
    CHECK(scene_bodies(scene) == 3);
    CHECK(scene_get_body(scene, 0) == a && scene_get_body(scene, 2) == c);
    CHECK(info_frees[3] == 1 && aux_frees[2] == 1);
    CHECK(scene_get_stats(scene).removed_bodies == 1);
    CHECK(aux_frees[1] == 0);

    /* The force and impulse added before it are still there for the next
     * real step: v' = v + (F/m + g) dt + J/m. */
    const double dt = 0.1;
    scene_tick(scene, dt);
    CHECK_VEC(body_get_velocity(a), 3 + 4.0 / 2.0 * dt, -1 - 9.8 * dt + 2.0 / 2.0, 1e-12);
    CHECK(spy->calls == 1);
    scene_free(scene);
    CHECK(test_no_leaks());
}

static void zero_dt_clears_the_record(void) {
    /* A seed collision recorded at a real step is not reported again after a
     * zero step, which runs no collision. */
    scene_t *scene = scene_init();
    body_t *a = tagged_box(0, VEC_ZERO, 1.0), *b = tagged_box(1, (vector_t){0.5, 0}, 1.0);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    create_physics_collision(scene, a, b, 1.0);
    scene_tick(scene, 0.01);
    CHECK(scene_contact_count(scene) == 1);
    scene_tick(scene, 0.0);
    CHECK(scene_contact_count(scene) == 0);
    scene_free(scene);
}

static void zero_dt_reaps_a_body_in_world_contact(void) {
    /* The world still holds last step's contacts of the reaped body when
     * the next real step starts: it must not read the freed body
     * (AddressSanitizer). */
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0, -9.8});
    scene_set_contacts_enabled(scene, true);
    body_t *floor = tagged_box(0, VEC_ZERO, INFINITY);
    body_t *box = tagged_box(1, (vector_t){0, 1}, 1.0);
    body_t *other = tagged_box(2, (vector_t){0.2, 2}, 1.0);
    scene_add_body(scene, floor);
    scene_add_body(scene, box);
    scene_add_body(scene, other);
    for (int i = 0; i < 30; i++) scene_tick(scene, 0.01);
    CHECK(scene_contact_count(scene) >= 2);
    body_remove(box);
    scene_tick(scene, 0.0);
    CHECK(scene_bodies(scene) == 2 && info_frees[1] == 1);
    CHECK(scene_contact_count(scene) == 0);
    for (int i = 0; i < 100; i++) scene_tick(scene, 0.01);
    CHECK_NEAR(body_get_centroid(other).y, 1.0, 0.02); /* fell onto the floor */
    scene_free(scene);
}

static void gravity_accelerates_finite_masses_only(void) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0, -9.8});
    CHECK_VEC(scene_get_gravity(scene), 0, -9.8, 0);
    body_t *ball = tagged_box(0, (vector_t){0, 10}, 3.0);
    body_t *floor = tagged_box(1, VEC_ZERO, INFINITY);
    body_set_velocity(ball, (vector_t){1, 2});
    scene_add_body(scene, ball);
    scene_add_body(scene, floor);
    const double dt = 0.01;
    for (int i = 0; i < 100; i++) scene_tick(scene, dt);
    /* The seed scheme is exact for constant acceleration. */
    CHECK_VEC(body_get_centroid(ball), 1.0, 10 + 2.0 - 4.9, 1e-12);
    CHECK_VEC(body_get_velocity(ball), 1.0, 2.0 - 9.8, 1e-12);
    CHECK_VEC(body_get_centroid(floor), 0, 0, 0);
    CHECK_VEC(body_get_velocity(floor), 0, 0, 0);
    /* Independent of mass. */
    body_t *heavy = tagged_box(2, (vector_t){5, 0}, 1000.0);
    scene_add_body(scene, heavy);
    scene_tick(scene, dt);
    CHECK_VEC(body_get_velocity(heavy), 0, -9.8 * dt, 1e-15);
    scene_free(scene);
}

/* n steps of dt from rest under constant acceleration a and one impulse
 * J (per unit mass j) in the first step. */
static void check_integrator(integrator_t integrator, double weight) {
    /* x' = x + dt ((1 - w) v + w v'): w = 0 explicit, 1/2 seed, 1 symplectic. */
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    CHECK(scene_get_integrator(scene) == integrator);
    scene_set_gravity(scene, (vector_t){0, -2.0});
    body_t *body = tagged_box(0, VEC_ZERO, 4.0); /* I = 4 * 2 / 12 = 2/3 */
    scene_add_body(scene, body);
    const double dt = 0.1, a = -2.0, j = 0.5;
    body_add_impulse(body, (vector_t){4.0 * j, 0});
    body_add_torque(body, 2.0 / 3.0); /* angular acceleration 1 in the first step */
    scene_tick(scene, dt);
    CHECK_VEC(body_get_velocity(body), j, a * dt, 1e-15);
    CHECK_VEC(body_get_centroid(body), dt * weight * j, dt * weight * a * dt, 1e-15);
    CHECK_NEAR(body_get_angular_velocity(body), dt, 1e-15);
    CHECK_NEAR(body_get_rotation(body), dt * weight * dt, 1e-15);
    const int n = 20;
    for (int i = 1; i < n; i++) scene_tick(scene, dt);
    /* y_n = a dt^2 sum_{k<n} (k + w) = a dt^2 (n (n - 1) / 2 + n w). */
    double expected_y = a * dt * dt * (n * (n - 1) / 2.0 + n * weight);
    CHECK_VEC(body_get_centroid(body), j * dt * (n - 1 + weight), expected_y, 1e-13);
    CHECK_VEC(body_get_velocity(body), j, a * dt * n, 1e-13);
    CHECK_NEAR(body_get_rotation(body), dt * dt * (n - 1 + weight), 1e-13);
    scene_free(scene);
}

static void integrators_follow_their_formulas(void) {
    check_integrator(INTEGRATOR_SEED, 0.5);
    check_integrator(INTEGRATOR_EXPLICIT_EULER, 0.0);
    check_integrator(INTEGRATOR_SYMPLECTIC_EULER, 1.0);
    check_integrator(INTEGRATOR_IMPLICIT_EULER, 1.0); /* no spring or drag: symplectic */
}

/* A centripetal force toward `center` for the body's current speed and
 * radius: F = -m |v|^2 / r^2 (x - c). */
typedef struct {
    body_t *body;
    vector_t center;
} centripetal_t;

static void centripetal(void *aux) {
    centripetal_t *c = aux;
    vector_t r = vec_subtract(body_get_centroid(c->body), c->center);
    double speed2 = vec_get_length_squared(body_get_velocity(c->body));
    double factor = -body_get_mass(c->body) * speed2 / vec_get_length_squared(r);
    body_add_force(c->body, vec_multiply(factor, r));
}

static void uniform_circular_motion_from_a_centripetal_force(void) {
    /* Radius 2 about (1, -1), speed 3: omega 1.5, period 4 pi / 3. */
    scene_t *scene = scene_init();
    vector_t center = {1, -1};
    body_t *body = tagged_box(0, (vector_t){3, -1}, 1.5);
    body_set_velocity(body, (vector_t){0, 3});
    scene_add_body(scene, body);
    centripetal_t *aux = malloc(sizeof *aux);
    *aux = (centripetal_t){body, center};
    scene_add_bodies_force_creator(scene, centripetal, aux, bodies_of(body, NULL), free);
    const double dt = 1e-4, omega = 1.5;
    const long steps = lround(2 * M_PI / omega / dt);
    double worst_radius = 0, worst_speed = 0, worst_position = 0;
    for (long i = 1; i <= steps; i++) {
        scene_tick(scene, dt);
        vector_t r = vec_subtract(body_get_centroid(body), center);
        worst_radius = fmax(worst_radius, fabs(vec_get_length(r) - 2.0));
        worst_speed = fmax(worst_speed, fabs(vec_get_length(body_get_velocity(body)) - 3.0));
        if (i % 1000 == 0) {
            /* Counter-clockwise at omega: (2 cos wt, 2 sin wt) about c. */
            vector_t expected = {2 * cos(omega * dt * i), 2 * sin(omega * dt * i)};
            worst_position = fmax(worst_position, vec_get_length(vec_subtract(r, expected)));
        }
    }
    CHECK_NEAR(worst_radius, 0.0, 2e-5 * 2.0);
    CHECK_NEAR(worst_speed, 0.0, 1e-3 * 3.0);
    CHECK_NEAR(worst_position, 0.0, 1e-2);
    vector_t end = body_get_centroid(body);
    CHECK_VEC(end, 3.0, -1.0, 1e-2); /* one full turn */
    scene_free(scene);
}

static void warm_tick_allocates_nothing(void) {
    scene_t *scene = scene_init();
    body_t *a = tagged_box(0, VEC_ZERO, 1.0), *b = tagged_box(1, (vector_t){3, 0}, 2.0);
    body_t *c = tagged_box(2, (vector_t){0.5, 0.2}, 1.0);
    body_t *wall = tagged_box(3, (vector_t){9, 0}, INFINITY);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    scene_add_body(scene, c);
    scene_add_body(scene, wall);
    scene_set_gravity(scene, (vector_t){0, -1});
    create_spring(scene, 1.0, a, b);
    create_drag(scene, 0.1, b);
    create_newtonian_gravity(scene, 1.0, a, b);
    create_physics_collision(scene, a, c, 0.5); /* overlapping from the start */
    create_physics_collision(scene, b, wall, 1.0);
    spy_t *spy = new_spy(1, a);
    scene_add_bodies_force_creator(scene, spy_force, spy, bodies_of(a, b), spy_free);
    scene_tick(scene, 0.01); /* warm: the record has grown once */
    size_t before = engine_allocation_count();
    for (int i = 0; i < 50; i++) scene_tick(scene, 0.01);
    CHECK(engine_allocation_count() == before);
    /* The counter does count: a new body allocates. */
    body_t *d = tagged_box(4, (vector_t){20, 0}, 1.0);
    CHECK(engine_allocation_count() > before);
    scene_add_body(scene, d);
    scene_free(scene);
}

/* Without world contacts a one-stage scheme moves each body as it works out
 * its motion, storing none: not even the first tick allocates. */
static void one_stage_tick_without_contacts_stores_no_motions(void) {
    const integrator_t one_stage[3] = {INTEGRATOR_SEED, INTEGRATOR_EXPLICIT_EULER,
                                       INTEGRATOR_SYMPLECTIC_EULER};
    for (int k = 0; k < 3; k++) {
        scene_t *scene = scene_init();
        scene_set_integrator(scene, one_stage[k]);
        body_t *a = tagged_box(0, VEC_ZERO, 1000.0), *b = tagged_box(1, (vector_t){10, 0}, 1.0);
        scene_add_body(scene, a);
        scene_add_body(scene, b);
        body_set_velocity(b, (vector_t){0, 10});
        create_newtonian_gravity(scene, 1.0, a, b);
        size_t before = engine_allocation_count();
        scene_tick(scene, 0.01);
        CHECK(engine_allocation_count() == before);
        CHECK(body_get_velocity(b).x < 0.0 && body_get_centroid(b).y > 0.0);
        scene_free(scene);
    }
}

/* Programmer errors. */

static scene_t *scene_of_two(void) {
    scene_t *scene = scene_init();
    scene_add_body(scene, tagged_box(0, VEC_ZERO, 1.0));
    scene_add_body(scene, tagged_box(1, (vector_t){2, 0}, 1.0));
    return scene;
}

BAD_CALL(free_null, scene_free(NULL))
BAD_CALL(bodies_null, scene_bodies(NULL))
BAD_CALL(get_body_null, scene_get_body(NULL, 0))
BAD_CALL(get_body_past_end, scene_get_body(scene_of_two(), 2))
BAD_CALL(get_body_from_empty, scene_get_body(scene_init(), 0))
BAD_CALL(add_body_null_scene, scene_add_body(NULL, tagged_box(0, VEC_ZERO, 1.0)))
BAD_CALL(add_null_body, scene_add_body(scene_init(), NULL))
BAD_CALL(remove_body_past_end, scene_remove_body(scene_of_two(), 5))
BAD_CALL(add_force_creator_null_scene, scene_add_force_creator(NULL, spy_force, NULL, NULL))
BAD_CALL(add_null_force_creator, scene_add_force_creator(scene_init(), NULL, NULL, NULL))
BAD_CALL(add_bodies_force_creator_null_scene,
         scene_add_bodies_force_creator(NULL, spy_force, NULL, NULL, NULL))
BAD_CALL(add_null_bodies_force_creator,
         scene_add_bodies_force_creator(scene_init(), NULL, NULL, list_init(0, NULL), NULL))
BAD_CALL(tick_null, scene_tick(NULL, 0.1))
BAD_CALL(tick_negative_dt, scene_tick(scene_of_two(), -0.01))
BAD_CALL(tick_nan_dt, scene_tick(scene_of_two(), NAN))
BAD_CALL(tick_infinite_dt, scene_tick(scene_of_two(), INFINITY))
BAD_CALL(gravity_nan, scene_set_gravity(scene_init(), (vector_t){0, NAN}))
BAD_CALL(gravity_null, scene_set_gravity(NULL, VEC_ZERO))
BAD_CALL(get_gravity_null, scene_get_gravity(NULL))
BAD_CALL(integrator_unknown, scene_set_integrator(scene_init(), (integrator_t)7))
BAD_CALL(drag_limit_unknown, integrator_get_drag_limit((integrator_t)7))
BAD_CALL(integrator_null, scene_set_integrator(NULL, INTEGRATOR_SEED))
BAD_CALL(get_integrator_null, scene_get_integrator(NULL))
BAD_CALL(contact_count_null, scene_contact_count(NULL))
BAD_CALL(get_contact_past_end, scene_get_contact(scene_init(), 0))
BAD_CALL(get_stats_null, scene_get_stats(NULL))

static list_t *list_with_null_body(void) {
    static int placeholder;
    list_t *bodies = list_init(2, NULL);
    list_add(bodies, &placeholder);
    list_set(bodies, 0, NULL); /* list_add refuses NULL */
    return bodies;
}

BAD_CALL(add_bodies_force_creator_null_body,
         scene_add_bodies_force_creator(scene_init(), spy_force, NULL, list_with_null_body(), NULL))

static void add_same_body(scene_t *scene) {
    body_t *body = tagged_box(0, VEC_ZERO, 1.0);
    scene_add_body(scene, body);
    scene_add_body(scene, body);
}

BAD_CALL(add_body_twice, add_same_body(scene_init()))

static void add_to_two_scenes(void) {
    body_t *body = tagged_box(0, VEC_ZERO, 1.0);
    scene_add_body(scene_init(), body);
    scene_add_body(scene_init(), body);
}

BAD_CALL(add_body_to_two_scenes, add_to_two_scenes())

/* A step whose result does not fit a double stops the program in scene_tick,
 * naming the body, the stage and the likely cause. */

static scene_t *scene_with_moving_body(vector_t velocity, double omega, bool contacts) {
    scene_t *scene = scene_of_two();
    scene_set_contacts_enabled(scene, contacts);
    body_set_velocity(scene_get_body(scene, 1), velocity);
    body_set_angular_velocity(scene_get_body(scene, 1), omega);
    return scene;
}

BAD_CALL(tick_fast_body, scene_tick(scene_with_moving_body((vector_t){1e308, 0}, 0, false), 10))
BAD_CALL(tick_fast_body_with_contacts,
         scene_tick(scene_with_moving_body((vector_t){1e308, 0}, 0, true), 10))
BAD_CALL(tick_fast_spin, scene_tick(scene_with_moving_body(VEC_ZERO, -1e308, false), 10))

static scene_t *scene_under_gravity(bool contacts) {
    scene_t *scene = scene_of_two();
    scene_set_contacts_enabled(scene, contacts);
    scene_set_gravity(scene, (vector_t){0, -9.81});
    return scene;
}

BAD_CALL(tick_huge_dt, scene_tick(scene_under_gravity(false), 1e200))
BAD_CALL(tick_huge_dt_with_contacts, scene_tick(scene_under_gravity(true), 1e200))

/* Two finite forces whose sum overflows. */
static void push_hard(void *aux) {
    body_add_force(aux, (vector_t){1e308, 0});
    body_add_force(aux, (vector_t){1e308, 0});
}

static void tick_with_overflowing_forces(void) {
    scene_t *scene = scene_of_two();
    body_t *body = scene_get_body(scene, 0);
    scene_add_bodies_force_creator(scene, push_hard, body, bodies_of(body, NULL), NULL);
    scene_tick(scene, 0.01);
}

BAD_CALL(tick_overflowing_forces, tick_with_overflowing_forces())

static void add_subnormal_mass_with_contacts(void) {
    scene_t *scene = scene_of_two();
    scene_set_contacts_enabled(scene, true);
    scene_add_body(scene, body_init(polygon_make_box((vector_t){0, 1}, 0.5, 0.5), 1e-310, GREY));
    scene_tick(scene, 0.01);
}

BAD_CALL(subnormal_mass_with_contacts, add_subnormal_mass_with_contacts())

static void non_finite_state_after_a_step_aborts_naming_the_body(void) {
    CHECK_DIES(tick_fast_body, NULL, "engine error in scene_tick:", "integrate stage",
               "body 1 (centroid (2, 0) before the step)", "position is not finite",
               "dt = 10 s", "too large for its velocity (1e+308, 0) m/s");
    CHECK_DIES(tick_fast_body_with_contacts, NULL, "engine error in scene_tick:",
               "integrate stage", "body 1", "position is not finite", "dt = 10 s",
               "too large for its velocity (1e+308, 0) m/s");
    CHECK_DIES(tick_fast_spin, NULL, "engine error in scene_tick:", "integrate stage", "body 1",
               "angle is not finite", "dt = 10 s", "too large for its angular velocity -1e+308");
    CHECK_DIES(tick_huge_dt, NULL, "engine error in scene_tick:", "integrate stage", "body 0",
               "position is not finite", "dt = 1e+200 s",
               "too large for its velocity (0, -9.81e+200) m/s");
    CHECK_DIES(tick_huge_dt_with_contacts, NULL, "engine error in scene_tick:",
               "integrate stage", "body 0", "not finite", "dt = 1e+200 s");
    CHECK_DIES(tick_overflowing_forces, NULL, "engine error in scene_tick:", "integrate stage",
               "body 0", "velocity is not finite", "force (inf, 0) N");
    CHECK_DIES(subnormal_mass_with_contacts, NULL, "engine error in body_init:",
               "mass 1e-310 kg", "inverse is not finite");
}

static void bad_input_aborts_with_message(void) {
    CHECK_DIES(free_null, NULL, "engine error in scene_free:", "NULL");
    CHECK_DIES(bodies_null, NULL, "engine error in scene_bodies:", "NULL");
    CHECK_DIES(get_body_null, NULL, "engine error in scene_get_body:", "NULL");
    CHECK_DIES(get_body_past_end, NULL, "engine error in scene_get_body:", "index 2",
               "out of range", "2 bodies");
    CHECK_DIES(get_body_from_empty, NULL, "engine error in scene_get_body:", "out of range");
    CHECK_DIES(add_body_null_scene, NULL, "engine error in scene_add_body:", "scene is NULL");
    CHECK_DIES(add_null_body, NULL, "engine error in scene_add_body:", "body is NULL");
    /* Today the message names scene_get_body, which scene_remove_body calls. */
    CHECK_DIES(remove_body_past_end, NULL, "engine error in scene_remove_body:", "index 5",
               "out of range");
    CHECK_DIES(add_force_creator_null_scene, NULL, "engine error in scene_add_force_creator:",
               "scene is NULL");
    CHECK_DIES(add_null_force_creator, NULL, "engine error in scene_add_force_creator:",
               "forcer is NULL");
    CHECK_DIES(add_bodies_force_creator_null_body, NULL,
               "engine error in scene_add_bodies_force_creator:", "bodies[0] is NULL");
    CHECK_DIES(add_body_twice, NULL, "engine error in scene_add_body:", "already belongs");
    CHECK_DIES(add_body_to_two_scenes, NULL, "engine error in scene_add_body:", "already belongs");
    CHECK_DIES(add_bodies_force_creator_null_scene, NULL,
               "engine error in scene_add_bodies_force_creator:", "scene is NULL");
    CHECK_DIES(add_null_bodies_force_creator, NULL,
               "engine error in scene_add_bodies_force_creator:", "forcer is NULL");
    CHECK_DIES(tick_null, NULL, "engine error in scene_tick:", "NULL");
    CHECK_DIES(tick_negative_dt, NULL,
               "engine error in scene_tick: dt must be finite and >= 0 (got -0.01)");
    CHECK_DIES(tick_nan_dt, NULL, "engine error in scene_tick: dt must be finite and >= 0",
               "nan");
    CHECK_DIES(tick_infinite_dt, NULL, "engine error in scene_tick: dt must be finite and >= 0",
               "inf");
    CHECK_DIES(gravity_nan, NULL, "engine error in scene_set_gravity:", "not finite");
    CHECK_DIES(gravity_null, NULL, "engine error in scene_set_gravity:", "NULL");
    CHECK_DIES(get_gravity_null, NULL, "engine error in scene_get_gravity:", "NULL");
    CHECK_DIES(integrator_unknown, NULL, "engine error in scene_set_integrator:",
               "unknown integrator 7");
    CHECK_DIES(drag_limit_unknown, NULL, "engine error in integrator_get_drag_limit:",
               "unknown integrator 7");
    CHECK_DIES(integrator_null, NULL, "engine error in scene_set_integrator:", "NULL");
    CHECK_DIES(get_integrator_null, NULL, "engine error in scene_get_integrator:", "NULL");
    CHECK_DIES(contact_count_null, NULL, "engine error in scene_contact_count:", "NULL");
    CHECK_DIES(get_contact_past_end, NULL, "engine error in scene_get_contact:", "out of range");
    CHECK_DIES(get_stats_null, NULL, "engine error in scene_get_stats:", "NULL");
}

TEST_SUITE(scene, TEST_CASE(init_is_empty_with_documented_defaults),
           TEST_CASE(bodies_are_kept_in_the_order_added),
           TEST_CASE(free_releases_bodies_and_aux_with_their_freers),
           TEST_CASE(tick_runs_force_creators_in_order_then_moves_bodies),
           TEST_CASE(forces_apply_in_the_same_tick_and_are_cleared),
           TEST_CASE(removal_is_deferred_to_the_end_of_the_next_tick),
           TEST_CASE(deprecated_scene_remove_body_only_marks),
           TEST_CASE(force_creators_of_a_removed_body_are_dropped_and_freed),
           TEST_CASE(bodies_list_never_frees_the_bodies),
           TEST_CASE(body_removed_during_a_tick_is_reaped_at_its_end),
           TEST_CASE(zero_dt_only_reaps_removed_bodies), TEST_CASE(zero_dt_clears_the_record),
           TEST_CASE(zero_dt_reaps_a_body_in_world_contact),
           TEST_CASE(gravity_accelerates_finite_masses_only),
           TEST_CASE(integrators_follow_their_formulas),
           TEST_CASE(uniform_circular_motion_from_a_centripetal_force),
           TEST_CASE(warm_tick_allocates_nothing),
           TEST_CASE(one_stage_tick_without_contacts_stores_no_motions),
           TEST_CASE(bad_input_aborts_with_message),
           TEST_CASE(non_finite_state_after_a_step_aborts_naming_the_body));
