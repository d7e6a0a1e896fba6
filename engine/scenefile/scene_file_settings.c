/*
 * The settings (scene_file_parse.h): gravity, contacts, integrator,
 * iterations, warm_starting, restitution_threshold, sleep_tolerance,
 * sleep_time, timestep, view, sleeping, sleep_phase, solver_steps, step_lengths, workers,
 * stepping, category, note and game, each written at most once.
 */
#include <math.h>
#include <string.h>
#include "scene_file_parse.h"

/* The integrators by name. One line per integrator: the writer and the
 * parser both read this table. */
static const struct {
    const char *name;
    integrator_t integrator;
} INTEGRATORS[] = {
    {"seed", INTEGRATOR_SEED},
    {"explicit_euler", INTEGRATOR_EXPLICIT_EULER},
    {"symplectic_euler", INTEGRATOR_SYMPLECTIC_EULER},
    {"velocity_verlet", INTEGRATOR_VELOCITY_VERLET},
    {"rk4", INTEGRATOR_RK4},
    {"symplectic4", INTEGRATOR_SYMPLECTIC4},
    {"implicit_euler", INTEGRATOR_IMPLICIT_EULER},
};
#define INTEGRATOR_NAMES (sizeof INTEGRATORS / sizeof INTEGRATORS[0])

const char *scene_file_integrator_name(integrator_t integrator) {
    for (size_t i = 0; i < INTEGRATOR_NAMES; i++) {
        if (INTEGRATORS[i].integrator == integrator) return INTEGRATORS[i].name;
    }
    return NULL;
}

static const size_t MAX_ITERATIONS = 1000; /* scene_set_solver_iterations */

/* Words up to the end of the statement, joined by one space, at most max
 * bytes: a category or a note. */
static bool read_text(parser_t *p, const char *what, size_t max, char *out) {
    size_t length = 0;
    if (p->token.kind != TOKEN_WORD) return sf_expected(p, what);
    while (p->token.kind == TOKEN_WORD) {
        size_t add = p->token.length + (length > 0);
        if (length + add > max) {
            return sf_fail(p->lexer, p->token.where,
                           "expected %s of at most %zu characters, found more", what, max);
        }
        if (length > 0) out[length++] = ' ';
        memcpy(out + length, p->token.text, p->token.length);
        length += p->token.length;
        next(p);
    }
    out[length] = '\0';
    return true;
}

/* workers, stepping, category, note: how the file asks to be run and what
 * it says about itself. */
static bool parse_run_setting(parser_t *p, const char *keyword, sf_where_t here) {
    sf_settings_t *s = &p->doc->settings;
    if (strcmp(keyword, "workers") == 0) {
        uint64_t workers = 0;
        if (!sf_first_time(p, &s->workers_where, keyword, here) ||
            !sf_read_count(p, "the workers", 1, SCENE_MAX_WORKERS, &workers))
            return false;
        s->workers = (size_t)workers;
        return true;
    }
    if (strcmp(keyword, "stepping") == 0) {
        if (!sf_first_time(p, &s->stepping_where, keyword, here)) return false;
        if (sf_token_is(&p->token, "fixed") || sf_token_is(&p->token, "frame")) {
            s->stepping = sf_token_is(&p->token, "frame") ? SCENE_FILE_STEP_FRAME
                                                          : SCENE_FILE_STEP_FIXED;
            next(p);
            return true;
        }
        return sf_expected(p, "fixed or frame (the stepping)");
    }
    if (strcmp(keyword, "category") == 0) {
        return sf_first_time(p, &s->category_where, keyword, here) &&
               read_text(p, "the category's name", SCENE_FILE_CATEGORY_MAX, s->category);
    }
    return sf_first_time(p, &s->note_where, keyword, here) &&
           read_text(p, "the note's text", SCENE_FILE_NOTE_MAX, s->note);
}

bool sf_parse_setting(parser_t *p, const char *keyword, sf_where_t here) {
    sf_settings_t *s = &p->doc->settings;
    if (strcmp(keyword, "workers") == 0 || strcmp(keyword, "stepping") == 0 ||
        strcmp(keyword, "category") == 0 || strcmp(keyword, "note") == 0) {
        return parse_run_setting(p, keyword, here);
    }
    if (strcmp(keyword, "gravity") == 0) {
        return sf_first_time(p, &s->gravity_where, keyword, here) &&
               sf_read_vector(p, &GRAVITY, &s->gravity);
    }
    if (strcmp(keyword, "contacts") == 0) {
        if (!sf_first_time(p, &s->contacts_where, keyword, here)) return false;
        if (sf_token_is(&p->token, "on") || sf_token_is(&p->token, "off")) {
            s->contacts = sf_token_is(&p->token, "on");
            next(p);
            return true;
        }
        return sf_expected(p, "on or off (world contacts)");
    }
    if (strcmp(keyword, "integrator") == 0) {
        if (!sf_first_time(p, &s->integrator_where, keyword, here)) return false;
        for (size_t i = 0; i < INTEGRATOR_NAMES; i++) {
            if (sf_token_is(&p->token, INTEGRATORS[i].name)) {
                s->integrator = INTEGRATORS[i].integrator;
                next(p);
                return true;
            }
        }
        char expectation[512] = "an integrator (";
        for (size_t i = 0; i < INTEGRATOR_NAMES; i++) {
            strcat(expectation, INTEGRATORS[i].name);
            strcat(expectation, i + 1 < INTEGRATOR_NAMES ? ", " : ")");
        }
        return sf_expected(p, expectation);
    }
    if (strcmp(keyword, "iterations") == 0) {
        uint64_t velocity = 0, position = 0;
        if (!sf_first_time(p, &s->iterations_where, keyword, here) ||
            !sf_read_count(p, "the velocity iterations", 1, MAX_ITERATIONS, &velocity) ||
            !sf_read_count(p, "the position iterations", 1, MAX_ITERATIONS, &position))
            return false;
        s->velocity_iterations = (size_t)velocity;
        s->position_iterations = (size_t)position;
        return true;
    }
    if (strcmp(keyword, "timestep") == 0) {
        return sf_first_time(p, &s->timestep_where, keyword, here) &&
               sf_read_quantity(p, &TIMESTEP, &s->timestep);
    }
    if (strcmp(keyword, "view") == 0) {
        s->view.has_view = true;
        return sf_first_time(p, &s->view_where, keyword, here) &&
               sf_read_vector(p, &COORDINATE, &s->view.center) &&
               sf_read_quantity(p, &VIEW_SIZE, &s->view.width) &&
               sf_read_quantity(p, &VIEW_SIZE, &s->view.height);
    }
    if (strcmp(keyword, "sleeping") == 0) {
        if (!sf_first_time(p, &s->sleeping_where, keyword, here)) return false;
        if (sf_token_is(&p->token, "on") || sf_token_is(&p->token, "off")) {
            s->sleeping = sf_token_is(&p->token, "on");
            next(p);
            return true;
        }
        return sf_expected(p, "on or off (sleeping)");
    }
    if (strcmp(keyword, "sleep_phase") == 0) {
        uint64_t phase = 0;
        if (!sf_first_time(p, &s->sleep_phase_where, keyword, here) ||
            !sf_read_count(p, "the sleep phase", 0, 7, &phase))
            return false;
        s->sleep_phase = (unsigned)phase;
        return true;
    }
    if (strcmp(keyword, "solver_steps") == 0) {
        return sf_first_time(p, &s->solver_steps_where, keyword, here) &&
               sf_read_count(p, "the solver's steps", 0, UINT64_MAX, &s->solver_steps);
    }
    if (strcmp(keyword, "step_lengths") == 0) {
        quantity_t last = DURATION, before = DURATION;
        last.what = "the last step's length (s)";
        before.what = "the length of the step before it (s)";
        return sf_first_time(p, &s->step_lengths_where, keyword, here) &&
               sf_read_quantity(p, &last, &s->last_step) &&
               sf_read_quantity(p, &before, &s->step_before);
    }
    if (strcmp(keyword, "warm_starting") == 0) {
        if (!sf_first_time(p, &s->warm_starting_where, keyword, here)) return false;
        if (sf_token_is(&p->token, "on") || sf_token_is(&p->token, "off")) {
            s->warm_starting = sf_token_is(&p->token, "on");
            next(p);
            return true;
        }
        return sf_expected(p, "on or off (warm starting)");
    }
    if (strcmp(keyword, "restitution_threshold") == 0) {
        return sf_first_time(p, &s->restitution_threshold_where, keyword, here) &&
               sf_read_quantity(p, &RESTITUTION_THRESHOLD, &s->restitution_threshold);
    }
    if (strcmp(keyword, "sleep_tolerance") == 0) {
        s->sleep_angular = INFINITY;
        if (!sf_first_time(p, &s->sleep_tolerance_where, keyword, here) ||
            !sf_read_quantity(p, &SLEEP_LINEAR, &s->sleep_linear))
            return false;
        /* The angular tolerance is optional: none of its own when absent. */
        if (p->token.kind != TOKEN_WORD) return true;
        return sf_read_quantity(p, &SLEEP_ANGULAR, &s->sleep_angular);
    }
    if (strcmp(keyword, "sleep_time") == 0) {
        return sf_first_time(p, &s->sleep_time_where, keyword, here) &&
               sf_read_quantity(p, &SLEEP_TIME, &s->sleep_time);
    }
    /* game */
    return sf_first_time(p, &s->game_where, keyword, here) &&
           sf_read_name(p, "the game's name", &s->game, NULL);
}
