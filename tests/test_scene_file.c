/* scene_file.h: the format feature by feature, the messages for malformed
 * files, the round trip, spawning, and the fuzz corpus replayed. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "jostle/jostle.h"
#include "jostle/scene_file.h"
#include "scene_file_check.h"
#include "test.h"

static scene_file_t *parse(const char *text) {
    scene_file_error_t error;
    scene_file_t *file = scene_file_parse(text, strlen(text), "t.scene", &error);
    if (file == NULL) test_fail(__FILE__, __LINE__, "refused: %s", error.message);
    return file;
}

static body_t *body_at(scene_file_t *file, size_t index) {
    return scene_get_body(scene_file_get_scene(file), index);
}

static size_t bodies(scene_file_t *file) {
    return scene_bodies(scene_file_get_scene(file));
}

static const char *tag(body_t *body) {
    return body_get_info(body);
}

/* ---- Features ------------------------------------------------------------- */

static void settings_reach_the_scene(void) {
    scene_file_t *file = parse("# comment line\n"
                               "gravity 0 -9.81   # trailing comment\n"
                               "contacts on\n"
                               "integrator symplectic_euler\n"
                               "iterations 12 6\n"
                               "timestep 1/240\n"
                               "view 1 2 30 20\n"
                               "game breakout\n");
    scene_t *scene = scene_file_get_scene(file);
    CHECK_VEC(scene_get_gravity(scene), 0, -9.81, 0);
    CHECK(scene_get_contacts_enabled(scene));
    CHECK(scene_get_integrator(scene) == INTEGRATOR_SYMPLECTIC_EULER);
    CHECK_NEAR(scene_file_get_timestep(file), 1.0 / 240.0, 0);
    scene_file_view_t view = scene_file_get_view(file);
    CHECK(view.has_view);
    CHECK_VEC(view.center, 1, 2, 0);
    CHECK_NEAR(view.width, 30, 0);
    CHECK_NEAR(view.height, 20, 0);
    CHECK(strcmp(scene_file_get_game(file), "breakout") == 0);
    /* The iterations have no getter in the engine: the written file shows them. */
    char *text = scene_file_write(file, NULL, NULL);
    CHECK(strstr(text, "iterations 12 6\n") != NULL);
    free(text);
    scene_file_free(file);
    /* Defaults. */
    file = parse("");
    scene = scene_file_get_scene(file);
    CHECK_VEC(scene_get_gravity(scene), 0, 0, 0);
    CHECK(!scene_get_contacts_enabled(scene));
    CHECK(scene_get_integrator(scene) == INTEGRATOR_SEED);
    CHECK_NEAR(scene_file_get_timestep(file), 1.0 / 120.0, 0);
    CHECK(!scene_file_get_view(file).has_view);
    CHECK(strcmp(scene_file_get_game(file), "") == 0);
    CHECK(bodies(file) == 0);
    scene_file_free(file);
    CHECK(test_no_leaks());
}

static void solver_settings_are_read_written_and_kept(void) {
    scene_file_t *file = parse("contacts on\niterations 12 3\nwarm_starting off\n"
                               "restitution_threshold 0.25\nsleep_tolerance 0.05 0.5\n"
                               "sleep_time 1.5\n");
    scene_t *scene = scene_file_get_scene(file);
    size_t velocity, position;
    double linear, angular;
    scene_get_solver_iterations(scene, &velocity, &position);
    scene_get_sleep_tolerance(scene, &linear, &angular);
    CHECK(velocity == 12 && position == 3 && !scene_get_warm_starting(scene));
    CHECK(scene_get_restitution_threshold(scene) == 0.25 && linear == 0.05 && angular == 0.5);
    CHECK(scene_get_sleep_time(scene) == 1.5);
    /* Changed while it runs, written as it is now, and read back the same. */
    scene_set_solver_iterations(scene, 20, 6);
    scene_set_sleep_tolerance(scene, 0.02, INFINITY);
    scene_set_warm_starting(scene, true);
    size_t length;
    char *text = scene_file_write(file, &length, NULL);
    CHECK(strstr(text, "iterations 20 6\n") != NULL);
    CHECK(strstr(text, "sleep_tolerance 0.02\n") != NULL);
    CHECK(strstr(text, "warm_starting") == NULL); /* the default is not written */
    CHECK(strstr(text, "restitution_threshold 0.25\n") != NULL);
    CHECK(strstr(text, "sleep_time 1.5\n") != NULL);
    char why[256];
    CHECK(scene_file_round_trip((const uint8_t *)text, length, "t.scene", why, sizeof why));
    scene_file_t *again = parse(text);
    CHECK(scene_file_same(file, again, why, sizeof why));
    scene_get_sleep_tolerance(scene_file_get_scene(again), &linear, &angular);
    CHECK(linear == 0.02 && angular == INFINITY);
    scene_file_free(again);
    free(text);
    scene_file_free(file);
    /* A file without them leaves the scene's defaults. */
    file = parse("contacts on\n");
    scene = scene_file_get_scene(file);
    CHECK(scene_get_warm_starting(scene) && scene_get_restitution_threshold(scene) == 1.0);
    CHECK(scene_get_sleep_time(scene) == 0.5);
    scene_file_free(file);
}

static void every_integrator_name_is_read_and_written(void) {
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        integrator_t integrator = (integrator_t)i;
        const char *name = scene_file_integrator_name(integrator);
        CHECK(name != NULL);
        char text[64];
        snprintf(text, sizeof text, "integrator %s\n", name);
        scene_file_t *file = parse(text);
        CHECK(scene_get_integrator(scene_file_get_scene(file)) == integrator);
        char *written = scene_file_write(file, NULL, NULL);
        CHECK(strstr(written, text) != NULL);
        free(written);
        scene_file_free(file);
    }
    CHECK(strcmp(scene_file_integrator_name(INTEGRATOR_SEED), "seed") == 0);
}

static void shapes_are_regular_boxes_or_vertices(void) {
    scene_file_t *file = parse("body hexagon { regular 6 2 }\n"
                               "body slab { box 4 1; position 10 0 }\n"
                               "body clockwise { vertices 0 0  0 3  3 0 }\n"
                               "body moved { vertices 0 0  3 0  0 3; position 5 5 }\n");
    CHECK(bodies(file) == 4);
    /* Regular: 6 vertices on a circle of radius 2, a flat bottom edge. */
    polygon_t hexagon = body_get_polygon(body_at(file, 0));
    CHECK(hexagon.count == 6);
    for (size_t i = 0; i < 6; i++) CHECK_NEAR(vec_get_length(hexagon.vertices[i]), 2, 1e-12);
    CHECK_NEAR(hexagon.vertices[0].y, hexagon.vertices[1].y, 1e-12);
    CHECK_NEAR(hexagon.vertices[0].y, -2 * cos(M_PI / 6), 1e-12);
    /* Box: full width and height, centred at its position. */
    aabb_t slab = body_get_bounds(body_at(file, 1));
    CHECK_VEC(slab.min, 8, -0.5, 1e-12);
    CHECK_VEC(slab.max, 12, 0.5, 1e-12);
    /* Vertices: world coordinates when no position is given; a clockwise list
     * is reversed (the engine keeps counter-clockwise polygons anyway). */
    CHECK_VEC(body_get_centroid(body_at(file, 2)), 1, 1, 1e-12);
    list_t *shape = body_get_shape(body_at(file, 2));
    CHECK(polygon_is_counterclockwise(shape));
    list_free(shape);
    char *text = scene_file_write(file, NULL, NULL);
    CHECK(strstr(text, "vertices 3 0 0 3 0 0\n") != NULL); /* reversed as written back */
    free(text);
    /* With a position, the centroid goes there. */
    CHECK_VEC(body_get_centroid(body_at(file, 3)), 5, 5, 1e-12);
    scene_file_free(file);
}

static void circles_and_capsules_are_round_bodies(void) {
    scene_file_t *file = parse("body ball { circle 0.5; density 2; position 1 2; angle 0.3 }\n"
                               "body rod { capsule 1 1 3 1 0.25; mass 3 }\n"
                               "body moved { capsule 0 0 0 2 0.5; position 5 5; angle 90deg }\n"
                               "template shot { circle 0.1; mass 0.2 }\n");
    CHECK(bodies(file) == 3);
    body_t *ball = body_at(file, 0), *rod = body_at(file, 1), *moved = body_at(file, 2);
    /* A circle about its position, of density times its exact area. */
    CHECK(body_get_shape_kind(ball) == BODY_SHAPE_CIRCLE);
    CHECK(body_get_round_radius(ball) == 0.5);
    CHECK_VEC(body_get_centroid(ball), 1, 2, 0);
    CHECK(body_get_rotation(ball) == 0.3);
    CHECK_NEAR(body_get_mass(ball), 2 * M_PI * 0.25, 1e-15);
    CHECK_NEAR(body_get_inertia(ball), 0.5 * body_get_mass(ball) * 0.25, 1e-15);
    /* A capsule's ends in world coordinates without a position: its centroid
     * at their midpoint. */
    CHECK(body_get_shape_kind(rod) == BODY_SHAPE_CAPSULE);
    CHECK(body_get_round_radius(rod) == 0.25);
    CHECK_VEC(body_get_centroid(rod), 2, 1, 0);
    vector_t p1, p2;
    body_get_core(rod, &p1, &p2);
    CHECK_VEC(p1, 1, 1, 1e-15);
    CHECK_VEC(p2, 3, 1, 1e-15);
    CHECK_NEAR(body_get_mass(rod), 3, 0);
    /* With a position and an angle: the core turned about the centroid. */
    body_get_core(moved, &p1, &p2);
    CHECK_VEC(p1, 6, 5, 1e-12);
    CHECK_VEC(p2, 4, 5, 1e-12);
    CHECK_NEAR(body_get_mass(moved), M_PI * 0.25 + 2, 1e-15); /* density 1 */
    /* The written file says the same. */
    char *text = scene_file_write(file, NULL, NULL);
    CHECK(strstr(text, "    circle 0.5\n    density 2\n") != NULL);
    CHECK(strstr(text, "    capsule 1 1 3 1 0.25\n    mass 3\n") != NULL);
    CHECK(strstr(text, "template shot {\n    circle 0.1\n") != NULL);
    free(text);
    body_t *shot = scene_file_spawn(file, "shot", (vector_t){0, 9}, VEC_ZERO);
    CHECK(shot != NULL && body_get_shape_kind(shot) == BODY_SHAPE_CIRCLE);
    CHECK_NEAR(body_get_mass(shot), 0.2, 0);
    scene_file_free(file);
    CHECK(test_no_leaks());
}

/* The text round-trips (scene_file_round_trip); loaded and stepped 70
 * steps of 1/60 s, then saved, the copy goes on as the original does for
 * 120 steps, every body the same to the bit. Returns the original, stepped,
 * and in *saved its text at the save (the caller frees both). */
static scene_file_t *continues_bit_for_bit(const char *text, char **saved) {
    char why[256] = "";
    CHECK(scene_file_round_trip((const uint8_t *)text, strlen(text), "t.scene", why, sizeof why));
    if (why[0] != '\0') printf("    %s\n", why);
    scene_file_t *file = parse(text);
    scene_t *scene = scene_file_get_scene(file);
    for (int i = 0; i < 70; i++) scene_tick(scene, 1.0 / 60);
    size_t length = 0;
    *saved = scene_file_write(file, &length, NULL);
    scene_file_t *again = parse(*saved);
    why[0] = '\0';
    for (int i = 0; i < 120 && why[0] == '\0'; i++) {
        CHECK(scene_file_same(file, again, why, sizeof why));
        scene_tick(scene, 1.0 / 60);
        scene_tick(scene_file_get_scene(again), 1.0 / 60);
    }
    if (why[0] != '\0') printf("    %s\n", why);
    scene_file_free(again);
    return file;
}

/* A scene of round bodies stepped, saved mid-run and reloaded goes on as the
 * original does, every body the same to the bit at every step; so does one
 * with round bodies the file did not make (a circle exactly, a capsule's
 * ends turned back by its angle to rounding). */
static void round_bodies_saved_mid_run_continue_bit_for_bit(void) {
    const char *text = "gravity 0 -9.81\ncontacts on\n"
                       "body floor { box 20 1; static; position 0 -0.5; friction 0.8 }\n"
                       "body ramp { capsule -6 3 -1 1 0.2; static }\n"
                       "body balls { circle 0.3; position -5 4; repeat 3 2 0.7 0.7; "
                       "elasticity 0.4 }\n"
                       "body rods { capsule -0.4 0 0.4 0 0.2; position 2 1; repeat 2 3 1.3 0.5; "
                       "angle 0.2 }\n";
    char *saved;
    scene_file_t *file = continues_bit_for_bit(text, &saved);
    free(saved);
    scene_t *scene = scene_file_get_scene(file);
    size_t length = 0;
    scene_file_t *again;
    /* Foreign round bodies: written as circle and capsule, loaded back. */
    body_t *ball = body_init_circle((vector_t){3, 6}, 0.4, 2, (rgb_color_t){1, 0, 0});
    body_t *rod = body_init_capsule((vector_t){-3, 6}, (vector_t){-2, 6.5}, 0.3, 1,
                                    (rgb_color_t){0, 1, 0});
    body_set_rotation(ball, 0.7);
    body_set_angular_velocity(rod, 1.5);
    scene_add_body(scene, ball);
    scene_add_body(scene, rod);
    for (int i = 0; i < 10; i++) scene_tick(scene, 1.0 / 60);
    saved = scene_file_write(file, &length, NULL);
    again = parse(saved);
    free(saved);
    scene_t *copy = scene_file_get_scene(again);
    CHECK(scene_bodies(copy) == scene_bodies(scene));
    size_t n = scene_bodies(copy);
    body_t *ball2 = scene_get_body(copy, n - 2), *rod2 = scene_get_body(copy, n - 1);
    CHECK(body_get_shape_kind(ball2) == BODY_SHAPE_CIRCLE);
    CHECK(body_get_round_radius(ball2) == 0.4 && body_get_mass(ball2) == 2);
    CHECK(body_get_centroid(ball2).x == body_get_centroid(ball).x);
    CHECK(body_get_rotation(ball2) == body_get_rotation(ball));
    CHECK(body_get_shape_kind(rod2) == BODY_SHAPE_CAPSULE);
    CHECK(body_get_round_radius(rod2) == 0.3 && body_get_mass(rod2) == 1);
    vector_t a1, a2, b1, b2;
    body_get_core(rod, &a1, &a2);
    body_get_core(rod2, &b1, &b2);
    CHECK_VEC(b1, a1.x, a1.y, 1e-12);
    CHECK_VEC(b2, a2.x, a2.y, 1e-12);
    scene_file_free(again);
    scene_file_free(file);
    CHECK(test_no_leaks());
}

/* Chains in scene files: `chain` and `loop` through points in world
 * coordinates, static; a scene with bodies resting and rolling on them,
 * saved mid-run (their contacts with the chains' segments included) and
 * reloaded, goes on as the original does, to the bit; a chain the file
 * did not make is written and comes back the same. */
static void chains_saved_mid_run_continue_bit_for_bit(void) {
    const char *text = "gravity 0 -9.81\ncontacts on\n"
                       "body ground { chain -8 4  -3 1  0 0  4 0  4.5 0.5  8 3; friction 0.8 }\n"
                       "body pen { loop 5 5  9 5  9 9  5 9; static; elasticity 0.5 }\n"
                       "body balls { circle 0.3; position -6 5; repeat 3 1 0.7 0; "
                       "elasticity 0.2 }\n"
                       "body crates { box 0.5 0.5; position 1 1; repeat 3 1 0.8 0 }\n"
                       "body rod { capsule 6 7 7 7 0.2 }\n";
    char *saved;
    scene_file_t *file = continues_bit_for_bit(text, &saved);
    CHECK(strstr(saved, "    chain -8 4 -3 1 0 0 4 0 4.5 0.5 8 3\n") != NULL);
    CHECK(strstr(saved, "    segment ") != NULL); /* contacts with the chain's segments */
    free(saved);
    scene_t *scene = scene_file_get_scene(file);
    body_t *ground = body_at(file, 0);
    CHECK(body_get_shape_kind(ground) == BODY_SHAPE_CHAIN && !body_is_loop(ground));
    CHECK(body_get_segment_count(ground) == 5 && isinf(body_get_mass(ground)));
    CHECK(body_is_loop(body_at(file, 1)) && body_get_segment_count(body_at(file, 1)) == 4);
    size_t length = 0;
    scene_file_t *again;
    /* A chain the file did not make, moved: its points in its frame. */
    body_t *shelf = body_init_chain((vector_t[]){{0, 0}, {1, 0.1}, {2, 0}}, 3, false,
                                    (rgb_color_t){0, 0, 1});
    body_set_centroid(shelf, (vector_t){-2, 6});
    scene_add_body(scene, shelf);
    saved = scene_file_write(file, &length, NULL);
    again = parse(saved);
    free(saved);
    scene_t *copy = scene_file_get_scene(again);
    body_t *shelf2 = scene_get_body(copy, scene_bodies(copy) - 1);
    CHECK(body_get_shape_kind(shelf2) == BODY_SHAPE_CHAIN && body_get_segment_count(shelf2) == 2);
    vector_t a1, a2, b1, b2;
    body_get_segment(shelf, 1, &a1, &a2);
    body_get_segment(shelf2, 1, &b1, &b2);
    CHECK(a1.x == b1.x && a1.y == b1.y && a2.x == b2.x && a2.y == b2.y);
    scene_file_free(again);
    scene_file_free(file);
    CHECK(test_no_leaks());
}

static void mass_density_or_static(void) {
    scene_file_t *file = parse("body a { box 2 3; mass 5 }\n"
                               "body b { box 2 3; density 2 }\n"
                               "body c { box 2 3 }\n"
                               "body d { box 2 3; static }\n");
    CHECK_NEAR(body_get_mass(body_at(file, 0)), 5, 0);
    CHECK_NEAR(body_get_mass(body_at(file, 1)), 12, 1e-12);
    CHECK_NEAR(body_get_mass(body_at(file, 2)), 6, 1e-12); /* density 1 by default */
    CHECK(isinf(body_get_mass(body_at(file, 3))));
    CHECK_NEAR(body_get_inertia(body_at(file, 0)), 5 * (4 + 9) / 12.0, 1e-12);
    scene_file_free(file);
}

static void pose_motion_and_material_reach_the_body(void) {
    scene_file_t *file = parse("body a {\n"
                               "    box 1 1; position 3 4; angle 90deg; velocity 1 -2\n"
                               "    spin -1.5; elasticity 0.75; friction 0.2\n"
                               "    color 0.1 0.2 0.3; tag crate\n"
                               "}\n"
                               "body b { regular 3 1 }\n");
    body_t *a = body_at(file, 0), *b = body_at(file, 1);
    CHECK_VEC(body_get_centroid(a), 3, 4, 0);
    CHECK_NEAR(body_get_rotation(a), M_PI / 2, 1e-15);
    CHECK_VEC(body_get_velocity(a), 1, -2, 0);
    CHECK_NEAR(body_get_angular_velocity(a), -1.5, 0);
    CHECK_NEAR(body_get_elasticity(a), 0.75, 0);
    CHECK_NEAR(body_get_friction(a), 0.2, 0);
    CHECK_NEAR(body_get_color(a).g, 0.2, 0);
    CHECK(strcmp(tag(a), "crate") == 0);
    /* Defaults: at rest, elasticity 0, friction 0.6, tag "". */
    CHECK_VEC(body_get_velocity(b), 0, 0, 0);
    CHECK_NEAR(body_get_elasticity(b), 0, 0);
    CHECK_NEAR(body_get_friction(b), 0.6, 0);
    CHECK(strcmp(tag(b), "") == 0);
    scene_file_free(file);
}

static void filters_keep_bodies_apart(void) {
    /* Two boxes thrown at each other with world contacts: they bounce, unless
     * their filters say no. */
    const char *base = "contacts on\n"
                       "body a { box 1 1; position -2 0; velocity 5 0; elasticity 1 %s }\n"
                       "body b { box 1 1; position 2 0; velocity -5 0; elasticity 1 %s }\n";
    char text[512];
    snprintf(text, sizeof text, base, "", "");
    scene_file_t *colliding = parse(text);
    snprintf(text, sizeof text, base, "; filter 1 1 0", "; filter 2 2 0");
    scene_file_t *apart = parse(text);
    for (int i = 0; i < 120; i++) {
        scene_tick(scene_file_get_scene(colliding), 1.0 / 60);
        scene_tick(scene_file_get_scene(apart), 1.0 / 60);
    }
    CHECK(body_get_centroid(body_at(colliding, 0)).x < -2);
    CHECK(body_get_centroid(body_at(apart, 0)).x > 2);
    scene_file_free(colliding);
    scene_file_free(apart);
}

static void repeat_makes_a_group_of_copies(void) {
    scene_file_t *file = parse("body brick { box 1 0.5; static; position -2 5; repeat 3 2 2 1 }\n"
                               "body ball { regular 8 0.2; position 0 0 }\n"
                               "collide ball brick physics 1\n");
    CHECK(bodies(file) == 7);
    /* Rows from the bottom, left to right within a row. */
    CHECK_VEC(body_get_centroid(body_at(file, 0)), -2, 5, 1e-12);
    CHECK_VEC(body_get_centroid(body_at(file, 2)), 2, 5, 1e-12);
    CHECK_VEC(body_get_centroid(body_at(file, 3)), -2, 6, 1e-12);
    CHECK(scene_file_force_count(file) == 6);
    /* The copies are the group: no single body is called brick. */
    CHECK(scene_file_find_body(file, "brick") == NULL);
    CHECK(scene_file_find_body(file, "ball") == body_at(file, 6));
    scene_file_free(file);
}

static void forces_and_rules_make_their_pairs(void) {
    scene_file_t *file = parse("body a { box 1 1; position 0 0 }\n"
                               "body b { box 1 1; position 3 0 }\n"
                               "body c { box 1 1; position 6 0; group g }\n"
                               "body d { box 1 1; position 9 0; group g }\n"
                               "spring 5 a b\n"            /* 1 */
                               "newton 2 all\n"            /* 4 bodies: 6 pairs */
                               "newton 3 a g\n"            /* a, c, d: 3 pairs */
                               "drag 0.5 b g\n"            /* 3 */
                               "collide a g physics 0.5\n" /* 2 */
                               "collide g g destructive\n" /* c-d once */
                               "collide all g physics 1\n" /* a,b with c,d: 4, and c-d once: 5 */
    );
    CHECK(scene_file_force_count(file) == 1 + 6 + 3 + 3 + 2 + 1 + 5);
    scene_file_force_t spring = scene_file_get_force(file, 0);
    CHECK(spring.kind == SCENE_FILE_SPRING);
    CHECK_NEAR(spring.constant, 5, 0);
    CHECK(spring.body1 == body_at(file, 0) && spring.body2 == body_at(file, 1));
    scene_file_force_t drag = scene_file_get_force(file, 10);
    CHECK(drag.kind == SCENE_FILE_DRAG && drag.body2 == NULL && drag.body1 == body_at(file, 1));
    scene_file_force_t rule = scene_file_get_force(file, 13);
    CHECK(rule.kind == SCENE_FILE_PHYSICS_COLLISION);
    CHECK(rule.body1 == body_at(file, 0) && rule.body2 == body_at(file, 2));
    scene_file_force_t destroy = scene_file_get_force(file, 15);
    CHECK(destroy.kind == SCENE_FILE_DESTRUCTIVE_COLLISION);
    CHECK(destroy.body1 == body_at(file, 2) && destroy.body2 == body_at(file, 3));
    /* The spring pulls: a moves toward b. */
    scene_tick(scene_file_get_scene(file), 0.01);
    CHECK(body_get_velocity(body_at(file, 0)).x > 0);
    scene_file_free(file);
}

static void springs_may_have_a_rest_length(void) {
    /* `length L` after the bodies: create_spring_with_length, which pushes
     * a and b apart when closer than L and pulls them together beyond it;
     * without it the spring's rest length is 0. One tick of 0.01 s on 1 kg
     * boxes 3 m apart: k (d - L) dt / m along the line. */
    scene_file_t *file = parse("body a { box 1 1; mass 1; position 0 0 }\n"
                               "body b { box 1 1; mass 1; position 3 0 }\n"
                               "body c { box 1 1; mass 1; position 0 5 }\n"
                               "body d { box 1 1; mass 1; position 3 5 }\n"
                               "body e { box 1 1; mass 1; position 0 10 }\n"
                               "body f { box 1 1; mass 1; position 3 10 }\n"
                               "spring 10 a b length 5\n"
                               "spring 10 c d length 1.5\n"
                               "spring 10 e f\n");
    CHECK(scene_file_force_count(file) == 3);
    CHECK_NEAR(scene_file_get_force(file, 0).rest_length, 5, 0);
    CHECK_NEAR(scene_file_get_force(file, 1).rest_length, 1.5, 0);
    CHECK_NEAR(scene_file_get_force(file, 2).rest_length, 0, 0);
    CHECK(scene_file_get_force(file, 0).kind == SCENE_FILE_SPRING);
    scene_tick(scene_file_get_scene(file), 0.01);
    CHECK_NEAR(body_get_velocity(body_at(file, 0)).x, 10 * (3 - 5) * 0.01, 1e-15);
    CHECK_NEAR(body_get_velocity(body_at(file, 2)).x, 10 * (3 - 1.5) * 0.01, 1e-15);
    CHECK_NEAR(body_get_velocity(body_at(file, 4)).x, 10 * 3 * 0.01, 1e-15);
    /* Written back with its length, and read again the same. */
    size_t length = 0;
    char *text = scene_file_write(file, &length, NULL);
    CHECK(strstr(text, "spring 10 a b length 5\n") != NULL);
    CHECK(strstr(text, "spring 10 c d length 1.5\n") != NULL);
    CHECK(strstr(text, "spring 10 e f\n") != NULL);
    char why[256] = "";
    CHECK(scene_file_round_trip((const uint8_t *)text, length, "t.scene", why, sizeof why));
    if (why[0] != '\0') printf("    %s\n", why);
    free(text);
    scene_file_free(file);
}

static void layout_is_free(void) {
    /* Semicolons, blank lines, CRLF, a brace on its own line, a vertex list
     * over several lines, fractions, comments anywhere. */
    scene_file_t *file = parse("gravity 0 -10; contacts off\r\n"
                               "\r\n"
                               "body tri   # a triangle\r\n"
                               "{\r\n"
                               "    vertices 0 0   1/2 0\r\n"
                               "             0 1/2 # the last vertex\r\n"
                               "    mass 1/4\r\n"
                               "}\r\n");
    CHECK(bodies(file) == 1);
    CHECK_NEAR(body_get_mass(body_at(file, 0)), 0.25, 0);
    CHECK_VEC(body_get_centroid(body_at(file, 0)), 1.0 / 6, 1.0 / 6, 1e-15);
    scene_file_free(file);
}

static void names_and_groups_may_be_used_before_their_blocks(void) {
    scene_file_t *file = parse("group empty\n"
                               "collide ball brick physics 1\n"
                               "drag 1 empty\n"
                               "body ball { regular 8 0.2 }\n"
                               "body { box 1 1; position 3 0; group brick }\n");
    CHECK(scene_file_force_count(file) == 1);
    scene_file_free(file);
}

/* ---- Templates and the live scene ---------------------------------------- */

static void spawn_applies_the_rules_of_its_groups(void) {
    scene_file_t *file = parse("body target { box 1 1; static; position 0 5; repeat 3 1 2 0 }\n"
                               "body other { box 1 1; static; position 0 -5 }\n"
                               "template shot { box 0.1 0.3; mass 0.1; tag shot; group bullets }\n"
                               "collide shot target destructive\n"
                               "drag 0.1 bullets\n");
    CHECK(bodies(file) == 4);
    CHECK(scene_file_force_count(file) == 0);
    CHECK(scene_file_has_template(file, "shot"));
    CHECK(!scene_file_has_template(file, "target"));
    body_t *shot = scene_file_spawn(file, "shot", (vector_t){0, 0}, (vector_t){0, 10});
    CHECK(shot != NULL && bodies(file) == 5);
    CHECK(strcmp(tag(shot), "shot") == 0);
    CHECK_VEC(body_get_centroid(shot), 0, 0, 1e-15);
    CHECK_VEC(body_get_velocity(shot), 0, 10, 0);
    CHECK(scene_file_force_count(file) == 3 + 1);
    /* Nothing spawns from a name that is no template, or at a non-finite or
     * out-of-range place. */
    CHECK(scene_file_spawn(file, "target", VEC_ZERO, VEC_ZERO) == NULL);
    CHECK(scene_file_spawn(file, "nothing", VEC_ZERO, VEC_ZERO) == NULL);
    CHECK(scene_file_spawn(file, "shot", (vector_t){NAN, 0}, VEC_ZERO) == NULL);
    CHECK(scene_file_spawn(file, "shot", (vector_t){2e9, 0}, VEC_ZERO) == NULL);
    CHECK(bodies(file) == 5);
    /* The shot flies into the first target: both disappear, and so do their
     * force creators. */
    for (int i = 0; i < 60; i++) scene_tick(scene_file_get_scene(file), 1.0 / 60);
    CHECK(bodies(file) == 3);
    CHECK(scene_file_force_count(file) == 0);
    scene_file_free(file);
    CHECK(test_no_leaks());
}

static void many_spawns_and_destructions_leave_nothing_behind(void) {
    /* A game that fires for a long time: every shot hits a wall that is
     * replaced at once, and what the file keeps about the destroyed ones is
     * dropped as it goes (sf_collect). */
    scene_file_t *file = parse("template wall { box 10 1; static; tag wall }\n"
                               "template shot { box 0.1 0.3; mass 0.1; tag shot }\n"
                               "collide shot wall destructive\n");
    for (int round = 0; round < 600; round++) {
        CHECK(scene_file_spawn(file, "wall", (vector_t){0, 5}, VEC_ZERO) != NULL);
        CHECK(scene_file_spawn(file, "shot", (vector_t){0, 4.5}, (vector_t){0, 10}) != NULL);
        CHECK(scene_file_force_count(file) == 1);
        scene_tick(scene_file_get_scene(file), 1.0 / 60);
        CHECK(bodies(file) == 0);
    }
    CHECK(scene_file_force_count(file) == 0);
    scene_file_free(file);
    CHECK(test_no_leaks());
}

static void find_body_forgets_freed_bodies(void) {
    scene_file_t *file = parse("body a { box 1 1 }\nbody b { box 1 1; position 5 0 }\n");
    body_t *a = scene_file_find_body(file, "a");
    CHECK(a == body_at(file, 0));
    body_remove(a);
    CHECK(scene_file_find_body(file, "a") == a); /* marked, not yet freed */
    scene_tick(scene_file_get_scene(file), 0);
    CHECK(scene_file_find_body(file, "a") == NULL);
    CHECK(scene_file_find_body(file, "b") == body_at(file, 0));
    CHECK(scene_file_find_body(file, "nothing") == NULL);
    scene_file_free(file);
}

/* A sample's category and note: the words to the end of the statement, one
 * space between them, kept through a save. */
static void category_and_note_are_kept(void) {
    scene_file_t *file = parse("category   Integrators and accuracy   # a comment\n"
                               "note watch the orbits: closed for 20 s; body a { box 1 1 }\n");
    CHECK(strcmp(scene_file_get_category(file), "Integrators and accuracy") == 0);
    CHECK(strcmp(scene_file_get_note(file), "watch the orbits: closed for 20 s") == 0);
    CHECK(bodies(file) == 1);
    char *text = scene_file_write(file, NULL, NULL);
    CHECK(text != NULL && strstr(text, "\ncategory Integrators and accuracy\n") != NULL &&
          strstr(text, "\nnote watch the orbits: closed for 20 s\n") != NULL);
    scene_file_t *again = parse(text);
    char why[128] = "";
    CHECK(again != NULL && scene_file_same(file, again, why, sizeof why));
    free(text);
    scene_file_free(again);
    scene_file_free(file);
    file = parse("body a { box 1 1 }\n");
    CHECK(strcmp(scene_file_get_category(file), "") == 0 &&
          strcmp(scene_file_get_note(file), "") == 0);
    scene_file_free(file);
}

/* The settings a program changes while the scene runs (the sandbox's
 * solver panel) reach the scene and are written. */
static void settings_changed_live_are_written(void) {
    scene_file_t *file = parse("body a { box 1 1 }\n");
    scene_t *scene = scene_file_get_scene(file);
    CHECK(scene_file_get_workers(file) == 0 &&
          scene_file_get_stepping(file) == SCENE_FILE_STEP_FIXED);
    char *plain = scene_file_write(file, NULL, NULL);
    CHECK(plain != NULL && strstr(plain, "\niterations 8 4\n") != NULL &&
          strstr(plain, "warm_starting") == NULL && strstr(plain, "restitution_threshold") == NULL &&
          strstr(plain, "sleep_tolerance") == NULL && strstr(plain, "sleep_time") == NULL);
    free(plain);
    scene_set_solver_iterations(scene, 12, 6);
    scene_set_warm_starting(scene, false);
    scene_set_restitution_threshold(scene, 0.25);
    scene_set_sleep_tolerance(scene, 0.03, 0.5);
    scene_set_sleep_time(scene, 2);
    CHECK(scene_file_set_timestep(file, 1.0 / 240));
    CHECK(!scene_file_set_timestep(file, 0) && !scene_file_set_timestep(file, NAN) &&
          !scene_file_set_timestep(file, 11));
    scene_file_set_stepping(file, SCENE_FILE_STEP_FRAME);
    scene_set_workers(scene_file_get_scene(file), 3);
    char *text = scene_file_write(file, NULL, NULL);
    CHECK(text != NULL && strstr(text, "\niterations 12 6\n") != NULL &&
          strstr(text, "\ntimestep 0.004166666666666667\n") != NULL &&
          strstr(text, "\nworkers 3\n") != NULL && strstr(text, "\nstepping frame\n") != NULL &&
          strstr(text, "\nwarm_starting off\n") != NULL &&
          strstr(text, "\nrestitution_threshold 0.25\n") != NULL &&
          strstr(text, "\nsleep_tolerance 0.03 0.5\n") != NULL &&
          strstr(text, "\nsleep_time 2\n") != NULL);
    scene_file_t *again = parse(text);
    char why[128] = "";
    CHECK(again != NULL && scene_file_same(file, again, why, sizeof why));
    CHECK(again != NULL && scene_file_get_workers(again) == 3 &&
          scene_get_workers(scene_file_get_scene(again)) == 3 &&
          scene_file_get_timestep(again) == 1.0 / 240);
    double linear = 0, angular = 0;
    if (again != NULL) scene_get_sleep_tolerance(scene_file_get_scene(again), &linear, &angular);
    CHECK(linear == 0.03 && angular == 0.5);
    free(text);
    scene_file_free(again);
    scene_file_free(file);
}

static void body_names_are_found_from_their_bodies(void) {
    scene_file_t *file = parse("body a { box 1 1 }\nbody { box 1 1; position 5 0 }\n"
                               "body row { box 1 1; position 0 5; repeat 2 1 2 0 }\n"
                               "template shot { box 0.1 0.3; mass 0.1 }\n");
    CHECK(strcmp(scene_file_body_name(file, body_at(file, 0)), "a") == 0);
    CHECK(strcmp(scene_file_body_name(file, body_at(file, 1)), "") == 0);
    CHECK(strcmp(scene_file_body_name(file, body_at(file, 3)), "row") == 0);
    body_t *shot = scene_file_spawn(file, "shot", VEC_ZERO, VEC_ZERO);
    CHECK(strcmp(scene_file_body_name(file, shot), "shot") == 0);
    /* A body the file did not make, and NULL arguments. */
    list_t *shape = polygon_make_box((vector_t){0, 9}, 0.5, 0.5);
    body_t *mine = body_init(shape, 1, (rgb_color_t){1, 1, 1});
    scene_add_body(scene_file_get_scene(file), mine);
    CHECK(scene_file_body_name(file, mine) == NULL);
    CHECK(scene_file_body_name(NULL, mine) == NULL);
    CHECK(scene_file_body_name(file, NULL) == NULL);
    scene_file_free(file);
}

/* ---- Writing -------------------------------------------------------------- */

static void written_scenes_load_back_the_same(void) {
    const char *text = "gravity 0 -9.81\ncontacts on\ntimestep 1/60\nview 0 5 20 12\n"
                       "body floor { box 20 1; static; position 0 -0.5; friction 0.9 }\n"
                       "body pile { regular 5 0.4; density 2; position -3 2; repeat 4 3 1 1; "
                       "elasticity 0.3; group stuff }\n"
                       "body odd { vertices 0 0 1 0 1.5 0.7 0.2 1.1; position 0 6; angle 0.1 }\n"
                       "template shot { box 0.1 0.2; mass 0.05; tag shot; filter 0x2 0xfffd 0 }\n"
                       "spring 10 odd floor\ndrag 0.2 stuff\n"
                       "collide shot stuff destructive\n";
    char why[256] = "";
    CHECK(scene_file_round_trip((const uint8_t *)text, strlen(text), "t.scene", why, sizeof why));
    if (why[0] != '\0') printf("    %s\n", why);
}

static void a_running_scene_is_written_as_it_is_now(void) {
    scene_file_t *file = parse("gravity 0 -9.81\ncontacts on\n"
                               "body floor { box 20 1; static; position 0 -0.5 }\n"
                               "body box { box 1 1; position 0 3; repeat 3 1 1.5 0 }\n"
                               "body doomed { box 1 1; position 5 3 }\n"
                               "template shot { box 0.1 0.3; mass 0.1; tag shot }\n"
                               "spring 1 doomed floor\n"
                               "collide shot box destructive\n");
    scene_t *scene = scene_file_get_scene(file);
    for (int i = 0; i < 90; i++) scene_tick(scene, 1.0 / 60);
    /* A shot that lands on the floor, away from the boxes: its rules stay. */
    CHECK(scene_file_spawn(file, "shot", (vector_t){-8, 2}, VEC_ZERO) != NULL);
    /* A body the file did not make: written as vertices with its mass. */
    body_t *dropped =
        body_init(polygon_make_regular(5, 0.5, (vector_t){8, 1}, 0.3), 2, (rgb_color_t){1, 0, 0});
    body_set_velocity(dropped, (vector_t){0.5, 0});
    scene_add_body(scene, dropped);
    body_remove(scene_file_find_body(file, "doomed"));
    for (int i = 0; i < 30; i++) scene_tick(scene, 1.0 / 60);
    size_t length = 0;
    char *text = scene_file_write(file, &length, NULL);
    CHECK(strstr(text, "spring") == NULL); /* went with doomed */
    CHECK(strstr(text, "collide shot box destructive") != NULL);
    scene_file_error_t error;
    scene_file_t *reloaded = scene_file_parse(text, length, "saved", &error);
    CHECK(reloaded != NULL);
    if (reloaded != NULL) {
        scene_t *again = scene_file_get_scene(reloaded);
        CHECK(scene_bodies(again) == scene_bodies(scene));
        for (size_t i = 0; i + 1 < scene_bodies(scene); i++) {
            body_t *a = scene_get_body(scene, i), *b = scene_get_body(again, i);
            CHECK(body_get_centroid(a).x == body_get_centroid(b).x);
            CHECK(body_get_rotation(a) == body_get_rotation(b));
            CHECK(body_get_velocity(a).y == body_get_velocity(b).y);
        }
        /* The dropped body, rebuilt from its world vertices: the same to
         * rounding. */
        body_t *last = scene_get_body(again, scene_bodies(again) - 1);
        CHECK_VEC(body_get_centroid(last), body_get_centroid(dropped).x,
                  body_get_centroid(dropped).y, 1e-12);
        CHECK_NEAR(body_get_mass(last), 2, 0);
        CHECK_VEC(body_get_velocity(last), body_get_velocity(dropped).x,
                  body_get_velocity(dropped).y, 0);
        /* The shot's rules come last in the running scene, in file order in
         * the reloaded one. */
        char why[256] = "";
        CHECK(scene_file_force_count(file) == 3);
        CHECK(scene_file_same_forces_in_any_order(file, reloaded, why, sizeof why));
        if (why[0] != '\0') printf("    %s\n", why);
        scene_file_free(reloaded);
    } else {
        printf("    %s\n", error.message);
    }
    free(text);
    scene_file_free(file);
    CHECK(test_no_leaks());
}

/* step_lengths, a contact's previous points and its face's lead reach the
 * world (a face without a lead: INFINITY, reused as before leads were
 * kept), and a scene written after steps of two lengths carries them. */
static void step_lengths_and_previous_points_reach_the_world(void) {
    const char *text = "contacts on\nstep_lengths 1/120 0.0125\n"
                       "body floor { box 10 1; static; position 0 -0.5 }\n"
                       "body box { box 1 1; position 0 0.5 }\n"
                       "contact 0 1 {\n    normal 0 1\n    point 131072 -0.5 0 0 0.02 0 0 0\n"
                       "    face a 0 1 5 0.5 lead 0.75 edge\n    incident 131072 -0.5 -0.5\n"
                       "    pose 0 1 0\n    previous 131072 0.03 -0.25\n"
                       "    previous 7 1e-300 0\n}\n";
    scene_file_t *file = parse(text);
    scene_t *scene = scene_file_get_scene(file);
    double last = 0.0, before = 0.0;
    scene_get_step_lengths(scene, &last, &before);
    CHECK(last == 1.0 / 120.0 && before == 0.0125);
    CHECK(scene_contact_memory_count(scene) == 1);
    scene_contact_memory_t m = scene_get_contact_memory(scene, 0);
    CHECK(m.previous_count == 2);
    CHECK(m.face_lead == 0.75 && m.edge_ends);
    CHECK(m.previous[0].id == 131072 && m.previous[0].normal_impulse == 0.03 &&
          m.previous[0].tangent_impulse == -0.25);
    CHECK(m.previous[1].id == 7 && m.previous[1].normal_impulse == 1e-300 &&
          m.previous[1].tangent_impulse == 0.0);
    char why[256] = "";
    CHECK(scene_file_round_trip((const uint8_t *)text, strlen(text), "t.scene", why, sizeof why));
    if (why[0] != '\0') printf("    %s\n", why);
    scene_file_free(file);

    file = parse("contacts on\nbody floor { box 10 1; static; position 0 -0.5 }\n"
                 "body box { box 1 1; position 0 0.5 }\n"
                 "contact 0 1 { normal 0 1; face a 0 1 0 0; pose 0 1 0 }\n");
    m = scene_get_contact_memory(scene_file_get_scene(file), 0);
    CHECK(m.face_lead == INFINITY);
    scene_file_free(file);

    file = parse("gravity 0 -10\ncontacts on\nbody floor { box 10 1; static; position 0 -0.5 }\n"
                 "body box { box 1 1; position 0 0.5 }\n");
    scene = scene_file_get_scene(file);
    size_t length = 0;
    char *written = scene_file_write(file, &length, NULL);
    CHECK(strstr(written, "step_lengths") == NULL); /* no step yet */
    free(written);
    scene_tick(scene, 1.0 / 60.0);
    scene_tick(scene, 1.0 / 30.0);
    scene_tick(scene, 1.0 / 90.0);
    written = scene_file_write(file, &length, NULL);
    CHECK(strstr(written, "step_lengths 0.011111111111111112 0.03333333333333333\n") != NULL);
    CHECK(strstr(written, "    previous ") != NULL);
    free(written);
    scene_file_free(file);
    CHECK(test_no_leaks());
}

static void save_and_load_through_a_path(void) {
    scene_file_t *file = parse("gravity 0 -1\nbody a { regular 7 1; position 1 2 }\n");
    char path[] = "/tmp/scene_file_test_XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    close(fd);
    scene_file_error_t error;
    CHECK(scene_file_save(file, path, &error));
    scene_file_t *loaded = scene_file_load(path, &error);
    CHECK(loaded != NULL);
    char why[256] = "";
    CHECK(loaded != NULL && scene_file_same(file, loaded, why, sizeof why));
    remove(path);
    CHECK(scene_file_load(path, &error) == NULL);
    CHECK(strstr(error.message, "scene_file_test_") != NULL);
    CHECK(strstr(error.message, ": cannot read: No such file or directory") != NULL);
    CHECK(error.line == 0 && error.column == 0);
    CHECK(!scene_file_save(file, "/nonexistent-directory/x.scene", &error));
    CHECK(strstr(error.message, "/nonexistent-directory/x.scene: cannot write: ") != NULL);
    scene_file_free(loaded);
    scene_file_free(file);
}

/* ---- Malformed files ------------------------------------------------------ */

typedef struct {
    const char *text;
    const char *message;
} bad_file_t;

#define DRAGS_10                                                                             \
    "drag 1 all\ndrag 1 all\ndrag 1 all\ndrag 1 all\ndrag 1 all\ndrag 1 all\ndrag 1 all\n"        \
    "drag 1 all\ndrag 1 all\ndrag 1 all\n"
#define DRAGS_100 DRAGS_10 DRAGS_10 DRAGS_10 DRAGS_10 DRAGS_10 DRAGS_10 DRAGS_10 DRAGS_10 DRAGS_10 DRAGS_10

static const bad_file_t BAD_FILES[] = {
    {"bdoy x { box 1 1 }",
     "t.scene:1:1: expected a statement (body, template, group, gravity, contacts, integrator, "
     "iterations, warm_starting, restitution_threshold, sleep_tolerance, sleep_time, timestep, "
     "view, game, sleeping, sleep_phase, solver_steps, step_lengths, workers, stepping, category, "
     "note, spring, newton, drag, collide, contact, joint), found \"bdoy\""},
    {"warm_starting maybe", "t.scene:1:15: expected on or off (warm starting), found \"maybe\""},
    {"warm_starting on\nwarm_starting off",
     "t.scene:2:1: expected one warm_starting statement per file, found a second (the first at "
     "line 1)"},
    {"restitution_threshold -1", "t.scene:1:23: expected the restitution threshold (m/s), a "
                                 "number >= 0 and <= 100, found \"-1\""},
    {"sleep_tolerance 0", "t.scene:1:17: expected the linear sleep tolerance (m/s), a number > 0 "
                          "and <= 10, found \"0\""},
    {"sleep_tolerance 0.01 101", "t.scene:1:22: expected the angular sleep tolerance (rad/s), a "
                                 "number > 0 and <= 100, found \"101\""},
    {"sleep_time 0", "t.scene:1:12: expected the sleep time (s), a number > 0 and <= 1000, found "
                     "\"0\""},
    {"gravity 0 abc",
     "t.scene:1:11: expected a gravity component (m/s^2), a number, found \"abc\""},
    {"gravity 0 1e999",
     "t.scene:1:11: expected a gravity component (m/s^2), a finite number, found \"1e999\""},
    {"gravity 0 nan",
     "t.scene:1:11: expected a gravity component (m/s^2), a number, found \"nan\""},
    {"gravity 0\n",
     "t.scene:1:10: expected a gravity component (m/s^2), a number, found the end of the line"},
    {"gravity 0 1e10", "t.scene:1:11: expected a gravity component (m/s^2), a number >= -1e+09 and "
                       "<= 1e+09, found \"1e10\""},
    {"timestep 1/0", "t.scene:1:10: expected the timestep (s), a fraction with a denominator other "
                     "than 0, found \"1/0\""},
    {"timestep 0", "t.scene:1:10: expected the timestep (s), a number > 0 and <= 10, found \"0\""},
    {"contacts maybe", "t.scene:1:10: expected on or off (world contacts), found \"maybe\""},
    {"integrator rk5", "t.scene:1:12: expected an integrator (seed, explicit_euler, "
                       "symplectic_euler, velocity_verlet, rk4, symplectic4, implicit_euler), found \"rk5\""},
    {"iterations 0 4",
     "t.scene:1:12: expected the velocity iterations, a whole number from 1 to 1000, found \"0\""},
    {"gravity 0 -10\ngravity 0 -9",
     "t.scene:2:1: expected one gravity statement per file, found a second (the first at line 1)"},
    {"view 0 0 0 10",
     "t.scene:1:10: expected a view size (m), a number > 0 and <= 2e+09, found \"0\""},
    {"game 3d",
     "t.scene:1:6: expected the game's name (a letter or '_', then letters, digits, '_', "
     "'.' or '-', at most 63 characters), found \"3d\""},
    {"body a { box 1 1 } extra",
     "t.scene:1:20: expected the end of the statement (a new line or ';'), found \"extra\""},
    {"body a { box 1 1 extra }",
     "t.scene:1:18: expected the end of the property (a new line, ';' or '}'), found \"extra\""},
    {"body a box 1 1", "t.scene:1:8: expected '{' to open the block, found \"box\""},
    {"body a { regular 2 1 }",
     "t.scene:1:18: expected the number of sides, a whole number from 3 to 1000, found \"2\""},
    {"body a { regular 5 -1 }",
     "t.scene:1:20: expected the radius (m), a number > 0 and <= 1e+09, found \"-1\""},
    {"body a { box 1 }", "t.scene:1:16: expected the height (m), a number, found '}'"},
    {"body a { vertices 0 0 1 0 }",
     "t.scene:1:27: expected at least 3 vertices (x y pairs), 2 so far, found '}'"},
    {"body a { vertices 0 0 1 0 1 }",
     "t.scene:1:29: expected the y of vertex 3 (m), a number, found '}'"},
    {"body a { vertices 0 0 2 0 1 0.2 2 2 0 2 }",
     "t.scene:1:10: expected a usable shape (convex, distinct vertices, some area), found one that "
     "is refused: polygon is not strictly convex: a vertex turns against the winding"},
    {"body a { vertices 0 0 1 0 2 0 1 1 }",
     "t.scene:1:10: expected a usable shape (convex, distinct vertices, some area), found one that "
     "is refused: polygon is not strictly convex: three consecutive vertices are collinear"},
    {"body a { vertices 0 0 1 0 1 0 0 1 }",
     "t.scene:1:10: expected a usable shape (convex, distinct vertices, some area), found one that "
     "is refused: polygon repeats a vertex"},
    {"body a { vertices 0 0 1 1 2 2 }",
     "t.scene:1:10: expected a usable shape (convex, distinct vertices, some area), found one that "
     "is refused: polygon has zero area"},
    {"body a { vertices 0 0 1 0 0 1 1 1 }",
     "t.scene:1:10: expected a usable shape (convex, distinct vertices, some area), found one that "
     "is refused: polygon has zero area"}, /* a bow tie: its two halves cancel */
    {"body star { vertices 0 1  -0.5878 -0.809  0.9511 0.309  -0.9511 0.309  0.5878 -0.809 }",
     "t.scene:1:13: expected a usable shape (convex, distinct vertices, some area), found one that "
     "is refused: polygon winds around more than once"},
    {"body a { box 1 1; mass -1 }",
     "t.scene:1:24: expected the mass (kg), a number > 0 and <= 1e+40, found \"-1\""},
    {"body a { box 1 1; mass 1e-310 }",
     "t.scene:1:19: expected a mass whose inverse is finite, found mass 1e-310 kg"},
    {"body a { box 1e-20 1e-20; mass 1e-280 }",
     "t.scene:1:27: expected a moment of inertia from 1e-290 to 1e+290 kg m^2, found 1.665e-321 "
     "kg m^2 (mass 1e-280 kg on this shape)"},
    /* The moment of so small a shape underflows on the way (to 0): refused,
     * as the engine would refuse it. */
    {"body a { box 1e-150 1e-150 }",
     "t.scene:1:10: expected a moment of inertia from 1e-290 to 1e+290 kg m^2, found 0 kg m^2 "
     "(density 1 kg/m^2 on 1e-300 m^2, 1e-300 kg on this shape)"},
    {"body a { circle 0 }",
     "t.scene:1:17: expected the radius (m), a number > 0 and <= 1e+09, found \"0\""},
    {"body a { circle }",
     "t.scene:1:17: expected the radius (m), a number, found '}'"},
    {"body a { chain 0 0 }",
     "t.scene:1:20: expected at least 2 points (x y pairs), 1 so far, found '}'"},
    {"body a { loop 0 0 1 0 }",
     "t.scene:1:23: expected at least 3 points (x y pairs), 2 so far, found '}'"},
    {"body a { chain 0 0 1 0 1 0 }",
     "t.scene:1:10: expected segments of some length, found point 3 (1, 0) equal to point 2"},
    {"body a { loop 0 0 1 0 1 1 0 0 }",
     "t.scene:1:10: expected segments of some length, found point 1 (0, 0) equal to point 4"},
    {"body a { chain 0 0 1 0; mass 2 }",
     "t.scene:1:25: expected a chain to be static (static, or no mass), found a mass"},
    {"template a { chain 0 0 1 0 }",
     "t.scene:1:14: expected no chain in a template (a game spawns moving copies), found one"},
    {"body a { chain 0 0 1 0; velocity 1 0 }",
     "t.scene:1:25: expected a chain at rest (it is static), found a velocity"},
    {"body a { chain 0 0 nan 0 }",
     "t.scene:1:20: expected at least 2 points (x y pairs), 1 so far, found \"nan\""},
    {"contacts on\nbody a { chain 0 0 1 0 }\nbody b { box 1 1 }\n"
     "contact 1 0 { segment 3; normal 0 1; pose 0 0 0 }",
     "t.scene:4:1: expected a segment of body 0 (it has 1), found segment 3"},
    {"body a { capsule 0 0 1 0 -1 }",
     "t.scene:1:26: expected the radius (m), a number > 0 and <= 1e+09, found \"-1\""},
    {"body a { capsule 0 0 1 }",
     "t.scene:1:24: expected the y of the second end (m), a number, found '}'"},
    {"body a { capsule 0 0 x 0 1 }",
     "t.scene:1:22: expected the x of the second end (m), a number, found \"x\""},
    {"body a { capsule 1 2 1 2 0.5 }",
     "t.scene:1:26: expected capsule ends at least 1e-09 of the radius apart (circle R for a "
     "circle), found them 0 m apart with radius 0.5 m"},
    {"body a { circle 1; centred }",
     "t.scene:1:10: expected centred with a vertices shape, found it with a circle"},
    {"body a { circle 1; box 1 1 }",
     "t.scene:1:20: expected one shape (regular, box, vertices, circle, capsule, chain or loop) per body, found "
     "a second (the first at line 1)"},
    {"body a { box 1 1; elasticity -0.5 }",
     "t.scene:1:30: expected the elasticity, a number >= 0 and <= 1e+09, found \"-0.5\""},
    {"body a { box 1 1; color 2 0 0 }",
     "t.scene:1:25: expected the red component of the colour, a number >= 0 and <= 1, found \"2\""},
    {"body a { box 1 1; position 30deg 0 }",
     "t.scene:1:28: expected a coordinate (m), a number, found \"30deg\""},
    {"body a { box 1 1; box 2 2 }",
     "t.scene:1:19: expected one shape (regular, box, vertices, circle, capsule, chain or loop) per body, found "
     "a second (the first at line 1)"},
    {"body a { box 1 1; static\n mass 2 }",
     "t.scene:2:2: expected one mass, density or static per body, found a second (the first at "
     "line 1)"},
    {"body a { mass 1 }", "t.scene:1:17: expected a shape (regular, box, vertices, circle, "
                          "capsule, chain or loop) in the body, found '}' without one"},
    {"body a {\n box 1 1\n",
     "t.scene:3:1: expected '}' to close the block opened at line 1, found the end of the file"},
    {"body a { colour 1 1 1 }",
     "t.scene:1:10: expected a body property (regular, box, vertices, circle, capsule, chain, loop, mass, "
     "density, static, elasticity, friction, color, position, angle, velocity, spin, tag, group, filter, centred, "
     "asleep, sleep_timer, repeat) or '}', found \"colour\""},
    {"body a { box 1 1 }\nbody a { box 1 1 }",
     "t.scene:2:6: expected a new name, found \"a\", already the name of a body (line 1)"},
    {"body a { box 1 1 }\nbody b { box 1 1; group a }",
     "t.scene:2:25: expected a group name, found \"a\", already the name of a body (line 1)"},
    {"body all { box 1 1 }",
     "t.scene:1:6: expected the body's name other than all (all stands for every body), found "
     "\"all\""},
    {"body 1x { box 1 1 }", "t.scene:1:6: expected the body's name (a letter or '_', then letters, "
                            "digits, '_', '.' or '-', "
                            "at most 63 characters), found \"1x\""},
    {"body a { box 1 1; filter 1 0x1ffffffff 0 }", "t.scene:1:28: expected the filter's mask bits, "
                                                   "a whole number from 0 to 4294967295 (or 0x0 to "
                                                   "0xffffffff), found \"0x1ffffffff\""},
    {"body a { box 1 1; repeat 200 200 1 1 }",
     "t.scene:1:1: expected at most 20000 bodies in a file, found 40000 with this block"},
    {"body a { box 1 1; repeat 3 1 1e9 0 }",
     "t.scene:1:19: expected copies within 1e+09 m of the origin, found the last at (2e+09, 0)"},
    {"template { box 1 1 }",
     "t.scene:1:10: expected the template's name (a letter or '_', then letters, digits, '_', '.' "
     "or '-', at most 63 characters), found '{'"},
    {"template t { box 1 1; repeat 2 1 1 0 }",
     "t.scene:1:23: expected no repeat in a template (a game spawns its copies), found one"},
    {"template t { box 1 1 }\ntemplate t { box 1 1 }",
     "t.scene:2:10: expected a new template name, found \"t\", already a template's (line 1)"},
    {"body a { box 1 1 }\nspring 1 a b",
     "t.scene:2:12: expected the name of a body or group, found \"b\", which names nothing in the "
     "file"},
    {"body g { box 1 1; repeat 2 1 2 0 }\nbody a { box 1 1 }\nspring 1 a g",
     "t.scene:3:12: expected a single body for the spring, found \"g\", a group (a repeated body, "
     "a "
     "template or a group)"},
    {"body a { box 1 1 }\nspring 1 a a",
     "t.scene:2:12: expected two different bodies for the spring, found \"a\" twice"},
    {"body a { box 1 1 }\nbody b { box 1 1 }\nspring 1 a b length -1",
     "t.scene:3:21: expected the spring's rest length (m), a number >= 0 and <= 2e+09, found "
     "\"-1\""},
    {"body a { box 1 1 }\nbody b { box 1 1 }\nspring 1 a b length",
     "t.scene:3:20: expected the spring's rest length (m), a number, found the end of the file"},
    {"body a { box 1 1 }\nbody b { box 1 1 }\nspring 1 a b 2",
     "t.scene:3:14: expected the end of the statement (a new line or ';'), found \"2\""},
    {"body a { box 1 1 }\nnewton 1\n",
     "t.scene:2:9: expected all or the bodies and groups that attract each other (a letter or '_', "
     "then letters, digits, '_', '.' or '-', at most 63 characters), found the end of the line"},
    {"body a { box 1 1 }\nbody b { box 1 1 }\ncollide a b elastic",
     "t.scene:3:13: expected the kind of collision (physics ELASTICITY, or destructive), found "
     "\"elastic\""},
    /* A drag per body and statement: 10000 bodies under 101 drags. (A newton
     * or collide over them all is one force creator.) */
    {"body a { box 1 1; repeat 100 100 2 2 }\n" DRAGS_100 "drag 1 all",
     "t.scene:102:1: expected at most 1000000 force creators from the forces and rules of a "
     "file, found 1010000 with this drag"},
    {"gravity 0 0\n\x01", "t.scene:2:1: expected text, found the control byte 0x01"},
    {"body a { box 1 1; tag \"x\" }", "t.scene:1:23: expected a tag (a letter or '_', then "
                                      "letters, digits, '_', '.' or '-', at most "
                                      "63 characters), found \"\\\"x\\\"\""},
    /* The state a continuation needs. */
    {"body a { box 1 1; centred }",
     "t.scene:1:10: expected centred with a vertices shape, found it with a box"},
    {"body a { vertices 0 0 1 0 0 1; centred }",
     "t.scene:1:10: expected vertices around their centroid (centred), found it at (0.333333, "
     "0.333333), more than a thousandth of the radius from the origin"},
    {"sleeping maybe", "t.scene:1:10: expected on or off (sleeping), found \"maybe\""},
    {"contacts on\nsleep_phase 8",
     "t.scene:2:13: expected the sleep phase, a whole number from 0 to 7, found \"8\""},
    {"body a { box 1 1; asleep 0 }",
     "t.scene:1:19: expected contacts on for the world's state (asleep, contact, sleep_phase, "
     "solver_steps, step_lengths), found contacts off"},
    {"contacts on\nsleeping off\nbody a { box 1 1; asleep 0 }",
     "t.scene:3:19: expected sleeping on for a body asleep, found sleeping off"},
    {"contacts on\nbody a { box 1 1; static; asleep 0 }",
     "t.scene:2:27: expected asleep on a body that can move, found it on a static body"},
    {"contacts on\nbody a { box 1 1; spin 1; asleep 0 }",
     "t.scene:2:27: expected a sleeping body at rest, found a velocity or spin on it"},
    {"template t { box 1 1; sleep_timer 1 1 0 0 0 }",
     "t.scene:1:23: expected no sleep state in a template (its copies start awake), found "
     "sleep_timer"},
    {"body a { box 1 1; sleep_timer -1 0 0 0 0 }",
     "t.scene:1:31: expected the time the body has been slow (s), a number >= 0 and <= 1e+300, "
     "found \"-1\""},
    {"contacts on\nbody a { box 1 1 }\ncontact 0 1 { normal 0 1; face a 0 1 0 0; pose 0 1 0 }",
     "t.scene:3:1: expected bodies numbered from 0 to 0 (the file makes 1), found 1"},
    {"contacts on\nbody a { box 1 1; repeat 2 1 2 0 }\ncontact 1 1 { normal 0 1; face a 0 1 0 0 }",
     "t.scene:3:1: expected two different bodies, found 1 twice"},
    {"contacts on\nbody a { box 1 1; repeat 2 1 2 0 }\n"
     "contact 0 1 { normal 0 0.5; face a 0 1 0 0 }",
     "t.scene:3:1: expected unit vectors for the normal and the face's normal, found lengths 0.5 "
     "and 1"},
    {"contacts on\nbody a { box 1 1; repeat 2 1 2 0 }\ncontact 0 1 { normal 0 1; face a 0 1 0 0 }\n"
     "contact 0 1 { normal 0 1; face a 0 1 0 0 }",
     "t.scene:4:1: expected one contact per pair, found a second for 0 and 1 (the first at line "
     "3)"},
    {"contacts on\nbody a { box 1 1; repeat 2 1 2 0 }\ncontact 0 1 { norm 0 1 }",
     "t.scene:3:15: expected a contact line (normal, point, face, incident, pose, previous, "
     "segment) or '}', found \"norm\""},
    {"contact 0 1 { incident 1 0 0; incident 2 0 0; incident 3 0 0 }",
     "t.scene:1:47: expected at most two incident lines in a contact, found a third"},
    {"contact 0 1 { previous 1 0 0; previous 2 0 0; previous 3 0 0 }",
     "t.scene:1:47: expected at most two previous lines in a contact, found a third"},
    {"contact 0 1 { face a 0 1 0 0 lead edge }",
     "t.scene:1:35: expected the reference face's lead (m), a number, found \"edge\""},
    {"contact 0 1 { previous 1 0 nan }",
     "t.scene:1:28: expected the tangent impulse of the step before (N s), a number, found "
     "\"nan\""},
    {"step_lengths 0.01 0.02",
     "t.scene:1:1: expected contacts on for the world's state (asleep, contact, sleep_phase, "
     "solver_steps, step_lengths), found contacts off"},
    {"solver_steps 3",
     "t.scene:1:1: expected contacts on for the world's state (asleep, contact, sleep_phase, "
     "solver_steps, step_lengths), found contacts off"},
    {"contacts on\nsolver_steps -1",
     "t.scene:2:14: expected the solver's steps, a whole number from 0 to 18446744073709551615, "
     "found \"-1\""},
    {"contacts on\nstep_lengths 0 0.02",
     "t.scene:2:1: expected a last step longer than 0 when the step before it has a length, "
     "found 0 and 0.02"},
    {"contacts on\nstep_lengths -0.01 0",
     "t.scene:2:14: expected the last step's length (s), a number >= 0 and <= 1e+300, found "
     "\"-0.01\""},
    {"contacts on\nstep_lengths 0.01",
     "t.scene:2:18: expected the length of the step before it (s), a number, found the end of the "
     "file"},
    {"contacts on\nstep_lengths 0.01 0\nstep_lengths 0.01 0",
     "t.scene:3:1: expected one step_lengths statement per file, found a second (the first at "
     "line 2)"},
    {"workers 0", "t.scene:1:9: expected the workers, a whole number from 1 to 64, found \"0\""},
    {"stepping sometimes",
     "t.scene:1:10: expected fixed or frame (the stepping), found \"sometimes\""},
    {"category", "t.scene:1:9: expected the category's name, found the end of the file"},
    {"note ; body a { box 1 1 }",
     "t.scene:1:6: expected the note's text, found ';'"},
    {"sleep_tolerance 0.01 0.5 1",
     "t.scene:1:26: expected the end of the statement (a new line or ';'), found \"1\""},
    {"category Stacking\ncategory Stacking",
     "t.scene:2:1: expected one category statement per file, found a second (the first at line "
     "1)"},
    {"category A very long category name that goes on and on",
     "t.scene:1:49: expected the category's name of at most 40 characters, found more"},
    {"contact 0 1 { face c 0 1 0 0 }",
     "t.scene:1:20: expected a or b (the body holding the reference face), found \"c\""},
    {"contact 0 1 { normal 0 1 }\ncontact 0",
     "t.scene:2:10: expected the number of the contact's second body, a whole number from 0 to "
     "19999, found the end of the file"},
};

static void malformed_files_are_refused_with_where_and_what(void) {
    for (size_t i = 0; i < sizeof BAD_FILES / sizeof BAD_FILES[0]; i++) {
        scene_file_error_t error;
        scene_file_t *file =
            scene_file_parse(BAD_FILES[i].text, strlen(BAD_FILES[i].text), "t.scene", &error);
        CHECK(file == NULL);
        scene_file_free(file);
        if (strcmp(error.message, BAD_FILES[i].message) != 0) {
            test_fail(__FILE__, __LINE__, "case %zu:\n      got      %s\n      expected %s", i,
                      error.message, BAD_FILES[i].message);
        }
        CHECK(error.line > 0 && error.column > 0);
    }
    CHECK(test_no_leaks());
}

static void a_nul_byte_is_refused_where_it_is(void) {
    const char text[] = "gravity 0 0\nbody a { box 1 1 }\0 trailing";
    scene_file_error_t error;
    CHECK(scene_file_parse(text, sizeof text - 1, "nul.scene", &error) == NULL);
    CHECK(strcmp(error.message, "nul.scene:2:19: expected the end of the statement (a new line or "
                                "';'), found the control byte 0x00") == 0);
    /* The length bounds the text: what follows it is never read. */
    scene_file_t *file = scene_file_parse(text, 11, NULL, &error);
    CHECK(file != NULL);
    scene_file_free(file);
    CHECK(scene_file_parse("gravity", 7, NULL, &error) == NULL);
    CHECK(strncmp(error.message, "<memory>:1:8: ", 14) == 0);
}

static void a_refused_file_leaves_the_open_scene_alone(void) {
    /* The sandbox keeps its scene until a new one has loaded: loading builds
     * a fresh scene and touches nothing else. */
    scene_file_t *open = parse("gravity 0 -10\nbody floor { box 10 1; static }\n"
                               "body a { box 1 1; position 0 3 }\n");
    scene_tick(scene_file_get_scene(open), 0.01);
    vector_t before = body_get_centroid(body_at(open, 1));
    for (size_t i = 0; i < sizeof BAD_FILES / sizeof BAD_FILES[0]; i++) {
        CHECK(scene_file_parse(BAD_FILES[i].text, strlen(BAD_FILES[i].text), NULL, NULL) == NULL);
    }
    CHECK(bodies(open) == 2);
    CHECK_VEC(body_get_centroid(body_at(open, 1)), before.x, before.y, 0);
    scene_tick(scene_file_get_scene(open), 0.01);
    CHECK(body_get_centroid(body_at(open, 1)).y < before.y);
    scene_file_free(open);
    CHECK(test_no_leaks());
}

static void every_engine_refusal_is_caught_first(void) {
    /* Values the engine would abort on (docs/api.md) never reach it: each of
     * these is refused with a message and the program goes on. */
    const char *const texts[] = {
        "body a { vertices 0 0 1 0 }",           /* < 3 vertices */
        "body a { vertices 0 0 2 0 1 1 1 0.5 }", /* reflex */
        "body a { regular 3 1e300 }",            /* out of range */
        "body a { box 1 1; mass 1e-320 }",       /* subnormal mass */
        "body a { box 1 1; mass 1e41 }",         /* past the mass limit */
        "body a { box 1e-100 1e-100 }",          /* a moment that underflows */
        "body a { box 1 1; friction -1 }",
        "body a { box 1 1; velocity 1e300 0 }",
        "body a { box 1 1 }\nbody b { box 1 1 }\ncollide a a physics 1\nspring -1 a b",
        "iterations 1001 1",
        "integrator 7",
    };
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        scene_file_error_t error;
        CHECK(scene_file_parse(texts[i], strlen(texts[i]), "t", &error) == NULL);
        CHECK(strncmp(error.message, "t:", 2) == 0);
    }
    /* collide a a alone is allowed and makes nothing: a body never collides
     * with itself. */
    scene_file_t *file = parse("body a { box 1 1 }\ncollide a a physics 1\n");
    CHECK(scene_file_force_count(file) == 0);
    scene_file_free(file);
}

/* ---- The documentation ---------------------------------------------------- */

static void documented_examples_load(void) {
    /* Every ```scene block of docs/scenes.md is a file that loads, so the
     * examples cannot drift from the parser. */
    FILE *stream = fopen("docs/scenes.md", "rb");
    CHECK(stream != NULL);
    if (stream == NULL) return;
    char *text = malloc(1 << 20);
    size_t size = fread(text, 1, (1 << 20) - 1, stream);
    fclose(stream);
    text[size] = '\0';
    size_t examples = 0;
    for (char *at = strstr(text, "```scene\n"); at != NULL; at = strstr(at, "```scene\n")) {
        at += strlen("```scene\n");
        char *end = strstr(at, "```");
        if (end == NULL) break;
        scene_file_error_t error;
        scene_file_t *file = scene_file_parse(at, (size_t)(end - at), "docs/scenes.md", &error);
        if (file == NULL)
            test_fail(__FILE__, __LINE__, "example %zu: %s", examples + 1, error.message);
        scene_file_free(file);
        examples++;
        at = end + 3;
    }
    CHECK(examples >= 13); /* one per feature, at the time of writing */
    free(text);
}

/* ---- The fuzz corpus ------------------------------------------------------ */

static size_t replay_directory(const char *path, size_t *failures) {
    DIR *directory = opendir(path);
    if (directory == NULL) {
        test_fail(__FILE__, __LINE__, "cannot open %s (run from the repository root)", path);
        return 0;
    }
    size_t replayed = 0;
    struct dirent *entry;
    while ((entry = readdir(directory)) != NULL) {
        if (entry->d_name[0] == '.') continue;
        char name[1024];
        snprintf(name, sizeof name, "%s/%s", path, entry->d_name);
        FILE *stream = fopen(name, "rb");
        if (stream == NULL) continue;
        uint8_t *data = malloc(1 << 20);
        size_t size = fread(data, 1, 1 << 20, stream);
        fclose(stream);
        char why[512] = "";
        if (!scene_file_round_trip(data, size, "fuzz", why, sizeof why)) {
            test_fail(__FILE__, __LINE__, "%s: %s", name, why);
            (*failures)++;
        }
        free(data);
        replayed++;
    }
    closedir(directory);
    return replayed;
}

static void fuzz_corpus_replays_cleanly(void) {
    /* Every input the fuzzer kept (tests/fuzz/corpus) and every preset goes
     * through the round trip under the sanitizers: refused with a message, or
     * loaded, written, reloaded the same and written the same. */
    size_t failures = 0;
    size_t replayed = replay_directory("tests/fuzz/corpus", &failures) +
                      replay_directory("assets/scenes", &failures);
    CHECK(replayed > 10);
    CHECK(failures == 0);
    CHECK(test_no_leaks());
}

TEST_SUITE(scene_file, TEST_CASE(settings_reach_the_scene),
           TEST_CASE(solver_settings_are_read_written_and_kept),
           TEST_CASE(every_integrator_name_is_read_and_written),
           TEST_CASE(shapes_are_regular_boxes_or_vertices),
           TEST_CASE(circles_and_capsules_are_round_bodies), TEST_CASE(mass_density_or_static),
           TEST_CASE(pose_motion_and_material_reach_the_body), TEST_CASE(filters_keep_bodies_apart),
           TEST_CASE(repeat_makes_a_group_of_copies), TEST_CASE(forces_and_rules_make_their_pairs),
           TEST_CASE(springs_may_have_a_rest_length),
           TEST_CASE(layout_is_free), TEST_CASE(names_and_groups_may_be_used_before_their_blocks),
           TEST_CASE(spawn_applies_the_rules_of_its_groups),
           TEST_CASE(many_spawns_and_destructions_leave_nothing_behind),
           TEST_CASE(find_body_forgets_freed_bodies),
           TEST_CASE(body_names_are_found_from_their_bodies),
           TEST_CASE(category_and_note_are_kept),
           TEST_CASE(settings_changed_live_are_written),
           TEST_CASE(written_scenes_load_back_the_same),
           TEST_CASE(round_bodies_saved_mid_run_continue_bit_for_bit),
           TEST_CASE(chains_saved_mid_run_continue_bit_for_bit),
           TEST_CASE(a_running_scene_is_written_as_it_is_now),
           TEST_CASE(step_lengths_and_previous_points_reach_the_world),
           TEST_CASE(save_and_load_through_a_path),
           TEST_CASE(malformed_files_are_refused_with_where_and_what),
           TEST_CASE(a_nul_byte_is_refused_where_it_is),
           TEST_CASE(a_refused_file_leaves_the_open_scene_alone),
           TEST_CASE(every_engine_refusal_is_caught_first), TEST_CASE(documented_examples_load),
           TEST_CASE(fuzz_corpus_replays_cleanly));
