#ifndef SCENE_FILE_CHECK_H
#define SCENE_FILE_CHECK_H

/*
 * Checks shared by the scene-file tests and the fuzz target
 * (tests/fuzz/fuzz_scene_file.c): two loaded files compared body by body and
 * force by force, and the whole round trip of one input.
 */

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "jostle/scene_file.h"

/* True when both files hold the same scene: settings (sleeping and the sleep
 * phase included), timestep, view, game; the same bodies in the same order
 * with every value the engine reports equal (pose, velocities, mass,
 * inertia, material, colour, world vertices, tag, filter, sleep timer,
 * sleeping island); the same contact memory (scene_state.h) by body index;
 * the same joints in the same order (definition, bodies by index);
 * the same force creators in the same order (kind, constant, bodies by
 * index). Otherwise false, and why (the first difference) in `why`. */
bool scene_file_same(scene_file_t *a, scene_file_t *b, char *why, size_t why_size);

/* Whether both files made the same force creators, in any order (a scene that
 * spawned bodies lists their forces last, a reload lists them in file order):
 * kind, constant, and bodies by their index in each scene. */
bool scene_file_same_forces_in_any_order(scene_file_t *a, scene_file_t *b, char *why,
                                         size_t why_size);

/*
 * One input through the whole pipeline: parse it; when refused, the message
 * must start with "NAME:" and nothing else must happen; when accepted, write
 * it, parse the text again (which must succeed), compare the two scenes with
 * scene_file_same, and write again: the text must not change. Returns true
 * when all of that holds, else false with the reason in `why`. Used on every
 * fuzz input and, by make check, on the corpus.
 */
bool scene_file_round_trip(const uint8_t *data, size_t size, const char *name, char *why,
                           size_t why_size);

#endif // #ifndef SCENE_FILE_CHECK_H
