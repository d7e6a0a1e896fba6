/* app/games: Breakout, Space Invaders and Pegs played through the engine
 * with scripted input, as the sandbox will play them with the keyboard. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "engine.h"
#include "game.h"
#include "scene_file.h"
#include "test.h"

typedef game_input_t (*controller_t)(scene_file_t *file);

static scene_file_t *load(const char *path) {
    scene_file_error_t error;
    scene_file_t *file = scene_file_load(path, &error);
    if (file == NULL) test_fail(__FILE__, __LINE__, "%s", error.message);
    return file;
}

/* Plays up to max_seconds of game time: scene_tick, then game_update with the
 * controller's input, as game.h says. Returns the final status. */
static game_status_t play(scene_file_t *file, controller_t controller, double max_seconds) {
    char error[256];
    game_t *game = game_start(file, error, sizeof error);
    CHECK(game != NULL);
    if (game == NULL) {
        printf("    %s\n", error);
        return (game_status_t){0};
    }
    scene_t *scene = scene_file_get_scene(file);
    double dt = scene_file_get_timestep(file);
    for (double t = 0; t < max_seconds; t += dt) {
        scene_tick(scene, dt);
        game_update(game, controller(file), dt);
        if (game_status(game).outcome != GAME_PLAYING) break;
    }
    game_status_t status = game_status(game);
    game_free(game);
    return status;
}

static game_input_t idle(scene_file_t *file) {
    (void)file;
    return (game_input_t){0.0, false};
}

static double clamp_unit(double x) {
    return x < -1.0 ? -1.0 : x > 1.0 ? 1.0 : x;
}

/* ---- Breakout ------------------------------------------------------------- */

/* Keeps the paddle under the ball, off centre by as much as sends the ball
 * toward the first brick left (the rules turn the ball by where it meets the
 * paddle: up to 60 degrees at its end, 1.2 m from the centre). */
static game_input_t breakout_player(scene_file_t *file) {
    scene_t *scene = scene_file_get_scene(file);
    vector_t ball = body_get_centroid(scene_file_find_body(file, "ball"));
    vector_t paddle = body_get_centroid(scene_file_find_body(file, "paddle"));
    vector_t target = {0, 12};
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (!body_is_removed(body) && game_body_has_tag(body, "brick")) {
            target = body_get_centroid(body);
            break;
        }
    }
    double angle = fmax(-1.0, fmin(1.0, atan2(target.x - paddle.x, target.y - paddle.y)));
    double offset = angle / (60.0 * M_PI / 180.0) * 1.2;
    return (game_input_t){clamp_unit(5.0 * (ball.x - offset - paddle.x)), false};
}

static void breakout_is_won_by_a_paddle_under_the_ball(void) {
    scene_file_t *file = load("assets/scenes/breakout.scene");
    game_status_t status = play(file, breakout_player, 600);
    CHECK(status.outcome == GAME_WON);
    CHECK(status.remaining == 0);
    CHECK(status.score == 50);
    CHECK(status.lives >= 1);
    /* The bricks are gone from the scene, not just counted (the last one is
     * freed at the next tick; dt = 0 applies removals only). */
    scene_tick(scene_file_get_scene(file), 0);
    scene_file_t *fresh = load("assets/scenes/breakout.scene");
    CHECK(scene_bodies(scene_file_get_scene(file)) ==
          scene_bodies(scene_file_get_scene(fresh)) - 50);
    scene_file_free(fresh);
    scene_file_free(file);
    CHECK(test_no_leaks());
}

static void breakout_is_lost_by_a_still_paddle(void) {
    scene_file_t *file = load("assets/scenes/breakout.scene");
    game_status_t status = play(file, idle, 600);
    CHECK(status.outcome == GAME_LOST);
    CHECK(status.lives == 0);
    CHECK(status.remaining > 0);
    scene_file_free(file);
}

/* ---- Space Invaders ------------------------------------------------------- */

/* Steps away from a bomb falling close above; otherwise goes under the
 * invader whose column a shot would meet, leading it by its march over the
 * shot's flight (14 m/s), and fires when under it. */
static game_input_t invaders_player(scene_file_t *file) {
    scene_t *scene = scene_file_get_scene(file);
    body_t *gun = scene_file_find_body(file, "player");
    if (gun == NULL) return (game_input_t){0};
    vector_t at = body_get_centroid(gun);
    double best = INFINITY, target = at.x;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body)) continue;
        vector_t c = body_get_centroid(body);
        if (game_body_has_tag(body, "bomb") && c.y < at.y + 5 && fabs(c.x - at.x) < 1.0) {
            return (game_input_t){c.x > at.x ? -1.0 : 1.0, true};
        }
        if (game_body_has_tag(body, "invader")) {
            double lead = c.x + body_get_velocity(body).x * (c.y - at.y) / 14.0;
            if (fabs(lead - at.x) < best) {
                best = fabs(lead - at.x);
                target = lead;
            }
        }
    }
    return (game_input_t){clamp_unit(4.0 * (target - at.x)), fabs(target - at.x) < 0.3};
}

static bool has_tagged(scene_t *scene, const char *tag) {
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        if (game_body_has_tag(scene_get_body(scene, i), tag)) return true;
    }
    return false;
}

static void space_invaders_is_won_by_aimed_fire(void) {
    scene_file_t *file = load("assets/scenes/space_invaders.scene");
    game_status_t status = play(file, invaders_player, 300);
    CHECK(status.outcome == GAME_WON);
    CHECK(status.score == 32);
    CHECK(!has_tagged(scene_file_get_scene(file), "invader"));
    CHECK(scene_file_find_body(file, "player") != NULL);
    scene_file_free(file);
    CHECK(test_no_leaks());
}

static void space_invaders_is_lost_by_a_still_gun(void) {
    scene_file_t *file = load("assets/scenes/space_invaders.scene");
    game_status_t status = play(file, idle, 300);
    CHECK(status.outcome == GAME_LOST);
    CHECK(status.lives == 0);
    CHECK(status.score == 0);
    scene_file_free(file);
}

static void space_invaders_march_down_and_shoot(void) {
    /* Five seconds in: the formation has moved sideways, bombs have fallen
     * (spawned from the bomb template, tagged bomb) and the gun's shots fly. */
    scene_file_t *file = load("assets/scenes/space_invaders.scene");
    scene_t *scene = scene_file_get_scene(file);
    body_t *first = NULL;
    for (size_t i = 0; i < scene_bodies(scene) && first == NULL; i++) {
        if (game_body_has_tag(scene_get_body(scene, i), "invader"))
            first = scene_get_body(scene, i);
    }
    vector_t start = body_get_centroid(first);
    char error[256];
    game_t *game = game_start(file, error, sizeof error);
    bool bombs = false, shots = false;
    for (int i = 0; i < 600; i++) {
        scene_tick(scene, scene_file_get_timestep(file));
        game_update(game, (game_input_t){0.0, true}, scene_file_get_timestep(file));
        bombs = bombs || has_tagged(scene, "bomb");
        shots = shots || has_tagged(scene, "shot");
    }
    CHECK(bombs && shots);
    vector_t now = body_get_centroid(first);
    CHECK(now.x != start.x);
    game_free(game);
    /* And given time, down: the idle game above is lost to them. */
    scene_file_free(file);
}

/* ---- Pegs and the interface ----------------------------------------------- */

static void pegs_drops_the_balls_again(void) {
    scene_file_t *file = load("assets/scenes/pegs.scene");
    game_status_t status = play(file, idle, 20);
    CHECK(status.outcome == GAME_PLAYING);
    CHECK(status.score >= 24); /* every ball went through at least once */
    scene_t *scene = scene_file_get_scene(file);
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (game_body_has_tag(body, "ball")) CHECK(body_get_centroid(body).y > -0.5 - 1.0);
    }
    scene_file_free(file);
}

static void games_refuse_scenes_they_cannot_play(void) {
    const struct {
        const char *text;
        const char *message;
    } cases[] = {
        {"body a { box 1 1 }", ""},
        {"game chess", "unknown game \"chess\""},
        {"game breakout\nbody ball { regular 8 0.2; velocity 1 1 }",
         "breakout: the scene has no body named paddle"},
        {"game breakout\nbody paddle { box 2 0.3; static }\nbody ball { regular 8 0.2 }",
         "breakout: the ball must move"},
        {"game space_invaders\nbody player { box 1 1; static }\nbody { box 1 1; tag invader }\n"
         "template shot { box 0.1 0.3 }\ntemplate bomb { box 0.1 0.3 }",
         "space_invaders: the scene has no view (the field)"},
        {"game space_invaders\nview 0 0 10 10\nbody player { box 1 1; static }\n"
         "body { box 1 1; tag invader }\ntemplate shot { box 0.1 0.3 }",
         "space_invaders: the scene has no template named bomb"},
        {"game pegs\nview 0 0 10 10", "pegs: the scene has no body tagged ball"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        scene_file_t *file = scene_file_parse(cases[i].text, strlen(cases[i].text), "t", NULL);
        CHECK(file != NULL);
        if (file == NULL) continue;
        char error[256] = "unchanged";
        CHECK(game_start(file, error, sizeof error) == NULL);
        if (strcmp(error, cases[i].message) != 0)
            test_fail(__FILE__, __LINE__, "case %zu: got \"%s\", expected \"%s\"", i, error,
                      cases[i].message);
        scene_file_free(file);
    }
    CHECK(game_find("breakout") == &BREAKOUT_RULES);
    CHECK(game_find("space_invaders") == &SPACE_INVADERS_RULES);
    CHECK(game_find("pegs") == &PEGS_RULES);
    CHECK(game_find("chess") == NULL);
    game_update(NULL, (game_input_t){0}, 0.01); /* allowed */
    game_free(NULL);
}

TEST_SUITE(games, TEST_CASE(breakout_is_won_by_a_paddle_under_the_ball),
           TEST_CASE(breakout_is_lost_by_a_still_paddle),
           TEST_CASE(space_invaders_is_won_by_aimed_fire),
           TEST_CASE(space_invaders_is_lost_by_a_still_gun),
           TEST_CASE(space_invaders_march_down_and_shoot), TEST_CASE(pegs_drops_the_balls_again),
           TEST_CASE(games_refuse_scenes_they_cannot_play));
