#include "test.h"
static void placeholder_forces(void) { CHECK(1); }
TEST_SUITE(forces, TEST_CASE(placeholder_forces));
