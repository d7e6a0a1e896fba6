/* When create_collision's handler fires on a pair that world contacts
 * resolve: once per meeting. A landing is one meeting however the body
 * rocks onto its face; a bounce, or a pair that parts and meets again, is a
 * new one. The pair has parted when it is further apart than a tenth of
 * the smaller body's radius at two reads in a row (docs/api.md). */
#include <stdlib.h>
#include "jostle/jostle.h"
#include "test.h"

#define COUNT_OF(array) (sizeof(array) / sizeof((array)[0]))

static const rgb_color_t GREY = {0.5, 0.5, 0.5};
static const double DT = 1.0 / 60.0;
/* The documented parting distance, as a fraction of the smaller radius. */
static const double PARTING_FRACTION = 0.1;

static void count_calls(body_t *body1, body_t *body2, vector_t axis, void *aux,
                        double force_const) {
    (void)body1, (void)body2, (void)axis, (void)force_const;
    (*(int *)aux)++;
}

static body_t *added(scene_t *scene, body_t *body) {
    scene_add_body(scene, body);
    return body;
}

/* The height of the body's lowest vertex. */
static double lowest(body_t *body) {
    polygon_t polygon = body_get_polygon(body);
    double y = INFINITY;
    for (size_t i = 0; i < polygon.count; i++) y = fmin(y, polygon.vertices[i].y);
    return y;
}

/* A static floor whose top is y = 0, wide for a body of radius r; gravity
 * -9.81, world contacts on. */
static scene_t *floor_scene(double r, double elasticity, body_t **floor) {
    scene_t *scene = scene_init();
    scene_set_contacts_enabled(scene, true);
    scene_set_gravity(scene, (vector_t){0, -9.81});
    *floor = added(scene, body_init(polygon_make_box((vector_t){0, -r}, 40 * r, r), INFINITY,
                                    GREY));
    body_set_elasticity(*floor, elasticity);
    return scene;
}

/* 72 drops at e = 0: regular polygons of 3 to 8 sides, 1 cm, 1 m and 10 m
 * across, falling 1 and 5 radii, turned so that most land on a corner and
 * tip onto a face (which lifts the first corner off the floor for a few
 * steps: a rocking block's hop, up to 6% of the radius here). Each landing
 * fires the handler once. */
static void a_landing_fires_once(void) {
    const double radii[] = {0.005, 0.5, 5.0};
    const double falls[] = {1.0, 5.0};
    const double angles[] = {0.1, 0.35};
    int drops = 0, wrong = 0;
    for (int sides = 3; sides <= 8; sides++) {
        for (size_t s = 0; s < COUNT_OF(radii); s++) {
            for (size_t f = 0; f < COUNT_OF(falls); f++) {
                for (size_t a = 0; a < COUNT_OF(angles); a++) {
                    double r = radii[s];
                    body_t *floor;
                    scene_t *scene = floor_scene(r, 0.0, &floor);
                    vector_t start = {0, (1.0 + falls[f]) * r};
                    body_t *body = added(scene, body_init(polygon_make_regular(sides, r, start,
                                                                               angles[a]),
                                                          r * r, GREY));
                    body_set_elasticity(body, 0.0);
                    int calls = 0;
                    create_collision(scene, body, floor, count_calls, &calls, 0.0);
                    for (int tick = 0; tick < 300; tick++) scene_tick(scene, DT);
                    drops++;
                    if (calls != 1) {
                        wrong++;
                        printf("    %d sides, radius %g m, fall %g r, angle %g: %d calls\n",
                               sides, r, falls[f], angles[a], calls);
                    }
                    /* At rest on the floor, within the solver's slop (1% of the radius). */
                    CHECK(fabs(lowest(body)) <= 0.011 * r);
                    scene_free(scene);
                }
            }
        }
    }
    CHECK(drops == 72);
    CHECK(wrong == 0);
}

/* A ball (a 20-gon) at e = 0.8 dropped 2 m + 4 radii, for radii 0.5 cm to
 * 5 m: each bounce is a new meeting, until the bounces die out (below
 * 1 m/s the solver does not bounce). A flight whose apex clears twice the
 * parting distance ends in a new call; one under the parting distance does
 * not. */
static void each_bounce_fires_once(void) {
    const double radii[] = {0.005, 0.05, 0.5, 5.0};
    for (size_t s = 0; s < COUNT_OF(radii); s++) {
        double r = radii[s], parting = PARTING_FRACTION * r;
        body_t *floor;
        scene_t *scene = floor_scene(r, 0.8, &floor);
        vector_t start = {0, 2.0 + 5.0 * r}; /* 2 m + 4 r above the floor */
        body_t *ball = added(scene, body_init(polygon_make_regular(20, r, start, 0.0), 1.0, GREY));
        body_set_elasticity(ball, 0.8);
        int calls = 0;
        create_collision(scene, ball, floor, count_calls, &calls, 0.0);
        /* The flights between impacts (the vertical velocity turning from
         * down to up), by their apex: each after the first impact ends in
         * another meeting, an impact or the final landing. */
        bool flying = false;
        double apex = 0.0, vy = 0.0;
        int clear = 0, above = 0; /* apexes over 2 and over 1 parting distance */
        for (int tick = 0; tick < 1200; tick++) {
            scene_tick(scene, DT);
            double previous = vy, gap = lowest(ball);
            vy = body_get_velocity(ball).y;
            if (previous < 0.0 && vy > 0.0) { /* an impact in this step */
                clear += flying && apex > 2.0 * parting;
                above += flying && apex > parting;
                flying = true;
                apex = 0.0;
            }
            apex = fmax(apex, gap);
        }
        clear += flying && apex > 2.0 * parting;
        above += flying && apex > parting;
        if (calls < 1 + clear || calls > 1 + above) {
            printf("    radius %g m: %d calls, %d bounces over 2 d, %d over d\n", r, calls,
                   clear, above);
        }
        CHECK(clear >= 3);
        CHECK(calls >= 1 + clear);
        CHECK(calls <= 1 + above);
        scene_free(scene);
    }
}

/* Two squares of half side h, no gravity, e = 0: a meets b, then is put
 * back at a gap and pushed in again. The pair parts only when the gap is
 * over the parting distance at two reads in a row. */
static void parting_is_relative_to_size_and_lasts_a_step(void) {
    const double halves[] = {0.005, 0.05, 0.5, 5.0};
    for (size_t s = 0; s < COUNT_OF(halves); s++) {
        double h = halves[s], speed = 2.0 * h / 0.1; /* a side per 0.1 s */
        double parting = PARTING_FRACTION * h * sqrt(2.0);
        scene_t *scene = scene_init();
        scene_set_contacts_enabled(scene, true);
        scene_set_sleeping(scene, false);
        body_t *a = added(scene, body_init(polygon_make_box((vector_t){-3 * h, 0}, h, h), 1.0,
                                           GREY));
        body_t *b = added(scene, body_init(polygon_make_box(VEC_ZERO, h, h), 2.0, GREY));
        body_set_elasticity(a, 0.0);
        body_set_elasticity(b, 0.0);
        int calls = 0;
        create_collision(scene, a, b, count_calls, &calls, 0.0);
        body_set_velocity(a, (vector_t){speed, 0});
        for (int tick = 0; tick < 30; tick++) scene_tick(scene, DT);
        CHECK(calls == 1);
        /* Put a back at `gap` parting distances from b, held at rest for
         * `hold` ticks (the first read may still see the last step's
         * contact), then pushed in for 30 ticks at `closing` parting
         * distances per step (0: a side per 0.1 s). */
        const struct {
            double gap;
            int hold;
            double closing;
            int calls_after;
        } steps[] = {
            {0.5, 20, 0.0, 1}, /* within the parting distance, however long */
            {3.0, 0, 2.5, 1},  /* beyond it at one read: at the next, 0.5 apart */
            {1.5, 3, 0.0, 2},  /* beyond it at two reads: parted, the push meets again */
            {0.9, 5, 0.0, 2},
            {20.0, 3, 0.0, 3},
        };
        for (size_t k = 0; k < COUNT_OF(steps); k++) {
            double x = body_get_centroid(b).x - 2 * h - steps[k].gap * parting;
            body_set_centroid(a, (vector_t){x, 0});
            body_set_rotation(a, body_get_rotation(b));
            body_set_velocity(a, VEC_ZERO);
            body_set_angular_velocity(a, 0.0);
            body_set_velocity(b, VEC_ZERO);
            body_set_angular_velocity(b, 0.0);
            for (int tick = 0; tick < steps[k].hold; tick++) scene_tick(scene, DT);
            double closing = steps[k].closing > 0.0 ? steps[k].closing * parting / DT : speed;
            body_set_velocity(a, (vector_t){closing, 0});
            for (int tick = 0; tick < 30; tick++) scene_tick(scene, DT);
            if (calls != steps[k].calls_after) {
                printf("    half side %g m, gap %g d held %d ticks: %d calls, expected %d\n", h,
                       steps[k].gap, steps[k].hold, calls, steps[k].calls_after);
            }
            CHECK(calls == steps[k].calls_after);
        }
        scene_free(scene);
    }
}

TEST_SUITE(collision_events, TEST_CASE(a_landing_fires_once), TEST_CASE(each_bounce_fires_once),
           TEST_CASE(parting_is_relative_to_size_and_lasts_a_step));
