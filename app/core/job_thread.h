#ifndef SANDBOX_JOB_THREAD_H
#define SANDBOX_JOB_THREAD_H

/*
 * A thread that runs one job at a time for its owner: the owner begins a
 * job, does its own work meanwhile, then waits for the job. The physics
 * thread (stepper.c) and the second drawing thread (raster.c) are both
 * one. Memory written before job_thread_begin is seen by the job, and what
 * the job wrote is seen after job_thread_finish.
 */

typedef struct job_thread job_thread_t;
typedef void (*job_fn_t)(void *context);

/* Starts a thread called `name` (for debuggers); NULL when SDL cannot. */
job_thread_t *job_thread_start(const char *name);

/* Runs fn(context) on the thread and returns at once; the job begun before
 * must have been finished. */
void job_thread_begin(job_thread_t *thread, job_fn_t fn, void *context);

/* Waits until the job begun last is done. */
void job_thread_finish(job_thread_t *thread);

/* Ends the thread (NULL is fine); no job may be running. */
void job_thread_stop(job_thread_t *thread);

#endif
