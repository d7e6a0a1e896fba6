#ifndef SANDBOX_SCENE_TEXT_H
#define SANDBOX_SCENE_TEXT_H

/*
 * The words of the side bar's SCENE panel: the open scene's place in the
 * list of scenes, its game's score, lives and what is left, or its
 * timestep. Plain C (no SDL, no engine), tested by tests/app_units.c; every
 * line fits the side bar (LAYOUT_LINE_CHARS).
 */

#include <stddef.h>
#include "core/layout.h"

#define SCENE_TEXT_SIZE (LAYOUT_LINE_CHARS + 1)

/* "2 of 12", or "file" for a scene that is not in the list (index < 0). */
void scene_text_position(int index, size_t count, char out[SCENE_TEXT_SIZE]);

/* A timestep: "timestep 1/120 s", "timestep 0.003 s". */
void scene_text_timestep(double step, char out[SCENE_TEXT_SIZE]);

typedef enum { SCENE_TEXT_PLAYING = 0, SCENE_TEXT_WON, SCENE_TEXT_LOST } scene_text_outcome_t;

/* A game's status in one line: "score 3  lives 2  bricks 47" (what is left
 * named by the game: bricks, invaders; pegs counts the balls on the board and
 * those that landed; a joint preset's rig, whose lives are -1, its joints:
 * "joints 9"), "WON  score 50  R: again", "LOST  score 12  R: again". */
void scene_text_game(const char *game, scene_text_outcome_t outcome, int score, int lives,
                     int remaining, char out[SCENE_TEXT_SIZE]);

#endif
