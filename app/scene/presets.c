#include "scene/presets.h"
#include <dirent.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int by_name(const void *a, const void *b) {
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static bool ends_with_scene(const char *name) {
    size_t length = strlen(name);
    return length > 6 && strcmp(name + length - 6, ".scene") == 0;
}

void presets_load(presets_t *presets, const char *dir) {
    memset(presets, 0, sizeof(*presets));
    if (dir == NULL) return;
    DIR *listing = opendir(dir);
    if (listing == NULL) return;
    struct dirent *entry;
    while ((entry = readdir(listing)) != NULL && presets->count < PRESETS_MAX) {
        if (entry->d_name[0] == '.' || !ends_with_scene(entry->d_name)) continue;
        size_t size = strlen(dir) + 1 + strlen(entry->d_name) + 1;
        char *path = malloc(size);
        if (path == NULL) break;
        snprintf(path, size, "%s/%s", dir, entry->d_name);
        presets->paths[presets->count++] = path;
    }
    closedir(listing);
    qsort(presets->paths, presets->count, sizeof(presets->paths[0]), by_name);
}

void presets_free(presets_t *presets) {
    for (size_t i = 0; i < presets->count; i++) free(presets->paths[i]);
    memset(presets, 0, sizeof(*presets));
}

size_t presets_scene_count(const presets_t *presets) {
    return presets->count + 1;
}

const char *presets_path(const presets_t *presets, size_t index) {
    return index >= 1 && index <= presets->count ? presets->paths[index - 1] : NULL;
}

int presets_find(const presets_t *presets, const char *path) {
    if (path == NULL || path[0] == '\0') return 0;
    char wanted[PATH_MAX], candidate[PATH_MAX];
    if (realpath(path, wanted) == NULL) return -1;
    for (size_t i = 0; i < presets->count; i++) {
        if (realpath(presets->paths[i], candidate) != NULL && strcmp(wanted, candidate) == 0) {
            return (int)i + 1;
        }
    }
    return -1;
}

size_t presets_next(const presets_t *presets, int from, int step) {
    long count = (long)presets_scene_count(presets);
    if (from < 0 || from >= count) return step >= 0 ? 0 : (size_t)(count - 1);
    long next = ((long)from + step) % count;
    if (next < 0) next += count;
    return (size_t)next;
}
