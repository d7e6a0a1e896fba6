/*
 * Pegs: the board never empties. Balls (tagged "ball") that fall out of the
 * bottom of the view are dropped again from its top, at rest, at a place
 * along the top chosen in turn from a fixed sequence, as the seed's demo kept
 * dropping balls. There is nothing to win or lose; the score counts the balls
 * that went through. The input is not used.
 *
 * The scene needs a view (the board) and at least one body tagged "ball".
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "game.h"

static const double DROP_MARGIN = 1.5; /* m below the view's top, and in from its sides */

typedef struct {
    scene_t *scene;
    aabb_t field;
    uint64_t random;
    game_status_t status;
} pegs_t;

static void *pegs_start(scene_file_t *file, char *error, size_t error_size) {
    scene_t *scene = scene_file_get_scene(file);
    scene_file_view_t view = scene_file_get_view(file);
    int balls = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++)
        balls += game_body_has_tag(scene_get_body(scene, i), "ball");
    const char *problem = !view.has_view ? "the scene has no view (the board)"
                          : balls == 0   ? "the scene has no body tagged ball"
                                         : NULL;
    if (problem != NULL) {
        snprintf(error, error_size, "pegs: %s", problem);
        return NULL;
    }
    pegs_t *game = calloc(1, sizeof *game);
    if (game == NULL) abort();
    vector_t half = {0.5 * view.width, 0.5 * view.height};
    *game = (pegs_t){scene,
                     {vec_subtract(view.center, half), vec_add(view.center, half)},
                     0x2545F4914F6CDD1DULL,
                     {GAME_PLAYING, 1, 0, balls}};
    return game;
}

/* xorshift64: the same drops every run. */
static double random_unit(pegs_t *game) {
    game->random ^= game->random << 13;
    game->random ^= game->random >> 7;
    game->random ^= game->random << 17;
    return (double)(game->random >> 11) / 9007199254740992.0;
}

static void pegs_update(void *state, game_input_t input, double dt) {
    (void)input;
    (void)dt;
    pegs_t *game = state;
    double left = game->field.min.x + DROP_MARGIN, right = game->field.max.x - DROP_MARGIN;
    for (size_t i = 0; i < scene_bodies(game->scene); i++) {
        body_t *ball = scene_get_body(game->scene, i);
        if (!game_body_has_tag(ball, "ball") || body_get_centroid(ball).y > game->field.min.y)
            continue;
        double x = left + (right - left) * random_unit(game);
        body_set_centroid(ball, (vector_t){x, game->field.max.y - DROP_MARGIN});
        body_set_velocity(ball, VEC_ZERO);
        game->status.score++;
    }
}

static game_status_t pegs_status(const void *state) {
    return ((const pegs_t *)state)->status;
}

const game_rules_t PEGS_RULES = {"pegs", pegs_start, pegs_update, pegs_status, free, false};
