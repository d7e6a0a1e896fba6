#include "scene/samples.h"
#include <dirent.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene/sample_categories.h"

static bool ends_with_scene(const char *name) {
    size_t length = strlen(name);
    return length > 6 && strcmp(name + length - 6, ".scene") == 0;
}

/* The category and note a loaded file gives. */
static void describe(sample_t *sample, const scene_file_t *file) {
    int category = sample_category_index(scene_file_get_category(file));
    sample->category = category >= 0 ? category : SAMPLE_CATEGORY_COUNT;
    snprintf(sample->note, sizeof sample->note, "%s", scene_file_get_note(file));
}

static void add_file(samples_t *samples, const char *dir, const char *file_name) {
    size_t size = strlen(dir) + 1 + strlen(file_name) + 1;
    char *path = malloc(size);
    if (path == NULL) return;
    snprintf(path, size, "%s/%s", dir, file_name);
    sample_t *sample = &samples->items[samples->count++];
    *sample = (sample_t){.path = path, .category = SAMPLE_CATEGORY_COUNT};
    snprintf(sample->name, sizeof sample->name, "%.*s", (int)(strlen(file_name) - 6), file_name);
    scene_file_error_t error;
    scene_file_t *file = scene_file_load(path, &error);
    if (file == NULL) {
        snprintf(sample->note, sizeof sample->note, "%.200s", error.message);
        return;
    }
    describe(sample, file);
    scene_file_free(file);
}

/* By category, then by name. */
static int by_category(const void *a, const void *b) {
    const sample_t *x = a, *y = b;
    if (x->category != y->category) return x->category < y->category ? -1 : 1;
    return strcmp(x->name, y->name);
}

void samples_load(samples_t *samples, const char *dir, const char *default_name,
                  const char *default_text) {
    memset(samples, 0, sizeof(*samples));
    sample_t *home = &samples->items[samples->count++];
    snprintf(home->name, sizeof home->name, "%s", default_name);
    home->category = 0;
    if (default_text != NULL) {
        scene_file_t *file = scene_file_parse(default_text, strlen(default_text), default_name,
                                              NULL);
        if (file != NULL) describe(home, file);
        scene_file_free(file);
    }
    if (dir == NULL) return;
    DIR *listing = opendir(dir);
    if (listing == NULL) return;
    struct dirent *entry;
    while ((entry = readdir(listing)) != NULL && samples->count < SAMPLES_MAX) {
        if (entry->d_name[0] == '.' || !ends_with_scene(entry->d_name)) continue;
        add_file(samples, dir, entry->d_name);
    }
    closedir(listing);
    qsort(samples->items + 1, samples->count - 1, sizeof samples->items[0], by_category);
}

void samples_free(samples_t *samples) {
    for (size_t i = 0; i < samples->count; i++) free(samples->items[i].path);
    memset(samples, 0, sizeof(*samples));
}

size_t samples_count(const samples_t *samples) {
    return samples->count > 0 ? samples->count : 1;
}

const char *samples_path(const samples_t *samples, size_t index) {
    return index >= 1 && index < samples->count ? samples->items[index].path : NULL;
}

int samples_find(const samples_t *samples, const char *path) {
    if (path == NULL || path[0] == '\0') return 0;
    char wanted[PATH_MAX], candidate[PATH_MAX];
    if (realpath(path, wanted) == NULL) return -1;
    for (size_t i = 1; i < samples->count; i++) {
        if (realpath(samples->items[i].path, candidate) != NULL &&
            strcmp(wanted, candidate) == 0) {
            return (int)i;
        }
    }
    return -1;
}

size_t samples_next(const samples_t *samples, int from, int step) {
    long count = (long)samples_count(samples);
    if (from < 0 || from >= count) return step >= 0 ? 0 : (size_t)(count - 1);
    long next = ((long)from + step) % count;
    if (next < 0) next += count;
    return (size_t)next;
}

const char *samples_category_name(const samples_t *samples, size_t index) {
    if (index >= samples->count) return "";
    int category = samples->items[index].category;
    return category >= 0 && category < SAMPLE_CATEGORY_COUNT ? SAMPLE_CATEGORIES[category]
                                                             : "Other";
}
