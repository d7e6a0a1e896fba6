/* scene_set_workers: a step over several threads gives the bytes one thread
 * gives, for any worker count, changed mid-run or with sleeping on; bad
 * counts are refused; a warm step allocates nothing. And the pool
 * (workers.h) under it. */

#include <math.h>
#include <stdint.h>
#include <string.h>
#include "jostle/jostle.h"
#include "test.h"
#include "base/workers.h"

static const double DT = 1.0 / 60.0;
static const rgb_color_t GREY = {0.5, 0.5, 0.5};

static uint64_t pile_state;

static double pile_random(void) {
    pile_state = pile_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(pile_state >> 11) / 9007199254740992.0;
}

static body_t *add_static_box(scene_t *scene, double x, double y, double hx, double hy) {
    body_t *body = body_init(polygon_make_box((vector_t){x, y}, hx, hy), INFINITY, GREY);
    scene_add_body(scene, body);
    return body;
}

/* Pushes the floor, which cannot move, so that its free velocity comes out
 * -0.0 (-0.0 plus the -0.0 its infinite mass makes of the push), which a
 * solver row may not keep (world.c's load_body). */
static void push_floor(void *aux) {
    body_add_force(aux, (vector_t){-1.0, -1.0});
    body_add_impulse(aux, (vector_t){-1.0, -1.0});
    body_add_torque(aux, -1.0);
}

/* count polygons of 3 to 8 sides dropped in a box 30 m wide, some bouncy
 * (the collision pass) and some smooth, on a pushed floor. */
static scene_t *build_pile(size_t count, size_t workers, bool sleeping) {
    static const size_t sides[6] = {3, 4, 5, 6, 8, 4};
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -9.81});
    scene_set_contacts_enabled(scene, true);
    scene_set_sleeping(scene, sleeping);
    scene_set_workers(scene, workers);
    body_t *floor = add_static_box(scene, 15.0, -0.5, 16.0, 0.5);
    body_set_velocity(floor, (vector_t){-0.0, -0.0});
    body_set_angular_velocity(floor, -0.0);
    list_t *pushed = list_init(1, NULL);
    list_add(pushed, floor);
    scene_add_bodies_force_creator(scene, push_floor, floor, pushed, NULL);
    add_static_box(scene, -0.5, 30.0, 0.5, 30.0);
    add_static_box(scene, 30.5, 30.0, 0.5, 30.0);
    pile_state = 2024;
    for (size_t i = 0; i < count; i++) {
        double column = (double)(i % 25), row = (double)(i / 25);
        vector_t center = {1.0 + 1.15 * column + 0.1 * pile_random(),
                           1.0 + 1.15 * row + 0.1 * pile_random()};
        list_t *shape = polygon_make_regular(sides[i % 6], 0.5, center, 0.0);
        body_t *body = body_init(shape, 1.0 + pile_random(), GREY);
        scene_add_body(scene, body);
        body_set_rotation(body, 2.0 * M_PI * pile_random());
        if (i % 7 == 0) body_set_elasticity(body, 0.6);
        if (i % 11 == 0) body_set_friction(body, 0.0);
    }
    return scene;
}

static uint64_t hash_bytes(uint64_t hash, const void *bytes, size_t size) {
    const unsigned char *p = bytes;
    for (size_t i = 0; i < size; i++) hash = (hash ^ p[i]) * 1099511628211ULL;
    return hash;
}

static uint64_t hash_double(uint64_t hash, double value) {
    return hash_bytes(hash, &value, sizeof value);
}

/* Every body's position, velocity, angle and spin, and the step's record
 * of contacts (their order, points, separations and impulses), byte by
 * byte. */
static uint64_t scene_hash(scene_t *scene) {
    uint64_t hash = 14695981039346656037ULL;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        vector_t c = body_get_centroid(body), v = body_get_velocity(body);
        hash = hash_double(hash_double(hash, c.x), c.y);
        hash = hash_double(hash_double(hash, v.x), v.y);
        hash = hash_double(hash, body_get_rotation(body));
        hash = hash_double(hash, body_get_angular_velocity(body));
    }
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        const contact_t *contact = scene_get_contact(scene, i);
        hash = hash_double(hash_double(hash, contact->axis.x), contact->axis.y);
        for (size_t j = 0; j < contact->point_count; j++) {
            hash = hash_double(hash_double(hash, contact->points[j].x), contact->points[j].y);
            hash = hash_double(hash, contact->separation[j]);
            hash = hash_double(hash, contact->normal_impulse[j]);
            hash = hash_double(hash, contact->tangent_impulse[j]);
        }
    }
    return hash;
}

static void run(scene_t *scene, int steps) {
    for (int i = 0; i < steps; i++) scene_tick(scene, DT);
}

static const size_t PILE = 400;
static const int STEPS = 240;

/* The hash of the pile after STEPS steps with this many workers. */
static uint64_t pile_hash(size_t workers, bool sleeping) {
    scene_t *scene = build_pile(PILE, workers, sleeping);
    run(scene, STEPS);
    uint64_t hash = scene_hash(scene);
    scene_free(scene);
    return hash;
}

static void any_worker_count_gives_the_same_bytes(void) {
    uint64_t one = pile_hash(1, false);
    CHECK(pile_hash(2, false) == one);
    CHECK(pile_hash(3, false) == one);
}

/* Switching between 1, 3 and 2 workers while the pile falls. */
static void changing_workers_mid_run_gives_the_same_bytes(void) {
    uint64_t one = pile_hash(1, false);
    scene_t *scene = build_pile(PILE, 1, false);
    run(scene, STEPS / 4);
    scene_set_workers(scene, 3);
    CHECK(scene_get_workers(scene) == 3);
    run(scene, STEPS / 4);
    scene_set_workers(scene, 1);
    run(scene, STEPS / 4);
    scene_set_workers(scene, 2);
    run(scene, STEPS / 4);
    CHECK(scene_hash(scene) == one);
    scene_free(scene);
}

/* Workers set while contacts are off reach the world made later. */
static void workers_set_before_contacts_are_kept(void) {
    scene_t *scene = scene_init();
    CHECK(scene_get_workers(scene) == 1);
    scene_set_workers(scene, 2);
    scene_set_contacts_enabled(scene, true);
    scene_set_contacts_enabled(scene, false);
    scene_set_contacts_enabled(scene, true);
    CHECK(scene_get_workers(scene) == 2);
    scene_free(scene);
}

static int count_asleep(scene_t *scene) {
    int asleep = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        asleep += body_is_sleeping(scene_get_body(scene, i));
    }
    return asleep;
}

/* A pile that settles and falls asleep, stepped on 2 workers: the bodies
 * that sleep and every byte are those of one worker, before and after a
 * dropped box wakes part of it. */
static void sleeping_with_workers_gives_the_same_bytes(void) {
    uint64_t hashes[2];
    int asleep[2], asleep_after_drop[2];
    for (size_t w = 0; w < 2; w++) {
        scene_t *scene = build_pile(150, w + 1, true);
        for (size_t i = 3; i < scene_bodies(scene); i++) { /* a pile that settles */
            body_set_friction(scene_get_body(scene, i), 0.6);
            body_set_elasticity(scene_get_body(scene, i), 0.0);
        }
        run(scene, 900);
        asleep[w] = count_asleep(scene);
        body_t *box = body_init(polygon_make_box((vector_t){15.0, 10.0}, 0.5, 0.5), 5.0, GREY);
        scene_add_body(scene, box);
        run(scene, 90);
        asleep_after_drop[w] = count_asleep(scene);
        hashes[w] = scene_hash(scene);
        scene_free(scene);
    }
    CHECK(asleep[0] > 100);
    CHECK(asleep_after_drop[0] < asleep[0]);
    CHECK(asleep[1] == asleep[0]);
    CHECK(asleep_after_drop[1] == asleep_after_drop[0]);
    CHECK(hashes[1] == hashes[0]);
}

static void warm_step_with_workers_allocates_nothing(void) {
    scene_t *scene = build_pile(300, 2, false);
    run(scene, 120);
    CHECK(test_warm_ticks_allocate_nothing(scene, 30, DT));
    scene_free(scene);
}

BAD_CALL(zero_workers, {
    scene_t *scene = scene_init();
    scene_set_workers(scene, 0);
})
BAD_CALL(too_many_workers, {
    scene_t *scene = scene_init();
    scene_set_workers(scene, SCENE_MAX_WORKERS + 1);
})
BAD_CALL(workers_of_null, scene_set_workers(NULL, 2))
BAD_CALL(get_workers_of_null, (void)scene_get_workers(NULL))

/* 200 boxes in a row on 2 workers, bodies 170 and 150 far too fast for
 * dt = 10 s: integration runs on both threads, and the message names body
 * 150, where one thread stops. */
static void tick_two_fast_bodies_on_workers(void) {
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    scene_set_workers(scene, 2);
    for (int i = 0; i < 200; i++) {
        body_t *box = body_init(polygon_make_box((vector_t){3.0 * i, 0.0}, 0.5, 0.5), 1.0, GREY);
        scene_add_body(scene, box);
    }
    body_set_velocity(scene_get_body(scene, 170), (vector_t){1e308, 0.0});
    body_set_velocity(scene_get_body(scene, 150), (vector_t){1e308, 0.0});
    scene_tick(scene, 10.0);
}

BAD_CALL(two_fast_bodies_on_workers, tick_two_fast_bodies_on_workers())

static void a_failed_integration_names_the_first_body(void) {
    CHECK_DIES(two_fast_bodies_on_workers, NULL, "engine error in scene_tick:",
               "integrate stage", "body 150 (centroid (450, 0) before the step)",
               "position is not finite");
}

static void bad_worker_counts_are_refused(void) {
    CHECK_DIES(zero_workers, NULL, "scene_set_workers", "workers must be in [1, 64] (got 0)");
    CHECK_DIES(too_many_workers, NULL, "scene_set_workers", "(got 65)");
    CHECK_DIES(workers_of_null, NULL, "scene_set_workers", "scene is NULL");
    CHECK_DIES(get_workers_of_null, NULL, "scene_get_workers", "scene is NULL");
}

/* The pool: each index of each call is visited once, by the chunk that
 * workers_chunks says holds it, for counts below, at and above the number
 * of chunks, and over many calls in a row; a chunk holds at least 8. */
typedef struct {
    unsigned char visits[1000];
    size_t chunk_of[1000];
} visits_t;

static void visit(void *context, size_t chunk, size_t begin, size_t end) {
    visits_t *v = context;
    for (size_t i = begin; i < end; i++) {
        v->visits[i]++;
        v->chunk_of[i] = chunk;
    }
}

static void pool_visits_every_index_once(void) {
    static const size_t counts[] = {0, 1, 2, 3, 17, 24, 25, 999, 1000};
    for (size_t threads = 2; threads <= 3; threads++) {
        workers_t *workers = workers_init(threads);
        CHECK(workers_count(workers) == threads);
        for (int round = 0; round < 50; round++) {
            for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++) {
                size_t count = counts[c];
                static visits_t v;
                memset(&v, 0, sizeof v);
                workers_for(workers, count, visit, &v);
                size_t chunks = workers_chunks(workers, count);
                CHECK(chunks <= WORKERS_MAX_CHUNKS && chunks <= count);
                CHECK(chunks <= 1 || count >= 8 * chunks); /* not a thread woken for less */
                for (size_t i = 0; i < count; i++) {
                    CHECK(v.visits[i] == 1);
                    size_t k = v.chunk_of[i];
                    CHECK(k * count / chunks <= i && i < (k + 1) * count / chunks);
                }
            }
        }
        workers_free(workers);
    }
    workers_free(NULL);
}

/* workers_each: each index its own chunk, visited once, for counts up to
 * the most chunks (the broadphase's parts: one per worker, which
 * workers_for's least chunk ran on the calling thread alone), with and
 * without a pool; more items than chunks are refused. */
static void each_item_is_a_chunk_of_its_own(void) {
    workers_t *workers = workers_init(2);
    workers_t *pools[2] = {NULL, workers};
    for (size_t p = 0; p < 2; p++) {
        for (size_t count = 0; count <= WORKERS_MAX_CHUNKS; count++) {
            static visits_t v;
            memset(&v, 0, sizeof v);
            workers_each(pools[p], count, visit, &v);
            for (size_t i = 0; i < count; i++) CHECK(v.visits[i] == 1 && v.chunk_of[i] == i);
            CHECK(v.visits[count] == 0);
        }
    }
    workers_free(workers);
}

BAD_CALL(too_many_items, {
    static visits_t v;
    workers_each(NULL, WORKERS_MAX_CHUNKS + 1, visit, &v);
})

static void too_many_items_are_refused(void) {
    CHECK_DIES(too_many_items, NULL, "engine error in workers_each", "at most 64 items (got 65)");
}

/* Three rows of 100 boxes on a floor: each row is a level of the shock
 * pass with more bodies than it spreads over the workers (shock.c's
 * SPLIT_LEVEL), so this runs that pass on several threads. */
static uint64_t rows_hash(size_t workers) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -9.81});
    scene_set_contacts_enabled(scene, true);
    scene_set_workers(scene, workers);
    add_static_box(scene, 60.0, -0.5, 61.0, 0.5);
    pile_state = 7;
    for (size_t row = 0; row < 3; row++) {
        for (size_t k = 0; k < 100; k++) {
            vector_t center = {1.0 + 1.2 * (double)k + 0.1 * pile_random(),
                               0.5 + 1.02 * (double)row + 0.01 * pile_random()};
            body_t *box = body_init(polygon_make_box(center, 0.5, 0.5), 1.0 + pile_random(), GREY);
            scene_add_body(scene, box);
        }
    }
    run(scene, 90);
    uint64_t hash = scene_hash(scene);
    scene_free(scene);
    return hash;
}

static void wide_levels_give_the_same_bytes(void) {
    uint64_t one = rows_hash(1);
    CHECK(rows_hash(2) == one);
    CHECK(rows_hash(3) == one);
}

TEST_SUITE(workers, TEST_CASE(any_worker_count_gives_the_same_bytes),
           TEST_CASE(wide_levels_give_the_same_bytes),
           TEST_CASE(changing_workers_mid_run_gives_the_same_bytes),
           TEST_CASE(workers_set_before_contacts_are_kept),
           TEST_CASE(sleeping_with_workers_gives_the_same_bytes),
           TEST_CASE(warm_step_with_workers_allocates_nothing),
           TEST_CASE(a_failed_integration_names_the_first_body),
           TEST_CASE(bad_worker_counts_are_refused), TEST_CASE(pool_visits_every_index_once),
           TEST_CASE(each_item_is_a_chunk_of_its_own), TEST_CASE(too_many_items_are_refused));
