/* The seed's body_tick: one body moved over dt by the seed scheme, outside
 * any scene. Here rather than in body.c because it calls the integrators,
 * which work on bodies: body.c stays below them. */
#include <math.h>
#include <stdio.h>
#include "jostle/body.h"
#include "base/check.h"
#include "dynamics/body_private.h"
#include "dynamics/integrator.h"

void body_tick(body_t *body, double dt) {
    REQUIRE_NOT_NULL(body);
    REQUIRE(isfinite(dt) && dt > 0.0, "dt must be finite and > 0 (got %g)", dt);
    body_motion_t before = body_motion(body);
    integrator_step_t step = {INTEGRATOR_SEED, dt, VEC_ZERO, NULL, NULL, NULL, 0, 0};
    integrator_motion_t motion;
    integrator_stages_t *no_stages = NULL;
    integrator_predict(&step, &body, 1, &motion, &no_stages);
    integrator_apply(body, &motion);
    body_note_move(body);
    if (!body_motion_is_finite(body)) {
        char message[512];
        body_explain_non_finite(body, &before, dt, message, sizeof message);
        engine_fail(__func__, "%s", message);
    }
    body_clear_accumulators(body);
}
