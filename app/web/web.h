#ifndef SANDBOX_WEB_H
#define SANDBOX_WEB_H

/*
 * The sandbox in a web page (the Emscripten build, docs/web.md): what the
 * browser does in place of the desktop. The page runs on one thread (the
 * physics and drawing threads fall back to the caller when SDL cannot start
 * them, and the engine's workers stay at 1); its frame loop is main.c's,
 * handing each frame to the browser here. Compiled for the page only.
 */

#include <emscripten/em_macros.h>
#include <stdbool.h>

/* After SDL_Init: the page's keys go to the sandbox rather than the
 * browser (Space, PageDown, Tab, Ctrl+S). */
void web_start(void);

/* Whether to hand the frame just drawn to the browser now: always in a
 * window; with the fixed clock of --headless (a scripted run) once 0.1 s of
 * frames has run since the last hand-over, so that such a run goes as fast
 * as it can while the page still shows it and answers. */
bool web_frame_due(bool fixed_clock);

/* Hands the frame presented to the browser: returns at the browser's next
 * animation frame, events received meanwhile waiting in SDL's queue. A
 * JavaScript import that waits (web.c, Asyncify), declared as such so that
 * main calls it directly: main is the one function that may wait. */
void web_frame_done(void) EM_IMPORT(__asyncjs__web_frame_done);

/* Offers the file the sandbox wrote at path (a saved scene, a screenshot)
 * as a download. */
void web_offer_file(const char *path);

/* The frame loop has ended (Esc, Q, a script's quit or its last frame,
 * --frames): the page says so; status is main's exit status. */
void web_stopped(int status);

/* Called by the page for a file it wrote into the file system (dropped on
 * the page or chosen): opens it as a file dropped on the window. */
void web_open_file(const char *path);

#endif
