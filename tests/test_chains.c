/* Chains (body.h): static geometry of line segments, one-sided, with
 * smooth joins; every shape against them; their bad input. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include "test.h"
#include "jostle/body.h"
#include "jostle/collision.h"
#include "jostle/forces.h"
#include "jostle/polygon.h"
#include "jostle/scene.h"
#include "collision/time_of_impact.h"
#include "dynamics/body_private.h"

static const double DT = 1.0 / 60.0;
static const double G = 9.81;
static const rgb_color_t GREY = {0.5, 0.5, 0.5};
enum { SEGMENTS = 40 };

static const double HEIGHT_TOLERANCE = 1e-3; /* m */
static const double ANGLE_TOLERANCE = 1e-6;  /* rad */

static scene_t *chain_scene(void) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -G});
    scene_set_contacts_enabled(scene, true);
    return scene;
}

/* An open chain along y = 0 from x = 0 to x = count * width, listed left
 * to right (solid from above), with friction mu. */
static body_t *add_floor(scene_t *scene, size_t count, double width, double mu) {
    vector_t *points = malloc((count + 1) * sizeof(vector_t));
    for (size_t i = 0; i <= count; i++) points[i] = (vector_t){(double)i * width, 0.0};
    body_t *floor = body_init_chain(points, count + 1, false, GREY);
    free(points);
    body_set_friction(floor, mu);
    scene_add_body(scene, floor);
    return floor;
}

/* A 0.5 m box of 1 kg resting on y = 0 with its centre at x. */
static body_t *add_box(scene_t *scene, double x, double mu) {
    body_t *box = body_init(polygon_make_box((vector_t){x, 0.25}, 0.25, 0.25), 1.0, GREY);
    body_set_friction(box, mu);
    scene_add_body(scene, box);
    return box;
}

static const double SPEEDS[] = {0.5, 1.0, 5.0, 20.0};
enum { SPEED_COUNT = sizeof(SPEEDS) / sizeof(SPEEDS[0]) };

/* A frictionless box slides over the 40 joins of a 40-segment floor at
 * 0.5 to 20 m/s: its height stays within 1 mm of resting and its rotation
 * under 1e-6 rad, and it keeps its speed. */
static void box_glides_over_a_segment_floor(void) {
    for (int k = 0; k < SPEED_COUNT; k++) {
        scene_t *scene = chain_scene();
        add_floor(scene, SEGMENTS, 1.0, 0.0);
        body_t *box = add_box(scene, 0.5, 0.0);
        body_set_velocity(box, (vector_t){SPEEDS[k], 0.0});
        double height = 0.0, angle = 0.0, speed = 0.0;
        int steps = 0;
        while (body_get_centroid(box).x < SEGMENTS - 0.5 && steps < 100000) {
            scene_tick(scene, DT);
            steps++;
            height = fmax(height, fabs(body_get_centroid(box).y - 0.25));
            angle = fmax(angle, fabs(body_get_rotation(box)));
            speed = fmax(speed, fabs(body_get_velocity(box).x - SPEEDS[k]));
        }
        CHECK(body_get_centroid(box).x >= SEGMENTS - 0.5);
        CHECK(height <= HEIGHT_TOLERANCE);
        CHECK(angle < ANGLE_TOLERANCE);
        CHECK(speed <= 1e-3 * SPEEDS[k]);
        if (!(height <= HEIGHT_TOLERANCE && angle < ANGLE_TOLERANCE)) {
            printf("  at %g m/s: height %.3g m, angle %.3g rad, speed %.3g m/s\n", SPEEDS[k],
                   height, angle, speed);
        }
        scene_free(scene);
    }
}

/* A body rolls or slides over the joins of the 40-segment floor (friction
 * 0.6) from x = 0.5 at 5 m/s: its height above the floor never moves by
 * more than `tolerance`, nor does it ever move upward faster than
 * 1e-3 m/s: no bump at a join. */
static void check_no_bumps(body_t *body, scene_t *scene, double rest, double tolerance) {
    double height = 0.0, rise = 0.0;
    int steps = 0;
    while (body_get_centroid(body).x < SEGMENTS - 1.0 && steps < 10000) {
        scene_tick(scene, DT);
        steps++;
        height = fmax(height, fabs(body_get_centroid(body).y - rest));
        rise = fmax(rise, body_get_velocity(body).y);
    }
    CHECK(body_get_centroid(body).x >= SEGMENTS - 1.0);
    CHECK(height <= tolerance);
    CHECK(rise <= 1e-3);
    if (!(height <= tolerance && rise <= 1e-3)) {
        printf("  height %.3g m, rise %.3g m/s\n", height, rise);
    }
}

static void circle_rolls_over_joins_without_bumps(void) {
    scene_t *scene = chain_scene();
    add_floor(scene, SEGMENTS, 1.0, 0.6);
    body_t *ball = body_init_circle((vector_t){0.5, 0.3}, 0.3, 1.0, GREY);
    scene_add_body(scene, ball);
    body_set_velocity(ball, (vector_t){5.0, 0.0});
    body_set_angular_velocity(ball, -5.0 / 0.3);
    check_no_bumps(ball, scene, 0.3, 1e-4);
    /* Rolling without slipping all the way. */
    CHECK_NEAR(body_get_velocity(ball).x, 5.0, 1e-3);
    CHECK_NEAR(body_get_angular_velocity(ball), -5.0 / 0.3, 1e-2);
    scene_free(scene);
}

static void capsule_slides_over_joins_without_bumps(void) {
    scene_t *scene = chain_scene();
    add_floor(scene, SEGMENTS, 1.0, 0.0);
    body_t *rod = body_init_capsule((vector_t){0.2, 0.2}, (vector_t){0.8, 0.2}, 0.2, 1.0, GREY);
    scene_add_body(scene, rod);
    body_set_velocity(rod, (vector_t){5.0, 0.0});
    check_no_bumps(rod, scene, 0.2, 1e-4);
    CHECK(fabs(body_get_rotation(rod)) < ANGLE_TOLERANCE);
    scene_free(scene);
}

/* A closed loop listed counter-clockwise keeps bodies inside: a box and a
 * ball thrown about at 20 m/s without gravity inside an octagon of radius
 * 3 m, bouncing elastically off its walls, stay within it for 10 s, and
 * the ball keeps its speed to 1%. */
static void loop_keeps_bodies_inside(void) {
    scene_t *scene = chain_scene();
    scene_set_gravity(scene, VEC_ZERO);
    vector_t points[8];
    for (int i = 0; i < 8; i++) {
        double angle = 2.0 * M_PI * i / 8.0;
        points[i] = (vector_t){3.0 * cos(angle), 3.0 * sin(angle)};
    }
    body_t *loop = body_init_chain(points, 8, true, GREY);
    body_set_elasticity(loop, 1.0);
    body_set_friction(loop, 0.0);
    scene_add_body(scene, loop);
    body_t *box = body_init(polygon_make_box((vector_t){-1, 0}, 0.2, 0.2), 1.0, GREY);
    body_t *ball = body_init_circle((vector_t){1, 0}, 0.2, 1.0, GREY);
    scene_add_body(scene, box);
    scene_add_body(scene, ball);
    /* Not against each other (a shared group): each bounces off the walls. */
    body_set_collision_filter(box, 1, UINT32_MAX, 7);
    body_set_collision_filter(ball, 1, UINT32_MAX, 7);
    body_set_velocity(box, (vector_t){20.0 * cos(1.0), 20.0 * sin(1.0)});
    body_set_velocity(ball, (vector_t){20.0 * cos(4.0), 20.0 * sin(4.0)});
    double inradius = 3.0 * cos(M_PI / 8.0), furthest = 0.0;
    for (int step = 0; step < 600; step++) {
        scene_tick(scene, DT);
        furthest = fmax(furthest, vec_get_length(body_get_centroid(box)));
        furthest = fmax(furthest, vec_get_length(body_get_centroid(ball)));
    }
    CHECK(furthest < inradius);
    /* Elastic frictionless bounces off the walls: the ball keeps its speed. */
    CHECK_RELATIVE(vec_get_length(body_get_velocity(ball)), 20.0, 0.01);
    scene_free(scene);
}

/* One-sided: a box thrown up through a floor listed left to right passes
 * it, and falls back onto it from above; a floor listed right to left is
 * solid from below only. */
static void chains_collide_on_their_left_side(void) {
    scene_t *scene = chain_scene();
    add_floor(scene, 4, 1.0, 0.6);
    body_t *box = body_init(polygon_make_box((vector_t){2, -1}, 0.25, 0.25), 1.0, GREY);
    scene_add_body(scene, box);
    body_set_velocity(box, (vector_t){0.0, 8.0});
    double highest = -INFINITY;
    for (int step = 0; step < 300; step++) {
        scene_tick(scene, DT);
        highest = fmax(highest, body_get_centroid(box).y);
    }
    CHECK(highest > 1.0);                                 /* through the floor */
    CHECK_NEAR(body_get_centroid(box).y, 0.25, 1e-3);     /* and back on it */
    scene_free(scene);

    scene = chain_scene();
    vector_t reversed[2] = {{4, 0}, {0, 0}};
    scene_add_body(scene, body_init_chain(reversed, 2, false, GREY));
    box = body_init(polygon_make_box((vector_t){2, 1}, 0.25, 0.25), 1.0, GREY);
    scene_add_body(scene, box);
    for (int step = 0; step < 120; step++) scene_tick(scene, DT);
    CHECK(body_get_centroid(box).y < -1.0); /* fell through from above */
    scene_free(scene);
}

/* A ball resting on a chain falls asleep, and its contacts name the chain. */
static void ball_on_a_chain_sleeps_and_reports_the_chain(void) {
    scene_t *scene = chain_scene();
    body_t *floor = add_floor(scene, 4, 1.0, 0.6);
    body_t *ball = body_init_circle((vector_t){2.0, 0.5}, 0.5, 1.0, GREY);
    scene_add_body(scene, ball);
    for (int step = 0; step < 30; step++) scene_tick(scene, DT);
    bool named = false;
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        const contact_t *c = scene_get_contact(scene, i);
        named |= (c->body1 == ball && c->body2 == floor) || (c->body1 == floor && c->body2 == ball);
        if (c->body2 == floor) CHECK_VEC(c->axis, 0.0, -1.0, 1e-12);
    }
    CHECK(named);
    for (int step = 0; step < 120; step++) scene_tick(scene, DT);
    CHECK(body_is_sleeping(ball));
    CHECK_NEAR(body_get_centroid(ball).y, 0.5, 1e-3);
    scene_free(scene);
}

/* find_collision on a chain: the segments by the chain's rules, the axis
 * from body1 toward body2, the depth exact. */
static void find_collision_with_a_chain(void) {
    vector_t points[3] = {{0, 0}, {1, 0}, {2, 0}};
    body_t *floor = body_init_chain(points, 3, false, GREY);
    body_t *ball = body_init_circle((vector_t){1.0, 0.4}, 0.5, 1.0, GREY);
    collision_info_t hit = find_collision(ball, floor);
    CHECK(hit.collided);
    CHECK_VEC(hit.axis, 0.0, -1.0, 1e-15);
    CHECK_NEAR(hit.depth, 0.1, 1e-15);
    hit = find_collision(floor, ball);
    CHECK(hit.collided);
    CHECK_VEC(hit.axis, 0.0, 1.0, 1e-15);
    CHECK_NEAR(hit.depth, 0.1, 1e-15);
    /* From behind: no collision (one-sided). */
    body_set_centroid(ball, (vector_t){1.0, -0.4});
    CHECK(!find_collision(ball, floor).collided);
    /* A box over the join at x = 1 lying flat: one face, no corner. */
    body_t *box = body_init(polygon_make_box((vector_t){1.0, 0.2}, 0.5, 0.25), 1.0, GREY);
    hit = find_collision(box, floor);
    CHECK(hit.collided);
    CHECK_VEC(hit.axis, 0.0, -1.0, 1e-15);
    CHECK_NEAR(hit.depth, 0.05, 1e-15);
    body_free(ball);
    body_free(box);
    body_free(floor);
}

/*
 * find_collision on a chain reports the contact the world builds, as for
 * round pairs (test_round.c): a capsule (radius 0.25) whose low end lies
 * 11.2 mm beyond a chain's open end and 0.2492 m above it, turned -67 mrad,
 * touches the end 0.55 mm deep, but the world's contact is on the chain's
 * face, where its end's side plane cuts the capsule, 0.8 mm - 11.2 mm
 * tan(67 mrad) = 0.05 mm deep; find_collision gives that point's depth
 * and the face's normal.
 */
static void find_collision_agrees_with_the_worlds_contact_on_a_chain(void) {
    scene_t *scene = chain_scene();
    scene_set_gravity(scene, VEC_ZERO);
    vector_t points[2] = {{-0.25, 0}, {0.25, 0}};
    body_t *floor = body_init_chain(points, 2, false, GREY);
    double turn = -0.067;
    vector_t right = {0.25 + 0.0112, 0.2492};
    vector_t left = {right.x - 0.5 * cos(turn), right.y - 0.5 * sin(turn)};
    body_t *rod = body_init_capsule(left, right, 0.25, 1.0, GREY);
    scene_add_body(scene, floor);
    scene_add_body(scene, rod);
    collision_info_t info = find_collision(floor, rod);
    scene_tick(scene, DT);
    const contact_t *world = NULL;
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        const contact_t *c = scene_get_contact(scene, i);
        if (c->kind == CONTACT_WORLD && (c->body1 == rod || c->body2 == rod)) world = c;
    }
    CHECK(world != NULL);
    if (world != NULL) {
        /* The world's axis runs from its body1 toward its body2. */
        vector_t axis = world->body1 == floor ? world->axis : vec_negate(world->axis);
        CHECK(world->point_count == 1);
        CHECK_NEAR(world->separation[0], 0.0112 * tan(0.067) - 0.0008, 1e-12);
        CHECK(info.collided);
        CHECK_VEC(info.axis, axis.x, axis.y, 1e-15);
        CHECK_NEAR(info.depth, -world->separation[0], 1e-15);
    }
    scene_free(scene);
}

/* The contact points of body's world contacts with `other` that lie within
 * 1 mm of p, after the last tick. */
static int points_near(scene_t *scene, const body_t *body, const body_t *other, vector_t p) {
    int near = 0;
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        const contact_t *c = scene_get_contact(scene, i);
        if (c->kind != CONTACT_WORLD) continue;
        if (!((c->body1 == body && c->body2 == other) || (c->body1 == other && c->body2 == body))) {
            continue;
        }
        for (size_t j = 0; j < c->point_count; j++) {
            near += vec_get_length(vec_subtract(c->points[j], p)) < 1e-3;
        }
    }
    return near;
}

/* A roof: up to an apex at the origin and down again, 0.1 m in 2 m each
 * way (a convex join, bending away from the free side above). */
static body_t *add_roof(scene_t *scene) {
    vector_t points[3] = {{-2.0, -0.1}, {0.0, 0.0}, {2.0, -0.1}};
    body_t *roof = body_init_chain(points, 3, false, GREY);
    body_set_friction(roof, 0.0);
    scene_add_body(scene, roof);
    return roof;
}

/* A box balanced on the roof's apex, and a ball resting on it: each has
 * one contact point at the apex, not one from each segment. */
static void convex_join_gives_one_corner_contact(void) {
    for (int shape = 0; shape < 2; shape++) {
        scene_t *scene = chain_scene();
        body_t *roof = add_roof(scene);
        body_t *body = shape == 0
                           ? body_init(polygon_make_box((vector_t){0, 0.25}, 0.25, 0.25), 1.0, GREY)
                           : body_init_circle((vector_t){0, 0.3}, 0.3, 1.0, GREY);
        scene_add_body(scene, body);
        scene_tick(scene, DT);
        int near = points_near(scene, body, roof, VEC_ZERO);
        CHECK(near == 1);
        if (near != 1) printf("  %s: %d points at the apex\n", shape == 0 ? "box" : "ball", near);
        scene_free(scene);
    }
}

/* A floor along y = 0 up to the origin, then down 0.02 m in 4 m (a convex
 * join of 5 mrad): a chain, or the top of one static polygon with both
 * faces. */
static body_t *add_edge(scene_t *scene, bool chain) {
    vector_t top[3] = {{-4.0, 0.0}, {0.0, 0.0}, {4.0, -0.02}};
    body_t *edge;
    if (chain) {
        edge = body_init_chain(top, 3, false, GREY);
    } else {
        list_t *points = list_init(5, free);
        vector_t corners[5] = {{-4.0, -1.0}, {4.0, -1.0}, top[2], top[1], top[0]};
        for (int i = 0; i < 5; i++) {
            vector_t *v = malloc(sizeof(vector_t));
            *v = corners[i];
            list_add(points, v);
        }
        edge = body_init(points, INFINITY, GREY);
    }
    body_set_friction(edge, 0.0);
    scene_add_body(scene, edge);
    return edge;
}

/* A frictionless box sliding at 0.5 to 20 m/s over the convex join and on
 * down the slope keeps its speed as over the polygon's corner: after 3.5 m
 * or 2.5 s its velocity is the polygon case's within 1e-3 of its speed and
 * its place within 1 mm. (How far it tilts once on the slope is set by
 * where it lands inside the 1 mm slop, up to 2 mrad either way.) */
static void box_slides_over_a_convex_join_as_over_a_corner(void) {
    for (int k = 0; k < SPEED_COUNT; k++) {
        vector_t velocity[2], place[2];
        int steps = (int)fmin(150.0, ceil(3.5 / SPEEDS[k] / DT));
        for (int kind = 0; kind < 2; kind++) {
            scene_t *scene = chain_scene();
            add_edge(scene, kind == 0);
            body_t *box = add_box(scene, -0.5, 0.0);
            body_set_velocity(box, (vector_t){SPEEDS[k], 0.0});
            for (int step = 0; step < steps; step++) scene_tick(scene, DT);
            velocity[kind] = body_get_velocity(box);
            place[kind] = body_get_centroid(box);
            scene_free(scene);
        }
        double off = vec_get_length(vec_subtract(velocity[0], velocity[1]));
        double moved = vec_get_length(vec_subtract(place[0], place[1]));
        CHECK(off <= 1e-3 * SPEEDS[k]);
        CHECK(moved <= 1e-3);
        if (!(off <= 1e-3 * SPEEDS[k] && moved <= 1e-3)) {
            printf("  at %g m/s: chain (%.6g, %.6g) at (%.4g, %.4g), polygon (%.6g, %.6g) at "
                   "(%.4g, %.4g)\n",
                   SPEEDS[k], velocity[0].x, velocity[0].y, place[0].x, place[0].y,
                   velocity[1].x, velocity[1].y, place[1].x, place[1].y);
        }
    }
}

/* A frictionless box sliding at 0.5 to 20 m/s across the join of a chain
 * and what continues it flush on its left, a static box's top or another
 * chain, either way (the seams' rule across the join): its height within
 * 1 mm of resting and its rotation under 1e-6 rad, and it keeps its
 * speed. */
static void box_glides_from_a_static_box_onto_a_chain(void) {
    for (int run = 0; run < 4 * SPEED_COUNT; run++) {
        double speed0 = SPEEDS[run % SPEED_COUNT];
        bool left_is_chain = run / SPEED_COUNT % 2 == 1, leftward = run / SPEED_COUNT >= 2;
        scene_t *scene = chain_scene();
        vector_t left_points[2] = {{-4, 0}, {0, 0}};
        body_t *left = left_is_chain
                           ? body_init_chain(left_points, 2, false, GREY)
                           : body_init(polygon_make_box((vector_t){-2.0, -0.5}, 2.0, 0.5),
                                       INFINITY, GREY);
        body_set_friction(left, 0.0);
        scene_add_body(scene, left);
        vector_t points[5] = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}};
        body_t *floor = body_init_chain(points, 5, false, GREY);
        body_set_friction(floor, 0.0);
        scene_add_body(scene, floor);
        double sign = leftward ? -1.0 : 1.0;
        body_t *box = add_box(scene, -3.0 * sign, 0.0);
        body_set_velocity(box, (vector_t){sign * speed0, 0.0});
        double height = 0.0, angle = 0.0, speed = 0.0;
        int steps = 0;
        while (sign * body_get_centroid(box).x < 3.0 && steps < 2000) {
            scene_tick(scene, DT);
            steps++;
            height = fmax(height, fabs(body_get_centroid(box).y - 0.25));
            angle = fmax(angle, fabs(body_get_rotation(box)));
            speed = fmax(speed, fabs(sign * body_get_velocity(box).x - speed0));
        }
        CHECK(sign * body_get_centroid(box).x >= 3.0);
        CHECK(height <= HEIGHT_TOLERANCE);
        CHECK(angle < ANGLE_TOLERANCE);
        CHECK(speed <= 1e-3 * speed0);
        if (!(height <= HEIGHT_TOLERANCE && angle < ANGLE_TOLERANCE && speed <= 1e-3 * speed0)) {
            printf("  from a %s, %s at %g m/s: height %.3g m, angle %.3g rad, speed off by %.3g "
                   "m/s\n",
                   left_is_chain ? "chain" : "static box", leftward ? "leftward" : "rightward",
                   speed0, height, angle, speed);
        }
        scene_free(scene);
    }
}

/*
 * A chain lying on a static box's top face (y = 0), or within a hair of it
 * (SEAM_TOLERANCE, 1 micrometre): the two are one surface, and a body on
 * the stretch they share gets one contact from it, as on one long face.
 * Each layout: the box's top from box_lo to box_hi (0.5 m deep), the chain
 * `count` points from chain_lo to chain_hi at height `lift`.
 */
typedef struct {
    const char *name;
    double box_lo, box_hi, chain_lo, chain_hi;
    size_t count;
    double lift;
} overlap_layout_t;

static const overlap_layout_t OVERLAPS[] = {
    {"a segment within the box's face", -2.0, 2.0, -1.0, 1.0, 2, 0.0},
    {"a chain over the box's end", -4.0, 1.0, -0.9258, 4.0, 6, 0.0},
    {"a chain over the whole face", -1.0, 1.0, -4.0, 4.0, 9, 0.0},
    {"a segment on the face exactly", -2.0, 2.0, -2.0, 2.0, 2, 0.0},
    {"a chain a hair above", -4.0, 4.0, -2.0, 2.0, 9, 5e-7},
    {"a chain a hair below", -4.0, 4.0, -2.0, 2.0, 9, -5e-7},
};
enum { OVERLAP_COUNT = sizeof(OVERLAPS) / sizeof(OVERLAPS[0]) };

/* The layout's static box and chain, frictionless, added box first or
 * chain first (the world's pair order follows). */
static void add_overlap(scene_t *scene, const overlap_layout_t *layout, bool chain_first,
                        body_t **base, body_t **chain) {
    double half = 0.5 * (layout->box_hi - layout->box_lo);
    *base = body_init(polygon_make_box((vector_t){layout->box_lo + half, -0.25}, half, 0.25),
                      INFINITY, GREY);
    vector_t points[16];
    for (size_t i = 0; i < layout->count; i++) {
        double t = (double)i / (double)(layout->count - 1);
        points[i] = (vector_t){layout->chain_lo + t * (layout->chain_hi - layout->chain_lo),
                               layout->lift};
    }
    *chain = body_init_chain(points, layout->count, false, GREY);
    body_set_friction(*base, 0.0);
    body_set_friction(*chain, 0.0);
    scene_add_body(scene, chain_first ? *chain : *base);
    scene_add_body(scene, chain_first ? *base : *chain);
}

/* Of body's world contacts with points after the last tick: how many with
 * `base` and with `chain`, and their normal impulses' sum. */
typedef struct {
    int with_base, with_chain;
    double impulse;
} surface_contacts_t;

static surface_contacts_t surface_contacts(scene_t *scene, const body_t *body,
                                           const body_t *base, const body_t *chain) {
    surface_contacts_t found = {0, 0, 0.0};
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        const contact_t *c = scene_get_contact(scene, i);
        if (c->kind != CONTACT_WORLD || c->point_count == 0) continue;
        const body_t *other = c->body1 == body ? c->body2 : c->body2 == body ? c->body1 : NULL;
        if (other == NULL) continue;
        found.with_base += other == base;
        found.with_chain += other == chain;
        for (size_t j = 0; j < c->point_count; j++) found.impulse += c->normal_impulse[j];
    }
    return found;
}

/* A 0.5 m box of 1 kg resting on the stretch the chain and the static box
 * share (centred where the chain starts or over its middle) has one
 * contact, with one of the two, whose impulse bears its weight: m g dt
 * per step, to 1e-6 relative. */
static void box_on_a_chain_over_a_static_box_meets_one_surface(void) {
    for (int run = 0; run < 2 * OVERLAP_COUNT; run++) {
        const overlap_layout_t *layout = &OVERLAPS[run / 2];
        bool chain_first = run % 2 == 1;
        scene_t *scene = chain_scene();
        body_t *base, *chain;
        add_overlap(scene, layout, chain_first, &base, &chain);
        double lo = fmax(layout->box_lo, layout->chain_lo);
        double hi = fmin(layout->box_hi, layout->chain_hi);
        double x = layout->chain_lo > layout->box_lo ? lo + 0.3 : 0.5 * (lo + hi) + 0.1;
        body_t *box = add_box(scene, x, 0.0);
        scene_set_sleeping(scene, false); /* a sleeping pair's contact is not recorded */
        for (int step = 0; step < 60; step++) scene_tick(scene, DT);
        surface_contacts_t found = surface_contacts(scene, box, base, chain);
        CHECK(found.with_base + found.with_chain == 1);
        CHECK_RELATIVE(found.impulse, G * DT, 1e-6);
        CHECK_NEAR(body_get_centroid(box).y, 0.25 + layout->lift, 1e-3);
        if (found.with_base + found.with_chain != 1) {
            printf("  %s, %s first: %d contacts with the box, %d with the chain\n", layout->name,
                   chain_first ? "chain" : "box", found.with_base, found.with_chain);
        }
        scene_free(scene);
    }
}

/* A frictionless box sliding at 0.5 to 20 m/s either way across a chain
 * laid over a static box's face (over its end, over the whole face, or a
 * hair into it): one contact from the surface at every step, its height
 * within 1 mm of resting, its rotation under 1e-6 rad, its speed kept to
 * 1e-3. (It starts 12.3 mm off the joins' grid: a step that ends with its
 * middle within the micrometre where two faces share their claims, at a
 * join, has a contact from each, as between flush boxes.) */
static void box_glides_across_a_chain_over_a_static_box(void) {
    const int layouts[] = {1, 2, 5};
    for (int run = 0; run < 3 * 2 * SPEED_COUNT; run++) {
        const overlap_layout_t *layout = &OVERLAPS[layouts[run / (2 * SPEED_COUNT)]];
        double speed0 = SPEEDS[run % SPEED_COUNT];
        bool leftward = run / SPEED_COUNT % 2 == 1;
        scene_t *scene = chain_scene();
        body_t *base, *chain;
        add_overlap(scene, layout, leftward, &base, &chain);
        double sign = leftward ? -1.0 : 1.0;
        body_t *box = add_box(scene, -2.9877 * sign, 0.0);
        body_set_centroid(box, (vector_t){-2.9877 * sign, 0.25 + layout->lift});
        body_set_velocity(box, (vector_t){sign * speed0, 0.0});
        double height = 0.0, angle = 0.0, speed = 0.0;
        int steps = 0, doubled = 0;
        while (sign * body_get_centroid(box).x < 3.0 && steps < 2000) {
            scene_tick(scene, DT);
            steps++;
            height = fmax(height, fabs(body_get_centroid(box).y - 0.25 - layout->lift));
            angle = fmax(angle, fabs(body_get_rotation(box)));
            speed = fmax(speed, fabs(sign * body_get_velocity(box).x - speed0));
            surface_contacts_t found = surface_contacts(scene, box, base, chain);
            doubled += found.with_base > 0 && found.with_chain > 0;
        }
        CHECK(sign * body_get_centroid(box).x >= 3.0);
        CHECK(doubled == 0);
        CHECK(height <= HEIGHT_TOLERANCE);
        CHECK(angle < ANGLE_TOLERANCE);
        CHECK(speed <= 1e-3 * speed0);
        if (!(doubled == 0 && height <= HEIGHT_TOLERANCE && angle < ANGLE_TOLERANCE &&
              speed <= 1e-3 * speed0)) {
            printf("  %s, %s at %g m/s: %d of %d steps with both, height %.3g m, angle %.3g rad, "
                   "speed off by %.3g m/s\n",
                   layout->name, leftward ? "leftward" : "rightward", speed0, doubled, steps,
                   height, angle, speed);
        }
        scene_free(scene);
    }
}

BAD_CALL(too_few_points, body_init_chain((vector_t[]){{0, 0}}, 1, false, GREY))
BAD_CALL(loop_of_two, body_init_chain((vector_t[]){{0, 0}, {1, 0}}, 2, true, GREY))
BAD_CALL(null_points, body_init_chain(NULL, 3, false, GREY))
BAD_CALL(nan_point, body_init_chain((vector_t[]){{0, 0}, {NAN, 0}}, 2, false, GREY))
BAD_CALL(zero_length, body_init_chain((vector_t[]){{0, 0}, {1, 0}, {1, 0}, {2, 0}}, 4, false, GREY))
BAD_CALL(loop_closed_twice,
         body_init_chain_with_info((vector_t[]){{0, 0}, {1, 0}, {1, 1}, {0, 0}}, 4, true, GREY,
                                   NULL, NULL))
BAD_CALL(moving_chain, body_set_velocity(body_init_chain((vector_t[]){{0, 0}, {1, 0}}, 2, false,
                                                         GREY),
                                         (vector_t){1, 0}))
BAD_CALL(spinning_chain,
         body_set_angular_velocity(body_init_chain((vector_t[]){{0, 0}, {1, 0}}, 2, false, GREY),
                                   1.0))
BAD_CALL(chain_inertia,
         body_set_inertia(body_init_chain((vector_t[]){{0, 0}, {1, 0}}, 2, false, GREY), 1.0))
BAD_CALL(segment_out_of_range, {
    vector_t p1, p2;
    body_get_segment(body_init_chain((vector_t[]){{0, 0}, {1, 0}}, 2, false, GREY), 1, &p1, &p2);
})

static void bad_input_aborts_with_message(void) {
    CHECK_DIES(too_few_points, NULL,
               "engine error in body_init_chain: an open chain needs at least 2 points (got 1)");
    CHECK_DIES(loop_of_two, NULL, "body_init_chain: a loop chain needs at least 3 points (got 2)");
    CHECK_DIES(null_points, NULL, "engine error in body_init_chain: points is NULL");
    CHECK_DIES(nan_point, NULL, "engine error in body_init_chain: point 1 is not finite (nan, 0)");
    CHECK_DIES(zero_length, NULL,
               "engine error in body_init_chain: segment 1 from (1, 0) to (1, 0) has zero length");
    CHECK_DIES(loop_closed_twice, NULL,
               "engine error in body_init_chain_with_info: segment 3 from (0, 0) to (0, 0) has "
               "zero length");
    CHECK_DIES(moving_chain, NULL,
               "engine error in body_set_velocity: a chain is static: it cannot be given a velocity");
    CHECK_DIES(spinning_chain, NULL,
               "engine error in body_set_angular_velocity: a chain is static");
    CHECK_DIES(chain_inertia, NULL,
               "engine error in body_set_inertia: a chain is static: it cannot be given a finite "
               "moment of inertia");
    CHECK_DIES(segment_out_of_range, NULL,
               "engine error in body_get_segment: segment 1 out of range (1 segments)");
}

/* What the seed's polygon functions and the accessors give for a chain. */
static void chain_accessors(void) {
    vector_t points[4] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
    body_t *open = body_init_chain(points, 4, false, GREY);
    body_t *loop = body_init_chain(points, 4, true, GREY);
    CHECK(body_get_shape_kind(open) == BODY_SHAPE_CHAIN);
    CHECK(body_get_segment_count(open) == 3);
    CHECK(body_get_segment_count(loop) == 4);
    CHECK(!body_is_loop(open) && body_is_loop(loop));
    CHECK(isinf(body_get_mass(open)) && isinf(body_get_inertia(open)));
    list_t *shape = body_get_shape(open);
    CHECK(list_size(shape) == 4);
    for (size_t i = 0; i < 4; i++) {
        vector_t *v = list_get(shape, i);
        CHECK(v->x == points[i].x && v->y == points[i].y);
    }
    list_free(shape);
    vector_t p1, p2;
    body_get_segment(loop, 3, &p1, &p2);
    CHECK_VEC(p1, 0, 1, 0);
    CHECK_VEC(p2, 0, 0, 0);
    aabb_t box = body_get_bounds(open);
    CHECK_VEC(box.min, 0, 0, 0);
    CHECK_VEC(box.max, 2, 1, 0);
    CHECK(body_contains_point(open, (vector_t){1.5, 0}));
    CHECK(body_contains_point(open, (vector_t){2, 0.5}));
    CHECK(!body_contains_point(open, (vector_t){1, 0.5})); /* a chain has no inside */
    CHECK(!body_contains_point(open, (vector_t){0, 0.5})); /* the open chain's missing side */
    CHECK(body_contains_point(loop, (vector_t){0, 0.5}));
    /* Moved and turned: the segments follow. */
    body_set_centroid(open, (vector_t){1, 1});
    body_set_rotation(open, M_PI / 2);
    body_get_segment(open, 0, &p1, &p2);
    CHECK_VEC(p1, 1, 1, 1e-15);
    CHECK_VEC(p2, 1, 3, 1e-15);
    body_free(open);
    body_free(loop);
}

/*
 * The broadphase against a long chain: a 200-segment terrain under 500
 * bodies resting on it. Each segment has its own box, so a body pairs with
 * the few segments beneath it, not with the whole chain: the pairs (at the
 * end) and the box tests (over the fall) grow as the bodies do (twice the
 * bodies, about twice the pairs and tests), as over a floor of boxes.
 */
static void long_chain_pairs_stay_linear(void) {
    size_t pairs[2], tests[2];
    for (int run = 0; run < 2; run++) {
        size_t bodies = run == 0 ? 250 : 500;
        scene_t *scene = chain_scene();
        vector_t points[201];
        for (int i = 0; i <= 200; i++) {
            points[i] = (vector_t){0.5 * i, 0.3 * sin(0.2 * i)};
        }
        scene_add_body(scene, body_init_chain(points, 201, false, GREY));
        for (size_t k = 0; k < bodies; k++) {
            double x = 0.5 + 99.0 * (double)k / (double)bodies;
            scene_add_body(scene, body_init(polygon_make_box((vector_t){x, 0.5}, 0.08, 0.08),
                                            1.0, GREY));
        }
        /* Over the whole fall: a step that keeps last step's pairs makes
         * fewer tests than one that searches the grid. */
        tests[run] = 0;
        for (int step = 0; step < 30; step++) {
            scene_tick(scene, DT);
            tests[run] += scene_get_stats(scene).broadphase_tests;
        }
        pairs[run] = scene_get_stats(scene).broadphase_pairs;
        scene_free(scene);
    }
    printf("  pairs %zu -> %zu, box tests %zu -> %zu\n", pairs[0], pairs[1], tests[0], tests[1]);
    CHECK(pairs[0] >= 250 && pairs[1] >= 500); /* each body touches the terrain */
    CHECK(pairs[1] <= 3 * pairs[0]);
    CHECK(tests[1] <= 3 * tests[0]);
    /* At most a handful of segments under each body and its neighbours. */
    CHECK(pairs[1] <= 500 * 8);
}

/* The moment of first touch within a step (time_of_impact) of a pair with
 * a round body or a chain's segment, on the exact shapes, to 1e-12 s
 * against the closed forms, where the outlines would be off by up to 0.5%
 * of a radius (the contacts below meet halfway between outline vertices). */
static double impact_time(body_t *a, toi_motion_t ma, body_t *b, toi_motion_t mb) {
    body_get_bounds(a); /* brings the world polygons up to date */
    body_get_bounds(b);
    toi_scratch_t scratch = {NULL, 0};
    toi_contact_t contact;
    double tolerance = 1e-12 * (a->radius + b->radius);
    bool touches = time_of_impact(a, &ma, b, &mb, 1.0, 0.01, tolerance, &scratch, &contact);
    free(scratch.vectors);
    CHECK(touches && contact.touches);
    return contact.time;
}

static void time_of_impact_is_exact_for_round_shapes(void) {
    toi_motion_t still = {VEC_ZERO, VEC_ZERO, 0.0};
    /* Two unit circles, a at 10 m/s along x, b placed so that they touch at
     * t = 0.3 along a normal at pi/32. */
    double phi = M_PI / 32.0;
    body_t *a = body_init_circle(VEC_ZERO, 1.0, 1.0, GREY);
    body_t *b = body_init_circle((vector_t){3.0 + 2.0 * cos(phi), 2.0 * sin(phi)}, 1.0, 1.0, GREY);
    CHECK_NEAR(impact_time(a, (toi_motion_t){{10, 0}, VEC_ZERO, 0.0}, b, still), 0.3, 1e-12);
    /* A flat capsule coming down at (2, -3) onto a circle turned by pi/32:
     * its side meets the top of the circle when -0.25 - 3 t = -1.5. */
    body_t *rod = body_init_capsule((vector_t){-1, 0}, (vector_t){1, 0}, 0.25, 1.0, GREY);
    body_t *ball = body_init_circle((vector_t){0.4, -2}, 0.5, 1.0, GREY);
    body_set_rotation(ball, M_PI / 32.0);
    CHECK_NEAR(impact_time(rod, (toi_motion_t){{2, -3}, VEC_ZERO, 0.0}, ball, still), 1.25 / 3.0,
               1e-12);
    /* A ball falling from rest at 5 m/s and g onto a chain's segment: 1.5 =
     * 5 t + 4.9 t^2. */
    vector_t points[2] = {{0, 0}, {4, 0}};
    body_t *floor = body_init_chain(points, 2, false, GREY);
    body_t *drop = body_init_circle((vector_t){1.3, 2.0}, 0.5, 1.0, GREY);
    body_set_rotation(drop, M_PI / 32.0);
    body_t *segment = floor->parts[0];
    body_update_world(segment);
    double expected = (-5.0 + sqrt(25.0 + 4.0 * 4.9 * 1.5)) / (2.0 * 4.9);
    CHECK_NEAR(impact_time(drop, (toi_motion_t){{0, -5}, {0, -9.8}, 0.0}, segment, still),
               expected, 1e-12);
    body_free(a);
    body_free(b);
    body_free(rod);
    body_free(ball);
    body_free(drop);
    body_free(floor);
}

/* The seed's collision handlers take a chain: with world contacts off, a
 * ball dropped on a chain floor under create_physics_collision at e = 1
 * bounces back up, and one pushed up through the floor from behind is left
 * alone (one-sided). */
static void seed_collision_handlers_take_a_chain(void) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0.0, -G});
    vector_t points[3] = {{-2, 0}, {0, 0}, {2, 0}};
    body_t *floor = body_init_chain(points, 3, false, GREY);
    body_t *ball = body_init_circle((vector_t){0.0, 1.0}, 0.25, 1.0, GREY);
    body_t *rising = body_init_circle((vector_t){1.0, -1.0}, 0.25, 1.0, GREY);
    scene_add_body(scene, floor);
    scene_add_body(scene, ball);
    scene_add_body(scene, rising);
    body_set_velocity(rising, (vector_t){0.0, 8.0});
    create_physics_collision(scene, ball, floor, 1.0);
    create_physics_collision(scene, rising, floor, 1.0);
    double lowest = INFINITY, rose = -INFINITY;
    for (int step = 0; step < 50; step++) {
        scene_tick(scene, DT);
        lowest = fmin(lowest, body_get_centroid(ball).y);
        rose = fmax(rose, body_get_centroid(rising).y);
    }
    CHECK(lowest > 0.0 && lowest < 0.25); /* reached the floor, not through it */
    CHECK(body_get_velocity(ball).y > 0.0 || body_get_centroid(ball).y > 0.5); /* bounced */
    CHECK(rose > 1.0); /* passed up through the floor */
    scene_free(scene);
}

TEST_SUITE(chains, TEST_CASE(box_glides_over_a_segment_floor),
           TEST_CASE(circle_rolls_over_joins_without_bumps),
           TEST_CASE(capsule_slides_over_joins_without_bumps), TEST_CASE(loop_keeps_bodies_inside),
           TEST_CASE(chains_collide_on_their_left_side),
           TEST_CASE(ball_on_a_chain_sleeps_and_reports_the_chain),
           TEST_CASE(find_collision_with_a_chain),
           TEST_CASE(find_collision_agrees_with_the_worlds_contact_on_a_chain),
           TEST_CASE(bad_input_aborts_with_message),
           TEST_CASE(chain_accessors), TEST_CASE(long_chain_pairs_stay_linear),
           TEST_CASE(time_of_impact_is_exact_for_round_shapes),
           TEST_CASE(seed_collision_handlers_take_a_chain),
           TEST_CASE(convex_join_gives_one_corner_contact),
           TEST_CASE(box_slides_over_a_convex_join_as_over_a_corner),
           TEST_CASE(box_glides_from_a_static_box_onto_a_chain),
           TEST_CASE(box_on_a_chain_over_a_static_box_meets_one_surface),
           TEST_CASE(box_glides_across_a_chain_over_a_static_box));
