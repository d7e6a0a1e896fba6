#ifndef SANDBOX_PRESETS_H
#define SANDBOX_PRESETS_H

/*
 * The scenes PageDown and PageUp go through: the default scene first, then
 * every *.scene file of the presets directory (assets/scenes/), in the order
 * of their names. A file dropped into that directory joins the list. Plain C
 * (no SDL, no engine), tested by tests/app_units.c.
 */

#include <stdbool.h>
#include <stddef.h>

#define PRESETS_MAX 256

typedef struct {
    char *paths[PRESETS_MAX]; /* the files, "DIR/NAME.scene", sorted by name */
    size_t count;             /* files; the list is count + 1 scenes long */
} presets_t;

/* Lists the *.scene files of dir (none when dir is NULL or cannot be read:
 * the list then holds the default scene alone). */
void presets_load(presets_t *presets, const char *dir);
void presets_free(presets_t *presets);

/* Scenes in the list: the default scene and the files. */
size_t presets_scene_count(const presets_t *presets);

/* The path of scene `index` of the list: NULL for 0, the default scene. */
const char *presets_path(const presets_t *presets, size_t index);

/* Where a scene is in the list: 0 for the default (path NULL), the file's
 * place when path names one of the files (compared as real paths), -1 when
 * it is not in the list. */
int presets_find(const presets_t *presets, const char *path);

/* The index `step` places after `from` (-1: a scene not in the list, from
 * which +1 goes to the default scene and -1 to the last file), wrapping
 * round. */
size_t presets_next(const presets_t *presets, int from, int step);

#endif
