#include "test.h"
static void placeholder_collision(void) { CHECK(1); }
TEST_SUITE(collision, TEST_CASE(placeholder_collision));
