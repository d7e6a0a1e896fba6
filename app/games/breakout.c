/*
 * Breakout: a paddle, a ball, bricks. The scene file makes the bodies and the
 * seed's elastic collisions (collide ball ... physics 1); these rules add what
 * physics does not: a brick the ball hits is removed, the ball leaves the
 * paddle at an angle set by where it hit (so the player can aim), a ball that
 * falls past the paddle costs a life, and the game is won when no brick is
 * left and lost with the last life.
 *
 * The scene needs: a body named "ball" (finite mass, moving), a body named
 * "paddle", bricks tagged "brick", and walls tagged "wall" (they bound the
 * paddle's travel).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "game.h"

static const int LIVES = 3;
static const double PADDLE_SPEED = 12.0;                    /* m/s at move = 1 */
static const double MAX_BOUNCE_ANGLE = 60.0 * M_PI / 180.0; /* off vertical, at the paddle's end */
static const double LOST_BELOW = 1.0; /* m under the paddle's bottom: the ball is lost */

typedef struct {
    scene_file_t *file;
    scene_t *scene;
    body_t *ball;
    body_t *paddle;
    vector_t ball_start;
    vector_t ball_start_velocity;
    double speed; /* the ball's speed, kept through every bounce */
    double paddle_half_width;
    double paddle_min_x, paddle_max_x; /* where the paddle's centre may go */
    double lost_y;
    game_status_t status;
} breakout_t;

static int count_bricks(scene_t *scene) {
    int bricks = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (!body_is_removed(body) && game_body_has_tag(body, "brick")) bricks++;
    }
    return bricks;
}

/* The paddle slides between the walls beside it: the nearest wall faces left
 * and right of its centre among the walls that reach its height. */
static void paddle_limits(breakout_t *game) {
    aabb_t paddle = body_get_bounds(game->paddle);
    double centre = body_get_centroid(game->paddle).x;
    double left = -INFINITY, right = INFINITY;
    for (size_t i = 0; i < scene_bodies(game->scene); i++) {
        body_t *wall = scene_get_body(game->scene, i);
        if (!game_body_has_tag(wall, "wall")) continue;
        aabb_t b = body_get_bounds(wall);
        if (b.max.y < paddle.min.y || b.min.y > paddle.max.y) continue;
        if (b.max.x <= centre) left = fmax(left, b.max.x);
        if (b.min.x >= centre) right = fmin(right, b.min.x);
    }
    game->paddle_half_width = 0.5 * (paddle.max.x - paddle.min.x);
    game->paddle_min_x = left + game->paddle_half_width;
    game->paddle_max_x = right - game->paddle_half_width;
    game->lost_y = paddle.min.y - LOST_BELOW;
}

static void *breakout_start(scene_file_t *file, char *error, size_t error_size) {
    body_t *ball = scene_file_find_body(file, "ball");
    body_t *paddle = scene_file_find_body(file, "paddle");
    const char *problem = NULL;
    if (ball == NULL)
        problem = "the scene has no body named ball";
    else if (paddle == NULL)
        problem = "the scene has no body named paddle";
    else if (isinf(body_get_mass(ball)))
        problem = "the ball must have a finite mass";
    else if (vec_get_length(body_get_velocity(ball)) == 0.0)
        problem = "the ball must move";
    if (problem != NULL) {
        snprintf(error, error_size, "breakout: %s", problem);
        return NULL;
    }
    breakout_t *game = calloc(1, sizeof *game);
    if (game == NULL) abort();
    game->file = file;
    game->scene = scene_file_get_scene(file);
    game->ball = ball;
    game->paddle = paddle;
    game->ball_start = body_get_centroid(ball);
    game->ball_start_velocity = body_get_velocity(ball);
    game->speed = vec_get_length(game->ball_start_velocity);
    paddle_limits(game);
    game->status = (game_status_t){GAME_PLAYING, LIVES, 0, count_bricks(game->scene)};
    return game;
}

static bool is_pair(const contact_t *contact, body_t *a, body_t *b) {
    return (contact->body1 == a && contact->body2 == b) ||
           (contact->body1 == b && contact->body2 == a);
}

/* The ball leaves the paddle at up to MAX_BOUNCE_ANGLE off vertical, by how
 * far from the paddle's centre it hit, at its usual speed. */
static void steer_off_paddle(breakout_t *game) {
    double offset = (body_get_centroid(game->ball).x - body_get_centroid(game->paddle).x) /
                    game->paddle_half_width;
    offset = fmax(-1.0, fmin(1.0, offset));
    double angle = offset * MAX_BOUNCE_ANGLE;
    body_set_velocity(game->ball, (vector_t){game->speed * sin(angle), game->speed * cos(angle)});
}

/* What the last step's collisions mean: bricks hit are removed, a paddle hit
 * steers the ball. */
static void read_hits(breakout_t *game) {
    for (size_t i = 0; i < scene_contact_count(game->scene); i++) {
        const contact_t *contact = scene_get_contact(game->scene, i);
        if (contact->kind != CONTACT_SEED) continue;
        if (is_pair(contact, game->ball, game->paddle)) {
            steer_off_paddle(game);
            continue;
        }
        body_t *other = contact->body1 == game->ball   ? contact->body2
                        : contact->body2 == game->ball ? contact->body1
                                                       : NULL;
        if (other != NULL && game_body_has_tag(other, "brick") && !body_is_removed(other)) {
            body_remove(other);
            game->status.score++;
        }
    }
}

static void move_paddle(breakout_t *game, double move, double dt) {
    vector_t at = body_get_centroid(game->paddle);
    double target = at.x + move * PADDLE_SPEED * dt;
    target = fmax(game->paddle_min_x, fmin(game->paddle_max_x, target));
    /* A paddle of infinite mass moves at its velocity: this one ends the next
     * step at the target, stopping at the walls. */
    body_set_velocity(game->paddle, (vector_t){(target - at.x) / dt, 0.0});
}

static void stop(breakout_t *game, game_outcome_t outcome) {
    game->status.outcome = outcome;
    body_set_velocity(game->ball, VEC_ZERO);
    body_set_velocity(game->paddle, VEC_ZERO);
}

static void breakout_update(void *state, game_input_t input, double dt) {
    breakout_t *game = state;
    read_hits(game);
    game->status.remaining = count_bricks(game->scene);
    if (game->status.remaining == 0) {
        stop(game, GAME_WON);
        return;
    }
    if (body_get_centroid(game->ball).y < game->lost_y) {
        game->status.lives--;
        if (game->status.lives == 0) {
            stop(game, GAME_LOST);
            return;
        }
        body_set_centroid(game->ball, game->ball_start);
        body_set_velocity(game->ball, game->ball_start_velocity);
    }
    if (dt > 0.0) move_paddle(game, input.move, dt);
}

static game_status_t breakout_status(const void *state) {
    return ((const breakout_t *)state)->status;
}

const game_rules_t BREAKOUT_RULES = {"breakout", breakout_start, breakout_update, breakout_status,
                                     free, true, false};
