#include "game.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Every game this build knows. */
static const game_rules_t *const GAMES[] = {
    &BREAKOUT_RULES, &SPACE_INVADERS_RULES, &PEGS_RULES, &DOUBLE_PENDULUM_RULES, &CAR_RULES};

struct game {
    const game_rules_t *rules;
    void *state;
};

const game_rules_t *game_find(const char *name) {
    for (size_t i = 0; i < sizeof GAMES / sizeof GAMES[0]; i++) {
        if (strcmp(GAMES[i]->name, name) == 0) return GAMES[i];
    }
    return NULL;
}

game_t *game_start(scene_file_t *file, char *error, size_t error_size) {
    if (error_size > 0) error[0] = '\0';
    const char *name = scene_file_get_game(file);
    if (name[0] == '\0') return NULL;
    const game_rules_t *rules = game_find(name);
    if (rules == NULL) {
        if (error_size > 0) snprintf(error, error_size, "unknown game \"%s\"", name);
        return NULL;
    }
    void *state = rules->start(file, error, error_size);
    if (state == NULL) return NULL;
    game_t *game = malloc(sizeof *game);
    if (game == NULL) abort();
    *game = (game_t){rules, state};
    return game;
}

void game_update(game_t *game, game_input_t input, double dt) {
    if (game == NULL) return;
    if (!(input.move >= -1.0)) input.move = -1.0; /* NaN too */
    if (input.move > 1.0) input.move = 1.0;
    if (game->rules->status(game->state).outcome != GAME_PLAYING) return;
    game->rules->update(game->state, input, dt);
}

game_status_t game_status(const game_t *game) {
    return game->rules->status(game->state);
}

bool game_takes_input(const game_t *game) {
    return game != NULL && game->rules->takes_input;
}

bool game_plots_energy(const game_t *game) {
    return game != NULL && game->rules->plots_energy;
}

void game_free(game_t *game) {
    if (game == NULL) return;
    game->rules->free(game->state);
    free(game);
}

bool game_body_has_tag(body_t *body, const char *tag) {
    const char *info = body_get_info(body);
    return info != NULL && strcmp(info, tag) == 0;
}
