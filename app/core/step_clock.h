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

/*
 * The step is the open scene's (a scene file's timestep; STEP_CLOCK_STEP
 * when `step` is 0). A frame runs at most as much simulated time as
 * STEP_CLOCK_MAX_STEPS steps of STEP_CLOCK_STEP (1/30 s), and never fewer
 * than STEP_CLOCK_MAX_STEPS steps: a file stepping at 1/1000 s runs up to 34
 * steps a frame, one at 1/60 s up to 4. The debt kept is at most
 * STEP_CLOCK_MAX_DEBT, or one step when a step is longer.
 */
typedef struct {
    double owed;      /* simulated seconds owed to the physics */
    double simulated; /* simulated seconds run so far */
    double forgiven;  /* simulated seconds dropped after stalls */
    double step;      /* seconds per step; 0: STEP_CLOCK_STEP */
    unsigned long held; /* frames whose steps the frame budget cut */
} step_clock_t;

/* Adds dt simulated seconds; returns the steps to run now. */
int step_clock_advance(step_clock_t *clock, double dt);

/*
 * The same, running at most `budget` steps (0: no budget; see
 * step_clock_budget). A frame the budget cuts is counted in `held`, and
 * what it owes beyond one step is forgiven at once: a machine that cannot
 * run the physics in real time slows the simulation down, frame after
 * frame at the budget, rather than keep a debt that would have every
 * following frame run the most steps (frames longer still: a spiral).
 */
int step_clock_advance_within(step_clock_t *clock, double dt, int budget);

/*
 * The steps that fit a frame of `period` seconds when the rest of the frame
 * (drawing) takes `other` seconds and a step `per_step` seconds (recent
 * measurements): at least 1, so the simulation never stops; 0 (no budget)
 * while a step has not been measured.
 */
int step_clock_budget(double period, double other, double per_step);

/*
 * The cost of one step (s) that step_clock_budget plans with, after a frame
 * whose `steps` steps took `seconds`: smoothed over frames of two steps or
 * more only. A frame's first step pays alone for waking the threads and
 * for caches the drawing emptied, so a
 * clock held to one step a frame, planning with those, would never see two
 * fit again. A frame of one step that is
 * cheaper than `cost` lowers it too (the scene got lighter); `cost` 0 (none
 * known yet) takes any frame's.
 */
double step_clock_step_cost(double cost, double seconds, int steps);

/* The clock's step (s). */
double step_clock_step(const step_clock_t *clock);

/* The most steps a frame may run at this step. */
int step_clock_max_steps(const step_clock_t *clock);

/* Steps of `step` seconds from now on (a new scene); nothing is owed. */
void step_clock_set_step(step_clock_t *clock, double step);

#endif
