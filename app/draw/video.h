#ifndef SANDBOX_VIDEO_H
#define SANDBOX_VIDEO_H

/*
 * Where frames go. By default every frame is drawn by SDL's software
 * renderer into a canvas surface of our own, which is copied to the window
 * (or, --headless, to nothing: SDL's dummy video driver, no window at all).
 * With --gpu the window gets SDL's accelerated renderer instead and there is
 * no canvas.
 */

#include <SDL.h>
#include <stdbool.h>

typedef struct {
    SDL_Window *window;     /* NULL when headless */
    SDL_Renderer *renderer;
    SDL_Surface *canvas;    /* the software renderer's target (32 bits a pixel); NULL with --gpu */
    bool vsync;             /* presenting waits for the display */
    double refresh_hz;      /* the display's refresh rate (60 when unknown) */
    int width, height;      /* output size in pixels */
} video_t;

/* Opens the output; false (with a message on stderr) when it cannot. */
bool video_open(video_t *video, bool headless, bool gpu, bool vsync, int width, int height);

/* Follows the window's size; true when the output size changed. A window
 * made smaller than LAYOUT_MIN_WIDTH x LAYOUT_MIN_HEIGHT (which a window
 * manager would refuse, but there may be none) is grown back to it. */
bool video_sync_size(video_t *video);

/* Asks for an output of width x height pixels (the script's `resize`), at
 * least the minimum: a window is resized as a person would resize it, and
 * video_sync_size follows at a later frame; headless, the canvas is made
 * anew at once. True when the output size changed now. */
bool video_request_size(video_t *video, int width, int height);

/* The file formats a screenshot can be saved in, told by the file name's
 * extension (.png or .bmp, any case). */
typedef enum { VIDEO_FORMAT_NONE = 0, VIDEO_FORMAT_PNG, VIDEO_FORMAT_BMP } video_format_t;
video_format_t video_format_of(const char *path);

/* What the command line and the script say when a file name's extension is
 * not one of them. */
#define VIDEO_FORMAT_HINT "the file name must end in .png or .bmp"

/* Saves the frame drawn so far (call before video_present) as a PNG or a BMP
 * by the file name's extension; false, with a message on stderr, when it
 * cannot. */
bool video_screenshot(video_t *video, const char *path);

/* Shows the frame. */
void video_present(video_t *video);

void video_close(video_t *video);

#endif
