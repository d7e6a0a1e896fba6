#ifndef GAME_H
#define GAME_H

/*
 * Game rules on top of a scene file: what a file's `game NAME` runs besides
 * the physics (Breakout's lives and bricks, Space Invaders' marching and
 * shooting). The engine knows nothing of games and the scene file only names
 * one; the rules are here, written against the engine's public API and
 * scene_file.h. No SDL: the tests link these files and play them with
 * scripted input (tests/test_games.c).
 *
 * How the sandbox runs a game:
 *
 *     scene_file_t *file = scene_file_load(path, &error);
 *     game_t *game = game_start(file, message, sizeof message); // NULL: no game
 *     each physics step:
 *         scene_tick(scene_file_get_scene(file), dt);
 *         game_update(game, input, dt);   // reads the step's record, applies input
 *     each frame: game_status(game) for the HUD
 *     game_free(game); scene_file_free(file);
 *
 * game_update comes after scene_tick because it reads the step's contact
 * record (valid until the next tick): a brick hit in that step, a ball that
 * left the paddle. The input it applies acts in the next tick.
 *
 * Games tell bodies apart by their tags (body_get_info of a scene file's body
 * is its tag string): "player", "invader", "shot", "brick", ...
 */

#include <stdbool.h>
#include <stddef.h>
#include "jostle/scene_file.h"

/* The player's controls for one step. */
typedef struct {
    double move; /* horizontal command, -1 (full speed left) to 1 (right); clamped */
    bool fire;   /* held: fire whenever the gun has reloaded */
} game_input_t;

typedef enum {
    GAME_PLAYING = 0,
    GAME_WON,
    GAME_LOST,
} game_outcome_t;

typedef struct {
    game_outcome_t outcome;
    int lives;     /* left, including the one being played */
    int score;     /* bricks or invaders destroyed */
    int remaining; /* bricks or invaders left */
} game_status_t;

/* One game's rules. A new game is a game_rules_t and one line in the table of
 * game.c. */
typedef struct {
    const char *name; /* as in the scene file's `game NAME` */
    /* Finds the bodies and templates the game needs; NULL and a message when
     * the scene lacks one. */
    void *(*start)(scene_file_t *file, char *error, size_t error_size);
    void (*update)(void *state, game_input_t input, double dt);
    game_status_t (*status)(const void *state);
    void (*free)(void *state);
    /* Whether the player's input does anything (the pegs board ignores it):
     * the sandbox gives the game its keys only then. */
    bool takes_input;
    /* Whether the sandbox opens it with its energy as the TOOLS page's
     * plot (F5): the double pendulum's. */
    bool plots_energy;
} game_rules_t;

extern const game_rules_t BREAKOUT_RULES;
extern const game_rules_t SPACE_INVADERS_RULES;
extern const game_rules_t PEGS_RULES;
/* The joint presets' games (rigs.c): the car's controls, the double
 * pendulum's energy plot; their files make the joints. */
extern const game_rules_t DOUBLE_PENDULUM_RULES;
extern const game_rules_t CAR_RULES;

typedef struct game game_t;

/* The rules of the game called name, NULL when there are none. */
const game_rules_t *game_find(const char *name);

/*
 * Starts the game the file names (scene_file_get_game) on the file's scene,
 * which it then drives until game_free (the file must outlive the game).
 * NULL with error = "" when the file names no game; NULL with a message in
 * error when it names an unknown game or the scene lacks what the game needs
 * ("breakout: the scene has no body named paddle"). error may be NULL when
 * error_size is 0.
 */
game_t *game_start(scene_file_t *file, char *error, size_t error_size);

/* Applies the rules after a scene_tick of dt seconds, then the input for the
 * next one. Nothing happens once the game is won or lost. NULL is allowed. */
void game_update(game_t *game, game_input_t input, double dt);

game_status_t game_status(const game_t *game);

/* Whether the game reads game_input_t (its rules' takes_input). */
bool game_takes_input(const game_t *game);

/* Whether its rules ask for the energy plot (plots_energy); false for NULL. */
bool game_plots_energy(const game_t *game);

/* Frees the game's state (not the scene). NULL is allowed. */
void game_free(game_t *game);

/* Whether body is a scene file's body with this tag (its info is the tag). */
bool game_body_has_tag(body_t *body, const char *tag);

#endif // #ifndef GAME_H
