/* forces.h, all pairs of a group as one force creator: the same forces and
 * handler calls as the pairwise creators, in the same order, with memory
 * and work that grow with the bodies, not the pairs; and the scene files'
 * newton and collide, built on them. */
#include <stdlib.h>
#include <string.h>
#include "jostle/jostle.h"
#include "jostle/scene_file.h"
#include "test.h"

#define COUNT_OF(array) (sizeof(array) / sizeof((array)[0]))

static const rgb_color_t GREY = {0.5, 0.5, 0.5};

/* AddressSanitizer's count of the bytes in use (make check builds with
 * it); absent otherwise. */
size_t __sanitizer_get_current_allocated_bytes(void) __attribute__((weak));

static body_t *added(scene_t *scene, body_t *body) {
    scene_add_body(scene, body);
    return body;
}

/* A deterministic number in [0, 1). */
static double unit(unsigned *seed) {
    *seed = *seed * 1103515245u + 12345u;
    return (double)((*seed >> 8) & 0xffffff) / 16777216.0;
}

/* ---- Gravity ---------------------------------------------------------------- */

/* Twelve bodies scattered over 20 m with masses 1 to 1000 kg, one of them
 * of infinite mass; the same in two scenes. */
enum { BODIES = 12 };

static scene_t *scattered(integrator_t integrator, body_t **bodies) {
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    unsigned seed = 7;
    for (int i = 0; i < BODIES; i++) {
        vector_t at = {20.0 * unit(&seed), 20.0 * unit(&seed)};
        double mass = i == 5 ? INFINITY : 1.0 + 999.0 * unit(&seed);
        bodies[i] = added(scene, body_init(polygon_make_regular(6, 0.2, at, 0.0), mass, GREY));
        if (i != 5) body_set_velocity(bodies[i], (vector_t){unit(&seed) - 0.5, unit(&seed) - 0.5});
    }
    return scene;
}

static bool same_motion(body_t *const *a, body_t *const *b, int count) {
    for (int i = 0; i < count; i++) {
        vector_t pa = body_get_centroid(a[i]), pb = body_get_centroid(b[i]);
        vector_t va = body_get_velocity(a[i]), vb = body_get_velocity(b[i]);
        if (pa.x != pb.x || pa.y != pb.y || va.x != vb.x || va.y != vb.y) return false;
    }
    return true;
}

static void gravity_group_applies_the_pairwise_forces_bit_for_bit(void) {
    const integrator_t integrators[] = {INTEGRATOR_SYMPLECTIC_EULER, INTEGRATOR_RK4};
    for (size_t k = 0; k < COUNT_OF(integrators); k++) {
        body_t *pairwise[BODIES], *grouped[BODIES];
        scene_t *a = scattered(integrators[k], pairwise);
        scene_t *b = scattered(integrators[k], grouped);
        list_t *members = list_init(BODIES, NULL);
        for (int i = 0; i < BODIES; i++) {
            for (int j = i + 1; j < BODIES; j++) {
                create_newtonian_gravity(a, 0.01, pairwise[i], pairwise[j]);
            }
            list_add(members, grouped[i]);
        }
        gravity_group_t *group = create_newtonian_gravity_group(b, 0.01, members);
        list_free(members);
        CHECK(group != NULL);
        for (int tick = 0; tick < 200; tick++) {
            scene_tick(a, 0.01);
            scene_tick(b, 0.01);
        }
        CHECK(same_motion(pairwise, grouped, BODIES));
        CHECK(body_get_velocity(pairwise[0]).x != 0.0);
        /* A removed body leaves the group; the others go on as with its
         * pairwise creators dropped. */
        body_remove(pairwise[3]);
        body_remove(grouped[3]);
        for (int tick = 0; tick < 200; tick++) {
            scene_tick(a, 0.01);
            scene_tick(b, 0.01);
        }
        body_t *rest_a[BODIES - 1], *rest_b[BODIES - 1];
        for (int i = 0, n = 0; i < BODIES; i++) {
            if (i == 3) continue;
            rest_a[n] = pairwise[i];
            rest_b[n++] = grouped[i];
        }
        CHECK(scene_bodies(b) == BODIES - 1);
        CHECK(same_motion(rest_a, rest_b, BODIES - 1));
        scene_free(a);
        scene_free(b);
    }
}

/* ---- Collisions --------------------------------------------------------------- */

/* Every handler call: tick, bodies by index in the scene. */
typedef struct {
    scene_t *scene;
    int tick;
    int calls;
    int log[4096][3];
    bool destroy; /* remove both, as a destructive collision */
    double elasticity;
} call_log_t;

static int index_in(scene_t *scene, body_t *body) {
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        if (scene_get_body(scene, i) == body) return (int)i;
    }
    return -1;
}

static void logging_handler(body_t *body1, body_t *body2, vector_t axis, void *aux,
                            double force_const) {
    call_log_t *log = aux;
    if (log->calls < (int)COUNT_OF(log->log)) {
        int *entry = log->log[log->calls];
        entry[0] = log->tick;
        entry[1] = index_in(log->scene, body1);
        entry[2] = index_in(log->scene, body2);
    }
    log->calls++;
    if (log->destroy) {
        destructive_collision_handler(body1, body2, axis, NULL, force_const);
    } else {
        physics_collision_handler(body1, body2, axis, NULL, force_const);
    }
}

static bool same_calls(const call_log_t *a, const call_log_t *b) {
    if (a->calls != b->calls) return false;
    for (int i = 0; i < a->calls && i < (int)COUNT_OF(a->log); i++) {
        if (memcmp(a->log[i], b->log[i], sizeof a->log[i]) != 0) return false;
    }
    return true;
}

/* Balls (octagons of radius 0.3) in a 10 m box of four static walls, at
 * random places and velocities; world contacts off (the seed's rule) or on
 * (with gravity, the world's rule). */
enum { BALLS = 40 };

static scene_t *box_of_balls(bool contacts, body_t **bodies, size_t *count) {
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, contacts);
    if (contacts) scene_set_gravity(scene, (vector_t){0, -9.8});
    const vector_t walls[][2] = {{{5, -0.5}, {5.5, 0.5}}, {{5, 10.5}, {5.5, 0.5}},
                                 {{-0.5, 5}, {0.5, 5.5}}, {{10.5, 5}, {0.5, 5.5}}};
    size_t n = 0;
    for (size_t w = 0; w < 4; w++) {
        bodies[n++] = added(scene, body_init(polygon_make_box(walls[w][0], walls[w][1].x,
                                                               walls[w][1].y),
                                              INFINITY, GREY));
    }
    unsigned seed = 11;
    for (int i = 0; i < BALLS; i++) {
        vector_t at = {0.5 + 9.0 * unit(&seed), 0.5 + 9.0 * unit(&seed)};
        body_t *ball = added(scene, body_init(polygon_make_regular(8, 0.3, at, 0.0), 1.0, GREY));
        body_set_velocity(ball, (vector_t){8.0 * unit(&seed) - 4.0, 8.0 * unit(&seed) - 4.0});
        bodies[n++] = ball;
    }
    *count = n;
    return scene;
}

/* The same scene with the pairwise creators (every pair i < j, in that
 * order) and with one group over all the bodies: the same handler calls in
 * the same order, and the same motion. */
static void collision_group_calls_what_the_pairwise_creators_call(void) {
    for (int contacts = 0; contacts < 2; contacts++) {
        for (int destroy = 0; destroy < 2; destroy++) {
            body_t *pairwise[BALLS + 4], *grouped[BALLS + 4];
            size_t n = 0;
            scene_t *a = box_of_balls(contacts, pairwise, &n);
            scene_t *b = box_of_balls(contacts, grouped, &n);
            call_log_t *log_a = calloc(1, sizeof *log_a), *log_b = calloc(1, sizeof *log_b);
            *log_a = (call_log_t){.scene = a, .destroy = destroy};
            *log_b = (call_log_t){.scene = b, .destroy = destroy};
            list_t *all = list_init(n, NULL);
            for (size_t i = 0; i < n; i++) {
                for (size_t j = i + 1; j < n; j++) {
                    create_collision(a, pairwise[i], pairwise[j], logging_handler, log_a, 0.9);
                }
                list_add(all, grouped[i]);
            }
            create_collision_group(b, all, all, logging_handler, log_b, 0.9);
            list_free(all);
            for (int tick = 0; tick < 300; tick++) {
                log_a->tick = log_b->tick = tick;
                scene_tick(a, 1.0 / 60);
                scene_tick(b, 1.0 / 60);
            }
            if (!same_calls(log_a, log_b)) {
                printf("    contacts %d, destroy %d: %d calls pairwise, %d grouped\n", contacts,
                       destroy, log_a->calls, log_b->calls);
            }
            CHECK(log_a->calls > (destroy ? 10 : 50));
            CHECK(same_calls(log_a, log_b));
            CHECK(scene_bodies(a) == scene_bodies(b));
            bool same = scene_bodies(a) == scene_bodies(b);
            for (size_t i = 0; same && i < scene_bodies(a); i++) {
                body_t *x = scene_get_body(a, i), *y = scene_get_body(b, i);
                same = same_motion(&x, &y, 1);
            }
            CHECK(same);
            free(log_a);
            free(log_b);
            scene_free(a);
            scene_free(b);
        }
    }
}

typedef struct {
    int calls;
    body_t *body1, *body2; /* of the last call */
} pair_log_t;

static void count_calls(body_t *body1, body_t *body2, vector_t axis, void *aux,
                        double force_const) {
    (void)axis, (void)force_const;
    pair_log_t *log = aux;
    log->calls++;
    log->body1 = body1;
    log->body2 = body2;
}

/* Two sets: a body of the first meets a body of the second, whichever list
 * holds it first; a body in both meets every other body of either; two
 * bodies of one set only never meet. */
static void the_two_sets_pair_as_documented(void) {
    /* Squares at x = 0, 10, 20, 30 (a, b, c, d): sets {a, b} and {b, c};
     * d in neither at first. Each test overlaps two of them. */
    const struct {
        int p, q;  /* the squares made to overlap: q moves onto p */
        int calls; /* handler calls */
        int body1; /* the handler's body1 */
    } cases[] = {
        {0, 1, 1, 0}, /* a (first) with b (both) */
        {0, 2, 1, 0}, /* a with c */
        {1, 2, 1, 1}, /* b (both) with c (second): b is body1 */
        {2, 1, 1, 1}, /* the same pair, b moving */
        {0, 3, 0, 0}, /* d is not in the group */
    };
    for (size_t k = 0; k < COUNT_OF(cases); k++) {
        scene_t *scene = scene_init();
        body_t *sq[4];
        for (int i = 0; i < 4; i++) {
            sq[i] = added(scene, body_init(polygon_make_box((vector_t){10.0 * i, 0}, 1, 1), 1.0,
                                           GREY));
        }
        list_t *first = list_init(2, NULL), *second = list_init(2, NULL);
        list_add(first, sq[0]);
        list_add(first, sq[1]);
        list_add(second, sq[1]);
        list_add(second, sq[2]);
        pair_log_t log = {0};
        create_collision_group(scene, first, second, count_calls, &log, 0.0);
        list_free(first);
        list_free(second);
        /* q moves onto p in one step of 1 s. */
        body_set_velocity(sq[cases[k].q], (vector_t){10.0 * (cases[k].p - cases[k].q) + 0.5, 0});
        scene_tick(scene, 1.0);
        scene_tick(scene, 1e-9);
        CHECK(log.calls == cases[k].calls);
        if (cases[k].calls > 0) CHECK(log.body1 == sq[cases[k].body1]);
        scene_free(scene);
    }
    /* Two bodies of the first set only never meet, nor of the second;
     * a body added later to both meets them all. */
    scene_t *scene = scene_init();
    body_t *a = added(scene, body_init(polygon_make_box(VEC_ZERO, 1, 1), 1.0, GREY));
    body_t *b = added(scene, body_init(polygon_make_box((vector_t){1, 0}, 1, 1), 1.0, GREY));
    body_t *c = added(scene, body_init(polygon_make_box((vector_t){0, 1}, 1, 1), 1.0, GREY));
    list_t *first = list_init(2, NULL), *none = list_init(0, NULL);
    list_add(first, a);
    list_add(first, b);
    pair_log_t log = {0};
    collision_group_t *group = create_collision_group(scene, first, none, count_calls, &log, 0);
    scene_tick(scene, 0.01);
    CHECK(log.calls == 0);
    collision_group_add(group, c, true, true);
    scene_tick(scene, 0.01);
    CHECK(log.calls == 2); /* a-c and b-c; a-b still not */
    CHECK(log.body1 == b && log.body2 == c); /* the last, in member order */
    list_free(first);
    list_free(none);
    scene_free(scene);
}

/* Once warm, a step of a scene with a gravity and a collision group over
 * all its bodies allocates nothing, with world contacts on (a box of balls
 * under gravity, the world's rule) and off (the seed's). */
static void a_warm_step_allocates_nothing(void) {
    for (int contacts = 0; contacts < 2; contacts++) {
        body_t *bodies[BALLS + 4];
        size_t n = 0;
        scene_t *scene = box_of_balls(contacts, bodies, &n);
        scene_set_sleeping(scene, false);
        list_t *all = list_init(n, NULL);
        for (size_t i = 0; i < n; i++) list_add(all, bodies[i]);
        call_log_t *log = calloc(1, sizeof *log);
        log->scene = scene;
        create_collision_group(scene, all, all, logging_handler, log, 0.9);
        create_newtonian_gravity_group(scene, 1e-3, all);
        list_free(all);
        for (int tick = 0; tick < 240; tick++) scene_tick(scene, 1.0 / 60);
        int calls = log->calls;
        size_t before = engine_allocation_count();
        for (int tick = 0; tick < 120; tick++) scene_tick(scene, 1.0 / 60);
        CHECK(engine_allocation_count() == before);
        /* Off, the balls still meet; on, they rest in a pile. */
        CHECK(contacts ? scene_contact_count(scene) > 0 : log->calls > calls);
        free(log);
        scene_free(scene);
    }
}

/* ---- Growth ------------------------------------------------------------------- */

typedef struct {
    size_t blocks;  /* engine allocations */
    size_t bytes;   /* bytes in use afterwards (0 without AddressSanitizer) */
    size_t tests;   /* bounding-box comparisons of a step */
    size_t listed;  /* forces the file lists */
} load_cost_t;

static size_t bytes_in_use(void) {
    return __sanitizer_get_current_allocated_bytes != NULL
               ? __sanitizer_get_current_allocated_bytes()
               : 0;
}

/* n hexagons of radius 0.3 in rows of 20, 0.5 m apart (neighbours
 * overlap), under `rule`. */
static load_cost_t load(size_t n, const char *rule) {
    char text[256];
    snprintf(text, sizeof text,
             "contacts off\nbody b { regular 6 0.3; position 0 0; repeat 20 %zu 0.5 0.5; group g "
             "}\n%s\n",
             n / 20, rule);
    size_t blocks = engine_allocation_count(), bytes = bytes_in_use();
    scene_file_error_t error;
    scene_file_t *file = scene_file_parse(text, strlen(text), "grow", &error);
    load_cost_t cost = {0};
    CHECK(file != NULL);
    if (file == NULL) {
        printf("    %s\n", error.message);
        return cost;
    }
    cost.blocks = engine_allocation_count() - blocks;
    cost.bytes = bytes_in_use() - bytes;
    scene_tick(scene_file_get_scene(file), 1.0 / 60);
    cost.tests = scene_get_stats(scene_file_get_scene(file)).broadphase_tests;
    cost.listed = scene_file_force_count(file);
    scene_file_free(file);
    return cost;
}

/* As the bodies double, loading newton or collide over all of them takes
 * twice the memory, not four times (one force creator, not one per pair),
 * and a step of the collide twice the box comparisons; the listing still
 * has every pair. */
static void loading_all_pairs_grows_with_the_bodies(void) {
    const char *const rules[] = {"newton 1 all", "collide g g physics 1"};
    for (size_t r = 0; r < COUNT_OF(rules); r++) {
        load_cost_t previous = {0};
        for (size_t n = 400; n <= 1600; n *= 2) {
            load_cost_t cost = load(n, rules[r]);
            CHECK(cost.listed == n * (n - 1) / 2);
            if (n > 400) {
                double blocks = (double)cost.blocks / (double)previous.blocks;
                double bytes = previous.bytes > 0 ? (double)cost.bytes / (double)previous.bytes : 2;
                printf("    %s, %zu bodies: %zu blocks (x%.2f), %zu bytes (x%.2f), %zu box "
                       "tests a step\n",
                       rules[r], n, cost.blocks, blocks, cost.bytes, bytes, cost.tests);
                CHECK(blocks < 2.3);
                CHECK(bytes < 2.3);
                if (r == 1) {
                    CHECK((double)cost.tests / (double)previous.tests < 2.3);
                    CHECK(cost.tests < 50 * n);
                }
            }
            previous = cost;
        }
    }
    /* The issue's file: newton over 1414 bodies, 998991 pairs. */
    load_cost_t issue = load(1420, "newton 1 all");
    CHECK(issue.listed == 1420 * 1419 / 2);
    CHECK(issue.blocks < 10000);
}

/* ---- Bad input ---------------------------------------------------------------- */

static list_t *one_body_list(body_t *body) {
    list_t *list = list_init(1, NULL);
    list_add(list, body);
    return list;
}

static void group_with_a_body_not_added(void *unused) {
    (void)unused;
    scene_t *scene = scene_init();
    body_t *loose = body_init(polygon_make_box(VEC_ZERO, 1, 1), 1.0, GREY);
    create_newtonian_gravity_group(scene, 1.0, one_body_list(loose));
}

static void collision_group_with_a_body_of_another_scene(void *unused) {
    (void)unused;
    scene_t *scene = scene_init(), *other = scene_init();
    body_t *elsewhere = added(other, body_init(polygon_make_box(VEC_ZERO, 1, 1), 1.0, GREY));
    list_t *none = list_init(0, NULL);
    create_collision_group(scene, none, one_body_list(elsewhere), count_calls, NULL, 0.0);
}

static void added_to_neither_set(void *unused) {
    (void)unused;
    scene_t *scene = scene_init();
    body_t *body = added(scene, body_init(polygon_make_box(VEC_ZERO, 1, 1), 1.0, GREY));
    list_t *none = list_init(0, NULL);
    collision_group_add(create_collision_group(scene, none, none, count_calls, NULL, 0.0), body,
                        false, false);
}

BAD_CALL(negative_g, create_newtonian_gravity_group(scene_init(), -1.0, list_init(0, NULL)))
BAD_CALL(null_bodies, create_newtonian_gravity_group(scene_init(), 1.0, NULL))
BAD_CALL(null_handler, create_collision_group(scene_init(), list_init(0, NULL),
                                              list_init(0, NULL), NULL, NULL, 0.0))
BAD_CALL(null_group, gravity_group_add(NULL, NULL))

static void bad_input_aborts_with_message(void) {
    CHECK_DIES(group_with_a_body_not_added, NULL,
               "engine error in create_newtonian_gravity_group:", "bodies[0] is not in the scene",
               "scene_add_body");
    CHECK_DIES(collision_group_with_a_body_of_another_scene, NULL,
               "engine error in create_collision_group:", "bodies2[0] is not in the scene");
    CHECK_DIES(added_to_neither_set, NULL, "engine error in collision_group_add:",
               "the first set, the second or both");
    CHECK_DIES(negative_g, NULL, "engine error in create_newtonian_gravity_group:",
               "G must be finite and >= 0");
    CHECK_DIES(null_bodies, NULL, "engine error in create_newtonian_gravity_group:",
               "bodies is NULL");
    CHECK_DIES(null_handler, NULL, "engine error in create_collision_group:", "handler is NULL");
    CHECK_DIES(null_group, NULL, "engine error in gravity_group_add:", "group is NULL");
}

TEST_SUITE(force_groups, TEST_CASE(gravity_group_applies_the_pairwise_forces_bit_for_bit),
           TEST_CASE(collision_group_calls_what_the_pairwise_creators_call),
           TEST_CASE(the_two_sets_pair_as_documented), TEST_CASE(a_warm_step_allocates_nothing),
           TEST_CASE(loading_all_pairs_grows_with_the_bodies),
           TEST_CASE(bad_input_aborts_with_message));
