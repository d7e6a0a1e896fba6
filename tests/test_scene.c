#include "test.h"
static void placeholder_scene(void) { CHECK(1); }
TEST_SUITE(scene, TEST_CASE(placeholder_scene));
