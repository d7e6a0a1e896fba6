/*
 * Space Invaders: a gun at the bottom, a formation of invaders that marches
 * from side to side, steps down at each edge and drops bombs. The scene file
 * makes the bodies, the templates of the shots and bombs, and the destructive
 * collisions between them (collide shot invader destructive, ...); these
 * rules move the formation and the gun, spawn shots and bombs from the
 * templates, clear what leaves the field, and decide the game.
 *
 * Bodies are told apart by their tags, the info field of a scene file's
 * bodies: "player", "invader", "shot", "bomb". The scene needs a body named
 * "player", at least one invader, templates named "shot" and "bomb", and a
 * view, which is the field.
 *
 * The gun has three lives. A bomb that touches it (find_collision, checked
 * after every step) costs one: the bomb and every other bomb in flight are
 * removed, and the gun plays on where it is. Won when no invader is left;
 * lost with the last life, when an invader reaches the gun (the file's
 * destructive collision removes it) or comes down to the gun's height.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "jostle/collision.h"
#include "game.h"

static const double GUN_SPEED = 8.0;        /* m/s at move = 1 */
static const double SHOT_SPEED = 14.0;      /* m/s, up */
static const double RELOAD = 0.35;          /* s between shots */
static const int MAX_SHOTS = 2;             /* the gun's shots in flight at once */
static const double MARCH_SPEED = 1.0;      /* m/s with the whole formation left ... */
static const double MARCH_SPEED_LAST = 4.0; /* ... and with one invader left */
static const double STEP_DOWN = 0.5;        /* m, at each edge */
static const double BOMB_SPEED = 5.0;       /* m/s, down */
static const double BOMB_INTERVAL = 0.9;    /* s between bombs */
static const int LIVES = 3;

typedef struct {
    scene_file_t *file;
    scene_t *scene;
    aabb_t field;
    double direction;  /* +1 marching right, -1 left */
    double reload;     /* s until the gun may fire */
    double bomb_timer; /* s until the next bomb */
    uint64_t random;
    int initial_invaders;
    game_status_t status;
} invaders_t;

/* xorshift64: the same bombs every game, so scripted games replay. */
static double random_unit(invaders_t *game) {
    uint64_t x = game->random;
    x ^= x << 13;
    x ^= x >> 7;
    x ^= x << 17;
    game->random = x;
    return (double)(x >> 11) / 9007199254740992.0;
}

static bool alive(body_t *body, const char *tag) {
    return !body_is_removed(body) && game_body_has_tag(body, tag);
}

static int count(scene_t *scene, const char *tag) {
    int n = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) n += alive(scene_get_body(scene, i), tag);
    return n;
}

static void *invaders_start(scene_file_t *file, char *error, size_t error_size) {
    scene_t *scene = scene_file_get_scene(file);
    scene_file_view_t view = scene_file_get_view(file);
    const char *problem = NULL;
    if (scene_file_find_body(file, "player") == NULL)
        problem = "the scene has no body named player";
    else if (count(scene, "invader") == 0)
        problem = "the scene has no body tagged invader";
    else if (!scene_file_has_template(file, "shot"))
        problem = "the scene has no template named shot";
    else if (!scene_file_has_template(file, "bomb"))
        problem = "the scene has no template named bomb";
    else if (!view.has_view)
        problem = "the scene has no view (the field)";
    if (problem != NULL) {
        snprintf(error, error_size, "space_invaders: %s", problem);
        return NULL;
    }
    invaders_t *game = calloc(1, sizeof *game);
    if (game == NULL) abort();
    vector_t half = {0.5 * view.width, 0.5 * view.height};
    *game = (invaders_t){
        .file = file,
        .scene = scene,
        .field = {vec_subtract(view.center, half), vec_add(view.center, half)},
        .direction = 1.0,
        .bomb_timer = BOMB_INTERVAL,
        .random = 0x9E3779B97F4A7C15ULL,
        .initial_invaders = count(scene, "invader"),
    };
    game->status = (game_status_t){GAME_PLAYING, LIVES, 0, game->initial_invaders};
    return game;
}

/* The formation's bounds, or false when no invader is left. */
static bool formation_bounds(invaders_t *game, aabb_t *bounds) {
    bool any = false;
    for (size_t i = 0; i < scene_bodies(game->scene); i++) {
        body_t *body = scene_get_body(game->scene, i);
        if (!alive(body, "invader")) continue;
        aabb_t b = body_get_bounds(body);
        *bounds = any ? aabb_union(*bounds, b) : b;
        any = true;
    }
    return any;
}

/* Invaders are static bodies moved by their velocity; at an edge the whole
 * formation steps down and turns. Fewer invaders march faster. */
static void march(invaders_t *game, aabb_t formation, double dt) {
    double left_fraction = (double)game->status.remaining / (double)game->initial_invaders;
    double speed = MARCH_SPEED_LAST + (MARCH_SPEED - MARCH_SPEED_LAST) * left_fraction;
    bool at_edge = (game->direction > 0 && formation.max.x + speed * dt > game->field.max.x) ||
                   (game->direction < 0 && formation.min.x - speed * dt < game->field.min.x);
    if (at_edge) game->direction = -game->direction;
    for (size_t i = 0; i < scene_bodies(game->scene); i++) {
        body_t *body = scene_get_body(game->scene, i);
        if (!alive(body, "invader")) continue;
        if (at_edge) {
            body_set_centroid(body, vec_add(body_get_centroid(body), (vector_t){0, -STEP_DOWN}));
        }
        body_set_velocity(body, (vector_t){game->direction * speed, 0.0});
    }
}

/* A bomb from the lowest invader of a column chosen at random. */
static void drop_bomb(invaders_t *game) {
    body_t *chosen = NULL;
    int target = (int)(random_unit(game) * game->status.remaining);
    for (size_t i = 0; i < scene_bodies(game->scene) && chosen == NULL; i++) {
        body_t *body = scene_get_body(game->scene, i);
        if (alive(body, "invader") && target-- == 0) chosen = body;
    }
    if (chosen == NULL) return;
    vector_t at = body_get_centroid(chosen);
    for (size_t i = 0; i < scene_bodies(game->scene); i++) {
        body_t *body = scene_get_body(game->scene, i);
        vector_t c = body_get_centroid(body);
        if (alive(body, "invader") && fabs(c.x - at.x) < 0.5 && c.y < at.y) {
            at = c;
            chosen = body;
        }
    }
    aabb_t bounds = body_get_bounds(chosen);
    scene_file_spawn(game->file, "bomb", (vector_t){at.x, bounds.min.y - 0.3},
                     (vector_t){0.0, -BOMB_SPEED});
}

/* Moves the gun within the field and fires when asked and reloaded. */
static void command_gun(invaders_t *game, body_t *gun, game_input_t input, double dt) {
    aabb_t bounds = body_get_bounds(gun);
    vector_t at = body_get_centroid(gun);
    double half = 0.5 * (bounds.max.x - bounds.min.x);
    double target = at.x + input.move * GUN_SPEED * dt;
    target = fmax(game->field.min.x + half, fmin(game->field.max.x - half, target));
    body_set_velocity(gun, (vector_t){(target - at.x) / dt, 0.0});
    game->reload -= dt;
    if (input.fire && game->reload <= 0.0 && count(game->scene, "shot") < MAX_SHOTS) {
        scene_file_spawn(game->file, "shot", (vector_t){at.x, bounds.max.y + 0.3},
                         (vector_t){0.0, SHOT_SPEED});
        game->reload = RELOAD;
    }
}

/* Shots and bombs that left the field are gone. */
static void clear_strays(invaders_t *game) {
    for (size_t i = 0; i < scene_bodies(game->scene); i++) {
        body_t *body = scene_get_body(game->scene, i);
        if (!alive(body, "shot") && !alive(body, "bomb")) continue;
        double y = body_get_centroid(body).y;
        if (y > game->field.max.y || y < game->field.min.y) body_remove(body);
    }
}

/* A bomb touching the gun costs a life and clears the bombs in flight;
 * true when that was the last life. */
static bool bombed(invaders_t *game, body_t *gun) {
    bool hit = false;
    for (size_t i = 0; i < scene_bodies(game->scene) && !hit; i++) {
        body_t *body = scene_get_body(game->scene, i);
        hit = alive(body, "bomb") && find_collision(body, gun).collided;
    }
    if (!hit) return false;
    for (size_t i = 0; i < scene_bodies(game->scene); i++) {
        body_t *body = scene_get_body(game->scene, i);
        if (alive(body, "bomb")) body_remove(body);
    }
    game->status.lives--;
    return game->status.lives == 0;
}

static void stop(invaders_t *game, game_outcome_t outcome) {
    game->status.outcome = outcome;
    if (outcome == GAME_LOST) game->status.lives = 0;
    for (size_t i = 0; i < scene_bodies(game->scene); i++) {
        body_t *body = scene_get_body(game->scene, i);
        if (isinf(body_get_mass(body))) body_set_velocity(body, VEC_ZERO);
    }
}

static void invaders_update(void *state, game_input_t input, double dt) {
    invaders_t *game = state;
    int left = count(game->scene, "invader");
    game->status.score += game->status.remaining - left;
    game->status.remaining = left;
    body_t *gun = scene_file_find_body(game->file, "player");
    aabb_t formation = {VEC_ZERO, VEC_ZERO}; /* set by formation_bounds when it returns true */
    if (!formation_bounds(game, &formation)) {
        stop(game, GAME_WON);
        return;
    }
    if (gun == NULL || body_is_removed(gun) || formation.min.y <= body_get_bounds(gun).max.y ||
        bombed(game, gun)) {
        stop(game, GAME_LOST);
        return;
    }
    if (dt <= 0.0) return;
    clear_strays(game);
    march(game, formation, dt);
    game->bomb_timer -= dt;
    if (game->bomb_timer <= 0.0) {
        drop_bomb(game);
        game->bomb_timer += BOMB_INTERVAL;
    }
    command_gun(game, gun, input, dt);
}

static game_status_t invaders_status(const void *state) {
    return ((const invaders_t *)state)->status;
}

const game_rules_t SPACE_INVADERS_RULES = {"space_invaders", invaders_start, invaders_update,
                                           invaders_status, free, true, false};
