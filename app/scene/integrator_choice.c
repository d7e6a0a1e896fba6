#include "scene/integrator_choice.h"
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Lower case, with spaces and hyphens as underscores. */
static void normalise(const char *text, char *out, size_t size) {
    size_t n = 0;
    for (; text[n] != '\0' && n + 1 < size; n++) {
        char c = text[n];
        out[n] = c == ' ' || c == '-' ? '_' : (char)tolower((unsigned char)c);
    }
    out[n] = '\0';
}

bool integrator_choice_parse(const char *text, integrator_t *integrator) {
    if (strlen(text) >= 64) return false;
    char wanted[64], name[64];
    normalise(text, wanted, sizeof(wanted));
    for (int i = 0; i < INTEGRATOR_COUNT; i++) {
        normalise(integrator_get_name((integrator_t)i), name, sizeof(name));
        if (strcmp(wanted, name) == 0) {
            *integrator = (integrator_t)i;
            return true;
        }
    }
    return false;
}

void integrator_choice_list(char *out, size_t size) {
    size_t used = 0;
    if (size > 0) out[0] = '\0';
    for (int i = 0; i < INTEGRATOR_COUNT && used < size; i++) {
        char name[64];
        normalise(integrator_get_name((integrator_t)i), name, sizeof(name));
        int wrote = snprintf(out + used, size - used, "%s%s", i > 0 ? ", " : "", name);
        if (wrote < 0) break;
        used += (size_t)wrote;
    }
}

integrator_t integrator_choice_step(integrator_t integrator, int step) {
    int next = ((int)integrator + step) % INTEGRATOR_COUNT;
    if (next < 0) next += INTEGRATOR_COUNT;
    return (integrator_t)next;
}

bool integrator_choice_unstable(integrator_t integrator) {
    return integrator_get_stability_limit(integrator) == 0.0;
}

void integrator_choice_stability(integrator_t integrator, char *out, size_t size) {
    if (integrator_choice_unstable(integrator)) {
        snprintf(out, size, "unstable with springs");
    } else if (isinf(integrator_get_stability_limit(integrator))) {
        snprintf(out, size, "stable for any w dt");
    } else {
        snprintf(out, size, "stable for w dt < %.2f", integrator_get_stability_limit(integrator));
    }
}
