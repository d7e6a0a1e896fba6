/* Every test suite, one line each: main.c declares and runs them in this
 * order. A new tests/test_NAME.c defines suite_NAME with TEST_SUITE(NAME, ...)
 * and gets a line here. */
SUITE(vector)
SUITE(list)
SUITE(polygon)
SUITE(body)
SUITE(scene)
SUITE(forces)
SUITE(collision)
SUITE(broadphase)
SUITE(contacts)
SUITE(solver)
SUITE(impacts)
