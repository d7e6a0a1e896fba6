#include "core/stepper.h"
#include <SDL.h>
#include <stdlib.h>
#include "core/job_thread.h"

struct stepper {
    app_t *app;
    job_thread_t *thread; /* NULL: steps run in stepper_begin */
    int steps;
    double seconds;
};

static void run_timed(void *context) {
    stepper_t *stepper = context;
    Uint64 start = SDL_GetPerformanceCounter();
    app_run_steps(stepper->app, stepper->steps);
    stepper->seconds =
        (double)(SDL_GetPerformanceCounter() - start) / (double)SDL_GetPerformanceFrequency();
}

stepper_t *stepper_start(app_t *app) {
    stepper_t *stepper = calloc(1, sizeof(stepper_t));
    if (stepper == NULL) return NULL;
    stepper->app = app;
    stepper->thread = job_thread_start("physics");
    return stepper;
}

void stepper_begin(stepper_t *stepper, int steps) {
    stepper->steps = steps;
    if (stepper->thread == NULL) {
        run_timed(stepper);
        return;
    }
    job_thread_begin(stepper->thread, run_timed, stepper);
}

double stepper_finish(stepper_t *stepper) {
    if (stepper->thread != NULL) job_thread_finish(stepper->thread);
    return stepper->seconds;
}

void stepper_stop(stepper_t *stepper) {
    if (stepper == NULL) return;
    job_thread_stop(stepper->thread);
    free(stepper);
}
