#include "test.h"
#include "jostle/jostle.h"
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define HAVE_LEAK_CHECK 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define HAVE_LEAK_CHECK 1
#endif
#endif
#ifdef HAVE_LEAK_CHECK
#include <sanitizer/lsan_interface.h>
#endif

int test_failures = 0;

bool test_no_leaks(void) {
#ifdef HAVE_LEAK_CHECK
    return __lsan_do_recoverable_leak_check() == 0;
#else
    return true;
#endif
}

bool test_warm_ticks_allocate_nothing(scene_t *scene, int ticks, double dt) {
    (void)scene_contact_count(scene);
    size_t before = engine_allocation_count();
    bool contacts = true;
    for (int i = 0; i < ticks; i++) {
        scene_tick(scene, dt);
        contacts &= scene_contact_count(scene) > 0;
    }
    return contacts && engine_allocation_count() == before;
}

list_t *test_make_polygon(const vector_t *points, size_t n) {
    list_t *polygon = list_init(n, free);
    for (size_t i = 0; i < n; i++) {
        vector_t *v = malloc(sizeof *v);
        *v = points[i];
        list_add(polygon, v);
    }
    return polygon;
}

void test_fail(const char *file, int line, const char *format, ...) {
    va_list args;
    va_start(args, format);
    printf("    %s:%d: ", file, line);
    vprintf(format, args);
    printf("\n");
    va_end(args);
    fflush(stdout);
    test_failures++;
}

/* Reads everything from fd into a heap string. */
static char *read_all(int fd) {
    size_t size = 0, capacity = 4096;
    char *text = malloc(capacity);
    ssize_t got;
    while ((got = read(fd, text + size, capacity - size - 1)) > 0) {
        size += (size_t)got;
        if (capacity - size < 2) text = realloc(text, capacity *= 2);
    }
    text[size] = '\0';
    return text;
}

bool test_dies_with(void (*function)(void *), void *argument, const char *const *substrings,
                    size_t count) {
    int pipe_fds[2];
    if (pipe(pipe_fds) != 0) return false;
    fflush(stdout);
    fflush(stderr);
    pid_t child = fork();
    if (child == 0) {
        dup2(pipe_fds[1], STDERR_FILENO);
        close(pipe_fds[0]);
        function(argument);
        _exit(0); /* returned normally: that is the failure */
    }
    close(pipe_fds[1]);
    char *message = read_all(pipe_fds[0]);
    close(pipe_fds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    bool died = WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT;
    bool named = true;
    for (size_t i = 0; i < count; i++) named = named && strstr(message, substrings[i]) != NULL;
    if (!died || !named) {
        printf("    expected an abort mentioning:");
        for (size_t i = 0; i < count; i++) printf(" \"%s\"", substrings[i]);
        printf("\n    got %s with stderr: %s\n", died ? "an abort" : "no abort", message);
    }
    free(message);
    return died && named;
}

static bool run_one(const test_case_t *test) {
    fflush(stdout);
    pid_t child = fork();
    if (child == 0) {
        test_failures = 0;
        test->run();
        fflush(stdout);
        _exit(test_failures == 0 ? 0 : 1);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (WIFSIGNALED(status)) {
        printf("    crashed with signal %d\n", WTERMSIG(status));
        return false;
    }
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

int test_run_suites(const test_suite_t *const *suites, size_t count, const char *filter) {
    size_t passed = 0, failed = 0;
    char full_name[256];
    for (size_t s = 0; s < count; s++) {
        for (size_t t = 0; t < suites[s]->count; t++) {
            const test_case_t *test = &suites[s]->cases[t];
            snprintf(full_name, sizeof full_name, "%s.%s", suites[s]->name, test->name);
            if (filter != NULL && strstr(full_name, filter) == NULL) continue;
            bool ok = run_one(test);
            printf("%s %s\n", ok ? "PASS" : "FAIL", full_name);
            fflush(stdout);
            if (ok) {
                passed++;
            } else {
                failed++;
            }
        }
    }
    printf("%zu passed, %zu failed\n", passed, failed);
    return failed == 0 ? 0 : 1;
}
