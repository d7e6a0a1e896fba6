#include "test.h"
static void placeholder_body(void) { CHECK(1); }
TEST_SUITE(body, TEST_CASE(placeholder_body));
