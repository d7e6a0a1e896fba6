#ifndef SANDBOX_SAMPLES_H
#define SANDBOX_SAMPLES_H

/*
 * The samples: the default scene, then every *.scene file of the samples'
 * directory (assets/scenes/), each with the category and the note its file
 * gives (`category`, `note`: docs/scenes.md), ordered by category
 * (sample_categories.h; a file of an unknown category or none comes last)
 * and by name within one. The SAMPLES panel lists them; PageDown and PageUp
 * go through them in this order. A file dropped into the directory joins
 * the list; one that does not load is listed with the message as its note.
 * Engine API (scene_file.h) only, no SDL; tested by tests/app_units.c.
 */

#include <stdbool.h>
#include <stddef.h>
#include "jostle/scene_file.h"

#define SAMPLES_MAX 256
#define SAMPLE_NAME_MAX 64

typedef struct {
    char *path;                 /* "DIR/NAME.scene"; NULL for the default scene */
    char name[SAMPLE_NAME_MAX]; /* the file's name without .scene; the default's given name */
    int category;               /* in SAMPLE_CATEGORIES, or SAMPLE_CATEGORY_COUNT: other */
    char note[SCENE_FILE_NOTE_MAX + 1];
} sample_t;

typedef struct {
    sample_t items[SAMPLES_MAX]; /* [0] is the default scene */
    size_t count;                /* the default scene and the files */
} samples_t;

/* Lists the default scene (its name, and its category and note read from
 * its text; text NULL: Basics, no note), then the *.scene files of dir (none
 * when dir is NULL or cannot be read). */
void samples_load(samples_t *samples, const char *dir, const char *default_name,
                  const char *default_text);
void samples_free(samples_t *samples);

/* Samples in the list: the default scene and the files. */
size_t samples_count(const samples_t *samples);

/* The path of sample `index`: NULL for 0, the default scene. */
const char *samples_path(const samples_t *samples, size_t index);

/* Where a scene is in the list: 0 for the default (path NULL or ""), the
 * file's place when path names one of the files (compared as real paths),
 * -1 when it is not in the list. */
int samples_find(const samples_t *samples, const char *path);

/* The index `step` places after `from` (-1: a scene not in the list, from
 * which +1 goes to the default scene and -1 to the last sample), wrapping
 * round. */
size_t samples_next(const samples_t *samples, int from, int step);

/* The category's name of sample `index` ("Other" for an unknown one). */
const char *samples_category_name(const samples_t *samples, size_t index);

#endif
