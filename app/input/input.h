#ifndef SANDBOX_INPUT_H
#define SANDBOX_INPUT_H

/*
 * Mouse and keyboard: each SDL event changes the app's state. Scripted input
 * (script.c) arrives here as the same SDL events, so a script drives exactly
 * what a person does.
 */

#include <SDL.h>
#include <stddef.h>
#include "core/app.h"

void input_handle_event(app_t *app, const SDL_Event *event);

/* The dynamic body under the cursor, or NULL. */
body_t *input_hovered_body(app_t *app);

/* The world point under the cursor. */
vector_t input_cursor_world(const app_t *app);

/* The controls, for the help screen and --help: keys and what they do. */
typedef struct {
    const char *keys;
    const char *action;
} input_control_t;

extern const input_control_t INPUT_CONTROLS[];
extern const size_t INPUT_CONTROL_COUNT;

#endif
