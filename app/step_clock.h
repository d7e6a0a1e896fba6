#ifndef SANDBOX_STEP_CLOCK_H
#define SANDBOX_STEP_CLOCK_H

/*
 * The physics runs in fixed steps, decoupled from the display: each frame
 * owes the simulation its duration (times the time scale), and runs the
 * whole steps owed, at most STEP_CLOCK_MAX_STEPS. A step owed but not run
 * stays owed for the next frames, so a late frame now and then is caught up
 * and the simulated clock keeps real time while the frame rate holds. Only
 * a debt beyond STEP_CLOCK_MAX_DEBT (a stall: a dragged window, a debugger,
 * a machine that cannot keep up) is forgiven: the simulation then slows down
 * rather than spiralling into ever longer frames. Plain C, no SDL.
 */

#define STEP_CLOCK_STEP (1.0 / 120.0)
#define STEP_CLOCK_MAX_STEPS 4
#define STEP_CLOCK_MAX_DEBT 0.1

typedef struct {
    double owed;      /* simulated seconds owed to the physics */
    double simulated; /* simulated seconds run so far */
    double forgiven;  /* simulated seconds dropped after stalls */
} step_clock_t;

/* Adds dt simulated seconds; returns the steps to run now. */
int step_clock_advance(step_clock_t *clock, double dt);

#endif
