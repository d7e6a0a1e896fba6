#ifndef SANDBOX_SCRIPT_H
#define SANDBOX_SCRIPT_H

/*
 * --script FILE: timed input replayed into the running app as SDL events, so
 * a test (or a demo) drives the real sandbox. The format is in SCRIPT_HELP
 * (shown by --help) and docs/sandbox-reference.md. Parsing checks the whole
 * file before the app starts and names the file and line of the first
 * problem.
 */

#include <SDL.h>
#include <stdbool.h>
#include <stddef.h>
#include "core/app.h"

typedef struct script script_t;

/* The script format, for --help. */
extern const char SCRIPT_HELP[];

/* Parses the file; NULL and a message ("FILE:LINE: ...") in error when it
 * cannot be opened or a line is malformed. */
script_t *script_load(const char *path, char *error, size_t error_size);

/* As script_load, from text in memory (name is used in messages). */
script_t *script_parse(const char *name, const char *text, char *error, size_t error_size);

void script_free(script_t *script);

/*
 * Runs the script's actions due at this frame: input goes to
 * input_handle_event, spawn adds bodies, quit sets app->quit. When a
 * screenshot is due, its path is returned in *screenshot (else NULL): the
 * caller saves the frame once it is drawn.
 */
void script_frame(script_t *script, app_t *app, const char **screenshot);

/* Whether every action has run. */
bool script_done(const script_t *script);

#endif
