#ifndef SANDBOX_SAMPLE_CATEGORIES_H
#define SANDBOX_SAMPLE_CATEGORIES_H

/*
 * The categories of the samples, in the order the browser lists them. A
 * scene file names its own (`category WORDS`, docs/scenes.md); the samples
 * browser (app/scene/samples.c) lists a category not here under "Other",
 * and tests/app_units.c fails on it. Header only, plain C.
 */

static const char *const SAMPLE_CATEGORIES[] = {
    "Basics", "Stacking", "Collisions", "Integrators and accuracy", "Stability", "Springs",
    "Games",  "Shapes",   "Joints",
};
#define SAMPLE_CATEGORY_COUNT ((int)(sizeof SAMPLE_CATEGORIES / sizeof SAMPLE_CATEGORIES[0]))

/* The index of a category's name in SAMPLE_CATEGORIES, or -1. */
static inline int sample_category_index(const char *name) {
    for (int i = 0; i < SAMPLE_CATEGORY_COUNT; i++) {
        const char *a = SAMPLE_CATEGORIES[i], *b = name;
        while (*a != '\0' && *a == *b) a++, b++;
        if (*a == '\0' && *b == '\0') return i;
    }
    return -1;
}

#endif
