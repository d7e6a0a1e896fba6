#include "input/script.h"
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "input/input.h"
#include "draw/video.h"
#include "scene/state_log.h"

const char SCRIPT_HELP[] =
    "Script files (--script FILE): one command per line; '#' starts a comment.\n"
    "Positions are world metres (x right, y up; in the default scene the floor's\n"
    "top is y = 0 and the walls are at x = -14 and 14; in a scene file, its own\n"
    "coordinates), or window pixels after the word 'px'.\n"
    "The frame rate of a script is 60 frames per second of display time.\n"
    "  wait N                  let N frames pass (N >= 0)\n"
    "  wait Ts                 let T seconds pass (e.g. wait 0.5s)\n"
    "  key NAME                press and release a key: a letter or digit, space,\n"
    "                          tab, enter, escape, backspace, delete, up, down,\n"
    "                          left, right, home, pageup, pagedown, f1..f12,\n"
    "                          [ ] + - = , .\n"
    "                          a prefix shift+, ctrl+ or alt+ holds that modifier\n"
    "  keydown NAME, keyup NAME  press or release a key (e.g. keydown shift)\n"
    "  move [px] X Y           move the mouse\n"
    "  click [px] X Y          left click (drops the current shape there)\n"
    "  press BUTTON [px] X Y   press left, right or middle at a point\n"
    "  release BUTTON [[px] X Y]  release it (where the mouse is, or at X Y)\n"
    "  drag BUTTON [px] X1 Y1 X2 Y2 [FRAMES]  press, move over FRAMES frames\n"
    "                          (default 10), release\n"
    "  throw [px] X1 Y1 X2 Y2 [FRAMES]  shift + left drag: throws the shape\n"
    "  grab [px] X1 Y1 X2 Y2 [FRAMES]   right drag: pulls the body at X1 Y1\n"
    "  wheel N                 turn the mouse wheel N notches (N < 0: down)\n"
    "  spawn N [SIZE]          add N bodies (SIZE m, default 0.2) in a grid\n"
    "  open FILE               open a scene file, as if dropped on the window\n"
    "  resize W H              resize the window to W x H pixels (as if dragged;\n"
    "                          never below 800x600)\n"
    "  screenshot FILE         save this frame (FILE ends in .png or .bmp)\n"
    "  log [bodies]            print the scene's state to stdout: bodies, a hash\n"
    "                          of their positions, a game's score (and with\n"
    "                          bodies, each body's x, y and rotation)\n"
    "  quit                    stop the app\n";

typedef enum {
    ACT_WAIT,
    ACT_KEY_DOWN,
    ACT_KEY_UP,
    ACT_MOVE,
    ACT_BUTTON_DOWN,
    ACT_BUTTON_UP,
    ACT_WHEEL,
    ACT_SPAWN,
    ACT_SCREENSHOT,
    ACT_OPEN,
    ACT_RESIZE,
    ACT_LOG,
    ACT_QUIT,
} action_kind_t;

typedef struct {
    action_kind_t kind;
    int line;
    long count;          /* WAIT frames, WHEEL notches, SPAWN bodies, LOG 1 with bodies */
    double size;         /* SPAWN */
    SDL_Keycode key;     /* KEY_* */
    Uint16 mod;          /* KEY_*: the modifier state the event reports */
    Uint8 button;        /* BUTTON_* */
    bool has_position;   /* MOVE, BUTTON_*: else the mouse stays where it is */
    bool pixels;         /* position in pixels rather than metres */
    vector_t position;
    char *path;          /* SCREENSHOT, OPEN */
} action_t;

struct script {
    action_t *actions;
    size_t count, capacity;
    size_t next;         /* the next action to run */
    long waiting;        /* frames left of the current wait */
};

#define MAX_TOKENS 16

typedef struct {
    const char *name;
    int line;
    char *error;
    size_t error_size;
    script_t *script;
} parser_t;

static bool fail(parser_t *p, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static bool fail(parser_t *p, const char *format, ...) {
    char message[256];
    va_list args;
    va_start(args, format);
    vsnprintf(message, sizeof(message), format, args);
    va_end(args);
    snprintf(p->error, p->error_size, "%s:%d: %s", p->name, p->line, message);
    return false;
}

static action_t *add(parser_t *p, action_kind_t kind) {
    script_t *s = p->script;
    if (s->count == s->capacity) {
        size_t capacity = s->capacity ? 2 * s->capacity : 32;
        action_t *grown = realloc(s->actions, capacity * sizeof(action_t));
        if (grown == NULL) {
            fprintf(stderr, "sandbox: out of memory reading the script\n");
            exit(1);
        }
        s->actions = grown;
        s->capacity = capacity;
    }
    action_t *a = &s->actions[s->count++];
    *a = (action_t){.kind = kind, .line = p->line};
    return a;
}

static bool parse_number(parser_t *p, const char *token, const char *what, double *out) {
    char *end;
    errno = 0;
    double value = strtod(token, &end);
    if (end == token || *end != '\0' || errno == ERANGE || !isfinite(value)) {
        return fail(p, "%s must be a number, got '%s'", what, token);
    }
    *out = value;
    return true;
}

static bool parse_integer(parser_t *p, const char *token, const char *what, long min, long max,
                          long *out) {
    char *end;
    errno = 0;
    long value = strtol(token, &end, 10);
    if (end == token || *end != '\0' || errno == ERANGE) {
        return fail(p, "%s must be a whole number, got '%s'", what, token);
    }
    if (value < min || value > max) {
        return fail(p, "%s must be between %ld and %ld, got %ld", what, min, max, value);
    }
    *out = value;
    return true;
}

typedef struct {
    const char *name;
    SDL_Keycode key;
} key_name_t;

static const key_name_t KEY_NAMES[] = {
    {"space", SDLK_SPACE},       {"tab", SDLK_TAB},         {"enter", SDLK_RETURN},
    {"return", SDLK_RETURN},     {"escape", SDLK_ESCAPE},   {"esc", SDLK_ESCAPE},
    {"backspace", SDLK_BACKSPACE}, {"delete", SDLK_DELETE}, {"del", SDLK_DELETE},
    {"up", SDLK_UP},             {"down", SDLK_DOWN},       {"left", SDLK_LEFT},
    {"right", SDLK_RIGHT},       {"home", SDLK_HOME},       {"shift", SDLK_LSHIFT},
    {"pageup", SDLK_PAGEUP},     {"pagedown", SDLK_PAGEDOWN}, {"pgup", SDLK_PAGEUP},
    {"pgdn", SDLK_PAGEDOWN},
    {"ctrl", SDLK_LCTRL},        {"alt", SDLK_LALT},        {"f1", SDLK_F1},           {"f2", SDLK_F2},
    {"f3", SDLK_F3},             {"f4", SDLK_F4},           {"f5", SDLK_F5},
    {"f6", SDLK_F6},             {"f7", SDLK_F7},           {"f8", SDLK_F8},
    {"f9", SDLK_F9},             {"f10", SDLK_F10},         {"f11", SDLK_F11},
    {"f12", SDLK_F12},
};

static bool equals_ignoring_case(const char *a, const char *b) {
    for (; *a && *b; a++, b++) {
        if (tolower((unsigned char)*a) != tolower((unsigned char)*b)) return false;
    }
    return *a == *b;
}

/* A key name, optionally prefixed by shift+, ctrl+ and alt+ (any order). */
static bool parse_key(parser_t *p, const char *token, SDL_Keycode *key, Uint16 *mod) {
    *mod = KMOD_NONE;
    *key = SDLK_UNKNOWN;
    const char *name = token;
    for (;;) {
        if (strncmp(name, "shift+", 6) == 0 && name[6] != '\0') {
            *mod |= KMOD_LSHIFT;
            name += 6;
        } else if (strncmp(name, "ctrl+", 5) == 0 && name[5] != '\0') {
            *mod |= KMOD_LCTRL;
            name += 5;
        } else if (strncmp(name, "alt+", 4) == 0 && name[4] != '\0') {
            *mod |= KMOD_LALT;
            name += 4;
        } else {
            break;
        }
    }
    if (strlen(name) == 1 && isprint((unsigned char)name[0]) && name[0] != ' ') {
        *key = (SDL_Keycode)tolower((unsigned char)name[0]);
        return true;
    }
    for (size_t i = 0; i < sizeof(KEY_NAMES) / sizeof(KEY_NAMES[0]); i++) {
        if (equals_ignoring_case(name, KEY_NAMES[i].name)) {
            *key = KEY_NAMES[i].key;
            return true;
        }
    }
    return fail(p, "unknown key '%s' (see --help for key names)", name);
}

static Uint16 modifier_of(SDL_Keycode key) {
    if (key == SDLK_LSHIFT) return KMOD_LSHIFT;
    if (key == SDLK_LCTRL) return KMOD_LCTRL;
    if (key == SDLK_LALT) return KMOD_LALT;
    return KMOD_NONE;
}

static bool parse_button(parser_t *p, const char *token, Uint8 *button) {
    if (strcmp(token, "left") == 0) *button = SDL_BUTTON_LEFT;
    else if (strcmp(token, "right") == 0) *button = SDL_BUTTON_RIGHT;
    else if (strcmp(token, "middle") == 0) *button = SDL_BUTTON_MIDDLE;
    else return fail(p, "unknown mouse button '%s' (left, right or middle)", token);
    return true;
}

/* Reads `count` points from tokens[*at...], with an optional leading "px". */
static bool parse_points(parser_t *p, const char *command, char **tokens, int ntokens, int *at,
                         int count, bool *pixels, vector_t *points) {
    *pixels = false;
    if (*at < ntokens && strcmp(tokens[*at], "px") == 0) {
        *pixels = true;
        (*at)++;
    }
    if (ntokens - *at < 2 * count) {
        return fail(p, "'%s' needs %d coordinates (%s), got %d", command, 2 * count,
                    count == 1 ? "X Y" : "X1 Y1 X2 Y2", ntokens - *at);
    }
    for (int i = 0; i < count; i++) {
        if (!parse_number(p, tokens[*at], "X", &points[i].x)) return false;
        if (!parse_number(p, tokens[*at + 1], "Y", &points[i].y)) return false;
        *at += 2;
    }
    if (*pixels) {
        for (int i = 0; i < count; i++) {
            if (fabs(points[i].x) > 30000 || fabs(points[i].y) > 30000) {
                return fail(p, "pixel coordinates out of range (%g, %g)", points[i].x,
                            points[i].y);
            }
        }
    }
    return true;
}

static bool no_more(parser_t *p, const char *command, int ntokens, int at) {
    if (at < ntokens) return fail(p, "too many arguments for '%s'", command);
    return true;
}

static void add_move(parser_t *p, bool pixels, vector_t at) {
    action_t *a = add(p, ACT_MOVE);
    a->has_position = true;
    a->pixels = pixels;
    a->position = at;
}

static void add_button(parser_t *p, action_kind_t kind, Uint8 button, bool has_position,
                       bool pixels, vector_t at) {
    action_t *a = add(p, kind);
    a->button = button;
    a->has_position = has_position;
    a->pixels = pixels;
    a->position = at;
}

static void add_key(parser_t *p, action_kind_t kind, SDL_Keycode key, Uint16 mod) {
    action_t *a = add(p, kind);
    a->key = key;
    a->mod = mod;
}

static void add_wait(parser_t *p, long frames) {
    if (frames > 0) add(p, ACT_WAIT)->count = frames;
}

/* Press at from, move to `to` over frames frames, release there. */
static void add_drag(parser_t *p, Uint8 button, bool pixels, vector_t from, vector_t to,
                     long frames) {
    add_move(p, pixels, from);
    add_button(p, ACT_BUTTON_DOWN, button, true, pixels, from);
    for (long i = 1; i <= frames; i++) {
        add_wait(p, 1);
        double t = (double)i / (double)frames;
        add_move(p, pixels, vec_add(from, vec_multiply(t, vec_subtract(to, from))));
    }
    add_button(p, ACT_BUTTON_UP, button, true, pixels, to);
}

static bool parse_drag_frames(parser_t *p, char **tokens, int ntokens, int *at, long *frames) {
    *frames = 10;
    if (*at < ntokens) {
        if (!parse_integer(p, tokens[*at], "FRAMES", 1, 6000, frames)) return false;
        (*at)++;
    }
    return true;
}

static bool parse_line(parser_t *p, char **tokens, int n) {
    const char *command = tokens[0];
    int at = 1;
    vector_t points[2];
    bool pixels;
    if (strcmp(command, "wait") == 0) {
        if (n != 2) return fail(p, "'wait' needs one value: frames (wait 30) or seconds (wait 0.5s)");
        size_t length = strlen(tokens[1]);
        long frames;
        if (length > 1 && tokens[1][length - 1] == 's') {
            tokens[1][length - 1] = '\0';
            double seconds;
            if (!parse_number(p, tokens[1], "the wait in seconds", &seconds)) return false;
            if (seconds < 0 || seconds > 3600) {
                return fail(p, "the wait must be between 0 and 3600 seconds, got %g", seconds);
            }
            frames = lround(seconds * 60.0);
        } else if (!parse_integer(p, tokens[1], "the wait in frames", 0, 216000, &frames)) {
            return false;
        }
        add_wait(p, frames);
        return true;
    }
    if (strcmp(command, "key") == 0 || strcmp(command, "keydown") == 0 ||
        strcmp(command, "keyup") == 0) {
        if (n != 2) return fail(p, "'%s' needs one key name", command);
        SDL_Keycode key = SDLK_UNKNOWN;
        Uint16 mod = KMOD_NONE;
        if (!parse_key(p, tokens[1], &key, &mod)) return false;
        mod |= modifier_of(key);
        if (strcmp(command, "keyup") == 0) {
            add_key(p, ACT_KEY_UP, key, KMOD_NONE);
        } else {
            add_key(p, ACT_KEY_DOWN, key, mod);
            if (strcmp(command, "key") == 0) add_key(p, ACT_KEY_UP, key, KMOD_NONE);
        }
        return true;
    }
    if (strcmp(command, "move") == 0 || strcmp(command, "click") == 0) {
        if (!parse_points(p, command, tokens, n, &at, 1, &pixels, points)) return false;
        if (!no_more(p, command, n, at)) return false;
        add_move(p, pixels, points[0]);
        if (strcmp(command, "click") == 0) {
            add_button(p, ACT_BUTTON_DOWN, SDL_BUTTON_LEFT, true, pixels, points[0]);
            add_button(p, ACT_BUTTON_UP, SDL_BUTTON_LEFT, true, pixels, points[0]);
        }
        return true;
    }
    if (strcmp(command, "press") == 0 || strcmp(command, "release") == 0) {
        if (n < 2) return fail(p, "'%s' needs a button: left, right or middle", command);
        Uint8 button;
        if (!parse_button(p, tokens[1], &button)) return false;
        at = 2;
        bool is_press = strcmp(command, "press") == 0;
        if (!is_press && n == 2) {
            add_button(p, ACT_BUTTON_UP, button, false, false, VEC_ZERO);
            return true;
        }
        if (!parse_points(p, command, tokens, n, &at, 1, &pixels, points)) return false;
        if (!no_more(p, command, n, at)) return false;
        add_move(p, pixels, points[0]);
        add_button(p, is_press ? ACT_BUTTON_DOWN : ACT_BUTTON_UP, button, true, pixels, points[0]);
        return true;
    }
    if (strcmp(command, "drag") == 0 || strcmp(command, "throw") == 0 ||
        strcmp(command, "grab") == 0) {
        Uint8 button = strcmp(command, "grab") == 0 ? SDL_BUTTON_RIGHT : SDL_BUTTON_LEFT;
        if (strcmp(command, "drag") == 0) {
            if (n < 2) return fail(p, "'drag' needs a button: left, right or middle");
            if (!parse_button(p, tokens[1], &button)) return false;
            at = 2;
        }
        long frames;
        if (!parse_points(p, command, tokens, n, &at, 2, &pixels, points)) return false;
        if (!parse_drag_frames(p, tokens, n, &at, &frames)) return false;
        if (!no_more(p, command, n, at)) return false;
        bool shift = strcmp(command, "throw") == 0;
        if (shift) add_key(p, ACT_KEY_DOWN, SDLK_LSHIFT, KMOD_LSHIFT);
        add_drag(p, button, pixels, points[0], points[1], frames);
        if (shift) add_key(p, ACT_KEY_UP, SDLK_LSHIFT, KMOD_NONE);
        return true;
    }
    if (strcmp(command, "wheel") == 0) {
        long notches;
        if (n != 2) return fail(p, "'wheel' needs one whole number of notches");
        if (!parse_integer(p, tokens[1], "the wheel notches", -100, 100, &notches)) return false;
        add(p, ACT_WHEEL)->count = notches;
        return true;
    }
    if (strcmp(command, "spawn") == 0) {
        long count;
        double size = 0.2;
        if (n < 2 || n > 3) return fail(p, "'spawn' needs a count and optionally a size");
        if (!parse_integer(p, tokens[1], "the spawn count", 1, 20000, &count)) return false;
        if (n == 3) {
            if (!parse_number(p, tokens[2], "the spawn size", &size)) return false;
            if (size < SHAPE_MIN_SIZE || size > SHAPE_MAX_SIZE) {
                return fail(p, "the spawn size must be between %g and %g m, got %g",
                            SHAPE_MIN_SIZE, SHAPE_MAX_SIZE, size);
            }
        }
        action_t *a = add(p, ACT_SPAWN);
        a->count = count;
        a->size = size;
        return true;
    }
    if (strcmp(command, "screenshot") == 0) {
        if (n != 2) return fail(p, "'screenshot' needs one file name (no spaces)");
        if (video_format_of(tokens[1]) == VIDEO_FORMAT_NONE) {
            return fail(p, "screenshot '%s': %s", tokens[1], VIDEO_FORMAT_HINT);
        }
        action_t *a = add(p, ACT_SCREENSHOT);
        a->path = malloc(strlen(tokens[1]) + 1);
        if (a->path == NULL) return fail(p, "out of memory");
        strcpy(a->path, tokens[1]);
        return true;
    }
    if (strcmp(command, "open") == 0) {
        if (n != 2) return fail(p, "'open' needs one file name (no spaces)");
        action_t *a = add(p, ACT_OPEN);
        a->path = malloc(strlen(tokens[1]) + 1);
        if (a->path == NULL) return fail(p, "out of memory");
        strcpy(a->path, tokens[1]);
        return true;
    }
    if (strcmp(command, "resize") == 0) {
        long width, height;
        if (n != 3) return fail(p, "'resize' needs a width and a height in pixels");
        if (!parse_integer(p, tokens[1], "the width", 1, 8192, &width) ||
            !parse_integer(p, tokens[2], "the height", 1, 8192, &height)) {
            return false;
        }
        action_t *a = add(p, ACT_RESIZE);
        a->position = (vector_t){(double)width, (double)height};
        return true;
    }
    if (strcmp(command, "quit") == 0) {
        if (n != 1) return fail(p, "'quit' takes no arguments");
        add(p, ACT_QUIT);
        return true;
    }
    if (strcmp(command, "log") == 0) {
        bool bodies = n == 2 && strcmp(tokens[1], "bodies") == 0;
        if (n > 2 || (n == 2 && !bodies)) return fail(p, "'log' takes nothing or the word bodies");
        add(p, ACT_LOG)->count = bodies;
        return true;
    }
    return fail(p, "unknown command '%s' (expected wait, key, keydown, keyup, move, click, "
                   "press, release, drag, throw, grab, wheel, spawn, open, resize, screenshot, "
                   "log or quit)",
                command);
}

script_t *script_parse(const char *name, const char *text, char *error, size_t error_size) {
    script_t *script = calloc(1, sizeof(script_t));
    if (script == NULL) {
        snprintf(error, error_size, "%s: out of memory", name);
        return NULL;
    }
    parser_t p = {name, 0, error, error_size, script};
    const char *cursor = text;
    while (*cursor != '\0') {
        p.line++;
        const char *end = strchr(cursor, '\n');
        size_t length = end ? (size_t)(end - cursor) : strlen(cursor);
        char line[1024];
        if (length >= sizeof(line)) {
            fail(&p, "line too long (over %zu characters)", sizeof(line) - 1);
            script_free(script);
            return NULL;
        }
        memcpy(line, cursor, length);
        line[length] = '\0';
        cursor = end ? end + 1 : cursor + length;

        char *hash = strchr(line, '#');
        if (hash != NULL) *hash = '\0';
        char *tokens[MAX_TOKENS];
        int n = 0;
        bool too_many = false;
        for (char *token = strtok(line, " \t\r"); token != NULL; token = strtok(NULL, " \t\r")) {
            if (n == MAX_TOKENS) {
                too_many = true;
                break;
            }
            tokens[n++] = token;
        }
        if (too_many) {
            fail(&p, "too many words on one line");
            script_free(script);
            return NULL;
        }
        if (n == 0) continue;
        if (!parse_line(&p, tokens, n)) {
            script_free(script);
            return NULL;
        }
    }
    return script;
}

script_t *script_load(const char *path, char *error, size_t error_size) {
    /* fopen opens a directory on Linux, and reading it fails without a word. */
    struct stat info;
    if (stat(path, &info) == 0 && S_ISDIR(info.st_mode)) {
        snprintf(error, error_size, "cannot read script '%s': it is a directory, not a file",
                 path);
        return NULL;
    }
    FILE *file = fopen(path, "rb");
    if (file == NULL) {
        snprintf(error, error_size, "cannot open script '%s': %s", path, strerror(errno));
        return NULL;
    }
    size_t capacity = 4096, length = 0;
    char *text = malloc(capacity);
    size_t got;
    while (text != NULL && (got = fread(text + length, 1, capacity - length - 1, file)) > 0) {
        length += got;
        if (length + 1 == capacity) {
            if (capacity > (64u << 20)) {
                snprintf(error, error_size, "script '%s' is too large (over 64 MB)", path);
                free(text);
                fclose(file);
                return NULL;
            }
            char *grown = realloc(text, 2 * capacity);
            if (grown == NULL) {
                free(text);
                text = NULL;
                break;
            }
            text = grown;
            capacity *= 2;
        }
    }
    int read_errno = ferror(file) ? errno : 0;
    fclose(file);
    if (text == NULL || read_errno != 0) {
        snprintf(error, error_size, "cannot read script '%s': %s", path,
                 text == NULL ? "out of memory" : strerror(read_errno));
        free(text);
        return NULL;
    }
    text[length] = '\0';
    if (memchr(text, '\0', length) != NULL) {
        snprintf(error, error_size, "script '%s' is not a text file (it holds NUL bytes)", path);
        free(text);
        return NULL;
    }
    script_t *script = script_parse(path, text, error, error_size);
    free(text);
    return script;
}

void script_free(script_t *script) {
    if (script == NULL) return;
    for (size_t i = 0; i < script->count; i++) free(script->actions[i].path);
    free(script->actions);
    free(script);
}

bool script_done(const script_t *script) {
    return script->next >= script->count && script->waiting == 0;
}

static vector_t pixel_of(const app_t *app, const action_t *a) {
    if (!a->has_position) return app->mouse;
    vector_t p = a->pixels ? a->position : camera_to_pixel(&app->camera, a->position);
    return (vector_t){round(p.x), round(p.y)};
}

static int to_int(double pixel) {
    return pixel > 30000 ? 30000 : pixel < -30000 ? -30000 : (int)pixel;
}

static void run_action(const action_t *a, app_t *app, const char **screenshot) {
    SDL_Event event;
    SDL_zero(event);
    Uint32 timestamp = (Uint32)(app->now * 1000.0);
    switch (a->kind) {
    case ACT_WAIT:
        break;
    case ACT_KEY_DOWN:
    case ACT_KEY_UP:
        event.type = a->kind == ACT_KEY_DOWN ? SDL_KEYDOWN : SDL_KEYUP;
        event.key.timestamp = timestamp;
        event.key.state = a->kind == ACT_KEY_DOWN ? SDL_PRESSED : SDL_RELEASED;
        event.key.keysym.sym = a->key;
        event.key.keysym.scancode = SDL_GetScancodeFromKey(a->key);
        event.key.keysym.mod = a->mod;
        input_handle_event(app, &event);
        break;
    case ACT_MOVE: {
        vector_t p = pixel_of(app, a);
        event.type = SDL_MOUSEMOTION;
        event.motion.timestamp = timestamp;
        event.motion.x = to_int(p.x);
        event.motion.y = to_int(p.y);
        event.motion.xrel = to_int(p.x - app->mouse.x);
        event.motion.yrel = to_int(p.y - app->mouse.y);
        input_handle_event(app, &event);
        break;
    }
    case ACT_BUTTON_DOWN:
    case ACT_BUTTON_UP: {
        vector_t p = pixel_of(app, a);
        event.type = a->kind == ACT_BUTTON_DOWN ? SDL_MOUSEBUTTONDOWN : SDL_MOUSEBUTTONUP;
        event.button.timestamp = timestamp;
        event.button.button = a->button;
        event.button.state = a->kind == ACT_BUTTON_DOWN ? SDL_PRESSED : SDL_RELEASED;
        event.button.clicks = 1;
        event.button.x = to_int(p.x);
        event.button.y = to_int(p.y);
        input_handle_event(app, &event);
        break;
    }
    case ACT_WHEEL:
        event.type = SDL_MOUSEWHEEL;
        event.wheel.timestamp = timestamp;
        event.wheel.y = (Sint32)a->count;
        event.wheel.direction = SDL_MOUSEWHEEL_NORMAL;
        input_handle_event(app, &event);
        break;
    case ACT_SPAWN:
        sandbox_spawn(&app->sandbox, (size_t)a->count, a->size, app->elasticity);
        break;
    case ACT_SCREENSHOT:
        *screenshot = a->path;
        break;
    case ACT_OPEN:
        /* The event a file dropped on the window makes; its handler frees
         * the name. */
        event.type = SDL_DROPFILE;
        event.drop.timestamp = timestamp;
        event.drop.file = SDL_strdup(a->path);
        input_handle_event(app, &event);
        break;
    case ACT_RESIZE:
        app->resize_width = (int)a->position.x;
        app->resize_height = (int)a->position.y;
        break;
    case ACT_LOG:
        state_log_print(stdout, &app->sandbox, (unsigned long)app->timing.frames, a->count != 0);
        break;
    case ACT_QUIT:
        app->quit = true;
        break;
    }
}

void script_frame(script_t *script, app_t *app, const char **screenshot) {
    *screenshot = NULL;
    if (script->waiting > 0) {
        script->waiting--;
        if (script->waiting > 0) return;
    }
    while (script->next < script->count) {
        const action_t *a = &script->actions[script->next++];
        if (a->kind == ACT_WAIT) {
            script->waiting = a->count;
            return;
        }
        run_action(a, app, screenshot);
        /* One screenshot per frame: the rest waits for the next frame. */
        if (a->kind == ACT_SCREENSHOT || app->quit) return;
    }
}
