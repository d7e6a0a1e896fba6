#include "jostle/vector.h"

const vector_t VEC_ZERO = {0.0, 0.0};
