/* The public entry points: read from memory or a path, free, settings. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_file_private.h"

static void release(scene_file_t *file) {
    /* The scene first: freeing its bodies calls record_freed on the records,
     * which must still exist. */
    if (file->scene != NULL) scene_free(file->scene);
    for (size_t i = 0; i < file->record_count; i++) free(file->records[i]);
    free(file->records);
    free(file->instances);
    free(file->groups);
    free(file->side1);
    free(file->side2);
    sf_doc_free(&file->doc);
    free(file);
}

scene_file_t *scene_file_parse(const char *text, size_t length, const char *file_name,
                               scene_file_error_t *error) {
    if (error != NULL) *error = (scene_file_error_t){0};
    scene_file_t *file = calloc(1, sizeof *file);
    if (file == NULL) abort();
    sf_lexer_t lexer;
    sf_lexer_init(&lexer, text != NULL ? text : "", text != NULL ? length : 0, file_name, error);
    if (!sf_parse(&lexer, &file->doc) || !sf_build(file, &lexer)) {
        release(file);
        return NULL;
    }
    return file;
}

/* A message without a place in the text: "FILE: WHAT: REASON". */
static void io_error(scene_file_error_t *error, const char *path, const char *what) {
    if (error == NULL) return;
    *error = (scene_file_error_t){0};
    snprintf(error->message, sizeof error->message, "%s: %s: %s", path, what, strerror(errno));
}

scene_file_t *scene_file_load(const char *path, scene_file_error_t *error) {
    if (path == NULL) {
        errno = EINVAL;
        io_error(error, "(null)", "cannot read");
        return NULL;
    }
    FILE *stream = fopen(path, "rb");
    if (stream == NULL) {
        io_error(error, path, "cannot read");
        return NULL;
    }
    size_t size = 0, capacity = 0;
    char *text = NULL;
    for (;;) {
        sf_reserve((void **)&text, &capacity, size + 4096, 1);
        size_t got = fread(text + size, 1, capacity - size, stream);
        size += got;
        if (got == 0) break;
    }
    bool failed = ferror(stream) != 0;
    fclose(stream);
    if (failed) {
        free(text);
        errno = EIO;
        io_error(error, path, "cannot read");
        return NULL;
    }
    scene_file_t *file = scene_file_parse(text, size, path, error);
    free(text);
    return file;
}

void scene_file_free(scene_file_t *file) {
    if (file != NULL) release(file);
}

scene_t *scene_file_get_scene(scene_file_t *file) {
    return file->scene;
}

double scene_file_get_timestep(const scene_file_t *file) {
    return file->doc.settings.timestep;
}

scene_file_view_t scene_file_get_view(const scene_file_t *file) {
    return file->doc.settings.view;
}

const char *scene_file_get_game(const scene_file_t *file) {
    return file->doc.settings.game.text;
}

bool scene_file_set_timestep(scene_file_t *file, double timestep) {
    if (!(timestep > 0.0 && timestep <= 10.0)) return false;
    file->doc.settings.timestep = timestep;
    return true;
}

size_t scene_file_get_workers(const scene_file_t *file) {
    return file->doc.settings.workers;
}

scene_file_stepping_t scene_file_get_stepping(const scene_file_t *file) {
    return file->doc.settings.stepping;
}

void scene_file_set_stepping(scene_file_t *file, scene_file_stepping_t stepping) {
    file->doc.settings.stepping =
        stepping == SCENE_FILE_STEP_FRAME ? SCENE_FILE_STEP_FRAME : SCENE_FILE_STEP_FIXED;
}

const char *scene_file_get_category(const scene_file_t *file) {
    return file->doc.settings.category;
}

const char *scene_file_get_note(const scene_file_t *file) {
    return file->doc.settings.note;
}

bool scene_file_save(scene_file_t *file, const char *path, scene_file_error_t *error) {
    size_t length = 0;
    char *text = scene_file_write(file, &length, error);
    if (text == NULL) return false;
    FILE *stream = fopen(path, "wb");
    if (stream == NULL) {
        io_error(error, path, "cannot write");
        free(text);
        return false;
    }
    bool ok = fwrite(text, 1, length, stream) == length;
    ok = fclose(stream) == 0 && ok;
    free(text);
    if (!ok) io_error(error, path, "cannot write");
    return ok;
}
