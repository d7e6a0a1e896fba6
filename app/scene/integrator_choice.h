#ifndef SANDBOX_INTEGRATOR_CHOICE_H
#define SANDBOX_INTEGRATOR_CHOICE_H

/*
 * The engine's integrators as the sandbox offers them: by name on the command
 * line (--integrator), one after another by key (N, Shift+N), and what each
 * one does with springs, in words. Engine API only (no SDL); tested by
 * tests/app_units.c.
 */

#include <stdbool.h>
#include <stddef.h>
#include "jostle/scene.h"

/* The integrator named `text`: integrator_get_name's names, in any case, with
 * spaces, underscores or hyphens alike ("symplectic_euler", "Symplectic
 * Euler", "rk4"). False when no integrator has that name. */
bool integrator_choice_parse(const char *text, integrator_t *integrator);

/* Every name as --integrator takes it, comma-separated ("seed,
 * explicit_euler, ..."). */
void integrator_choice_list(char *out, size_t size);

/* The next integrator (step +1) or the previous one (-1), wrapping around. */
integrator_t integrator_choice_step(integrator_t integrator, int step);

/* Whether the scheme adds energy to every spring at every dt
 * (integrator_get_stability_limit is 0: seed and explicit Euler). */
bool integrator_choice_unstable(integrator_t integrator);

/* What it does with springs, in at most 22 characters: "unstable with
 * springs", "stable for w dt < 2.00" (w = sqrt(k / m) of the spring), or
 * "stable for any w dt" (implicit Euler). */
void integrator_choice_stability(integrator_t integrator, char *out, size_t size);

#endif
