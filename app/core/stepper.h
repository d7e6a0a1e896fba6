#ifndef SANDBOX_STEPPER_H
#define SANDBOX_STEPPER_H

/*
 * A physics thread. Each frame the main loop plans its steps, hands them to
 * the stepper, shows the previous frame meanwhile (handing a software-drawn
 * frame to the display is mostly waiting on it), then waits for the steps and
 * draws the new state. While the stepper runs, the main thread touches
 * neither the scene nor the impulse trail: events are handled before, drawing
 * after. When no thread can be made, the steps run on the caller's thread.
 */

#include "core/app.h"

typedef struct stepper stepper_t;

stepper_t *stepper_start(app_t *app);

/* Starts running `steps` steps (app_run_steps); returns at once. */
void stepper_begin(stepper_t *stepper, int steps);

/* Waits for them; returns the seconds they took. */
double stepper_finish(stepper_t *stepper);

/* Ends the thread (NULL is fine). */
void stepper_stop(stepper_t *stepper);

#endif
