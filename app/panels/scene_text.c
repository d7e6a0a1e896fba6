#include "panels/scene_text.h"
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "panels/text.h"

/* One line, cut to the side bar's width should it ever outgrow it. */
static void put(char out[SCENE_TEXT_SIZE], const char *text) {
    char line[128];
    snprintf(line, sizeof(line), "%s", text);
    text_fit(line, LAYOUT_LINE_CHARS);
    memcpy(out, line, strlen(line) + 1);
}

void scene_text_position(int index, size_t count, char out[SCENE_TEXT_SIZE]) {
    char text[64];
    if (index < 0) snprintf(text, sizeof(text), "file");
    else snprintf(text, sizeof(text), "%d of %zu", index + 1, count);
    put(out, text);
}

void scene_text_timestep(double step, char out[SCENE_TEXT_SIZE]) {
    char text[64];
    double per_second = 1.0 / step;
    double whole = round(per_second);
    if (step > 0.0 && whole >= 1.0 && whole <= 1e6 && fabs(per_second - whole) < 1e-9 * whole) {
        snprintf(text, sizeof(text), "timestep 1/%.0f s", whole);
    } else {
        snprintf(text, sizeof(text), "timestep %.4g s", step);
    }
    put(out, text);
}

void scene_text_game(const char *game, scene_text_outcome_t outcome, int score, int lives,
                     int remaining, char out[SCENE_TEXT_SIZE]) {
    char text[128];
    if (outcome == SCENE_TEXT_WON) {
        snprintf(text, sizeof(text), "WON  score %d  R: again", score);
    } else if (outcome == SCENE_TEXT_LOST) {
        snprintf(text, sizeof(text), "LOST  score %d  R: again", score);
    } else if (lives < 0) {
        /* A joint preset's game (app/games/rigs.c): nothing to win. */
        snprintf(text, sizeof(text), "joints %d", remaining);
    } else if (strcmp(game, "pegs") == 0) {
        snprintf(text, sizeof(text), "balls %d  landed %d", remaining, score);
    } else {
        const char *left = strcmp(game, "breakout") == 0         ? "bricks"
                           : strcmp(game, "space_invaders") == 0 ? "invaders"
                                                                 : "left";
        snprintf(text, sizeof(text), "score %d  lives %d  %s %d", score, lives, left, remaining);
    }
    put(out, text);
}
