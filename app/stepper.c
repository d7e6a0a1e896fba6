#include "stepper.h"
#include <SDL.h>
#include <stdlib.h>

struct stepper {
    app_t *app;
    SDL_Thread *thread;     /* NULL: steps run in stepper_begin */
    SDL_sem *go, *done;
    int steps;
    bool quit;
    double seconds;
};

static double run_timed(app_t *app, int steps) {
    Uint64 start = SDL_GetPerformanceCounter();
    app_run_steps(app, steps);
    return (double)(SDL_GetPerformanceCounter() - start) / (double)SDL_GetPerformanceFrequency();
}

static int worker(void *data) {
    stepper_t *stepper = data;
    for (;;) {
        SDL_SemWait(stepper->go);
        if (stepper->quit) break;
        stepper->seconds = run_timed(stepper->app, stepper->steps);
        SDL_SemPost(stepper->done);
    }
    return 0;
}

stepper_t *stepper_start(app_t *app) {
    stepper_t *stepper = calloc(1, sizeof(stepper_t));
    if (stepper == NULL) return NULL;
    stepper->app = app;
    stepper->go = SDL_CreateSemaphore(0);
    stepper->done = SDL_CreateSemaphore(0);
    if (stepper->go != NULL && stepper->done != NULL) {
        stepper->thread = SDL_CreateThread(worker, "physics", stepper);
    }
    return stepper;
}

void stepper_begin(stepper_t *stepper, int steps) {
    stepper->steps = steps;
    if (stepper->thread == NULL) {
        stepper->seconds = run_timed(stepper->app, steps);
        return;
    }
    SDL_SemPost(stepper->go);
}

double stepper_finish(stepper_t *stepper) {
    if (stepper->thread != NULL) SDL_SemWait(stepper->done);
    return stepper->seconds;
}

void stepper_stop(stepper_t *stepper) {
    if (stepper == NULL) return;
    if (stepper->thread != NULL) {
        stepper->quit = true;
        SDL_SemPost(stepper->go);
        SDL_WaitThread(stepper->thread, NULL);
    }
    if (stepper->go) SDL_DestroySemaphore(stepper->go);
    if (stepper->done) SDL_DestroySemaphore(stepper->done);
    free(stepper);
}
