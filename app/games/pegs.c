/*
 * Pegs, after the seed course's demo: a ball is dropped from the top of the
 * board every second and freezes where it lands, so the balls pile up at the
 * bottom.
 *
 * Every DROP_INTERVAL seconds a ball is spawned from the template "ball",
 * DROP_BELOW_TOP below the top of the view (the board), at its middle plus a
 * random offset of up to DROP_SPREAD either way (the same sequence every
 * game), moving down at DROP_SPEED. A ball whose collision with the floor
 * (a body tagged "floor") or with a frozen ball starts in a step (the step's
 * contact record) freezes: it is removed and a copy of the template "frozen"
 * (static) takes its place, at rest. When a ball freezes within two ball
 * sizes of the drop point the board is full: every frozen ball is removed
 * and the board fills again. There is nothing to win or lose; the score
 * counts the balls that landed, `remaining` the balls on the board. The
 * input is not used.
 *
 * The scene needs a view and the templates "ball" and "frozen"; its rules
 * make the collisions (collide ball floor physics 0, collide ball frozen
 * physics 0, which stop the ball and enter the record).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "game.h"

static const double DROP_INTERVAL = 1.0;  /* s between balls */
static const double DROP_BELOW_TOP = 6.5; /* m from the view's top to the drop point */
static const double DROP_SPREAD = 0.5;    /* m either side of the middle */
static const double DROP_SPEED = 8.0;     /* m/s, down */

typedef struct {
    scene_file_t *file;
    scene_t *scene;
    vector_t drop;     /* where balls are dropped */
    double drop_timer; /* s until the next ball */
    uint64_t random;
    game_status_t status;
} pegs_t;

static void *pegs_start(scene_file_t *file, char *error, size_t error_size) {
    scene_file_view_t view = scene_file_get_view(file);
    const char *problem = !view.has_view ? "the scene has no view (the board)"
                          : !scene_file_has_template(file, "ball")
                              ? "the scene has no template named ball"
                          : !scene_file_has_template(file, "frozen")
                              ? "the scene has no template named frozen"
                              : NULL;
    if (problem != NULL) {
        snprintf(error, error_size, "pegs: %s", problem);
        return NULL;
    }
    pegs_t *game = calloc(1, sizeof *game);
    if (game == NULL) abort();
    *game = (pegs_t){
        .file = file,
        .scene = scene_file_get_scene(file),
        .drop = {view.center.x, view.center.y + 0.5 * view.height - DROP_BELOW_TOP},
        .drop_timer = 0.0,
        .random = 0x2545F4914F6CDD1DULL,
        .status = {GAME_PLAYING, 1, 0, 0},
    };
    return game;
}

/* xorshift64: the same drops every game. */
static double random_unit(pegs_t *game) {
    game->random ^= game->random << 13;
    game->random ^= game->random >> 7;
    game->random ^= game->random << 17;
    return (double)(game->random >> 11) / 9007199254740992.0;
}

static bool alive(body_t *body, const char *tag) {
    return !body_is_removed(body) && game_body_has_tag(body, tag);
}

/* The ball of a contact that froze it (touching, the other body the floor or
 * a frozen ball), or NULL. */
static body_t *landed_ball(const contact_t *contact) {
    if (!contact->touching) return NULL;
    body_t *pair[2] = {contact->body1, contact->body2};
    for (int i = 0; i < 2; i++) {
        body_t *other = pair[1 - i];
        if (alive(pair[i], "ball") &&
            (game_body_has_tag(other, "floor") || game_body_has_tag(other, "frozen")))
            return pair[i];
    }
    return NULL;
}

/* Replaces the ball with a frozen one where it is; true when that fills the
 * board (it froze within two ball sizes of the drop point). */
static bool freeze(pegs_t *game, body_t *ball) {
    vector_t at = body_get_centroid(ball);
    aabb_t bounds = body_get_bounds(ball);
    body_remove(ball);
    scene_file_spawn(game->file, "frozen", at, VEC_ZERO);
    game->status.score++;
    return vec_get_length(vec_subtract(at, game->drop)) < 2.0 * (bounds.max.y - bounds.min.y);
}

static void clear_frozen(pegs_t *game) {
    for (size_t i = 0; i < scene_bodies(game->scene); i++) {
        body_t *body = scene_get_body(game->scene, i);
        if (alive(body, "frozen")) body_remove(body);
    }
}

static int count_on_board(pegs_t *game) {
    int n = 0;
    for (size_t i = 0; i < scene_bodies(game->scene); i++) {
        body_t *body = scene_get_body(game->scene, i);
        n += alive(body, "ball") || alive(body, "frozen");
    }
    return n;
}

static void pegs_update(void *state, game_input_t input, double dt) {
    (void)input;
    pegs_t *game = state;
    bool full = false;
    for (size_t i = 0; i < scene_contact_count(game->scene); i++) {
        body_t *ball = landed_ball(scene_get_contact(game->scene, i));
        if (ball != NULL) full = freeze(game, ball) || full;
    }
    if (full) clear_frozen(game);
    if (dt > 0.0) {
        game->drop_timer -= dt;
        if (game->drop_timer <= 0.0) {
            double x = game->drop.x + DROP_SPREAD * (2.0 * random_unit(game) - 1.0);
            scene_file_spawn(game->file, "ball", (vector_t){x, game->drop.y},
                             (vector_t){0.0, -DROP_SPEED});
            game->drop_timer += DROP_INTERVAL;
        }
    }
    game->status.remaining = count_on_board(game);
}

static game_status_t pegs_status(const void *state) {
    return ((const pegs_t *)state)->status;
}

const game_rules_t PEGS_RULES = {"pegs", pegs_start, pegs_update, pegs_status, free, false, false};
