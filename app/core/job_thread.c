#include "core/job_thread.h"
#include <SDL.h>
#include <stdbool.h>
#include <stdlib.h>

struct job_thread {
    SDL_Thread *thread;
    SDL_sem *go, *done;
    job_fn_t fn;
    void *context;
    bool quit;
};

static int thread_main(void *data) {
    job_thread_t *job = data;
    for (;;) {
        SDL_SemWait(job->go);
        if (job->quit) return 0;
        job->fn(job->context);
        SDL_SemPost(job->done);
    }
}

job_thread_t *job_thread_start(const char *name) {
    job_thread_t *job = calloc(1, sizeof(job_thread_t));
    if (job == NULL) return NULL;
    job->go = SDL_CreateSemaphore(0);
    job->done = SDL_CreateSemaphore(0);
    if (job->go != NULL && job->done != NULL) {
        job->thread = SDL_CreateThread(thread_main, name, job);
    }
    if (job->thread == NULL) {
        job_thread_stop(job);
        return NULL;
    }
    return job;
}

void job_thread_begin(job_thread_t *job, job_fn_t fn, void *context) {
    job->fn = fn;
    job->context = context;
    SDL_SemPost(job->go);
}

void job_thread_finish(job_thread_t *job) {
    SDL_SemWait(job->done);
}

void job_thread_stop(job_thread_t *job) {
    if (job == NULL) return;
    if (job->thread != NULL) {
        job->quit = true;
        SDL_SemPost(job->go);
        SDL_WaitThread(job->thread, NULL);
    }
    if (job->go != NULL) SDL_DestroySemaphore(job->go);
    if (job->done != NULL) SDL_DestroySemaphore(job->done);
    free(job);
}
