#ifndef WORKERS_H
#define WORKERS_H

/*
 * A small pool of threads for the world's parallel loops (scene_set_workers).
 * workers_for splits [0, count) into fixed chunks, a function of count and
 * the worker count alone, and runs them on the calling thread and the
 * pool's threads together; it returns when every chunk is done, and what
 * the chunks wrote is then visible to the caller. Each thread has a share
 * of the chunks, the same in every call with as many chunks (the caller the
 * first, thread i the i-th), and takes the rest of the others' once its own
 * are done: loops over the same indices then find their data in the same
 * core's cache. Which thread runs a chunk still varies, so a chunk must
 * write only what its own indices decide (never a sum over chunks in
 * floating point): then the result is the same for any worker count.
 *
 * The threads are started on the first workers_for and parked between
 * calls: they spin for a few microseconds (the world's loops come in quick
 * succession within a step) and then sleep on a condition variable until
 * the next call. A call allocates nothing.
 */

#include <stddef.h>

typedef struct workers workers_t;

/* The most chunks a call makes, whatever count is. */
enum { WORKERS_MAX_CHUNKS = 64 };

/* Runs indices [begin, end), chunk `chunk` of the call. */
typedef void (*workers_fn_t)(void *context, size_t chunk, size_t begin, size_t end);

/* A pool for `count` threads of work (count >= 2): the caller and count - 1
 * threads, started lazily. */
workers_t *workers_init(size_t count);
/* Stops and joins the threads; NULL is allowed. */
void workers_free(workers_t *workers);

size_t workers_count(const workers_t *workers);

/* How many chunks workers_for makes of count indices: chunk k is
 * [k count / n, (k + 1) count / n), n = workers_chunks(workers, count),
 * each of at least a few indices (one chunk for a handful). Without a pool
 * (workers NULL) that is one chunk, none for count 0. */
size_t workers_chunks(const workers_t *workers, size_t count);

/* Runs fn over the chunks of [0, count) in parallel; with workers NULL, on
 * the calling thread as chunk 0 (not at all for count 0). Not reentrant:
 * fn must not call workers_for on the same pool. */
void workers_for(workers_t *workers, size_t count, workers_fn_t fn, void *context);

/* Runs fn on each index of [0, count) as a chunk of its own (chunk i is
 * [i, i + 1)), in parallel: for a few heavy items, such as the
 * broadphase's parts, which workers_for's least chunk would run on the
 * calling thread alone. count <= WORKERS_MAX_CHUNKS (asserted); with
 * workers NULL, one after the other on the calling thread. Not reentrant,
 * as workers_for. */
void workers_each(workers_t *workers, size_t count, workers_fn_t fn, void *context);

#endif // #ifndef WORKERS_H
