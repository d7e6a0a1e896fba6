/*
 * The canonical scenes (bench_scenes.h) on this project's engine, through its
 * public API only: cc -O2 -Iengine/include bench_engine.c build/libjostle.a -lm.
 * The engine's variants and settings are in bench_ours.h.
 *
 * Besides bench_scenes.h's options: --integrator NAME (seed,
 * explicit-euler, symplectic-euler, velocity-verlet, rk4, symplectic4,
 * implicit-euler)
 * runs every variant but ours-symplectic with that integrator; --workers N
 * (1 to SCENE_MAX_WORKERS, default 1) steps every scene on N threads
 * (scene_set_workers).
 */

#ifndef BENCH_ENGINE_VERSION
#define BENCH_ENGINE_VERSION "unknown"
#endif

#include <ctype.h>
#include "bench_ours.h"

/* integrator_get_name's words, lower case, spaces as '-'. */
static int ours_parse_integrator(const char *text) {
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        char name[64];
        snprintf(name, sizeof name, "%s", integrator_get_name((integrator_t)i));
        for (char *p = name; *p; p++) *p = *p == ' ' ? '-' : (char)tolower((unsigned char)*p);
        if (strcmp(name, text) == 0) return i;
    }
    return -1;
}

int main(int argc, char **argv) {
    const bench_ops_t *ops[4] = {&ours_ops, &ours_seed_ops, &ours_symplectic_ops,
                                 &ours_sleeping_ops};
    /* --integrator and --workers are this program's own: taken out before
     * bench_main. */
    int kept = 1;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--integrator") == 0 && i + 1 < argc) {
            bench_integrator = ours_parse_integrator(argv[++i]);
            if (bench_integrator < 0) {
                fprintf(stderr, "%s: unknown integrator %s\n", argv[0], argv[i]);
                return 2;
            }
            printf("# ours: integrator %s\n", integrator_get_name((integrator_t)bench_integrator));
        } else if (strcmp(argv[i], "--workers") == 0 && i + 1 < argc) {
            char *end;
            unsigned long workers = strtoul(argv[++i], &end, 10);
            if (*end != '\0' || workers < 1 || workers > SCENE_MAX_WORKERS) {
                fprintf(stderr, "%s: --workers takes 1 to %d, not %s\n", argv[0],
                        SCENE_MAX_WORKERS, argv[i]);
                return 2;
            }
            bench_workers = (size_t)workers;
            printf("# ours: %zu workers\n", bench_workers);
        } else {
            argv[kept++] = argv[i];
        }
    }
    return bench_main(kept, argv, ops, 4);
}
