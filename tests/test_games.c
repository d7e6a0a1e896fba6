/* app/games: Breakout, Space Invaders and Pegs played through the engine
 * with scripted input, as the sandbox will play them with the keyboard. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "jostle/jostle.h"
#include "game.h"
#include "jostle/scene_file.h"
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

/* Bodies with the tag, not marked removed. */
static int count_tagged(scene_t *scene, const char *tag) {
    int n = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        n += !body_is_removed(body) && game_body_has_tag(body, tag);
    }
    return n;
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

/* The ball is a circle and keeps its speed (the rules serve it at 7.6 m/s
 * and aim it off the paddle at that speed; walls, ceiling and bricks are
 * elastic and immovable) through a minute of play, to 1e-9; off a side
 * wall it comes back mirrored, its vertical velocity unchanged (a face
 * meets a round ball along its normal). */
static void breakout_ball_keeps_its_speed_and_bounces_off_the_walls_mirrored(void) {
    scene_file_t *file = load("assets/scenes/breakout.scene");
    scene_t *scene = scene_file_get_scene(file);
    body_t *ball = scene_file_find_body(file, "ball");
    CHECK(body_get_shape_kind(ball) == BODY_SHAPE_CIRCLE);
    char error[256];
    game_t *game = game_start(file, error, sizeof error);
    CHECK(game != NULL);
    if (game == NULL) return;
    double dt = scene_file_get_timestep(file), speed = vec_get_length(body_get_velocity(ball));
    int side_bounces = 0, lives = game_status(game).lives;
    vector_t before = body_get_velocity(ball);
    for (long step = 0; step < lround(60.0 / dt); step++) {
        scene_tick(scene, dt);
        game_update(game, breakout_player(file), dt);
        if (game_status(game).outcome != GAME_PLAYING) break;
        vector_t v = body_get_velocity(ball);
        CHECK_RELATIVE(vec_get_length(v), speed, 1e-9);
        CHECK(body_get_angular_velocity(ball) == 0.0);
        bool served = game_status(game).lives != lives;
        lives = game_status(game).lives;
        if (!served && fabs(body_get_centroid(ball).x) > 6.75 && v.x * before.x < 0.0) {
            CHECK_NEAR(v.x, -before.x, 1e-12);
            CHECK_NEAR(v.y, before.y, 1e-12);
            side_bounces++;
        }
        before = v;
        if (test_failures > 0) break;
    }
    CHECK(side_bounces >= 3);
    game_free(game);
    scene_file_free(file);
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

static void space_invaders_gun_has_three_lives(void) {
    /* A still gun under the bombs: three lives, one lost per bomb that
     * reaches it; each hit clears the bombs in flight and the gun plays on
     * (still in the scene, still playing) until the third, which loses the
     * game with the gun in place. */
    scene_file_t *file = load("assets/scenes/space_invaders.scene");
    scene_t *scene = scene_file_get_scene(file);
    double dt = scene_file_get_timestep(file);
    char error[256];
    game_t *game = game_start(file, error, sizeof error);
    CHECK(game != NULL);
    if (game == NULL) return;
    CHECK(game_status(game).lives == 3);
    int lives = 3, hits = 0;
    for (double t = 0; t < 300 && game_status(game).outcome == GAME_PLAYING; t += dt) {
        scene_tick(scene, dt);
        game_update(game, (game_input_t){0}, dt);
        game_status_t status = game_status(game);
        if (status.lives == lives) continue;
        hits++;
        CHECK(status.lives == lives - 1);
        lives = status.lives;
        CHECK(count_tagged(scene, "bomb") == 0);
        body_t *gun = scene_file_find_body(file, "player");
        CHECK(gun != NULL && !body_is_removed(gun));
        CHECK(status.outcome == (lives > 0 ? GAME_PLAYING : GAME_LOST));
        CHECK(status.remaining == 32); /* the invaders were never shot */
    }
    CHECK(hits == 3);
    CHECK(game_status(game).outcome == GAME_LOST && game_status(game).lives == 0);
    game_free(game);
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

static void pegs_drops_a_ball_every_second_and_freezes_it_where_it_lands(void) {
    /* The first ball: at the drop point (76 m up, within 0.5 m of the
     * middle), moving down at 8 m/s. */
    scene_file_t *file = load("assets/scenes/pegs.scene");
    scene_t *scene = scene_file_get_scene(file);
    double dt = scene_file_get_timestep(file);
    char error[256];
    game_t *game = game_start(file, error, sizeof error);
    CHECK(game != NULL && !game_takes_input(game));
    scene_tick(scene, dt);
    game_update(game, (game_input_t){0}, dt);
    CHECK(count_tagged(scene, "ball") == 1);
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *ball = scene_get_body(scene, i);
        if (!game_body_has_tag(ball, "ball")) continue;
        CHECK(body_get_shape_kind(ball) == BODY_SHAPE_CIRCLE && body_get_round_radius(ball) == 1.0);
        CHECK(fabs(body_get_centroid(ball).x) <= 0.5);
        CHECK_NEAR(body_get_centroid(ball).y, 76.0, 1e-12);
        CHECK_VEC(body_get_velocity(ball), 0, -8, 0);
    }
    /* 30 s: a ball each second, 31 in all counting the first, each falling
     * or landed; every landed one frozen (static, at rest) on the floor
     * (top at y = 0) or on another frozen ball, touching it. */
    for (int i = 1; i < lround(30.0 / dt); i++) {
        scene_tick(scene, dt);
        game_update(game, (game_input_t){0}, dt);
    }
    scene_tick(scene, 0); /* frees the bodies the rules removed */
    game_status_t status = game_status(game);
    int falling = count_tagged(scene, "ball"), frozen = count_tagged(scene, "frozen");
    CHECK(status.outcome == GAME_PLAYING);
    CHECK(status.score == frozen && status.remaining == falling + frozen);
    CHECK(falling + frozen == 31);
    CHECK(frozen >= 15);
    const double radius = 1.0; /* the balls are circles of 1 m */
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *ball = scene_get_body(scene, i);
        if (!game_body_has_tag(ball, "frozen")) continue;
        CHECK(body_get_shape_kind(ball) == BODY_SHAPE_CIRCLE);
        CHECK(isinf(body_get_mass(ball)));
        CHECK_VEC(body_get_velocity(ball), 0, 0, 0);
        vector_t at = body_get_centroid(ball);
        double gap = at.y - radius; /* above the floor */
        for (size_t j = 0; j < scene_bodies(scene); j++) {
            body_t *other = scene_get_body(scene, j);
            if (other == ball || !game_body_has_tag(other, "frozen")) continue;
            vector_t d = vec_subtract(body_get_centroid(other), at);
            gap = fmin(gap, vec_get_length(d) - 2.0 * radius);
        }
        CHECK(gap < 0.2); /* landed: within one step's fall of what froze it */
    }
    game_free(game);
    scene_file_free(file);
}

static void pegs_clears_a_full_board(void) {
    /* A floor 3 m under the drop point (76 m up, as the view puts it): the
     * first ball freezes within two ball sizes of it, which fills the board,
     * so it is cleared at once; the next ball lands on the bare floor. */
    const char *text = "game pegs\nview 0 41 20 83\ngravity 0 -9.8\ncontacts on\n"
                       "body floor { box 20 1; static; position 0 72.5; tag floor }\n"
                       "template ball { circle 1; mass 2; tag ball }\n"
                       "template frozen { circle 1; static; tag frozen }\n";
    scene_file_t *file = scene_file_parse(text, strlen(text), "t", NULL);
    CHECK(file != NULL);
    if (file == NULL) return;
    scene_t *scene = scene_file_get_scene(file);
    char error[256];
    game_t *game = game_start(file, error, sizeof error);
    CHECK(game != NULL);
    int landed = 0;
    for (int i = 0; i < 240 && landed < 2; i++) {
        scene_tick(scene, 1.0 / 120);
        game_update(game, (game_input_t){0}, 1.0 / 120);
        if (game_status(game).score > landed) {
            landed = game_status(game).score;
            CHECK(count_tagged(scene, "frozen") == 0);
        }
    }
    CHECK(landed == 2);
    game_free(game);
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
        {"game pegs\nview 0 0 10 10", "pegs: the scene has no template named ball"},
        {"game pegs\nview 0 0 10 10\ntemplate ball { box 1 1 }",
         "pegs: the scene has no template named frozen"},
        {"game pegs\ntemplate ball { box 1 1 }\ntemplate frozen { box 1 1 }",
         "pegs: the scene has no view (the board)"},
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
           TEST_CASE(breakout_ball_keeps_its_speed_and_bounces_off_the_walls_mirrored),
           TEST_CASE(space_invaders_is_won_by_aimed_fire),
           TEST_CASE(space_invaders_is_lost_by_a_still_gun),
           TEST_CASE(space_invaders_gun_has_three_lives),
           TEST_CASE(space_invaders_march_down_and_shoot),
           TEST_CASE(pegs_drops_a_ball_every_second_and_freezes_it_where_it_lands),
           TEST_CASE(pegs_clears_a_full_board),
           TEST_CASE(games_refuse_scenes_they_cannot_play));
