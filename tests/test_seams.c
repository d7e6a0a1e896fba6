/* Seams between static bodies: a body slides over tiles laid flush as it
 * slides over one long body (no "ghost collision" at the tiles' shared
 * edges), while a genuine step still stops it; the engine's knowledge of
 * which tiles are flush follows tiles that move, go, change filter or come.
 *
 * Each glide runs the tiled scene in lockstep with the same scene on one
 * long static body and compares them step by step. Tolerances are the
 * issue's: height (distance from the surface) within 1 mm of the long
 * surface's, rotation under 1e-6 rad, speed within 0.1%. */
#include <math.h>
#include <string.h>
#include "jostle/jostle.h"
#include "test.h"

static const double DT = 1.0 / 60.0;
static const double G = 9.81;
static const rgb_color_t GREY = {0.5, 0.5, 0.5};
enum { TILES = 40 };

static const double HEIGHT_TOLERANCE = 1e-3;  /* m */
static const double ANGLE_TOLERANCE = 1e-6;   /* rad */
static const double SPEED_TOLERANCE = 1e-3;   /* relative */

static scene_t *seam_scene(vector_t gravity) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, gravity);
    scene_set_contacts_enabled(scene, true);
    return scene;
}

/* A static box spanning [x0, x1] x [y0, y1] with friction mu. */
static body_t *add_block(scene_t *scene, double x0, double y0, double x1, double y1, double mu) {
    body_t *block = body_init(POLYGON({x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}), INFINITY, GREY);
    body_set_friction(block, mu);
    scene_add_body(scene, block);
    return block;
}

/* count tiles laid along x from 0, tile i widths[i % w] wide and
 * depths[i % d] deep below its top face at y = 0; returns where they end. */
static double add_floor_tiles(scene_t *scene, const double *widths, size_t w,
                              const double *depths, size_t d, size_t count, double mu) {
    double x = 0.0;
    for (size_t i = 0; i < count; i++) {
        double next = x + widths[i % w];
        add_block(scene, x, -depths[i % d], next, 0.0, mu);
        x = next;
    }
    return x;
}

/* A 0.5 m box of 1 kg resting on y = 0 with its centre at x. */
static body_t *add_box(scene_t *scene, double x, double mu) {
    body_t *box = body_init(polygon_make_box((vector_t){x, 0.25}, 0.25, 0.25), 1.0, GREY);
    body_set_friction(box, mu);
    scene_add_body(scene, box);
    return box;
}

/* The largest differences between a box on tiles and the same box on one
 * long body over a run: position across the surface (m), rotation (rad),
 * speed relative to the long surface's (and position along it, m). */
typedef struct {
    double across, angle, speed, along;
    int steps; /* how many were run */
} drift_t;

/* Steps both scenes until the box on tiles passes `until` along `along`
 * (a unit vector) or `steps` steps have run, and measures the drift. */
static drift_t glide(scene_t *tiled, body_t *box, scene_t *whole, body_t *reference,
                     vector_t along, double until, int steps) {
    drift_t drift = {0.0, 0.0, 0.0, 0.0, 0};
    vector_t across = {-along.y, along.x};
    for (; drift.steps < steps && vec_dot(body_get_centroid(box), along) < until; drift.steps++) {
        scene_tick(tiled, DT);
        scene_tick(whole, DT);
        vector_t offset = vec_subtract(body_get_centroid(box), body_get_centroid(reference));
        drift.across = fmax(drift.across, fabs(vec_dot(offset, across)));
        drift.along = fmax(drift.along, fabs(vec_dot(offset, along)));
        drift.angle = fmax(drift.angle, fabs(body_get_rotation(box)));
        double speed = vec_get_length(body_get_velocity(reference));
        double difference = vec_get_length(
            vec_subtract(body_get_velocity(box), body_get_velocity(reference)));
        if (speed > 0.0) drift.speed = fmax(drift.speed, difference / speed);
    }
    return drift;
}

static void check_glides(drift_t drift) {
    CHECK(drift.across <= HEIGHT_TOLERANCE);
    CHECK(drift.angle < ANGLE_TOLERANCE);
    CHECK(drift.speed <= SPEED_TOLERANCE);
    if (!(drift.across <= HEIGHT_TOLERANCE && drift.angle < ANGLE_TOLERANCE &&
          drift.speed <= SPEED_TOLERANCE)) {
        printf("  drift: across %.3g m, angle %.3g rad, speed %.3g, along %.3g m\n",
               drift.across, drift.angle, drift.speed, drift.along);
    }
}

/* A frictionless box sliding at speed over a floor of tiles (widths and
 * depths cycled) against the same box on one floor as long. */
static void glide_over_floor(const double *widths, size_t w, const double *depths, size_t d,
                             double speed, double mu) {
    scene_t *tiled = seam_scene((vector_t){0.0, -G});
    double end = add_floor_tiles(tiled, widths, w, depths, d, TILES, mu);
    body_t *box = add_box(tiled, 0.5, mu);
    body_set_velocity(box, (vector_t){speed, 0.0});
    scene_t *whole = seam_scene((vector_t){0.0, -G});
    add_block(whole, 0.0, -1.0, end, 0.0, mu);
    body_t *reference = add_box(whole, 0.5, mu);
    body_set_velocity(reference, (vector_t){speed, 0.0});
    int steps = (int)((end - 1.0) / speed / DT) + 1;
    check_glides(glide(tiled, box, whole, reference, (vector_t){1.0, 0.0}, end - 0.5, steps));
    scene_free(tiled);
    scene_free(whole);
}

static const double SPEEDS[] = {0.5, 1.0, 5.0, 20.0};
enum { SPEED_COUNT = sizeof(SPEEDS) / sizeof(SPEEDS[0]) };

/* 40 tiles of 1 m, flush: from 0.5 to 20 m/s the box glides. */
static void box_glides_over_flush_tiles(void) {
    const double width = 1.0, depth = 1.0;
    for (int k = 0; k < SPEED_COUNT; k++) glide_over_floor(&width, 1, &depth, 1, SPEEDS[k], 0.0);
}

/* Tiles from 0.3 m (narrower than the box, which then spans three) to
 * 2.2 m wide. */
static const double WIDTHS[] = {0.3, 1.7, 0.55, 1.0, 2.2, 0.8, 0.35, 1.3};
enum { WIDTH_COUNT = sizeof(WIDTHS) / sizeof(WIDTHS[0]) };

static void box_glides_over_tiles_of_differing_widths(void) {
    const double depth = 1.0;
    for (int k = 0; k < SPEED_COUNT; k++) {
        glide_over_floor(WIDTHS, WIDTH_COUNT, &depth, 1, SPEEDS[k], 0.0);
    }
}

/* Tiles of differing widths and depths whose top faces are flush: a tile's
 * side is then partly covered by its neighbour and partly open below it. */
static void box_glides_over_tiles_of_differing_heights(void) {
    const double depths[] = {1.0, 0.25, 2.0, 0.6, 0.1};
    for (int k = 0; k < SPEED_COUNT; k++) {
        glide_over_floor(WIDTHS, WIDTH_COUNT, depths, 5, SPEEDS[k], 0.0);
    }
}

/* With friction mu = 0.5 the box decelerates at mu g on tiles exactly as
 * on one floor: same speed and place step by step, and it stops where
 * theory says, v^2 / (2 mu g) on. */
static void friction_on_tiles_decelerates_as_on_one_floor(void) {
    const double width = 1.0, depth = 1.0, mu = 0.5, speed = 10.0;
    scene_t *tiled = seam_scene((vector_t){0.0, -G});
    add_floor_tiles(tiled, &width, 1, &depth, 1, TILES, mu);
    body_t *box = add_box(tiled, 0.5, mu);
    body_set_velocity(box, (vector_t){speed, 0.0});
    scene_t *whole = seam_scene((vector_t){0.0, -G});
    add_block(whole, 0.0, -1.0, TILES, 0.0, mu);
    body_t *reference = add_box(whole, 0.5, mu);
    body_set_velocity(reference, (vector_t){speed, 0.0});
    double stop_time = speed / (mu * G);
    int steps = (int)(stop_time / DT) - 1;
    drift_t drift = glide(tiled, box, whole, reference, (vector_t){1.0, 0.0}, TILES, steps);
    check_glides(drift);
    CHECK(drift.along <= 1e-6);
    /* Still sliding: the speed is theory's v0 - mu g t. */
    CHECK(drift.steps == steps);
    CHECK_NEAR(body_get_velocity(box).x, speed - mu * G * steps * DT, 1e-6 * speed);
    for (int i = 0; i < 120; i++) scene_tick(tiled, DT);
    CHECK_NEAR(body_get_centroid(box).x, 0.5 + speed * speed / (2.0 * mu * G), 0.01);
    CHECK_NEAR(body_get_velocity(box).x, 0.0, 1e-9);
    scene_free(tiled);
    scene_free(whole);
}

/* A static wall of stacked tiles spanning [-1, 0] in x, tile i heights[i %
 * h] tall, from y = 0 up; returns its top. */
static double add_wall_tiles(scene_t *scene, const double *heights, size_t h, size_t count) {
    double y = 0.0;
    for (size_t i = 0; i < count; i++) {
        double next = y + heights[i % h];
        add_block(scene, -1.0, y, 0.0, next, 0.0);
        y = next;
    }
    return y;
}

/* Gravity along a wall, leaning 0.5 m/s^2 into it: a box pressed lightly
 * on a wall of 40 stacked tiles falls along it as beside one long wall,
 * freely (frictionless), 40 m in 2.8 s, catching on no seam. */
static void box_falls_along_a_wall_of_stacked_tiles(void) {
    const double heights[] = {1.0, 0.4, 1.6};
    const vector_t gravity = {-0.5, -G};
    scene_t *tiled = seam_scene(gravity);
    double top = add_wall_tiles(tiled, heights, 3, TILES);
    scene_t *whole = seam_scene(gravity);
    add_block(whole, -1.0, 0.0, 0.0, top, 0.0);
    body_t *boxes[2];
    scene_t *scenes[2] = {tiled, whole};
    for (int k = 0; k < 2; k++) {
        boxes[k] = body_init(polygon_make_box((vector_t){0.25, top - 0.5}, 0.25, 0.25), 1.0, GREY);
        body_set_friction(boxes[k], 0.0);
        body_set_velocity(boxes[k], (vector_t){0.0, -1.0});
        scene_add_body(scenes[k], boxes[k]);
    }
    drift_t drift = glide(tiled, boxes[0], whole, boxes[1], (vector_t){0.0, -1.0}, -1.0, 1000);
    check_glides(drift);
    CHECK(drift.along <= HEIGHT_TOLERANCE);
    /* Past every seam, in free fall along the wall: v = v0 - g t. */
    CHECK(body_get_centroid(boxes[0]).y <= 1.0);
    CHECK_RELATIVE(body_get_velocity(boxes[0]).y, -1.0 - G * drift.steps * DT, SPEED_TOLERANCE);
    scene_free(tiled);
    scene_free(whole);
}

/* A wall standing on a floor with their outer faces flush (x = 0) makes a
 * seam on the outside: a box falling down the wall's outer face (gravity
 * leaning into it as above) passes on down the floor's end face as beside
 * one wall 11 m high. */
static void box_falls_past_a_wall_standing_on_a_floor(void) {
    const vector_t gravity = {0.5, -G};
    scene_t *tiled = seam_scene(gravity);
    add_block(tiled, 0.0, -1.0, 20.0, 0.0, 0.0); /* floor */
    add_block(tiled, 0.0, 0.0, 1.0, 10.0, 0.0);  /* wall standing on it */
    scene_t *whole = seam_scene(gravity);
    add_block(whole, 0.0, -1.0, 1.0, 10.0, 0.0);
    body_t *boxes[2];
    scene_t *scenes[2] = {tiled, whole};
    for (int k = 0; k < 2; k++) {
        /* 0.5 mm into the wall, as a resting contact may be (the slop) */
        boxes[k] = body_init(polygon_make_box((vector_t){-0.2495, 9.5}, 0.25, 0.25), 1.0, GREY);
        body_set_friction(boxes[k], 0.0);
        body_set_velocity(boxes[k], (vector_t){0.0, -1.0});
        scene_add_body(scenes[k], boxes[k]);
    }
    /* until its centre is 0.5 m below the seam, the box still on the floor's end face */
    drift_t drift = glide(tiled, boxes[0], whole, boxes[1], (vector_t){0.0, -1.0}, 0.5, 1000);
    check_glides(drift);
    CHECK(body_get_centroid(boxes[0]).y <= -0.5);
    CHECK_RELATIVE(body_get_velocity(boxes[0]).y, -1.0 - G * drift.steps * DT, SPEED_TOLERANCE);
    scene_free(tiled);
    scene_free(whole);
}

/* Boxes turned 0.3 to 1.2 rad dropped corner first just beside a seam,
 * their lower edge leaning over the next tile: they land, tip and come to
 * rest as on one floor (the tile under the corner holds the contact). */
static void turned_boxes_land_beside_a_seam_as_on_one_floor(void) {
    const double offsets[] = {-0.2, -0.05, -0.01, 0.0, 0.01, 0.05, 0.2};
    for (int k = 0; k < 7; k++) {
        for (int turn = 0; turn < 4; turn++) {
            double angle = 0.3 + 0.3 * turn;
            scene_t *tiled = seam_scene((vector_t){0.0, -G});
            for (int i = 0; i < 6; i++) add_block(tiled, i, -1.0, i + 1.0, 0.0, 0.0);
            scene_t *whole = seam_scene((vector_t){0.0, -G});
            add_block(whole, 0.0, -1.0, 6.0, 0.0, 0.0);
            body_t *boxes[2];
            scene_t *scenes[2] = {tiled, whole};
            for (int j = 0; j < 2; j++) {
                list_t *shape = polygon_make_box((vector_t){0.0, 0.0}, 0.25, 0.25);
                polygon_rotate(shape, angle, VEC_ZERO);
                boxes[j] = body_init(shape, 1.0, GREY);
                body_set_friction(boxes[j], 0.4);
                /* its lowest corner 2 cm above the floor, offsets[k] from the seam at x = 3 */
                aabb_t bounds = body_get_bounds(boxes[j]);
                list_t *probe = body_get_shape(boxes[j]);
                double lowest_x = 0.0;
                for (size_t v = 0; v < list_size(probe); v++) {
                    vector_t *p = list_get(probe, v);
                    if (p->y == bounds.min.y) lowest_x = p->x;
                }
                list_free(probe);
                body_set_centroid(boxes[j], (vector_t){3.0 + offsets[k] - lowest_x,
                                                       0.02 - bounds.min.y});
                scene_add_body(scenes[j], boxes[j]);
            }
            drift_t drift =
                glide(tiled, boxes[0], whole, boxes[1], (vector_t){1.0, 0.0}, 10.0, 180);
            CHECK(drift.across <= HEIGHT_TOLERANCE);
            CHECK(drift.along <= HEIGHT_TOLERANCE);
            CHECK(fabs(body_get_rotation(boxes[0]) - body_get_rotation(boxes[1])) < 1e-3);
            scene_free(tiled);
            scene_free(whole);
        }
    }
}

/* Gravity presses the box onto the wall (the floor test turned a quarter):
 * it slides up along the 40 stacked tiles at 0.5 to 20 m/s. */
static void box_pressed_on_a_tiled_wall_slides_along_it(void) {
    const double heights[] = {1.0, 0.4, 1.6};
    for (int k = 0; k < SPEED_COUNT; k++) {
        scene_t *tiled = seam_scene((vector_t){-G, 0.0});
        double top = add_wall_tiles(tiled, heights, 3, TILES);
        body_t *box = body_init(polygon_make_box((vector_t){0.25, 0.5}, 0.25, 0.25), 1.0, GREY);
        body_set_friction(box, 0.0);
        body_set_velocity(box, (vector_t){0.0, SPEEDS[k]});
        scene_add_body(tiled, box);
        scene_t *whole = seam_scene((vector_t){-G, 0.0});
        add_block(whole, -1.0, 0.0, 0.0, top, 0.0);
        body_t *reference =
            body_init(polygon_make_box((vector_t){0.25, 0.5}, 0.25, 0.25), 1.0, GREY);
        body_set_friction(reference, 0.0);
        body_set_velocity(reference, (vector_t){0.0, SPEEDS[k]});
        scene_add_body(whole, reference);
        int steps = (int)((top - 1.0) / SPEEDS[k] / DT) + 1;
        check_glides(glide(tiled, box, whole, reference, (vector_t){0.0, 1.0}, top - 0.5, steps));
        scene_free(tiled);
        scene_free(whole);
    }
}

/* Tiles laid along a 20 degree slope (each turned, so their corners come
 * from sines and cosines): a frictionless box slides down them as down one
 * long slope, at g sin(20 deg). */
static void box_slides_down_a_slope_of_tiles(void) {
    const double angle = -20.0 * M_PI / 180.0;
    vector_t along = {cos(angle), sin(angle)};
    scene_t *tiled = seam_scene((vector_t){0.0, -G});
    for (int i = 0; i < 20; i++) {
        list_t *shape = POLYGON({i, -1.0}, {i + 1.0, -1.0}, {i + 1.0, 0.0}, {i, 0.0});
        polygon_rotate(shape, angle, VEC_ZERO);
        body_t *tile = body_init(shape, INFINITY, GREY);
        body_set_friction(tile, 0.0);
        scene_add_body(tiled, tile);
    }
    list_t *long_shape = POLYGON({0.0, -1.0}, {20.0, -1.0}, {20.0, 0.0}, {0.0, 0.0});
    polygon_rotate(long_shape, angle, VEC_ZERO);
    scene_t *whole = seam_scene((vector_t){0.0, -G});
    body_t *slope = body_init(long_shape, INFINITY, GREY);
    body_set_friction(slope, 0.0);
    scene_add_body(whole, slope);
    body_t *boxes[2];
    scene_t *scenes[2] = {tiled, whole};
    for (int k = 0; k < 2; k++) {
        list_t *shape = polygon_make_box((vector_t){0.5, 0.25}, 0.25, 0.25);
        polygon_rotate(shape, angle, VEC_ZERO);
        boxes[k] = body_init(shape, 1.0, GREY);
        body_set_friction(boxes[k], 0.0);
        body_set_velocity(boxes[k], vec_multiply(1.0, along));
        scene_add_body(scenes[k], boxes[k]);
    }
    drift_t drift = glide(tiled, boxes[0], whole, boxes[1], along, 19.5, 1000);
    CHECK(drift.across <= HEIGHT_TOLERANCE);
    CHECK(drift.speed <= SPEED_TOLERANCE);
    CHECK(drift.angle < ANGLE_TOLERANCE); /* the boxes are made turned: their angle starts at 0 */
    CHECK(vec_dot(body_get_centroid(boxes[0]), along) >= 19.5);
    scene_free(tiled);
    scene_free(whole);
}

/* The furthest the box's centre goes in x over `steps` steps, and the most
 * it turns. */
static double furthest_x(scene_t *scene, body_t *box, int steps, double *turn) {
    double furthest = -INFINITY;
    *turn = 0.0;
    for (int i = 0; i < steps; i++) {
        scene_tick(scene, DT);
        furthest = fmax(furthest, body_get_centroid(box).x);
        *turn = fmax(*turn, fabs(body_get_rotation(box)));
    }
    return furthest;
}

/* The box meets the step at x = 5 (its centre then at 4.75) and is
 * stopped: it rocks on the step's edge (its centre goes at most 0.1 m on)
 * but never gets onto it, and ends back before it. */
static void check_stopped_at_step(scene_t *scene, body_t *box) {
    double turn;
    CHECK(furthest_x(scene, box, 300, &turn) < 4.85);
    CHECK(body_get_centroid(box).x <= 4.75 + 1e-3);
    CHECK(body_get_velocity(box).x <= 1e-9);
}

/* A genuine step, tile 5 one centimetre higher, is not a seam: at 0.5 and
 * 1 m/s it stops the box; at 5 m/s the box trips over it (turns by more
 * than 0.1 rad) instead of gliding on. */
static void one_centimetre_step_stops_the_box(void) {
    const double speeds[] = {0.5, 1.0, 5.0};
    for (int k = 0; k < 3; k++) {
        scene_t *scene = seam_scene((vector_t){0.0, -G});
        for (int i = 0; i < 10; i++) add_block(scene, i, -1.0, i + 1.0, i == 5 ? 0.01 : 0.0, 0.0);
        body_t *box = add_box(scene, 2.5, 0.0);
        body_set_velocity(box, (vector_t){speeds[k], 0.0});
        if (speeds[k] < 2.0) {
            check_stopped_at_step(scene, box);
        } else {
            double turn;
            furthest_x(scene, box, 60, &turn);
            CHECK(turn > 0.1);
        }
        scene_free(scene);
    }
}

/* Moving a tile 1 cm up after the scene has run makes it a step, which
 * stops the box as above: what the engine knew of the flush tiles goes. */
static void raising_a_tile_makes_a_step(void) {
    scene_t *scene = seam_scene((vector_t){0.0, -G});
    body_t *tiles[10];
    for (int i = 0; i < 10; i++) tiles[i] = add_block(scene, i, -1.0, i + 1.0, 0.0, 0.0);
    body_t *box = add_box(scene, 1.5, 0.0);
    body_set_velocity(box, (vector_t){1.0, 0.0});
    for (int i = 0; i < 60; i++) scene_tick(scene, DT);
    CHECK(body_get_velocity(box).x > 0.999); /* it glided over a seam */
    body_set_centroid(tiles[5], vec_add(body_get_centroid(tiles[5]), (vector_t){0.0, 0.01}));
    check_stopped_at_step(scene, box);
    scene_free(scene);
}

/* The box slides into the 1 m gap a missing tile 5 leaves (the tiles are
 * 1 m deep, with nothing below) and falls through it: tile 6's side, no
 * longer covered, stops it instead of lifting it onto tile 6. */
static void check_box_falls_through_gap(scene_t *scene, body_t *box) {
    for (int i = 0; i < 240; i++) scene_tick(scene, DT);
    CHECK(body_get_centroid(box).y < -5.0);
}

/* Removing a tile opens a gap. */
static void removing_a_tile_opens_a_gap(void) {
    scene_t *scene = seam_scene((vector_t){0.0, -G});
    for (int i = 0; i < 10; i++) add_block(scene, i, -1.0, i + 1.0, 0.0, 0.0);
    body_t *box = add_box(scene, 2.5, 0.0);
    body_set_velocity(box, (vector_t){1.0, 0.0});
    for (int i = 0; i < 30; i++) scene_tick(scene, DT);
    scene_remove_body(scene, 5);
    check_box_falls_through_gap(scene, box);
    scene_free(scene);
}

/* A tile whose collision filter keeps the box out is no neighbour of the
 * tiles beside it: for the box there is a gap. */
static void tile_filtered_out_is_no_neighbour(void) {
    scene_t *scene = seam_scene((vector_t){0.0, -G});
    for (int i = 0; i < 10; i++) {
        body_t *tile = add_block(scene, i, -1.0, i + 1.0, 0.0, 0.0);
        if (i == 5) body_set_collision_filter(tile, 2, UINT32_MAX, 0);
    }
    body_t *box = add_box(scene, 2.5, 0.0);
    body_set_collision_filter(box, 1, 1, 0);
    body_set_velocity(box, (vector_t){1.0, 0.0});
    check_box_falls_through_gap(scene, box);
    scene_free(scene);
}

/* The same, the filter set after the scene has run with the tile in. */
static void changing_a_filter_after_running(void) {
    scene_t *scene = seam_scene((vector_t){0.0, -G});
    body_t *tiles[10];
    for (int i = 0; i < 10; i++) tiles[i] = add_block(scene, i, -1.0, i + 1.0, 0.0, 0.0);
    body_t *box = add_box(scene, 2.5, 0.0);
    body_set_collision_filter(box, 1, 1, 0);
    body_set_velocity(box, (vector_t){1.0, 0.0});
    for (int i = 0; i < 30; i++) scene_tick(scene, DT);
    body_set_collision_filter(tiles[5], 2, UINT32_MAX, 0);
    check_box_falls_through_gap(scene, box);
    scene_free(scene);
}

/* A tile removed while world contacts are off: switched on again, the
 * world knows of no seam the tile made. */
static void contacts_switched_off_and_on_forget_old_tiles(void) {
    scene_t *scene = seam_scene((vector_t){0.0, -G});
    for (int i = 0; i < 10; i++) add_block(scene, i, -1.0, i + 1.0, 0.0, 0.0);
    body_t *box = add_box(scene, 2.5, 0.0);
    body_set_velocity(box, (vector_t){1.0, 0.0});
    for (int i = 0; i < 30; i++) scene_tick(scene, DT);
    scene_set_contacts_enabled(scene, false);
    scene_remove_body(scene, 5);
    vector_t where = body_get_centroid(box);
    scene_tick(scene, 0.0); /* reaps the tile, moves nothing */
    scene_set_contacts_enabled(scene, true);
    CHECK(body_get_centroid(box).x == where.x);
    check_box_falls_through_gap(scene, box);
    scene_free(scene);
}

/* Tiles added while the box slides join the floor: it glides over all. */
static void tiles_added_later_join_the_floor(void) {
    const double speed = 5.0;
    scene_t *tiled = seam_scene((vector_t){0.0, -G});
    const double width = 1.0, depth = 1.0;
    add_floor_tiles(tiled, &width, 1, &depth, 1, 20, 0.0);
    body_t *box = add_box(tiled, 0.5, 0.0);
    body_set_velocity(box, (vector_t){speed, 0.0});
    scene_t *whole = seam_scene((vector_t){0.0, -G});
    add_block(whole, 0.0, -1.0, TILES, 0.0, 0.0);
    body_t *reference = add_box(whole, 0.5, 0.0);
    body_set_velocity(reference, (vector_t){speed, 0.0});
    check_glides(glide(tiled, box, whole, reference, (vector_t){1.0, 0.0}, 10.0, 1000));
    for (int i = 20; i < TILES; i++) add_block(tiled, i, -1.0, i + 1.0, 0.0, 0.0);
    check_glides(glide(tiled, box, whole, reference, (vector_t){1.0, 0.0}, TILES - 0.5, 1000));
    CHECK(body_get_centroid(box).x >= TILES - 0.5);
    scene_free(tiled);
    scene_free(whole);
}

/* The seams change nothing in how the work is split over threads: the
 * box over tiles of differing widths ends on the same bytes with 1, 2 and
 * 3 workers. */
static void workers_give_the_same_bytes(void) {
    const double depth = 1.0;
    vector_t where[3];
    double angle[3];
    for (size_t workers = 1; workers <= 3; workers++) {
        scene_t *scene = seam_scene((vector_t){0.0, -G});
        scene_set_workers(scene, workers);
        add_floor_tiles(scene, WIDTHS, WIDTH_COUNT, &depth, 1, TILES, 0.3);
        for (int k = 0; k < 8; k++) {
            body_t *box = add_box(scene, 0.5 + 4.0 * k, 0.3);
            body_set_velocity(box, (vector_t){3.0 + k, 0.0});
        }
        for (int i = 0; i < 120; i++) scene_tick(scene, DT);
        body_t *last = scene_get_body(scene, scene_bodies(scene) - 1);
        where[workers - 1] = body_get_centroid(last);
        angle[workers - 1] = body_get_rotation(last);
        scene_free(scene);
    }
    for (int k = 1; k < 3; k++) {
        CHECK(memcmp(&where[k], &where[0], sizeof where[0]) == 0);
        CHECK(memcmp(&angle[k], &angle[0], sizeof angle[0]) == 0);
    }
}

/* Two static boxes whose top faces overlap flush, over [0, 1]: one
 * surface, each holding its side of the overlap's middle (x = 0.5). A box
 * resting on the overlap at x = 0.3 or 0.8 has one contact, with the box
 * on that side, bearing its weight (m g dt per step, to 1e-6 relative). */
static void box_on_overlapping_tiles_meets_one_face(void) {
    const double at[2] = {0.3, 0.8};
    for (int k = 0; k < 2; k++) {
        scene_t *scene = seam_scene((vector_t){0.0, -G});
        scene_set_sleeping(scene, false); /* a sleeping pair's contact is not recorded */
        body_t *left = add_block(scene, -2.0, -1.0, 1.0, 0.0, 0.0);
        body_t *right = add_block(scene, 0.0, -0.5, 3.0, 0.0, 0.0);
        body_t *box = add_box(scene, at[k], 0.0);
        for (int step = 0; step < 60; step++) scene_tick(scene, DT);
        int with_left = 0, with_right = 0;
        double impulse = 0.0;
        for (size_t i = 0; i < scene_contact_count(scene); i++) {
            const contact_t *c = scene_get_contact(scene, i);
            if (c->point_count == 0 || (c->body1 != box && c->body2 != box)) continue;
            with_left += c->body1 == left || c->body2 == left;
            with_right += c->body1 == right || c->body2 == right;
            for (size_t j = 0; j < c->point_count; j++) impulse += c->normal_impulse[j];
        }
        CHECK(with_left == (k == 0) && with_right == (k == 1));
        CHECK_RELATIVE(impulse, G * DT, 1e-6);
        if (!(with_left == (k == 0) && with_right == (k == 1))) {
            printf("  at x = %g: %d contacts with the left box, %d with the right\n", at[k],
                   with_left, with_right);
        }
        scene_free(scene);
    }
}

TEST_SUITE(seams, TEST_CASE(box_glides_over_flush_tiles),
           TEST_CASE(box_glides_over_tiles_of_differing_widths),
           TEST_CASE(box_glides_over_tiles_of_differing_heights),
           TEST_CASE(friction_on_tiles_decelerates_as_on_one_floor),
           TEST_CASE(box_falls_along_a_wall_of_stacked_tiles),
           TEST_CASE(box_falls_past_a_wall_standing_on_a_floor),
           TEST_CASE(turned_boxes_land_beside_a_seam_as_on_one_floor),
           TEST_CASE(box_pressed_on_a_tiled_wall_slides_along_it),
           TEST_CASE(box_slides_down_a_slope_of_tiles),
           TEST_CASE(one_centimetre_step_stops_the_box), TEST_CASE(raising_a_tile_makes_a_step),
           TEST_CASE(removing_a_tile_opens_a_gap), TEST_CASE(tile_filtered_out_is_no_neighbour),
           TEST_CASE(changing_a_filter_after_running),
           TEST_CASE(contacts_switched_off_and_on_forget_old_tiles),
           TEST_CASE(tiles_added_later_join_the_floor), TEST_CASE(workers_give_the_same_bytes),
           TEST_CASE(box_on_overlapping_tiles_meets_one_face));
