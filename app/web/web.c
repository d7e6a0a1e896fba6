#include "web/web.h"
#include <SDL.h>
#include <emscripten.h>

/* Waits for the browser's next animation frame. An import that waits
 * (Asyncify): main's stack is kept and taken up again then, so main calls
 * it directly (app/web/web.mk names main alone). */
EM_ASYNC_JS(void, web_frame_done, (void), {
    if (Module.sandboxFrameShown) Module.sandboxFrameShown();
    await new Promise(function(resolve) { requestAnimationFrame(resolve); });
});

EM_JS(void, offer_file, (const char *path), {
    var name = UTF8ToString(path);
    var blob = new Blob([FS.readFile(name)], {type: "application/octet-stream"});
    var link = document.createElement("a");
    link.href = URL.createObjectURL(blob);
    link.download = name.split("/").pop();
    document.body.appendChild(link);
    link.click();
    link.remove();
    setTimeout(function() { URL.revokeObjectURL(link.href); }, 60000);
});

EM_JS(void, say_stopped, (int status), {
    if (Module.sandboxStopped) Module.sandboxStopped(status);
});

/* The most a scripted run works between two hand-overs (s). */
static const double FIXED_CLOCK_SLICE = 0.1;
static double last_hand_over = -1.0; /* s; none yet */

void web_start(void) {
    /* Only main may wait for the browser (Asyncify, app/web/web.mk):
     * SDL_Delay spins. */
    SDL_SetHint(SDL_HINT_EMSCRIPTEN_ASYNCIFY, "0");
    /* With text input on, SDL leaves keys without a browser meaning of
     * their own to the browser; the sandbox reads no text. */
    SDL_StopTextInput();
}

bool web_frame_due(bool fixed_clock) {
    double now = emscripten_get_now() / 1000.0;
    if (fixed_clock && now - last_hand_over < FIXED_CLOCK_SLICE) return false;
    last_hand_over = now;
    return true;
}

void web_offer_file(const char *path) {
    offer_file(path);
}

void web_stopped(int status) {
    say_stopped(status);
}

EMSCRIPTEN_KEEPALIVE void web_open_file(const char *path) {
    SDL_Event event;
    SDL_zero(event);
    event.type = SDL_DROPFILE;
    event.drop.file = SDL_strdup(path);
    if (event.drop.file != NULL && SDL_PushEvent(&event) != 1) SDL_free(event.drop.file);
}
