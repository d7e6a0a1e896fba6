/* The values of the constants solver_types.h declares and explains. */
#include "solver/solver_types.h"

const double SOLVER_FREE_RESTITUTION_THRESHOLD = 1e-3;
const double SOLVER_LINEAR_SLOP = 0.001;
const double SOLVER_SLOP_FRACTION = 0.01;
/* Twice Box2D's 0.2: large piles' overlaps close in half the depth and
 * the 40-row pyramid stands (docs/design.md, Position correction). */
const double SOLVER_POSITION_RATE = 0.4;
const double SOLVER_STATIC_POSITION_RATE = 0.5;
const double SOLVER_MAX_POSITION_CORRECTION = 0.2;
const double SOLVER_MAX_PUSH_SPEED = 4.0;
const double SOLVER_MAX_PUSH = 0.2;
const double SOLVER_MAX_TURN = 0.2;
