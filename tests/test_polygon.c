#include "test.h"
static void placeholder_polygon(void) { CHECK(1); }
TEST_SUITE(polygon, TEST_CASE(placeholder_polygon));
