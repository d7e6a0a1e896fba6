#include "test.h"
static void placeholder_list(void) { CHECK(1); }
TEST_SUITE(list, TEST_CASE(placeholder_list));
