#include "base/workers.h"
#include <pthread.h>
#include <sched.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>
#include "base/check.h"
#include "base/memory.h"

/* Chunks per thread: enough that a thread slowed by other work on the
 * machine leaves its share to the others, few enough that taking a chunk
 * costs nothing next to running it. */
static const size_t CHUNKS_PER_WORKER = 8;
/* Each chunk gets at least this many indices: waking the threads for a
 * loop over a handful (the static bodies of a scene whose every other body
 * sleeps) cost more than the loop, ten times an all-asleep step's time. */
static const size_t MIN_CHUNK = 8;
/* A waiting thread spins this many pauses (each a few tens of cycles:
 * about the gap between two loops of a step), then yields the processor
 * this many times (about a millisecond when nothing else wants it: the
 * longest stretches a step runs on the calling thread alone, so a worker is
 * rarely woken from sleep within a step; pile(10000) on 2 workers took 0.70
 * of one worker's time with 128 yields, 0.64 with 2048), in case a thread
 * of the pool waits for it to run (the machine may have fewer free cores
 * than threads), and then a parked thread sleeps until the next call. */
static const unsigned SPINS = 1u << 11;
static const unsigned YIELDS_BEFORE_SLEEP = 1u << 11;

/*
 * The call in progress is published in `state`: its number in the high 32
 * bits, CLOSED once the caller has finished taking chunks, and in the low
 * bits how many threads joined it. A thread joins by a compare-and-swap
 * that fails once the call is closed or replaced, so the caller knows
 * exactly whom to wait for, and a thread that wakes late never runs a
 * chunk of the next call with this call's function.
 */
static const uint64_t CLOSED = (uint64_t)1 << 31;
static const uint64_t JOINED = CLOSED - 1;

/* The chunks a thread takes first: from `next` up to `end`, by a counter
 * on a line of its own; once they are gone it takes what is left of the
 * others' shares. */
typedef struct {
    _Alignas(64) atomic_size_t next;
    size_t end;
} share_t;

typedef struct {
    pthread_t thread;
    workers_t *workers;
    size_t index; /* its share; the caller's is 0 */
} thread_t;

struct workers {
    size_t count;
    thread_t *threads;
    size_t started;

    /* The call: written by the caller before `state` publishes it. */
    workers_fn_t fn;
    void *context;
    size_t total, chunks;
    share_t *shares; /* one per thread */
    atomic_size_t finished; /* joined threads that have left the call */
    _Atomic uint64_t state;

    pthread_mutex_t lock;
    pthread_cond_t wake;
    atomic_size_t sleepers;
    atomic_bool quit;
};

static inline void pause_briefly(void) {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

/* One turn of a wait on another thread: a pause, or later a yield. */
static void wait_turn(unsigned spin) {
    if (spin < SPINS) {
        pause_briefly();
    } else {
        sched_yield();
    }
}

static uint32_t call_number(uint64_t state) {
    return (uint32_t)(state >> 32);
}

/* Takes and runs chunks of the current call until none is left: its own
 * share first, then the others'. A thread that runs the same chunks of
 * each loop over the bodies finds their lines in its own cache, where
 * taking the next free chunk left half of them in the other core's (two
 * workers ran body_update_world in twice one worker's CPU time). */
static void run_chunks(workers_t *workers, size_t self) {
    for (size_t k = 0; k < workers->count; k++) {
        share_t *share = &workers->shares[(self + k) % workers->count];
        for (;;) {
            size_t chunk = atomic_fetch_add_explicit(&share->next, 1, memory_order_relaxed);
            if (chunk >= share->end) break;
            size_t begin = chunk * workers->total / workers->chunks;
            size_t end = (chunk + 1) * workers->total / workers->chunks;
            workers->fn(workers->context, chunk, begin, end);
        }
    }
}

/* Waits until a call newer than `seen` is published (or the pool stops);
 * returns its state. */
static uint64_t await_call(workers_t *workers, uint32_t seen) {
    for (unsigned spin = 0; spin < SPINS + YIELDS_BEFORE_SLEEP; spin++) {
        uint64_t state = atomic_load(&workers->state);
        if (call_number(state) != seen || atomic_load(&workers->quit)) return state;
        wait_turn(spin);
    }
    pthread_mutex_lock(&workers->lock);
    atomic_fetch_add(&workers->sleepers, 1);
    uint64_t state = atomic_load(&workers->state);
    while (call_number(state) == seen && !atomic_load(&workers->quit)) {
        pthread_cond_wait(&workers->wake, &workers->lock);
        state = atomic_load(&workers->state);
    }
    atomic_fetch_sub(&workers->sleepers, 1);
    pthread_mutex_unlock(&workers->lock);
    return state;
}

static void *thread_main(void *argument) {
    const thread_t *self = argument;
    workers_t *workers = self->workers;
    uint32_t seen = 0;
    for (;;) {
        uint64_t state = await_call(workers, seen);
        if (atomic_load(&workers->quit)) return NULL;
        seen = call_number(state);
        /* Join unless the caller has closed the call already. */
        while (!(state & CLOSED) && call_number(state) == seen) {
            if (atomic_compare_exchange_weak(&workers->state, &state, state + 1)) {
                run_chunks(workers, self->index);
                atomic_fetch_add_explicit(&workers->finished, 1, memory_order_release);
                break;
            }
        }
    }
}

workers_t *workers_init(size_t count) {
    REQUIRE(count >= 2, "a pool needs at least 2 workers (got %zu)", count);
    workers_t *workers = memory_calloc(1, sizeof(workers_t));
    workers->count = count;
    workers->threads = memory_calloc(count - 1, sizeof(thread_t));
    size_t share_capacity = 0; /* on lines of their own */
    memory_reserve_lines((void **)&workers->shares, &share_capacity, count, sizeof(share_t));
    pthread_mutex_init(&workers->lock, NULL);
    pthread_cond_init(&workers->wake, NULL);
    for (size_t i = 0; i < count; i++) atomic_init(&workers->shares[i].next, 0);
    atomic_init(&workers->finished, 0);
    atomic_init(&workers->state, 0);
    atomic_init(&workers->sleepers, 0);
    atomic_init(&workers->quit, false);
    return workers;
}

static void start_threads(workers_t *workers) {
    for (; workers->started < workers->count - 1; workers->started++) {
        thread_t *thread = &workers->threads[workers->started];
        thread->workers = workers;
        thread->index = workers->started + 1;
        int error = pthread_create(&thread->thread, NULL, thread_main, thread);
        REQUIRE(error == 0, "cannot start a worker thread (%s)", strerror(error));
    }
}

void workers_free(workers_t *workers) {
    if (workers == NULL) return;
    pthread_mutex_lock(&workers->lock);
    atomic_store(&workers->quit, true);
    pthread_cond_broadcast(&workers->wake);
    pthread_mutex_unlock(&workers->lock);
    for (size_t i = 0; i < workers->started; i++) pthread_join(workers->threads[i].thread, NULL);
    pthread_cond_destroy(&workers->wake);
    pthread_mutex_destroy(&workers->lock);
    memory_free(workers->threads);
    memory_free(workers->shares);
    memory_free(workers);
}

size_t workers_count(const workers_t *workers) {
    return workers->count;
}

size_t workers_chunks(const workers_t *workers, size_t count) {
    if (workers == NULL) return count < 1 ? count : 1;
    size_t chunks = workers->count * CHUNKS_PER_WORKER;
    if (chunks > WORKERS_MAX_CHUNKS) chunks = WORKERS_MAX_CHUNKS;
    size_t most = count / MIN_CHUNK > 1 ? count / MIN_CHUNK : (count < 1 ? count : 1);
    return most < chunks ? most : chunks;
}

/* Publishes the call and wakes the threads that sleep. The caller's store
 * of state and a parking thread's count of sleepers are both sequentially
 * consistent, so either the caller sees the sleeper or the sleeper sees
 * the call. */
static void publish(workers_t *workers) {
    uint64_t state = atomic_load_explicit(&workers->state, memory_order_relaxed);
    atomic_store(&workers->state, (uint64_t)(call_number(state) + 1) << 32);
    if (atomic_load(&workers->sleepers) > 0) {
        pthread_mutex_lock(&workers->lock);
        pthread_cond_broadcast(&workers->wake);
        pthread_mutex_unlock(&workers->lock);
    }
}

/* Closes the call to latecomers and waits for the threads that joined it. */
static void finish(workers_t *workers) {
    uint64_t state = atomic_fetch_or(&workers->state, CLOSED);
    size_t joined = (size_t)(state & JOINED);
    for (unsigned spin = 0; atomic_load_explicit(&workers->finished, memory_order_acquire) < joined;
         spin++) {
        wait_turn(spin);
    }
}

/* Runs fn over [0, count) in `chunks` chunks (at least 2) on the pool. */
static void run_call(workers_t *workers, size_t count, size_t chunks, workers_fn_t fn,
                     void *context) {
    start_threads(workers);
    workers->fn = fn;
    workers->context = context;
    workers->total = count;
    workers->chunks = chunks;
    for (size_t t = 0; t < workers->count; t++) {
        atomic_store_explicit(&workers->shares[t].next, t * chunks / workers->count,
                              memory_order_relaxed);
        workers->shares[t].end = (t + 1) * chunks / workers->count;
    }
    atomic_store_explicit(&workers->finished, 0, memory_order_relaxed);
    publish(workers);
    run_chunks(workers, 0);
    finish(workers);
}

void workers_for(workers_t *workers, size_t count, workers_fn_t fn, void *context) {
    size_t chunks = workers_chunks(workers, count);
    if (chunks <= 1) {
        if (count > 0) fn(context, 0, 0, count);
        return;
    }
    run_call(workers, count, chunks, fn, context);
}

void workers_each(workers_t *workers, size_t count, workers_fn_t fn, void *context) {
    REQUIRE(count <= WORKERS_MAX_CHUNKS, "at most %d items (got %zu)", WORKERS_MAX_CHUNKS, count);
    if (workers == NULL || count <= 1) {
        for (size_t i = 0; i < count; i++) fn(context, i, i, i + 1);
        return;
    }
    run_call(workers, count, count, fn, context);
}
